#pragma once
/// The through-thickness integration of a Belytschko-Tsay shell or C0 triangle (shell_block.hpp):
/// the plane-stress law's update at each point of the thickness rule and the resultants.
#include <array>
#include <cstddef>

#include "slideline/core/types.hpp"
#include "slideline/element/shell_bt.hpp"
#include "slideline/material/shell_material.hpp"

namespace slideline::shell_thickness {

/// What integrate() reports besides the resultants when asked (a null pointer: nothing, and not
/// one operation more). At each point the normal strain increment follows from sigma_zz = 0: the
/// law is isotropic linear elastic with plastic flow at constant volume (every shell law here), so
/// the volume changes only elastically, d eps_kk = (1 - 2 nu) / E d(sigma_xx + sigma_yy), and
///     d eps_zz = (1 - 2 nu) / E d(sigma_xx + sigma_yy) - dt (d_xx + d_yy);
/// elastic: -nu / (1 - nu) dt (d_xx + d_yy); plastic: minus the in-plane plastic increments.
/// Without its elastic part (*CONTROL_SHELL ISTUPD = 4) the plastic increment alone,
/// (1 - nu) / E d(sigma_xx + sigma_yy) - dt (d_xx + d_yy).
struct PointStrains {
  Real total_factor = 0.0;      ///< (1 - 2 nu) / E (length^2 / force)
  Real thickness_factor = 0.0;  ///< the factor of `mean`: (1 - 2 nu) / E, or (1 - nu) / E (ISTUPD = 4)
  /// Out: the thickness average sum_ip (w_ip / 2) d eps_zz of the step, with thickness_factor.
  Real mean = 0.0;
  /// When not null, rule.n entries: each point's accumulated strain in the element frame, tensor
  /// components xx, yy, zz, xy, yz, xz, to which the step's increments dt d (and d eps_zz with
  /// total_factor) are added.
  std::array<Real, 6>* strain = nullptr;
};

/// integrate()'s PointStrains at point ip (weight w): `ds` the step's change of sigma_xx + sigma_yy.
inline void add_point_strain(PointStrains& ps, int ip, Real w, Real ds, const ShellRate& rate, Real dt) {
  const Real tr = dt * (rate.xx + rate.yy);
  ps.mean += 0.5 * w * (ps.thickness_factor * ds - tr);
  if (!ps.strain) return;
  std::array<Real, 6>& e = ps.strain[ip];
  e[0] += dt * rate.xx;
  e[1] += dt * rate.yy;
  e[2] += ps.total_factor * ds - tr;
  e[3] += 0.5 * dt * rate.xy;
  e[4] += 0.5 * dt * rate.yz;
  e[5] += 0.5 * dt * rate.xz;
}

/// Advances the law's state `st` (rule.n points, bottom first) of one element with the strain
/// rates `sr` over dt and integrates the stresses into the resultants `r` (which start at zero),
/// `thickness` the section's, `kappa` the shear factor. When damped, adds the Rayleigh
/// stiffness-damping stress beta (C : strain rate) to the resultants only, and returns its power per
/// unit area. `ps` (may be null): the normal strains (PointStrains).
template <bool damped, PlaneStressMaterial Law>
Real integrate(const Law& mat, const shell_bt::ThicknessRule& rule, Real thickness, Real beta,
               typename Law::State* st, const shell_bt::StrainRates& sr, Real dt, shell_bt::Resultants& r,
               Real kappa, PointStrains* ps = nullptr) {
  const Real half_t = 0.5 * thickness;
  [[maybe_unused]] const PlaneStressStiffness cs = mat.stiffness();
  [[maybe_unused]] const Real gs = kappa * cs.g;
  Real damp = 0.0;
  for (int ip = 0; ip < rule.n; ++ip) {
    const Real z = rule.xi[ip] * half_t;
    const Real wz = rule.w[ip] * half_t;  // dz weight
    const ShellRate rate{sr.membrane[0] + z * sr.curvature[0], sr.membrane[1] + z * sr.curvature[1],
                         sr.membrane[2] + z * sr.curvature[2], sr.shear[0], sr.shear[1]};
    Real s_before = 0.0;
    if (ps) {
      const ShellStress s0 = mat.stress(st[ip]);
      s_before = s0[0] + s0[1];
    }
    const ShellStress s = mat.update(st[ip], rate, dt, kappa);
    if (ps) add_point_strain(*ps, ip, rule.w[ip], s[0] + s[1] - s_before, rate, dt);
    r.n[0] += wz * s[0];
    r.n[1] += wz * s[1];
    r.n[2] += wz * s[2];
    r.m[0] += wz * z * s[0];
    r.m[1] += wz * z * s[1];
    r.m[2] += wz * z * s[2];
    r.q[0] += wz * s[3];
    r.q[1] += wz * s[4];
    if constexpr (damped) {
      const Real rxx = rate.xx, ryy = rate.yy, rxy = rate.xy;
      const Real d0 = beta * (cs.c11 * rxx + cs.c12 * ryy);
      const Real d1 = beta * (cs.c12 * rxx + cs.c11 * ryy);
      const Real d2 = beta * cs.g * rxy;
      const Real d3 = beta * gs * sr.shear[0];
      const Real d4 = beta * gs * sr.shear[1];
      r.n[0] += wz * d0;
      r.n[1] += wz * d1;
      r.n[2] += wz * d2;
      r.m[0] += wz * z * d0;
      r.m[1] += wz * z * d1;
      r.m[2] += wz * z * d2;
      r.q[0] += wz * d3;
      r.q[1] += wz * d4;
      damp += wz * (d0 * rxx + d1 * ryy + d2 * rxy + d3 * sr.shear[0] + d4 * sr.shear[1]);
    }
  }
  return damp;
}


}  // namespace slideline::shell_thickness
