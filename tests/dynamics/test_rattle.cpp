// rattle: order 2 in the state and in the multiplier Λ (against (j(ω)² + j(ω̇))K from a dop853 reference),
// the plane lamina (K singular), invariants over a long run, gravity, the axisymmetric closed form, and a
// Newton failure reported with its time.
#include "poinsot/dynamics/rattle.hpp"

#include <gtest/gtest.h>

#include "dynamics_test_util.hpp"
#include "poinsot/so3/projection.hpp"
#include "poinsot_test.hpp"

namespace poinsot::test {
namespace {

using dynamics::RattleIntegrator;

/// Λ = (j(ω)² + j(ω̇))K with J ω̇ = τ − ω × Jω (docs/conventions.md conventions).
Mat3 exact_multiplier(const RigidBody& body, const TorqueModel& tau, const State& s) {
  const Vec3& w = s.omega_body;
  const Vec3 wdot =
      body.inertia_inverse() * (tau.torque_body(s.time, s.R_space_body, w) - w.cross(body.inertia() * w));
  const Mat3 jw = so3::hat(w);
  return (jw * jw + so3::hat(wdot)) * body.poinsot();
}

/// The error of the multiplier of the last of n steps to T, against the reference at the step's midpoint.
double multiplier_error(const RigidBody& body, std::shared_ptr<const TorqueModel> tau, const State& s0,
                        double T, long long n) {
  RattleIntegrator m(body, tau);
  run_fixed(m, s0, T, n);
  Mat3 lambda;
  EXPECT_TRUE(m.last_multiplier(lambda));
  const double t_mid = T - 0.5 * T / static_cast<double>(n);
  const Mat3 ref = exact_multiplier(body, *tau, reference(body, tau, s0, t_mid));
  return (lambda - ref).norm() / ref.norm();
}

TEST(Rattle, ConvergesAtOrderTwo) {
  EXPECT_NEAR(order_against_reference<RattleIntegrator>(kBody, TorqueModel::none(), tumbling(), 2.0, 200),
              2.0, 0.05);
}

TEST(Rattle, ConvergesAtOrderTwoWithTorques) {
  const State s0 = tumbling();
  EXPECT_NEAR(order_against_reference<RattleIntegrator>(
                  kBody, TorqueModel::constant_space(Vec3(0.3, 0.1, -0.2)), s0, 2.0, 200),
              2.0, 0.05);
  const auto damping = TorqueModel::callback(
      [](double, const Mat3&, const Vec3& w) { return Vec3(-0.2 * w); }, true, "damping");
  EXPECT_NEAR(order_against_reference<RattleIntegrator>(kBody, damping, s0, 2.0, 200), 2.0, 0.05);
}

TEST(Rattle, MultiplierConvergesAtOrderTwo) {
  const State s0 = tumbling();
  const auto none = TorqueModel::none();
  const double e1 = multiplier_error(kBody, none, s0, 2.0, 200);
  const double e2 = multiplier_error(kBody, none, s0, 2.0, 400);
  EXPECT_NEAR(measured_order(e1, e2), 2.0, 0.1) << e1 << " " << e2;
  EXPECT_LT(e2, 1e-3);
  // With a torque the kicks add j(J⁻¹τ̄)K, and Λ is no longer symmetric (Λ − Λᵀ = j(τ)).
  const auto tau = TorqueModel::constant_body(Vec3(0.4, -0.2, 0.3));
  const double f1 = multiplier_error(kBody, tau, s0, 2.0, 200);
  const double f2 = multiplier_error(kBody, tau, s0, 2.0, 400);
  EXPECT_NEAR(measured_order(f1, f2), 2.0, 0.1) << f1 << " " << f2;
}

TEST(Rattle, NoMultiplierBeforeTheFirstStep) {
  RattleIntegrator m(kBody, TorqueModel::none());
  Mat3 lambda;
  EXPECT_FALSE(m.last_multiplier(lambda));
}

TEST(Rattle, WorksForAPlaneLamina) {
  // Principal moments (1, 2, 3) kg·m²: I1 + I2 = I3, a plane lamina, K = diag(2, 1, 0) singular.
  const RigidBody lamina = RigidBody::from_principal_moments(Vec3(1.0, 2.0, 3.0));
  ASSERT_NEAR(lamina.poinsot()(2, 2), 0.0, 1e-15);
  const State s0 = tumbling();
  EXPECT_NEAR(order_against_reference<RattleIntegrator>(lamina, TorqueModel::none(), s0, 2.0, 200), 2.0,
              0.05);
  RattleIntegrator m(lamina, TorqueModel::none());
  const State s = run_fixed(m, s0, 5.0, 1000);
  Mat3 lambda;
  ASSERT_TRUE(m.last_multiplier(lambda));
  // Λ = (…)K has a zero last column (K e3 = 0) and, being symmetric (free body), a zero last row.
  EXPECT_LT(lambda.col(2).norm(), 1e-12 * lambda.norm());
  EXPECT_LT(lambda.row(2).norm(), 1e-12 * lambda.norm());
  EXPECT_LT(so3::orthogonality_error(s.R_space_body), 1e-14);
}

TEST(Rattle, LongRunKeepsTheInvariants) {
  // As in test_dlm: the tennis racket at 1/200 of its rotation period, 3·10⁴ steps (10⁶ in bench_dynamics).
  const RigidBody racket = RigidBody::from_principal_moments(Vec3(0.00121, 0.01638, 0.01748));
  State s;
  s.omega_body = Vec3(0.01, 2.0, 0.01);
  const double h = 2.0 * M_PI / s.omega_body.norm() / 200.0;
  RattleIntegrator rattle(racket, TorqueModel::none());
  const double E0 = dynamics::kinetic_energy(racket, s);
  const Vec3 L0 = dynamics::angular_momentum_space(racket, s);
  const int n = 30000;
  double e_first = 0.0, e_all = 0.0, L_err = 0.0;
  for (int i = 0; i < n; ++i) {
    rattle.step(s, h);
    const double e = std::abs(dynamics::kinetic_energy(racket, s) - E0) / E0;
    if (i < n / 10) e_first = std::max(e_first, e);
    e_all = std::max(e_all, e);
    L_err = std::max(L_err, (dynamics::angular_momentum_space(racket, s) - L0).norm() / L0.norm());
  }
  std::printf("rattle 3e4 steps: energy %.3g (first tenth %.3g), L_space %.3g, |RtR-I| %.3g\n", e_all,
              e_first, L_err, so3::orthogonality_error(s.R_space_body));
  // Bounded: no worse than the first tenth of the run, or at round-off. (For the free body the discrete
  // Moser–Veselov map conserves the kinetic energy itself: the error is round-off, ~1e-14.)
  EXPECT_LT(e_all, std::max(1.5 * e_first, 1e-12));
  EXPECT_LT(e_all, 1e-2);
  EXPECT_LT(L_err, 1e-12);
  EXPECT_LT(so3::orthogonality_error(s.R_space_body), 1e-13);
}

TEST(Rattle, AgreesWithTheAxisymmetricClosedForm) {
  const double A = 2.0, C = 1.0;  // docs/conventions.md case b
  const RigidBody body = RigidBody::from_principal_moments(Vec3(A, A, C));
  State s0;
  s0.omega_body = Vec3(0.3, -0.4, 1.2);
  RattleIntegrator a(body, TorqueModel::none());
  RattleIntegrator b(body, TorqueModel::none());
  const State exact = axisymmetric_exact(A, C, s0, 5.0);
  const double e1 = state_error(run_fixed(a, s0, 5.0, 500), exact);
  const double e2 = state_error(run_fixed(b, s0, 5.0, 1000), exact);
  EXPECT_NEAR(measured_order(e1, e2), 2.0, 0.05);
}

TEST(Rattle, HeavyTopEnergyStaysBounded) {
  const HeavyTopCase top;
  const EnergyRun run = heavy_top_energy_run<RattleIntegrator>(top, 10000, 1e-3);
  EXPECT_LT(run.all_max, 1.5 * run.first_tenth_max);
  EXPECT_LT(run.all_max, 1e-3);
  EXPECT_NEAR(order_against_reference<RattleIntegrator>(top.body, top.gravity, top.initial, 0.5, 500), 2.0,
              0.05);
}

TEST(Rattle, ReportsANewtonFailureWithItsTime) {
  IntegratorOptions o;
  o.newton_max_iterations = 1;  // one iteration cannot reach 1e-14
  RattleIntegrator m(kBody, TorqueModel::none(), o);
  State s = tumbling();
  s.time = 1.25;
  POINSOT_EXPECT_THROWS_MESSAGE(m.step(s, 0.01), ComputationFailed, "t = 1.25 s");
}

TEST(Rattle, NonPrincipalBodyFrameGivesTheSameMotion) {
  expect_same_motion_in_a_rotated_body_frame<RattleIntegrator>();
}

}  // namespace
}  // namespace poinsot::test
