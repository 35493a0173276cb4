#pragma once
/// Per node, the elements' stable step for the contact springs' step votes (contact/
/// element_steps_view.hpp; docs/solver.md, "The step of a node with elements and a contact spring").
///
/// The element blocks vote their smallest step (ElementBlock::compute_forces); a node's dt_e here is
/// the smallest vote of the blocks it belongs to, so it is never above the step of any element on the
/// node (equal where the block's smallest element is on it, as at an impact face; below it where a
/// smaller element elsewhere in the block sets the block's vote). Nodes are grouped at build() by the
/// set of blocks they belong to (most nodes: one block), so a cycle costs one pass over the groups,
/// not over the nodes.
#include <span>
#include <vector>

#include "slideline/contact/element_steps_view.hpp"
#include "slideline/core/types.hpp"
#include "slideline/element/element_block.hpp"

namespace slideline {

class NodalElementSteps {
 public:
  /// Groups the `node_count` nodes by the set of blocks that bound the step (bounds_time_step())
  /// they belong to; group 0 holds the nodes of none (their element term is 0). Allocates: once,
  /// at initialize().
  void build(const ElementBlocks& blocks, Index node_count);
  /// This cycle's votes, one per block of build() (time, before TSSFAC; +max or +inf: the block
  /// votes nothing): each group's 1 / dt_e^2, the largest over its blocks. Allocates nothing.
  void update(std::span<const Real> block_steps);
  /// The per-node view the interfaces read (empty before build()).
  ElementStepsView view() const { return {group_, group_inv2_}; }
  bool built() const { return !group_.empty(); }
  std::size_t group_count() const { return group_inv2_.size(); }

 private:
  std::vector<Index> group_;         ///< per node: its group
  std::vector<Index> group_offset_;  ///< CSR over the groups: their blocks in group_block_
  std::vector<Index> group_block_;
  std::vector<Real> group_inv2_;     ///< per group: 1 / dt_e^2 of this cycle (1 / time^2)
};

}  // namespace slideline
