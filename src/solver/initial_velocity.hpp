#pragma once
// Internal to build_simulation: the nodal velocities at t = 0 from the deck's *INITIAL_VELOCITY,
// *INITIAL_VELOCITY_GENERATION and *INITIAL_VELOCITY_NODE cards. Not installed.
#include <unordered_map>
#include <vector>

#include "slideline/mesh/mesh_sets.hpp"
#include "slideline/mesh/nodal_fields.hpp"
#include "slideline/model/model.hpp"
#include "slideline/solver/boundary.hpp"

namespace slideline {

/// What the builder knows when the velocities are applied (after the elements, sets and supports).
struct InitialVelocityInputs {
  const model::Model& model;
  const std::unordered_map<Id, Index>& node_index;      ///< deck node id -> internal index
  const MeshSets& sets;                                 ///< node sets, part sets, part nodes
  const std::unordered_map<Index, Id>& rigid_node_part; ///< node -> the rigid part that moves it
  const std::vector<SupportGroup>& supports;
};

/// Writes v(0) into nodes.v and the rotational velocity into nodes.omega (nodes of shells only;
/// solid nodes carry no rotations). The simulation starts from v(0) (its first step is a half step
/// from it) and books the kinetic energy of v(0) as the initial kinetic energy.
///
/// A node given two different velocities by two cards, a rotational velocity on cards whose nodes
/// carry none, or a rigid part whose nodes' velocities are not one rigid-body motion is an
/// InputError naming the card(s); local systems (ICID), IVATN and PHASE are NotImplementedError.
/// Components that a support fixes at t = 0 start at zero: the support wins, as it would after the
/// first step anyway, and no spurious support work enters the energy balance.
void apply_initial_velocities(const InitialVelocityInputs& in, NodalFields& nodes);

}  // namespace slideline
