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
#include "slideline/core/tensor3.hpp"
#include "slideline/core/types.hpp"
#include "slideline/mesh/hex8_geometry.hpp"

namespace slideline::hex8 {

using HgMat = Eigen::Matrix<Real, 4, 8>;  ///< hourglass vectors, one row per mode

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
/// nodal field (velocities or displacements). Multiply by -k for the hourglass force. `modes`, when
/// given, receives the generalised values gamma_a . w of the four modes (x, y, z components).
inline void hourglass_resistance(const NodeLanes& x, const NodeLanes& y, const NodeLanes& z,
                                 const NodeLanes& bx, const NodeLanes& by, const NodeLanes& bz,
                                 const NodeLanes& wx, const NodeLanes& wy, const NodeLanes& wz,
                                 NodeLanes& hx, NodeLanes& hy, NodeLanes& hz,
                                 std::array<std::array<Lanes, 3>, 4>* modes = nullptr) {
  for (int k = 0; k < 8; ++k) hx[k] = hy[k] = hz[k] = Lanes::Zero();
  int a = 0;
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
    if (modes) (*modes)[a] = {dx, dy, dz};
    ++a;
  }
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

/// D = sym(v (x) B) of a batch (1/time), from the nodal velocities and the gradient operator.
inline Tensor3<Lanes> rate_of_deformation(const NodeLanes& vx, const NodeLanes& vy,
                                          const NodeLanes& vz, const NodeLanes& bx,
                                          const NodeLanes& by, const NodeLanes& bz) {
  Lanes dxx = Lanes::Zero(), dyy = Lanes::Zero(), dzz = Lanes::Zero();
  Lanes lxy = Lanes::Zero(), lyx = Lanes::Zero(), lyz = Lanes::Zero();
  Lanes lzy = Lanes::Zero(), lxz = Lanes::Zero(), lzx = Lanes::Zero();
  for (int k = 0; k < 8; ++k) {
    dxx += vx[k] * bx[k];
    dyy += vy[k] * by[k];
    dzz += vz[k] * bz[k];
    lxy += vx[k] * by[k];
    lyx += vy[k] * bx[k];
    lyz += vy[k] * bz[k];
    lzy += vz[k] * by[k];
    lxz += vx[k] * bz[k];
    lzx += vz[k] * bx[k];
  }
  const Lanes dxy = 0.5 * (lxy + lyx), dyz = 0.5 * (lyz + lzy), dxz = 0.5 * (lxz + lzx);
  return {{{dxx, dxy, dxz}, {dxy, dyy, dyz}, {dxz, dyz, dzz}}};
}

}  // namespace slideline::hex8
