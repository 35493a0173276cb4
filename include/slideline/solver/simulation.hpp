#pragma once
/// Explicit central-difference time integration of a model of element blocks, loads, supports,
/// damping, rigid bodies and contact interfaces.
///
/// One cycle (t^n -> t^{n+1}) is a flat sequence of named phases over small owned parts (see
/// step(), docs/solver.md and docs/architecture.md, "The time step"):
///   plan_step -> check_step -> form_accelerations -> apply_constraints -> update_velocities
///   (+ tied slaves, energy audit) -> check_energy -> record -> advance -> assemble_forces
/// The forces at t^{n+1} and the stable step they vote for come out of assemble_forces() as a value.
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "slideline/contact/contact_manager.hpp"
#include "slideline/core/diagnostics.hpp"
#include "slideline/core/types.hpp"
#include "slideline/element/element_block.hpp"
#include "slideline/mesh/corner_buffer.hpp"
#include "slideline/mesh/mesh_sets.hpp"
#include "slideline/mesh/nodal_fields.hpp"
#include "slideline/solver/boundary.hpp"
#include "slideline/solver/central_difference.hpp"
#include "slideline/solver/energy_ledger.hpp"
#include "slideline/solver/exchange.hpp"
#include "slideline/solver/mass_rescaling.hpp"
#include "slideline/solver/mass_scaling.hpp"
#include "slideline/solver/nodal_element_steps.hpp"
#include "slideline/solver/nodal_constraint.hpp"
#include "slideline/solver/node_roles.hpp"
#include "slideline/solver/output_recorder.hpp"
#include "slideline/solver/output_sink.hpp"
#include "slideline/solver/part_energy_monitor.hpp"
#include "slideline/solver/simulation_controls.hpp"
#include "slideline/solver/simulation_setup.hpp"
#include "slideline/solver/stability_monitor.hpp"

namespace slideline {

class Simulation {
 public:
  /// A simulation of `setup` (simulation_setup.hpp: the mesh, blocks, loads, supports, contact
  /// interfaces and controls), which it owns from here on. Its exchange points (exchange.hpp: the
  /// force gather, the dt reduction, the energy sums) go through `exchange`, e.g. a distributed
  /// run's; null means one process. Nothing is computed here: initialize() starts the run.
  explicit Simulation(SimulationSetup setup, std::unique_ptr<Exchange> exchange = nullptr);

  // What the simulation was set up with, as it is now (positions, velocities, reactions, contact
  // state change as it runs). Read-only: the setup is changed before construction.
  const NodalFields& nodes() const { return nodes_; }
  const std::vector<std::unique_ptr<ElementBlock>>& blocks() const { return blocks_; }
  const std::vector<std::unique_ptr<NodalConstraint>>& constraints() const { return constraints_; }  ///< rigid parts
  const ContactManager& contacts() const { return contacts_; }
  const std::vector<BodyLoad>& body_loads() const { return body_loads_; }
  const std::vector<NodalLoad>& nodal_loads() const { return nodal_loads_; }
  /// The support groups, with the reaction each carried at the last step.
  const std::vector<SupportGroup>& supports() const { return supports_; }
  const std::vector<MassDamping>& damping() const { return damping_; }
  const std::vector<Index>& history_nodes() const { return history_nodes_; }  ///< recorded displacements
  const MeshSets& sets() const { return sets_; }
  const SimulationControls& controls() const { return controls_; }

  // Steering between cycles, for a driver that decides from the stable step once the run has
  // started (tests/verification/test_shell_stability.cpp lands every step on its output times).
  // Everything else is set in the SimulationSetup before construction.
  void set_end_time(Real t) { controls_.end_time = t; }
  void set_dt_max(Real dt) { controls_.dt_max = dt; }  ///< 0 = no cap
  void set_history_interval(Real dt) { controls_.history_interval = dt; }

  /// Computes masses, builds the corner gather lists, evaluates the forces at t = 0 and the first
  /// stable step. Call once after construction (step() and run() call it if it was not).
  void initialize();

  /// Where warnings go (build_simulation sets it from BuildOptions::diagnostics; null, the
  /// default, drops them): the contact interfaces get it at initialize().
  void set_diagnostics(DiagnosticSink* sink) { diagnostics_ = sink; }

  /// Advances one cycle. Returns false when the end time or cycle limit was reached.
  bool step();

  /// Runs to the end time, writing to the sinks. `progress` (may be empty) is called about every
  /// `progress_every` cycles. On an instability the sinks are flushed and the error rethrown with
  /// the time and cycle.
  void run(const std::vector<OutputSink*>& sinks,
           const std::function<void(const Simulation&)>& progress = {}, long progress_every = 100);

  /// The step the next cycle will take (scaled stable step, dt_max, landing on output and end
  /// times). The CLI's progress line uses it too.
  StepPlan plan_step() const;

  Real time() const { return t_; }
  long cycle() const { return cycle_; }
  Real dt() const { return dt_; }
  Real stable_dt() const { return votes_.stable(); }
  /// The votes of the last force evaluation (elements and contact, before TSSFAC).
  const StepVotes& votes() const { return votes_; }
  const EnergyReport& energy() const { return ledger_.report(); }
  /// Total element count over all blocks.
  Index element_count() const;
  /// The channel list the simulation records (valid after initialize()).
  const std::vector<HistoryChannel>& channels() const { return recorder_.channels(); }
  MeshDescription mesh_description() const;
  /// Wall-clock seconds spent in element force evaluation and in contact, for the run summary.
  Real element_seconds() const { return element_seconds_; }
  Real contact_seconds() const { return contact_seconds_; }
  /// Set once the energy balance error first passed controls.energy_error_warning.
  const std::optional<EnergyWarning>& energy_warning() const { return monitor_.energy_warning(); }
  /// Set once contact had created more than StabilityMonitor::kContactEnergyWarning of the largest
  /// energy in play (its forces did that much more work on the bodies than they took from them).
  const std::optional<EnergyWarning>& contact_energy_warning() const { return monitor_.contact_energy_warning(); }
  /// Parts whose hourglass energy passed 10% of their internal energy, in the order it happened
  /// (one entry per part at most; part_energy_monitor.hpp).
  const std::vector<HourglassWarning>& hourglass_warnings() const { return part_energy_.hourglass_warnings(); }
  /// What mass scaling (controls().dt2ms) did, one entry per element block (part), after
  /// initialize() and, with controls().mass_scaling_every_cycle (MS1ST = 0), as of the last force
  /// evaluation; empty without mass scaling.
  const std::vector<PartAddedMass>& added_mass() const { return added_mass_; }
  /// Internal and hourglass energy per part.
  const PartEnergyMonitor& part_energies() const { return part_energy_; }
  /// |balance error| over the largest energy in play so far (the quantity the limits apply to).
  Real energy_error_fraction() const { return monitor_.energy_error_fraction(ledger_.report()); }
  /// Effective translational mass (own + condensed tied slaves) used in the last cycle.
  std::span<const Real> effective_mass() const {
    return contacts_.condenses() ? std::span<const Real>(mass_eff_) : std::span<const Real>(nodes_.mass);
  }

 private:
  // initialize(), job by job.
  void check_controls() const;
  /// Masses lumped by the blocks and the corner gather lists; returns the mass each block lumps
  /// to each node (for the body loads).
  std::vector<std::vector<Real>> lump_masses();
  /// Mass scaling of one block just lumped (`before`: the nodal masses before it), into added_mass_.
  void scale_block_mass(ElementBlock& block, const std::vector<Real>& before);
  /// Refuses a model whose mass scaling added more than controls_.added_mass_limit_percent.
  void check_added_mass() const;
  /// MS1ST = 0: stops the run (InstabilityError, as DTMIN does) once the added mass passes it.
  void check_added_mass_in_run() const;
  /// MS1ST = 0: refuses what takes the nodal masses once (a rigid body sharing nodes with
  /// rescaled elements).
  void refuse_unsupported_rescaling() const;
  void check_nodal_moments() const;
  void resolve_body_loads(const std::vector<std::vector<Real>>& block_mass);
  void initialize_contacts();
  /// Throws NotImplementedError for a tied interface with BT or DT whose master nodes include a
  /// rigid body's (its mass properties take the tied slaves once).
  void refuse_timed_ties_on_rigid_bodies() const;
  void classify_contact_nodes();
  OutputSources output_sources() const;

  // Forces at t^n and the stable step they vote for (simulation_forces.cpp).
  StepVotes assemble_forces();
  /// Element forces gathered into f_int (m_int); returns the elements' vote and sets its block.
  Real compute_internal_forces(const ElementBlock*& controlling);
  void compute_external_forces();
  /// Penalty and friction forces into f_contact (m_contact); returns the interfaces' vote.
  Real apply_contact_forces();

  // The constraint phase (simulation_constraints.cpp), in the order apply_constraints documents.
  void apply_constraints(const StepPlan& plan);
  void condense_ties();
  void constrain_rigid_bodies(const StepPlan& plan);
  void prescribe_supports(const StepPlan& plan);
  void compute_reactions();
  ConstraintLoads constraint_loads() const;

  // The rest of a cycle.
  void update_damping_coefficients();
  VelocityStep velocity_step(const StepPlan& plan) const;
  /// The tied slaves' v^{n-1/2} and omega^{n-1/2}, before the velocity update.
  void remember_dictated_velocities();
  /// Tied slaves take their masters' velocities; returns their energy sums.
  NodalEnergySums follow_ties(const VelocityStep& vs);
  /// The cycle's energy sums (over all processes) into the ledger.
  void book_energies(NodalEnergySums sums);
  /// x^{n+1}, t^{n+1}; rigid bodies and ties reset their nodes.
  void advance(const StepPlan& plan);

  bool has_contact() const { return !contacts_.empty(); }

  // The setup (simulation_setup.hpp documents each), owned and advanced by the simulation.
  NodalFields nodes_;
  std::vector<std::unique_ptr<ElementBlock>> blocks_;
  std::vector<std::unique_ptr<NodalConstraint>> constraints_;
  ContactManager contacts_;
  std::vector<BodyLoad> body_loads_;  // initialize() resolves their nodes and masses
  std::vector<NodalLoad> nodal_loads_;
  std::vector<SupportGroup> supports_;  // the run writes their reactions
  std::vector<MassDamping> damping_;
  std::vector<Index> history_nodes_;
  MeshSets sets_;
  SimulationControls controls_;
  /// Where a distributed run exchanges data (exchange.hpp); one process here.
  std::unique_ptr<Exchange> exchange_;
  NodeRoles roles_;
  OutputRecorder recorder_;
  StabilityMonitor monitor_;
  EnergyLedger ledger_;
  PartEnergyMonitor part_energy_;
  std::vector<BlockEnergy> block_energy_;  // this cycle's element powers per block (exchange point 3)
  std::vector<Real> corner_power_chunks_;  // per chunk of a block's corners (CornerBuffer::power)
  // The contact springs' votes count the elements on their nodes (controls_.contact_step_with_elements):
  // each block's vote of this cycle, and per node the smallest of its blocks'.
  std::vector<Real> block_step_;
  NodalElementSteps element_steps_;
  CornerBuffer corners_;
  std::vector<Real> alpha_;              // per-node mass-damping coefficient
  std::vector<PartAddedMass> added_mass_;  // mass scaling per block (initialize; every cycle with MS1ST = 0)
  MassRescaling rescaling_;                // MS1ST = 0 (inactive otherwise)
  std::vector<Vec3> dictated_v_old_;     // the tied slaves' v^{n-1/2} (and omega) during a cycle
  std::vector<Vec3> dictated_w_old_;
  // Effective mass and total loads of the constraint phase (see ConstraintLoads). Without
  // condensing ties mass_eff_ is unused and effective_mass() is NodalFields::mass.
  std::vector<Real> mass_eff_;
  std::vector<Real> rot_inertia_eff_;
  Vec3Field f_total_;
  Vec3Field m_total_;
  std::vector<NodalEnergySums> chunk_e_;  // energy partial sums per chunk
  StepVotes votes_;  // the stable step the forces at t_ vote for
  Real last_vote_ = 0.0;  // the last finite stable vote (held once every element has eroded)
  Real t_ = 0.0;
  Real dt_ = 0.0;    // last step t^{n} - t^{n-1}
  Real dt_initial_ = 0.0;  // TSSFAC x the elements' stable step at t = 0 (StepTimes::dt_initial)
  long cycle_ = 0;
  bool initialized_ = false;
  DiagnosticSink* diagnostics_ = nullptr;
  bool finished_ = false;
  bool has_damping_curves_ = false;
  bool has_rotations_ = false;  // any node carries rotations (then moments are cleared each step)
  Real element_seconds_ = 0.0;
  Real contact_seconds_ = 0.0;
};

}  // namespace slideline
