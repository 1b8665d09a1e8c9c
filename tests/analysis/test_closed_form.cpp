#include "poinsot/analysis/closed_form.hpp"

#include "poinsot/analysis/multipliers.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/so3/hat.hpp"
#include "poinsot_test.hpp"

namespace poinsot::analysis {
namespace {
using dynamics::RigidBody;
using test::kEps;

Mat3 random_inertia() {
  Vec3 m;
  do {
    m = Vec3(test::uniform(0.2, 3.0), test::uniform(0.2, 3.0), test::uniform(0.2, 3.0));
  } while (m[0] + m[1] < m[2] || m[1] + m[2] < m[0] || m[0] + m[2] < m[1]);
  const Mat3 Q = test::random_rotation();
  return Q * m.asDiagonal() * Q.transpose();
}

// The closed forms involve J³ ~ 27 and τ0 ~ 1/det J (up to ~100 for the smallest bodies drawn): the
// cancellation between terms loses a factor of about τ0·|J|³ ≲ 1e3 over the round-off of Λ itself.
constexpr double kClosedFormTol = 1e-11;

TEST(ClosedForm, AllThreeFormsEqualTheStateFormula) {
  for (int i = 0; i < 500; ++i) {
    const Mat3 J = random_inertia();
    const RigidBody body = RigidBody::from_inertia(J);
    const Vec3 w = test::random_vector(2.0);
    const Mat3 reference =
        lambda_from_omega(body, w, angular_acceleration_body(body, {0.0, Mat3::Identity(), w}));
    const double scale = std::max(1.0, reference.norm());
    for (const ClosedForm form : {ClosedForm::property2, ClosedForm::eq38, ClosedForm::symmetric}) {
      EXPECT_LE(test::max_abs_diff(lambda_closed_form(J, w, form), reference), kClosedFormTol * scale);
    }
  }
}

TEST(ClosedForm, Lemma1GivesTheAngularAcceleration) {
  // (3.5) with C4: j(ω̇) = τ0 (ξ12 − ξ21) against ω̇ = J⁻¹((Jω) × ω) solved by LU.
  for (int i = 0; i < 500; ++i) {
    const Mat3 J = random_inertia();
    const Vec3 w = test::random_vector(2.0);
    const Vec3 wd = J.lu().solve((J * w).cross(w));
    EXPECT_LE(test::max_abs_diff(omega_dot_hat_lemma1(J, w), so3::hat(wd)), 1e-12 * std::max(1.0, wd.norm()));
  }
}

TEST(ClosedForm, CayleyHamiltonCorrectedC7) {
  for (int i = 0; i < 500; ++i) {
    const Mat3 J = random_inertia();
    EXPECT_LE(cayley_hamilton_residual(J).cwiseAbs().maxCoeff(), 1e-13 * std::pow(J.norm(), 3));
  }
}

TEST(ClosedForm, InvariantsOfAnAxisymmetricBodyLemma2) {
  // Lemma 2: τ1 = A + C/2, 1/τ0 = A²C, τ2 = A(A + 2C), J² = (C + A)J − AC I.
  for (int i = 0; i < 200; ++i) {
    const double A = test::uniform(0.5, 3.0);
    const double C = test::uniform(0.1, 2.0 * A);
    const Vec3 k = test::random_unit_vector();
    const Mat3 J = A * Mat3::Identity() + (C - A) * k * k.transpose();
    const InertiaInvariants t = inertia_invariants(J);
    EXPECT_NEAR(t.tau1, A + C / 2, 1e-14 * A);
    EXPECT_NEAR(1.0 / t.tau0, A * A * C, 1e-13 * A * A * A);
    EXPECT_NEAR(t.tau2, A * (A + 2 * C), 1e-13 * A * A);
    EXPECT_LE(test::max_abs_diff(J * J, (C + A) * J - A * C * Mat3::Identity()), 1e-13 * A * A);
  }
}

TEST(ClosedForm, PrintedEq38IsNotSymmetricCorrectedIsErrataC6) {
  // Case b (A = 2, C = 1, k = e3, Ω0 = (0.3, −0.4, 1.2)): the corrected Λ13 is 0.27 (docs/conventions.md C6,
  // printed to two digits); the printed (3.8) with τ0 in place of τ0τ1 gives 0.54 and an unsymmetric matrix.
  const Mat3 J = Vec3(2.0, 2.0, 1.0).asDiagonal();
  const Vec3 w(0.3, -0.4, 1.2);
  const Mat3 lambda = lambda_closed_form(J, w, ClosedForm::eq38);
  EXPECT_NEAR(lambda(0, 2), 0.27, 0.005);
  EXPECT_NEAR(lambda(2, 0), 0.27, 0.005);
  const InertiaInvariants t = inertia_invariants(J);
  const Vec3 w1 = J * w, w2 = J * w1;
  const Mat3 printed_minus_corrected =
      (t.tau0 - t.tau0 * t.tau1) * (w1 * w2.transpose() - w2 * w1.transpose());
  EXPECT_NEAR((lambda + printed_minus_corrected)(0, 2), 0.54, 0.005);
}

TEST(ClosedForm, LaminaIsFine) {
  // J = diag(1, 2, 3): K singular but J invertible; the closed form never needs K⁻¹.
  const Mat3 J = Vec3(1.0, 2.0, 3.0).asDiagonal();
  const RigidBody body = RigidBody::from_inertia(J);
  const Vec3 w(0.4, -1.1, 0.7);
  const Mat3 reference = lambda_from_omega(body, w, J.inverse() * (J * w).cross(w));
  EXPECT_LE(test::max_abs_diff(lambda_closed_form(J, w, ClosedForm::symmetric), reference), 1e-13);
}

TEST(ClosedForm, SingularInertiaIsRejected) {
  EXPECT_THROW(inertia_invariants(Mat3::Zero()), InvalidInput);
  Mat3 bad = Mat3::Identity();
  bad(0, 0) = std::nan("");
  EXPECT_THROW(lambda_closed_form(bad, Vec3::Ones()), InvalidInput);
}

}  // namespace
}  // namespace poinsot::analysis
