#include "poinsot/io/run/summary.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "poinsot/core/error.hpp"
#include "poinsot_test.hpp"

namespace poinsot::io {
namespace {

RunSummary sample_summary() {
  RunSummary s;
  s.scenario = "racket";
  s.method = "exact";
  s.principal_moments = Vec3(1, 2, 3);
  s.inertia = Vec3(1, 2, 3).asDiagonal();
  s.symmetry = "asymmetric";
  s.result.final_state.time = 20.0;
  s.result.final_state.omega_body = Vec3(0.1, -2.0, 0.1);
  s.result.steps = 1234;
  s.result.wall_time_s = 0.5;
  s.result.flip_times = {1.0, 3.0, 5.0};
  s.result.errors.energy_rel_max = 1e-15;
  s.result.errors.L_space_rel_max = std::nan("");  // not finite: written as null
  s.flip_interval_theory = 2.0;
  s.period_theory = 4.0;
  return s;
}

TEST(Summary, HoldsTheDocumentedKeys) {
  const auto j = nlohmann::json::parse(summary_json(sample_summary()));
  EXPECT_EQ(j["final"]["t"], 20.0);
  EXPECT_EQ(j["final"]["omega_body"], nlohmann::json({0.1, -2.0, 0.1}));
  EXPECT_EQ(j["final"]["R"], nlohmann::json({{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}}));
  EXPECT_EQ(j["final"]["quaternion"], nlohmann::json({1.0, 0.0, 0.0, 0.0}));
  EXPECT_EQ(j["invariants"]["energy_rel_error_max"], 1e-15);
  EXPECT_TRUE(j["invariants"]["L_space_rel_error_max"].is_null());
  EXPECT_TRUE(j["invariants"].contains("orthogonality_error_max"));
  EXPECT_EQ(j["events"]["flip_times"], nlohmann::json({1.0, 3.0, 5.0}));
  EXPECT_EQ(j["events"]["flip_interval_theory"], 2.0);
  EXPECT_EQ(j["events"]["flip_interval_mean"], 2.0);  // (5 − 1)/2
  EXPECT_EQ(j["events"]["period_theory"], 4.0);
  EXPECT_EQ(j["steps"], 1234);
  EXPECT_EQ(j["wall_time_s"], 0.5);
  EXPECT_EQ(j["status"], "completed");
  EXPECT_EQ(j["interrupted"], false);
  EXPECT_TRUE(j["top"].is_null());
}

TEST(Summary, SaysInterruptedOrFailed) {
  RunSummary s = sample_summary();
  s.result.interrupted = true;
  EXPECT_EQ(nlohmann::json::parse(summary_json(s))["status"], "interrupted");
  s.failure = "dop853: step failed at t = 3 s";
  const auto j = nlohmann::json::parse(summary_json(s));
  EXPECT_EQ(j["status"], "failed");
  EXPECT_EQ(j["failure"], s.failure);
}

TEST(Summary, TopKeys) {
  RunSummary s = sample_summary();
  TopEvents t;
  t.kind = dynamics::TopKind::heavy;
  t.precession_rate_mean = 0.5;
  t.precession_rate_theory = 0.49;
  t.nutation_frequency = 100.0;
  s.top = t;
  const auto j = nlohmann::json::parse(summary_json(s));
  EXPECT_EQ(j["events"]["precession_rate_mean"], 0.5);
  EXPECT_EQ(j["events"]["precession_rate_fast_top"], 0.49);
  EXPECT_EQ(j["events"]["nutation_frequency"], 100.0);
  EXPECT_EQ(j["top"]["kind"], "heavy top");
}

TEST(Summary, AtomicWriteReplacesTheFileAndLeavesNoTemporary) {
  namespace fs = std::filesystem;
  const auto dir = ::poinsot::test::temp_path("poinsot_io_test_atomic");
  fs::remove_all(dir);
  fs::create_directories(dir);
  const auto path = (dir / "summary.json").string();
  write_file_atomic(path, "old\n");
  write_file_atomic(path, "new\n");
  std::ifstream in(path);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, "new\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  EXPECT_THROW(write_file_atomic((dir / "missing" / "s.json").string(), "x"), ComputationFailed);
}

}  // namespace
}  // namespace poinsot::io
