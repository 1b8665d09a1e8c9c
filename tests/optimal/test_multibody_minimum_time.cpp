// Minimum time for coupled bodies: one rod on a hinge, gravity off, rest to rest through Θ with |u| ≤ ū,
// whose optimum is bang-bang (u = ū, then −ū from T/2) with T* = 2 √(Θ I / ū), I the inertia about the hinge.
// Both transcriptions with a free final time against T*, the mesh's blur of the switch shrinking with N, the
// re-simulation of the control history, the energy regularisation, and the bad inputs. (The exactness of the
// derivatives with respect to T: test_hermite_simpson_nlp.cpp.)
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "multibody_test_problems.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/optimal/multibody_direct.hpp"
#include "poinsot_test.hpp"

namespace poinsot::optimal {
namespace {

constexpr double kTurnAngle = 1.0;    // rad
constexpr double kTorqueBound = 1.0;  // N·m

MultibodyProblem fastest_turn(int intervals, double energy_weight = 0.0) {
  MultibodyProblem p = testing::single_hinge(kTurnAngle, 1.0, intervals);
  p.actuators[0].torque_max = kTorqueBound;
  p.objective = MultibodyObjective::minimum_time;
  p.final_time_min = 0.1;
  p.final_time_max = 10.0;
  p.energy_weight = energy_weight;
  return p;
}

double bang_bang_time() {
  return 2.0 * std::sqrt(kTurnAngle * testing::single_hinge_inertia() / kTorqueBound);
}

TEST(MultibodyMinimumTime, AnOddMeshBlursTheSwitchByOrderHSquared) {
  if (::poinsot::test::sanitized())
    GTEST_SKIP()
        << "three meshes: 0.4 s in release, 27 s under ASan; the even-mesh and R-coordinate tests run "
           "the same transcription there";
  // With N odd the switch at T/2 falls on the midpoint of the middle interval, where the control is a
  // quadratic through the node values ±ū: the mesh cannot jump, and the transcription's T exceeds T* by
  // about 0.19/N² s (measured 3.95e-3, 8.57e-4, 2.00e-4 s at N = 7, 15, 31: the ratios 4.6 and 4.3 of an
  // order-2 blur; T* = 1.155783 s). The bounds 0.1/N² and 0.3/N² check the order and the constant.
  const double T_star = bang_bang_time();
  for (const int n : {7, 15, 31}) {
    const MultibodyProblem p = fastest_turn(n);
    const MultibodyOptimum r = testing::solve_in(p, MultibodyCoordinates::minimal);
    ASSERT_TRUE(r.converged) << r.status;
    const double T = r.time.back();
    EXPECT_DOUBLE_EQ(r.cost, T);  // ε = 0: the objective is T
    EXPECT_GT(T - T_star, 0.1 / (n * n)) << "N = " << n;
    EXPECT_LT(T - T_star, 0.3 / (n * n)) << "N = " << n;
    // Saturated away from the switch: u = ū at the first midpoint, −ū at the last.
    EXPECT_NEAR(r.controls[1](0), kTorqueBound, 1e-6);
    EXPECT_NEAR(r.controls[r.controls.size() - 2](0), -kTorqueBound, 1e-6);
    // The re-simulated control reaches the target: the blur is in the transcription's own control, which
    // the replay follows (measured attitude errors 3.4e-6, 7.3e-7, 1.8e-7 rad).
    EXPECT_LT(replay_controls(p, r, 64).attitude_error, 1e-5) << "N = " << n;
  }
}

TEST(MultibodyMinimumTime, AnEvenMeshPutsTheSwitchOnANodeAndMeetsTheBangBangTime) {
  // With N even the switch falls on the middle node, whose control (shared by its two intervals) takes 0:
  // the two quadratics through (ū, ū, 0) and (0, −ū, −ū) carry the exact impulse in θ̈ = u/I, so in minimal
  // coordinates T = T* to Ipopt's tolerance (measured T − T* = −5.5e-9 s at N = 16).
  const MultibodyOptimum r = testing::solve_in(fastest_turn(16), MultibodyCoordinates::minimal);
  ASSERT_TRUE(r.converged) << r.status;
  EXPECT_NEAR(r.time.back(), bang_bang_time(), 1e-7);
  EXPECT_NEAR(r.controls[16](0), 0.0, 1e-6);
}

TEST(MultibodyMinimumTime, RotationMatrixTranscriptionAgreesAndItsControlReachesTheTarget) {
  const int n = 15;
  const MultibodyProblem p = fastest_turn(n);
  const MultibodyOptimum r = testing::solve_in(p, MultibodyCoordinates::rotation_matrix);
  ASSERT_TRUE(r.converged) << r.status;
  // The same blur of the switch as in minimal coordinates plus R-coordinates' own transcription error (cos θ,
  // sin θ are not polynomials): measured T − T* = 8.60e-4 s against 8.57e-4 in minimal coordinates.
  EXPECT_GT(r.time.back() - bang_bang_time(), 0.1 / (n * n));
  EXPECT_LT(r.time.back() - bang_bang_time(), 0.3 / (n * n));
  // Re-simulated by the projected RK4 from the control history over the optimum's own T (64 steps per
  // interval): the target is missed by the transcription's error (measured 4.8e-6 rad, 2.9e-7 rad/s).
  const MultibodyReplay replay = replay_controls(p, r, 64);
  EXPECT_LT(replay.attitude_error, 1e-4);
  EXPECT_LT(replay.velocity_error, 1e-4);
  EXPECT_LT(replay.max_joint_gap, 1e-12);
}

TEST(MultibodyMinimumTime, EnergyRegularisationTradesTimeForEffort) {
  if (::poinsot::test::sanitized())
    GTEST_SKIP() << "0.3 s in release, 13 s under ASan; the even-mesh and R-coordinate tests run the same "
                    "transcription there";
  // T + ε ∫u²dt: the regularised optimum is slower than the pure one and uses less than ū² T of effort.
  const MultibodyOptimum pure = testing::solve_in(fastest_turn(15), MultibodyCoordinates::minimal);
  const MultibodyOptimum soft = testing::solve_in(fastest_turn(15, 1.0), MultibodyCoordinates::minimal);
  ASSERT_TRUE(pure.converged && soft.converged) << soft.status;
  const double T = soft.time.back();
  EXPECT_GT(T, pure.time.back());
  const double effort = soft.cost - T;  // ε = 1
  EXPECT_GT(effort, 0.0);
  EXPECT_LT(effort, kTorqueBound * kTorqueBound * T);
}

void expect_time_refused(const MultibodyProblem& p, const std::string& message) {
  try {
    validate(p);
    ADD_FAILURE() << "accepted; expected: " << message;
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
  }
}

TEST(MultibodyMinimumTime, RefusesInconsistentTimeBoundsAndUnboundedTorques) {
  MultibodyProblem p = fastest_turn(8);
  p.final_time_max = 0.05;
  expect_time_refused(p, "final_time: got the bounds [0.1, 0.05] s");
  p = fastest_turn(8);
  p.final_time = 20.0;
  expect_time_refused(p, "expected 0 < final_time_min ≤ final_time ≤ final_time_max");
  p = fastest_turn(8);
  p.energy_weight = -1.0;
  expect_time_refused(p, "energy_weight: got -1");
  p = fastest_turn(8);
  p.actuators[0].torque_max = std::numeric_limits<double>::infinity();
  expect_time_refused(p, "torque_max: got inf N·m; expected a finite bound");
}

}  // namespace
}  // namespace poinsot::optimal
