#pragma once
/// Mass scaling applied once (*CONTROL_TIMESTEP DT2MS with MS1ST = 1): the one loop every block's
/// ElementBlock::scale_element_masses runs (hex_block.hpp, full_hex_block.hpp, tet_block.hpp,
/// shell_block.hpp). docs/solver.md, "Mass scaling".
#include <cmath>
#include <span>

#include "slideline/core/types.hpp"
#include "slideline/element/element_mass_scaling.hpp"
#include "slideline/mesh/nodal_fields.hpp"

namespace slideline {

/// Adds to each corner k of every element e its share of the element's mass (and rotary inertia)
/// times factor[e] - 1: share(e) gives the CornerShare (per-corner mass and inertia, first slot in
/// `conn`, corner count). Sets step_factor[e] = sqrt(factor[e]) (the element loop's step grows with
/// the mass). Returns the mass added (negative: removed, DT2MS > 0).
template <class Share>
Real scale_corner_masses(Index elements, std::span<const Real> factor, const Index* conn, Share&& share,
                         NodalFields& nodes, Real* step_factor) {
  Real added = 0.0;
  for (Index e = 0; e < elements; ++e) {
    const Real f = factor[static_cast<std::size_t>(e)];
    const ElementMassScaling::CornerShare c = share(e);
    const Real dm = c.mass * (f - 1.0);
    for (int k = 0; k < c.corners; ++k) nodes.mass[conn[c.first + k]] += dm;
    if (c.inertia != 0.0) {
      const Real dj = c.inertia * (f - 1.0);
      for (int k = 0; k < c.corners; ++k) nodes.rot_inertia[conn[c.first + k]] += dj;
    }
    added += c.corners * dm;
    step_factor[e] = std::sqrt(f);
  }
  return added;
}

}  // namespace slideline
