#pragma once
/// Tie offsets carried in the master segment's frame (docs/contact.md, "Tie offsets under
/// rotation"): a slave tied off its master surface (a gap, a shell offset, a node slightly inside)
/// keeps its tie-time offset d_s as components in segment_frame (e1, e2, n) of its master segment,
/// and the offset at any later configuration x is segment_frame(x) times them: it turns with the
/// segment, so a rigid rotation of the tied pair rotates the offset too. Every tie of the library
/// (penalty tiebreaks, kinematic ties, the automatic tiebreak's sticking ties) uses these two
/// functions, so that they share one frame definition.
///
/// An offset of round-off size (below kCarriedTieOffset of the segment's longer diagonal: the slave
/// on the surface) has no direction to carry: it is not carried, and the tie keeps it in global
/// components (so a tie with a zero offset computes exactly what it did before offsets turned).
#include "slideline/contact/search/tie_search.hpp"
#include "slideline/core/types.hpp"
#include "slideline/mesh/segment_geometry.hpp"
#include "slideline/mesh/surface.hpp"

namespace slideline {

/// Offsets longer than this fraction of the master segment's diagonal are carried in its frame.
inline constexpr Real kCarriedTieOffset = 1e-9;

/// Whether tie t's offset (t.offset, length) is carried in the frame of its master segment
/// (t.segment of `master`) at coordinates x; if so, its components there go to `local`
/// (e1, e2, n; length). False (local untouched) for a round-off offset or a degenerate segment.
inline bool carry_tie_offset(const Surface& master, const TiePoint& t, const Vec3Field& x, Vec3& local) {
  const Eigen::Matrix3d frame = segment_frame(master, t.segment, x);
  if (!(t.offset.norm() > kCarriedTieOffset * segment_max_diagonal(master, t.segment, x)) || frame.isZero(0.0))
    return false;
  local = frame.transpose() * t.offset;
  return true;
}

/// A carried offset's global components at coordinates x (length): segment_frame(x) * local.
inline Vec3 carried_tie_offset(const Surface& master, Index segment, const Vec3Field& x, const Vec3& local) {
  return segment_frame(master, segment, x) * local;
}

}  // namespace slideline
