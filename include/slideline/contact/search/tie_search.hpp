#pragma once
/// The one-time search of tied interfaces (Types 2, 6, 7, 8, 9): each slave node is projected onto
/// its nearest master segment at initialisation and keeps that point for good (tied interfaces
/// never search again). Master segments are binned into a uniform grid of cells one largest
/// segment diagonal wide, so the search costs O(slaves + segments), allocated once.
///
/// A slave is tied only when its closest point lies on the segment (within `parametric_tol` of
/// the segment size along the surface) and within `normal_tol` x the segment size of it along the
/// normal; other slaves are reported as untied, never silently attached to a far segment.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "slideline/contact/search/closest_point.hpp"
#include "slideline/core/diagnostics.hpp"
#include "slideline/core/types.hpp"
#include "slideline/mesh/nodal_fields.hpp"
#include "slideline/mesh/surface.hpp"

namespace slideline {

/// One slave node's master point.
struct TiePoint {
  Index slave = -1;
  Index segment = -1;               ///< -1: no master segment within the tolerances (untied)
  std::array<Index, 4> master{};    ///< the segment's 4 node indices (corner 3 repeats 2 on a triangle)
  std::array<Real, 4> shape{};      ///< shape functions of the master point (sum 1)
  Vec3 offset = Vec3::Zero();       ///< x_slave - x_point at tie time (length)
  Vec3 normal = Vec3::Zero();       ///< master unit normal at tie time
  Real gap = 0.0;                   ///< signed normal gap at tie time (length)
  Real size = 0.0;                  ///< master segment diagonal (length)
};

struct TieSearchOptions {
  Real parametric_tol = 1e-3;  ///< tangential distance off the segment / segment size
  Real normal_tol = 0.3;       ///< |normal gap| / segment size
  /// Shell thickness offsets (length; shell_offset.hpp), empty for none: per master segment, and
  /// per node index of x. A slave is then tied within normal_tol x size of the two contact
  /// surfaces, i.e. |gap| <= normal_tol x size + master_offset[s] + node_offset[slave] (*CONTACT_
  /// AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK OPTION 8: shells tied at their offsets).
  std::span<const Real> master_offset = {};
  std::span<const Real> node_offset = {};
};

/// Entry i of a per-index offset table (0 when the table is empty).
inline Real offset_of(std::span<const Real> table, Index i) {
  return table.empty() ? 0.0 : table[static_cast<std::size_t>(i)];
}

/// Projects each node of `slaves` (indices into x) onto `master` at coordinates `x`. Returns one
/// TiePoint per slave, in the order of `slaves`; untied ones have segment = -1.
inline std::vector<TiePoint> find_tie_points(std::span<const Index> slaves, const Surface& master,
                                             const Vec3Field& x, const TieSearchOptions& opt = {}) {
  std::vector<TiePoint> out(slaves.size());
  const Index ns = master.segment_count();
  Real cell = 0.0;
  for (Index s = 0; s < ns; ++s) cell = std::max(cell, detail::segment_size(segment_corners(master, s, x)));
  // The reach of a slave beyond a segment's box: the normal tolerance of the largest segment.
  Real reach = std::max(opt.normal_tol, opt.parametric_tol) * cell;
  const bool offsets = !opt.master_offset.empty() || !opt.node_offset.empty();
  if (offsets) {
    Real largest = 0.0;
    for (Real o : opt.master_offset) largest = std::max(largest, o);
    Real node_largest = 0.0;
    for (Index s : slaves) node_largest = std::max(node_largest, offset_of(opt.node_offset, s));
    reach += largest + node_largest;
  }
  cell = cell > 0.0 ? cell : 1.0;
  auto key = [](std::int64_t i, std::int64_t j, std::int64_t k) {
    return (i * 73856093) ^ (j * 19349663) ^ (k * 83492791);
  };
  std::unordered_map<std::int64_t, std::vector<Index>> grid;
  auto cell_of = [&](Real v) { return static_cast<std::int64_t>(std::floor(v / cell)); };
  for (Index s = 0; s < ns; ++s) {
    const SegmentCorners c = segment_corners(master, s, x);
    Vec3 lo = c[0], hi = c[0];
    for (const Vec3& p : c) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    lo.array() -= reach;
    hi.array() += reach;
    for (auto i = cell_of(lo[0]); i <= cell_of(hi[0]); ++i)
      for (auto j = cell_of(lo[1]); j <= cell_of(hi[1]); ++j)
        for (auto k = cell_of(lo[2]); k <= cell_of(hi[2]); ++k) grid[key(i, j, k)].push_back(s);
  }
  for (std::size_t n = 0; n < slaves.size(); ++n) {
    TiePoint& t = out[n];
    t.slave = slaves[n];
    const Vec3 p = x.get(t.slave);
    const auto it = grid.find(key(cell_of(p[0]), cell_of(p[1]), cell_of(p[2])));
    if (it == grid.end()) continue;
    // Hash collisions only add candidates; ascending order keeps is_better_projection's tie rule.
    Projection best;
    Index best_s = -1;
    for (Index s : it->second) {
      const Projection pr = project_point_to_segment(p, master, s, x);
      if (best_s < 0 || is_better_projection(pr, s, best, best_s)) best = pr, best_s = s;
    }
    if (best_s < 0) continue;
    const Real tangential = std::sqrt(std::max(0.0, best.distance * best.distance - best.gap * best.gap));
    Real normal_reach = opt.normal_tol * best.size;
    if (offsets) normal_reach += offset_of(opt.master_offset, best_s) + offset_of(opt.node_offset, t.slave);
    if (tangential > opt.parametric_tol * best.size || std::abs(best.gap) > normal_reach) continue;
    t.segment = best_s;
    for (int a = 0; a < 4; ++a) t.master[a] = master.conn[4 * static_cast<std::size_t>(best_s) + a];
    t.shape = best.shape;
    t.offset = p - best.point;
    t.normal = best.normal;
    t.gap = best.gap;
    t.size = best.size;
  }
  return out;
}

/// The ties of an interface at initialisation (Types 2, 6, 7, 8, 9 alike): find_tie_points for
/// each of `candidates` that is not itself a node of `master` (a shared node is not tied to
/// itself); the tied ones go to `links`, the others to `untied` (both cleared first) and, when
/// there are any, to a warning (`diagnostics`) naming the interface and the first ten node ids: an
/// untied slave is free, which the user must hear about.
inline void tie_candidates(const std::string& name, std::span<const Index> candidates, const Surface& master,
                           const NodalFields& nodes, const TieSearchOptions& opt, std::vector<TiePoint>& links,
                           std::vector<Index>& untied, DiagnosticSink* diagnostics) {
  std::vector<std::uint8_t> is_master(nodes.size(), 0);
  for (Index m : master.conn) is_master[m] = 1;
  std::vector<Index> slaves;
  for (Index s : candidates)
    if (!is_master[s]) slaves.push_back(s);
  links.clear();
  untied.clear();
  for (const TiePoint& t : find_tie_points(slaves, master, nodes.x, opt)) {
    if (t.segment >= 0) links.push_back(t);
    else untied.push_back(t.slave);
  }
  if (untied.empty()) return;
  std::string ids;
  for (std::size_t k = 0; k < untied.size() && k < 10; ++k) ids += (k ? ", " : "") + std::to_string(nodes.ids[untied[k]]);
  warn(diagnostics, "contact %s: %zu slave node(s) project outside every master segment and are left free "
       "(first ids: %s)", name.c_str(), untied.size(), ids.c_str());
}

/// x at the master point of t: sum_a N_a f(master_a).
inline Vec3 tie_point_value(const TiePoint& t, const Vec3Field& f) {
  return t.shape[0] * f.get(t.master[0]) + t.shape[1] * f.get(t.master[1]) + t.shape[2] * f.get(t.master[2]) +
         t.shape[3] * f.get(t.master[3]);
}

}  // namespace slideline
