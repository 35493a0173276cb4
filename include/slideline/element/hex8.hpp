#pragma once
/// 8-node hexahedron with one-point (uniform-strain) integration and hourglass control.
///
/// Uniform strain after Flanagan & Belytschko (1981), "A uniform strain hexahedron and
/// quadrilateral with orthogonal hourglass control", IJNME 17:679-706: the gradient operator is the
/// volume average B_I = (1/V) dV/dx_I, exact for any trilinear hexahedron, so the element passes
/// the constant-strain patch test on distorted meshes. Node order is LS-DYNA's: 1-4 the bottom face
/// counter-clockwise seen from the top, 5-8 the top face above them.
#include <array>
#include <cmath>

#include "slideline/core/lanes.hpp"
#include "slideline/core/types.hpp"

namespace slideline::hex8 {

using NodeMat = Eigen::Matrix<Real, 8, 3>;  ///< one row per node, columns x y z
using HgMat = Eigen::Matrix<Real, 4, 8>;    ///< hourglass vectors, one row per mode

/// Flanagan-Belytschko hourglass base vectors: xi*eta, eta*zeta... evaluated at the nodes.
inline constexpr int hourglass_signs[4][8] = {{1, 1, -1, -1, -1, -1, 1, 1},
                                              {1, -1, -1, 1, -1, 1, 1, -1},
                                              {1, -1, 1, -1, 1, -1, 1, -1},
                                              {-1, 1, -1, 1, 1, -1, 1, -1}};

/// hourglass_signs as a matrix, one row per mode.
inline const HgMat& hourglass_base() {
  static const HgMat g = [] {
    HgMat m;
    for (int a = 0; a < 4; ++a)
      for (int k = 0; k < 8; ++k) m(a, k) = hourglass_signs[a][k];
    return m;
  }();
  return g;
}

namespace detail {
/// dV/dx of one node from the coordinates of the six nodes it shares faces with, in the order of
/// Flanagan & Belytschko's appendix (the same closed form LULESH uses).
/// T is Real for one element or Lanes for a batch of elements.
template <class T>
inline void volume_derivative(const T* x, const T* y, const T* z, const int* p, T& dx, T& dy,
                              T& dz) {
  const T x0 = x[p[0]], x1 = x[p[1]], x2 = x[p[2]], x3 = x[p[3]], x4 = x[p[4]], x5 = x[p[5]];
  const T y0 = y[p[0]], y1 = y[p[1]], y2 = y[p[2]], y3 = y[p[3]], y4 = y[p[4]], y5 = y[p[5]];
  const T z0 = z[p[0]], z1 = z[p[1]], z2 = z[p[2]], z3 = z[p[3]], z4 = z[p[4]], z5 = z[p[5]];
  constexpr Real twelfth = 1.0 / 12.0;
  dx = twelfth * ((y1 + y2) * (z0 + z1) - (y0 + y1) * (z1 + z2) + (y0 + y4) * (z3 + z4) -
                  (y3 + y4) * (z0 + z4) - (y2 + y5) * (z3 + z5) + (y3 + y5) * (z2 + z5));
  dy = twelfth * (-(x1 + x2) * (z0 + z1) + (x0 + x1) * (z1 + z2) - (x0 + x4) * (z3 + z4) +
                  (x3 + x4) * (z0 + z4) + (x2 + x5) * (z3 + z5) - (x3 + x5) * (z2 + z5));
  dz = twelfth * (-(y1 + y2) * (x0 + x1) + (y0 + y1) * (x1 + x2) - (y0 + y4) * (x3 + x4) +
                  (y3 + y4) * (x0 + x4) + (y2 + y5) * (x3 + x5) - (y3 + y5) * (x2 + x5));
}

/// For each node: its three edge neighbours and three face-diagonal partners, in the cyclic order
/// the closed form needs.
inline constexpr int perm[8][6] = {{1, 2, 3, 4, 5, 7}, {2, 3, 0, 5, 6, 4}, {3, 0, 1, 6, 7, 5},
                                   {0, 1, 2, 7, 4, 6}, {7, 6, 5, 0, 3, 1}, {4, 7, 6, 1, 0, 2},
                                   {5, 4, 7, 2, 1, 3}, {6, 5, 4, 3, 2, 0}};

/// Corner nodes of the six faces, in cyclic order (the diagonals 0-2 and 1-3 span the face).
inline constexpr int faces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                    {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
}  // namespace detail

/// The six faces with OUTWARD node order (counter-clockwise seen from outside, so that
/// (x[f[2]] - x[f[0]]) x (x[f[3]] - x[f[1]]) points out of the element) for LS-DYNA's node order
/// and a positive volume. With (xi, eta, zeta) the element's natural coordinates (node 1 at
/// (-1,-1,-1), 2 at (1,-1,-1), 3 at (1,1,-1), 4 at (-1,1,-1), 5-8 the same at zeta = +1):
///   0: zeta = -1 (nodes 1 4 3 2), points along -zeta      1: zeta = +1 (5 6 7 8), +zeta
///   2: eta  = -1 (nodes 1 2 6 5), points along -eta       3: xi   = +1 (2 3 7 6), +xi
///   4: eta  = +1 (nodes 3 4 8 7), points along +eta       5: xi   = -1 (4 1 5 8), -xi
/// Face k has the same nodes as detail::faces[k]; only face 0 runs the other way there.
inline constexpr int outward_faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                            {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

/// Volume derivatives dV/dx_I (8x3) of a hexahedron with node coordinates X (8x3).
/// The volume itself is V = (1/3) sum_I x_I . dV/dx_I (V is homogeneous of degree 3).
inline NodeMat volume_gradient(const NodeMat& X) {
  using detail::perm;
  Real x[8], y[8], z[8];
  for (int i = 0; i < 8; ++i) {
    x[i] = X(i, 0);
    y[i] = X(i, 1);
    z[i] = X(i, 2);
  }
  NodeMat g;
  for (int i = 0; i < 8; ++i) detail::volume_derivative(x, y, z, perm[i], g(i, 0), g(i, 1), g(i, 2));
  return g;
}

/// One nodal component of a batch of kLanes elements: entry k holds node k of every element.
using NodeLanes = std::array<Lanes, 8>;

/// volume_gradient for a batch of elements (one per lane): the same closed form, evaluated on lane
/// vectors, so one call serves kLanes elements without shuffles.
inline void volume_gradient(const NodeLanes& x, const NodeLanes& y, const NodeLanes& z,
                            NodeLanes& gx, NodeLanes& gy, NodeLanes& gz) {
  for (int i = 0; i < 8; ++i)
    detail::volume_derivative(x.data(), y.data(), z.data(), detail::perm[i], gx[i], gy[i], gz[i]);
}

/// Largest face area of each element of a batch (squared areas compared, one square root).
inline Lanes max_face_area(const NodeLanes& x, const NodeLanes& y, const NodeLanes& z) {
  Lanes a2 = Lanes::Zero();
  for (const auto& f : detail::faces) {
    const Lanes ax = x[f[2]] - x[f[0]], ay = y[f[2]] - y[f[0]], az = z[f[2]] - z[f[0]];
    const Lanes bx = x[f[3]] - x[f[1]], by = y[f[3]] - y[f[1]], bz = z[f[3]] - z[f[1]];
    const Lanes cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
    a2 = a2.max(cx * cx + cy * cy + cz * cz);
  }
  return 0.5 * lane_sqrt(a2);
}

/// Hourglass resistance h_I = sum_a gamma_a,I (gamma_a . w) of a batch of elements (one per lane),
/// with gamma_a = Gamma_a - (Gamma_a . x) B the hourglass shape vectors of hourglass_shape and w a
/// nodal field (velocities or displacements). Multiply by -k for the hourglass force.
inline void hourglass_resistance(const NodeLanes& x, const NodeLanes& y, const NodeLanes& z,
                                 const NodeLanes& bx, const NodeLanes& by, const NodeLanes& bz,
                                 const NodeLanes& wx, const NodeLanes& wy, const NodeLanes& wz,
                                 NodeLanes& hx, NodeLanes& hy, NodeLanes& hz) {
  for (int k = 0; k < 8; ++k) hx[k] = hy[k] = hz[k] = Lanes::Zero();
  for (const auto& g : hourglass_signs) {
    // Gamma_a . x: the signs are +-1, so these are sums and differences of coordinates.
    Lanes gx = Lanes::Zero(), gy = Lanes::Zero(), gz = Lanes::Zero();
    for (int k = 0; k < 8; ++k) {
      if (g[k] > 0) {
        gx += x[k];
        gy += y[k];
        gz += z[k];
      } else {
        gx -= x[k];
        gy -= y[k];
        gz -= z[k];
      }
    }
    NodeLanes gam;
    Lanes dx = Lanes::Zero(), dy = Lanes::Zero(), dz = Lanes::Zero();
    for (int k = 0; k < 8; ++k) {
      gam[k] = Real(g[k]) - (gx * bx[k] + gy * by[k] + gz * bz[k]);
      dx += gam[k] * wx[k];
      dy += gam[k] * wy[k];
      dz += gam[k] * wz[k];
    }
    for (int k = 0; k < 8; ++k) {
      hx[k] += gam[k] * dx;
      hy[k] += gam[k] * dy;
      hz[k] += gam[k] * dz;
    }
  }
}

/// Volume of a trilinear hexahedron.
inline Real volume(const NodeMat& X, const NodeMat& dvdx) {
  return (X.array() * dvdx.array()).sum() / 3.0;
}

/// Largest face area, for the characteristic length V / A_max (LS-DYNA's solid time step).
inline Real max_face_area(const NodeMat& X) {
  Real amax = 0.0;
  for (const auto& f : detail::faces) {
    const Vec3 d1 = (X.row(f[2]) - X.row(f[0])).transpose();
    const Vec3 d2 = (X.row(f[3]) - X.row(f[1])).transpose();
    amax = std::max(amax, 0.5 * d1.cross(d2).norm());
  }
  return amax;
}

/// Flanagan-Belytschko hourglass shape vectors gamma = Gamma - (Gamma . x) B (4x8): orthogonal to
/// every linear field on the current configuration, so rigid motion and uniform strain produce no
/// hourglass force.
inline HgMat hourglass_shape(const NodeMat& X, const NodeMat& B) {
  const HgMat& G = hourglass_base();
  const Eigen::Matrix<Real, 4, 3> gx = G * X;  // (Gamma_alpha . x_i)
  return G - gx * B.transpose();
}

}  // namespace slideline::hex8
