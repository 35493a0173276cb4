#pragma once
/// Broad phase of the contact search: which master segments may touch which slave nodes.
///
/// Rules (both implementations follow them exactly, so that they return identical candidates):
/// - Each master segment gets the axis-aligned box of its 4 corners at the current coordinates,
///   inflated by `margin` on every side. A slave node's query box is [p - r, p + r] (r = the
///   query radius, e.g. a nodal radius or a shell half thickness; 0 for a point).
/// - (node, segment) is a candidate when the two closed boxes overlap (touching counts).
/// - Domain limit (DYNA3D Type 12's bounding box): when `domain` is set, a segment takes part
///   only if its un-inflated box overlaps the domain, and a node only if it lies inside the closed
///   domain. Segments are re-classified on every update().
/// - With `skip_incident`, a node never gets a segment it is a corner of (single-surface contact).
/// - Candidates come out grouped by node in the order of the query list, each node's segments
///   ascending. With an ascending node list (Surface::nodes is one) that is "sorted by node, then
///   segment". The result does not depend on the number of threads.
/// - Storage: build() allocates; update() and query() reuse what earlier calls allocated, so in a
///   steady state (same sizes, similar candidate counts) a time step allocates nothing. The output
///   vector only grows when a query returns more candidates than any earlier one.
#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "slideline/core/error.hpp"
#include "slideline/core/parallel.hpp"
#include "slideline/core/types.hpp"
#include "slideline/mesh/nodal_fields.hpp"
#include "slideline/mesh/surface.hpp"

namespace slideline {

/// A closed axis-aligned box [lo, hi] (length). The empty box has lo = +inf, hi = -inf.
struct Aabb {
  Vec3 lo = Vec3::Constant(std::numeric_limits<Real>::infinity());
  Vec3 hi = Vec3::Constant(-std::numeric_limits<Real>::infinity());

  static Aabb empty() { return {}; }
  static Aabb around(const Vec3& p, Real r) { return {p - Vec3::Constant(r), p + Vec3::Constant(r)}; }
  bool is_empty() const { return lo[0] > hi[0] || lo[1] > hi[1] || lo[2] > hi[2]; }
  void expand(const Vec3& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  void inflate(Real m) {
    lo.array() -= m;
    hi.array() += m;
  }
  bool contains(const Vec3& p) const {
    return lo[0] <= p[0] && p[0] <= hi[0] && lo[1] <= p[1] && p[1] <= hi[1] && lo[2] <= p[2] &&
           p[2] <= hi[2];
  }
  /// Closed-interval overlap; an empty box overlaps nothing.
  bool overlaps(const Aabb& o) const {
    return lo[0] <= o.hi[0] && o.lo[0] <= hi[0] && lo[1] <= o.hi[1] && o.lo[1] <= hi[1] &&
           lo[2] <= o.hi[2] && o.lo[2] <= hi[2];
  }
};

/// One broad-phase candidate: internal node index and master segment index.
struct Candidate {
  Index node = 0;
  Index segment = 0;
  friend bool operator==(const Candidate&, const Candidate&) = default;
  friend auto operator<=>(const Candidate&, const Candidate&) = default;
};

struct BroadPhaseOptions {
  /// Inflation of every segment box on each side (length). It lets candidates stay valid while
  /// the bodies move; see SearchCadence for when a new search is due.
  Real margin = 0.0;
  /// Only segments whose box meets this box, and nodes inside it, take part (Type 12 domain).
  std::optional<Aabb> domain;
  /// Leave out the segments a node is a corner of (single-surface contact, Type 12, where every
  /// node is a slave and every segment a master: a node always touches its own segments).
  bool skip_incident = false;
};

/// The broad-phase interface. Derived classes only index the segment boxes; the box rules, the
/// domain limit, ordering and threading live here so that every implementation agrees.
class BroadPhase {
 public:
  virtual ~BroadPhase() = default;

  /// Builds the search structure for the segments of `master` at coordinates x (SoA, length; x
  /// indexed by internal node). Keeps a pointer to `master`: it must outlive this object or the
  /// next build(). Allocates.
  void build(const Surface& master, const Vec3Field& x, const BroadPhaseOptions& options) {
    master_ = &master;
    options_ = options;
    boxes_.resize(static_cast<std::size_t>(master.segment_count()));
    compute_boxes(x);
    rebuild_index();
  }

  /// Recomputes the segment boxes from the current coordinates x and refits the index.
  /// No allocation. O(segments).
  void update(const Vec3Field& x) {
    require_built();
    compute_boxes(x);
    refit_index();
  }

  /// Candidates for the slave nodes `nodes` (internal indices) at coordinates x, with query
  /// radius r (length, >= 0). Clears and fills `out` (see the file comment for the order).
  void query(std::span<const Index> nodes, const Vec3Field& x, Real r, std::vector<Candidate>& out) {
    query_impl(nodes, x, [r](Index) { return r; }, out);
  }

  /// The same with one query radius per node: radius[i] (length, >= 0) for nodes[i], e.g. half
  /// the thickness of the shell a node belongs to.
  void query(std::span<const Index> nodes, const Vec3Field& x, std::span<const Real> radius,
             std::vector<Candidate>& out) {
    if (radius.size() != nodes.size()) throw Error("BroadPhase::query: one radius per node");
    query_impl(nodes, x, [radius](Index i) { return radius[static_cast<std::size_t>(i)]; }, out);
  }

  /// The inflated segment boxes (empty for a segment outside the domain), one per segment.
  const std::vector<Aabb>& segment_boxes() const { return boxes_; }
  const BroadPhaseOptions& options() const { return options_; }
  /// Number of segments that take part (inside the domain, or all without one).
  Index active_segment_count() const {
    return static_cast<Index>(std::count_if(boxes_.begin(), boxes_.end(),
                                            [](const Aabb& b) { return !b.is_empty(); }));
  }

 protected:
  // Copy and move only through a final class (no slicing through the interface).
  BroadPhase() = default;
  BroadPhase(const BroadPhase&) = default;
  BroadPhase& operator=(const BroadPhase&) = default;
  BroadPhase(BroadPhase&&) = default;
  BroadPhase& operator=(BroadPhase&&) = default;

  /// Per-chunk working storage, kept between queries.
  struct QueryScratch {
    std::vector<Index> hits;          ///< segments found for the current node, any order
    std::vector<const void*> stack;   ///< traversal stack for tree implementations
  };

  /// (Re)creates the index over segment_boxes(). Called by build(). May allocate.
  virtual void rebuild_index() = 0;
  /// The boxes changed (same count): make the index consistent. Must not allocate.
  virtual void refit_index() = 0;
  /// Appends to scratch.hits every segment whose box overlaps q (Aabb::overlaps), each once, in
  /// any order. Called concurrently from several threads with distinct scratch objects.
  virtual void collect(const Aabb& q, QueryScratch& scratch) const = 0;

  const Surface& master() const { return *master_; }

 private:
  struct ChunkScratch {
    QueryScratch scratch;
    std::vector<Candidate> pairs;
  };

  template <class RadiusOf>
  void query_impl(std::span<const Index> nodes, const Vec3Field& x, RadiusOf radius_of,
                  std::vector<Candidate>& out) {
    require_built();
    const Index n = static_cast<Index>(nodes.size());
    const Index nchunks = chunk_count(n);
    if (static_cast<Index>(chunks_.size()) < nchunks) chunks_.resize(static_cast<std::size_t>(nchunks));
    parallel_for_chunks(n, [&](Index b, Index e, Index c) {
      ChunkScratch& cs = chunks_[static_cast<std::size_t>(c)];
      cs.pairs.clear();
      for (Index i = b; i < e; ++i) {
        const Index node = nodes[static_cast<std::size_t>(i)];
        const Vec3 p = x.get(node);
        if (options_.domain && !options_.domain->contains(p)) continue;
        cs.scratch.hits.clear();
        collect(Aabb::around(p, radius_of(i)), cs.scratch);
        std::sort(cs.scratch.hits.begin(), cs.scratch.hits.end());
        for (Index s : cs.scratch.hits) {
          if (options_.skip_incident && is_corner(node, s)) continue;
          cs.pairs.push_back({node, s});
        }
      }
    });
    out.clear();
    for (Index c = 0; c < nchunks; ++c) {
      const auto& p = chunks_[static_cast<std::size_t>(c)].pairs;
      out.insert(out.end(), p.begin(), p.end());
    }
  }

  void require_built() const {
    if (master_ == nullptr) throw Error("BroadPhase: update() or query() before build()");
  }

  bool is_corner(Index node, Index s) const {
    const Index* c = &master_->conn[4 * static_cast<std::size_t>(s)];
    return c[0] == node || c[1] == node || c[2] == node || c[3] == node;
  }

  void compute_boxes(const Vec3Field& x) {
    const Surface& m = *master_;
    parallel_for(m.segment_count(), [&](Index s) {
      Aabb b;
      for (int k = 0; k < 4; ++k) b.expand(x.get(m.conn[4 * static_cast<std::size_t>(s) + k]));
      if (options_.domain && !options_.domain->overlaps(b)) {
        b = Aabb::empty();
      } else {
        b.inflate(options_.margin);
      }
      boxes_[static_cast<std::size_t>(s)] = b;
    });
  }

  const Surface* master_ = nullptr;
  BroadPhaseOptions options_;
  std::vector<Aabb> boxes_;
  std::vector<ChunkScratch> chunks_;
};

}  // namespace slideline
