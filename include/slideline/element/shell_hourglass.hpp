#pragma once
/// The hourglass control of a Belytschko-Tsay quadrilateral (shell_block.hpp), viscous or
/// stiffness: kept apart from the block (its size).
#include <algorithm>
#include <cmath>

#include "slideline/core/types.hpp"
#include "slideline/element/shell_bt.hpp"

namespace slideline::shell_hourglass {

/// Hourglass control on the membrane (x, y), bending (z) and rotation (x, y) modes of an element on
/// the mid-step geometry (gm, Xm), added to the forces f and moments m (global components); returns
/// its power. `qhg` the coefficient (LS-DYNA QM), `youngs` and `gs` (the shear factor times G) the
/// law's moduli, `t` the element's thickness (its stiffness), `m_node` and `j_node` its corner mass
/// and rotary inertia (from the section's thickness: the mass does not change).
/// `q` null: the viscous form (IHQ 1-3), each mode's force qhg times its critical damping times
/// its rate. `q` the element's 5 stored generalised forces (local components: membrane x, y,
/// bending z, rotation x, y): the stiffness form (IHQ 4-6, which LS-DYNA makes one form on
/// quadrilateral shells), Q += qhg k dt qdot with the mode stiffnesses k below, the forces -Q gamma
/// on the geometry `g` at x^n. The local frame turns with the element: the forces are objective.
/// `prev` (5, the viscous form's: its generalised forces of the last evaluation, replaced by this
/// one's; the stiffness form reads `q` before it grows) gives `prev_power`, the power of the last
/// evaluation's forces at these rates: the first half of the trapezoidal hourglass work.
inline Real add(Real qhg, Real youngs, Real gs, Real t, Real m_node, Real j_node, const shell_bt::LocalGeometry& gm,
                const shell_bt::NodeMat& Xm, const shell_bt::NodeMat& V, const shell_bt::NodeMat& W,
                shell_bt::NodeMat& f, shell_bt::NodeMat& m, Real* q, Real dt, const shell_bt::LocalGeometry* g,
                Real* prev, Real& prev_power) {
  // Relative to the element's mean rigid rotation: on a warped element the rotation about an
  // in-plane axis moves the nodes in plane in proportion to their warp, which is an hourglass
  // pattern; it must not be resisted.
  const Eigen::Matrix<Real, 1, 3> wbar = 0.25 * W.colwise().sum();
  const Eigen::Matrix<Real, 1, 3> xc = 0.25 * Xm.colwise().sum();
  shell_bt::NodeMat vrel;
  for (int k = 0; k < 4; ++k) vrel.row(k) = V.row(k) - wbar.cross(Xm.row(k) - xc);
  const shell_bt::NodeMat vl = vrel * gm.e;
  const shell_bt::NodeMat wl = W * gm.e;
  const Real bb = gm.b1.squaredNorm() + gm.b2.squaredNorm();
  // Mode stiffnesses of LS-DYNA's BT hourglass control (force per unit hourglass displacement).
  const Real k_m = youngs * t * gm.area * bb / 8.0;
  const Real k_w = gs * t * t * t * bb / 12.0;
  const Real k_r = youngs * t * t * t * gm.area * bb / 192.0;
  const Eigen::Matrix<Real, 4, 1> gam = gm.gamma.transpose();
  const Eigen::Matrix<Real, 1, 3> qv = gam.transpose() * vl;  // x, y, z mode rates
  const Eigen::Matrix<Real, 1, 3> qw = gam.transpose() * wl;
  if (q) {
    prev_power = q[0] * qv[0] + q[1] * qv[1] + q[2] * qv[2] + q[3] * qw[0] + q[4] * qw[1];
    const Real s = qhg * dt;
    q[0] += s * k_m * qv[0];
    q[1] += s * k_m * qv[1];
    q[2] += s * k_w * qv[2];
    q[3] += s * k_r * qw[0];
    q[4] += s * k_r * qw[1];
    // The stored forces act on the geometry at x^n (`g`, where the stresses act), the rates were
    // those of the mid step.
    const Eigen::Matrix<Real, 1, 3> hv(-q[0], -q[1], -q[2]);
    const Eigen::Matrix<Real, 1, 3> hw(-q[3], -q[4], 0.0);
    const Eigen::Matrix<Real, 4, 1> gn = g->gamma.transpose();
    f += gn * (hv * g->e.transpose());
    m += gn * (hw * g->e.transpose());
    return q[0] * qv[0] + q[1] * qv[1] + q[2] * qv[2] + q[3] * qw[0] + q[4] * qw[1];
  }
  // The viscous coefficient is qhg times the critical damping of the mode.
  const Real inv_gg = 1.0 / gm.gamma.squaredNorm();
  const Real cm = 2.0 * qhg * std::sqrt(k_m * m_node * inv_gg);
  const Real cw = 2.0 * qhg * std::sqrt(k_w * m_node * inv_gg);
  const Real cr = 2.0 * qhg * std::sqrt(k_r * j_node * inv_gg);
  const Eigen::Matrix<Real, 1, 3> hv(-cm * qv[0], -cm * qv[1], -cw * qv[2]);
  const Eigen::Matrix<Real, 1, 3> hw(-cr * qw[0], -cr * qw[1], 0.0);
  prev_power = prev[0] * qv[0] + prev[1] * qv[1] + prev[2] * qv[2] + prev[3] * qw[0] + prev[4] * qw[1];
  prev[0] = cm * qv[0];
  prev[1] = cm * qv[1];
  prev[2] = cw * qv[2];
  prev[3] = cr * qw[0];
  prev[4] = cr * qw[1];
  f += gam * (hv * gm.e.transpose());
  m += gam * (hw * gm.e.transpose());
  return cm * (qv[0] * qv[0] + qv[1] * qv[1]) + cw * qv[2] * qv[2] + cr * (qw[0] * qw[0] + qw[1] * qw[1]);
}

}  // namespace slideline::shell_hourglass
