#include "poinsot/analysis/axisymmetric.hpp"

#include <Eigen/Eigenvalues>

#include "errata_cases.hpp"
#include "poinsot/analysis/multipliers.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/so3/hat.hpp"
#include "poinsot_test.hpp"
#include "reference_motion.hpp"

namespace poinsot::analysis {
namespace {
using dynamics::RigidBody;
using dynamics::State;
using test::kEps;

using errata::kCaseB;
using errata::kCaseC;
using errata::kOmegaB;
using errata::kOmegaC;

RigidBody body_of(const AxisymmetricInertia& a) {
  return RigidBody::from_inertia(a.inertia());
}

State state_at_rest_attitude(const Vec3& w) {
  State s;
  s.omega_body = w;
  return s;
}

TEST(Axisymmetric, CaseBProlateErrataNumbers) {
  const AxisymmetricLambda a(kCaseB, kOmegaB);
  // Printed to 4-5 digits in docs/conventions.md (eigenvalue ordering remark, C21).
  EXPECT_NEAR(a.lambda1(), -1.0294, 5e-5);
  EXPECT_NEAR(a.lambda2(), -0.0656, 5e-5);
  EXPECT_NEAR(a.lambda3(), -0.845, 5e-16);  // −C⟨Ω0,Ω0⟩/2 = −1.69/2 exactly representable to 1 ulp
  EXPECT_NEAR(a.mu(), 1.2, 4 * kEps);
  EXPECT_NEAR(a.r(), 0.5, 4 * kEps);
  // The printed λ3 = −(C/2)η0² would be −1.42805 (C21).
  EXPECT_GT(std::abs(a.lambda3() - (-0.5 * 1.69 * 1.69)), 0.5);
  // C19: (EᵀΛE)33 = −(A − C/2) r² = −0.375 (the printed sign gives +0.375).
  EXPECT_NEAR(a.constant_matrix_54()(2, 2), -0.375, 8 * kEps);
  EXPECT_NEAR(a.constant_matrix_53()(2, 2), -0.375, 8 * kEps);
  const Vec3 e = a.eigenvalues_sorted();
  EXPECT_EQ(e[1], a.lambda3());  // λ1 < λ3 < λ2 here
}

TEST(Axisymmetric, CaseCOblateErrataNumbers) {
  const AxisymmetricLambda a(kCaseC, kOmegaC);
  EXPECT_NEAR(a.lambda1(), -3.6460, 5e-5);
  EXPECT_NEAR(a.lambda2(), -0.0790, 5e-5);
  EXPECT_NEAR(a.lambda3(), -4.725, 8 * kEps * 4.725);
  // C23: Δ = 12.72 < c1² = 13.88 but Δ² = 161.9 > c1².
  EXPECT_NEAR(a.Delta(), 12.72, 0.005);
  EXPECT_NEAR(a.c1() * a.c1(), 13.88, 0.005);
  EXPECT_NEAR(a.Delta() * a.Delta(), 161.9, 0.1);
  EXPECT_EQ(a.eigenvalues_sorted()[0], a.lambda3());  // λ3 < λ1 < λ2 here
}

TEST(Axisymmetric, DiscriminantAndCharacteristicPolynomial) {
  // Δ = c1² + 4c2 as printed, and λ1, λ2 are the roots of λ² − c1λ − c2 (checked directly).
  for (int i = 0; i < 500; ++i) {
    const double A = test::uniform(0.5, 3.0);
    const AxisymmetricInertia in{A, test::uniform(0.05, 2.0 * A), test::random_unit_vector()};
    const AxisymmetricLambda a(in, test::random_vector(2.0));
    const double scale = a.c1() * a.c1() + 1e-300;
    EXPECT_NEAR(a.Delta(), a.c1() * a.c1() + 4 * a.c2(), 32 * kEps * scale);
    for (const double l : {a.lambda1(), a.lambda2()}) {
      EXPECT_NEAR(l * l - a.c1() * l - a.c2(), 0.0, 32 * kEps * scale);
    }
    EXPECT_LE(a.lambda1(), a.lambda2());
    EXPECT_LE(a.lambda2(), 0.0);
    // C22: the corrected lower bound Δ ≥ [(A − C/2) r² − Cμ²/2]².
    const double bound = (A - in.C / 2) * a.r() * a.r() - in.C * a.mu() * a.mu() / 2;
    EXPECT_GE(a.Delta(), bound * bound * (1 - 1e-12));
  }
}

TEST(Axisymmetric, RemarkTwoCounterexampleErrataC22) {
  // A = 2, C = 1, r = 0.1, μ = 2: Δ = 4.0302, below the printed bound 15.880 and above the corrected 3.9402.
  const AxisymmetricLambda a(kCaseB, Vec3(0.1, 0.0, 2.0));
  EXPECT_NEAR(a.Delta(), 4.0302, 5e-5);
  const double printed = (1.5 * 0.01 - 4.0);
  EXPECT_LT(a.Delta(), printed * printed);
  EXPECT_GE(a.Delta(), 3.9402 - 5e-5);
}

TEST(Axisymmetric, ClosedFormsEqualTheStateFormulaAtT0) {
  // (5.3), (5.4) and the eigenvalues against Λ(0) = (j(ω)² + j(ω̇))K from the state, for random bodies.
  for (int i = 0; i < 500; ++i) {
    const double A = test::uniform(0.5, 3.0);
    const AxisymmetricInertia in{A, test::uniform(0.05, 2.0 * A), test::random_unit_vector()};
    const Vec3 w0 = test::random_vector(2.0);
    const AxisymmetricLambda a(in, w0);
    const Mat3 lambda = lambda_from_state(body_of(in), state_at_rest_attitude(w0));
    const double scale = std::max(1.0, lambda.norm());
    EXPECT_LE(test::max_abs_diff(a.constant_matrix_53(), lambda), 64 * kEps * scale);
    EXPECT_LE(test::max_abs_diff(a.constant_matrix_54(), lambda), 64 * kEps * scale);
    EXPECT_LE(test::max_abs_diff(a.eigenvalues_sorted(), sorted_eigenvalues(lambda)), 64 * kEps * scale);
    // (5.5): its eigenvalues are λ1, λ2.
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> s;
    s.computeDirect(a.reduced_matrix_55(), Eigen::EigenvaluesOnly);
    EXPECT_NEAR(s.eigenvalues()[0], a.lambda1(), 32 * kEps * scale);
    EXPECT_NEAR(s.eigenvalues()[1], a.lambda2(), 32 * kEps * scale);
  }
}

TEST(Axisymmetric, OmegaPrecessesAsEq42WithItsPrintedSign) {
  // docs/conventions.md C11: ω(t) = E Ω0 with E = exp[t (C/A − 1) μ j(k)], against the reference RK4 (error
  // ~1e-12); the opposite sign is off by O(1).
  for (const auto& [in, w0] : {std::pair{kCaseB, kOmegaB}, std::pair{kCaseC, kOmegaC}}) {
    const AxisymmetricLambda a(in, w0);
    const State s = test::advance(body_of(in), nullptr, state_at_rest_attitude(w0), 7.5);
    EXPECT_LE((a.omega(7.5) - s.omega_body).norm(), 1e-10);
    EXPECT_GT((a.E(7.5).transpose() * w0 - s.omega_body).norm(), 0.1);
  }
}

TEST(Axisymmetric, EigenvectorIsKCrossOmegaOfTErrataC14) {
  // Case b at t = 7.5 s: Λ(k×Ω0) = (−0.298, −0.207, 0.220) ≠ λ3(k×Ω0) = (−0.338, −0.254, 0), while
  // Λ(k×ω) = λ3(k×ω). Λ(t) from the reference trajectory, independently of E.
  const AxisymmetricLambda a(kCaseB, kOmegaB);
  const State s = test::advance(body_of(kCaseB), nullptr, state_at_rest_attitude(kOmegaB), 7.5);
  const Mat3 lambda = lambda_from_state(body_of(kCaseB), s);
  const Vec3 v0 = Vec3::UnitZ().cross(kOmegaB);
  const Vec3 wrong = lambda * v0;
  EXPECT_NEAR(wrong[0], -0.298, 5e-4);
  EXPECT_NEAR(wrong[1], -0.207, 5e-4);
  EXPECT_NEAR(wrong[2], 0.220, 5e-4);
  const Vec3 v = a.lambda3_eigenvector(7.5);
  EXPECT_LE((lambda * v - a.lambda3() * v).norm(), 1e-10);
  EXPECT_LE((v - Vec3::UnitZ().cross(s.omega_body)).norm(), 1e-10);
  // And the closed-form Λ(t) = E(EᵀΛE)Eᵀ is the trajectory's.
  EXPECT_LE(test::max_abs_diff(a.lambda_at(7.5), lambda), 1e-10);
}

TEST(Axisymmetric, RandomBodiesEigenvaluesConstantAlongTheTrajectory) {
  // The Theorem: eig Λ(t) constant and equal to the closed forms, along the reference RK4 trajectory
  // (h = 1e-3 s, |ω| ≤ 1.7 rad/s, t ≤ 2 s: error ≲ 1e-11 relative).
  for (int i = 0; i < 10; ++i) {
    const double A = test::uniform(0.5, 3.0);
    const AxisymmetricInertia in{A, test::uniform(0.05, 2.0 * A), test::random_unit_vector()};
    const Vec3 w0 = test::random_vector(1.0);
    const AxisymmetricLambda a(in, w0);
    const RigidBody body = body_of(in);
    State s = state_at_rest_attitude(w0);
    s.R_space_body = test::random_rotation();  // the body-frame closed form does not depend on R(0)
    for (int j = 0; j < 4; ++j) {
      s = test::advance(body, nullptr, s, s.time + 0.5);
      const Mat3 lambda = lambda_from_state(body, s);
      const double scale = std::max(1.0, lambda.norm());
      EXPECT_LE(test::max_abs_diff(sorted_eigenvalues(lambda), a.eigenvalues_sorted()), 1e-10 * scale);
      EXPECT_LE(test::max_abs_diff(a.lambda_at(s.time), lambda), 1e-10 * scale);
    }
  }
}

TEST(Axisymmetric, SpecialCases) {
  {  // the ball: Λ = C j(Ω0)²/2, E = I
    const AxisymmetricLambda a({1.5, 1.5, Vec3::UnitZ()}, kOmegaB);
    EXPECT_TRUE(a.special_cases().ball);
    EXPECT_LE(test::max_abs_diff(a.lambda_at(3.0), 0.75 * so3::hat(kOmegaB) * so3::hat(kOmegaB)), 16 * kEps);
    EXPECT_LE(test::max_abs_diff(a.E(3.0), Mat3::Identity()), 0.0);
    EXPECT_NEAR(a.lambda2(), 0.0, 16 * kEps);  // ṘV = 0 for V ∥ ω
  }
  {  // r = 0: spin about the axis, λ1 = λ3 = −Cμ²/2, λ2 = 0
    const AxisymmetricLambda a(kCaseB, Vec3(0.0, 0.0, 2.0));
    EXPECT_TRUE(a.special_cases().axial_spin);
    EXPECT_FALSE(a.special_cases().equatorial_spin);
    EXPECT_NEAR(a.lambda1(), -2.0, 16 * kEps);
    EXPECT_NEAR(a.lambda3(), -2.0, 16 * kEps);
    EXPECT_EQ(a.lambda2(), 0.0);
    EXPECT_LE(test::max_abs_diff(a.constant_matrix_54(), a.constant_matrix_53()), 16 * kEps);
  }
  {  // μ = 0: Ω0 ⟂ k, E = I, λ2 = 0
    const AxisymmetricLambda a(kCaseC, Vec3(1.0, -0.5, 0.0));
    EXPECT_TRUE(a.special_cases().equatorial_spin);
    EXPECT_EQ(a.lambda2(), 0.0);
    EXPECT_LE(test::max_abs_diff(a.E(10.0), Mat3::Identity()), 0.0);
  }
  {  // flat disc A = C/2: c2 = 0, λ2 = 0; with μ = 0 also Δ = 0 (double eigenvalue, C22)
    const AxisymmetricLambda a({1.0, 2.0, Vec3::UnitZ()}, Vec3(0.3, 0.4, 0.0));
    EXPECT_TRUE(a.special_cases().flat);
    EXPECT_TRUE(a.special_cases().zero_discriminant);
    EXPECT_EQ(a.Delta(), 0.0);
    EXPECT_EQ(a.lambda1(), a.lambda2());
    const AxisymmetricLambda b({1.0, 2.0, Vec3::UnitZ()}, kOmegaC);
    EXPECT_TRUE(b.special_cases().flat);
    EXPECT_FALSE(b.special_cases().zero_discriminant);
    EXPECT_EQ(b.c2(), 0.0);
    EXPECT_NEAR(b.lambda2(), 0.0, 0.0);
  }
  {  // a general case has none of them
    const AxisymmetricLambda a(kCaseB, kOmegaB);
    const AxisymmetricSpecialCases sc = a.special_cases();
    EXPECT_FALSE(sc.ball || sc.flat || sc.axial_spin || sc.equatorial_spin || sc.zero_discriminant ||
                 sc.zero_velocity);
  }
  {  // at rest: Λ = 0
    const AxisymmetricLambda a(kCaseB, Vec3::Zero());
    EXPECT_TRUE(a.special_cases().zero_velocity);
    EXPECT_EQ(a.eigenvalues_sorted(), Vec3::Zero());
  }
}

TEST(Axisymmetric, DetectionFromARigidBody) {
  const Mat3 Q = test::random_rotation();
  {  // oblate: two small equal moments, C the largest, k = the third principal axis
    const auto a =
        detect_axisymmetry(RigidBody::from_inertia(Q * Vec3(1.0, 1.0, 1.8).asDiagonal() * Q.transpose()));
    ASSERT_TRUE(a.has_value());
    EXPECT_NEAR(a->A, 1.0, 1e-14);
    EXPECT_NEAR(a->C, 1.8, 1e-14);
    EXPECT_NEAR(std::abs(a->k.dot(Q.col(2))), 1.0, 1e-12);
  }
  {  // prolate: C the smallest
    const auto a =
        detect_axisymmetry(RigidBody::from_inertia(Q * Vec3(2.0, 1.0, 2.0).asDiagonal() * Q.transpose()));
    ASSERT_TRUE(a.has_value());
    EXPECT_NEAR(a->A, 2.0, 1e-14);
    EXPECT_NEAR(a->C, 1.0, 1e-14);
    EXPECT_NEAR(std::abs(a->k.dot(Q.col(1))), 1.0, 1e-12);
  }
  {  // the ball
    const auto a = detect_axisymmetry(RigidBody::from_principal_moments(Vec3(2.0, 2.0, 2.0)));
    ASSERT_TRUE(a.has_value());
    EXPECT_EQ(a->A, a->C);
  }
  EXPECT_FALSE(detect_axisymmetry(RigidBody::from_principal_moments(Vec3(1.0, 2.0, 3.0))).has_value());
  // The detected inertia reproduces J.
  const RigidBody b = RigidBody::from_inertia(Q * Vec3(3.0, 3.0, 4.0).asDiagonal() * Q.transpose());
  EXPECT_LE(test::max_abs_diff(detect_axisymmetry(b)->inertia(), b.inertia()), 1e-13);
}

TEST(Axisymmetric, RejectsUnphysicalInput) {
  EXPECT_THROW(AxisymmetricLambda({1.0, 2.5, Vec3::UnitZ()}, kOmegaB), InvalidInput);  // C > 2A
  EXPECT_THROW(AxisymmetricLambda({-1.0, 1.0, Vec3::UnitZ()}, kOmegaB), InvalidInput);
  EXPECT_THROW(AxisymmetricLambda({1.0, 1.0, Vec3::Zero()}, kOmegaB), InvalidInput);
  EXPECT_THROW(AxisymmetricLambda(kCaseB, Vec3(std::nan(""), 0, 0)), InvalidInput);
}

}  // namespace
}  // namespace poinsot::analysis
