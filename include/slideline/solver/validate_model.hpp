#pragma once
/// The validation layer: every check of a model's content, each problem named with its card and
/// file:line, the same problem over many elements one line with a count. Two entry points:
///
/// - check_references: the ids (dangling and duplicate), which the CLI runs on a deck it reads;
/// - validate_model: what build_simulation runs first: an empty model, element kinds (degenerate
///   hexahedra: tetrahedra, pentahedra, pyramids; triangular shells), inverted hexahedra (node
///   order), material constants, *CONTROL_TIMESTEP TSSFAC, the end time, contact birth and death,
///   and prescribed-motion fields that are read but not run (validate_model.cpp); what each part
///   asks of its section, hourglass card and material, *MAT_RIGID constraints, nodal TC/RC and
///   _RIGID motions (validate_parts.cpp); supports, loads, damping, curves, the other controls
///   and contact titles (validate_loads.cpp); the fields of the initial-velocity cards
///   (validate_initial.cpp). The builder then builds from a validated model; it keeps only its id
///   lookups and the checks that need the built mesh (two initial-velocity cards on one node, a
///   velocity that is not one rigid motion of a rigid part).
///
/// The reader checks only the syntax of each field (io/keyword_reader.hpp). See docs/keywords.md.
#include <vector>

#include "slideline/core/blockers.hpp"
#include "slideline/core/diagnostics.hpp"
#include "slideline/model/model.hpp"
#include "slideline/solver/build.hpp"

namespace slideline {

/// Every dangling or duplicate id in a model: elements referring to undefined nodes or parts,
/// parts to undefined sections, materials or hourglass cards, sets to undefined nodes or parts,
/// boundary conditions, loads and contacts to undefined sets, parts or curves. A reference to an
/// id that an unsupported (dropped) card defines names that card. The same problem repeated over
/// many elements is one Diagnostic with a count and the first few ids. Empty when clean.
std::vector<Diagnostic> check_references(const model::Model& model);

/// Throws InputError listing every bad input (one line each, collapsed over elements), or
/// NotImplementedError when every problem is a feature not implemented yet. Returns when clean.
void validate_model(const model::Model& model, const BuildOptions& options = {});

/// The problems validate_model throws, returned instead (bad input and features not implemented
/// apart, each line as it would be thrown); empty when clean.
Blockers find_model_problems(const model::Model& model, const BuildOptions& options = {});

}  // namespace slideline
