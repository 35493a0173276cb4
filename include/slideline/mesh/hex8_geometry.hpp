#pragma once
/// Geometry of the trilinear hexahedron: its volume and the volume's derivatives with respect to
/// the nodes (Flanagan & Belytschko 1981, the closed form LULESH uses). Mesh code needs the volume
/// (the outward side of a face, a contact segment's element volume) and the element kernel
/// (element/hex8.hpp) builds its gradient operator on it, so it lives here, below both.
/// Node order is LS-DYNA's: 1-4 the bottom face counter-clockwise seen from the top, 5-8 the top
/// face above them.
#include "slideline/core/types.hpp"

namespace slideline::hex8 {

using NodeMat = Eigen::Matrix<Real, 8, 3>;  ///< one row per node, columns x y z

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

/// Volume of a trilinear hexahedron.
inline Real volume(const NodeMat& X, const NodeMat& dvdx) {
  return (X.array() * dvdx.array()).sum() / 3.0;
}

}  // namespace slideline::hex8
