// dlm: order 2 measured against a dop853 reference; invariants over a long run at 1/200 of the rotation
// period (energy bounded, L_space and orthogonality at round-off); a body frame that is not principal gives
// the same motion; torques by Strang kicks keep order 2; gravity keeps the heavy top's energy bounded.
#include "poinsot/dynamics/dlm.hpp"

#include <gtest/gtest.h>

#include "dynamics_test_util.hpp"
#include "poinsot/so3/projection.hpp"
#include "poinsot_test.hpp"

namespace poinsot::test {
namespace {

using dynamics::DlmIntegrator;

TEST(Dlm, ConvergesAtOrderTwo) {
  // Errors ~1e-4..1e-5 ≫ the reference's: the ratio is 2² up to O(h²) corrections.
  EXPECT_NEAR(order_against_reference<DlmIntegrator>(kBody, TorqueModel::none(), tumbling(), 2.0, 200), 2.0,
              0.05);
}

TEST(Dlm, ConvergesAtOrderTwoWithTorques) {
  const State s0 = tumbling();
  EXPECT_NEAR(order_against_reference<DlmIntegrator>(kBody, TorqueModel::constant_body(Vec3(0.1, -0.3, 0.2)),
                                                     s0, 2.0, 200),
              2.0, 0.05);
  EXPECT_NEAR(order_against_reference<DlmIntegrator>(kBody, TorqueModel::constant_space(Vec3(0.3, 0.1, -0.2)),
                                                     s0, 2.0, 200),
              2.0, 0.05);
  // A damping torque τ = −0.2 ω reads ω: the closing kick is implicit and the method stays symmetric.
  const auto damping = TorqueModel::callback(
      [](double, const Mat3&, const Vec3& w) { return Vec3(-0.2 * w); }, true, "damping");
  EXPECT_NEAR(order_against_reference<DlmIntegrator>(kBody, damping, s0, 2.0, 200), 2.0, 0.05);
}

TEST(Dlm, LongRunKeepsTheInvariants) {
  // The tennis racket (kg·m²) spun mostly about its intermediate axis, h = 1/200 of the rotation period
  // 2π/|ω|, 3·10⁴ steps (≈ 150 rotations, ≈ 25 flips). The 10⁶-step figures are measured by bench_dynamics.
  const RigidBody racket = RigidBody::from_principal_moments(Vec3(0.00121, 0.01638, 0.01748));
  State s;
  s.omega_body = Vec3(0.01, 2.0, 0.01);
  const double h = 2.0 * M_PI / s.omega_body.norm() / 200.0;
  DlmIntegrator dlm(racket, TorqueModel::none());
  const double E0 = dynamics::kinetic_energy(racket, s);
  const Vec3 L0 = dynamics::angular_momentum_space(racket, s);
  const int n = 30000;
  double e_first = 0.0, e_all = 0.0, L_err = 0.0;
  for (int i = 0; i < n; ++i) {
    dlm.step(s, h);
    const double e = std::abs(dynamics::kinetic_energy(racket, s) - E0) / E0;
    if (i < n / 10) e_first = std::max(e_first, e);
    e_all = std::max(e_all, e);
    L_err = std::max(L_err, (dynamics::angular_momentum_space(racket, s) - L0).norm() / L0.norm());
  }
  std::printf("dlm 3e4 steps: energy %.3g (first tenth %.3g), L_space %.3g, |RtR-I| %.3g\n", e_all, e_first,
              L_err, so3::orthogonality_error(s.R_space_body));
  // Bounded energy error: the whole run is no worse than its first tenth (a drift would be ten times worse).
  EXPECT_LT(e_all, 1.5 * e_first);
  EXPECT_LT(e_all, 1e-2);  // O((hω)²) with hω = 2π/200
  EXPECT_LT(L_err, 1e-12);
  EXPECT_LT(so3::orthogonality_error(s.R_space_body), 1e-13);
}

TEST(Dlm, NonPrincipalBodyFrameGivesTheSameMotion) {
  expect_same_motion_in_a_rotated_body_frame<DlmIntegrator>();
}

TEST(Dlm, AgreesWithTheAxisymmetricClosedForm) {
  const double A = 1.0, C = 1.8;  // docs/conventions.md case c
  const RigidBody body = RigidBody::from_principal_moments(Vec3(A, A, C));
  State s0;
  s0.omega_body = Vec3(1.0, 0.5, -2.0);
  DlmIntegrator a(body, TorqueModel::none());
  DlmIntegrator b(body, TorqueModel::none());
  const State exact = axisymmetric_exact(A, C, s0, 5.0);
  const double e1 = state_error(run_fixed(a, s0, 5.0, 1000), exact);
  const double e2 = state_error(run_fixed(b, s0, 5.0, 2000), exact);
  EXPECT_NEAR(measured_order(e1, e2), 2.0, 0.05);
  EXPECT_LT(e2, 1e-4);
}

TEST(Dlm, HeavyTopEnergyStaysBounded) {
  // A symmetric top (kg·m² about the centre of mass, 1 kg, centre of mass 0.1 m up its axis) tilted 60°
  // and spun at 50 rad/s, h = 1 ms: the gravity kicks are exact flows of the potential, so the total energy
  // error oscillates at O(h²) without drift. ω3 (conserved by the exact motion, τ3 = 0 and I1 = I2 about
  // the pivot) is kept to O(h²): the splitting rotates about the two equal axes separately.
  const HeavyTopCase top;
  const EnergyRun run = heavy_top_energy_run<DlmIntegrator>(top, 10000, 1e-3);
  EXPECT_LT(run.all_max, 1.5 * run.first_tenth_max);
  EXPECT_LT(run.all_max, 1e-3);
  EXPECT_NEAR(run.final_state.omega_body.z(), 50.0, 50.0 * 1e-5);
  EXPECT_NEAR(order_against_reference<DlmIntegrator>(top.body, top.gravity, top.initial, 0.5, 500), 2.0,
              0.05);
}

}  // namespace
}  // namespace poinsot::test
