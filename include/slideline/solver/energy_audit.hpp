#pragma once
/// The parts of the energy audit outside the velocity update (central_difference.hpp forms the
/// sums of the nodes it moves): the tied slaves, whose velocities the ties set, and the kinetic
/// energy that rigid bodies' and ties' resets change after the position update.
#include <span>

#include "slideline/core/types.hpp"
#include "slideline/mesh/nodal_fields.hpp"
#include "slideline/solver/central_difference.hpp"
#include "slideline/solver/energy_ledger.hpp"

namespace slideline {

/// The energy sums of the tied slaves `nodes_idx` after they took their masters' velocities:
/// their kinetic energy and the work of the tie force m (v^{n+1/2} - v^{n-1/2}) / dt_avg - f
/// (damping included: they move as their masters do). `v_old`, `w_old`: their v^{n-1/2} and
/// omega^{n-1/2}, in the order of `nodes_idx`.
NodalEnergySums dictated_node_sums(const NodalFields& nodes, std::span<const Index> nodes_idx,
                                   std::span<const Vec3> v_old, std::span<const Vec3> w_old, const VelocityStep& step);

/// Kinetic energy of the half-step velocities of `idx` (translation and, where the node has them,
/// rotations), summed serially in the order of `idx`.
Real kinetic_energy(const NodalFields& nodes, std::span<const Index> idx);

/// Translational kinetic energy of the half-step velocities of `idx`, summed serially.
Real translational_kinetic_energy(const NodalFields& nodes, std::span<const Index> idx);

}  // namespace slideline
