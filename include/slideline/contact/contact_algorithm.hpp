#pragma once
/// The plug-in point for contact: one final class per interface type implements ContactAlgorithm
/// (what every family offers) and one role interface (its family's hooks). The simulation calls a
/// few virtual functions per interface and cycle (none per node), through the ContactManager, in
/// the phases of docs/solver.md:
///
///   apply_contact_forces:  ContactForces::apply_forces          (penalty, tiebreak)
///   apply_constraints:     KinematicTie::condense               (ties: slave mass and force -> masters)
///                          ContactConstraint::enforce           (Lagrange multipliers at x^{n+1})
///   update_velocities:     KinematicTie::follow_velocities      (ties: slave velocity from the masters)
///   update_positions:      KinematicTie::follow_positions       (ties: slave position from the masters)
///
/// An interface reads the nodal state through const references and writes only its own force
/// buffer (f_contact, m_contact), or, for constraint interfaces, the accelerations, velocities and
/// positions of the nodes it owns. It owns all of its state (candidates, gaps, sticking points,
/// failure flags), allocated in initialize() or on a re-search, never per cycle.
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "slideline/contact/element_steps_view.hpp"
#include "slideline/core/diagnostics.hpp"
#include "slideline/core/types.hpp"
#include "slideline/mesh/nodal_fields.hpp"

namespace slideline {

class ElementBlock;
struct MeshSets;

/// Times of the cycle being taken, from t^n to t^{n+1} = t + dt_next.
struct StepTimes {
  Real t = 0.0;        ///< t^n
  Real dt_prev = 0.0;  ///< t^n - t^{n-1} (0 on the first cycle)
  Real dt_avg = 0.0;   ///< velocity step (dt_prev + dt_next) / 2 (dt_next / 2 on the first cycle)
  Real dt_next = 0.0;  ///< t^{n+1} - t^n
  long cycle = 0;
  /// The run's initial step: the time-step scale factor (TSSFAC) x the elements' stable step at
  /// t = 0 (time); 0 where the driver does not know it. SOFT = 1 sizes its springs by it.
  Real dt_initial = 0.0;
  /// Per node, 1 / dt_e^2 of its elements at this cycle's force evaluation (element_steps_view.hpp):
  /// each spring's step vote adds it to its own (1 / dt^2 = 1 / dt_e^2 + 1 / dt_c^2). Empty where
  /// the driver does not give it (and with SimulationControls::contact_step_with_elements off):
  /// the springs vote alone.
  ElementStepsView element_steps{};
};

/// What an interface may look at when it initialises (after masses are lumped, before the first
/// force evaluation).
struct ContactContext {
  const NodalFields& nodes;
  const std::vector<std::unique_ptr<ElementBlock>>& blocks;
  const MeshSets* sets = nullptr;       ///< the deck's sets resolved to indices (may be null)
  std::span<const std::uint8_t> rigid;  ///< per node: 1 if a rigid body dictates its motion
  DiagnosticSink* diagnostics = nullptr;  ///< where the interface's warnings go (null: dropped)
};

/// The contact force buffers (zeroed by the simulation before the phase).
struct ContactForceView {
  Vec3Field& force;   ///< f_contact
  Vec3Field& moment;  ///< m_contact
};

/// Kinematic ties move the mass and force of each slave node onto its master nodes here.
struct CondenseView {
  std::span<Real> mass;         ///< effective translational mass (starts as NodalFields::mass)
  Vec3Field& force;             ///< total force (starts as f_int + f_ext + f_contact)
  std::span<Real> rot_inertia;  ///< effective rotary inertia (starts as NodalFields::rot_inertia)
  Vec3Field& moment;            ///< total moment
};

/// The Lagrange-multiplier phase: accelerations at t^n are formed and every other constraint
/// (ties, rigid bodies, supports) has acted. A node component is immovable for the solve when
/// `fixed[c][i]` (prescribed by a support) or `rigid[i]`; the simulation re-runs the rigid bodies
/// with the contact forces afterwards. The velocity update that follows is
///   v^{n+1/2} = ((1 - h) v^{n-1/2} + dt_avg a) / (1 + h),  h = damping[i] dt_avg / 2,
/// and x^{n+1} = x^n + dt_next v^{n+1/2}. An interface that changes the contact force on a node
/// by df adds df to f_contact and to force, and, on a movable component, df / mass to a.
struct ConstraintView {
  const NodalFields& nodes;       ///< x^n, v^{n-1/2}, omega
  std::span<const Real> mass;     ///< effective mass
  std::span<const Real> damping;  ///< mass-damping coefficient per node (1/time)
  std::span<const std::uint8_t> fixed[3];
  std::span<const std::uint8_t> rigid;
  Vec3Field& a;
  Vec3Field& force;  ///< total force
  Vec3Field& f_contact;
};

/// Penalty-type forces at t^n (penalty interfaces, tiebreaks): the apply_contact_forces phase.
class ContactForces {
 public:
  /// Penalty and friction forces at t^n (x^n, v^{n-1/2}) added into `out`.
  virtual void apply_forces(const NodalFields& nodes, const StepTimes& times, ContactForceView out) = 0;
  /// Once, right after initialize() and before the first step: move the nodes the interface found
  /// below its surface at t = 0 out to it (LS-DYNA's IGNORE = 0), x and x0 together so that no
  /// element starts strained. Default: nothing (penetrations, if any, stay the interface's business).
  virtual void resolve_initial_penetrations(NodalFields& /*nodes*/) {}

 protected:
  ~ContactForces() = default;
};

/// Lagrange multipliers (Types 3, 5, 10, 12 _LAGRANGE, Type 1): the apply_constraints phase.
class ContactConstraint {
 public:
  virtual void enforce(ConstraintView view, const StepTimes& times) = 0;

 protected:
  ~ContactConstraint() = default;
};

/// Kinematic ties (Types 2, 6, 7): slave mass and force condensed onto the masters, slave motion
/// following them. The simulation keeps effective mass arrays apart from NodalFields::mass while
/// an interface with this role is active.
class KinematicTie {
 public:
  virtual void condense(const NodalFields& nodes, CondenseView view) = 0;
  /// After the velocity update: tied slaves take the velocity of their master point.
  virtual void follow_velocities(NodalFields& nodes) = 0;
  /// After the position update (and after rigid bodies reset their nodes).
  virtual void follow_positions(NodalFields& nodes) = 0;
  /// Nodes whose motion the tie dictates (its slaves): the simulation books the work of the forces
  /// that move them to the contact term.
  virtual std::span<const Index> dictated_nodes() const = 0;
  /// Nodes that receive condensed slave mass and force (its masters): the simulation books the
  /// work of the tie forces on them to the contact term.
  virtual std::span<const Index> tie_master_nodes() const = 0;

 protected:
  ~KinematicTie() = default;
};

/// The phases an interface takes part in: each family implements one role (null for the others).
struct ContactPhases {
  ContactForces* forces = nullptr;
  ContactConstraint* constraint = nullptr;
  KinematicTie* tie = nullptr;
};

/// What every interface family offers; the family-specific hooks are behind phases().
class ContactAlgorithm {
 public:
  virtual ~ContactAlgorithm() = default;

  /// Output title (deck heading, else "contact_<id>").
  virtual const std::string& name() const = 0;
  /// Once, after masses are lumped and before the first force evaluation (at birth).
  virtual void initialize(const ContactContext& context) = 0;
  /// The roles this interface plays; the same pointers for the interface's lifetime.
  virtual ContactPhases phases() = 0;

  /// Largest step this interface allows (penalty springs), before the global scale factor.
  virtual Real stable_dt() const { return std::numeric_limits<Real>::max(); }
  /// Total force on the slave side and on the master side (summed where added to master nodes).
  virtual Vec3 slave_force() const = 0;
  virtual Vec3 master_force() const = 0;
  /// Energy dissipated by friction so far (>= 0), for the energy ledger's friction term.
  virtual Real friction_work() const { return 0.0; }
  /// Extra 3-vector history channels, named relative to interfaces/<name>/ (e.g.
  /// "transmitted_force"); values written 3 per name into a preallocated span.
  virtual void append_output_names(std::vector<std::string>& /*names*/) const {}
  virtual void write_output_values(std::span<Real> /*out*/) const {}

  /// True when the interface condenses tied slaves onto masters (a KinematicTie).
  bool condenses() const { return tie() != nullptr; }
  /// KinematicTie::dictated_nodes(), empty for the other families.
  std::span<const Index> dictated_nodes() const {
    const KinematicTie* t = tie();
    return t ? t->dictated_nodes() : std::span<const Index>{};
  }
  /// KinematicTie::tie_master_nodes(), empty for the other families.
  std::span<const Index> tie_master_nodes() const {
    const KinematicTie* t = tie();
    return t ? t->tie_master_nodes() : std::span<const Index>{};
  }

 private:
  const KinematicTie* tie() const { return const_cast<ContactAlgorithm*>(this)->phases().tie; }
};

}  // namespace slideline
