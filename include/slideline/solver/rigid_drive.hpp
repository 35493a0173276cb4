#pragma once
/// RigidDrive: a prescribed translation of a rigid body's centre of mass along a global axis, or
/// a prescribed rotation about a global axis through it (LS-DYNA *BOUNDARY_PRESCRIBED_MOTION_RIGID,
/// DOF 1-3 and 5-7).
#include <limits>

#include "slideline/core/types.hpp"
#include "slideline/solver/boundary.hpp"
#include "slideline/solver/load_curve.hpp"

namespace slideline {

struct RigidDrive {
  Axis axis = Axis::x;
  bool rotation = false;  ///< drives the angular velocity about `axis` instead of the translation
  /// scale * curve(t) is the centre of mass's displacement from its initial position, its
  /// velocity or its acceleration (the deck reader refuses the last, as LS-DYNA does); for a
  /// rotation: the angle turned about `axis` since t = 0 (radians), the angular velocity or the
  /// angular acceleration.
  Prescribed kind = Prescribed::velocity;
  LoadCurve curve;
  Real scale = 1.0;
  /// Acts for birth <= t <= death (at the start of a step); outside that window the axis is free.
  Real birth = 0.0;
  Real death = std::numeric_limits<Real>::infinity();
  bool active(Real t) const { return t >= birth && t <= death; }
};

}  // namespace slideline
