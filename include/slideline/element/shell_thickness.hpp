#pragma once
/// The through-thickness integration of a Belytschko-Tsay shell or C0 triangle (shell_block.hpp):
/// the plane-stress law's update at each point of the thickness rule and the resultants.
#include <cstddef>

#include "slideline/core/types.hpp"
#include "slideline/element/shell_bt.hpp"
#include "slideline/material/shell_material.hpp"

namespace slideline::shell_thickness {

/// Advances the law's state `st` (rule.n points, bottom first) of one element with the strain
/// rates `sr` over dt and integrates the stresses into the resultants `r` (which start at zero),
/// `thickness` the section's, `kappa` the shear factor. When damped, adds the Rayleigh
/// stiffness-damping stress beta (C : strain rate) to the resultants only, and returns its power per
/// unit area.
template <bool damped, PlaneStressMaterial Law>
Real integrate(const Law& mat, const shell_bt::ThicknessRule& rule, Real thickness, Real beta,
               typename Law::State* st, const shell_bt::StrainRates& sr, Real dt, shell_bt::Resultants& r,
               Real kappa) {
  const Real half_t = 0.5 * thickness;
  [[maybe_unused]] const PlaneStressStiffness cs = mat.stiffness();
  [[maybe_unused]] const Real gs = kappa * cs.g;
  Real damp = 0.0;
  for (int ip = 0; ip < rule.n; ++ip) {
    const Real z = rule.xi[ip] * half_t;
    const Real wz = rule.w[ip] * half_t;  // dz weight
    const ShellRate rate{sr.membrane[0] + z * sr.curvature[0], sr.membrane[1] + z * sr.curvature[1],
                         sr.membrane[2] + z * sr.curvature[2], sr.shear[0], sr.shear[1]};
    const ShellStress s = mat.update(st[ip], rate, dt, kappa);
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
