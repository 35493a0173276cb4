// FclBroadPhase: segment boxes in FCL's dynamic AABB tree. The tree is walked here rather than
// through FCL's collision-manager callbacks so that queries allocate nothing, run concurrently
// (const traversal, one stack per chunk). A leaf holds a bit-for-bit copy of its segment's box
// and is tested with the same closed-interval comparisons as Aabb::overlaps, so the candidates
// are exactly the brute force's.
#include "slideline/contact/search/fcl_broad_phase.hpp"

#include <cstdint>
#include <memory>
#include <fcl/broadphase/detail/hierarchy_tree.h>
#include <fcl/math/bv/AABB.h>

namespace slideline {

namespace {
using FclBox = fcl::AABB<double>;
using Tree = fcl::detail::HierarchyTree<FclBox>;
using TreeNode = Tree::NodeType;

FclBox to_fcl(const Aabb& b) { return FclBox(fcl::Vector3d(b.lo), fcl::Vector3d(b.hi)); }

bool overlaps(const FclBox& a, const Aabb& q) {
  return a.min_[0] <= q.hi[0] && q.lo[0] <= a.max_[0] && a.min_[1] <= q.hi[1] &&
         q.lo[1] <= a.max_[1] && a.min_[2] <= q.hi[2] && q.lo[2] <= a.max_[2];
}

Index segment_of(const TreeNode* leaf) {
  return static_cast<Index>(reinterpret_cast<std::intptr_t>(leaf->data));
}
}  // namespace

struct FclBroadPhase::Impl {
  Tree tree;                       // owns its nodes, leaves included
  std::vector<TreeNode*> leaf_of;  // leaf of segment s
};

FclBroadPhase::FclBroadPhase() : impl_(std::make_unique<Impl>()) {}
FclBroadPhase::~FclBroadPhase() = default;
FclBroadPhase::FclBroadPhase(FclBroadPhase&&) noexcept = default;
FclBroadPhase& FclBroadPhase::operator=(FclBroadPhase&&) noexcept = default;

Index FclBroadPhase::tree_height() const {
  return static_cast<Index>(impl_->tree.getMaxHeight());
}

void FclBroadPhase::rebuild_index() {
  Impl& m = *impl_;
  m.tree.clear();
  const std::vector<Aabb>& boxes = segment_boxes();
  const std::size_t n = boxes.size();
  m.leaf_of.assign(n, nullptr);
  std::vector<std::unique_ptr<TreeNode>> owned(n);  // until the tree takes ownership in init()
  std::vector<TreeNode*> leaves(n);
  bool any_empty = false;
  for (std::size_t s = 0; s < n; ++s) {
    owned[s] = std::make_unique<TreeNode>();
    TreeNode* leaf = owned[s].get();
    // A segment outside the domain has an empty box, whose centre is not finite: place it at the
    // origin for the build and empty it afterwards.
    if (boxes[s].is_empty()) {
      any_empty = true;
      leaf->bv = FclBox(fcl::Vector3d::Zero());
    } else {
      leaf->bv = to_fcl(boxes[s]);
    }
    leaf->data = reinterpret_cast<void*>(static_cast<std::intptr_t>(s));
    leaf->parent = nullptr;
    leaf->children[1] = nullptr;  // isLeaf() tests children[1]; data shares the union with [0]
    leaves[s] = leaf;
    m.leaf_of[s] = leaf;
  }
  if (n == 0) return;
  // Level 2: leaves sorted by the Morton code of their centre, split on the code bits. On plates of
  // 10^4..10^6 segments it builds 5-20x faster than level 0 (top-down median splits) and queries
  // visit ~10 % fewer tree nodes.
  for (auto& o : owned) o.release();
  m.tree.init(leaves, 2);
  if (any_empty) refit_index();
}

void FclBroadPhase::refit_index() {
  Impl& m = *impl_;
  const std::vector<Aabb>& boxes = segment_boxes();
  for (std::size_t s = 0; s < m.leaf_of.size(); ++s) {
    FclBox& bv = m.leaf_of[s]->bv;
    bv.min_ = boxes[s].lo;
    bv.max_ = boxes[s].hi;
  }
  m.tree.refit();
}

void FclBroadPhase::collect(const Aabb& q, QueryScratch& scratch) const {
  const TreeNode* root = impl_->tree.getRoot();
  if (root == nullptr) return;
  std::vector<const void*>& stack = scratch.stack;
  stack.clear();
  stack.push_back(root);
  while (!stack.empty()) {
    const auto* node = static_cast<const TreeNode*>(stack.back());
    stack.pop_back();
    if (!overlaps(node->bv, q)) continue;
    if (node->isLeaf()) {
      scratch.hits.push_back(segment_of(node));
    } else {
      stack.push_back(node->children[1]);
      stack.push_back(node->children[0]);
    }
  }
}

}  // namespace slideline
