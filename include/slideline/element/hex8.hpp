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
#include <cstring>
#if defined(__AVX512F__)
#include <immintrin.h>
#endif

#include "slideline/core/types.hpp"

namespace slideline::hex8 {

using NodeMat = Eigen::Matrix<Real, 8, 3>;  ///< one row per node, columns x y z
using HgMat = Eigen::Matrix<Real, 4, 8>;    ///< hourglass vectors, one row per mode

/// Flanagan-Belytschko hourglass base vectors: xi*eta, eta*zeta... evaluated at the nodes.
inline const HgMat& hourglass_base() {
  static const HgMat g = [] {
    HgMat m;
    m << 1, 1, -1, -1, -1, -1, 1, 1,   //
        1, -1, -1, 1, -1, 1, 1, -1,    //
        1, -1, 1, -1, 1, -1, 1, -1,    //
        -1, 1, -1, 1, 1, -1, 1, -1;
    return m;
  }();
  return g;
}

namespace detail {
/// dV/dx of one node from the coordinates of the six nodes it shares faces with, in the order of
/// Flanagan & Belytschko's appendix (the same closed form LULESH uses).
inline void volume_derivative(const Real* x, const Real* y, const Real* z, const int* p, Real& dx,
                              Real& dy, Real& dz) {
  const Real x0 = x[p[0]], x1 = x[p[1]], x2 = x[p[2]], x3 = x[p[3]], x4 = x[p[4]], x5 = x[p[5]];
  const Real y0 = y[p[0]], y1 = y[p[1]], y2 = y[p[2]], y3 = y[p[3]], y4 = y[p[4]], y5 = y[p[5]];
  const Real z0 = z[p[0]], z1 = z[p[1]], z2 = z[p[2]], z3 = z[p[3]], z4 = z[p[4]], z5 = z[p[5]];
  constexpr Real twelfth = 1.0 / 12.0;
  dx = twelfth * ((y1 + y2) * (z0 + z1) - (y0 + y1) * (z1 + z2) + (y0 + y4) * (z3 + z4) -
                  (y3 + y4) * (z0 + z4) - (y2 + y5) * (z3 + z5) + (y3 + y5) * (z2 + z5));
  dy = twelfth * (-(x1 + x2) * (z0 + z1) + (x0 + x1) * (z1 + z2) - (x0 + x4) * (z3 + z4) +
                  (x3 + x4) * (z0 + z4) + (x2 + x5) * (z3 + z5) - (x3 + x5) * (z2 + z5));
  dz = twelfth * (-(y1 + y2) * (x0 + x1) + (y0 + y1) * (x1 + x2) - (y0 + y4) * (x3 + x4) +
                  (y3 + y4) * (x0 + x4) + (y2 + y5) * (x3 + x5) - (y3 + y5) * (x2 + x5));
}
}  // namespace detail

/// Volume derivatives dV/dx_I (8x3) of a hexahedron with node coordinates X (8x3).
/// The volume itself is V = (1/3) sum_I x_I . dV/dx_I (V is homogeneous of degree 3).
inline NodeMat volume_gradient(const NodeMat& X) {
  // For each node: its three edge neighbours and three face-diagonal partners, in the cyclic order
  // the closed form needs.
  static constexpr int perm[8][6] = {{1, 2, 3, 4, 5, 7}, {2, 3, 0, 5, 6, 4}, {3, 0, 1, 6, 7, 5},
                                     {0, 1, 2, 7, 4, 6}, {7, 6, 5, 0, 3, 1}, {4, 7, 6, 1, 0, 2},
                                     {5, 4, 7, 2, 1, 3}, {6, 5, 4, 3, 2, 0}};
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

/// Eight nodal values of one component, one per node (vectorises as one or two SIMD registers).
using Col8 = Eigen::Array<Real, 8, 1>;

namespace detail {
/// Column j of the neighbour table of volume_gradient, as a permutation of the 8 nodes. With
/// AVX-512 this is one register permute per call.
#if defined(__AVX512F__)
template <int j>
inline Col8 permute(const Col8& a) {
  static const __m512i idx[6] = {_mm512_setr_epi64(1, 2, 3, 0, 7, 4, 5, 6),
                                 _mm512_setr_epi64(2, 3, 0, 1, 6, 7, 4, 5),
                                 _mm512_setr_epi64(3, 0, 1, 2, 5, 6, 7, 4),
                                 _mm512_setr_epi64(4, 5, 6, 7, 0, 1, 2, 3),
                                 _mm512_setr_epi64(5, 6, 7, 4, 3, 0, 1, 2),
                                 _mm512_setr_epi64(7, 4, 5, 6, 1, 2, 3, 0)};
  Col8 out;
  _mm512_storeu_pd(out.data(), _mm512_permutexvar_pd(idx[j], _mm512_loadu_pd(a.data())));
  return out;
}
#else
template <int j>
inline Col8 permute(const Col8& a) {
  static constexpr int p[6][8] = {{1, 2, 3, 0, 7, 4, 5, 6}, {2, 3, 0, 1, 6, 7, 4, 5},
                                  {3, 0, 1, 2, 5, 6, 7, 4}, {4, 5, 6, 7, 0, 1, 2, 3},
                                  {5, 6, 7, 4, 3, 0, 1, 2}, {7, 4, 5, 6, 1, 2, 3, 0}};
  Col8 r;
  for (int i = 0; i < 8; ++i) r[i] = a[p[j][i]];
  return r;
}
#endif
}  // namespace detail

/// volume_gradient for coordinates held as three Col8 (x, y, z of the 8 nodes): the same closed
/// form evaluated for all 8 nodes at once on permuted copies of the coordinates.
inline void volume_gradient(const Col8& x, const Col8& y, const Col8& z, Col8& gx, Col8& gy,
                            Col8& gz) {
  using detail::permute;
  const Col8 x0 = permute<0>(x), x1 = permute<1>(x), x2 = permute<2>(x), x3 = permute<3>(x),
             x4 = permute<4>(x), x5 = permute<5>(x);
  const Col8 y0 = permute<0>(y), y1 = permute<1>(y), y2 = permute<2>(y), y3 = permute<3>(y),
             y4 = permute<4>(y), y5 = permute<5>(y);
  const Col8 z0 = permute<0>(z), z1 = permute<1>(z), z2 = permute<2>(z), z3 = permute<3>(z),
             z4 = permute<4>(z), z5 = permute<5>(z);
  constexpr Real twelfth = 1.0 / 12.0;
  gx = twelfth * ((y1 + y2) * (z0 + z1) - (y0 + y1) * (z1 + z2) + (y0 + y4) * (z3 + z4) -
                  (y3 + y4) * (z0 + z4) - (y2 + y5) * (z3 + z5) + (y3 + y5) * (z2 + z5));
  gy = twelfth * (-(x1 + x2) * (z0 + z1) + (x0 + x1) * (z1 + z2) - (x0 + x4) * (z3 + z4) +
                  (x3 + x4) * (z0 + z4) + (x2 + x5) * (z3 + z5) - (x3 + x5) * (z2 + z5));
  gz = twelfth * (-(y1 + y2) * (x0 + x1) + (y0 + y1) * (x1 + x2) - (y0 + y4) * (x3 + x4) +
                  (y3 + y4) * (x0 + x4) + (y2 + y5) * (x3 + x5) - (y3 + y5) * (x2 + x5));
}

/// Largest face area of the hexahedron given as three Col8 (one square root, not six).
inline Real max_face_area(const Col8& x, const Col8& y, const Col8& z) {
  static constexpr int faces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                      {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  Real a2 = 0.0;
  for (const auto& f : faces) {
    const Real ax = x[f[2]] - x[f[0]], ay = y[f[2]] - y[f[0]], az = z[f[2]] - z[f[0]];
    const Real bx = x[f[3]] - x[f[1]], by = y[f[3]] - y[f[1]], bz = z[f[3]] - z[f[1]];
    const Real cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
    a2 = std::max(a2, cx * cx + cy * cy + cz * cz);
  }
  return 0.5 * std::sqrt(a2);
}

/// Volume of a trilinear hexahedron.
inline Real volume(const NodeMat& X, const NodeMat& dvdx) {
  return (X.array() * dvdx.array()).sum() / 3.0;
}

/// Largest face area, for the characteristic length V / A_max (LS-DYNA's solid time step).
inline Real max_face_area(const NodeMat& X) {
  static constexpr int faces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                      {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  Real amax = 0.0;
  for (const auto& f : faces) {
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
