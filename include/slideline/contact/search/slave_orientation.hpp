#pragma once
/// Which master segments a slave node may pair with, and which of them it takes: the contact
/// choice every node-on-segment interface shares (penalty Types 3, 5, 10, 12 and their Lagrange
/// forms). See docs/contact.md, "Choosing a segment".
///
/// Rule:
/// 1. Orientation (SlaveOrientation::admits). A slave node on solid faces only (its own body's
///    surface: the interface's slave surface, or for a node set the exterior faces of the parts
///    its nodes belong to) pairs only with a master segment that faces it: one whose normal
///    opposes the normal of at least one of the node's own faces by more than 60 degrees
///    (n_own . n_m <= -0.5; |n_own . n_m| >= 0.5 for a shell master, which has two sides).
///    A node on a block's edge has the faces of both sides, so it meets a face across either of
///    them, but never the side face of a flush master, which its faces do not oppose. A node with
///    a shell segment (a shell has two sides and its edge may hit anything) or with no face (a
///    discrete node) is not filtered.
/// 2. Choice (is_better_contact): among admitted candidates, one the node is over (its offset
///    from the segment's normal through the closest point is within 1e-3 of the segment size)
///    beats one it is beside; then the nearer (is_better_projection: ties within 1e-9 of the
///    segment size); then the lower segment index.
/// Why: a node on the edge of a flush contact face is at distance 0 from the master body's side
/// face and at the penetration depth from its end face, so "nearest" alone gives it the side face
/// (zero gap, no force); and a master node just ahead of a sliding block's edge is nearest to the
/// block's leading face, which then pushes the block back (a snag at every row of nodes).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "slideline/contact/search/closest_point.hpp"
#include "slideline/element/element_block.hpp"
#include "slideline/mesh/segment_geometry.hpp"
#include "slideline/mesh/segment_stiffness.hpp"
#include "slideline/mesh/surface.hpp"

namespace slideline {

/// The orientation data of a slave node list: per slave, the corner nodes of its own solid faces
/// (none for a node the rule does not filter). Built once (allocates); queries allocate nothing.
class SlaveOrientation {
 public:
  /// No orientation: every segment is admitted.
  SlaveOrientation() = default;

  /// own: the surface the slaves lie on (adjacency built; a node not on it is not filtered);
  /// slaves: internal node indices in the order the interface numbers its slaves.
  SlaveOrientation(const Surface& own, std::span<const Index> slaves) {
    offset_.assign(slaves.size() + 1, 0);
    for (std::size_t i = 0; i < slaves.size(); ++i) {
      offset_[i + 1] = offset_[i];
      const auto it = std::lower_bound(own.nodes.begin(), own.nodes.end(), slaves[i]);
      if (it == own.nodes.end() || *it != slaves[i]) continue;  // own.nodes is sorted
      const Index row = static_cast<Index>(it - own.nodes.begin());
      bool shell = false;
      for (Index j = own.node_segments.begin(row); j < own.node_segments.end(row); ++j)
        shell = shell || own.kind[static_cast<std::size_t>(own.node_segments.value[static_cast<std::size_t>(j)])] ==
                             SegmentKind::shell;
      if (shell) continue;
      for (Index j = own.node_segments.begin(row); j < own.node_segments.end(row); ++j) {
        const Index s = own.node_segments.value[static_cast<std::size_t>(j)];
        const Index* c = &own.conn[4 * static_cast<std::size_t>(s)];
        conn_.insert(conn_.end(), c, c + 4);
        face_segment_.push_back(s);
        ++offset_[i + 1];
      }
    }
  }

  /// Under erosion (search/contact_erosion.hpp): per segment of the `own` surface, 1 while it is
  /// active; an inactive own face orients nothing. A view of the owner's flags; never called: every
  /// own face counts.
  void set_own_activity(std::span<const std::uint8_t> active) { own_active_ = active; }

  /// True when slave i is filtered (a node on solid faces only).
  bool filtered(std::size_t i) const { return !offset_.empty() && offset_[i + 1] > offset_[i]; }

  /// True when slave i may pair with segment s of `master` at coordinates x (rule 1 above).
  bool admits(std::size_t i, const Surface& master, Index s, const Vec3Field& x) const {
    if (!filtered(i)) return true;
    const Vec3 nm = segment_normal(master, s, x);
    const bool two_sided = master.kind[static_cast<std::size_t>(s)] == SegmentKind::shell;
    for (Index f = offset_[i]; f < offset_[i + 1]; ++f) {
      if (!own_active_.empty() && own_active_[static_cast<std::size_t>(face_segment_[static_cast<std::size_t>(f)])] == 0)
        continue;
      const Index* c = &conn_[4 * static_cast<std::size_t>(f)];
      const Vec3 a = (x.get(c[2]) - x.get(c[0])).cross(x.get(c[3]) - x.get(c[1]));
      const Real len = a.norm();
      if (!(len > 0.0)) continue;
      const Real d = a.dot(nm) / len;
      if (two_sided ? std::abs(d) >= 0.5 : d <= -0.5) return true;
    }
    return false;
  }

 private:
  std::vector<Index> offset_;  ///< slaves + 1 entries (empty: nothing filtered)
  std::vector<Index> conn_;    ///< 4 nodes per own face
  std::vector<Index> face_segment_;  ///< per own face: its segment in the `own` surface
  std::span<const std::uint8_t> own_active_;  ///< set_own_activity() (empty: all count)
};

/// The deepest a slave may be behind segment s of `master` (at coordinates x) and still belong to
/// it (length): half its longer diagonal and, for a solid face, half the thickness of its element
/// (volume / face area). Deeper, the node is nearer the element's far side: e.g. a node on the
/// bottom of a one-element slab against the slab's own top face in single-surface contact.
/// Needs blocks[master.block[s]] to hold the face's element; without it, half the diagonal.
inline Real contact_depth_limit(const Surface& master, Index s, const std::vector<std::unique_ptr<ElementBlock>>& blocks,
                                const Vec3Field& x) {
  Real limit = 0.5 * segment_max_diagonal(master, s, x);
  const std::size_t su = static_cast<std::size_t>(s);
  if (master.kind[su] == SegmentKind::shell || master.block.size() <= su ||
      static_cast<std::size_t>(master.block[su]) >= blocks.size())
    return limit;  // a shell, or a surface given without its elements (tests)
  const SegmentStiffnessData d = segment_stiffness_data(master, s, blocks, x);
  if (d.face_area > 0.0 && d.element_volume > 0.0) limit = std::min(limit, 0.5 * d.element_volume / d.face_area);
  return limit;
}

/// LS-DYNA's segment thickness of PENCHK = 1 (length): the shell's thickness for a shell segment,
/// 1/20 of the shorter diagonal for a solid face (the shortest side of a triangular face). Without
/// the segment's element in `blocks` (a surface given alone, tests), the solid rule.
inline Real penetration_check_thickness(const Surface& master, Index s,
                                        const std::vector<std::unique_ptr<ElementBlock>>& blocks, const Vec3Field& x) {
  const std::size_t su = static_cast<std::size_t>(s);
  const bool own_block = master.block.size() > su && static_cast<std::size_t>(master.block[su]) < blocks.size();
  if (master.kind[su] == SegmentKind::shell && own_block) return segment_stiffness_data(master, s, blocks, x).thickness;
  const Index* c = master.conn.data() + 4 * su;
  const Real d02 = (x.get(c[2]) - x.get(c[0])).norm();
  if (master.is_triangle(s))
    return (1.0 / 20.0) * std::min({d02, (x.get(c[1]) - x.get(c[0])).norm(), (x.get(c[2]) - x.get(c[1])).norm()});
  return (1.0 / 20.0) * std::min(d02, (x.get(c[3]) - x.get(c[1])).norm());
}

/// The offset of p from the normal line through the closest point of `pr` (length).
inline Real lateral_offset(const Vec3& p, const Projection& pr) {
  return (p - pr.point - pr.gap * pr.normal).norm();
}

/// True when p is over the segment of `pr` (rule 2 above): lateral offset within 1e-3 of its size.
inline bool is_over(const Vec3& p, const Projection& pr) { return lateral_offset(p, pr) <= 1e-3 * pr.size; }

/// Rule 2 above for two projections of one point p: over beats beside, then is_better_projection.
inline bool is_better_contact(const Vec3& p, const Projection& a, Index sa, const Projection& b, Index sb,
                              const ProjectionOptions& opt = {}) {
  const bool over_a = is_over(p, a), over_b = is_over(p, b);
  if (over_a != over_b) return over_a;
  return is_better_projection(a, sa, b, sb, opt);
}

/// The choice rule of one slave node for search and tracking (track_segment, nearest_segment):
/// admitted segments only (rule 1), compared by is_better_contact (rule 2).
struct FacingRule {
  const SlaveOrientation* orientation = nullptr;
  std::size_t slave = 0;
  const Surface* master = nullptr;
  const Vec3Field* x = nullptr;
  bool admits(Index s) const { return !orientation || orientation->admits(slave, *master, s, *x); }
  bool better(const Vec3& p, const Projection& a, Index sa, const Projection& b, Index sb,
              const ProjectionOptions& opt) const {
    return is_better_contact(p, a, sa, b, sb, opt);
  }
};

/// The nearest-segment rule (no orientation, nearer wins): tied contact and the default of the
/// search functions.
struct NearestRule {
  bool admits(Index) const { return true; }
  bool better(const Vec3&, const Projection& a, Index sa, const Projection& b, Index sb,
              const ProjectionOptions& opt) const {
    return is_better_projection(a, sa, b, sb, opt);
  }
};

}  // namespace slideline
