#pragma once
/// *MAT_NULL on shells: a surface with mass and no stiffness (a contact surface, a common modelling
/// device). The stress stays zero and the hourglass and stiffness damping see no stiffness;
/// Young's modulus YM and Poisson's ratio PR (LS-DYNA: "used for null shells only") set the time
/// step of the shells and the contact stiffness of their segments.
#include <cmath>
#include <string>

#include "slideline/core/types.hpp"
#include "slideline/material/shell_material.hpp"

namespace slideline {

/// A PlaneStressMaterial (shell_material.hpp) whose stress is always zero.
class NullShell {
 public:
  struct State {};

  /// `density` mass/length^3, `youngs` force/length^2 and `poisson` for the time step and contact.
  NullShell(Real density, Real youngs, Real poisson) : rho_(density), e_(youngs), nu_(poisson) {}

  Real density() const { return rho_; }
  Real youngs_modulus() const { return e_; }
  Real shear_modulus() const { return e_ / (2.0 * (1.0 + nu_)); }
  Real bulk_modulus() const { return e_ / (3.0 * (1.0 - 2.0 * nu_)); }
  /// The plate wave speed of YM, PR: it sets the step as for an elastic shell of those constants.
  Real wave_speed() const { return std::sqrt(e_ / (rho_ * (1.0 - nu_ * nu_))); }
  /// No stiffness: no hourglass resistance and no stiffness damping.
  PlaneStressStiffness stiffness() const { return {}; }

  std::string problem() const {
    if (!(rho_ > 0.0) || !(e_ > 0.0) || !(nu_ > -1.0 && nu_ < 0.5))
      return "*MAT_NULL shells need a positive density RO and Young's modulus YM (for the time step and the "
             "contact stiffness) and PR in (-1, 0.5)";
    return {};
  }

  ShellStress update(State&, const ShellRate&, Real, Real) const { return {}; }
  ShellStress stress(const State&) const { return {}; }

 private:
  Real rho_, e_, nu_;
};

}  // namespace slideline
