#pragma once
/// Explicit central-difference time integration of a model of element blocks, loads, supports,
/// damping and contact interfaces.
///
/// One cycle is a flat sequence of named phases (see step()):
///   accelerations -> contact constraints -> support reactions -> velocities (damped) ->
///   energy balance -> output on its cadence -> positions -> time -> forces at the new time
///   (element blocks, body loads, contact forces) and the next stable step.
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "slideline/contact/contact_interface.hpp"
#include "slideline/core/types.hpp"
#include "slideline/element/element_block.hpp"
#include "slideline/io/output_sink.hpp"
#include "slideline/mesh/corner_buffer.hpp"
#include "slideline/mesh/mesh_sets.hpp"
#include "slideline/mesh/nodal_fields.hpp"
#include "slideline/solver/boundary.hpp"

namespace slideline {

struct SimulationControls {
  Real end_time = 0.0;
  Real dt_scale = 0.9;          ///< time-step scale factor applied to the stable element step
  Real dt_max = 0.0;            ///< upper bound on the step (0 = none)
  Real history_interval = 0.0;  ///< 0 = histories at every cycle
  Real state_interval = 0.0;    ///< 0 = no nodal states
  long max_cycles = 0;          ///< 0 = no limit
};

/// Energies at the last recorded time (all in force x length).
struct EnergyReport {
  Real kinetic = 0.0;
  Real kinetic0 = 0.0;          ///< at t = 0
  Real internal = 0.0;          ///< stress work of the elements (strain energy for elastic bodies)
  Real hourglass = 0.0;         ///< work against hourglass forces
  Real bulk_viscosity = 0.0;    ///< work against bulk viscosity
  Real damping = 0.0;           ///< work dissipated by mass damping
  Real external = 0.0;          ///< work of body loads and contact forces
  Real support = 0.0;           ///< work of prescribed motions on the body
  /// Work of the forces that NodalConstraints (rigid bodies) apply to their nodes: the forces that
  /// keep a body rigid and hold its fixed dofs, and the velocity reset after the position update.
  Real constraint = 0.0;
  /// (kinetic + internal + hourglass + bulk viscosity + damping)
  ///   - (kinetic0 + external + support + constraint)
  Real balance_error() const {
    return kinetic + internal + hourglass + bulk_viscosity + damping - kinetic0 - external -
           support - constraint;
  }
  /// balance_error() relative to the largest energy in play.
  Real relative_balance_error() const;
};

/// A hook that moves nodes together as a rigid body or otherwise constrains them. Called in the
/// order: after_forces (forces at t^n are complete) and after_positions (x^{n+1} set).
class NodalConstraint {
 public:
  virtual ~NodalConstraint() = default;
  virtual void initialize(NodalFields& nodes) = 0;
  /// Replaces the accelerations of the constrained nodes (and may record forces).
  virtual void constrain_accelerations(NodalFields& nodes, Real t) = 0;
  /// Corrects positions and velocities after the position update.
  virtual void after_positions(NodalFields& nodes, Real t) = 0;
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

class Simulation {
 public:
  NodalFields nodes;
  std::vector<std::unique_ptr<ElementBlock>> blocks;
  std::vector<std::unique_ptr<NodalConstraint>> constraints;  ///< rigid parts
  std::vector<std::unique_ptr<ContactInterface>> contacts;
  std::vector<BodyLoad> body_loads;
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

  Real time() const { return t_; }
  long cycle() const { return cycle_; }
  Real dt() const { return dt_; }
  Real stable_dt() const { return dt_crit_; }
  const EnergyReport& energy() const { return energy_; }
  /// Total element count over all blocks.
  Index element_count() const;
  /// The channel list the simulation records (valid after initialize()).
  const std::vector<HistoryChannel>& channels() const { return channels_; }
  MeshDescription mesh_description() const;
  /// Wall-clock seconds spent in element force evaluation and in contact, for the run summary.
  Real element_seconds() const { return element_seconds_; }
  Real contact_seconds() const { return contact_seconds_; }

 private:
  void compute_forces();            // f_int, f_ext at t_, dt_crit_
  void form_accelerations();
  void update_damping_coefficients();
  void compute_reactions_and_velocities(Real dt_avg, Real dt_new);
  void update_positions(Real dt_new);
  Real constrained_kinetic_energy() const;
  void collect_history(std::vector<Real>& values) const;
  Real next_output_time(Real interval, Real last) const;
  void write_outputs(const std::vector<OutputSink*>& sinks, bool force);

  CornerBuffer corners_;
  std::vector<Real> alpha_;            // per-node damping coefficient
  std::vector<std::uint8_t> fixed_[3];  // per axis: 1 if a support prescribes this component
  std::vector<std::uint8_t> fixed_rot_[3];  // per axis: 1 if a support fixes this rotation
  std::vector<std::uint8_t> constrained_;   // 1 if a NodalConstraint dictates the node's motion
  std::vector<Index> constrained_nodes_;   // the same nodes as a list, in order of first mention
  std::vector<std::size_t> constraint_outputs_;  // history values each constraint writes
  std::vector<Real> chunk_e_;          // energy partial sums, kEnergyTerms per chunk
  std::vector<Real> history_values_;
  std::vector<Real> state_values_;
  std::vector<HistoryChannel> channels_;
  EnergyReport energy_;
  Real t_ = 0.0;
  Real dt_ = 0.0;        // last step t^{n} - t^{n-1}
  Real dt_crit_ = 0.0;   // stable step at t^n (unscaled)
  long cycle_ = 0;
  Real last_history_ = -1.0;
  Real last_state_ = -1.0;
  Real stress_work_ = 0.0;    // committed work sums (see compute_reactions_and_velocities)
  Real external_work_ = 0.0;
  Real damping_work_ = 0.0;
  Real support_work_ = 0.0;
  Real constraint_work_ = 0.0;
  const std::vector<OutputSink*>* sinks_ = nullptr;
  bool initialized_ = false;
  bool finished_ = false;
  bool has_damping_curves_ = false;
  bool has_rotations_ = false;  // any node carries rotations (then m_ext is cleared each step)
  Real element_seconds_ = 0.0;
  Real contact_seconds_ = 0.0;
};

}  // namespace slideline
