#pragma once
/// The input checks build_simulation runs first, so that every refusal names a card and its
/// file:line and the same problem over many elements is one line with a count: an empty model,
/// element kinds (degenerate hexahedra: tetrahedra, pentahedra, pyramids; triangular shells),
/// inverted hexahedra (node order), material constants, *CONTROL_TIMESTEP TSSFAC, the end time,
/// and prescribed-motion fields that are read but not run.
#include "slideline/model/model.hpp"
#include "slideline/solver/build.hpp"

namespace slideline {

/// Throws InputError listing every bad input (one line each, collapsed over elements), or
/// NotImplementedError when every problem is a feature not implemented yet. Returns when clean.
void validate_model(const model::Model& model, const BuildOptions& options = {});

}  // namespace slideline
