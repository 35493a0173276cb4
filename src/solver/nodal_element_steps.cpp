#include "slideline/solver/nodal_element_steps.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace slideline {

void NodalElementSteps::build(const ElementBlocks& blocks, Index node_count) {
  const auto n = static_cast<std::size_t>(node_count);
  // Per node, the blocks that bound the step (CSR, blocks ascending: they are visited in order).
  std::vector<Index> count(n + 1, 0), last(n, -1);
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    if (!blocks[k]->bounds_time_step()) continue;
    for (Index i : blocks[k]->connectivity())
      if (last[static_cast<std::size_t>(i)] != static_cast<Index>(k)) {
        last[static_cast<std::size_t>(i)] = static_cast<Index>(k);
        ++count[static_cast<std::size_t>(i) + 1];
      }
  }
  for (std::size_t i = 0; i < n; ++i) count[i + 1] += count[i];
  std::vector<Index> member(static_cast<std::size_t>(count[n]));
  std::vector<Index> fill(count.begin(), count.end() - 1);
  std::fill(last.begin(), last.end(), -1);
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    if (!blocks[k]->bounds_time_step()) continue;
    for (Index i : blocks[k]->connectivity()) {
      const auto iu = static_cast<std::size_t>(i);
      if (last[iu] == static_cast<Index>(k)) continue;
      last[iu] = static_cast<Index>(k);
      member[static_cast<std::size_t>(fill[iu]++)] = static_cast<Index>(k);
    }
  }
  // One group per distinct set; group 0 is the empty set.
  std::map<std::vector<Index>, Index> groups;
  groups.emplace(std::vector<Index>{}, 0);
  group_offset_.assign(1, 0);
  group_offset_.push_back(0);
  group_block_.clear();
  group_.assign(n, 0);
  std::vector<Index> key;
  for (std::size_t i = 0; i < n; ++i) {
    key.assign(member.begin() + count[i], member.begin() + count[i + 1]);
    const auto [it, added] = groups.emplace(key, static_cast<Index>(groups.size()));
    if (added) {
      group_block_.insert(group_block_.end(), key.begin(), key.end());
      group_offset_.push_back(static_cast<Index>(group_block_.size()));
    }
    group_[i] = it->second;
  }
  group_inv2_.assign(groups.size(), 0.0);
}

void NodalElementSteps::update(std::span<const Real> block_steps) {
  for (std::size_t g = 0; g < group_inv2_.size(); ++g) {
    Real w = 0.0;
    for (Index b = group_offset_[g]; b < group_offset_[g + 1]; ++b) {
      const Real d = block_steps[static_cast<std::size_t>(group_block_[static_cast<std::size_t>(b)])];
      if (d > 0.0 && d < std::numeric_limits<Real>::max()) w = std::max(w, 1.0 / (d * d));
    }
    group_inv2_[g] = w;
  }
}

}  // namespace slideline
