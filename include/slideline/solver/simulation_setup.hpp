#pragma once
/// Everything a Simulation is built from, as one movable value: the builder (build_setup in
/// build.hpp) or a test fills it, then hands it to the Simulation constructor, which owns it from
/// then on. Nothing here is derived state: masses, corner gather lists, node roles, the forces at
/// t = 0 and the first step are computed by Simulation::initialize().
///
/// Units are the deck's consistent set (length L, mass M, time T), as everywhere in the library.
#include <memory>
#include <vector>

#include "slideline/contact/contact_manager.hpp"
#include "slideline/core/types.hpp"
#include "slideline/element/element_block.hpp"
#include "slideline/mesh/mesh_sets.hpp"
#include "slideline/mesh/nodal_fields.hpp"
#include "slideline/solver/boundary.hpp"
#include "slideline/solver/nodal_constraint.hpp"
#include "slideline/solver/simulation_controls.hpp"

namespace slideline {

struct SimulationSetup {
  /// Every node, dense internal index i: deck id ids[i], reference and current position x0, x (L),
  /// initial velocity v (L/T) and, for nodes with rotations, omega (1/T). Masses are left empty:
  /// the blocks lump them at initialize().
  NodalFields nodes;
  /// The element blocks (hex, shell, rigid mass), one per part and element kind; connectivity in
  /// internal node indices.
  std::vector<std::unique_ptr<ElementBlock>> blocks;
  /// The rigid parts: each moves its nodes as one rigid body.
  std::vector<std::unique_ptr<NodalConstraint>> constraints;
  /// The contact interfaces with their birth/death windows (T).
  ContactManager contacts;
  /// Acceleration fields on parts (scale in L/T^2 times a curve of t).
  std::vector<BodyLoad> body_loads;
  /// Concentrated nodal forces (M L/T^2) or moments (M L^2/T^2), scale times a curve of t.
  std::vector<NodalLoad> nodal_loads;
  /// Fixed and prescribed-motion nodes, in groups reported together (reactions in M L/T^2).
  std::vector<SupportGroup> supports;
  /// Mass-proportional damping (alpha in 1/T).
  std::vector<MassDamping> damping;
  /// Internal indices of the nodes whose displacement is recorded as a history.
  std::vector<Index> history_nodes;
  /// The deck's node, part and segment sets, resolved to internal indices (for contact and loads).
  MeshSets sets;
  /// End time (T), cycle limit, step scaling and bounds, output cadence, stability limits.
  SimulationControls controls;
};

}  // namespace slideline
