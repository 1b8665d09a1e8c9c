#include "poinsot/io/run/optimal_run.hpp"
#include "poinsot_test.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace poinsot::io {
namespace {

constexpr const char* kEnergy = R"(
[body]
principal_moments = [2.5, 2.5, 2.5]
[optimal_control]
objective = "minimum_energy"
torque_bound = "norm"
torque_max = 100.0
final_time = 3.0
mesh_tolerance = 1e-6
[optimal_control.final]
orientation = { axis_angle = { axis = [1.0, -2.0, 0.5], angle = 2.0 } }
)";

// The whole run on the minimum-energy sphere (cost 12 j²Θ²/T³), its texts, and determinism: two runs of the
// same input give the same summary, byte for byte.
TEST(OptimalRun, SphereEnergyRunIsVerifiedAndDeterministic) {
  const OptimalScenario sc = parse_optimal_scenario(kEnergy, "energy.toml", ".");
  const OptimalRun r = run_optimal(sc);
  ASSERT_TRUE(r.optimal) << r.status;
  EXPECT_EQ(r.status, "optimal (verified)");
  EXPECT_EQ(r.outcome, OptimalOutcome::optimal);
  EXPECT_STREQ(solution_source(r), "indirect");
  EXPECT_TRUE(r.failed_phase.empty() && r.advice.empty() && !r.direct_replayed);
  EXPECT_NEAR(r.indirect.cost / (12.0 * 2.5 * 2.5 * 4.0 / 27.0), 1.0, 1e-11);
  const std::string summary = optimal_summary_json(r);
  EXPECT_NE(summary.find("\"optimal\": true"), std::string::npos);
  EXPECT_NE(summary.find("\"outcome\": \"optimal\""), std::string::npos);
  EXPECT_EQ(summary, optimal_summary_json(run_optimal(sc)));
  EXPECT_NE(optimal_report(r).find("status: optimal (verified)"), std::string::npos);

  const auto dir = ::poinsot::test::temp_path("poinsot_test_optimal_run");
  std::filesystem::remove_all(dir);
  write_optimal_files(r, dir.string());
  for (const char* f : {"trajectory.csv", "control.csv", "costates.csv"})
    EXPECT_EQ(test::read_text(dir / f).rfind("# status: optimal (verified)\n", 0), 0u) << f;
  EXPECT_EQ(test::read_text(dir / "summary.json"), summary);
  std::filesystem::remove_all(dir);
}

// The three outcomes of a run and the exit statuses of `poinsot optimize` (2 is bad input, before any run).
TEST(OptimalRun, OutcomesAndExitCodes) {
  EXPECT_EQ(outcome_exit_code(OptimalOutcome::optimal), 0);
  EXPECT_EQ(outcome_exit_code(OptimalOutcome::converged_direct), 3);
  EXPECT_EQ(outcome_exit_code(OptimalOutcome::not_converged), 1);
  EXPECT_STREQ(outcome_name(OptimalOutcome::optimal), "optimal");
  EXPECT_STREQ(outcome_name(OptimalOutcome::converged_direct), "converged_direct");
  EXPECT_STREQ(outcome_name(OptimalOutcome::not_converged), "not_converged");
}

// The report's events where boundary arcs of one axis meet (an exit and the next entry at one time, as the
// shooting converges where the direct solution dipped off the bound for a few samples) and for an arc of zero
// length (entry, then exit); the events are given in the order of the shooting's unknowns.
TEST(OptimalRun, ReportNamesTheEventsOfBoundaryArcsThatMeet) {
  OptimalRun r;
  r.scenario = parse_optimal_scenario(kEnergy, "energy.toml", ".");
  r.indirect.time = {0.0, 4.0};
  r.indirect.rate_bound_arcs = {{1, -1.0, 0.5, 2.0}, {1, -1.0, 2.0, 3.5}, {2, 1.0, 3.0, 3.0}};
  r.indirect.switch_times = {0.5, 2.0, 2.0, 3.0, 3.0, 3.5};
  r.indirect.switch_axes = {1, 1, 1, 2, 2, 1};
  EXPECT_NE(optimal_report(r).find("  entry into the boundary arc ω2 = −r at t = 0.5 s\n"
                                   "  exit from the boundary arc ω2 = −r at t = 2 s\n"
                                   "  entry into the boundary arc ω2 = −r at t = 2 s\n"
                                   "  entry into the boundary arc ω3 = r at t = 3 s\n"
                                   "  exit from the boundary arc ω3 = r at t = 3 s\n"
                                   "  exit from the boundary arc ω2 = −r at t = 3.5 s\n"),
            std::string::npos)
      << optimal_report(r);
}

}  // namespace
}  // namespace poinsot::io
