#pragma once
/// Broad phase on FCL's dynamic AABB tree (fcl::detail::HierarchyTree<AABB>). FCL stays in
/// src/contact/search/fcl_broad_phase.cpp behind a pointer to an incomplete type.
///
/// build() builds the tree from the inflated segment boxes (Morton order); update() writes the new boxes
/// into the leaves and refits the internal boxes bottom-up (same topology, no allocation), so the
/// tree stays correct however far the segments move, only less tight: rebuild (call build()
/// again) when the mesh has moved far, e.g. every N searches. Queries walk the tree with an
/// explicit per-thread stack and test leaves with Aabb::overlaps, the same test as the brute
/// force, so both return identical candidates.
#include <memory>

#include "slideline/contact/search/broad_phase.hpp"

namespace slideline {

class FclBroadPhase final : public BroadPhase {
 public:
  FclBroadPhase();
  ~FclBroadPhase() override;
  FclBroadPhase(FclBroadPhase&&) noexcept;
  FclBroadPhase& operator=(FclBroadPhase&&) noexcept;

  /// Height of the tree (0 before build()), for diagnostics.
  Index tree_height() const;

 protected:
  void rebuild_index() override;
  void refit_index() override;
  void collect(const Aabb& q, QueryScratch& scratch) const override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace slideline
