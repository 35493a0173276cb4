#pragma once
/// Batch forms of the narrow phase for a whole slave node list: the nearest segment among each
/// node's broad-phase candidates (after a search), and local tracking (between searches).
/// Both run in parallel over nodes, write one result per node, allocate nothing, and give the
/// same result for any thread count (each node is independent).
#include <algorithm>
#include <span>

#include "slideline/contact/search/broad_phase.hpp"
#include "slideline/contact/search/segment_tracking.hpp"
#include "slideline/core/parallel.hpp"

namespace slideline {

/// For every slave node nodes[i] (internal indices, strictly ascending, the list given to
/// BroadPhase::query), the nearest of its candidates in `candidates` (that query's output) by
/// is_better_projection, at coordinates x (length). out[i].segment = -1 for a node without
/// candidates. out.size() must equal nodes.size().
/// With `orientation` (the slaves' SlaveOrientation, indexed like `nodes`), the choice of
/// slave_orientation.hpp: admitted candidates only, over before beside, then nearest.
inline void assign_nearest_segments(std::span<const Index> nodes,
                                    std::span<const Candidate> candidates, const Surface& master,
                                    const Vec3Field& x, std::span<SegmentProjection> out,
                                    const ProjectionOptions& opt = {},
                                    const SlaveOrientation* orientation = nullptr) {
  parallel_for(static_cast<Index>(nodes.size()), [&](Index i) {
    const std::size_t k = static_cast<std::size_t>(i);
    const Index node = nodes[k];
    const auto first = std::lower_bound(candidates.begin(), candidates.end(), node,
                                        [](const Candidate& c, Index n) { return c.node < n; });
    auto last = first;
    while (last != candidates.end() && last->node == node) ++last;
    const std::span<const Candidate> run(first, last);
    out[k] = orientation ? nearest_segment(x.get(node), run, master, x, opt, FacingRule{orientation, k, &master, &x})
                         : nearest_segment(x.get(node), run, master, x, opt);
  });
}

/// For every slave node nodes[i] with a segment (segment[i] >= 0), track_segment from segment[i]
/// at coordinates x; writes out[i] (segment -1, projection untouched, for a node without one).
/// segment, out: nodes.size() entries each. segment and out may not alias.
/// With `orientation`, tracking moves only to admitted segments (slave_orientation.hpp).
inline void track_segments(std::span<const Index> nodes, std::span<const Index> segment,
                           const Surface& master, const Vec3Field& x,
                           std::span<SegmentProjection> out, const TrackingOptions& opt = {},
                           const SlaveOrientation* orientation = nullptr) {
  parallel_for(static_cast<Index>(nodes.size()), [&](Index i) {
    const std::size_t k = static_cast<std::size_t>(i);
    if (segment[k] < 0) {
      out[k].segment = -1;
      out[k].hops = 0;
      return;
    }
    out[k] = orientation ? track_segment(x.get(nodes[k]), segment[k], master, x, opt,
                                         FacingRule{orientation, k, &master, &x})
                         : track_segment(x.get(nodes[k]), segment[k], master, x, opt);
  });
}

}  // namespace slideline
