#include "poinsot/ensemble/fixed_histogram.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "poinsot/core/error.hpp"

namespace poinsot::ensemble {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The oracle: every value compared with every edge as the histogram reports them (bin i holds e_i <= x <
// e_(i+1), the last bin also x = hi), no quotient.
struct DirectCount {
  std::vector<std::int64_t> bins;
  std::int64_t under = 0, over = 0, nan = 0;
};
DirectCount count_directly(const FixedHistogram& h, const std::vector<double>& values) {
  DirectCount c;
  c.bins.assign(static_cast<std::size_t>(h.bins()), 0);
  for (double x : values) {
    if (std::isnan(x)) {
      ++c.nan;
      continue;
    }
    if (x < h.edge(0)) {
      ++c.under;
      continue;
    }
    if (x > h.edge(h.bins())) {
      ++c.over;
      continue;
    }
    for (int i = 0; i < h.bins(); ++i) {
      if (x >= h.edge(i) && (x < h.edge(i + 1) || (i == h.bins() - 1 && x == h.edge(i + 1)))) {
        ++c.bins[static_cast<std::size_t>(i)];
        break;
      }
    }
  }
  return c;
}

// Values on, just beside and between the rounded edges of an awkward range (edges that are not exact binary
// fractions), the ends, outside, ±∞ and NaN.
std::vector<double> probe_values(const FixedHistogram& h) {
  std::vector<double> v;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(h.edge(0) - 0.2 * (h.edge(h.bins()) - h.edge(0)),
                                           h.edge(h.bins()) + 0.2 * (h.edge(h.bins()) - h.edge(0)));
  for (int i = 0; i < 2000; ++i)
    v.push_back(u(rng));
  for (int i = 0; i <= h.bins(); ++i) {
    v.push_back(h.edge(i));
    v.push_back(std::nextafter(h.edge(i), -kInf));
    v.push_back(std::nextafter(h.edge(i), kInf));
  }
  v.insert(v.end(), {kInf, -kInf, kNaN, kNaN});
  return v;
}

TEST(FixedHistogram, CountsEqualADirectComparisonWithTheEdges) {
  for (const auto& [range, bins] :
       {std::pair{HistogramRange{0.1, 0.7}, 7}, std::pair{HistogramRange{-3.3, 1e-3}, 20},
        std::pair{HistogramRange{1e-9, 1.1e-9}, 13}, std::pair{HistogramRange{0.0, 1.0}, 1}}) {
    FixedHistogram h(range, bins);
    const std::vector<double> v = probe_values(h);
    for (double x : v)
      h.add(x);
    const DirectCount c = count_directly(h, v);
    EXPECT_EQ(h.counts(), c.bins);
    EXPECT_EQ(h.underflow(), c.under);
    EXPECT_EQ(h.overflow(), c.over);
    EXPECT_EQ(h.nan_count(), 2);
    std::int64_t total = h.underflow() + h.overflow() + h.nan_count();
    for (std::int64_t n : h.counts())
      total += n;
    EXPECT_EQ(total, static_cast<std::int64_t>(v.size()));  // nothing dropped
    EXPECT_GT(h.underflow(), 1);                            // −∞ and the values below lo
    EXPECT_GT(h.overflow(), 1);
    EXPECT_EQ(h.edge(0), range.lo);
    EXPECT_EQ(h.edge(bins), range.hi);
  }
}

TEST(FixedHistogram, MergesInAnyOrderToTheSameCounts) {
  const FixedHistogram empty({-1.0, 2.0}, 9);
  const std::vector<double> v = probe_values(empty);
  FixedHistogram all = empty;
  for (double x : v)
    all.add(x);
  // Three parts merged in two orders, and through the flat counts (MPI's transport).
  FixedHistogram parts[3] = {empty, empty, empty};
  for (std::size_t i = 0; i < v.size(); ++i)
    parts[i % 3].add(v[i]);
  FixedHistogram a = empty, b = empty, c = empty;
  a.merge(parts[0]);
  a.merge(parts[1]);
  a.merge(parts[2]);
  b.merge(parts[2]);
  b.merge(parts[0]);
  b.merge(parts[1]);
  for (const FixedHistogram& p : parts)
    c.add_flat_counts(p.flat_counts());
  for (const FixedHistogram* m : {&a, &b, &c}) {
    EXPECT_EQ(m->flat_counts(), all.flat_counts());
  }
  EXPECT_THROW(a.merge(FixedHistogram({-1.0, 2.0}, 8)), InvalidInput);
  EXPECT_THROW(a.merge(FixedHistogram({-1.0, 2.5}, 9)), InvalidInput);
  EXPECT_THROW(a.add_flat_counts(std::vector<std::int64_t>(5, 1)), InvalidInput);
}

TEST(FixedHistogram, PilotRangeWidensTheValuesWithoutCrossingZero) {
  const std::vector<double> mixed = {1.0, -2.0, kNaN, 3.0, kInf};
  const auto r = pilot_range(mixed);
  ASSERT_TRUE(r.has_value());
  EXPECT_DOUBLE_EQ(r->lo, -2.5);  // [−2, 3] widened by 5/10
  EXPECT_DOUBLE_EQ(r->hi, 3.5);
  const auto pos = pilot_range(std::vector<double>{0.01, 1.0});
  EXPECT_EQ(pos->lo, 0.0);  // 0.01 − 0.099 < 0: an output of one sign keeps it
  EXPECT_DOUBLE_EQ(pos->hi, 1.099);
  const auto neg = pilot_range(std::vector<double>{-1.0, -0.5});
  EXPECT_DOUBLE_EQ(neg->lo, -1.05);
  EXPECT_DOUBLE_EQ(neg->hi, -0.45);
  const auto single = pilot_range(std::vector<double>{2.0, 2.0});
  EXPECT_DOUBLE_EQ(single->lo, 1.998);
  EXPECT_DOUBLE_EQ(single->hi, 2.002);
  const auto zero = pilot_range(std::vector<double>{0.0});
  EXPECT_LT(zero->lo, 0.0);
  EXPECT_GT(zero->hi, 0.0);
  EXPECT_FALSE(pilot_range(std::vector<double>{kNaN, kInf}).has_value());
  EXPECT_FALSE(pilot_range(std::vector<double>{}).has_value());
}

TEST(FixedHistogram, RefusesBadEdges) {
  EXPECT_THROW(FixedHistogram({0.0, 1.0}, 0), InvalidInput);
  EXPECT_THROW(FixedHistogram({0.0, 1.0}, kMaxHistogramBins + 1), InvalidInput);
  EXPECT_THROW(FixedHistogram({1.0, 1.0}, 5), InvalidInput);
  EXPECT_THROW(FixedHistogram({2.0, 1.0}, 5), InvalidInput);
  EXPECT_THROW(FixedHistogram({0.0, kInf}, 5), InvalidInput);
  EXPECT_THROW(FixedHistogram({-1.7e308, 1.7e308}, 5), InvalidInput);  // hi − lo overflows
  EXPECT_THROW(FixedHistogram({kNaN, 1.0}, 5), InvalidInput);
  FixedHistogram none;  // no edges: counts nothing
  none.add(1.0);
  EXPECT_FALSE(none.has_edges());
  EXPECT_EQ(none.nan_count() + none.underflow() + none.overflow(), 0);
}

}  // namespace
}  // namespace poinsot::ensemble
