#pragma once
/// Mass scaling re-evaluated every cycle: LS-DYNA's DT2MS with MS1ST = 0 (its default) of
/// *CONTROL_TIMESTEP; docs/solver.md, "Mass scaling". After every force evaluation each block's
/// elements get the factor mass_scale_factor(dt_e, DT2MS) of their current stable step dt_e, and the
/// nodal masses are rebuilt as the physical mass (lumped once: elements, rigid parts, lumped masses)
/// plus the mass the elements add, gathered per node over the corner slots in a fixed order (no
/// atomics, thread-count independent); the rotary inertia of shell nodes likewise, over the moment
/// slots (a shell element's inertia is scaled by its mass factor). Changing a node's mass at its
/// current (half-step) velocity changes the kinetic energy by 1/2 dm |v|^2 (+ 1/2 dJ |omega|^2):
/// rescale() returns that sum for the energy ledger.
/// Everything is sized at initialize(); a step allocates nothing.
#include <span>
#include <vector>

#include "slideline/core/types.hpp"
#include "slideline/element/element_block.hpp"
#include "slideline/mesh/corner_buffer.hpp"
#include "slideline/mesh/nodal_fields.hpp"
#include "slideline/solver/boundary.hpp"
#include "slideline/solver/mass_scaling.hpp"

namespace slideline {

class MassRescaling {
 public:
  /// What one re-evaluation gives the step.
  struct Result {
    Real step = 0.0;  ///< the elements' smallest step after the new factors (time, before TSSFAC)
    const ElementBlock* controlling = nullptr;  ///< the block that has it
    Real kinetic_change = 0.0;  ///< sum over the nodes of 1/2 (m_new - m_old) |v|^2 (energy)
    Real added = 0.0;           ///< the total mass added now
  };

  bool active() const { return active_; }

  /// At the start, once the blocks lumped their physical masses into `nodes.mass` (and rotary
  /// inertias into `nodes.rot_inertia`) and `slots` (the corner gather lists of `corner_count`
  /// force slots) and `moment_slots` (of `moment_count` moment slots; unused when 0) are built:
  /// enables every block that bounds the step (ElementBlock::enable_mass_rescaling; the others,
  /// rigid parts, keep their mass), sets the factors from the reference steps and rebuilds the
  /// masses. `parts[k]` (one per block, its physical mass set) gets block k's added mass.
  /// `moment_slots` must outlive this object unchanged.
  void initialize(ElementBlocks& blocks, NodalFields& nodes, const NodeSlots& slots, Index corner_count,
                  const NodeSlots& moment_slots, Index moment_count, Real dt2ms, std::vector<PartAddedMass>& parts);

  /// After the element forces at the current state: re-evaluates the factors from the steps the
  /// blocks just computed (`at_reference`: from their reference steps), rebuilds `nodes.mass` and
  /// updates `parts`; `block_steps` (one per block, may be empty) gets each rescaled block's
  /// smallest step after its new factors.
  Result rescale(ElementBlocks& blocks, NodalFields& nodes, const NodeSlots& slots, bool at_reference,
                 std::vector<PartAddedMass>& parts, std::span<Real> block_steps = {});

  /// Body loads act on the mass of their parts, added mass included (as with MS1ST = 1): from now
  /// on rescale() also rebuilds `loads[l].mass` (resolved by then: nodes and physical masses) from
  /// the corner shares of the loaded rescaled blocks. `loads` must outlive this object unchanged.
  void attach_body_loads(std::vector<BodyLoad>& loads, const ElementBlocks& blocks, const NodeSlots& slots);

  /// The nodes whose mass the rescaled blocks change (sorted, unique).
  std::span<const Index> scaled_nodes() const { return scaled_nodes_; }

 private:
  bool active_ = false;
  Real dt2ms_ = 0.0;
  std::vector<std::size_t> blocks_;   ///< indices of the rescaled blocks
  std::vector<Real> base_mass_;       ///< per node, the physical mass
  std::vector<Real> corner_added_;    ///< per force slot, the mass its element adds to its node
  // Rotary inertia (blocks with moments, shells): per node the physical one, per moment slot the
  // inertia its element adds; empty without moment slots.
  std::vector<Real> base_inertia_, corner_inertia_;
  const NodeSlots* moment_slots_ = nullptr;
  std::vector<Real> chunk_dk_;        ///< per node chunk, sum of 1/2 dm |v|^2
  // Body loads: per load, per loaded node, its physical mass and (CSR) its slots in loaded blocks.
  struct LoadMasses {
    std::vector<Real> base;
    std::vector<Index> offset, slot;
  };
  std::vector<BodyLoad>* loads_ = nullptr;
  std::vector<LoadMasses> load_masses_;
  std::vector<Index> scaled_nodes_;
};

}  // namespace slideline
