#include "poinsot/ensemble/block_merge.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"

namespace poinsot::ensemble {
namespace {

std::uint64_t span(std::int32_t level) {
  return std::uint64_t{1} << level;
}

/// The node (level, start) of the tree, from the sorted subtrees `nodes` (empty where no block is present).
BlockSummary node_at(const std::vector<BlockNode>& nodes, std::int32_t level, std::uint64_t start,
                     std::uint64_t blocks) {
  BlockSummary out;
  out.index = start;
  if (start >= blocks) return out;
  // The first subtree starting at or after `start`: none inside [start, start + 2^level) means empty.
  const auto it = std::lower_bound(nodes.begin(), nodes.end(), start,
                                   [](const BlockNode& n, std::uint64_t s) { return n.summary.index < s; });
  if (it == nodes.end() || it->summary.index >= start + span(level)) return out;
  if (it->summary.index == start && it->level == level) return it->summary;
  if (level == 0) return out;  // not reached: a block is a level-0 subtree or inside a larger one
  out = node_at(nodes, level - 1, start, blocks);
  merge_summary(out, node_at(nodes, level - 1, start + span(level - 1), blocks));
  out.index = start;
  return out;
}

}  // namespace

void merge_summary(BlockSummary& into, const BlockSummary& right) {
  for (std::size_t q = 0; q < into.stats.size(); ++q)
    into.stats[q].merge(right.stats[q]);
  into.rejected += right.rejected;
  into.repaired += right.repaired;
  into.body_steps += right.body_steps;
}

void BlockTree::push(const BlockSummary& block) {
  if (!nodes_.empty() && block.index != next_) {
    throw InvalidInput(fmt::format("ensemble: block {} pushed after block {}; expected block {}", block.index,
                                   next_ - 1, next_));
  }
  next_ = block.index + 1;
  nodes_.push_back({0, block});
  // Merge while the last two nodes are the left and right halves of one node.
  while (nodes_.size() >= 2) {
    BlockNode& left = nodes_[nodes_.size() - 2];
    const BlockNode& right = nodes_.back();
    const std::int32_t l = right.level;
    if (left.level != l || left.summary.index % span(l + 1) != 0 ||
        right.summary.index != left.summary.index + span(l))
      break;
    merge_summary(left.summary, right.summary);
    left.level = l + 1;
    nodes_.pop_back();
  }
}

BlockSummary merge_tree(std::vector<BlockNode> nodes, std::uint64_t blocks) {
  std::sort(nodes.begin(), nodes.end(),
            [](const BlockNode& a, const BlockNode& b) { return a.summary.index < b.summary.index; });
  for (std::size_t i = 1; i < nodes.size(); ++i) {
    if (nodes[i - 1].summary.index + span(nodes[i - 1].level) > nodes[i].summary.index) {
      throw InvalidInput(
          fmt::format("ensemble: the subtrees at blocks {} and {} overlap; expected disjoint ranges",
                      nodes[i - 1].summary.index, nodes[i].summary.index));
    }
  }
  std::int32_t top = 0;
  while (span(top) < blocks)
    ++top;
  return node_at(nodes, top, 0, blocks);
}

}  // namespace poinsot::ensemble
