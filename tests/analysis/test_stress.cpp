#include "poinsot/analysis/stress.hpp"

#include <numbers>

#include "poinsot/analysis/multipliers.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/so3/hat.hpp"
#include "poinsot_test.hpp"

namespace poinsot::analysis {
namespace {
using dynamics::RigidBody;
using dynamics::State;
using std::numbers::pi;
using test::kEps;

// Gauss–Legendre nodes and weights on [−1, 1] (3 points: exact for polynomials of degree ≤ 5).
constexpr double kGaussX[3] = {-0.7745966692414834, 0.0, 0.7745966692414834};
constexpr double kGaussW[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};

TEST(Stress, SpinningThinDiscTimoshenko) {
  // Timoshenko's plane-stress solution for a thin disc of radius b spinning at ω about its axis:
  //   σr = (3+ν)ρω²(b²−r²)/8,  σθ = ρω²[(3+ν)b² − (1+3ν)r²]/8,  σz = 0.
  // Its volume integral, by quadrature (Gauss in r, exact for this cubic integrand; the periodic trapezoid
  // rule in θ, exact for the trigonometric polynomials er⊗er, eθ⊗eθ), is diag(S, S, 0) with S = m b² ω²/4,
  // for every ν, and equals −Λ of the disc (a steel disc, b = 0.1 m, h = 5 mm, ω = 300 rad/s).
  const double rho = 7850.0, b = 0.1, h = 0.005, omega = 300.0;
  const double m = rho * pi * b * b * h;
  const double S = m * b * b * omega * omega / 4.0;
  // The thin disc: C = m b²/2, A = m b²/4 + m h²/12 about the centre of mass.
  const RigidBody body = RigidBody::from_principal_moments(
      Vec3(m * b * b / 4 + m * h * h / 12, m * b * b / 4 + m * h * h / 12, m * b * b / 2));
  State s;
  s.omega_body = Vec3(0.0, 0.0, omega);
  const Mat3 minus_lambda = -lambda_from_state(body, s);
  for (const double nu : {0.0, 0.3, 0.45}) {
    Mat3 integral = Mat3::Zero();
    const int n_theta = 16;
    for (int i = 0; i < 3; ++i) {
      const double r = 0.5 * b * (kGaussX[i] + 1.0);
      const double wr = 0.5 * b * kGaussW[i];
      const double sr = (3 + nu) * rho * omega * omega * (b * b - r * r) / 8;
      const double st = rho * omega * omega * ((3 + nu) * b * b - (1 + 3 * nu) * r * r) / 8;
      for (int j = 0; j < n_theta; ++j) {
        const double th = 2 * pi * j / n_theta;
        const Vec3 er(std::cos(th), std::sin(th), 0.0), et(-std::sin(th), std::cos(th), 0.0);
        const Mat3 sigma = sr * er * er.transpose() + st * et * et.transpose();
        integral += sigma * (wr * r * (2 * pi / n_theta) * h);
      }
    }
    const Mat3 expected = Vec3(S, S, 0.0).asDiagonal();
    EXPECT_LE(test::max_abs_diff(integral, expected), 1e-12 * S) << "nu = " << nu;
    EXPECT_LE(test::max_abs_diff(minus_lambda, expected), 1e-13 * S);
  }
  // The steady-spin closed form, in any attitude: ∫σ dv = R diag(S, S, 0) Rᵀ.
  s.R_space_body = test::random_rotation();
  const Mat3 expected_space = s.R_space_body * Vec3(S, S, 0.0).asDiagonal() * s.R_space_body.transpose();
  EXPECT_LE(test::max_abs_diff(stress_integral_space(body, s), expected_space), 1e-12 * S);
  EXPECT_LE(test::max_abs_diff(steady_spin_stress_integral_body(body.poinsot(), Vec3::UnitZ(), omega),
                               Mat3(Vec3(S, S, 0.0).asDiagonal())),
            1e-13 * S);
}

TEST(Stress, TumblingBoxAgainstQuadratureOfRhoAX) {
  // ∫σ dv = −∫ρ a⊗x dv over the box, with the acceleration of each material point from the classical
  // space-frame kinematics a = Ω̇ × x + Ω × (Ω × x), Ω = Rω and Ω̇ from Euler's equations written in space,
  // J_s Ω̇ = −Ω × J_s Ω with J_s = R J Rᵀ. 3-point Gauss per axis integrates the quadratic integrand exactly.
  const double a = 0.3, b = 0.5, c = 0.8, mass = 2.5;
  const double rho = mass / (a * b * c);
  const RigidBody body =
      RigidBody::from_principal_moments(mass / 12 * Vec3(b * b + c * c, a * a + c * c, a * a + b * b));
  for (int trial = 0; trial < 20; ++trial) {
    State s;
    s.R_space_body = test::random_rotation();
    s.omega_body = test::random_vector(3.0);
    const Vec3 W = s.R_space_body * s.omega_body;
    const Mat3 Js = s.R_space_body * body.inertia() * s.R_space_body.transpose();
    const Vec3 Wdot = Js.lu().solve(-W.cross(Js * W));
    Mat3 quad = Mat3::Zero();
    const Vec3 half(a / 2, b / 2, c / 2);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k) {
          const Vec3 X(half[0] * kGaussX[i], half[1] * kGaussX[j], half[2] * kGaussX[k]);
          const double w = kGaussW[i] * kGaussW[j] * kGaussW[k] * half.prod();
          const Vec3 x = s.R_space_body * X;
          const Vec3 acc = Wdot.cross(x) + W.cross(W.cross(x));
          quad -= rho * w * acc * x.transpose();
        }
    const Mat3 integral = stress_integral_space(body, s);
    EXPECT_LE(test::max_abs_diff(integral, quad), 1e-12 * std::max(1.0, integral.norm()));
    // Symmetric, positive semi-definite, trace 2T (the virial).
    const StressSummary sum = summarize_stress(integral);
    EXPECT_GE(sum.principal[0], -1e-14 * integral.norm());
    EXPECT_NEAR(sum.trace, 2 * dynamics::kinetic_energy(body, s), 1e-13 * integral.norm());
  }
}

TEST(Stress, SteadySpinOfABoxErrataSection6) {
  // Box (a, b, c) spinning about z: ∫σ dv = ω² diag(m a²/12, m b²/12, 0).
  const double a = 0.3, b = 0.5, c = 0.8, m = 2.5, w = 7.0;
  const RigidBody body =
      RigidBody::from_principal_moments(m / 12 * Vec3(b * b + c * c, a * a + c * c, a * a + b * b));
  State s;
  s.omega_body = Vec3(0.0, 0.0, w);
  const Mat3 expected = w * w * Vec3(m * a * a / 12, m * b * b / 12, 0.0).asDiagonal();
  EXPECT_LE(test::max_abs_diff(stress_integral_space(body, s), expected), 1e-13 * expected.norm());
  EXPECT_LE(test::max_abs_diff(steady_spin_stress_integral_body(body.poinsot(), Vec3(0, 0, 2), w), expected),
            1e-13 * expected.norm());
}

TEST(Stress, TrescaAndVonMises) {
  const StressSummary s = summarize_stress(Mat3(Vec3(1.0, 2.0, 4.0).asDiagonal()));
  EXPECT_DOUBLE_EQ(s.tresca, 1.5);
  EXPECT_NEAR(s.von_mises, std::sqrt(7.0), 4 * kEps);
  // Invariance and the deviatoric form √(3/2 s:s), s = σ − tr(σ)/3 I, on random tensors.
  for (int i = 0; i < 200; ++i) {
    const Mat3 g = Mat3::Random();
    const Mat3 m = g + g.transpose();
    const Mat3 Q = test::random_rotation();
    const StressSummary a = summarize_stress(m);
    const StressSummary b = summarize_stress(Q * m * Q.transpose());
    const Mat3 dev = m - m.trace() / 3 * Mat3::Identity();
    EXPECT_NEAR(a.von_mises, std::sqrt(1.5 * dev.squaredNorm()), 1e-14 * m.norm());
    EXPECT_NEAR(a.von_mises, b.von_mises, 1e-14 * m.norm());
    EXPECT_NEAR(a.tresca, b.tresca, 1e-14 * m.norm());
    // √3 τmax ≤ σ_vM ≤ 2 τmax for every stress state.
    EXPECT_LE(std::sqrt(3.0) * a.tresca, a.von_mises * (1 + 1e-14));
    EXPECT_LE(a.von_mises, 2 * a.tresca * (1 + 1e-14));
    EXPECT_LE(
        test::max_abs_diff(a.principal_axes * a.principal.asDiagonal() * a.principal_axes.transpose(), m),
        1e-14 * m.norm() * 8);
  }
}

TEST(Stress, MeanStressDividesByTheVolume) {
  const RigidBody body = RigidBody::from_principal_moments(Vec3(2.0, 3.0, 4.0));
  State s;
  s.omega_body = Vec3(1.0, 0.5, 0.3);
  const Mat3 lambda = lambda_from_state(body, s);
  const ConstraintStress none = constraint_stress(lambda, s.R_space_body);
  EXPECT_FALSE(none.has_mean);
  const ConstraintStress c = constraint_stress(lambda, s.R_space_body, 0.25);
  ASSERT_TRUE(c.has_mean);
  EXPECT_LE(test::max_abs_diff(c.mean.tensor, c.integral.tensor / 0.25), 1e-15);
  EXPECT_NEAR(c.mean.von_mises, c.integral.von_mises / 0.25, 1e-14);
  EXPECT_THROW(constraint_stress(lambda, s.R_space_body, -1.0), InvalidInput);
  EXPECT_THROW(steady_spin_stress_integral_body(body.poinsot(), Vec3::Zero(), 1.0), InvalidInput);
}

}  // namespace
}  // namespace poinsot::analysis
