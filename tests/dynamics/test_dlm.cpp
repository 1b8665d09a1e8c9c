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

const RigidBody kBody = RigidBody::from_principal_moments(Vec3(1.0, 2.0, 3.0));
State tumbling() {
  State s;
  s.R = so3::exp(Vec3(0.3, -0.2, 0.5));
  s.omega_body = Vec3(1.0, 0.6, -0.8);
  return s;
}

double order_against_reference(const RigidBody& body, std::shared_ptr<const TorqueModel> tau, const State& s0,
                               double T, long long n) {
  const State ref = reference(body, tau, s0, T);
  DlmIntegrator a(body, tau);
  DlmIntegrator b(body, tau);
  const double e1 = state_error(run_fixed(a, s0, T, n), ref);
  const double e2 = state_error(run_fixed(b, s0, T, 2 * n), ref);
  return measured_order(e1, e2);
}

TEST(Dlm, ConvergesAtOrderTwo) {
  // Errors ~1e-4..1e-5 ≫ the reference's: the ratio is 2² up to O(h²) corrections.
  EXPECT_NEAR(order_against_reference(kBody, TorqueModel::none(), tumbling(), 2.0, 200), 2.0, 0.05);
}

TEST(Dlm, ConvergesAtOrderTwoWithTorques) {
  const State s0 = tumbling();
  EXPECT_NEAR(order_against_reference(kBody, TorqueModel::constant_body(Vec3(0.1, -0.3, 0.2)), s0, 2.0, 200),
              2.0, 0.05);
  EXPECT_NEAR(order_against_reference(kBody, TorqueModel::constant_space(Vec3(0.3, 0.1, -0.2)), s0, 2.0, 200),
              2.0, 0.05);
  // A damping torque τ = −0.2 ω reads ω: the closing kick is implicit and the method stays symmetric.
  const auto damping = TorqueModel::callback(
      [](double, const Mat3&, const Vec3& w) { return Vec3(-0.2 * w); }, true, "damping");
  EXPECT_NEAR(order_against_reference(kBody, damping, s0, 2.0, 200), 2.0, 0.05);
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
              L_err, so3::orthogonality_error(s.R));
  // Bounded energy error: the whole run is no worse than its first tenth (a drift would be ten times worse).
  EXPECT_LT(e_all, 1.5 * e_first);
  EXPECT_LT(e_all, 1e-2);  // O((hω)²) with hω = 2π/200
  EXPECT_LT(L_err, 1e-12);
  EXPECT_LT(so3::orthogonality_error(s.R), 1e-13);
}

TEST(Dlm, NonPrincipalBodyFrameGivesTheSameMotion) {
  // J = Q diag(1, 2, 3) Qᵀ in a body frame rotated by Q: R_b = R_p Qᵀ, ω_b = Q ω_p.
  const Mat3 Q = so3::exp(Vec3(0.4, -0.7, 0.2));
  const RigidBody rotated = RigidBody::from_inertia(Q * Vec3(1.0, 2.0, 3.0).asDiagonal() * Q.transpose());
  const State p0 = tumbling();
  State b0 = p0;
  b0.R = p0.R * Q.transpose();
  b0.omega_body = Q * p0.omega_body;
  DlmIntegrator a(kBody, TorqueModel::none());
  DlmIntegrator b(rotated, TorqueModel::none());
  const State p = run_fixed(a, p0, 3.0, 300);
  const State q = run_fixed(b, b0, 3.0, 300);
  // Same method in a rotated frame: equal to round-off (and to the eigen-decomposition's accuracy of P).
  EXPECT_LT(max_abs_diff(q.R, Mat3(p.R * Q.transpose())), 1e-12);
  EXPECT_LT(max_abs_diff(q.omega_body, Vec3(Q * p.omega_body)), 1e-12);
}

TEST(Dlm, AgreesWithTheAxisymmetricClosedForm) {
  const double A = 1.0, C = 1.8;  // ERRATA case c
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
  const RigidBody top =
      RigidBody::from_principal_moments(Vec3(0.002, 0.002, 0.004)).with_pivot(1.0, Vec3(0, 0, 0.1));
  const Vec3 g(0, 0, -9.81);
  const auto gravity = TorqueModel::gravity(top, g);
  State s;
  s.R = so3::exp(Vec3(M_PI / 3, 0, 0));
  s.omega_body = Vec3(0, 0, 50.0);
  DlmIntegrator dlm(top, gravity);
  const double E0 = dynamics::total_energy(top, s, g);
  const int n = 10000;
  double e_first = 0.0, e_all = 0.0;
  for (int i = 0; i < n; ++i) {
    dlm.step(s, 1e-3);
    const double e = std::abs(dynamics::total_energy(top, s, g) - E0) / std::abs(E0);
    if (i < n / 10) e_first = std::max(e_first, e);
    e_all = std::max(e_all, e);
  }
  EXPECT_LT(e_all, 1.5 * e_first);
  EXPECT_LT(e_all, 1e-3);
  EXPECT_NEAR(s.omega_body.z(), 50.0, 50.0 * 1e-5);
  EXPECT_NEAR(order_against_reference(top, gravity,
                                      State{0.0, so3::exp(Vec3(M_PI / 3, 0, 0)), Vec3(0, 0, 50)}, 0.5, 500),
              2.0, 0.05);
}

}  // namespace
}  // namespace poinsot::test
