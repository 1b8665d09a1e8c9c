// rk4: order 4 measured against a dop853 reference, orthogonality kept by renormalisation, energy drift
// recorded (the contrast with dlm and rattle), torques, the axisymmetric closed form.
#include "poinsot/dynamics/rk4.hpp"

#include <gtest/gtest.h>

#include "dynamics_test_util.hpp"
#include "poinsot/so3/projection.hpp"
#include "poinsot_test.hpp"

namespace poinsot::test {
namespace {

using dynamics::Rk4Integrator;

// A tumbling asymmetric body (no symmetry, ω not near a principal axis).
TEST(Rk4, ConvergesAtOrderFour) {
  const State s0 = tumbling();
  const double T = 2.0;
  const State ref = reference(kBody, TorqueModel::none(), s0, T);
  Rk4Integrator a(kBody, TorqueModel::none());
  Rk4Integrator b(kBody, TorqueModel::none());
  const double e1 = state_error(run_fixed(a, s0, T, 100), ref);
  const double e2 = state_error(run_fixed(b, s0, T, 200), ref);
  // Errors ~1e-7..1e-8 (far above the reference's 1e-13): the ratio is 2^4 up to O(h) corrections.
  EXPECT_NEAR(measured_order(e1, e2), 4.0, 0.15) << e1 << " " << e2;
}

TEST(Rk4, ConvergesAtOrderFourWithTorqueInSpace) {
  const State s0 = tumbling();
  const auto tau = TorqueModel::constant_space(Vec3(0.2, -0.1, 0.3));
  const double T = 2.0;
  const State ref = reference(kBody, tau, s0, T);
  Rk4Integrator a(kBody, tau);
  Rk4Integrator b(kBody, tau);
  const double e1 = state_error(run_fixed(a, s0, T, 100), ref);
  const double e2 = state_error(run_fixed(b, s0, T, 200), ref);
  EXPECT_NEAR(measured_order(e1, e2), 4.0, 0.15) << e1 << " " << e2;
}

TEST(Rk4, AgreesWithTheAxisymmetricClosedForm) {
  const double A = 2.0, C = 1.0;  // docs/conventions.md case b (prolate)
  const RigidBody body = RigidBody::from_principal_moments(Vec3(A, A, C));
  State s0;
  s0.omega_body = Vec3(0.3, -0.4, 1.2);
  Rk4Integrator rk4(body, TorqueModel::none());
  const State s = run_fixed(rk4, s0, 10.0, 2000);
  // h = 5 ms, |ω| ~ 1.3 rad/s: global error ~ (hω)⁴·t ~ 1e-9.
  EXPECT_LT(state_error(s, axisymmetric_exact(A, C, s0, 10.0)), 1e-8);
}

TEST(Rk4, KeepsTheRotationOrthogonalAndRecordsItsEnergyDrift) {
  // The tennis racket at 1/200 of the period of its spin (2 rad/s → T ≈ 3.1 s, h = 0.0157 s) for 2·10⁴ steps:
  // rk4 is not symplectic, its energy error grows secularly, whereas dlm and rattle stay bounded (see
  // test_dlm / test_rattle). The drift is recorded here so the contrast is visible.
  const RigidBody racket = RigidBody::from_principal_moments(Vec3(0.00121, 0.01638, 0.01748));
  State s;
  s.omega_body = Vec3(0.4, 0.2, 2.0);
  const double h = 2.0 * M_PI / 2.0 / 200.0;
  Rk4Integrator rk4(racket, TorqueModel::none());
  const double E0 = dynamics::kinetic_energy(racket, s);
  double drift_first = 0.0, drift_last = 0.0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    rk4.step(s, h);
    const double e = std::abs(dynamics::kinetic_energy(racket, s) - E0) / E0;
    if (i < n / 10) drift_first = std::max(drift_first, e);
    drift_last = std::max(drift_last, e);
  }
  RecordProperty("rk4_energy_drift_first_tenth", std::to_string(drift_first));
  RecordProperty("rk4_energy_drift_total", std::to_string(drift_last));
  std::printf("rk4 energy error: max %.3g over the first %d steps, %.3g over %d steps\n", drift_first, n / 10,
              drift_last, n);
  EXPECT_LT(so3::orthogonality_error(s.R_space_body), 1e-14);  // renormalised quaternion
  // A drift, not an oscillation: the error keeps growing (ten times the steps, several times the error).
  EXPECT_GT(drift_last, 3.0 * drift_first);
}

TEST(Rk4, RejectsANonPositiveStep) {
  IntegratorOptions o;
  o.dt = 0.0;
  EXPECT_THROW(Rk4Integrator(kBody, TorqueModel::none(), o), InvalidInput);
}

TEST(Rk4, ResumesFromAStateItDidNotProduce) {
  // Changing the state between steps (as a user may) must be honoured, not overwritten by the cached one.
  Rk4Integrator rk4(kBody, TorqueModel::none());
  State s = tumbling();
  rk4.step(s, 0.01);
  State other = tumbling();
  other.time = s.time;
  rk4.step(other, 0.01);
  Rk4Integrator fresh(kBody, TorqueModel::none());
  State expect = tumbling();
  expect.time = other.time - 0.01;
  fresh.step(expect, 0.01);
  EXPECT_LT(max_abs_diff(other.omega_body, expect.omega_body), 1e-15);
}

TEST(Rk4, NonPrincipalBodyFrameGivesTheSameMotion) {
  expect_same_motion_in_a_rotated_body_frame<Rk4Integrator>();
}

}  // namespace
}  // namespace poinsot::test
