#pragma once
/// Local search between two broad-phase searches: a slave node keeps its master segment and
/// re-projects; when the closest point reaches an edge it looks across that edge.
///
/// Rule (deterministic): project onto the current segment. If the closest point lies on one or
/// more local edges (within the parametric tolerance: a point beyond an edge projects onto it),
/// project onto the neighbour across each such edge not yet visited, in edge order 0..3. Move to
/// the best of them if it is better than the current one by `is_better_projection` (nearer beyond
/// the tie tolerance, or a tie and a lower segment index). Repeat up to `max_hops` times; stop
/// when the closest point is interior or no neighbour is better. Because ties go to the lower
/// index in both, tracking agrees with `nearest_segment` over all segments on flat and convex
/// surfaces, including points exactly above edges and corners, and on curved surfaces while the
/// point is near the surface (distance small against the radius of curvature). Far from a wavy
/// surface the distance has several local minima and the walk may stop in one; over a valley (a
/// concave kink between two segments) both sides may hold an interior minimum and the walk keeps
/// the one it is on (the two distances differ to second order). The periodic broad-phase search
/// (SearchCadence, then nearest_segment) resets it.
#include <algorithm>
#include <array>
#include <span>

#include "slideline/contact/search/broad_phase.hpp"
#include "slideline/contact/search/closest_point.hpp"
#include "slideline/mesh/nodal_fields.hpp"
#include "slideline/mesh/surface.hpp"

namespace slideline {

struct TrackingOptions {
  int max_hops = 4;  ///< at most 7 (the visited set is a fixed array)
  ProjectionOptions projection;
};

/// A projection together with the segment it is on.
struct SegmentProjection {
  Index segment = -1;  ///< -1: no segment (empty candidate list)
  Projection projection;
  int hops = 0;  ///< neighbour moves made by track_segment
};

/// The neighbour of segment s across its local edge k (0..3, see closest_point.hpp), from
/// surface.segment_neighbors: the lowest-index neighbour that contains both end nodes of the
/// edge, or -1 on a free boundary or a triangle's collapsed edge. No allocation.
inline Index neighbor_across_edge(const Surface& surface, Index s, int k) {
  const std::size_t base = 4 * static_cast<std::size_t>(s);
  const Index a = surface.conn[base + static_cast<std::size_t>(k)];
  const Index b = surface.conn[base + static_cast<std::size_t>((k + 1) % 4)];
  if (a == b) return -1;
  const Csr& nb = surface.segment_neighbors;
  for (Index j = nb.begin(s); j < nb.end(s); ++j) {
    const Index t = nb.value[static_cast<std::size_t>(j)];
    const Index* c = &surface.conn[4 * static_cast<std::size_t>(t)];
    const bool has_a = c[0] == a || c[1] == a || c[2] == a || c[3] == a;
    const bool has_b = c[0] == b || c[1] == b || c[2] == b || c[3] == b;
    if (has_a && has_b) return t;
  }
  return -1;
}

/// Re-projects point p (length) starting from segment `start` of `surface` at coordinates x and
/// walks to neighbours as described in the file comment. Returns the segment it ends on and the
/// projection there. No allocation.
inline SegmentProjection track_segment(const Vec3& p, Index start, const Surface& surface,
                                       const Vec3Field& x, const TrackingOptions& opt = {}) {
  const ProjectionOptions& po = opt.projection;
  SegmentProjection best{start, project_point_to_segment(p, surface, start, x, po), 0};
  std::array<Index, 32> visited{};
  int nvisited = 0;
  visited[nvisited++] = start;
  const int max_hops = std::min(opt.max_hops, 7);
  for (int hop = 0; hop < max_hops && !best.projection.interior(); ++hop) {
    Index next = -1;
    Projection next_proj;
    for (int k = 0; k < kSegmentEdges; ++k) {
      if (!best.projection.on_edge(k)) continue;
      const Index nb = neighbor_across_edge(surface, best.segment, k);
      if (nb < 0 || std::find(visited.begin(), visited.begin() + nvisited, nb) != visited.begin() + nvisited) {
        continue;
      }
      visited[nvisited++] = nb;
      const Projection pr = project_point_to_segment(p, surface, nb, x, po);
      if (next < 0 || is_better_projection(pr, nb, next_proj, next, po)) {
        next = nb;
        next_proj = pr;
      }
    }
    if (next < 0 || !is_better_projection(next_proj, next, best.projection, best.segment, po)) break;
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
/// output; only `segment` is read). Segment -1 when the run is empty. No allocation.
inline SegmentProjection nearest_segment(const Vec3& p, std::span<const Candidate> candidates,
                                         const Surface& surface, const Vec3Field& x,
                                         const ProjectionOptions& opt = {}) {
  SegmentProjection best;
  for (const Candidate& c : candidates) {
    const Projection pr = project_point_to_segment(p, surface, c.segment, x, opt);
    if (best.segment < 0 || is_better_projection(pr, c.segment, best.projection, best.segment, opt)) {
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
