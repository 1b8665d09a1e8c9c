// The first mesh solved from several guesses (CollocationOptions::starts), through the whole run of
// `poinsot optimize`. Oracles: on a spinning start whose first guess lies in the basin of a local optimum
// 11 % above another, the run from one guess ends with the higher direct optimum (unverified), and from four
// it continues from the lowest first-mesh optimum to an extremal that the minimum principle and an
// independent re-simulation (DOP853) verify; on a sphere, whose optimum is the eigenaxis rotation whatever
// the transverse bump, every start reaches the same optimum and the first guess is kept.
#include "poinsot/io/run/optimal_run.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "poinsot/core/error.hpp"
#include "poinsot/core/types.hpp"
#include "poinsot/optimal/direct_collocation.hpp"
#include "poinsot_test.hpp"

namespace poinsot::io {
namespace {

// A minimum-time slew from a spin (problem 0 of seed 5 of the benchmark's spin family).
constexpr const char* kSpinningStart = R"(
[body]
principal_moments = [0.5237635626751175, 1.5377236929568319, 1.7330131356814409]
[optimal_control]
objective = "minimum_time"
torque_bound = "per_axis"
torque_max = [1.319743885522331, 0.9886239387933974, 1.2104550924499842]
[optimal_control.initial]
omega_body = [-0.40959180269660017, 0.6385907266657693, 0.4157446279534912]
[optimal_control.final]
orientation = { axis_angle = { axis = [0.011830933327007048, -0.525502300563717, -0.8507099159636338], angle = 1.7941556993034453 } }
)";

std::string with_key(const std::string& scenario, const std::string& line) {
  std::string s = scenario;
  const std::string section = "[optimal_control]\n";
  return s.insert(s.find(section) + section.size(), line + "\n");
}

TEST(OptimalStarts, TheLowestFirstMeshOptimumLeadsToAVerifiedExtremalThatOneGuessMisses) {
  const OptimalRun one =
      run_optimal(parse_optimal_scenario(with_key(kSpinningStart, "starts = 1"), "s.toml", "."));
  EXPECT_TRUE(one.direct.first_mesh_starts.empty());
  const OptimalRun four = run_optimal(parse_optimal_scenario(kSpinningStart, "s.toml", "."));
  ASSERT_EQ(four.scenario.collocation.starts, 4);
  ASSERT_TRUE(four.optimal) << four.status;
  EXPECT_TRUE(four.verification.passed);

  const auto& starts = four.direct.first_mesh_starts;
  ASSERT_EQ(starts.size(), 4u);
  const auto lowest = std::min_element(starts.begin(), starts.end(),
                                       [](const auto& a, const auto& b) { return a.cost < b.cost; });
  EXPECT_EQ(four.direct.chosen_start, lowest - starts.begin());
  EXPECT_NE(four.direct.chosen_start, 0) << "the first guess is in the other basin";
  for (int k = 0; k < 4; ++k) {
    EXPECT_TRUE(starts[k].solved) << k;
    EXPECT_NEAR(starts[k].turn, k * std::numbers::pi / 2.0, 1e-15);
  }
  // The first guess's first-mesh optimum is the one the single start refines: distinct local optima,
  // not rounding (kDistinctFirstMeshOptima).
  EXPECT_GT(starts[0].cost, 1.05 * lowest->cost);
  // The run from one guess ends at the higher optimum, which the shooting cannot verify; the verified
  // extremal of the four starts is shorter by more than the direct method's error (the mesh error times T).
  EXPECT_NE(one.outcome, OptimalOutcome::optimal) << one.status;
  EXPECT_LT(four.indirect.cost, 0.95 * one.direct.cost);
  test::expect_has(optimal_report(four), {"first mesh from 4 starts", "refined from the start at"});
  test::expect_has(optimal_summary_json(four), {"\"first_mesh_starts\"", "\"chosen_start\""});
}

// The sphere (J = 2.5 kg·m²) turned by 2 rad in 3 s at minimum energy under a norm bound: every transverse
// bump leads to the same eigenaxis optimum, 12 J² Θ²/T³; the starts agree far within kDistinctFirstMeshOptima
// and the first is kept.
TEST(OptimalStarts, StartsThatReachTheSameOptimumKeepTheFirst) {
  optimal::ReorientationProblem p;
  p.inertia_body = 2.5 * Mat3::Identity();
  p.objective = optimal::Objective::minimum_energy;
  p.bound = optimal::TorqueBound::norm;
  p.torque_max = Vec3::Constant(100.0);
  p.final_time = 3.0;
  p.attitude_final = Quat(Eigen::AngleAxisd(2.0, Vec3(1.0, -2.0, 0.5).normalized()));
  optimal::CollocationOptions o;
  o.max_mesh_iterations = 1;
  const optimal::DirectSolution d = optimal::solve_direct(p, o);
  ASSERT_EQ(d.first_mesh_starts.size(), 4u);
  EXPECT_EQ(d.chosen_start, 0);
  for (const auto& s : d.first_mesh_starts) {
    EXPECT_TRUE(s.solved);
    EXPECT_NEAR(s.cost / d.first_mesh_starts[0].cost, 1.0, 1e-8);
  }
  EXPECT_EQ(d.cost, d.first_mesh_starts[0].cost) << "the refinement took over the first start's run";
  // The first mesh (10 intervals) holds the eigenaxis optimum to Hermite–Simpson's error there, 4.1e-6
  // (relative).
  EXPECT_NEAR(d.cost / (12.0 * 2.5 * 2.5 * 4.0 / 27.0), 1.0, 1e-5);
}

// Stopping a tumble (free final attitude) has no eigenaxis to turn a bump about: one guess, no starts.
TEST(OptimalStarts, AGuessWithoutAnEigenaxisIsSolvedOnce) {
  optimal::ReorientationProblem p;
  p.inertia_body = Vec3(1.0, 2.0, 3.0).asDiagonal();
  p.bound = optimal::TorqueBound::norm;
  p.torque_max = Vec3::Constant(1.0);
  p.omega_initial = Vec3(0.3, 0.2, 0.1);
  p.free_final_attitude = true;
  optimal::CollocationOptions o;
  o.max_mesh_iterations = 1;
  const optimal::DirectSolution d = optimal::solve_direct(p, o);
  EXPECT_TRUE(d.nlp_solved) << d.status;
  EXPECT_TRUE(d.first_mesh_starts.empty());
  EXPECT_EQ(d.chosen_start, 0);
}

TEST(OptimalStarts, StartsOutOfRangeAreRefused) {
  optimal::CollocationOptions o;
  for (const int n : {0, -1, optimal::kMaxStarts + 1}) {
    o.starts = n;
    test::expect_has(test::message_of<InvalidInput>([&] { optimal::validate(o); }, "starts out of range"),
                     {"collocation.starts: " + std::to_string(n), "expected 1"});
  }
  EXPECT_DOUBLE_EQ(optimal::first_mesh_turn(3, 4), 1.5 * std::numbers::pi);
}

}  // namespace
}  // namespace poinsot::io
