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
};

/// The laws of `material`, its curves (*MAT_PIECEWISE_LINEAR_PLASTICITY's LCSS and LCSR) taken from
/// `curves`. Its constants are taken as they are: the deck's values are checked before
/// (validate_model, the builder), with the file and line of the card. Throws InputError for a
/// curve id not in `curves`.
MaterialLaws material_laws(const model::Material& material, std::span<const model::Curve> curves = {});

}  // namespace slideline
