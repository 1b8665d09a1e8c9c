#pragma once
/// @file block_merge.hpp
/// The statistics of an ensemble merged over its blocks of samples in one fixed order, in memory that does
/// not grow with the number of blocks.
///
/// The blocks' summaries are merged pairwise in the binary tree over the block indices: a node at level ℓ
/// holds blocks [s, s + 2^ℓ) with s a multiple of 2^ℓ, and is the merge (RunningStats::merge, Chan et al.)
/// of its two halves, left then right; a block beyond the run, or not run (an interrupted run), is empty.
/// Floating-point merging is not associative, but the tree does not depend on how the blocks were shared
/// out, so the root has the same bits for any number of threads or MPI ranks. Pairwise merging also bounds
/// the rounding error of the mean and M2 by O(log₂ blocks) merges instead of O(blocks).
///
/// BlockTree takes a contiguous range of blocks in index order and keeps only its complete subtrees whose
/// sibling has not arrived: at most 2⌈log₂ B⌉ + 1 nodes for B blocks (a binary counter). merge_tree
/// assembles the root from the subtrees of any number of such ranges (the shares of MPI ranks).
#include <array>
#include <cstdint>
#include <vector>

#include "poinsot/ensemble/statistics.hpp"

namespace poinsot::ensemble {

/// The outputs' count (runner.hpp names them).
inline constexpr int kOutputSlots = 15;

/// The statistics of one block of consecutive samples (the unit of merging), or of a subtree of blocks.
struct BlockSummary {
  std::uint64_t index = 0;  ///< block number (of a subtree: its first block)
  std::array<RunningStats, kOutputSlots> stats;
  std::int64_t rejected = 0, repaired = 0;
  std::int64_t body_steps = 0;  ///< the steps its samples took
};

/// `into` ← the merge of `into` (the left part) and `right`: statistics by RunningStats::merge, counts
/// summed.
void merge_summary(BlockSummary& into, const BlockSummary& right);

/// A complete subtree: blocks [summary.index, summary.index + 2^level).
struct BlockNode {
  std::int32_t level = 0;
  BlockSummary summary;
};

class BlockTree {
 public:
  /// Adds the next block: its index must follow the previous one's (InvalidInput otherwise).
  void push(const BlockSummary& block);
  /// The complete subtrees held, left to right; together they hold every block pushed.
  const std::vector<BlockNode>& nodes() const { return nodes_; }

 private:
  std::vector<BlockNode> nodes_;
  std::uint64_t next_ = 0;
};

/// The root of the tree over blocks [0, blocks) from complete subtrees (of one or several BlockTrees over
/// disjoint ranges, in any order): the statistics of all blocks present, the same bits however the blocks
/// were split into ranges. Throws InvalidInput for overlapping subtrees.
BlockSummary merge_tree(std::vector<BlockNode> nodes, std::uint64_t blocks);

}  // namespace poinsot::ensemble
