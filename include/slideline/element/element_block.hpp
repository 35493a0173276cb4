#pragma once
/// The interface every element block (hexahedra, shells, rigid parts' elements) implements.
/// A block holds elements of one part: one formulation, one material, one section.
#include <algorithm>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "slideline/core/error.hpp"
#include "slideline/core/parallel.hpp"

#include "slideline/core/types.hpp"
#include "slideline/element/cell_output.hpp"
#include "slideline/element/element_erosion.hpp"
#include "slideline/element/element_mass_scaling.hpp"
#include "slideline/mesh/corner_buffer.hpp"
#include "slideline/mesh/mesh_block.hpp"
#include "slideline/mesh/nodal_fields.hpp"

namespace slideline {

/// Energy rates an element block reports for one force evaluation.
struct BlockEnergy {
  Real internal = 0.0;   ///< stored strain energy, where the material has one (else 0)
  Real hourglass_power = 0.0;  ///< rate of work done against hourglass forces
  Real viscous_power = 0.0;    ///< rate of work done against bulk viscosity
  /// Rate of work done against stiffness-proportional (Rayleigh) damping stresses,
  /// V beta D : C : D >= 0 summed over the elements (force x length / time).
  Real damping_power = 0.0;
  /// Rate of work of all the element forces, -sum f . v over the corners (stress, hourglass, bulk
  /// viscosity and damping together; moments with angular velocities for shells). Its part net of
  /// the three powers above is the rate of the stored (internal) energy, per part for the
  /// hourglass and negative-energy checks (solver/part_energy_monitor.hpp).
  Real element_power = 0.0;
  /// Element erosion (element_erosion.hpp): the energies (force x length, not rates) that the
  /// elements deleted at this evaluation held, stress work and hourglass work, and their number.
  Real eroded_internal = 0.0;
  Real eroded_hourglass = 0.0;
  Index eroded_elements = 0;

  BlockEnergy& operator+=(const BlockEnergy& o) {
    internal += o.internal;
    eroded_internal += o.eroded_internal;
    eroded_hourglass += o.eroded_hourglass;
    eroded_elements += o.eroded_elements;
    hourglass_power += o.hourglass_power;
    viscous_power += o.viscous_power;
    damping_power += o.damping_power;
    element_power += o.element_power;
    return *this;
  }
};

/// The plasticity of a block at an output time, for the history channels of its part
/// (docs/output.md, "History channels").
struct PlasticityTotals {
  Real max_plastic_strain = 0.0;  ///< largest effective plastic strain of its integration points
  Real plastic_work = 0.0;        ///< plastic work of its elements (force x length)

  /// Combines two blocks of one part: the larger strain, the sum of the works.
  PlasticityTotals& operator+=(const PlasticityTotals& o) {
    max_plastic_strain = std::max(max_plastic_strain, o.max_plastic_strain);
    plastic_work += o.plastic_work;
    return *this;
  }
};

/// Reduces the per-chunk results of an element loop in chunk order (so the result does not depend
/// on the thread count): throws InstabilityError naming the first bad element (`bad[c] >= 0` is an
/// element index; `ids` maps it to the deck id), adds the hourglass, bulk-viscosity and
/// stiffness-damping powers to `energy`, and returns the smallest element step.
inline Real reduce_element_chunks(const std::vector<Real>& dt, const std::vector<Real>& hourglass,
                                  const std::vector<Real>& viscous, const std::vector<Real>& damping,
                                  const std::vector<Real>& power, const std::vector<Index>& bad,
                                  BlockEnergy& energy,
                                  const char* kind, const std::vector<Id>& ids, Id part,
                                  const char* failure) {
  for (Index b : bad)
    if (b >= 0)
      throw InstabilityError(std::string(kind) + " element " + std::to_string(ids[b]) + " of part " +
                                 std::to_string(part) + " " + failure,
                             0.0, 0);
  energy.hourglass_power += ordered_sum(hourglass, 0.0);
  energy.viscous_power += ordered_sum(viscous, 0.0);
  energy.damping_power += ordered_sum(damping, 0.0);
  energy.element_power += ordered_sum(power, 0.0);
  Real dtmin = std::numeric_limits<Real>::max();
  for (Real d : dt) dtmin = std::min(dtmin, d);
  return dtmin;
}

/// Index of the first chunk with the smallest step (chunk order, so thread-count independent).
inline std::size_t argmin_chunk(const std::vector<Real>& dt) {
  std::size_t k = 0;
  for (std::size_t c = 1; c < dt.size(); ++c)
    if (dt[c] < dt[k]) k = c;
  return k;
}

/// An element block: the mesh's view of it (MeshBlock: part, connectivity, topology, ids) plus
/// the element formulation (mass, forces, time step).
class ElementBlock : public MeshBlock {
 public:
  ~ElementBlock() override = default;

  /// True when the block writes corner moments (its nodes carry rotations).
  virtual bool has_moments() const { return false; }
  /// True when the block's hourglass control is a stiffness (IHQ 4-6, 10): its trapezoidal work is
  /// then a stored energy that cannot go negative unless the control creates energy. A viscous
  /// control's work can dip below zero for a while after a kick (its force lags the velocity by
  /// half a step), so the negative-hourglass stop judges stiffness forms only.
  virtual bool stiffness_hourglass() const { return false; }
  /// False for blocks whose step only matters when nothing else bounds it (rigid parts: as in
  /// LS-DYNA, rigid elements do not set the step of a model with deformable elements).
  virtual bool bounds_time_step() const { return true; }
  /// Deck id of the element whose stable step was the smallest at the last compute_forces
  /// (for messages when the step collapses); -1 when the block has no step of its own.
  virtual Id smallest_step_element() const { return -1; }

  /// Computes reference element data and adds this block's lumped mass (and rotary inertia) to
  /// the nodes. Called once, before the first step.
  virtual void initialize(NodalFields& nodes) = 0;

  /// Mass scaling (solver/mass_scaling.hpp): each element's stable step (before any scale factor)
  /// at the reference geometry at rest, as compute_forces would vote it there, into `out`
  /// (element_count() entries, time). A block without a step of its own writes +max.
  virtual void reference_steps(const NodalFields& /*nodes*/, std::span<Real> out) const {
    std::fill(out.begin(), out.end(), std::numeric_limits<Real>::max());
  }

  /// Mass scaling: multiplies the mass (and rotary inertia) element e lumps to its nodes by
  /// factor[e] > 0, adding the difference to `nodes`, and the stable step it votes from now on by
  /// sqrt(factor[e]). Called once, after initialize(). Returns the mass added (negative where mass
  /// was removed). A block that cannot scale (no step of its own) accepts only factors of 1.
  virtual Real scale_element_masses(std::span<const Real> factor, NodalFields& /*nodes*/) {
    for (Real f : factor)
      if (f != 1.0) throw NotImplementedError("part " + std::to_string(part_id()) + ": mass scaling of " + kind() +
                                              " elements is not implemented");
    return 0.0;
  }

  /// Mass scaling every cycle (MS1ST = 0; element_mass_scaling.hpp): from now on compute_forces
  /// keeps each element's stable step before any factor. Called once, after initialize(), instead
  /// of scale_element_masses. A block that cannot (no step of its own, or not implemented) refuses.
  virtual void enable_mass_rescaling() {
    throw NotImplementedError("part " + std::to_string(part_id()) + ": mass scaling re-evaluated every cycle "
                              "(DT2MS with MS1ST = 0 of *CONTROL_TIMESTEP) of " + kind() +
                              " elements is not implemented (MS1ST = 1 scales them once, at the start)");
  }
  /// MS1ST = 0: re-evaluates every element's factor mass_scale_factor(dt_e, dt2ms) from its step
  /// dt_e at the last compute_forces (`at_reference`: from reference_steps instead, at the start),
  /// writes the mass each element adds to each of its corners (its physical mass / corners x
  /// (factor - 1)) into `corner_added` (the block's own corner slots, from 0) and, for a block with
  /// moments, the rotary inertia it adds (its lumped rotary inertia per corner x (factor - 1)) into
  /// `corner_inertia` (its own moment slots, from 0; empty for a block without moments), and
  /// multiplies the step it votes from the next compute_forces on by sqrt(factor). Allocates
  /// nothing.
  virtual RescaledBlock rescale_element_masses(Real /*dt2ms*/, bool /*at_reference*/, const NodalFields& /*nodes*/,
                                               std::span<Real> /*corner_added*/, std::span<Real> /*corner_inertia*/) {
    throw NotImplementedError("part " + std::to_string(part_id()) + ": mass scaling every cycle is not implemented");
  }

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

  /// The output values of every element at the current state (`out`: element_count() entries, in
  /// element order), for the state output; not called inside a step. A block without stresses
  /// (a rigid part) reports zeros.
  virtual void cell_outputs(const NodalFields& /*nodes*/, std::span<CellOutput> out) const {
    std::fill(out.begin(), out.end(), CellOutput{});
  }

  /// True when the block's law has an effective plastic strain and a plastic work (the J2 laws,
  /// material/j2_plasticity.hpp, piecewise_plasticity.hpp, shell_plasticity.hpp): its part gets
  /// the plastic history channels.
  virtual bool has_plasticity() const { return false; }

  /// At an output time (not inside a step; allocates nothing, sums in element order): the largest
  /// effective plastic strain of the block's integration points and its plastic work, the sum over
  /// the points of the law's plastic work density (per unit current volume, accumulated increment
  /// by increment) times the point's share of the element's current volume. Zero for a block
  /// without plasticity.
  virtual PlasticityTotals plasticity_totals(const NodalFields& /*nodes*/) const { return {}; }

  /// Element erosion (element_erosion.hpp): deletes the elements that meet `criteria`
  /// (erosion_criteria.hpp; at least one set). Called once, before the first step. A block that
  /// cannot erode, or not by one of the criteria, refuses (NotImplementedError).
  virtual void enable_erosion(const ErosionCriteria& criteria) {
    (void)criteria;
    throw NotImplementedError("part " + std::to_string(part_id()) + ": element erosion of " + kind() +
                              " elements is not implemented");
  }
  /// The block's erosion bookkeeping; null for a block that cannot erode.
  virtual const ElementErosion* erosion() const { return nullptr; }
  ElementErosion* erosion() { return const_cast<ElementErosion*>(std::as_const(*this).erosion()); }

  /// Shells: the thickness follows the membrane strain (*CONTROL_SHELL ISTUPD; `mode` 1: the whole
  /// normal strain of plane stress, 4: its plastic part alone). Called once, before initialize().
  /// A block without a thickness refuses (NotImplementedError).
  virtual void enable_thickness_update(int mode) {
    throw NotImplementedError("part " + std::to_string(part_id()) + ": a thickness change (*CONTROL_SHELL ISTUPD = " +
                              std::to_string(mode) + ") of " + kind() + " elements is not implemented");
  }
  /// Per element, the current thickness (length) of a block whose thickness changes
  /// (enable_thickness_update); empty: it does not change (BlockTopology's section thickness).
  virtual std::span<const Real> current_thickness() const { return {}; }

  /// Deck id of the block's material (*PART MID), for the output; 0 when not set.
  Id material_id() const { return material_id_; }
  void set_material_id(Id mid) { material_id_ = mid; }

 protected:
  Index force_base_ = 0;
  Index moment_base_ = 0;
  Id material_id_ = 0;
};

/// The blocks of a model, in the order their segments and output cells are listed.
using ElementBlocks = std::vector<std::unique_ptr<ElementBlock>>;

}  // namespace slideline
