#pragma once
/// The interface every element block (hexahedra, shells, rigid parts' elements) implements.
/// A block holds elements of one part: one formulation, one material, one section.
#include <span>
#include <string>

#include "slideline/core/types.hpp"
#include "slideline/mesh/corner_buffer.hpp"
#include "slideline/mesh/nodal_fields.hpp"

namespace slideline {

/// Energy rates an element block reports for one force evaluation.
struct BlockEnergy {
  Real internal = 0.0;   ///< stored strain energy, where the material has one (else 0)
  Real hourglass_power = 0.0;  ///< rate of work done against hourglass forces
  Real viscous_power = 0.0;    ///< rate of work done against bulk viscosity
};

class ElementBlock {
 public:
  virtual ~ElementBlock() = default;

  virtual std::string kind() const = 0;
  virtual Id part_id() const = 0;
  virtual Index element_count() const = 0;
  virtual int nodes_per_element() const = 0;
  /// Flat connectivity, nodes_per_element() internal node indices per element.
  virtual std::span<const Index> connectivity() const = 0;
  /// Deck id of element e, for messages.
  virtual Id element_id(Index e) const = 0;
  /// True when the block writes corner moments (its nodes carry rotations).
  virtual bool has_moments() const { return false; }
  /// False for blocks whose step only matters when nothing else bounds it (rigid parts: as in
  /// LS-DYNA, rigid elements do not set the step of a model with deformable elements).
  virtual bool bounds_time_step() const { return true; }

  /// Computes reference element data and adds this block's lumped mass (and rotary inertia) to
  /// the nodes. Called once, before the first step.
  virtual void initialize(NodalFields& nodes) = 0;

  /// Tells the block where its corner slots start in the shared buffer.
  void set_slot_base(Index force_base, Index moment_base) {
    force_base_ = force_base;
    moment_base_ = moment_base;
  }
  Index force_slot_base() const { return force_base_; }
  Index moment_slot_base() const { return moment_base_; }

  /// Computes the element forces at the current state into the block's corner slots and returns
  /// the smallest stable time step of its elements (before any scale factor). `dt` is the last
  /// step (t^{n+1/2} - t^{n-1/2}); velocities in `nodes.v` are at t^{n-1/2}.
  /// Throws InstabilityError naming the element on a negative volume or non-finite stress.
  virtual Real compute_forces(const NodalFields& nodes, Real dt, CornerBuffer& corners,
                              BlockEnergy& energy) = 0;

 protected:
  Index force_base_ = 0;
  Index moment_base_ = 0;
};

}  // namespace slideline
