// Tests of quantile_sketch.hpp against the exact percentiles (statistics.hpp: sort, definition 7) of the same
// values: the stated bound |P̂ − P| ≤ α · max(|x_(lo)|, |x_(hi)|) on positive, mixed-sign, zero-heavy and
// wide-range data; merging in any order gives the same bits; the bucket count stays within its bound; and,
// through the runner, percentiles without rows agree with those from the rows within the bound and are
// identical for 1 and 3 threads.
#include "poinsot/ensemble/quantile_sketch.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "poinsot/core/error.hpp"
#include "poinsot/ensemble/runner.hpp"
#include "poinsot/ensemble/statistics.hpp"

namespace poinsot::ensemble {
namespace {

constexpr double kAlpha = kQuantileRelativeAccuracy;
// The bound holds up to the rounding of log and exp (|i ln γ| ≤ 745, so ~1e-13 relative); 1e-9 of α is far
// above that and far below α itself.
constexpr double kRounding = 1e-9;

const double kProbes[] = {0.0, 1.0, 5.0, 25.0, 50.0, 75.0, 95.0, 99.0, 99.9, 100.0};

/// Checks every probe percentile of `values` against the exact one, with the bound of the header.
void expect_within_bound(const std::vector<double>& values, const char* what) {
  SCOPED_TRACE(what);
  QuantileSketch s;
  for (double x : values)
    s.add(x);
  std::vector<double> sorted;
  for (double x : values)
    if (std::isfinite(x)) sorted.push_back(x);
  std::sort(sorted.begin(), sorted.end());
  ASSERT_EQ(s.count(), static_cast<std::int64_t>(sorted.size()));
  for (double p : kProbes) {
    const double exact = percentile(values, p);
    const double rank = p / 100.0 * static_cast<double>(sorted.size() - 1);
    const auto lo = static_cast<std::size_t>(std::floor(rank));
    const std::size_t hi = std::min(lo + 1, sorted.size() - 1);
    const double scale = std::max(std::abs(sorted[lo]), std::abs(sorted[hi]));
    EXPECT_LE(std::abs(s.percentile(p) - exact), kAlpha * (1.0 + kRounding) * scale)
        << "P" << p << " exact " << exact << " sketch " << s.percentile(p);
  }
}

TEST(QuantileSketch, PercentilesAreWithinTheStatedBoundOfTheExactOnes) {
  std::mt19937_64 rng(7);
  std::vector<double> lognormal, mixed, zeros, wide, ties;
  std::lognormal_distribution<double> ln(0.0, 2.0);
  std::normal_distribution<double> normal(0.3, 1.0);
  std::uniform_real_distribution<double> exponent(-300.0, 300.0);
  for (int i = 0; i < 20000; ++i) {
    lognormal.push_back(ln(rng));
    mixed.push_back(normal(rng));
    zeros.push_back(i % 3 == 0 ? 0.0 : -ln(rng));
    wide.push_back(std::pow(10.0, exponent(rng)));
    ties.push_back(static_cast<double>(i % 7));
  }
  expect_within_bound(lognormal, "lognormal");
  expect_within_bound(mixed, "normal, both signs");
  expect_within_bound(zeros, "a third zeros, the rest negative");
  expect_within_bound(wide, "600 decades");
  expect_within_bound(ties, "seven repeated values");
  expect_within_bound({42.0}, "one value");
  // Not counted: NaN and infinities (as in percentile()).
  QuantileSketch s;
  EXPECT_TRUE(std::isnan(s.percentile(50.0)));
  s.add(std::numeric_limits<double>::quiet_NaN());
  s.add(std::numeric_limits<double>::infinity());
  EXPECT_EQ(s.count(), 0);
  EXPECT_THROW(s.percentile(101.0), InvalidInput);
  EXPECT_THROW(QuantileSketch(0.0), InvalidInput);
}

TEST(QuantileSketch, MergingInAnyOrderGivesTheSameBits) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> normal(1.0, 3.0);
  std::vector<double> v(9000);
  for (double& x : v)
    x = normal(rng);
  QuantileSketch whole, forward, backward, restored;
  std::vector<QuantileSketch> parts(9);
  for (std::size_t i = 0; i < v.size(); ++i) {
    whole.add(v[i]);
    parts[i % parts.size()].add(v[i]);
  }
  for (const auto& part : parts)
    forward.merge(part);
  for (auto it = parts.rbegin(); it != parts.rend(); ++it)
    backward.merge(*it);
  for (const QuantileBucket& b : whole.buckets())  // the transport of the MPI driver
    restored.add_bucket(b);
  for (double p : kProbes) {
    const double w = whole.percentile(p), f = forward.percentile(p), b = backward.percentile(p),
                 r = restored.percentile(p);
    EXPECT_EQ(std::memcmp(&w, &f, sizeof w), 0) << p;
    EXPECT_EQ(std::memcmp(&w, &b, sizeof w), 0) << p;
    EXPECT_EQ(std::memcmp(&w, &r, sizeof w), 0) << p;
  }
  EXPECT_THROW(whole.merge(QuantileSketch(0.01)), InvalidInput);
  EXPECT_THROW(restored.add_bucket({2, 0, 1}), InvalidInput);
}

TEST(QuantileSketch, MemoryIsBoundedByTheRangeNotTheCount) {
  // Values in [1, 10]: at most R = ln 10 / ln γ + 1 buckets (≈ 1152) occupied, and the storage (counted, not
  // timed) at most R + 2 max(16, R/8) (the header's bound): the same after 10^5 and 10^6 values.
  QuantileSketch s;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(1.0, 10.0);
  const double gamma = (1.0 + kAlpha) / (1.0 - kAlpha);
  const double range = std::log(10.0) / std::log(gamma) + 2.0;
  std::size_t storage_1e5 = 0;
  for (int i = 0; i < 1000000; ++i) {
    s.add(u(rng));
    if (i + 1 == 100000) storage_1e5 = s.storage_buckets();
  }
  EXPECT_LE(static_cast<double>(s.buckets().size()), range);
  EXPECT_GT(s.buckets().size(), 1000u);  // and the buckets are used: the bound is not vacuous
  EXPECT_LE(static_cast<double>(s.storage_buckets()), 1.25 * range + 32.0);
  EXPECT_EQ(s.storage_buckets(), storage_1e5);
  // A range filled one bucket at a time from both ends (the tails of an ensemble's outputs fill so): the
  // storage of each sign stays within R + 2 max(16, R/8), R = n.
  QuantileSketch tails;
  const int n = 20000;  // buckets, about 17 decades each side
  for (int i = 0; i < n; ++i) {
    tails.add(std::pow(gamma, i - 0.5));    // mid-bucket: bucket i
    tails.add(-std::pow(gamma, -i - 0.5));  // bucket −i of the negative store
  }
  EXPECT_EQ(tails.buckets().size(), static_cast<std::size_t>(2 * n));
  EXPECT_LE(static_cast<double>(tails.storage_buckets()), 2.0 * (1.25 * n + 32.0));
}

Sampler sketch_racket_sampler() {
  Nominal n;
  n.moments = Vec3(1.0, 2.0, 2.5);
  n.omega_body = Vec3(0.05, 3.0, 0.05);
  Dispersions d;
  d.moments = {Law::normal, 0.02, true};
  d.omega = {Law::normal, 0.02, false};
  return Sampler(n, d, 99);
}

TEST(QuantileSketch, EnsembleWithoutRowsGivesPercentilesWithinTheBoundOfTheRowsOnes) {
  EnsembleOptions o;
  o.samples = 2500;  // three blocks, the last partial
  o.method = "dlm";
  o.t_end = 0.05;
  o.dt = 0.01;
  const EnsembleResult rows = run_ensemble(sketch_racket_sampler(), o);
  o.keep_rows = false;
  const EnsembleResult one = run_ensemble(sketch_racket_sampler(), o);
  o.threads = 3;
  const EnsembleResult three = run_ensemble(sketch_racket_sampler(), o);
  ASSERT_TRUE(one.rows.empty());
  int checked = 0;
  for (std::size_t q = 0; q < static_cast<std::size_t>(kOutputCount); ++q) {
    std::vector<double> v;
    for (const SampleRow& r : rows.rows)
      if (std::isfinite(r.out[q])) v.push_back(r.out[q]);
    EXPECT_EQ(one.sketches[q].count(), static_cast<std::int64_t>(v.size())) << kOutputNames[q];
    if (v.empty()) continue;
    std::sort(v.begin(), v.end());
    for (double p : kPercentiles) {
      const double rank = p / 100.0 * static_cast<double>(v.size() - 1);
      const auto lo = static_cast<std::size_t>(std::floor(rank));
      const double scale = std::max(std::abs(v[lo]), std::abs(v[std::min(lo + 1, v.size() - 1)]));
      const double a = one.sketches[q].percentile(p), b = three.sketches[q].percentile(p);
      EXPECT_LE(std::abs(a - percentile(v, p)), kAlpha * (1.0 + kRounding) * scale) << kOutputNames[q] << p;
      EXPECT_EQ(std::memcmp(&a, &b, sizeof a), 0) << kOutputNames[q] << p;
      ++checked;
    }
  }
  EXPECT_GE(checked, 3 * 6);  // at least three outputs apply to these free bodies
}

}  // namespace
}  // namespace poinsot::ensemble
