#pragma once
/// What an element block reports per element for the state output (docs/output.md, "Cell
/// fields"): the Cauchy stress, its von Mises value, the effective plastic strain and the internal
/// energy density. Read at output times only, never inside the step.
#include <array>
#include <cmath>
#include <span>

#include "slideline/core/lanes.hpp"
#include "slideline/core/tensor3.hpp"
#include "slideline/core/types.hpp"

namespace slideline {

/// A symmetric tensor in global components, in the order xx, yy, zz, xy, yz, xz (force/length^2
/// for a stress): LS-DYNA's and VTK's order, the one ParaView's Xdmf3 readers name an XDMF
/// "Tensor6" attribute's components in (docs/output.md, "ParaView").
using SymTensor6 = std::array<Real, 6>;

/// One element's output values.
struct CellOutput {
  /// Cauchy stress of the law (without bulk viscosity and stiffness damping), global components;
  /// a shell's at its mid surface.
  SymTensor6 stress{};
  /// A shell's stress at its outermost through-thickness points (bottom: most negative z,
  /// top: most positive z, z along the element normal); a solid's equal `stress`.
  SymTensor6 stress_bottom{}, stress_top{};
  /// Effective plastic strain (dimensionless): the law state's `eps`, 0 for a law without one.
  Real plastic_strain = 0.0;
  /// Internal (strain) energy per unit reference volume (force/length^2 = energy/length^3); 0 for
  /// a law that does not report one.
  Real energy_density = 0.0;
  /// Deleted by erosion (element_erosion.hpp): its stress and energy density are then 0.
  bool deleted = false;
};

/// von Mises equivalent stress sqrt(3 J2) of a symmetric tensor (same units).
inline Real von_mises(const SymTensor6& s) {
  const Real a = s[0] - s[1], b = s[1] - s[2], c = s[2] - s[0];
  return std::sqrt(0.5 * (a * a + b * b + c * c) + 3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

/// Lane l of a lane vector, or the value itself (a law's state for one element or a batch).
inline Real lane_value(const Lanes& v, int l) { return v[l]; }
inline Real lane_value(Real v, int) { return v; }

/// The effective plastic strain a law's state holds (its member `eps`), lane l of a batch state;
/// 0 for a state without one (a hyperelastic law).
template <class State>
Real plastic_strain_of(const State& s, int lane = 0) {
  if constexpr (requires { s.eps; })
    return lane_value(s.eps, lane);
  else
    return 0.0;
}

/// A law state with an effective plastic strain `eps` and a plastic work density `work` (the J2
/// laws' states, solid and shell).
template <class State>
concept PlasticState = requires(const State& s) {
  s.eps;
  s.work;
};

/// The plastic work density a law's state holds (its member `work`, force/length^2: the sum of
/// sigma : d eps_p over its increments, per unit current volume), lane l of a batch state.
template <PlasticState State>
Real plastic_work_density_of(const State& s, int lane = 0) {
  return lane_value(s.work, lane);
}

/// Lane l of a lane tensor as a SymTensor6.
inline SymTensor6 sym6(const Tensor3<Lanes>& t, int l) {
  return {t[0][0][l], t[1][1][l], t[2][2][l], t[0][1][l], t[1][2][l], t[0][2][l]};
}

}  // namespace slideline
