#pragma once
/// Local search between two broad-phase searches: a slave node keeps its master segment and
/// re-projects; when the closest point reaches an edge it looks across that edge.
///
/// Rule (deterministic): project onto the current segment. If the closest point lies on one or
/// more local edges (within the parametric tolerance: a point beyond an edge projects onto it),
/// project onto every neighbour not yet visited that shares such an edge (segment_neighbors
/// order; all of them where more than two segments share an edge), and in any case onto a
/// coincident segment (same nodes, e.g. a shell on a solid face). Move to the best of them if it
/// is better than the current one by `is_better_projection` (nearer beyond the tie tolerance, or
/// a tie and a lower segment index). Repeat up to `max_hops` times; stop when no neighbour looked
/// at is better. Because ties go to the lower index in both, tracking agrees with
/// `nearest_segment` over all segments on flat and convex surfaces, including points exactly
/// above edges and corners, and on curved surfaces while the point is near the surface (distance
/// small against the radius of curvature). Far from a wavy surface the distance has several
/// local minima and the walk may stop in one; over a valley (a concave kink between two
/// segments) both sides may hold an interior minimum and the walk keeps the one it is on (the
/// two distances differ to second order). The periodic broad-phase search
/// (SearchCadence, then nearest_segment) resets it.
#include <algorithm>
#include <array>
#include <span>

#include "slideline/contact/search/broad_phase.hpp"
#include "slideline/contact/search/closest_point.hpp"
#include "slideline/contact/search/slave_orientation.hpp"
#include "slideline/mesh/nodal_fields.hpp"
#include "slideline/mesh/surface.hpp"

namespace slideline {

struct TrackingOptions {
  int max_hops = 4;  ///< neighbour moves at most (the walk also stops after 64 segments looked at)
  ProjectionOptions projection;
};

/// A projection together with the segment it is on.
struct SegmentProjection {
  Index segment = -1;  ///< -1: no segment (empty candidate list)
  Projection projection;
  int hops = 0;  ///< neighbour moves made by track_segment
};

namespace detail {

inline bool segment_has_node(const Surface& surface, Index t, Index n) {
  const Index* c = &surface.conn[4 * static_cast<std::size_t>(t)];
  return c[0] == n || c[1] == n || c[2] == n || c[3] == n;
}

/// True when t has every node of s (a coincident segment, e.g. a shell lying on a solid face).
inline bool covers_segment(const Surface& surface, Index t, Index s) {
  const Index* c = &surface.conn[4 * static_cast<std::size_t>(s)];
  return segment_has_node(surface, t, c[0]) && segment_has_node(surface, t, c[1]) &&
         segment_has_node(surface, t, c[2]) && segment_has_node(surface, t, c[3]);
}

/// True when segment t contains both end nodes of local edge k of s (a non-collapsed edge).
inline bool shares_edge(const Surface& surface, Index s, int k, Index t) {
  const std::size_t base = 4 * static_cast<std::size_t>(s);
  const Index a = surface.conn[base + static_cast<std::size_t>(k)];
  const Index b = surface.conn[base + static_cast<std::size_t>((k + 1) % 4)];
  return a != b && segment_has_node(surface, t, a) && segment_has_node(surface, t, b);
}

}  // namespace detail

/// The neighbour of segment s across its local edge k (0..3, see closest_point.hpp), from
/// surface.segment_neighbors: the lowest-index neighbour that contains both end nodes of the
/// edge and is not coincident with s (same nodes, e.g. a shell lying on a solid face), or -1 on
/// a free edge or a triangle's collapsed edge. No allocation.
inline Index neighbor_across_edge(const Surface& surface, Index s, int k) {
  const Csr& nb = surface.segment_neighbors;
  for (Index j = nb.begin(s); j < nb.end(s); ++j) {
    const Index t = nb.value[static_cast<std::size_t>(j)];
    if (detail::shares_edge(surface, s, k, t) && !detail::covers_segment(surface, t, s)) return t;
  }
  return -1;
}

/// Re-projects point p (length) starting from segment `start` (a valid index) of `surface` at
/// coordinates x and walks to neighbours as described in the file comment: every unvisited
/// neighbour (surface.segment_neighbors) that shares an edge the closest point lies on is
/// projected onto, so coincident segments and edges shared by more than two segments are handled.
/// Returns the segment it ends on and the projection there. No allocation.
/// `rule` (slave_orientation.hpp): NearestRule compares by is_better_projection; FacingRule only
/// moves to segments the slave's orientation admits and compares by is_better_contact.
template <class Rule = NearestRule>
SegmentProjection track_segment(const Vec3& p, Index start, const Surface& surface, const Vec3Field& x,
                                const TrackingOptions& opt = {}, const Rule& rule = {}) {
  const ProjectionOptions& po = opt.projection;
  SegmentProjection best{start, project_point_to_segment(p, surface, start, x, po), 0};
  std::array<Index, 64> visited{};
  std::size_t nvisited = 0;
  visited[nvisited++] = start;
  const Csr& nb = surface.segment_neighbors;
  for (int hop = 0; hop < opt.max_hops; ++hop) {
    Index next = -1;
    Projection next_proj;
    for (Index j = nb.begin(best.segment); j < nb.end(best.segment); ++j) {
      const Index t = nb.value[static_cast<std::size_t>(j)];
      bool across = detail::covers_segment(surface, t, best.segment);
      for (int k = 0; k < kSegmentEdges && !across; ++k) {
        across = best.projection.on_edge(k) && detail::shares_edge(surface, best.segment, k, t);
      }
      if (!across) continue;
      if (std::find(visited.begin(), visited.begin() + nvisited, t) != visited.begin() + nvisited) continue;
      if (nvisited == visited.size()) break;  // an extreme fan: stop looking further
      visited[nvisited++] = t;
      if (!rule.admits(t)) continue;
      const Projection pr = project_point_to_segment(p, surface, t, x, po);
      if (next < 0 || rule.better(p, pr, t, next_proj, next, po)) {
        next = t;
        next_proj = pr;
      }
    }
    if (next < 0 || !rule.better(p, next_proj, next, best.projection, best.segment, po)) break;
    best = {next, next_proj, hop + 1};
  }
  return best;
}

/// The best projection of p over the segments `segments` (any order; e.g. one node's broad-phase
/// candidates) by `is_better_projection`. Segment -1 when the list is empty. No allocation.
inline SegmentProjection nearest_segment(const Vec3& p, std::span<const Index> segments,
                                         const Surface& surface, const Vec3Field& x,
                                         const ProjectionOptions& opt = {}) {
  SegmentProjection best;
  for (Index s : segments) {
    const Projection pr = project_point_to_segment(p, surface, s, x, opt);
    if (best.segment < 0 || is_better_projection(pr, s, best.projection, best.segment, opt)) {
      best.segment = s;
      best.projection = pr;
    }
  }
  return best;
}

/// The same over one node's broad-phase candidates (a run of equal `node` in BroadPhase::query's
/// output; only `segment` is read), by `rule` (see track_segment). Segment -1 when the run is
/// empty or the rule admits none of it. No allocation.
template <class Rule = NearestRule>
SegmentProjection nearest_segment(const Vec3& p, std::span<const Candidate> candidates, const Surface& surface,
                                  const Vec3Field& x, const ProjectionOptions& opt = {}, const Rule& rule = {}) {
  SegmentProjection best;
  for (const Candidate& c : candidates) {
    if (!rule.admits(c.segment)) continue;
    const Projection pr = project_point_to_segment(p, surface, c.segment, x, opt);
    if (best.segment < 0 || rule.better(p, pr, c.segment, best.projection, best.segment, opt)) {
      best.segment = c.segment;
      best.projection = pr;
    }
  }
  return best;
}

/// The end of the run of candidates of node candidates[begin].node, starting at begin (the
/// output of BroadPhase::query is grouped by node): candidates[begin .. end) share the node.
inline std::size_t candidate_run_end(std::span<const Candidate> candidates, std::size_t begin) {
  std::size_t end = begin;
  while (end < candidates.size() && candidates[end].node == candidates[begin].node) ++end;
  return end;
}

}  // namespace slideline
