#pragma once
/// The energy ledger: named energy terms and the trapezoidal work sums that feed them.
///
/// Works are integrated with the trapezoid rule over the nodal displacements of each cycle. The
/// velocity update at t^n knows the forces at t^n and both half-step velocities, so it computes the
/// work of each force over the half interval before t^n (x^n - x^{n-1/2}) and the half after it
/// (x^{n+1/2} - x^n): `WorkHalves`. The energy reported at t^n is the committed sum plus the half
/// before; the half after is committed for the next report.
#include <array>

#include "slideline/core/types.hpp"

namespace slideline {

/// Energies at the last recorded time (all in force x length).
struct EnergyReport {
  Real kinetic = 0.0;
  Real kinetic0 = 0.0;        ///< at t = 0
  Real internal = 0.0;        ///< stress work of the elements (strain energy for elastic bodies)
  Real hourglass = 0.0;       ///< work against hourglass forces
  Real bulk_viscosity = 0.0;  ///< work against bulk viscosity
  Real damping = 0.0;         ///< work dissipated by mass- and stiffness-proportional damping
  /// Contact: minus the work of the contact forces on the bodies, less the friction dissipation:
  /// the elastic energy stored in penalty springs (and the work of kinematic and Lagrange contact
  /// constraints, zero when they are exact).
  Real contact = 0.0;
  Real friction = 0.0;        ///< energy dissipated by friction (>= 0)
  Real external = 0.0;        ///< work of body loads
  Real support = 0.0;         ///< work of prescribed motions on the body
  /// Work of the forces that NodalConstraints (rigid bodies) apply to their nodes: the forces that
  /// keep a body rigid and hold its fixed dofs, and the velocity reset after the position update.
  Real constraint = 0.0;
  /// Element erosion (element/element_erosion.hpp): the stress work and the hourglass work that
  /// the deleted elements held when they were deleted, taken out of `internal` and `hourglass`
  /// (which are then those of the elements still in the model). 0 without erosion.
  Real eroded_internal = 0.0;
  Real eroded_hourglass = 0.0;
  /// The eroded energy, eroded_internal + eroded_hourglass.
  Real eroded() const { return eroded_internal + eroded_hourglass; }
  /// Mass scaling every cycle (MS1ST = 0; solver/mass_rescaling.hpp): the kinetic energy the mass
  /// changes put in, the sum over the changes of 1/2 (m_new - m_old) |v|^2 at the node's velocity
  /// when its mass changed (an input, as external work). 0 otherwise.
  Real mass_scaling = 0.0;

  /// (kinetic + internal + hourglass + bulk viscosity + damping + contact + friction + eroded)
  ///   - (kinetic0 + external + support + constraint + mass_scaling)
  Real balance_error() const {
    Real e = kinetic + internal + hourglass + bulk_viscosity + damping + contact + friction -
             kinetic0 - external - support - constraint;
    if (mass_scaling != 0.0) e -= mass_scaling;
    return eroded_internal == 0.0 && eroded_hourglass == 0.0 ? e : e + eroded();
  }
  /// balance_error() relative to the largest energy in play.
  Real relative_balance_error() const;

  /// The history channel names (energy/<name>) in output order, and their values.
  static constexpr std::array<const char*, 11> names{
      "kinetic",  "internal", "hourglass", "bulk_viscosity", "damping",      "contact",
      "friction", "external", "support",   "constraint",     "balance_error"};
  std::array<Real, 11> values() const {
    return {kinetic,  internal, hourglass, bulk_viscosity, damping,        contact,
            friction, external, support,   constraint,     balance_error()};
  }
};

/// The work of one kind of nodal force over a cycle, split at t^n.
struct WorkHalves {
  Real before = 0.0;  ///< over x^n - x^{n-1/2}
  Real after = 0.0;   ///< over x^{n+1/2} - x^n

  /// Adds the work of force f over the two half displacements.
  void add(Real f, Real d_before, Real d_after) {
    before += f * d_before;
    after += f * d_after;
  }
  WorkHalves& operator+=(const WorkHalves& o) {
    before += o.before;
    after += o.after;
    return *this;
  }
};

/// What one velocity update contributes to the ledger (per chunk, then summed in chunk order).
struct NodalEnergySums {
  Real kinetic = 0.0;  ///< at t^n
  WorkHalves stress;      ///< -f_int . dx (the elements' stress work, hourglass and bulk viscosity included)
  WorkHalves external;    ///< f_ext . dx
  WorkHalves contact;     ///< f_contact . dx and the work of tie forces on dictated nodes
  WorkHalves damping;     ///< -f_damping . dx (dissipated, >= 0)
  WorkHalves support;     ///< work of the support forces on prescribed components
  WorkHalves constraint;  ///< work of NodalConstraint forces on their nodes

  NodalEnergySums& operator+=(const NodalEnergySums& o) {
    kinetic += o.kinetic;
    stress += o.stress;
    external += o.external;
    contact += o.contact;
    damping += o.damping;
    support += o.support;
    constraint += o.constraint;
    return *this;
  }
};

/// Accumulates the works cycle by cycle and reports the energies at t^n.
class EnergyLedger {
 public:
  void reset() { *this = EnergyLedger{}; }

  /// Element-side powers at t^n (hourglass, bulk viscosity, stiffness damping) over the step `dt`
  /// that ends at t^n (0 on the first evaluation). Reported from the next book() on: the forces at
  /// t^n are evaluated at the end of the cycle before, so the report stays a snapshot of t^n
  /// between two cycles.
  void add_element_powers(Real hourglass_power, Real viscous_power, Real damping_power, Real dt) {
    hourglass_ += hourglass_power * dt;
    bulk_viscosity_ += viscous_power * dt;
    element_damping_ += damping_power * dt;
  }
  /// Erosion: the stress and hourglass work that the elements deleted at this force evaluation
  /// held (energies): moved from the internal and hourglass terms to the eroded ones (from the
  /// next book() on, as add_element_powers).
  void add_eroded(Real internal, Real hourglass) {
    eroded_internal_ += internal;
    eroded_hourglass_ += hourglass;
    hourglass_ -= hourglass;
  }
  /// Books one velocity update's sums; `first` on the first cycle (sets kinetic0).
  void book(const NodalEnergySums& s, bool first) {
    report_.hourglass = hourglass_;
    report_.bulk_viscosity = bulk_viscosity_;
    report_.eroded_internal = eroded_internal_;
    report_.eroded_hourglass = eroded_hourglass_;
    report_.kinetic = s.kinetic;
    if (first) report_.kinetic0 = s.kinetic;
    report_.external = external_.at_n(s.external);
    report_.damping = damping_.at_n(s.damping) + element_damping_;
    report_.support = support_.at_n(s.support);
    report_.constraint = constraint_.at_n(s.constraint);
    contact_work_ = contact_.at_n(s.contact);
    report_.internal = stress_.at_n(s.stress) - report_.hourglass - report_.bulk_viscosity - element_damping_;
    if (report_.eroded() != 0.0) report_.internal -= report_.eroded();
    report_.contact = -contact_work_ - report_.friction;
    stress_.commit(s.stress);
    external_.commit(s.external);
    contact_.commit(s.contact);
    damping_.commit(s.damping);
    support_.commit(s.support);
    constraint_.commit(s.constraint);
  }
  /// Mass scaling every cycle: the kinetic energy change 1/2 dm |v|^2 of one re-evaluation.
  void add_mass_scaling_work(Real w) { report_.mass_scaling += w; }
  /// Work done on constrained nodes outside the velocity update (a rigid body's velocity reset).
  void add_constraint_work(Real w) { constraint_.committed += w; }
  /// Work done by contact outside the velocity update (a tie resetting its slaves).
  void add_contact_work(Real w) { contact_.committed += w; }
  /// The friction dissipation reported by the interfaces (a running total).
  void set_friction(Real dissipated) {
    report_.friction = dissipated;
    report_.contact = -contact_work_ - dissipated;
  }
  const EnergyReport& report() const { return report_; }

 private:
  struct Accumulator {
    Real committed = 0.0;
    Real at_n(const WorkHalves& h) const { return committed + h.before; }
    void commit(const WorkHalves& h) { committed += h.before + h.after; }
  };
  Accumulator stress_, external_, contact_, damping_, support_, constraint_;
  /// The element-side terms as of the last force evaluation (report_ takes them at book()).
  Real hourglass_ = 0.0, bulk_viscosity_ = 0.0, element_damping_ = 0.0;
  Real eroded_internal_ = 0.0, eroded_hourglass_ = 0.0;
  Real contact_work_ = 0.0;
  EnergyReport report_;
};

}  // namespace slideline
