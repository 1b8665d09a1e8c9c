// Tests of block_merge.hpp: the root of the block tree assembled from the subtrees of any split of the blocks
// into contiguous ranges has the same bits as from one range, and equals an independent recursive pairwise
// merge of the blocks (the oracle: the tree's definition written directly); the mean and variance agree with
// a two-pass computation over all values (in long double) to 1e-12 relative (Welford within a block and
// ⌈log₂ B⌉ = 17 levels of merges, each rounding by a few 1e-16); the subtrees held stay within 2⌈log₂ B⌉ + 1
// for 10^5 blocks (counted).
#include "poinsot/ensemble/block_merge.hpp"

#include <cmath>
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "poinsot/core/error.hpp"

namespace poinsot::ensemble {
namespace {

/// Block b's values of output q: seven values of exp(3u) (q = 0) or 5 + 0.1 u (q = 1), u uniform in [0, 1)
/// from splitmix64 of (b, q, i), and NaN as the fourth value of every fifth block.
std::vector<double> block_values(std::uint64_t b, int q) {
  std::vector<double> v;
  for (std::uint64_t i = 0; i < 7; ++i) {
    std::uint64_t z = (b * 16 + static_cast<std::uint64_t>(q) * 8 + i + 1) * 0x9E3779B97F4A7C15ULL;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    const double u = static_cast<double>(z >> 11) * 0x1.0p-53;
    v.push_back(i == 3 && b % 5 == 0 ? std::nan("") : (q == 0 ? std::exp(3.0 * u) : 5.0 + 0.1 * u));
  }
  return v;
}

BlockSummary block(std::uint64_t b) {
  BlockSummary s;
  s.index = b;
  for (int q = 0; q < 2; ++q)
    for (double x : block_values(b, q))
      s.stats[static_cast<std::size_t>(q)].add(x);
  s.rejected = static_cast<std::int64_t>(b % 3);
  s.repaired = static_cast<std::int64_t>(b % 2);
  return s;
}

/// The oracle: the node (level, start) by the tree's definition, recursively from the blocks.
BlockSummary oracle(int level, std::uint64_t start, std::uint64_t blocks) {
  BlockSummary out;
  if (start >= blocks) return out;
  if (level == 0) return block(start);
  out = oracle(level - 1, start, blocks);
  const BlockSummary right = oracle(level - 1, start + (std::uint64_t{1} << (level - 1)), blocks);
  for (std::size_t q = 0; q < out.stats.size(); ++q)
    out.stats[q].merge(right.stats[q]);
  out.rejected += right.rejected;
  out.repaired += right.repaired;
  return out;
}

bool same_bits(const BlockSummary& a, const BlockSummary& b) {
  for (std::size_t q = 0; q < a.stats.size(); ++q) {
    const RunningStats &x = a.stats[q], &y = b.stats[q];
    if (x.count != y.count || x.nan_count != y.nan_count ||
        std::memcmp(&x.mean, &y.mean, sizeof x.mean) != 0 || std::memcmp(&x.m2, &y.m2, sizeof x.m2) != 0 ||
        x.min != y.min || x.max != y.max)
      return false;
  }
  return a.rejected == b.rejected && a.repaired == b.repaired;
}

std::vector<BlockNode> tree_of(std::uint64_t first, std::uint64_t last) {
  BlockTree t;
  for (std::uint64_t b = first; b < last; ++b)
    t.push(block(b));
  return t.nodes();
}

TEST(BlockMerge, AnySplitIntoRangesGivesTheBitsOfTheTreeDefinition) {
  for (std::uint64_t blocks : {1u, 2u, 5u, 37u, 64u}) {
    int top = 0;
    while ((std::uint64_t{1} << top) < blocks)
      ++top;
    const BlockSummary expected = oracle(top, 0, blocks);
    EXPECT_TRUE(same_bits(merge_tree(tree_of(0, blocks), blocks), expected)) << blocks;
    // Two, three and `blocks` ranks (one block each), at every cut.
    for (std::uint64_t cut = 1; cut < blocks; ++cut) {
      std::vector<BlockNode> two = tree_of(cut, blocks);  // given out of order: merge_tree sorts
      const std::vector<BlockNode> left = tree_of(0, cut);
      two.insert(two.end(), left.begin(), left.end());
      EXPECT_TRUE(same_bits(merge_tree(two, blocks), expected)) << blocks << " cut " << cut;
      const std::uint64_t cut2 = (cut + blocks) / 2;
      std::vector<BlockNode> three = tree_of(0, cut);
      for (const auto& part : {tree_of(cut, cut2), tree_of(cut2, blocks)})
        three.insert(three.end(), part.begin(), part.end());
      EXPECT_TRUE(same_bits(merge_tree(three, blocks), expected))
          << blocks << " cuts " << cut << ", " << cut2;
    }
    std::vector<BlockNode> singles;
    for (std::uint64_t b = 0; b < blocks; ++b)
      singles.push_back({0, block(b)});
    EXPECT_TRUE(same_bits(merge_tree(singles, blocks), expected)) << blocks;
  }
  // Missing blocks (an interrupted run) count as empty; overlapping subtrees and gaps in a range are refused.
  EXPECT_EQ(merge_tree(tree_of(0, 3), 8).stats[0].count, 3 * 7 - 1);
  std::vector<BlockNode> overlap = tree_of(0, 4);
  overlap.push_back({0, block(2)});
  EXPECT_THROW(merge_tree(overlap, 4), InvalidInput);
  BlockTree gap;
  gap.push(block(3));
  EXPECT_THROW(gap.push(block(5)), InvalidInput);
}

TEST(BlockMerge, MeanAndVarianceAgreeWithTwoPassAndTheSubtreesStayLogarithmic) {
  const std::uint64_t blocks = 100000, first = 12345;  // a range that starts off every subtree boundary
  BlockTree t;
  std::size_t most = 0;
  long double sum = 0.0L;
  std::vector<double> all;
  for (std::uint64_t b = first; b < first + blocks; ++b) {
    t.push(block(b));
    most = std::max(most, t.nodes().size());
    for (double x : block_values(b, 0))
      if (!std::isnan(x)) all.push_back(x);
  }
  EXPECT_LE(most, 2u * 17u + 1u);  // ⌈log₂(112345)⌉ = 17
  for (double x : all)
    sum += x;
  const long double mean_ld = sum / static_cast<long double>(all.size());
  long double m2_ld = 0.0L;
  for (double x : all)
    m2_ld += (x - mean_ld) * (x - mean_ld);
  const auto mean = static_cast<double>(mean_ld), m2 = static_cast<double>(m2_ld);
  const RunningStats s = merge_tree(t.nodes(), first + blocks).stats[0];
  ASSERT_EQ(s.count, static_cast<std::int64_t>(all.size()));
  // The long double sums round by at most n·5.4e-20 ≈ 4e-14 relative: negligible against 1e-12.
  EXPECT_NEAR(s.mean, mean, 1e-12 * mean);
  EXPECT_NEAR(s.m2, m2, 1e-12 * m2);
}

}  // namespace
}  // namespace poinsot::ensemble
