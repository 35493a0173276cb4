#pragma once
// The uniaxial bilinear stress-strain curve of J2 plasticity with mixed hardening (LS-DYNA
// material 3), in closed form: the reference of the hexahedron and shell plasticity tests.
#include "slideline/core/types.hpp"

namespace slideline::test_support {

/// E Young's modulus, Et tangent modulus, sy initial yield stress, beta 1 isotropic / 0 kinematic.
struct Bilinear {
  Real e, et, sy, beta;
  Real ep() const { return e * et / (e - et); }
  /// Monotonic loading.
  Real loading(Real eps) const { return eps <= sy / e ? e * eps : sy + et * (eps - sy / e); }
  /// After loading to e1, unloading to eps <= e1: elastic until the reverse yield stress (isotropic:
  /// -sigma_1; kinematic: sigma_1 - 2 sigma_y; mixed: the back stress minus the grown radius), then
  /// slope Et.
  Real reversed(Real e1, Real eps) const {
    const Real s1 = loading(e1);
    const Real eps_p = e1 - s1 / e;
    const Real back = (1.0 - beta) * ep() * eps_p, radius = sy + beta * ep() * eps_p;
    const Real s_rev = back - radius;
    const Real s_el = s1 + e * (eps - e1);
    return s_el >= s_rev ? s_el : s_rev + et * (eps - (e1 - (s1 - s_rev) / e));
  }
};

}  // namespace slideline::test_support
