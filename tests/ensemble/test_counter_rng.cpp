#include "poinsot/ensemble/counter_rng.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "ks.hpp"

namespace poinsot::ensemble {
namespace {

TEST(CounterRng, DrawsDependOnlyOnSeedSampleStreamAndDrawNumber) {
  SampleStream a(7, 12345, Stream::omega);
  std::vector<std::uint64_t> first;
  for (int i = 0; i < 10; ++i)
    first.push_back(a.next_word());
  // Another stream object, created after unrelated draws of other samples, repeats the sequence.
  SampleStream other(7, 99, Stream::omega);
  for (int i = 0; i < 5; ++i)
    other.next_word();
  SampleStream b(7, 12345, Stream::omega);
  for (int i = 0; i < 10; ++i)
    EXPECT_EQ(b.next_word(), first[static_cast<std::size_t>(i)]);
  EXPECT_EQ(b.draws(), 10u);
  // Any change of seed, sample or stream changes the draws.
  EXPECT_NE(SampleStream(8, 12345, Stream::omega).next_word(), first[0]);
  EXPECT_NE(SampleStream(7, 12346, Stream::omega).next_word(), first[0]);
  EXPECT_NE(SampleStream(7, 12345, Stream::axes).next_word(), first[0]);
}

TEST(CounterRng, UniformAndNormalPassKolmogorovSmirnov) {
  const std::size_t n = 20000;
  std::vector<double> u, z;
  for (std::size_t i = 0; i < n; ++i) {
    SampleStream s(2026, i, Stream::moments);  // one sample each: the cross-sample independence matters
    const double x = s.uniform();
    EXPECT_GT(x, 0.0);
    EXPECT_LT(x, 1.0);
    u.push_back(x);
    z.push_back(s.normal());
  }
  EXPECT_LT(test::ks_statistic(u, [](double x) { return x; }), test::ks_critical_0001(n));
  EXPECT_LT(test::ks_statistic(z, test::normal_cdf), test::ks_critical_0001(n));
}

}  // namespace
}  // namespace poinsot::ensemble
