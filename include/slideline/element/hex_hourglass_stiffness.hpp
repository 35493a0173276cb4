#pragma once
/// Stiffness hourglass forms of the one-point hexahedron, on batches of kLanes elements (one per
/// lane): the Flanagan-Belytschko stiffness form (LS-DYNA IHQ 4 and 5) and our assumed-strain
/// form after Belytschko & Bindeman (1993) (IHQ 6). Both act on the generalised hourglass
/// displacements (or their rates) q_a = sum_I gamma_aI w_I, gamma the orthogonalised hourglass
/// shape vectors of hex8::hourglass_shape (4 modes a, a vector per mode), and return forces
/// f_I = -sum_a gamma_aI Q_a, so a linear field (rigid motion, uniform strain) gives none.
#include <array>

#include "slideline/core/lanes.hpp"
#include "slideline/element/hex8.hpp"

namespace slideline::hex8 {

/// The hourglass shape vectors gamma_a of a batch: one NodeLanes per mode.
using ModeShapes = std::array<NodeLanes, 4>;
/// One vector (x, y, z lanes) per hourglass mode.
using ModeVectors = std::array<std::array<Lanes, 3>, 4>;

/// gamma_a = Gamma_a - (Gamma_a . x) B of every mode (current configuration x, gradient B).
inline void hourglass_shapes(const NodeLanes& x, const NodeLanes& y, const NodeLanes& z, const NodeLanes& bx,
                             const NodeLanes& by, const NodeLanes& bz, ModeShapes& gam) {
  for (int a = 0; a < 4; ++a) {
    const auto& g = hourglass_signs[a];
    Lanes gx = Lanes::Zero(), gy = Lanes::Zero(), gz = Lanes::Zero();
    for (int k = 0; k < 8; ++k) {
      gx += Real(g[k]) * x[k];
      gy += Real(g[k]) * y[k];
      gz += Real(g[k]) * z[k];
    }
    for (int k = 0; k < 8; ++k) gam[a][k] = Real(g[k]) - (gx * bx[k] + gy * by[k] + gz * bz[k]);
  }
}

/// q_a = sum_I gamma_aI w_I for every mode (w a nodal field: velocities or displacements).
inline ModeVectors hourglass_project(const ModeShapes& gam, const NodeLanes& wx, const NodeLanes& wy,
                                     const NodeLanes& wz) {
  ModeVectors q;
  for (int a = 0; a < 4; ++a) {
    q[a] = {Lanes::Zero(), Lanes::Zero(), Lanes::Zero()};
    for (int k = 0; k < 8; ++k) {
      q[a][0] += gam[a][k] * wx[k];
      q[a][1] += gam[a][k] * wy[k];
      q[a][2] += gam[a][k] * wz[k];
    }
  }
  return q;
}

/// Hourglass nodal forces h_I = -sum_a gamma_aI Q_a (residual form) of generalised forces Q.
inline void hourglass_scatter(const ModeShapes& gam, const ModeVectors& Q, NodeLanes& hx, NodeLanes& hy,
                              NodeLanes& hz) {
  for (int k = 0; k < 8; ++k) {
    hx[k] = -(gam[0][k] * Q[0][0] + gam[1][k] * Q[1][0] + gam[2][k] * Q[2][0] + gam[3][k] * Q[3][0]);
    hy[k] = -(gam[0][k] * Q[0][1] + gam[1][k] * Q[1][1] + gam[2][k] * Q[2][1] + gam[3][k] * Q[3][1]);
    hz[k] = -(gam[0][k] * Q[0][2] + gam[1][k] * Q[1][2] + gam[2][k] * Q[2][2] + gam[3][k] * Q[3][2]);
  }
}

/// The element's corotational frame: e_0 along the xi axis of the current Jacobian at the
/// centre, e_1 the eta axis made orthogonal to it, e_2 = e_0 x e_1 (Gram-Schmidt). Rows: axes,
/// columns: global components.
using Frame = std::array<std::array<Lanes, 3>, 3>;

inline Frame corotational_frame(const NodeLanes& x, const NodeLanes& y, const NodeLanes& z) {
  static constexpr int xi[8] = {-1, 1, 1, -1, -1, 1, 1, -1};
  static constexpr int eta[8] = {-1, -1, 1, 1, -1, -1, 1, 1};
  std::array<Lanes, 3> j0{Lanes::Zero(), Lanes::Zero(), Lanes::Zero()}, j1 = j0;
  for (int k = 0; k < 8; ++k) {
    j0[0] += Real(xi[k]) * x[k];
    j0[1] += Real(xi[k]) * y[k];
    j0[2] += Real(xi[k]) * z[k];
    j1[0] += Real(eta[k]) * x[k];
    j1[1] += Real(eta[k]) * y[k];
    j1[2] += Real(eta[k]) * z[k];
  }
  Frame e;
  const Lanes n0 = 1.0 / lane_sqrt(j0[0] * j0[0] + j0[1] * j0[1] + j0[2] * j0[2]);
  for (int i = 0; i < 3; ++i) e[0][i] = j0[i] * n0;
  const Lanes d = j1[0] * e[0][0] + j1[1] * e[0][1] + j1[2] * e[0][2];
  for (int i = 0; i < 3; ++i) e[1][i] = j1[i] - d * e[0][i];
  const Lanes n1 = 1.0 / lane_sqrt(e[1][0] * e[1][0] + e[1][1] * e[1][1] + e[1][2] * e[1][2]);
  for (int i = 0; i < 3; ++i) e[1][i] *= n1;
  e[2][0] = e[0][1] * e[1][2] - e[0][2] * e[1][1];
  e[2][1] = e[0][2] * e[1][0] - e[0][0] * e[1][2];
  e[2][2] = e[0][0] * e[1][1] - e[0][1] * e[1][0];
  return e;
}

/// Assumed-strain hourglass forces (IHQ 6): generalised forces Q (global components) of the
/// generalised hourglass displacements q (global components), from the energy of the
/// hourglass part of the trilinear displacement field of a rectangular element in the
/// corotational frame, with the strains that make a one-point element lock in bending left out:
///  - normal strains, modulus E (uniaxial stress: no Poisson stiffening): for local component k
///    and a mode that varies along axis k, e_kk = q_ka xi_b / (8 a_k) with a_k the half length,
///    stiffness E V / (192 a_k^2) (modes xi eta, xi zeta, eta zeta) or E V / (576 a_k^2) (xi eta zeta);
///  - the shear of the three twist modes, modulus mu: gamma_ij = (xi_m / 8)(q_i,jm / a_j + q_j,im / a_i)
///    couples u_i's mode without xi_i with u_j's mode without xi_j, so plate twist is exact;
///  - left out: the parasitic shear of the bending modes (u_i with xi_i xi_j gives gamma_ij ~ xi_i / a_j,
///    which makes a coarse beam shear-lock) and the shear of the xi eta zeta mode.
/// 1 / a_k^2 is taken as 8 sum_I (e_k . B_I)^2 (exact for a rectangular element). Everything is
/// scaled by QM: QM = 1 gives a rectangular element the exact pure-bending stiffness.
/// `vol` volume, `e_mod` Young's modulus and `mu` the shear modulus (force/length^2).
inline ModeVectors assumed_strain_forces(const Frame& e, const NodeLanes& bx, const NodeLanes& by,
                                         const NodeLanes& bz, const ModeVectors& q, const Lanes& vol,
                                         Real e_mod, Real mu, Real qm) {
  std::array<Lanes, 3> w, rw;  // 1 / a_k^2 and 1 / a_k
  for (int k = 0; k < 3; ++k) {
    w[k] = Lanes::Zero();
    for (int n = 0; n < 8; ++n) {
      const Lanes bk = e[k][0] * bx[n] + e[k][1] * by[n] + e[k][2] * bz[n];
      w[k] += bk * bk;
    }
    w[k] *= 8.0;
    rw[k] = lane_sqrt(w[k]);
  }
  ModeVectors ql, Ql;  // local components
  for (int a = 0; a < 4; ++a)
    for (int k = 0; k < 3; ++k) ql[a][k] = e[k][0] * q[a][0] + e[k][1] * q[a][1] + e[k][2] * q[a][2];
  const Lanes c = (qm / 192.0) * vol;
  // Mode a < 3 does not vary along axis a (mode 0 = eta zeta, 1 = xi zeta, 2 = xi eta).
  for (int a = 0; a < 3; ++a)
    for (int k = 0; k < 3; ++k) Ql[a][k] = k == a ? Lanes::Zero() : Lanes(c * e_mod * w[k] * ql[a][k]);
  for (int k = 0; k < 3; ++k) Ql[3][k] = c * (e_mod / 3.0) * w[k] * ql[3][k];
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) {
      const Lanes s = c * mu * (ql[i][i] * rw[j] + ql[j][j] * rw[i]);
      Ql[i][i] += s * rw[j];
      Ql[j][j] += s * rw[i];
    }
  ModeVectors Q;
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 3; ++i) Q[a][i] = e[0][i] * Ql[a][0] + e[1][i] * Ql[a][1] + e[2][i] * Ql[a][2];
  return Q;
}

}  // namespace slideline::hex8
