#pragma once
/// Mass scaling (LS-DYNA's DT2MS of *CONTROL_TIMESTEP), applied once when the masses are lumped:
/// each element's mass is multiplied by (T / dt_e)^2, dt_e its stable step at the reference
/// geometry at rest and T = |DT2MS|, so that its step becomes T:
///   DT2MS < 0: only the elements with dt_e < T (mass added);
///   DT2MS > 0: every deformable element (mass added below T, removed above it).
/// Rigid parts are not scaled. See docs/solver.md, "Mass scaling".
#include <string>
#include <vector>

#include "slideline/core/types.hpp"
#include "slideline/element/element_block.hpp"
#include "slideline/element/element_mass_scaling.hpp"
#include "slideline/mesh/nodal_fields.hpp"

namespace slideline {

/// What mass scaling did to one block (one part).
struct PartAddedMass {
  Id part = 0;
  Real mass = 0.0;          ///< the part's physical mass (density x volume)
  Real added = 0.0;         ///< mass added (negative: removed, DT2MS > 0)
  Index scaled = 0;         ///< elements whose mass changed
  Index elements = 0;
  Real smallest_step = 0.0; ///< the smallest element step before scaling (time)
};

// mass_scale_factor(dt_e, dt2ms), the factor (T / dt_e)^2: element/element_mass_scaling.hpp.

/// Scales the masses `block` lumped to `nodes` (after its initialize(); `block_mass` is the mass
/// it lumped) for `dt2ms` != 0, and reports the change.
PartAddedMass scale_block_mass(ElementBlock& block, NodalFields& nodes, Real block_mass, Real dt2ms);

/// One line per part for the run's log: "part 2: mass 0.01, added 0.0025 (25%), 3 of 12 elements".
std::string describe(const PartAddedMass& p);

}  // namespace slideline
