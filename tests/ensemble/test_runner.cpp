#include "poinsot/ensemble/runner.hpp"

#include <gtest/gtest.h>

#include <cstring>

#include "poinsot/core/error.hpp"
#include "poinsot/dynamics/exact_free_body.hpp"
#include "poinsot/dynamics/integrator.hpp"
#include "poinsot/dynamics/simulation.hpp"
#include "poinsot_test.hpp"

namespace poinsot::ensemble {
namespace {

Sampler racket_sampler(TorqueKind torque = TorqueKind::none) {
  Nominal n;
  n.moments = Vec3(1.0, 2.0, 2.5);
  n.omega_body = Vec3(0.05, 3.0, 0.05);
  n.torque = torque;
  n.torque_value = torque == TorqueKind::none ? Vec3::Zero() : Vec3(0.001, 0.0, 0.002);
  Dispersions d;
  d.moments = {Law::normal, 0.02, true};
  d.axes = {RotationLaw::cone, 0.035};
  d.omega = {Law::normal, 0.02, false};
  return Sampler(n, d, 2026);
}

EnsembleOptions opts(std::uint64_t samples, const char* method, double t_end, double dt = 1e-3,
                     unsigned threads = 1) {
  EnsembleOptions o;
  o.samples = samples;
  o.method = method;
  o.t_end = t_end;
  o.dt = dt;
  o.threads = threads;
  return o;
}

bool same_bits(const RunningStats& a, const RunningStats& b) {
  return a.count == b.count && a.nan_count == b.nan_count &&
         std::memcmp(&a.mean, &b.mean, sizeof(double)) == 0 &&
         std::memcmp(&a.m2, &b.m2, sizeof(double)) == 0 && a.min == b.min && a.max == b.max;
}

TEST(Runner, ResultsAreBitIdenticalForAnyThreadsAndWithOrWithoutSimd) {
  for (const char* method : {"rk4", "dlm"}) {
    // rk4: four blocks (the last partial), so that four threads each take one; dlm: two blocks (the cost of
    // these tests under the sanitizers is in the per-sample set-up).
    const std::uint64_t n = std::string_view(method) == "rk4" ? 3100 : 1100;
    EnsembleOptions o = opts(n, method, 0.1, 0.01);
    const EnsembleResult ref = run_ensemble(racket_sampler(), o);
    EXPECT_EQ(ref.completed, n);
    EXPECT_EQ(ref.body_steps, static_cast<std::int64_t>(n) * 10);
    // Two threads without SIMD, and four threads with SIMD and statistics only (the same merge order).
    for (const auto& [threads, simd] : {std::pair{2u, Simd::off}, std::pair{4u, Simd::automatic}}) {
      EnsembleOptions p = o;
      p.threads = threads;
      p.simd = simd;
      p.keep_rows = threads == 2;
      const EnsembleResult r = run_ensemble(racket_sampler(), p);
      for (int q = 0; q < kOutputCount; ++q)
        EXPECT_TRUE(same_bits(r.stats[q], ref.stats[q]))
            << method << " " << kOutputNames[q] << " threads " << threads;
      for (std::size_t i = 0; i < r.rows.size(); ++i) {
        ASSERT_EQ(r.rows[i].final_state.R_space_body, ref.rows[i].final_state.R_space_body);
        ASSERT_EQ(std::memcmp(r.rows[i].out.data(), ref.rows[i].out.data(), sizeof(r.rows[i].out)), 0);
      }
    }
  }
}

// The merged statistics against a two-pass computation over the stored rows: the mean to round-off (1e-14
// relative), the variance to 1e-10 (Chan's merge loses a few digits for large δ² terms), min and max exactly.
TEST(Runner, MergedStatisticsMatchATwoPassComputation) {
  const EnsembleResult r = run_ensemble(racket_sampler(), opts(2000, "rk4", 4.0, 0.01, 2));
  for (int q = 0; q < kOutputCount; ++q) {
    std::vector<double> v;
    for (const auto& row : r.rows)
      if (!std::isnan(row.out[q])) v.push_back(row.out[q]);
    const RunningStats& s = r.stats[q];
    ASSERT_EQ(static_cast<std::size_t>(s.count), v.size()) << kOutputNames[q];
    if (v.size() < 2) continue;
    double mean = 0, var = 0;
    for (double x : v)
      mean += x;
    mean /= static_cast<double>(v.size());
    for (double x : v)
      var += (x - mean) * (x - mean);
    var /= static_cast<double>(v.size() - 1);
    EXPECT_NEAR(s.mean, mean, 1e-14 * std::abs(mean) + 1e-300) << kOutputNames[q];
    EXPECT_NEAR(s.variance(), var, 1e-10 * var) << kOutputNames[q];
    EXPECT_EQ(s.min, *std::min_element(v.begin(), v.end()));
    EXPECT_EQ(s.max, *std::max_element(v.begin(), v.end()));
  }
  // rk4 at h = 0.01 over 4 s: flip intervals agree with 2K(k)/ω_p to the method's error (~1e-6 relative).
  for (const auto& row : r.rows)
    if (!std::isnan(row.out[flip_interval])) {
      EXPECT_NEAR(row.out[flip_interval], row.out[flip_interval_theory],
                  1e-5 * row.out[flip_interval_theory]);
    }
  EXPECT_EQ(r.nominal.out[attitude_error], 0.0);
}

TEST(Runner, PercentilesAreExactOrderStatistics) {
  std::vector<double> v;
  for (int i = 100; i >= 0; --i)
    v.push_back(i);  // 0..100 shuffled by reversal
  EXPECT_EQ(percentile(v, 50), 50.0);
  EXPECT_NEAR(percentile(v, 99.9), 99.9, 1e-12);
  EXPECT_EQ(percentile(v, 1), 1.0);
  v.push_back(std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(percentile(v, 100), 100.0);
}

TEST(Runner, ExactAndScalarPathsAgreeWithTheClosedFormAndTheTorquedPath) {
  const Sampler s = racket_sampler();
  const SampleRow e = run_sample(s, 17, opts(1, "exact", 3.0));
  const Sample x = s.draw(17);
  const dynamics::State direct = dynamics::ExactFreeBody(x.body(), x.initial).state_at(3.0);
  EXPECT_EQ(e.final_state.R_space_body, direct.R_space_body);
  // dop853 through dynamics::simulate reaches the same state to its tolerance.
  const SampleRow d = run_sample(s, 17, opts(1, "dop853", 3.0, 0.01));
  EXPECT_LT(test::max_abs_diff(d.final_state.R_space_body, direct.R_space_body), 1e-8);
  // Constant body torque: batched rk4 and scalar dop853 agree to rk4's error.
  const Sampler t = racket_sampler(TorqueKind::body);
  const SampleRow a = run_sample(t, 5, opts(1, "rk4", 2.0));
  const SampleRow b = run_sample(t, 5, opts(1, "dop853", 2.0));
  EXPECT_LT(test::max_abs_diff(a.final_state.omega_body, b.final_state.omega_body), 1e-9);
  EXPECT_TRUE(std::isnan(a.out[L_space_error]));
  // Constant space torque, batched too, against dop853 (rtol 1e-10): rk4 (order 4, h = 1e-3) to 1e-9 as
  // under the body torque above (1e-13 measured), dlm (order 2) to 2e-5, ten times its h² error (2e-6).
  const Sampler sp = racket_sampler(TorqueKind::space);
  EXPECT_NE(run_ensemble(sp, opts(3, "dlm", 0.01)).path.find("batched"), std::string::npos);
  const SampleRow c = run_sample(sp, 5, opts(1, "dop853", 2.0));
  const SampleRow r4 = run_sample(sp, 5, opts(1, "rk4", 2.0));
  const SampleRow dl = run_sample(sp, 5, opts(1, "dlm", 2.0));
  EXPECT_LT(test::max_abs_diff(r4.final_state.omega_body, c.final_state.omega_body), 1e-9);
  EXPECT_LT(test::max_abs_diff(r4.final_state.R_space_body, c.final_state.R_space_body), 1e-9);
  EXPECT_LT(test::max_abs_diff(dl.final_state.omega_body, c.final_state.omega_body), 2e-5);
  // The torque acts: the free sample ends elsewhere by far more than the tolerances.
  const SampleRow free = run_sample(s, 5, opts(1, "dop853", 2.0));
  EXPECT_GT(test::max_abs_diff(c.final_state.omega_body, free.final_state.omega_body), 1e-3);
}

// An adaptive method's body steps are the steps its samples took, counted one by one: the same as the
// driver's count for each sample, and (no largest step by default) far fewer than t_end/dt each. With
// max_step = dt every step is capped, so each sample takes t_end/dt of them (one more where round-off leaves
// a sliver).
TEST(Runner, AdaptiveMethodsCountTheStepsTheirSamplesTook) {
  const Sampler s = racket_sampler();
  EnsembleOptions o = opts(6, "dop853", 3.0);
  const EnsembleResult r = run_ensemble(s, o);
  std::int64_t expected = 0;
  for (std::uint64_t i = 0; i < 6; ++i) {
    const Sample x = s.draw(i);
    auto m = dynamics::make_integrator("dop853", x.body(), nullptr, {.dt = o.dt});
    expected += dynamics::simulate(x.body(), nullptr, x.initial, *m, {.t_end = 3.0, .sample_dt = 3.0}).steps;
  }
  EXPECT_EQ(r.body_steps, expected);
  EXPECT_LT(r.body_steps, 6 * 3000 / 10);
  o.max_step = o.dt;
  const std::int64_t capped = run_ensemble(s, o).body_steps;
  EXPECT_GE(capped, 6 * 3000);
  EXPECT_LE(capped, 6 * 3001);  // the sum of 3000 steps of 1e-3 may fall short of 3 s by round-off
}

TEST(Runner, StopsBetweenRoundsKeepingCompleteRows) {
  int calls = 0;
  EnsembleOptions o = opts(20000, "rk4", 0.1, 0.01);
  o.stop_requested = [&] { return ++calls >= 1; };
  const EnsembleResult r = run_ensemble(racket_sampler(), o);
  EXPECT_TRUE(r.interrupted);
  EXPECT_EQ(r.completed, 4 * kBlockSamples);
  EXPECT_EQ(r.rows.size(), r.completed);
  EXPECT_EQ(r.rows.back().index, r.completed - 1);
}

TEST(Runner, RefusesBadOptionsBeforeAllocating) {
  const Sampler s = racket_sampler();
  POINSOT_EXPECT_THROWS_MESSAGE(run_ensemble(s, opts(100000000000ULL, "rk4", 1.0)), InvalidInput,
                                "100000000000 samples", "GB", "per-sample output off");
  EXPECT_THROW(run_ensemble(s, opts(0, "rk4", 1.0)), InvalidInput);
  EXPECT_THROW(run_ensemble(s, opts(10, "euler", 1.0)), InvalidInput);
  EXPECT_THROW(run_ensemble(s, opts(10, "rk4", -1.0)), InvalidInput);
  EXPECT_THROW(run_ensemble(racket_sampler(TorqueKind::body), opts(10, "exact", 1.0)), InvalidInput);
}

}  // namespace
}  // namespace poinsot::ensemble

namespace poinsot::ensemble {
namespace {

// The distributed invariant (MPI ranks): blocks run in separate calls and merged in the block tree give the
// statistics of one run bit for bit, and the rows of the two shares are the rows of the whole.
TEST(Runner, BlockRangesMergedInTheTreeEqualOneRun) {
  const EnsembleOptions o = opts(3100, "dlm", 0.2, 0.01);  // four blocks, the last partial
  const EnsembleResult whole = run_ensemble(racket_sampler(), o);
  std::vector<BlockNode> nodes;
  const std::uint64_t n = block_count(o.samples), split = 1;  // [0, 1) and [1, 4): not a subtree boundary
  const EnsembleResult a = run_ensemble_blocks(racket_sampler(), o, 0, split, &nodes);
  const EnsembleResult b = run_ensemble_blocks(racket_sampler(), o, split, n, &nodes);
  ASSERT_EQ(nodes.size(), 3u);  // block 0 | block 1, blocks [2, 4)
  EXPECT_EQ(a.rows.size() + b.rows.size(), whole.rows.size());
  EXPECT_EQ(b.rows.front().index, split * kBlockSamples);
  EXPECT_EQ(b.rows.front().final_state.R_space_body,
            whole.rows[split * kBlockSamples].final_state.R_space_body);
  EnsembleResult merged;
  set_statistics(merged, nodes, o.samples);
  for (int q = 0; q < kOutputCount; ++q)
    EXPECT_TRUE(same_bits(merged.stats[q], whole.stats[q])) << kOutputNames[q];
  EXPECT_EQ(merged.rejected, whole.rejected);
  EXPECT_THROW(run_ensemble_blocks(racket_sampler(), o, 3, n + 1, nullptr), InvalidInput);
}

}  // namespace
}  // namespace poinsot::ensemble
