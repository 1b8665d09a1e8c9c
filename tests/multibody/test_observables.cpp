// Energy, momenta and constraint violation against hand computations.
#include "poinsot/multibody/observables.hpp"

#include "poinsot/core/error.hpp"
#include "poinsot/so3/hat.hpp"
#include "poinsot_test.hpp"

namespace poinsot::multibody {
namespace {

TEST(Observables, KineticEnergyIsTheTraceFormOfTheTwelveCoordinates) {
  // ½ m|v|² + ½ tr(Ṙ K Ṙᵀ) with Ṙ = R j(ω) equals ½ m|v|² + ½ ωᵀJω.
  System s;
  s.add_body("a", 2.0, Vec3(0.3, 0.2, 0.05).asDiagonal());
  State st;
  st.bodies.resize(1);
  st.bodies[0].R_space_body = poinsot::test::random_rotation();
  st.bodies[0].v_space = Vec3(1, 2, 3);
  st.bodies[0].omega_body = Vec3(-1, 0.5, 2);
  const Mat3 Rdot = st.bodies[0].R_space_body * so3::hat(st.bodies[0].omega_body);
  const double T = 0.5 * 2.0 * 14.0 + 0.5 * (Rdot * s.bodies()[0].poinsot * Rdot.transpose()).trace();
  EXPECT_NEAR(kinetic_energy(s, st), T, 1e-14 * T);
  s.set_gravity(Vec3(0, 0, -9.81));
  st.bodies[0].x_space = Vec3(0, 0, 2);
  EXPECT_NEAR(total_energy(s, st), T + 2.0 * 9.81 * 2, 1e-13);
  EXPECT_LT((linear_momentum(s, st) - Vec3(2, 4, 6)).norm(), 1e-15);
  const Vec3 L = Vec3(0, 0, 2).cross(Vec3(2, 4, 6)) +
                 st.bodies[0].R_space_body * (s.bodies()[0].inertia * st.bodies[0].omega_body);
  EXPECT_LT((angular_momentum(s, st) - L).norm(), 1e-14);
}

TEST(Observables, ViolationsAreMeasuredAndInconsistentStatesRejected) {
  System s;
  s.add_body("a", 1.0, Mat3::Identity());
  s.add_ball("p", 0, Vec3(1, 0, 0), kWorld, Vec3::Zero());
  State st;
  st.bodies.resize(1);
  st.bodies[0].x_space = Vec3(-1, 0, 0.003);
  st.bodies[0].v_space = Vec3(0, 0, 0.5);
  const ConstraintViolation v = constraint_violation(s, st);
  EXPECT_NEAR(v.joint_gap, 0.003, 1e-15);
  EXPECT_NEAR(v.joint_velocity, 0.5, 1e-15);
  EXPECT_THROW(check_consistent(s, st), InvalidInput);
  st.bodies[0].x_space = Vec3(-1, 0, 0);
  EXPECT_NO_THROW(check_consistent(s, st));
  st.bodies[0].R_space_body(0, 0) = 1.001;
  EXPECT_THROW(check_consistent(s, st), InvalidInput);
  st.bodies.clear();
  EXPECT_THROW(check_consistent(s, st), InvalidInput);
}

}  // namespace
}  // namespace poinsot::multibody
