#pragma once
/// Kernel of the 4-node Belytschko-Tsay shell (LS-DYNA element formulation 2).
///
/// References: T. Belytschko, J.I. Lin, C.S. Tsay, "Explicit algorithms for the nonlinear dynamics
/// of shells", Comput. Methods Appl. Mech. Engrg. 42 (1984) 225-251; J.O. Hallquist, LS-DYNA
/// Theory Manual, section "Belytschko-Tsay shell".
///
/// Everything here works on one element in its co-rotational frame: the normal e3 is the cross
/// product of the diagonals, e1 is side 1-2 projected onto the plane (or, with invariant node
/// numbering, from the lines joining opposite mid-sides: local_geometry), e2 = e3 x e1. The element
/// is a flat Mindlin plate in that frame with one in-plane integration point (the centroid).
#include <array>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

#include "slideline/core/error.hpp"
#include "slideline/core/types.hpp"
#include "slideline/element/block_options.hpp"
#include "slideline/element/cell_output.hpp"

namespace slideline::shell_bt {

using NodeMat = Eigen::Matrix<Real, 4, 3>;  ///< one row per node: x, y, z
using Row4 = Eigen::Matrix<Real, 1, 4>;

/// The element in its co-rotational frame.
struct LocalGeometry {
  Mat3 e;          ///< columns e1, e2, e3 (global components)
  Row4 xl, yl;     ///< in-plane local coordinates of the nodes (origin at the centroid)
  Row4 b1, b2;     ///< dN_I/dx^, dN_I/dy^ at the centroid (1/length)
  Row4 gamma;      ///< Flanagan-Belytschko hourglass vector (orthogonal to linear fields)
  Real area = 0.0; ///< projected area (length^2); <= 0 for a degenerate or inverted element
};

/// The in-plane direction e1 of the invariant frame (LS-DYNA *CONTROL_ACCURACY INN = 2): a and b,
/// the unit vectors along the lines joining the mid-sides 4-1 -> 2-3 and 1-2 -> 3-4 (projected
/// onto the plane of normal e3), c their bisector and d = e3 x c; e1 = (c - d) / sqrt 2 lies 45
/// degrees from c on a's side (and e2 = e3 x e1 = (c + d) / sqrt 2 on b's). Renumbering the nodes
/// 1234 -> 2341 maps (a, b) to (b, -a), so the frame turns by exactly 90 degrees with the numbering
/// and an isotropic element gives the same answer; on a rectangle e1 is side 1-2. A zero vector
/// when a + b vanishes (a degenerate element).
inline Vec3 invariant_e1(const NodeMat& x, const Vec3& e3) {
  Vec3 a = (x.row(1) + x.row(2) - x.row(0) - x.row(3)).transpose();
  Vec3 b = (x.row(2) + x.row(3) - x.row(0) - x.row(1)).transpose();
  a -= a.dot(e3) * e3;
  b -= b.dot(e3) * e3;
  const Real na = a.norm(), nb = b.norm();
  if (!(na > 0.0) || !(nb > 0.0)) return Vec3::Zero();
  const Vec3 s = a / na + b / nb;
  const Real ns = s.norm();
  if (!(ns > 0.0)) return Vec3::Zero();
  const Vec3 c = s / ns;
  return (c - e3.cross(c)) * std::sqrt(0.5);
}

/// Builds the co-rotational frame, the centroid B matrix and the hourglass vector of the quad
/// with node coordinates `x` (4 x 3, global); `invariant`: e1 from invariant_e1, else side 1-2.
inline LocalGeometry local_geometry(const NodeMat& x, bool invariant = false) {
  LocalGeometry g;
  const Vec3 r31 = (x.row(2) - x.row(0)).transpose();
  const Vec3 r42 = (x.row(3) - x.row(1)).transpose();
  Vec3 e3 = r31.cross(r42);
  const Real n3 = e3.norm();
  if (!(n3 > 0.0)) return g;  // area stays 0: the caller reports the element
  e3 /= n3;
  Vec3 s1 = invariant ? invariant_e1(x, e3) : Vec3((x.row(1) - x.row(0)).transpose());
  s1 -= s1.dot(e3) * e3;
  const Real n1 = s1.norm();
  if (!(n1 > 0.0)) return g;
  const Vec3 e1 = s1 / n1;
  const Vec3 e2 = e3.cross(e1);
  g.e.col(0) = e1;
  g.e.col(1) = e2;
  g.e.col(2) = e3;
  const Eigen::Matrix<Real, 1, 3> c = 0.25 * x.colwise().sum();
  for (int k = 0; k < 4; ++k) {
    const Eigen::Matrix<Real, 1, 3> d = x.row(k) - c;
    g.xl[k] = d.dot(e1.transpose());
    g.yl[k] = d.dot(e2.transpose());
  }
  const Row4& X = g.xl;
  const Row4& Y = g.yl;
  g.area = 0.5 * ((X[2] - X[0]) * (Y[3] - Y[1]) + (X[1] - X[3]) * (Y[2] - Y[0]));
  if (!(g.area > 0.0)) return g;
  const Real inv2a = 0.5 / g.area;
  g.b1 << (Y[1] - Y[3]), (Y[2] - Y[0]), (Y[3] - Y[1]), (Y[0] - Y[2]);
  g.b2 << (X[3] - X[1]), (X[0] - X[2]), (X[1] - X[3]), (X[2] - X[0]);
  g.b1 *= inv2a;
  g.b2 *= inv2a;
  const Row4 h(1.0, -1.0, 1.0, -1.0);
  g.gamma = h - h.dot(X) * g.b1 - h.dot(Y) * g.b2;
  return g;
}

/// Characteristic length A / max(longest side, longest diagonal) of the quad with nodes `x` and
/// area `area`. LS-DYNA's default (A / longest side) can exceed the stable length of a single
/// free element by ~10% (it leans on the 0.9 step scale factor); the diagonal (LS-DYNA ISDO = 1)
/// bounds the highest membrane frequency of the one-point element from below.
inline Real characteristic_length(const NodeMat& x, Real area) {
  Real m = std::max((x.row(2) - x.row(0)).squaredNorm(), (x.row(3) - x.row(1)).squaredNorm());
  for (int k = 0; k < 4; ++k) m = std::max(m, (x.row((k + 1) % 4) - x.row(k)).squaredNorm());
  return area / std::sqrt(m);
}

/// Velocity strains at the centroid, in the local frame (1/time).
struct StrainRates {
  Eigen::Matrix<Real, 3, 1> membrane;   ///< d_xx, d_yy, 2 d_xy of the mid-surface
  Eigen::Matrix<Real, 3, 1> curvature;  ///< kappa_xx, kappa_yy, 2 kappa_xy (1/(length time))
  Eigen::Matrix<Real, 2, 1> shear;      ///< 2 d_yz, 2 d_xz (transverse)
};

/// Strain rates from the local nodal velocities `vl` and angular velocities `wl` (4 x 3 each,
/// local components). The strain rate at height z is membrane + z * curvature (Mindlin kinematics:
/// v_x(z) = v_x + z w_y, v_y(z) = v_y - z w_x).
inline StrainRates strain_rates(const LocalGeometry& g, const NodeMat& vl, const NodeMat& wl) {
  StrainRates s;
  const auto vx = vl.col(0), vy = vl.col(1), vz = vl.col(2);
  const auto wx = wl.col(0), wy = wl.col(1);
  s.membrane[0] = g.b1.dot(vx);
  s.membrane[1] = g.b2.dot(vy);
  s.membrane[2] = g.b2.dot(vx) + g.b1.dot(vy);
  s.curvature[0] = g.b1.dot(wy);
  s.curvature[1] = -g.b2.dot(wx);
  s.curvature[2] = g.b2.dot(wy) - g.b1.dot(wx);
  s.shear[0] = g.b2.dot(vz) - 0.25 * wx.sum();
  s.shear[1] = g.b1.dot(vz) + 0.25 * wy.sum();
  return s;
}

/// Resultants per unit length of the element (from the stresses integrated through the thickness).
struct Resultants {
  Eigen::Matrix<Real, 3, 1> n = Eigen::Matrix<Real, 3, 1>::Zero();  ///< N_xx, N_yy, N_xy (force/length)
  Eigen::Matrix<Real, 3, 1> m = Eigen::Matrix<Real, 3, 1>::Zero();  ///< M_xx, M_yy, M_xy = int z sigma dz
  Eigen::Matrix<Real, 2, 1> q = Eigen::Matrix<Real, 2, 1>::Zero();  ///< Q_yz, Q_xz (force/length)
};

/// Nodal forces `f` and moments `m` (4 x 3, local components, residual form: what the element
/// applies to its nodes) of the resultants `r` on the element `g`. They are minus the derivative of
/// the internal power with respect to the nodal velocities (the transpose of strain_rates()).
inline void resultant_forces(const LocalGeometry& g, const Resultants& r, NodeMat& f, NodeMat& m) {
  const Real a = g.area;
  f.col(0) = -a * (r.n[0] * g.b1 + r.n[2] * g.b2).transpose();
  f.col(1) = -a * (r.n[1] * g.b2 + r.n[2] * g.b1).transpose();
  f.col(2) = -a * (r.q[1] * g.b1 + r.q[0] * g.b2).transpose();
  m.col(0) = a * (r.m[1] * g.b2 + r.m[2] * g.b1).transpose();
  m.col(0).array() += 0.25 * a * r.q[0];
  m.col(1) = -a * (r.m[0] * g.b1 + r.m[2] * g.b2).transpose();
  m.col(1).array() -= 0.25 * a * r.q[1];
  m.col(2).setZero();  // no drilling stiffness
}

/// Through-thickness integration rule on [-1, 1] (weights sum to 2).
struct ThicknessRule {
  using Kind = ThicknessRuleKind;  // gauss, lobatto (block_options.hpp)
  static constexpr int kMaxPoints = 10;
  int n = 0;
  std::array<Real, kMaxPoints> xi{};
  std::array<Real, kMaxPoints> w{};

  /// The rule with `nip` points (Gauss 1..10, Lobatto 2..10, LS-DYNA's ranges). Throws InputError
  /// otherwise. Up to 5 points the abscissae and weights are the closed forms; beyond, the roots of
  /// P_n (Gauss) or of (1 - x^2) P'_{n-1} (Lobatto) by Newton's method, to round-off.
  static ThicknessRule make(int nip, Kind kind) {
    ThicknessRule r;
    r.n = nip;
    if (nip > 5 && nip <= kMaxPoints) return computed(nip, kind);
    if (kind == Kind::gauss) {
      switch (nip) {
        case 1: r.xi = {0.0}; r.w = {2.0}; return r;
        case 2: { const Real a = 1.0 / std::sqrt(3.0); r.xi = {-a, a}; r.w = {1.0, 1.0}; return r; }
        case 3: { const Real a = std::sqrt(0.6); r.xi = {-a, 0.0, a}; r.w = {5.0 / 9, 8.0 / 9, 5.0 / 9}; return r; }
        case 4: {
          const Real a = std::sqrt(3.0 / 7 - 2.0 / 7 * std::sqrt(1.2));
          const Real b = std::sqrt(3.0 / 7 + 2.0 / 7 * std::sqrt(1.2));
          const Real wa = (18.0 + std::sqrt(30.0)) / 36, wb = (18.0 - std::sqrt(30.0)) / 36;
          r.xi = {-b, -a, a, b}; r.w = {wb, wa, wa, wb}; return r;
        }
        case 5: {
          const Real a = std::sqrt(5.0 - 2.0 * std::sqrt(10.0 / 7)) / 3;
          const Real b = std::sqrt(5.0 + 2.0 * std::sqrt(10.0 / 7)) / 3;
          const Real wa = (322.0 + 13.0 * std::sqrt(70.0)) / 900;
          const Real wb = (322.0 - 13.0 * std::sqrt(70.0)) / 900;
          r.xi = {-b, -a, 0.0, a, b}; r.w = {wb, wa, 128.0 / 225, wa, wb}; return r;
        }
        default: break;
      }
    } else {
      switch (nip) {
        case 2: r.xi = {-1.0, 1.0}; r.w = {1.0, 1.0}; return r;
        case 3: r.xi = {-1.0, 0.0, 1.0}; r.w = {1.0 / 3, 4.0 / 3, 1.0 / 3}; return r;
        case 4: { const Real a = std::sqrt(0.2); r.xi = {-1.0, -a, a, 1.0}; r.w = {1.0 / 6, 5.0 / 6, 5.0 / 6, 1.0 / 6}; return r; }
        case 5: { const Real a = std::sqrt(3.0 / 7); r.xi = {-1.0, -a, 0.0, a, 1.0}; r.w = {0.1, 49.0 / 90, 32.0 / 45, 49.0 / 90, 0.1}; return r; }
        default: break;
      }
    }
    throw InputError("shell: unsupported number of through-thickness integration points " +
                     std::to_string(nip) + (kind == Kind::gauss ? " (Gauss: 1..10)" : " (Lobatto: 2..10)"));
  }

 private:
  /// Legendre P_n(x) and P_{n-1}(x) by the three-term recurrence.
  static std::pair<Real, Real> legendre(int n, Real x) {
    Real p0 = 1.0, p1 = x;
    for (int k = 2; k <= n; ++k) {
      const Real p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
      p0 = p1;
      p1 = p2;
    }
    return {p1, p0};
  }
  /// Gauss: x_i the roots of P_n, w_i = 2 / ((1 - x^2) P_n'(x)^2). Lobatto: +-1 and the roots of
  /// P'_{n-1}, w_i = 2 / (n (n - 1) P_{n-1}(x)^2).
  static ThicknessRule computed(int n, Kind kind) {
    ThicknessRule r;
    r.n = n;
    const Real pi = 3.14159265358979323846;
    const int m = kind == Kind::gauss ? n : n - 1;  // the Legendre degree whose roots (or turns) are used
    for (int i = 0; i < n; ++i) {
      Real x = -std::cos(pi * (i + (kind == Kind::gauss ? 0.75 : 0.0)) / (m + (kind == Kind::gauss ? 0.5 : 0.0)));
      if (kind == Kind::lobatto && (i == 0 || i == n - 1)) {
        r.xi[i] = i == 0 ? -1.0 : 1.0;
        r.w[i] = 2.0 / (n * (n - 1.0));
        continue;
      }
      for (int it = 0; it < 100; ++it) {
        const auto [p, q] = legendre(m, x);
        const Real dp = m * (x * p - q) / (x * x - 1.0);  // P_m'
        Real step;
        if (kind == Kind::gauss) {
          step = p / dp;
        } else {  // Newton on P_m' using P_m'' = (2 x P_m' - m (m + 1) P_m) / (1 - x^2)
          step = dp / ((2.0 * x * dp - m * (m + 1.0) * p) / (1.0 - x * x));
        }
        x -= step;
        if (std::abs(step) < 1e-16) break;
      }
      const auto [p, q] = legendre(m, x);
      const Real dp = m * (x * p - q) / (x * x - 1.0);
      r.xi[i] = x;
      r.w[i] = kind == Kind::gauss ? 2.0 / ((1.0 - x * x) * dp * dp) : 2.0 / (n * (n - 1.0) * p * p);
    }
    return r;
  }
};

/// A point's local stress (xx, yy, xy, yz, xz; zz = 0) in global components, e = the element's
/// frame (columns e1, e2, e3).
inline SymTensor6 global_stress(const Mat3& e, const Eigen::Matrix<Real, 5, 1>& s) {
  Mat3 local;
  local << s[0], s[2], s[4], s[2], s[1], s[3], s[4], s[3], 0.0;
  const Mat3 g = e * local * e.transpose();
  return {g(0, 0), g(1, 1), g(2, 2), g(0, 1), g(1, 2), g(0, 2)};
}

}  // namespace slideline::shell_bt
