#include "poinsot/io/scenario/optimal_scenario.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "poinsot/core/error.hpp"
#include "poinsot_test.hpp"

namespace poinsot::io {
namespace {

constexpr const char* kBetts = R"(
[body]
principal_moments = [5621.0, 4547.0, 2364.0]
[optimal_control]
torque_max = [50.0, 50.0, 50.0]
rate_max = 0.5
[optimal_control.final]
orientation = { axis_angle = { axis = [1.0, 0.0, 0.0], angle = 150.0 }, degrees = true }
)";

TEST(OptimalScenario, ReadsTheProblem) {
  const OptimalScenario sc = parse_optimal_scenario(kBetts, "betts.toml", ".");
  const auto& p = sc.problem;
  EXPECT_EQ(p.objective, optimal::Objective::minimum_time);
  EXPECT_EQ(p.bound, optimal::TorqueBound::per_axis);
  EXPECT_EQ(p.inertia_body(1, 1), 4547.0);
  EXPECT_EQ(p.rate_max, 0.5);
  const double half = 75.0 * std::numbers::pi / 180.0;
  EXPECT_NEAR(p.attitude_final.w(), std::cos(half), 1e-15);
  EXPECT_NEAR(p.attitude_final.x(), std::sin(half), 1e-15);
  EXPECT_TRUE(p.omega_final.isZero(0.0));
  EXPECT_FALSE(p.free_final_attitude);
  EXPECT_EQ(sc.shooting.shooting_nodes, 1);  // single shooting unless the file asks
  const std::string t = kBetts;
  const OptimalScenario multiple = parse_optimal_scenario(
      std::string(t).replace(t.find("rate_max = 0.5"), 14, "shooting_nodes = 8"), "betts.toml", ".");
  EXPECT_EQ(multiple.shooting.shooting_nodes, 8);
  // The phase-per-arc re-solve is on, at 64 intervals per arc, unless the file says otherwise.
  EXPECT_TRUE(sc.phased);
  EXPECT_EQ(sc.phased_options.intervals_per_arc, 64);
  const OptimalScenario off = parse_optimal_scenario(
      std::string(t).replace(t.find("rate_max = 0.5"), 14, "phased = false\nphased_intervals_per_arc = 16"),
      "betts.toml", ".");
  EXPECT_FALSE(off.phased);
  EXPECT_EQ(off.phased_options.intervals_per_arc, 16);
  // The first mesh is solved from four guesses unless the file says otherwise.
  EXPECT_EQ(sc.collocation.starts, 4);
  EXPECT_EQ(parse_optimal_scenario(std::string(t).replace(t.find("rate_max = 0.5"), 14, "starts = 1"),
                                   "betts.toml", ".")
                .collocation.starts,
            1);
}

// Each message is one line that locates the key and says what was expected.
void expect_error(const std::string& text, const std::string& needle) {
  const std::string msg = test::message_of<InvalidInput>([&] { parse_optimal_scenario(text, "s.toml", "."); },
                                                         "a scenario expected to fail naming " + needle);
  test::expect_has(msg, {needle});
  EXPECT_EQ(msg.rfind("s.toml:", 0), 0u) << msg;
}

TEST(OptimalScenario, LocatedErrors) {
  std::string t = kBetts;
  expect_error(t + "objective = 1\n", "objective");  // after [optimal_control.final]: not a key there
  expect_error(std::string(kBetts).replace(t.find("rate_max = 0.5"), 14, "rate_max = -1"), "rate_max");
  expect_error(std::string(kBetts).replace(t.find("rate_max = 0.5"), 14, "speed = 1"), "speed");
  expect_error(std::string(kBetts).replace(t.find("rate_max = 0.5"), 14, "objective = \"fast\""),
               "unknown objective");
  expect_error(std::string(kBetts).replace(t.find("rate_max = 0.5"), 14, "final_time = 3.0"), "final_time");
  expect_error(std::string(kBetts).replace(t.find("rate_max = 0.5"), 14, "initial_intervals = 1.5"),
               "initial_intervals");
  expect_error(std::string(kBetts).replace(t.find("rate_max = 0.5"), 14, "shooting_nodes = 0"),
               "shooting_nodes");
  expect_error(std::string(kBetts).replace(t.find("rate_max = 0.5"), 14, "phased = 1"), "phased");
  expect_error(std::string(kBetts).replace(t.find("rate_max = 0.5"), 14, "starts = 0"), "starts");
  expect_error(std::string(kBetts).replace(t.find("rate_max = 0.5"), 14, "starts = 65"), "starts");
  expect_error(std::string(kBetts).replace(t.find("rate_max = 0.5"), 14, "phased_intervals_per_arc = 2001"),
               "phased_intervals_per_arc");
  expect_error("[body]\nprincipal_moments = [1.0, 1.0, 1.0]\n", "optimal_control");
  // A run scenario (its [initial] is no key of an optimal-control file) is answered with its sub-command.
  expect_error(
      "[body]\nprincipal_moments = [1.0, 2.0, 3.0]\n[initial]\nomega_body = [0.0, 1.0, 0.0]\n",
      "[top level] optimal_control: missing; expected an [optimal_control] section (a scenario without "
      "one is simulated by `poinsot run s.toml`)");
}

TEST(OptimalScenario, FreeFinalAttitude) {
  const OptimalScenario sc = parse_optimal_scenario(R"(
[body]
principal_moments = [1.0, 2.0, 2.5]
[optimal_control]
torque_bound = "norm"
torque_max = 0.5
[optimal_control.initial]
omega_body = [0.1, 1.0, 0.0]
[optimal_control.final]
free_attitude = true
)",
                                                    "s.toml", ".");
  EXPECT_TRUE(sc.problem.free_final_attitude);
  EXPECT_EQ(sc.problem.bound, optimal::TorqueBound::norm);
  EXPECT_EQ(sc.problem.torque_max[0], 0.5);
}

}  // namespace
}  // namespace poinsot::io
