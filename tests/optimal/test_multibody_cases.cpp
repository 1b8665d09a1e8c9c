// Optimal motions of coupled bodies, the cases: the spacecraft with a reaction wheel (a free-floating system
// whose final conditions leave the wheel angle free and skip the conserved momenta) against the closed form
// of the equivalent single axis (the bounded case against the single-body optimum of the same effective
// inertia is measured by bench/bench_optimal_multibody: its solve takes minutes); the arm with a free elbow
// angle. The falling cat is tested in test_falling_cat.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "multibody_test_problems.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/multibody/observables.hpp"
#include "poinsot/optimal/multibody_direct.hpp"
#include "poinsot/so3/distance.hpp"
#include "poinsot_test.hpp"

namespace poinsot::optimal {
namespace {

TEST(MultibodyCases, ReactionWheelUnboundedIsTheSingleAxisClosedForm) {
  // Θ = 1 rad in 10 s with a bound above the unbounded peak 6IΘ/T² = 0.12 N·m: the bus follows the
  // single-axis optimum, cost 12 I² Θ² / T³ with I = I_bus,zz = 2 kg·m².
  const double theta = 1.0, T = 10.0, I = 2.0;
  const MultibodyProblem p = testing::reaction_wheel(theta, T, 1.0, 8);
  const MultibodyOptimum r = testing::solve_in(p, MultibodyCoordinates::rotation_matrix);
  ASSERT_TRUE(r.converged) << r.status;
  const double exact = 12.0 * I * I * theta * theta / (T * T * T);
  EXPECT_NEAR(r.cost / exact, 1.0, 1e-3) << r.cost;
  // The bus reaches the target; the wheel ends wherever the conserved angular momentum puts it. H (zero at
  // the start) is not an NLP row: along the collocated motion it is kept to the transcription's error
  // (measured 6.9e-5 kg·m²/s at N = 8, against a peak wheel momentum of 0.3 kg·m²/s).
  EXPECT_LT(so3::angle_between(r.states.back().bodies[0].R_space_body, p.final_state.bodies[0].R_space_body),
            1e-8);
  for (const multibody::State& s : r.states)
    EXPECT_LT(multibody::angular_momentum(p.system, s).norm(), 2e-4) << "t = " << s.time;
  // Re-simulated by the projected RK4: the bus misses its target by the transcription's error (measured
  // 2.1e-5 rad, 2.6e-5 rad/s), the wheel's axis and spin rate likewise; the joint stays closed and the
  // momenta stay zero at round-off (the motion is about z alone, where H_z = Σ J_zz ω_z is a linear invariant
  // that Runge–Kutta methods keep exactly).
  const MultibodyReplay replay = replay_controls(p, r, 32);
  EXPECT_LT(replay.attitude_error, 1e-4);
  EXPECT_LT(replay.velocity_error, 1e-4);
  EXPECT_LT(replay.position_error, 1e-12);
  EXPECT_LT(replay.max_joint_gap, 1e-12);
  EXPECT_LT(replay.max_momentum_change, 1e-12);
  // The final conditions: 3 attitude rows and 1 rate row (14 tangent directions, less 9 fixed by P, H and the
  // centre of mass, less the wheel angle); the other 10 are reached by the dynamics alone, so the rates at T
  // vanish to the error with which the transcription keeps H (measured 1.1e-5 rad/s).
  EXPECT_LT(r.states.back().bodies[0].omega_body.norm(), 1e-4);
  EXPECT_LT(std::abs(r.states.back().bodies[1].omega_body.z()), 1e-4);
}

TEST(MultibodyCases, FreeElbowAngleInMinimalCoordinates) {
  if (::poinsot::test::sanitized())
    GTEST_SKIP()
        << "about 2 s in release, 12 s under ASan; the other arm tests cover the minimal transcription there";
  // The arm with the elbow's final angle left free (its rate still zero at T): a relaxation of the fixed
  // problem, so its optimum costs no more; the shoulder reaches its target and both rates vanish (NLP rows,
  // to Ipopt's tolerance), and the elbow ends elsewhere than the fixed problem's target.
  MultibodyProblem p = testing::two_link_arm(1.0, 0.5, 1.5, 8);
  MultibodyOptions o;
  o.coordinates = MultibodyCoordinates::minimal;
  const MultibodyOptimum fixed = solve_multibody(p, o);
  p.free_final_hinges = {1};
  const MultibodyOptimum free = solve_multibody(p, o);
  ASSERT_TRUE(fixed.converged) << fixed.status;
  ASSERT_TRUE(free.converged) << free.status;
  EXPECT_LT(free.cost, fixed.cost);
  const multibody::State& end = free.states.back();
  EXPECT_LT(so3::angle_between(end.bodies[0].R_space_body, p.final_state.bodies[0].R_space_body), 1e-8);
  EXPECT_LT(end.bodies[0].omega_body.norm(), 1e-8);
  EXPECT_LT(end.bodies[1].omega_body.norm(), 1e-8);
  EXPECT_GT(so3::angle_between(end.bodies[1].R_space_body, p.final_state.bodies[1].R_space_body), 1e-3);
}

TEST(MultibodyCases, ReactionWheelBadInput) {
  const MultibodyProblem p = testing::reaction_wheel(1.0, 10.0, 1.0, 4);
  MultibodyProblem q = p;
  q.final_state.bodies[1].omega_body.z() = 0.5;  // the wheel spinning at T: H would have to change
  EXPECT_THROW(
      {
        try {
          solve_multibody(q);
        } catch (const InvalidInput& e) {
          EXPECT_NE(std::string(e.what()).find("final state: its momenta"), std::string::npos) << e.what();
          throw;
        }
      },
      InvalidInput);
  q = p;
  q.free_final_hinges = {3};
  EXPECT_THROW(solve_multibody(q), InvalidInput);
  q = p;
  q.actuators[0].kind = ActuatorKind::ball_torque;  // on the wheel's hinge
  try {
    solve_multibody(q);
    ADD_FAILURE() << "expected InvalidInput";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("actuators[0]: joint: got index 0; expected a ball joint"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace poinsot::optimal
