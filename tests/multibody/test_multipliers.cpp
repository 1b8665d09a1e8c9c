// Multipliers: the steady conical pendulum's reaction (closed form), a free body's Λ against the single-body
// formula, and the integrator's stage multipliers converging to the exact ones.
#include "poinsot/multibody/multipliers.hpp"

#include <cmath>

#include "multibody_fixtures.hpp"
#include "poinsot/multibody/observables.hpp"
#include "poinsot/multibody/rattle.hpp"
#include "poinsot/so3/hat.hpp"
#include "poinsot_test.hpp"

namespace poinsot::multibody {
namespace {

using poinsot::so3::hat;
using test::kG;  // the fixtures' gravity, m/s²

TEST(Multipliers, ConicalPendulumReactionIsTheClosedForm) {
  const test::Conical c;
  const System s = c.system();
  const State st = c.state();
  check_consistent(s, st);
  const ExactMultipliers ex = exact_multipliers(s, st);
  const Vec3 F = c.reaction(st.bodies[0].x_space);
  EXPECT_NEAR(F.norm(), c.m * kG / std::cos(c.theta), 1e-12 * F.norm());  // the closed form's own check
  EXPECT_LT((ex.joint_force_space[0] - F).norm(), 1e-12 * F.norm());
  EXPECT_LT(ex.joint_torque_space[0].norm(), 1e-15);
  // Steady: no angular acceleration, the centre of mass accelerates centripetally.
  EXPECT_LT(ex.omega_dot_body[0].norm(), 1e-12);
  EXPECT_LT((ex.acceleration_space[0] - (F / c.m + Vec3(0, 0, -kG))).norm(), 1e-12 * kG);
}

TEST(Multipliers, ConicalPendulumStageReactionsTrackTheClosedFormAtSecondOrder) {
  const test::Conical c;
  const System s = c.system();
  auto max_error = [&](double h) {
    State st = c.state();
    Rattle rattle(s, h);
    Vec3 previous_velocity_stage = Vec3::Zero();
    double err = 0.0;
    for (int n = 0; n < static_cast<int>(std::lround(2.0 / h / test::slowdown())); ++n) {
      const Vec3 x = st.bodies[0].x_space;
      rattle.step(st);
      if (n > 0) {  // at t_n: mean of the velocity stage of step n−1 and the position stage of step n
        const Vec3 mean = 0.5 * (previous_velocity_stage + rattle.position_stage().joint_force_space[0]);
        err = std::max(err, (mean - c.reaction(x)).norm() / (c.m * kG));
      }
      previous_velocity_stage = rattle.velocity_stage().joint_force_space[0];
    }
    return err;
  };
  const double e1 = max_error(2e-3), e2 = max_error(1e-3);
  EXPECT_LT(e2, 1e-5);             // (Ωh)² ≈ 1.5e-5 scale
  EXPECT_NEAR(e1 / e2, 4.0, 0.6);  // second order
}

TEST(Multipliers, FreeBodyLambdaIsTheSingleBodyFormula) {
  // An unconnected asymmetric body and a lamina (singular K): Λ = (j(ω)² + j(ω̇)) K with ω̇ from Euler's
  // equations J ω̇ = −ω × J ω (docs/conventions.md conventions).
  System s;
  s.add_body_from_inertia("box", 1.5, Vec3(0.2, 0.3, 0.4).asDiagonal());
  s.add_body("plate", 0.8, Vec3(0.05, 0.02, 0.0).asDiagonal());
  State st;
  st.bodies.resize(2);
  st.bodies[0].omega_body = Vec3(1.0, -2.0, 0.5);
  st.bodies[0].R_space_body = poinsot::test::random_rotation();
  st.bodies[1].omega_body = Vec3(-0.4, 1.2, 2.0);
  st.bodies[1].x_space = Vec3(3, 0, 0);
  const ExactMultipliers ex = exact_multipliers(s, st);
  for (std::size_t i = 0; i < 2; ++i) {
    const Body& b = s.bodies()[i];
    const Vec3 w = st.bodies[i].omega_body;
    const Vec3 w_dot = b.inertia_inverse * (-w.cross(b.inertia * w));
    const Mat3 expected = (hat(w) * hat(w) + hat(w_dot)) * b.poinsot;
    EXPECT_LT(poinsot::test::max_abs_diff(ex.Lambda_body[i], expected), 1e-14 * expected.norm());
    EXPECT_LT(poinsot::test::max_abs_diff(ex.omega_dot_body[i], w_dot), 1e-14 * w.squaredNorm());
    // Virial identity of Vallée & Dumitriu: tr Λ = −2T (rotational kinetic energy T).
    EXPECT_NEAR(ex.Lambda_body[i].trace(), -w.dot(b.inertia * w), 1e-14 * w.squaredNorm());
  }
  // The integrator's multipliers (the symmetric part of its R-equations, no formula) converge to the same at
  // second order along the trajectory.
  auto max_error = [&](double h) {
    State run = st;
    Rattle rattle(s, h);
    Mat3 previous = Mat3::Zero();
    double err = 0.0;
    for (int n = 0; n < static_cast<int>(std::lround(1.0 / h)); ++n) {
      const State before = run;
      rattle.step(run);
      if (n > 0) {
        const Mat3 mean = 0.5 * (previous + rattle.position_stage().Lambda_body[1]);
        err = std::max(err, poinsot::test::max_abs_diff(mean, exact_multipliers(s, before).Lambda_body[1]));
      }
      previous = rattle.velocity_stage().Lambda_body[1];
    }
    return err;
  };
  const double e1 = max_error(4e-3), e2 = max_error(2e-3);
  EXPECT_LT(e2, 1e-4);
  EXPECT_NEAR(e1 / e2, 4.0, 0.6);
}

TEST(Multipliers, JointedFreeSystemLambdaIncludesTheJointLoads) {
  // Two bodies joined by a hinge, no gravity: Λ = (j(ω)² + j(ω̇))K − sym Φ_joint, and the reactions on the
  // two bodies are opposite, so the total force is zero (free system: m_a a_a + m_b a_b = 0).
  System s;
  s.add_body_from_inertia("a", 1.0, Vec3(0.1, 0.2, 0.25).asDiagonal());
  s.add_body_from_inertia("b", 2.0, Vec3(0.3, 0.3, 0.1).asDiagonal());
  s.add_hinge("h", 0, Vec3(0.3, 0, 0), Vec3(0, 0, 1), 1, Vec3(-0.2, 0, 0), Vec3(0, 0, 1));
  State st;
  st.bodies.resize(2);
  st.bodies[0].x_space = Vec3(-0.3, 0, 0);
  st.bodies[1].x_space = Vec3(0.2, 0, 0);
  const Vec3 Omega(0.3, 0.5, 1.0);
  st.bodies[0].omega_body = Omega;
  st.bodies[1].omega_body = Omega + Vec3(0, 0, 2.0);
  st.bodies[0].v_space = Omega.cross(st.bodies[0].x_space);
  st.bodies[1].v_space = Omega.cross(st.bodies[1].x_space) + Vec3(0, 0, 2.0).cross(Vec3(-0.2, 0, 0)) * -1.0;
  // Make the velocity consistent: the hinge point moves the same on both bodies.
  const Vec3 pa = st.bodies[0].v_space + Omega.cross(Vec3(0.3, 0, 0));
  const Vec3 pb = st.bodies[1].v_space + st.bodies[1].omega_body.cross(Vec3(-0.2, 0, 0));
  st.bodies[1].v_space += pa - pb;
  ASSERT_LT(constraint_violation(s, st).joint_velocity, 1e-15);
  const ExactMultipliers ex = exact_multipliers(s, st);
  const Vec3 total =
      s.bodies()[0].mass * ex.acceleration_space[0] + s.bodies()[1].mass * ex.acceleration_space[1];
  EXPECT_LT(total.norm(), 1e-13);
  EXPECT_GT(ex.joint_force_space[0].norm(), 0.1);  // the test is not vacuous
  // Λ of body a from its own pieces: the joint force at A and the hinge couple Σ λ_k n_k.
  const Body& a = s.bodies()[0];
  const Vec3 f_body = ex.joint_force_space[0];  // R = I
  const Mat3 W = hat(Omega);
  const Mat3 full = (W * W + hat(ex.omega_dot_body[0])) * a.poinsot;
  // The skew parts balance (Euler's equation): skew(full) = ½ j(torque of all loads).
  const Vec3 torque = Vec3(0.3, 0, 0).cross(f_body) + ex.joint_torque_space[0];
  EXPECT_LT((so3::vee(full - full.transpose()) - torque).norm(), 1e-12);
  // Λ = full − sym Φ is symmetric.
  EXPECT_LT(poinsot::test::max_abs_diff(ex.Lambda_body[0], ex.Lambda_body[0].transpose()), 1e-15);
}

}  // namespace
}  // namespace poinsot::multibody
