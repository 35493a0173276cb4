#pragma once
/// The plug-in point for contact interfaces. One final class per interface type implements it;
/// the simulation calls a few virtual functions per step (none per node).
#include <limits>
#include <string>

#include "slideline/core/types.hpp"
#include "slideline/mesh/nodal_fields.hpp"

namespace slideline {

class ContactInterface {
 public:
  virtual ~ContactInterface() = default;

  /// Output title (deck heading, else "contact_<id>").
  virtual const std::string& name() const = 0;
  /// Called once after masses are known and before the first force evaluation.
  virtual void initialize(const NodalFields& nodes) = 0;
  /// Force phase at time t (configuration x^t, velocities at t - dt/2): adds penalty or
  /// friction forces to nodes.f_ext and returns nothing. Kinematic and Lagrange interfaces do their
  /// work in constrain_accelerations instead.
  virtual void apply_forces(NodalFields& nodes, Real t, Real dt) = 0;
  /// Constraint phase, after accelerations are formed: kinematic and Lagrange-multiplier
  /// interfaces correct nodes.a here.
  virtual void constrain_accelerations(NodalFields& /*nodes*/, Real /*t*/, Real /*dt*/) {}
  /// Largest step this interface allows (penalty springs), before the global scale factor.
  virtual Real stable_dt() const { return std::numeric_limits<Real>::max(); }
  /// Total interface force on the slave side and on the master side at the last step.
  virtual Vec3 slave_force() const = 0;
  virtual Vec3 master_force() const = 0;
};

}  // namespace slideline
