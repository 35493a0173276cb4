#pragma once
/// Stiffness hourglass forms of the one-point hexahedron, on batches of kLanes elements (one per
/// lane): the Flanagan-Belytschko stiffness form (LS-DYNA IHQ 4 and 5) and our assumed-strain
/// form after Belytschko & Bindeman (1993) (IHQ 6). Both act on the generalised hourglass
/// displacements (or their rates) q_a = sum_I gamma_aI w_I, gamma the orthogonalised hourglass
/// shape vectors of hex8::hourglass_shape (4 modes a, a vector per mode), and return forces
/// f_I = -sum_a gamma_aI Q_a, so a linear field (rigid motion, uniform strain) gives none.
/// HexBlock keeps Q per element in the element's corotational frame and integrates it from the
/// rates (Q += K dt qdot in local components), so both forms are objective and incremental.
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

/// Local (corotational) components of global mode vectors: v_l[a][k] = e_k . v[a].
inline ModeVectors to_local(const Frame& e, const ModeVectors& v) {
  ModeVectors l;
  for (int a = 0; a < 4; ++a)
    for (int k = 0; k < 3; ++k) l[a][k] = e[k][0] * v[a][0] + e[k][1] * v[a][1] + e[k][2] * v[a][2];
  return l;
}

/// Global components of local mode vectors: v[a][i] = sum_k e_k,i l[a][k].
inline ModeVectors to_global(const Frame& e, const ModeVectors& l) {
  ModeVectors v;
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 3; ++i) v[a][i] = e[0][i] * l[a][0] + e[1][i] * l[a][1] + e[2][i] * l[a][2];
  return v;
}

/// Assumed-strain hourglass stiffness (IHQ 6): the generalised forces Q (local components) of
/// generalised hourglass displacements q (local components, frame e), from the energy of the
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
/// scaled by QM: QM = 1 gives a rectangular element the exact pure-bending stiffness. The map is
/// linear in q: HexBlock applies it to the increments of q (the incremental, corotational form).
/// `vol` volume, `e_mod` Young's modulus and `mu` the shear modulus (force/length^2).
inline ModeVectors assumed_strain_stiffness(const Frame& e, const NodeLanes& bx, const NodeLanes& by,
                                            const NodeLanes& bz, const ModeVectors& ql, const Lanes& vol,
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
  ModeVectors Ql;
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
  return Ql;
}

/// The stiffness hourglass forces h (residual form) of a batch, incremental and corotational:
/// the generalised hourglass rates qdot_a = gamma_a . v are taken into the element's frame e
/// (corotational_frame), the stored generalised forces (12 per batch, local components, mode-major
/// `q`) grow by K dt qdot_l and return to global components for h_I = -sum_a gamma_aI Q_a.
/// K is k = `fb_k` V |B|^2 (IHQ 4, 5: fb_k = QM (lambda + 2 mu) / 72, the Flanagan-Belytschko
/// stiffness) or the assumed-strain operator (IHQ 6, `assumed_strain`). Keeping Q in the frame
/// that turns with the element makes the forces objective; integrating the rates makes the
/// hourglass energy the work of the forces actually applied (no total-displacement form, whose
/// stiffness changes with the shape and stops being conservative under large deformation).
/// `prev_power` receives Q_old . qdot_l, the power of the forces of the last evaluation at these
/// rates (the first half of the step's trapezoidal hourglass work, docs/solver.md "Energy").
inline void stiffness_hourglass_forces(bool assumed_strain, const NodeLanes& x, const NodeLanes& y,
                                       const NodeLanes& z, const NodeLanes& bx, const NodeLanes& by,
                                       const NodeLanes& bz, const NodeLanes& vx, const NodeLanes& vy,
                                       const NodeLanes& vz, const Lanes& vol, Real dt, Real fb_k, Real e_mod,
                                       Real mu, Real qm, Lanes* q, NodeLanes& hx, NodeLanes& hy, NodeLanes& hz,
                                       Lanes& prev_power) {
  ModeShapes gam;
  hourglass_shapes(x, y, z, bx, by, bz, gam);
  const Frame e = corotational_frame(x, y, z);
  ModeVectors dq = to_local(e, hourglass_project(gam, vx, vy, vz));
  prev_power = Lanes::Zero();
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 3; ++i) prev_power += q[3 * a + i] * dq[a][i];
  for (auto& mode : dq)
    for (auto& c : mode) c *= dt;
  ModeVectors dQ;
  if (assumed_strain) {
    dQ = assumed_strain_stiffness(e, bx, by, bz, dq, vol, e_mod, mu, qm);
  } else {
    Lanes b2 = Lanes::Zero();
    for (int k = 0; k < 8; ++k) b2 += bx[k] * bx[k] + by[k] * by[k] + bz[k] * bz[k];
    const Lanes k_fb = fb_k * vol * b2;
    for (int a = 0; a < 4; ++a)
      for (int i = 0; i < 3; ++i) dQ[a][i] = k_fb * dq[a][i];
  }
  ModeVectors Ql;
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 3; ++i) Ql[a][i] = q[3 * a + i] += dQ[a][i];
  hourglass_scatter(gam, to_global(e, Ql), hx, hy, hz);
}

}  // namespace slideline::hex8
