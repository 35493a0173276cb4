#pragma once
/// The contract between a shell's plane-stress law and the shell element (the counterpart of
/// SolidMaterial, solid_material.hpp). The element works in its co-rotational frame, so the law
/// sees rates and stresses in local components and never a rotation; it is called once per
/// element, through-thickness point and step, and the element owns one `State` per point.
#include <array>
#include <concepts>
#include <string>

#include "slideline/core/types.hpp"

namespace slideline {

/// Stress at a shell point, local co-rotational components: xx, yy, xy (plane stress) and the
/// transverse shears yz, xz (force/length^2).
using ShellStress = std::array<Real, 5>;

/// Rate of deformation at a shell point, local components (1/time): d_xx, d_yy, 2 d_xy (the
/// mid-surface rate plus z times the curvature rate) and the transverse 2 d_yz, 2 d_xz.
struct ShellRate {
  Real xx = 0.0, yy = 0.0, xy = 0.0, yz = 0.0, xz = 0.0;
};

/// The plane-stress stiffness sigma_xx = c11 e_xx + c12 e_yy, sigma_yy = c12 e_xx + c11 e_yy,
/// sigma_xy = g gamma_xy (force/length^2): what the element needs besides the stress (stiffness
/// damping, hourglass control).
struct PlaneStressStiffness {
  Real c11 = 0.0, c12 = 0.0, g = 0.0;
};

/// A shell law: `update(state, d, dt, k)` advances `state` by the rate d over the step dt (time)
/// and returns the new stress, k being the section's transverse shear factor; `stress(state)` is
/// the stress the state holds. `problem()` says why the constants cannot make a law (empty when
/// they can). The constants: density (mass/length^3), the plate wave speed (length/time), the
/// moduli (force/length^2).
template <class M>
concept PlaneStressMaterial =
    std::copy_constructible<M> && std::default_initializable<typename M::State> &&
    requires(const M m, typename M::State& s, const ShellRate& d, Real dt, Real k) {
      { m.update(s, d, dt, k) } -> std::same_as<ShellStress>;
      { m.stress(s) } -> std::same_as<ShellStress>;
      { m.problem() } -> std::same_as<std::string>;
      { m.density() } -> std::convertible_to<Real>;
      { m.wave_speed() } -> std::convertible_to<Real>;
      { m.youngs_modulus() } -> std::convertible_to<Real>;
      { m.shear_modulus() } -> std::convertible_to<Real>;
      { m.bulk_modulus() } -> std::convertible_to<Real>;
      { m.stiffness() } -> std::same_as<PlaneStressStiffness>;
    };

}  // namespace slideline
