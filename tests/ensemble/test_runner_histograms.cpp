// The runner's fixed-edge histograms: counted on the fly, with rows kept or not, equal to a count over the
// stored rows, the same for any threads and any split of the blocks between processes (MPI ranks).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "poinsot/core/error.hpp"
#include "poinsot/ensemble/runner.hpp"

namespace poinsot::ensemble {
namespace {

Sampler histogram_sampler() {
  Nominal n;
  n.moments = Vec3(1.0, 2.0, 2.5);
  n.omega_body = Vec3(0.05, 3.0, 0.05);
  Dispersions d;
  d.moments = {Law::normal, 0.02, true};
  d.axes = {RotationLaw::cone, 0.035};
  d.omega = {Law::normal, 0.02, false};
  return Sampler(n, d, 99);
}

EnsembleOptions histogram_options(std::uint64_t samples, unsigned threads, bool rows) {
  EnsembleOptions o;
  o.samples = samples;
  o.method = "rk4";
  o.t_end = 8.0;
  o.dt = 0.01;
  o.threads = threads;
  o.keep_rows = rows;
  return o;
}

// A count over the rows against the histogram's edges, written out (the oracle).
std::vector<std::int64_t> count_rows(const std::vector<SampleRow>& rows, int q, const FixedHistogram& h) {
  std::vector<std::int64_t> c(static_cast<std::size_t>(h.bins()) + 3, 0);  // [under, over, NaN, bins]
  for (const SampleRow& row : rows) {
    const double x = row.out[static_cast<std::size_t>(q)];
    if (std::isnan(x)) {
      ++c[2];
    } else if (x < h.edge(0)) {
      ++c[0];
    } else if (x > h.edge(h.bins())) {
      ++c[1];
    } else {
      int i = 0;
      while (i < h.bins() - 1 && x >= h.edge(i + 1))
        ++i;
      ++c[static_cast<std::size_t>(i) + 3];
    }
  }
  return c;
}

TEST(RunnerHistograms, EqualACountOverTheStoredRowsForAnyThreadsAndSplit) {
  const std::uint64_t n = 2600;  // three blocks, the last partial
  const Sampler s = histogram_sampler();
  const EnsembleResult ref = run_ensemble(s, histogram_options(n, 1, true));
  ASSERT_EQ(ref.rows.size(), n);
  int with_edges = 0;
  for (int q = 0; q < kOutputCount; ++q) {
    const FixedHistogram& h = ref.histograms[static_cast<std::size_t>(q)];
    std::vector<double> pilot;
    for (std::uint64_t i = 0; i < kBlockSamples; ++i)
      pilot.push_back(ref.rows[i].out[static_cast<std::size_t>(q)]);
    const auto edges = pilot_range(pilot);
    ASSERT_EQ(h.has_edges(), edges.has_value()) << kOutputNames[q];
    if (!edges) continue;
    ++with_edges;
    // The edges: the pilot's range (the first kBlockSamples samples), in kHistogramBins bins.
    EXPECT_EQ(h.range().lo, edges->lo);
    EXPECT_EQ(h.range().hi, edges->hi);
    EXPECT_EQ(h.bins(), kHistogramBins);
    EXPECT_EQ(h.flat_counts(), count_rows(ref.rows, q, h)) << kOutputNames[q];
    std::int64_t total = 0;
    for (std::int64_t c : h.flat_counts())
      total += c;
    EXPECT_EQ(total, static_cast<std::int64_t>(n)) << kOutputNames[q];  // every sample counted once
  }
  EXPECT_GE(with_edges, 5);  // the free body's outputs; the tops' are NaN throughout

  // Two threads with rows, two without (statistics only), and the blocks split between two "ranks"
  // [0, 1) and [1, 3) (the second runs the pilot itself) and merged: the same counts.
  const EnsembleResult two = run_ensemble(s, histogram_options(n, 2, true));
  const EnsembleResult no_rows = run_ensemble(s, histogram_options(n, 2, false));
  EXPECT_TRUE(no_rows.rows.empty());
  const EnsembleOptions o = histogram_options(n, 1, false);
  const EnsembleResult first = run_ensemble_blocks(s, o, 0, 1, nullptr);
  const EnsembleResult second = run_ensemble_blocks(s, o, 1, 3, nullptr);
  for (std::size_t q = 0; q < static_cast<std::size_t>(kOutputCount); ++q) {
    const FixedHistogram& h = ref.histograms[q];
    EXPECT_EQ(two.histograms[q].flat_counts(), h.flat_counts()) << kOutputNames[q];
    EXPECT_EQ(no_rows.histograms[q].flat_counts(), h.flat_counts()) << kOutputNames[q];
    if (!h.has_edges()) continue;
    FixedHistogram merged = first.histograms[q];
    merged.merge(second.histograms[q]);  // throws unless the edges are the same
    EXPECT_EQ(merged.flat_counts(), h.flat_counts()) << kOutputNames[q];
  }
}

TEST(RunnerHistograms, GivenRangesAreUsedAndTheRestCountedOutside) {
  const Sampler s = histogram_sampler();
  EnsembleOptions o = histogram_options(300, 1, true);
  o.histograms.bins = 4;
  // A range narrower than the values: samples fall on both sides and are counted there.
  const EnsembleResult probe = run_ensemble(s, o);
  const RunningStats& st = probe.stats[attitude_error];
  const double mid = probe.stats[attitude_error].mean;
  o.histograms.ranges[attitude_error] = HistogramRange{0.5 * (st.min + mid), 0.5 * (mid + st.max)};
  const EnsembleResult r = run_ensemble(s, o);
  const FixedHistogram& h = r.histograms[attitude_error];
  EXPECT_EQ(h.range().lo, 0.5 * (st.min + mid));
  EXPECT_EQ(h.bins(), 4);
  EXPECT_GT(h.underflow(), 0);
  EXPECT_GT(h.overflow(), 0);
  EXPECT_EQ(h.flat_counts(), count_rows(r.rows, attitude_error, h));
  EXPECT_EQ(r.histograms[energy_error].bins(), 4);  // the pilot's range, the given bins

  EnsembleOptions bad = o;
  bad.histograms.ranges[energy_error] = HistogramRange{1.0, 0.5};
  EXPECT_THROW(run_ensemble(s, bad), InvalidInput);
  bad = o;
  bad.histograms.bins = 0;
  EXPECT_THROW(run_ensemble(s, bad), InvalidInput);
}

}  // namespace
}  // namespace poinsot::ensemble
