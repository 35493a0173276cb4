#pragma once
/// The material registry: the one place that maps a deck's material card (model::Material) to the
/// law its elements run (material/laws.hpp). It visits the card with one case per alternative and
/// no generic case, so a material added to model::Material without a case here does not compile.
#include <optional>
#include <span>

#include "slideline/material/laws.hpp"
#include "slideline/model/model.hpp"

namespace slideline {

/// What the elements of a part made of one material run.
struct MaterialLaws {
  std::optional<SolidLaw> solid;  ///< the law of hexahedra; empty: not available for solids
  std::optional<ShellLaw> shell;  ///< the law of shells; empty: not available for shells
  /// *MAT_RIGID: no deformable law. The part becomes one rigid body (solver/rigid_body.hpp) made
  /// from the card itself; E and PR set only its contact stiffness and time step.
  bool rigid = false;
  const char* keyword = "";  ///< the card, for messages: "*MAT_ELASTIC"
  /// The effective plastic strain at which elements erode (FS of *MAT_PLASTIC_KINEMATIC, FAIL of
  /// *MAT_PIECEWISE_LINEAR_PLASTICITY; element/element_erosion.hpp); 0: never.
  Real failure_strain = 0.0;
  const char* failure_field = "";  ///< its field name, for messages: "FS"
  /// TDEL of *MAT_PIECEWISE_LINEAR_PLASTICITY: elements whose stable step (time) falls below it
  /// erode; 0: never.
  Real min_step = 0.0;
  /// TEROD / CEROD of *MAT_NULL: solids erode when V/V0 exceeds / falls below them; 0: never.
  Real max_relative_volume = 0.0;
  Real min_relative_volume = 0.0;
};

/// The equation of state of `eos` for a material of reference density `rho0` (*EOS_GRUNEISEN's
/// rho0 C^2). V0 other than 1 is refused by validation; it is not read here.
EquationOfState equation_of_state(const model::Eos& eos, Real rho0);

/// The laws of `material`, its curves (*MAT_PIECEWISE_LINEAR_PLASTICITY's LCSS and LCSR) taken from
/// `curves`. Its constants are taken as they are: the deck's values are checked before
/// (validate_model, the builder), with the file and line of the card. Throws InputError for a
/// curve id not in `curves`. `eos`: the part's equation of state (EOSID of *PART), null when it has
/// none; only *MAT_NULL reads it (its solid law needs one; validation refuses an EOS on any other
/// material).
MaterialLaws material_laws(const model::Material& material, std::span<const model::Curve> curves = {},
                           const model::Eos* eos = nullptr);

}  // namespace slideline
