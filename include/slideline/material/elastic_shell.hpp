#pragma once
/// Linear elastic, plane-stress law of a shell point, hypoelastic: each step adds C : D dt to the
/// stress the point holds, in the element's co-rotational frame, so the stored stress turns with
/// the element (Belytschko, Lin & Tsay 1984). *MAT_ELASTIC on shells.
#include <cmath>
#include <string>

#include "slideline/core/types.hpp"
#include "slideline/material/shell_material.hpp"

namespace slideline {

/// A PlaneStressMaterial (shell_material.hpp) whose state is the stress.
class ElasticShell {
 public:
  struct State {
    ShellStress sigma{};  ///< local xx, yy, xy, yz, xz (force/length^2); zero at the start
  };

  /// `density` mass/length^3, `youngs` force/length^2, `poisson` in (-1, 0.5).
  ElasticShell(Real density, Real youngs, Real poisson)
      : rho_(density), e_(youngs), nu_(poisson) {
    k_.c11 = e_ / (1.0 - nu_ * nu_);
    k_.c12 = nu_ * k_.c11;
    k_.g = e_ / (2.0 * (1.0 + nu_));
  }

  Real density() const { return rho_; }
  Real youngs_modulus() const { return e_; }
  Real poisson_ratio() const { return nu_; }
  Real shear_modulus() const { return k_.g; }
  /// E / (3 (1 - 2 nu)), the 3-D bulk modulus.
  Real bulk_modulus() const { return e_ / (3.0 * (1.0 - 2.0 * nu_)); }
  /// Plate (plane-stress) wave speed sqrt(E / (rho (1 - nu^2))), length / time.
  Real wave_speed() const { return std::sqrt(e_ / (rho_ * (1.0 - nu_ * nu_))); }
  PlaneStressStiffness stiffness() const { return k_; }

  /// Why these constants make no law, or empty.
  std::string problem() const {
    if (!(rho_ > 0.0) || !(e_ > 0.0) || !(nu_ > -1.0 && nu_ < 0.5))
      return "density and Young's modulus must be positive and Poisson's ratio in (-1, 0.5)";
    return {};
  }

  /// The PlaneStressMaterial step: sigma += C : d dt, with the transverse shear modulus k G
  /// (k = `shear_factor`, the section's). Returns the new stress.
  ShellStress update(State& state, const ShellRate& d, Real dt, Real shear_factor) const {
    ShellStress& s = state.sigma;
    const Real dxx = dt * d.xx;
    const Real dyy = dt * d.yy;
    const Real gxy = dt * d.xy;
    s[0] += k_.c11 * dxx + k_.c12 * dyy;
    s[1] += k_.c12 * dxx + k_.c11 * dyy;
    s[2] += k_.g * gxy;
    s[3] += shear_factor * k_.g * dt * d.yz;
    s[4] += shear_factor * k_.g * dt * d.xz;
    return s;
  }

  ShellStress stress(const State& state) const { return state.sigma; }

  /// Strain energy per unit volume held at a point, sigma : C^-1 : sigma / 2 (force/length^2), with
  /// the transverse shear modulus k G (k = `shear_factor`).
  Real energy_density(const State& state, Real shear_factor) const {
    const ShellStress& s = state.sigma;
    const Real exx = (s[0] - nu_ * s[1]) / e_, eyy = (s[1] - nu_ * s[0]) / e_;
    const Real in_plane = s[0] * exx + s[1] * eyy + s[2] * s[2] / k_.g;
    return 0.5 * (in_plane + (s[3] * s[3] + s[4] * s[4]) / (shear_factor * k_.g));
  }

 private:
  Real rho_, e_, nu_;
  PlaneStressStiffness k_;
};

}  // namespace slideline
