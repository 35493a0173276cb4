#pragma once
/// Kernel of the 3-node C0 triangular shell (LS-DYNA element formulation 4, after T. Belytschko,
/// H. Stolarski, N. Carpenter, "A C0 triangular plate element with one-point quadrature", Int. J.
/// Numer. Meth. Engng 20 (1984) 787-802). LS-DYNA runs a triangle (N3 = N4) of a form-2 part as
/// this element.
///
/// A flat Mindlin plate in its co-rotational frame: e3 the normal (x2 - x1) x (x3 - x1), e1 side
/// 1-2 and e2 = e3 x e1. Linear velocity and rotation fields give the constant membrane strain
/// rate and the constant curvature rate, evaluated at the one in-plane point (the centroid) with
/// the part's through-thickness points, as the quad's.
///
/// Transverse shear: the linear field would lock (its shear at the centroid is not zero for the
/// pure-bending modes of a thin plate) and, taken at one point only, leaves a spurious mode (the
/// "radial" rotation field theta = s (x, y) has no curvature and no shear at the centroid). We use
/// the assumed (covariant) shear field of the C0 discrete-shear family (MITC3: Lee & Bathe 2004):
/// gamma = (a + c y, b - c x), whose tangential component is constant along each side and equal
/// to the side's mean tangential shear
///   e_k = (w_j - w_i) / L_k + tau_x (theta_y,i + theta_y,j) / 2 - tau_y (theta_x,i + theta_x,j) / 2.
/// It vanishes for every Kirchhoff mode of constant curvature (no locking in pure bending), and its
/// rotational part c, integrated exactly (int |gamma|^2 = A (a^2 + b^2) + c^2 I_p about the
/// centroid), stiffens the radial mode, so the element needs no hourglass control. The law sees
/// (a, b), the shear at the centroid; the c part is elastic (kappa G t I_p / A per unit area).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products
#include <Eigen/LU>        // 3 x 3 inverse

#include "slideline/core/types.hpp"
#include "slideline/element/shell_bt.hpp"

namespace slideline::shell_c0tri {

using NodeMat = Eigen::Matrix<Real, 3, 3>;  ///< one row per node: x, y, z
using Row3 = Eigen::Matrix<Real, 1, 3>;

/// The triangle in its co-rotational frame.
struct LocalGeometry {
  Mat3 e;             ///< columns e1, e2, e3 (global components)
  Row3 xl, yl;        ///< in-plane local coordinates of the nodes (origin at the centroid)
  Row3 b1, b2;        ///< dN_I/dx^, dN_I/dy^ (constant; 1/length)
  Row3 len;           ///< side lengths, side k from node k to node k + 1 (length)
  Row3 tx, ty;        ///< unit tangents of the sides (local components)
  Eigen::Matrix<Real, 3, 3> shear_map;  ///< rows a, b, c of the assumed shear from the side shears
  Real polar = 0.0;   ///< I_p / A = (sum x^2 + y^2) / 12 about the centroid (length^2)
  Real area = 0.0;    ///< area (length^2); <= 0 for a degenerate element
};

/// Moves the triangles (N3 = N4) of a shell connectivity (4 nodes per element, ids alongside)
/// after the quadrilaterals, each group in its original order, keeping a triangle's three nodes
/// only; returns the number of quadrilaterals.
inline Index triangles_last(std::vector<Index>& conn, std::vector<Id>& ids) {
  std::vector<Index> quads, tri;
  std::vector<Id> quad_ids, tri_ids;
  for (std::size_t e = 0; e < ids.size(); ++e) {
    const Index* n = conn.data() + 4 * e;
    const bool triangle = n[2] == n[3];
    (triangle ? tri : quads).insert((triangle ? tri : quads).end(), n, n + (triangle ? 3 : 4));
    (triangle ? tri_ids : quad_ids).push_back(ids[e]);
  }
  const auto nq = static_cast<Index>(quad_ids.size());
  if (tri_ids.empty()) return nq;
  quads.insert(quads.end(), tri.begin(), tri.end());
  quad_ids.insert(quad_ids.end(), tri_ids.begin(), tri_ids.end());
  conn = std::move(quads);
  ids = std::move(quad_ids);
  return nq;
}

/// The in-plane direction e1 of the invariant frame of a triangle (*CONTROL_ACCURACY INN = 2, 4;
/// LS-DYNA documents its construction for quadrilaterals only, this one is ours): the reference
/// side 1-2 direction carried by the rotation R of the polar decomposition F = R U of the
/// triangle's in-plane deformation gradient (current sides against reference sides, each in its
/// plane's basis p1 = side 1-2, p2 = e3 x p1). R does not depend on the numbering, and listing the
/// nodes from another corner turns the reference direction by a constant angle, so the frame
/// turns by that constant angle and an isotropic element gives the same answer. `x0`: the
/// reference coordinates; `e3`, `p1`: the current normal and side 1-2 direction (unit).
inline Vec3 invariant_e1(const NodeMat& x, const NodeMat& x0, const Vec3& e3, const Vec3& p1) {
  const Vec3 p2 = e3.cross(p1);
  const Vec3 s1 = (x.row(1) - x.row(0)).transpose(), s2 = (x.row(2) - x.row(0)).transpose();
  const Vec3 r1 = (x0.row(1) - x0.row(0)).transpose(), r2 = (x0.row(2) - x0.row(0)).transpose();
  const Vec3 q1 = r1.normalized();
  const Vec3 q2 = r1.cross(r2).normalized().cross(q1);
  Eigen::Matrix<Real, 2, 2> cur, ref;  // columns: the sides 1-2 and 1-3 in their plane's basis
  cur << s1.dot(p1), s2.dot(p1), s1.dot(p2), s2.dot(p2);
  ref << r1.dot(q1), r2.dot(q1), r1.dot(q2), r2.dot(q2);
  const Eigen::Matrix<Real, 2, 2> f = cur * ref.inverse();
  const Real phi = std::atan2(f(1, 0) - f(0, 1), f(0, 0) + f(1, 1));  // R of F = R U (det F > 0)
  return std::cos(phi) * p1 + std::sin(phi) * p2;
}

/// The frame, B matrix and assumed-shear map of the triangle with node coordinates `x`; with the
/// reference coordinates `x0` given, the invariant frame (invariant_e1), else e1 along side 1-2.
inline LocalGeometry local_geometry(const NodeMat& x, const NodeMat* x0 = nullptr) {
  LocalGeometry g;
  const Vec3 s1 = (x.row(1) - x.row(0)).transpose();
  const Vec3 s2 = (x.row(2) - x.row(0)).transpose();
  Vec3 e3 = s1.cross(s2);
  const Real n3 = e3.norm();
  const Real n1 = s1.norm();
  if (!(n3 > 0.0) || !(n1 > 0.0)) return g;  // area stays 0: the caller reports the element
  e3 /= n3;
  const Vec3 e1 = x0 != nullptr ? invariant_e1(x, *x0, e3, s1 / n1) : Vec3(s1 / n1);
  g.e.col(0) = e1;
  g.e.col(1) = e3.cross(e1);
  g.e.col(2) = e3;
  const Row3 c = x.colwise().sum() / 3.0;
  for (int k = 0; k < 3; ++k) {
    const Row3 d = x.row(k) - c;
    g.xl[k] = d.dot(g.e.col(0).transpose());
    g.yl[k] = d.dot(g.e.col(1).transpose());
  }
  const Row3& X = g.xl;
  const Row3& Y = g.yl;
  g.area = 0.5 * ((X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]));
  if (!(g.area > 0.0)) return g;
  const Real inv2a = 0.5 / g.area;
  g.b1 << (Y[1] - Y[2]), (Y[2] - Y[0]), (Y[0] - Y[1]);
  g.b2 << (X[2] - X[1]), (X[0] - X[2]), (X[1] - X[0]);
  g.b1 *= inv2a;
  g.b2 *= inv2a;
  Eigen::Matrix<Real, 3, 3> m;  // row k: gamma . tau_k at side k's midpoint in terms of (a, b, c)
  for (int k = 0; k < 3; ++k) {
    const int j = (k + 1) % 3;
    const Real dx = X[j] - X[k], dy = Y[j] - Y[k];
    g.len[k] = std::sqrt(dx * dx + dy * dy);
    g.tx[k] = dx / g.len[k];
    g.ty[k] = dy / g.len[k];
    const Real mx = 0.5 * (X[j] + X[k]), my = 0.5 * (Y[j] + Y[k]);
    m.row(k) << g.tx[k], g.ty[k], g.tx[k] * my - g.ty[k] * mx;
  }
  g.shear_map = m.inverse();
  g.polar = (X.squaredNorm() + Y.squaredNorm()) / 12.0;
  return g;
}

/// The transverse shear factor of the triangle: the section's `kappa` times t^2 / (t^2 + alpha h^2),
/// h its longest side, alpha = 0.1 (the stabilisation of Lyly, Stenberg & Vihinen 1993 and
/// Pitkaranta for low-order Mindlin plates). The constant assumed shear still over-constrains thin
/// plates on coarse meshes (h / t >> 1: measured 24 % too stiff on an 8 x 8 simply supported
/// plate at a / t = 100); the factor relaxes it there and tends to 1 as h / t -> 0.
inline Real stabilised_shear_factor(const LocalGeometry& g, Real kappa, Real t) {
  constexpr Real alpha = 0.1;
  const Real h2 = g.len.maxCoeff() * g.len.maxCoeff();
  return kappa * t * t / (t * t + alpha * h2);
}

/// The stable-step length l (length) for the step l / c, c^2 = c11 / rho the plate wave speed, of
/// the triangle with plane-stress moduli c11 and g (shear): from the trace of its lumped-mass
/// membrane stiffness, 3 (c11 + g) / rho sum |grad N_I|^2 >= omega_max^2, with
/// |grad N_I| = (opposite side) / 2A: l = 4 A / sqrt(3 (1 + g / c11) sum L_k^2). The smallest
/// altitude 2 A / (longest side) (LS-DYNA's length) exceeds the free element's limit by up to 1.7
/// times (measured against its eigenvalues); this bound is 0.7-0.9 of it.
inline Real characteristic_length(const LocalGeometry& g, Real c11, Real shear) {
  return 4.0 * g.area / std::sqrt(3.0 * (1.0 + shear / c11) * g.len.squaredNorm());
}

/// Upper bound (1/time^2) on the squared highest frequency of the triangle's bending and
/// transverse-shear modes: the trace sum K_ii / M_ii over the w and rotation degrees of freedom,
/// with the plane-stress moduli c11, g, the shear modulus kappa g of the section, thickness t,
/// nodal mass m and rotary inertia j. (The membrane modes decouple from these in the flat element
/// and are bounded by characteristic_length.)
inline Real bending_omega2_bound(const LocalGeometry& g, Real c11, Real gmod, Real kappa, Real t, Real m,
                                 Real j) {
  const Real ks = kappa * gmod * t;
  Eigen::Matrix<Real, 3, 3> w = Eigen::Matrix<Real, 3, 3>::Zero();  // (a, b, c) energy weights
  w(0, 0) = ks * g.area;
  w(1, 1) = ks * g.area;
  w(2, 2) = ks * g.area * g.polar;
  const Eigen::Matrix<Real, 3, 3> q = g.shear_map.transpose() * w * g.shear_map;  // side-shear stiffness
  const Real db = g.area * t * t * t / 12.0;
  Real trace = 0.0;
  for (int n = 0; n < 3; ++n) {
    Eigen::Matrix<Real, 3, 1> dz = Eigen::Matrix<Real, 3, 1>::Zero(), dx = dz, dy = dz;  // d(side)/d(dof)
    for (int k = 0; k < 3; ++k) {
      const int jn = (k + 1) % 3;
      if (n != k && n != jn) continue;
      dz[k] = (n == jn ? 1.0 : -1.0) / g.len[k];
      dy[k] = 0.5 * g.tx[k];
      dx[k] = -0.5 * g.ty[k];
    }
    trace += dz.dot(q * dz) / m;
    trace += (dx.dot(q * dx) + db * (c11 * g.b2[n] * g.b2[n] + gmod * g.b1[n] * g.b1[n])) / j;
    trace += (dy.dot(q * dy) + db * (c11 * g.b1[n] * g.b1[n] + gmod * g.b2[n] * g.b2[n])) / j;
  }
  return trace;
}

/// Velocity strains, as the quad's (shell_bt::StrainRates), plus the rate of the shear's
/// rotational part c (1/(length time)).
struct StrainRates {
  shell_bt::StrainRates s;
  Real shear_c = 0.0;
};

/// Strain rates from the local nodal velocities `vl` and angular velocities `wl` (3 x 3 each, local
/// components); the sign conventions are shell_bt::strain_rates' (shear[0] = 2 d_yz, [1] = 2 d_xz).
inline StrainRates strain_rates(const LocalGeometry& g, const NodeMat& vl, const NodeMat& wl) {
  StrainRates r;
  const auto vx = vl.col(0), vy = vl.col(1), vz = vl.col(2);
  const auto wx = wl.col(0), wy = wl.col(1);
  r.s.membrane[0] = g.b1.dot(vx);
  r.s.membrane[1] = g.b2.dot(vy);
  r.s.membrane[2] = g.b2.dot(vx) + g.b1.dot(vy);
  r.s.curvature[0] = g.b1.dot(wy);
  r.s.curvature[1] = -g.b2.dot(wx);
  r.s.curvature[2] = g.b2.dot(wy) - g.b1.dot(wx);
  Eigen::Matrix<Real, 3, 1> side;
  for (int k = 0; k < 3; ++k) {
    const int j = (k + 1) % 3;
    side[k] = (vz[j] - vz[k]) / g.len[k] + 0.5 * (g.tx[k] * (wy[k] + wy[j]) - g.ty[k] * (wx[k] + wx[j]));
  }
  const Eigen::Matrix<Real, 3, 1> abc = g.shear_map * side;
  r.s.shear[1] = abc[0];  // 2 d_xz
  r.s.shear[0] = abc[1];  // 2 d_yz
  r.shear_c = abc[2];
  return r;
}

/// Nodal forces `f` and moments `m` (3 x 3, local, residual form) of the resultants `r` and the
/// resultant `qc` (force/length^2 times length: kappa G t I_p / A times the integrated c) of the
/// shear's rotational part: minus the derivative of A (N.d + M.kappa + Q.gamma + qc c) with
/// respect to the nodal velocities (the transpose of strain_rates()).
inline void resultant_forces(const LocalGeometry& g, const shell_bt::Resultants& r, Real qc, NodeMat& f,
                             NodeMat& m) {
  const Real a = g.area;
  f.col(0) = -a * (r.n[0] * g.b1 + r.n[2] * g.b2).transpose();
  f.col(1) = -a * (r.n[1] * g.b2 + r.n[2] * g.b1).transpose();
  f.col(2).setZero();
  m.col(0) = a * (r.m[1] * g.b2 + r.m[2] * g.b1).transpose();
  m.col(1) = -a * (r.m[0] * g.b1 + r.m[2] * g.b2).transpose();
  m.col(2).setZero();  // no drilling stiffness
  // The generalised force on side k's shear: A (Q_xz, Q_yz, qc) . (column k of shear_map).
  const Eigen::Matrix<Real, 1, 3> side = a * (Eigen::Matrix<Real, 1, 3>(r.q[1], r.q[0], qc) * g.shear_map);
  for (int k = 0; k < 3; ++k) {
    const int j = (k + 1) % 3;
    const Real fz = side[k] / g.len[k];
    f(j, 2) -= fz;
    f(k, 2) += fz;
    const Real my = 0.5 * side[k] * g.tx[k], mx = 0.5 * side[k] * g.ty[k];
    m(k, 1) -= my;
    m(j, 1) -= my;
    m(k, 0) += mx;
    m(j, 0) += mx;
  }
}

}  // namespace slideline::shell_c0tri
