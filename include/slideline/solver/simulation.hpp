#pragma once
/// Explicit central-difference time integration of a model of element blocks, loads, supports,
/// damping, rigid bodies and contact interfaces.
///
/// One cycle (t^n -> t^{n+1}) is a flat sequence of named phases (see step() and docs/solver.md):
///   compute_internal_forces -> compute_external_forces -> apply_contact_forces   (forces at t^n)
///   -> plan_step -> form_accelerations -> apply_constraints -> update_velocities
///   -> record_outputs -> update_positions
/// The constraint order inside apply_constraints is documented in docs/solver.md.
#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "slideline/contact/contact_manager.hpp"
#include "slideline/core/types.hpp"
#include "slideline/element/element_block.hpp"
#include "slideline/io/output_sink.hpp"
#include "slideline/mesh/corner_buffer.hpp"
#include "slideline/mesh/mesh_sets.hpp"
#include "slideline/mesh/nodal_fields.hpp"
#include "slideline/solver/boundary.hpp"
#include "slideline/solver/energy_ledger.hpp"
#include "slideline/solver/exchange.hpp"
#include "slideline/solver/nodal_constraint.hpp"
#include "slideline/solver/part_energy_monitor.hpp"

namespace slideline {

struct SimulationControls {
  Real end_time = 0.0;
  Real dt_scale = 0.9;          ///< time-step scale factor applied to the stable element step
  Real dt_max = 0.0;            ///< upper bound on the step (0 = none)
  /// Upper bound on the step against time (LS-DYNA LCTM of *CONTROL_TIMESTEP), when set.
  bool has_dt_max_curve = false;
  LoadCurve dt_max_curve;
  Real history_interval = 0.0;  ///< 0 = histories at every cycle
  Real state_interval = 0.0;    ///< 0 = no nodal states
  long max_cycles = 0;          ///< 0 = no limit
  /// Stop with an InstabilityError when |energy balance error| exceeds this fraction of the
  /// largest energy in play so far (0 = never). Checked from cycle kEnergyCheckStart on: before
  /// that the energies are round-off and their ratio means nothing.
  Real energy_error_limit = 0.05;
  /// Record a warning (Simulation::energy_warning) the first time the error exceeds this fraction.
  Real energy_error_warning = 0.01;
  /// Stop when the step falls below this fraction of the first step (LS-DYNA's DTMIN of
  /// *CONTROL_TERMINATION; 0 = never), naming the part whose elements control the step.
  Real dt_min_fraction = 1e-4;
};

/// The first cycle at which the energy balance is checked against the limits above.
inline constexpr long kEnergyCheckStart = 100;

/// The first time the energy balance error passed SimulationControls::energy_error_warning.
struct EnergyWarning {
  Real time = 0.0;
  long cycle = 0;
  Real relative_error = 0.0;
};

/// The step plan_step() decides for the coming cycle.
struct StepPlan {
  Real dt_next = 0.0;  ///< t^{n+1} - t^n
  Real dt_avg = 0.0;   ///< the velocity step (dt_prev + dt_next) / 2, dt_next / 2 on the first cycle
  Real t_next = 0.0;   ///< t^{n+1} (exactly the output or end time it lands on, if it lands)
  bool at_end = false; ///< the end time or cycle limit is reached: record and stop
};

class Simulation {
 public:
  NodalFields nodes;
  std::vector<std::unique_ptr<ElementBlock>> blocks;
  std::vector<std::unique_ptr<NodalConstraint>> constraints;  ///< rigid parts
  ContactManager contacts;
  std::vector<BodyLoad> body_loads;
  std::vector<NodalLoad> nodal_loads;
  std::vector<SupportGroup> supports;
  std::vector<MassDamping> damping;
  std::vector<Index> history_nodes;  ///< internal indices of nodes whose displacement is recorded
  MeshSets sets;  ///< the deck's node, part and segment sets, resolved (for contact)
  SimulationControls controls;

  /// Computes masses, builds the corner gather lists, evaluates the forces at t = 0 and the first
  /// stable step. Call once after filling the members above.
  void initialize();

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
  Real stable_dt() const { return dt_crit_; }
  const EnergyReport& energy() const { return ledger_.report(); }
  /// Total element count over all blocks.
  Index element_count() const;
  /// The channel list the simulation records (valid after initialize()).
  const std::vector<HistoryChannel>& channels() const { return channels_; }
  MeshDescription mesh_description() const;
  /// Wall-clock seconds spent in element force evaluation and in contact, for the run summary.
  Real element_seconds() const { return element_seconds_; }
  Real contact_seconds() const { return contact_seconds_; }
  /// Set once the energy balance error first passed controls.energy_error_warning.
  const std::optional<EnergyWarning>& energy_warning() const { return energy_warning_; }
  /// Parts whose hourglass energy passed 10% of their internal energy, in the order it happened
  /// (one entry per part at most; part_energy_monitor.hpp).
  const std::vector<HourglassWarning>& hourglass_warnings() const { return part_energy_.hourglass_warnings(); }
  /// Internal and hourglass energy per part.
  const PartEnergyMonitor& part_energies() const { return part_energy_; }
  /// |balance error| over the largest energy in play so far (the quantity the limits apply to).
  Real energy_error_fraction() const;
  /// Effective translational mass (own + condensed tied slaves) used in the last cycle.
  std::span<const Real> effective_mass() const {
    return contacts.condenses() ? std::span<const Real>(mass_eff_) : std::span<const Real>(nodes.mass);
  }

 private:
  // The phases of a cycle, in order.
  void compute_internal_forces();
  void compute_external_forces();
  void apply_contact_forces();
  void form_accelerations();
  void apply_constraints(const StepPlan& plan);
  void update_velocities(const StepPlan& plan);
  void record_outputs(bool force);
  void update_positions(const StepPlan& plan);

  // Pieces of the constraint phase.
  void condense_ties();
  void constrain_rigid_bodies(const StepPlan& plan);
  void prescribe_supports(const StepPlan& plan);
  void compute_reactions();
  void refresh_support_flags();
  void book_dictated_nodes(const StepPlan& plan);

  /// node_kind_ and dictated_nodes_ from the active contact interfaces (simulation_contacts.cpp).
  void classify_contact_nodes();
  void update_damping_coefficients();
  Real constrained_kinetic_energy() const;
  void collect_history(std::vector<Real>& values) const;
  Real next_output_time(Real interval, Real last) const;
  ConstraintLoads constraint_loads() const;
  void check_stability();
  std::string locate_non_finite() const;
  std::string describe_node(Index i) const;

  /// Where a distributed run exchanges data (exchange.hpp); one process here.
  std::unique_ptr<Exchange> exchange_ = std::make_unique<SingleProcessExchange>();
  CornerBuffer corners_;
  std::vector<Real> alpha_;             // per-node mass-damping coefficient
  std::vector<std::uint8_t> fixed_[3];  // per axis: 1 if a support prescribes this component
  std::vector<std::uint8_t> fixed_rot_[3];  // per axis: 1 if a support fixes this rotation
  /// Per node: who dictates its motion. kFree: the velocity update; kRigid: a NodalConstraint
  /// (work booked to `constraint`); kDictated: a contact tie sets its velocity (a tied slave);
  /// kTieMaster: the velocity update moves it with tied slave mass condensed onto it (the tie
  /// forces' work is booked to `contact`).
  enum NodeKind : std::uint8_t { kFree = 0, kRigid = 1, kDictated = 2, kTieMaster = 3 };
  std::vector<std::uint8_t> node_kind_;
  std::vector<std::uint8_t> rigid_;        // 1 if kRigid (a view for contact)
  std::vector<Index> constrained_nodes_;   // kRigid nodes, in order of first mention
  std::vector<Index> dictated_nodes_;      // kDictated nodes, ascending
  std::vector<Vec3> dictated_v_old_;       // their v^{n-1/2} (and omega) during a cycle
  std::vector<Vec3> dictated_w_old_;
  NodalEnergySums dictated_sums_;          // their energy sums in the current cycle
  std::vector<std::size_t> constraint_outputs_;  // history values each constraint writes
  std::vector<std::size_t> contact_outputs_;     // extra history values each interface writes
  // Effective mass and total loads of the constraint phase (see ConstraintLoads). Without
  // condensing ties mass_eff_ is unused and effective_mass() is NodalFields::mass.
  std::vector<Real> mass_eff_;
  std::vector<Real> rot_inertia_eff_;
  Vec3Field f_total_;
  Vec3Field m_total_;
  std::vector<NodalEnergySums> chunk_e_;  // energy partial sums per chunk
  std::vector<Real> history_values_;
  std::vector<Real> state_values_;
  std::vector<HistoryChannel> channels_;
  EnergyLedger ledger_;
  Real t_ = 0.0;
  Real dt_ = 0.0;        // last step t^{n} - t^{n-1}
  Real dt_crit_ = 0.0;   // stable step at t^n (unscaled)
  Real dt_elements_ = 0.0;  // the elements' part of dt_crit_
  long cycle_ = 0;
  Real last_history_ = -1.0;
  Real last_state_ = -1.0;
  const std::vector<OutputSink*>* sinks_ = nullptr;
  bool initialized_ = false;
  bool finished_ = false;
  bool forces_current_ = false;  // the forces at t_ are evaluated
  bool has_damping_curves_ = false;
  bool has_timed_supports_ = false;  // a support with BIRTH/DEATH: fixed_ is refreshed each cycle
  bool has_rotations_ = false;  // any node carries rotations (then moments are cleared each step)
  Real dt_first_ = 0.0;           // the first step taken (for dt_min_fraction)
  Real peak_energy_ = 0.0;         // largest energy in play so far
  Id dt_part_ = 0;                 // part whose elements set dt_elements_
  std::string dt_kind_;            // and their kind
  const ElementBlock* dt_block_ = nullptr;  // block whose element set dt_elements_ last
  /// "hex8 element 12 of part 3" or "contact interface 'x'": what sets the step now (messages).
  std::string step_controller() const;
  std::optional<EnergyWarning> energy_warning_;
  PartEnergyMonitor part_energy_;
  Real element_seconds_ = 0.0;
  Real contact_seconds_ = 0.0;
};

}  // namespace slideline
