#pragma once
/// NodalConstraint: a hook that dictates the motion of some nodes (rigid bodies; test-only loads).
#include <span>
#include <string>
#include <vector>

#include "slideline/core/types.hpp"
#include "slideline/mesh/nodal_fields.hpp"
#include "slideline/solver/total_force.hpp"

namespace slideline {

/// What a constraint sees in the constraint phase of a cycle (all at t^n, per node):
/// the effective translational mass (the node's own plus the mass of tied slave nodes condensed
/// onto it) and the total force and moment (element, external and contact forces, plus the forces
/// of condensed tied slaves). Nodes that nothing is tied to have mass == NodalFields::mass and
/// force == f_int + f_ext + f_contact.
struct ConstraintLoads {
  std::span<const Real> mass;
  const NodalFields& nodes;
  const Vec3Field* total_force = nullptr;   ///< set when contact keeps a total (else summed here)
  const Vec3Field* total_moment = nullptr;
  /// The coming step: v^{n+1/2} = v^{n-1/2} + dt_avg a^n, x^{n+1} = x^n + dt_next v^{n+1/2}
  /// (prescribed motions of a rigid body need them to land on their curve). 0 = not known.
  Real dt_avg = 0.0;
  Real dt_next = 0.0;

  Vec3 force(Index i) const {
    if (total_force != nullptr) return total_force->get(i);
    return {slideline::total_force(nodes, 0, i), slideline::total_force(nodes, 1, i),
            slideline::total_force(nodes, 2, i)};
  }
  Vec3 moment(Index i) const {
    if (total_moment != nullptr) return total_moment->get(i);
    return {slideline::total_moment(nodes, 0, i), slideline::total_moment(nodes, 1, i),
            slideline::total_moment(nodes, 2, i)};
  }
};

/// Called by Simulation in this order each cycle: constrain_accelerations (forces at t^n are
/// complete, after tied contact condensed its slaves), then after_positions (x^{n+1} set).
/// See docs/solver.md, "Constraint order".
class NodalConstraint {
 public:
  virtual ~NodalConstraint() = default;
  /// Once, after the element blocks lumped their mass; `mass` is the effective mass (see above).
  virtual void initialize(NodalFields& nodes, std::span<const Real> mass) = 0;
  /// Replaces the accelerations (nodes.a, nodes.alpha) of the constrained nodes (and may record
  /// forces). May be called more than once per cycle (again after Lagrange-multiplier contact
  /// added its forces): it must depend only on its arguments and on state it sets in
  /// after_positions.
  virtual void constrain_accelerations(const ConstraintLoads& loads, NodalFields& nodes, Real t) = 0;
  /// Corrects positions and velocities after the position update.
  virtual void after_positions(std::span<const Real> mass, NodalFields& nodes, Real t) = 0;
  /// The nodes whose motion the constraint dictates (internal indices). The simulation books the
  /// work it does on them (EnergyReport::constraint); a hook that only adds loads lists none.
  virtual std::span<const Index> constrained_nodes() const { return {}; }
  /// Appends the names of the 3-vector history channels the constraint reports. Called once, by
  /// Simulation::initialize after initialize().
  virtual void append_output_names(std::vector<std::string>& /*names*/) const {}
  /// Writes the values of those channels at the current time, 3 per name in the same order, into
  /// `out` (size 3 x the number of names; preallocated, so no allocation per record).
  virtual void write_output_values(std::span<Real> /*out*/) const {}
};

}  // namespace slideline
