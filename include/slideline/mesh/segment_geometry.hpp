#pragma once
/// Geometry of one surface segment at given nodal coordinates (reference x0 or current x): the
/// quantities contact search and enforcement need per segment, in one place so that every
/// algorithm uses the same definitions.
///
/// A quadrilateral segment is in general warped; its normal and area here are those of the
/// bilinear patch's mean plane: a = (x2 - x0) x (x3 - x1) / 2 is exact for a planar quad and, for
/// a warped one, the area vector of the patch (the integral of its normal over the patch). A
/// triangle (x3 == x2) gives the triangle's own area vector from the same formula.
#include <algorithm>

#include "slideline/core/types.hpp"
#include "slideline/mesh/nodal_fields.hpp"
#include "slideline/mesh/surface.hpp"

namespace slideline {

/// The 4 corner coordinates of segment s (row k = node conn[4 s + k]), length.
inline Eigen::Matrix<Real, 4, 3> segment_coordinates(const Surface& surf, Index s, const Vec3Field& x) {
  return gather_rows<4>(x, surf.conn.data() + 4 * static_cast<std::size_t>(s));
}

/// Area vector (x2 - x0) x (x3 - x1) / 2 of segment s: its direction is the segment normal (outward
/// for a hexahedron face), its length the area (length^2).
inline Vec3 segment_area_vector(const Surface& surf, Index s, const Vec3Field& x) {
  const Index* c = surf.conn.data() + 4 * static_cast<std::size_t>(s);
  const Vec3 d1 = x.get(c[2]) - x.get(c[0]);
  const Vec3 d2 = x.get(c[3]) - x.get(c[1]);
  return 0.5 * d1.cross(d2);
}

/// Unit normal of segment s (zero for a degenerate segment of zero area).
inline Vec3 segment_normal(const Surface& surf, Index s, const Vec3Field& x) {
  const Vec3 a = segment_area_vector(surf, s, x);
  const Real n = a.norm();
  return n > 0.0 ? Vec3(a / n) : Vec3::Zero();
}

/// An orthonormal frame of segment s that turns with it: columns e1 (the diagonal x2 - x0's part
/// in the segment's plane, normalised), e2 = n x e1 and n (segment_normal). A rigid rotation Q of
/// the segment's nodes turns the frame into Q times it, exactly up to round-off. Zero for a
/// degenerate segment.
inline Eigen::Matrix3d segment_frame(const Surface& surf, Index s, const Vec3Field& x) {
  const Index* c = surf.conn.data() + 4 * static_cast<std::size_t>(s);
  const Vec3 n = segment_normal(surf, s, x);
  const Vec3 d = x.get(c[2]) - x.get(c[0]);
  const Vec3 t = d - d.dot(n) * n;
  const Real len = t.norm();
  Eigen::Matrix3d f = Eigen::Matrix3d::Zero();
  if (!(len > 0.0) || n.isZero(0.0)) return f;
  f.col(0) = t / len;
  f.col(1) = n.cross(f.col(0));
  f.col(2) = n;
  return f;
}

/// Area of segment s (length^2).
inline Real segment_area(const Surface& surf, Index s, const Vec3Field& x) {
  return segment_area_vector(surf, s, x).norm();
}

/// Centroid of the corners of segment s (a triangle's three distinct nodes), length.
inline Vec3 segment_centroid(const Surface& surf, Index s, const Vec3Field& x) {
  const Index* c = surf.conn.data() + 4 * static_cast<std::size_t>(s);
  if (surf.is_triangle(s)) return (x.get(c[0]) + x.get(c[1]) + x.get(c[2])) / 3.0;
  return 0.25 * (x.get(c[0]) + x.get(c[1]) + x.get(c[2]) + x.get(c[3]));
}

/// The longer diagonal of a quadrilateral segment, the longest side of a triangle (length): the
/// length LS-DYNA divides by in a shell's penalty stiffness.
inline Real segment_max_diagonal(const Surface& surf, Index s, const Vec3Field& x) {
  const Index* c = surf.conn.data() + 4 * static_cast<std::size_t>(s);
  const Real d02 = (x.get(c[2]) - x.get(c[0])).norm();
  const Real d13 = (x.get(c[3]) - x.get(c[1])).norm();
  if (!surf.is_triangle(s)) return std::max(d02, d13);
  return std::max({d02, d13, (x.get(c[1]) - x.get(c[0])).norm()});
}

/// Unit normals of every segment into `normals` (resized to segment_count()), at the coordinates
/// `x` (pass nodes.x for the current configuration). Allocates only when the size changes, so a
/// contact algorithm can call it every step on a member field.
inline void compute_segment_normals(const Surface& surf, const Vec3Field& x, Vec3Field& normals) {
  const Index ns = surf.segment_count();
  if (normals.size() != static_cast<std::size_t>(ns)) normals.resize(ns);
  for (Index s = 0; s < ns; ++s) normals.set(s, segment_normal(surf, s, x));
}

}  // namespace slideline
