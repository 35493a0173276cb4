#pragma once
/// The one-point hexahedron's terms for a law whose state carries each element's sound speed
/// (`State::sound_speed`: a *MAT_NULL solid's equation of state, material/null_solid.hpp; docs/solver.md,
/// "Null solids"), kept apart from hex_block.hpp (its size).
#include "slideline/core/lanes.hpp"
#include "slideline/core/types.hpp"
#include "slideline/element/block_options.hpp"

namespace slideline::state_speed {

/// The bulk viscosity q of a batch (force/length^2; 0 unless compressing) on the elements' own sound
/// speeds, written to `c`; the step's viscous term `qdt` (length/time), which the law's viscous
/// deviatoric stress 2 MU D' adds 4/3 MU / (rho len) to (the dilatational mode's damping, as stiffness
/// damping of beta (lambda + 2 mu) = 4/3 MU would); and the shock heating: q's work per unit
/// reference volume -q dJ = -q J tr(D) dt added to the state's internal energy `e`.
/// `rho` current density, `len` characteristic length, `trd` tr D, `j` V/V0, `dt` the step.
template <class State>
Lanes bulk_viscosity(State& state, Real viscosity, const BulkViscosity& bulk, const Lanes& rho, const Lanes& len,
                     const Lanes& trd, const LaneMask& compressing, const Lanes& j, Real dt, Lanes& qdt, Lanes& c) {
  c = state.sound_speed;
  const Lanes q = compressing.select(rho * len * (bulk.quadratic * len * trd * trd - bulk.linear * c * trd), 0.0);
  qdt = compressing.select(bulk.linear * c + bulk.quadratic * len * (-trd), 0.0) + (4.0 / 3.0 * viscosity) / (rho * len);
  state.e -= q * j * trd * dt;
  return q;
}

}  // namespace slideline::state_speed
