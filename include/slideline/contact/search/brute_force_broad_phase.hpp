#pragma once
/// The reference broad phase: every query tests every segment box. O(nodes x segments); the
/// oracle that every accelerated broad phase is diffed against, and fast enough for small
/// interfaces (a few hundred segments).
#include "slideline/contact/search/broad_phase.hpp"

namespace slideline {

class BruteForceBroadPhase final : public BroadPhase {
 protected:
  void rebuild_index() override {}
  void refit_index() override {}
  void collect(const Aabb& q, QueryScratch& scratch) const override {
    const std::vector<Aabb>& boxes = segment_boxes();
    const Index n = static_cast<Index>(boxes.size());
    for (Index s = 0; s < n; ++s) {
      if (boxes[static_cast<std::size_t>(s)].overlaps(q)) scratch.hits.push_back(s);
    }
  }
};

}  // namespace slideline
