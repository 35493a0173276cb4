#pragma once
/// Closest-point projection of a point onto one contact segment (a bilinear quadrilateral, or a
/// triangle stored as a quadrilateral whose corner 3 repeats corner 2, see mesh/surface.hpp).
///
/// Rules (every caller may rely on them):
/// - Quadrilateral: x(xi, eta) = sum_a N_a(xi, eta) x_a with the bilinear shape functions
///   N_0 = (1-xi)(1-eta)/4, N_1 = (1+xi)(1-eta)/4, N_2 = (1+xi)(1+eta)/4, N_3 = (1-xi)(1+eta)/4,
///   (xi, eta) in [-1, 1]^2. Newton's method (full Hessian, Gauss-Newton when that is not positive
///   definite) from the centre finds the stationary point. If it converges to a point with
///   |xi|, |eta| <= 1 + tol (inclusive) that point is the answer, clamped into the square. Otherwise
///   the minimum lies on the boundary: the four edges of a bilinear quad are straight, so each edge
///   is solved in closed form (projection onto a line segment, clamped to its end points, which
///   covers the corners) and the nearest edge point wins (the lowest edge number on exact ties).
///   On a strongly warped quad (twist |x0 - x1 + x2 - x3| . n above 8 % of its diagonal) the
///   edges are checked even after an interior Newton solution, which may be a local minimum, and
///   Newton is restarted from the best point found; on extreme warps (corners a diagonal's length
///   off-plane) a worse local minimum can still win.
/// - Triangle: exact projection onto the plane with barycentric coordinates (l0, l1, l2); a point
///   with every l >= -tol is inside, otherwise the nearest of the three edges. Reported in the
///   collapsed-quad parametrisation: eta = 2 l2 - 1, xi = (l1 - l0) / (l0 + l1), and the shape
///   functions are {l0, l1, l2, 0} so that the repeated node never receives a share twice.
/// - The normal is n = dx/dxi x dx/deta at the contact point, normalised (for a triangle the
///   constant plane normal). Counter-clockwise corners give the outward normal, consistent with
///   surface.hpp's (x2 - x0) x (x3 - x1). Where dx/dxi x dx/deta vanishes (a degenerate corner)
///   the segment normal (x2 - x0) x (x3 - x1) is used instead.
/// - gap = (p - point) . n: positive on the side the normal points to, negative behind the segment.
/// - Ties between segments (a point equidistant from two segments, e.g. exactly above a shared
///   edge) are resolved by `is_better_projection`: distances equal within tie_tolerance x the
///   larger segment size count as equal, and the lower segment index wins.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "slideline/core/types.hpp"
#include "slideline/mesh/nodal_fields.hpp"
#include "slideline/mesh/surface.hpp"

namespace slideline {

/// The 4 corner coordinates of a segment (length units); corner 3 == corner 2 for a triangle.
using SegmentCorners = std::array<Vec3, 4>;

/// Local edge k joins local corners k and (k + 1) % 4:
/// edge 0: eta = -1 (0-1), edge 1: xi = +1 (1-2), edge 2: eta = +1 (2-3), edge 3: xi = -1 (3-0).
/// A triangle's edges are 0 (0-1), 1 (1-2) and 3 (2-0); its edge 2 is the collapsed one.
inline constexpr int kSegmentEdges = 4;

struct ProjectionOptions {
  /// Parametric tolerance (dimensionless): |xi| <= 1 + tol counts as on the segment, and a point
  /// within tol of an edge (in xi or eta, or in a barycentric coordinate) is flagged on that edge.
  Real tol = 1e-9;
  /// Newton iterations on the quadrilateral before falling back to the edges.
  int max_iterations = 20;
  /// Relative tolerance for ties between segments, times the larger segment size (diagonal).
  Real tie_tolerance = 1e-9;
};

/// The result of projecting one point onto one segment.
struct Projection {
  Real xi = 0.0;   ///< parametric coordinates of the closest point, in [-1, 1]
  Real eta = 0.0;
  Vec3 point = Vec3::Zero();     ///< closest point on the segment (length)
  Real distance = 0.0;           ///< |p - point| (length)
  std::array<Real, 4> shape{};   ///< shape functions at the closest point (sum 1), per local corner
  Vec3 normal = Vec3::Zero();    ///< unit normal of the segment at the closest point
  Real gap = 0.0;                ///< signed normal gap (p - point) . normal (length)
  Real size = 0.0;               ///< the segment's longer diagonal (length), scales tolerances
  std::uint8_t edges = 0;        ///< bit k set: the closest point lies on local edge k (within tol)

  /// True when the closest point lies strictly inside the segment (on no edge).
  bool interior() const { return edges == 0; }
  bool on_edge(int k) const { return (edges >> k) & 1u; }
};

namespace detail {

inline std::array<Real, 4> bilinear_shape(Real xi, Real eta) {
  return {0.25 * (1 - xi) * (1 - eta), 0.25 * (1 + xi) * (1 - eta), 0.25 * (1 + xi) * (1 + eta),
          0.25 * (1 - xi) * (1 + eta)};
}

inline Vec3 combine(const SegmentCorners& c, const std::array<Real, 4>& n) {
  return n[0] * c[0] + n[1] * c[1] + n[2] * c[2] + n[3] * c[3];
}

inline Vec3 segment_normal_direction(const SegmentCorners& c) {
  return (c[2] - c[0]).cross(c[3] - c[1]);
}

inline Real segment_size(const SegmentCorners& c) {
  return std::max((c[2] - c[0]).norm(), (c[3] - c[1]).norm());
}

/// Closest point parameter t in [0, 1] on the line segment a + t (b - a).
inline Real segment_parameter(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 e = b - a;
  const Real ee = e.squaredNorm();
  if (!(ee > 0.0)) return 0.0;
  return std::clamp((p - a).dot(e) / ee, Real(0), Real(1));
}

inline std::uint8_t quad_edge_flags(Real xi, Real eta, Real tol) {
  std::uint8_t f = 0;
  if (eta <= -1 + tol) f |= 1u;
  if (xi >= 1 - tol) f |= 2u;
  if (eta >= 1 - tol) f |= 4u;
  if (xi <= -1 + tol) f |= 8u;
  return f;
}

inline void finish(Projection& r, const Vec3& p, Vec3 n, const SegmentCorners& c) {
  r.distance = (p - r.point).norm();
  const Real nn = n.norm();
  if (!(nn > 1e-14 * r.size * r.size)) {
    n = segment_normal_direction(c);
  }
  const Real len = n.norm();
  r.normal = len > 0.0 ? Vec3(n / len) : Vec3::Zero();
  r.gap = (p - r.point).dot(r.normal);
}

enum class NewtonStep { moved, converged, singular };

/// One Newton step on grad(1/2 |x(xi, eta) - p|^2) = 0 from (xi, eta), the new iterate clamped to
/// [-2, 2]^2 so that a far point cannot run away. A function of (xi, eta) alone (p, c and
/// x_xe = d2x / dxi deta fixed). singular: (xi, eta) left as they were.
inline NewtonStep quad_newton_step(const Vec3& p, const SegmentCorners& c, const Vec3& x_xe, Real& xi, Real& eta) {
  const Vec3 x_xi = 0.25 * ((1 - eta) * (c[1] - c[0]) + (1 + eta) * (c[2] - c[3]));
  const Vec3 x_eta = 0.25 * ((1 - xi) * (c[3] - c[0]) + (1 + xi) * (c[2] - c[1]));
  const Vec3 res = combine(c, bilinear_shape(xi, eta)) - p;
  const Real g0 = x_xi.dot(res), g1 = x_eta.dot(res);
  const Real a = x_xi.squaredNorm(), d = x_eta.squaredNorm();
  Real b = x_xi.dot(x_eta) + res.dot(x_xe);
  Real det = a * d - b * b;
  if (!(det > 1e-12 * a * d)) {  // not positive definite: Gauss-Newton
    b = x_xi.dot(x_eta);
    det = a * d - b * b;
  }
  if (!(det > 0.0)) return NewtonStep::singular;  // degenerate segment: the edges decide
  const Real dxi = -(d * g0 - b * g1) / det;
  const Real deta = -(a * g1 - b * g0) / det;
  xi = std::clamp(xi + dxi, Real(-2), Real(2));
  eta = std::clamp(eta + deta, Real(-2), Real(2));
  // Quadratic convergence: after a step below 1e-10 the error is at round-off level.
  return std::max(std::abs(dxi), std::abs(deta)) < 1e-10 ? NewtonStep::converged : NewtonStep::moved;
}

/// True when a and b are the same double to the bit (so that -0.0 and +0.0 differ).
inline bool same_bits(Real a, Real b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

/// Up to max_iterations Newton steps (quad_newton_step) from (xi, eta). Returns true when
/// converged; (xi, eta) hold the last iterate.
///
/// A point whose stationary point lies beyond the clamp never converges: the clamped iterate
/// lands on the same (xi, eta) again and again (or alternates between two), up to
/// max_iterations. A step is a function of (xi, eta) alone, so an iterate equal to the one before
/// it (a fixed point) or to the one two before (a 2-cycle), bit for bit, repeats for good: the
/// loop stops there and returns what the remaining steps would have left, the same bits (false,
/// and the fixed point, or the member of the 2-cycle the count's parity lands on). On a contact
/// surface these are ~40 % of the projections and three quarters of the Newton steps.
inline bool quad_newton(const Vec3& p, const SegmentCorners& c, const Vec3& x_xe, int max_iterations,
                        Real& xi, Real& eta) {
  Real xi1 = std::numeric_limits<Real>::quiet_NaN(), eta1 = xi1;  // the iterate before (xi, eta)
  Real xi2 = xi1, eta2 = xi1;                                      // the one before that
  for (int it = 0; it < max_iterations; ++it) {
    if (it >= 1 && same_bits(xi, xi1) && same_bits(eta, eta1)) return false;
    if (it >= 2 && same_bits(xi, xi2) && same_bits(eta, eta2)) {
      // Iterates it-1 and it alternate: the last one, max_iterations, is iterate it when
      // max_iterations - it is even, else iterate it-1.
      if ((max_iterations - it) % 2 != 0) xi = xi1, eta = eta1;
      return false;
    }
    xi2 = xi1, eta2 = eta1;
    xi1 = xi, eta1 = eta;
    const NewtonStep step = quad_newton_step(p, c, x_xe, xi, eta);
    if (step == NewtonStep::singular) return false;
    if (step == NewtonStep::converged) return true;
  }
  return false;
}

}  // namespace detail

/// Projects point p (length) onto the bilinear quadrilateral with corners c (counter-clockwise).
/// Returns the closest point on the closed quadrilateral; see the file comment for the rules.
inline Projection project_point_to_quad(const Vec3& p, const SegmentCorners& c,
                                        const ProjectionOptions& opt = {}) {
  Projection r;
  r.size = detail::segment_size(c);
  const Vec3 x_xe = 0.25 * (c[0] - c[1] + c[2] - c[3]);  // d2x / dxi deta (constant)

  Real xi = 0.0, eta = 0.0;
  const bool converged = detail::quad_newton(p, c, x_xe, opt.max_iterations, xi, eta);
  const Real lim = 1 + opt.tol;
  const bool newton_inside = std::abs(xi) <= lim && std::abs(eta) <= lim;
  Real best_d2 = std::numeric_limits<Real>::infinity();
  if (newton_inside) {
    xi = std::clamp(xi, Real(-1), Real(1));
    eta = std::clamp(eta, Real(-1), Real(1));
    r.xi = xi;
    r.eta = eta;
    r.shape = detail::bilinear_shape(xi, eta);
    r.point = detail::combine(c, r.shape);
    best_d2 = (p - r.point).squaredNorm();
  }
  // A strongly warped quad can hold an interior local minimum that is not the global one: check
  // the edges too when the twist |x0 - x1 + x2 - x3| . n exceeds 8 % of the diagonal.
  const Vec3 seg_n = detail::segment_normal_direction(c);
  const Real seg_nn = seg_n.norm();
  const bool warped = seg_nn > 0.0 && std::abs(x_xe.dot(seg_n)) > 0.02 * r.size * seg_nn;
  if (!(newton_inside && converged) || warped) {
    // The minimum lies on the boundary (or Newton failed): each straight edge in closed form.
    for (int k = 0; k < kSegmentEdges; ++k) {
      const Real t = detail::segment_parameter(p, c[k], c[(k + 1) % 4]);
      const Real s = -1 + 2 * t;
      const Real e_xi = k == 0 ? s : (k == 1 ? 1.0 : (k == 2 ? -s : -1.0));
      const Real e_eta = k == 0 ? -1.0 : (k == 1 ? s : (k == 2 ? 1.0 : -s));
      const auto shape = detail::bilinear_shape(e_xi, e_eta);
      const Vec3 q = detail::combine(c, shape);
      const Real d2 = (p - q).squaredNorm();
      if (d2 < best_d2) {
        best_d2 = d2;
        r.xi = e_xi;
        r.eta = e_eta;
        r.shape = shape;
        r.point = q;
      }
    }
    if (warped) {
      // Newton again from the best point so far, pulled slightly inside: on a warped quad an
      // interior minimum may sit next to the edge that Newton from the centre did not reach.
      Real xi2 = 0.9 * r.xi, eta2 = 0.9 * r.eta;
      if (detail::quad_newton(p, c, x_xe, opt.max_iterations, xi2, eta2) && std::abs(xi2) <= lim &&
          std::abs(eta2) <= lim) {
        xi2 = std::clamp(xi2, Real(-1), Real(1));
        eta2 = std::clamp(eta2, Real(-1), Real(1));
        const auto shape = detail::bilinear_shape(xi2, eta2);
        const Vec3 q = detail::combine(c, shape);
        if ((p - q).squaredNorm() < best_d2) {
          r.xi = xi2;
          r.eta = eta2;
          r.shape = shape;
          r.point = q;
        }
      }
    }
  }
  r.edges = detail::quad_edge_flags(r.xi, r.eta, opt.tol);
  const Vec3 x_xi = 0.25 * ((1 - r.eta) * (c[1] - c[0]) + (1 + r.eta) * (c[2] - c[3]));
  const Vec3 x_eta = 0.25 * ((1 - r.xi) * (c[3] - c[0]) + (1 + r.xi) * (c[2] - c[1]));
  detail::finish(r, p, x_xi.cross(x_eta), c);
  return r;
}

/// Projects point p (length) onto the triangle c[0], c[1], c[2] (c[3] is ignored; it repeats c[2]
/// in the surface layout). Reported in the collapsed-quad parametrisation (file comment).
inline Projection project_point_to_triangle(const Vec3& p, const SegmentCorners& c,
                                            const ProjectionOptions& opt = {}) {
  Projection r;
  r.size = std::max({(c[1] - c[0]).norm(), (c[2] - c[1]).norm(), (c[0] - c[2]).norm()});
  const Vec3 e0 = c[1] - c[0], e1 = c[2] - c[0], w = p - c[0];
  const Real d00 = e0.dot(e0), d01 = e0.dot(e1), d11 = e1.dot(e1);
  const Real d20 = w.dot(e0), d21 = w.dot(e1);
  const Real den = d00 * d11 - d01 * d01;
  std::array<Real, 3> l{1.0, 0.0, 0.0};
  bool inside = false;
  if (den > 1e-14 * d00 * d11) {
    const Real l1 = (d11 * d20 - d01 * d21) / den;
    const Real l2 = (d00 * d21 - d01 * d20) / den;
    const Real l0 = 1 - l1 - l2;
    if (l0 >= -opt.tol && l1 >= -opt.tol && l2 >= -opt.tol) {
      inside = true;
      l = {std::max(l0, Real(0)), std::max(l1, Real(0)), std::max(l2, Real(0))};
      const Real s = l[0] + l[1] + l[2];
      for (Real& v : l) v /= s;
    }
  }
  if (!inside) {
    Real best_d2 = std::numeric_limits<Real>::infinity();
    // Edges 0-1, 1-2, 2-0 as barycentric segments.
    for (int k = 0; k < 3; ++k) {
      const int a = k, b = (k + 1) % 3;
      const Real t = detail::segment_parameter(p, c[a], c[b]);
      std::array<Real, 3> lk{0.0, 0.0, 0.0};
      lk[a] = 1 - t;
      lk[b] = t;
      const Real d2 = (p - (lk[0] * c[0] + lk[1] * c[1] + lk[2] * c[2])).squaredNorm();
      if (d2 < best_d2) {
        best_d2 = d2;
        l = lk;
      }
    }
  }
  r.shape = {l[0], l[1], l[2], 0.0};
  r.point = l[0] * c[0] + l[1] * c[1] + l[2] * c[2];
  r.eta = 2 * l[2] - 1;
  r.xi = (l[0] + l[1]) > 0.0 ? (l[1] - l[0]) / (l[0] + l[1]) : 0.0;
  r.edges = static_cast<std::uint8_t>((l[2] <= opt.tol ? 1u : 0u) | (l[0] <= opt.tol ? 2u : 0u) |
                                      (l[1] <= opt.tol ? 8u : 0u));
  detail::finish(r, p, e0.cross(e1), c);
  return r;
}

/// Projects p onto the segment with corners c: a triangle when c[3] == c[2] exactly, otherwise a
/// bilinear quadrilateral.
inline Projection project_point_to_segment(const Vec3& p, const SegmentCorners& c,
                                           const ProjectionOptions& opt = {}) {
  return c[3] == c[2] ? project_point_to_triangle(p, c, opt) : project_point_to_quad(p, c, opt);
}

/// The current corner coordinates of segment s of `surface`, gathered from x (SoA, length).
inline SegmentCorners segment_corners(const Surface& surface, Index s, const Vec3Field& x) {
  const Index* n = &surface.conn[4 * static_cast<std::size_t>(s)];
  return {x.get(n[0]), x.get(n[1]), x.get(n[2]), x.get(n[3])};
}

/// Projects p onto segment s of `surface` at the coordinates x (triangle per surface.is_triangle).
inline Projection project_point_to_segment(const Vec3& p, const Surface& surface, Index s,
                                           const Vec3Field& x, const ProjectionOptions& opt = {}) {
  const SegmentCorners c = segment_corners(surface, s, x);
  return surface.is_triangle(s) ? project_point_to_triangle(p, c, opt)
                                : project_point_to_quad(p, c, opt);
}

/// The tie rule between two segments' projections of the same point: a (on segment sa) is better
/// than b (on sb) when it is nearer by more than tie_tolerance x max(a.size, b.size); within that
/// tolerance the lower segment index wins. Visit candidates in ascending segment order so that the
/// outcome does not depend on anything but the geometry.
inline bool is_better_projection(const Projection& a, Index sa, const Projection& b, Index sb,
                                 const ProjectionOptions& opt = {}) {
  const Real tol = opt.tie_tolerance * std::max(a.size, b.size);
  if (a.distance < b.distance - tol) return true;
  if (b.distance < a.distance - tol) return false;
  return sa < sb;
}

/// True when no projection of p onto the segment with corners c can replace `best` under
/// is_better_projection (the candidate visited after best): every point of the segment lies in
/// the box of its corners, so the box's distance bounds its projection's distance from below, and
/// when that bound is farther than best by more than the tie tolerance (taken with the box's
/// extent, >= the segment's size) and a margin for round-off (the computed closest point and
/// distances err by a few ulps of the coordinates), the candidate's projection would lose. Lets a
/// search skip the projection (a Newton solve) of segments that cannot win, with the same result.
inline bool cannot_beat(const Vec3& p, const SegmentCorners& c, const Projection& best,
                        const ProjectionOptions& opt = {}) {
  Vec3 lo = c[0], hi = c[0];
  for (int a = 1; a < 4; ++a) lo = lo.cwiseMin(c[a]), hi = hi.cwiseMax(c[a]);
  const Real lower2 = (lo - p).cwiseMax(p - hi).cwiseMax(Vec3::Zero()).squaredNorm();
  // The common case, a box not beyond the best distance: keep the candidate, no root, no bound
  // (keeping one that could have been skipped costs a projection, never a different pick).
  if (!(lower2 > best.distance * best.distance)) return false;
  const Real lower = std::sqrt(lower2);
  const Real tol = opt.tie_tolerance * std::max(best.size, (hi - lo).sum());
  const Real scale = std::max({p.cwiseAbs().maxCoeff(), lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff()});
  const Real round_off = 64 * std::numeric_limits<Real>::epsilon() * (scale + best.distance);
  return lower > best.distance + tol + round_off;
}

}  // namespace slideline
