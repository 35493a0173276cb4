#pragma once
/// Loads and supports in physical form (the builder converts deck semantics into these).
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "slideline/core/types.hpp"
#include "slideline/solver/load_curve.hpp"

namespace slideline {

/// An acceleration field on parts: force on node i = m_i * scale * curve(t) along axis, where m_i
/// is the mass the loaded parts' elements lump to node i (a node shared with an unloaded part
/// carries only the loaded part's share). Physical sign: a positive scale pushes in +axis; the
/// builder turns LS-DYNA's base accelerations into this form.
struct BodyLoad {
  Axis axis = Axis::x;
  Real scale = 0.0;
  LoadCurve curve = LoadCurve::constant(1.0);
  std::vector<Id> parts;     ///< loaded part ids; empty = every element block
  // Filled by Simulation::initialize:
  std::vector<Index> nodes;  ///< nodes of the loaded parts
  std::vector<Real> mass;    ///< loaded mass at each of those nodes
};

/// A concentrated load on nodes: force (or, with `moment`, moment about `axis`) of
/// scale * curve(t) on each node along `axis` (LS-DYNA *LOAD_NODE_POINT / _SET).
struct NodalLoad {
  Axis axis = Axis::x;
  bool moment = false;
  Real scale = 1.0;
  LoadCurve curve = LoadCurve::constant(1.0);
  std::vector<Index> nodes;  ///< unique
  std::string source;        ///< "deck.k:12: *LOAD_NODE_SET", for messages
};

/// What a prescribed-motion curve gives (LS-DYNA VAD: 2, 0 and 1).
enum class Prescribed : std::uint8_t { displacement, velocity, acceleration };

/// Prescribed motion of a node set along one axis: zero displacement when `has_curve` is false,
/// else scale * curve(t) is the displacement u(t), the velocity or the acceleration (`kind`).
/// Records the reaction: the total force the body exerts on the support.
struct Support {
  std::string name;  ///< output title, e.g. "spc_1" or the deck heading
  Axis axis = Axis::x;
  bool rotational = false;  ///< fixes the rotation about `axis` (zero only; no reaction moment recorded)
  std::vector<Index> nodes;
  bool has_curve = false;
  Prescribed kind = Prescribed::displacement;  ///< what the curve gives (with has_curve)
  LoadCurve curve;
  Real scale = 1.0;
  /// The support acts for birth <= t <= death (LS-DYNA BIRTH/DEATH of a prescribed motion); outside
  /// that window its components are free. A displacement curve gives the absolute u(t).
  Real birth = 0.0;
  Real death = std::numeric_limits<Real>::infinity();
  bool active(Real t) const { return t >= birth && t <= death; }
  bool timed() const { return birth > 0.0 || death < 1e28; }
};

/// A group of supports reported together (one *BOUNDARY_SPC_SET fixing several directions is one
/// group with one reaction vector).
struct SupportGroup {
  std::string name;
  std::vector<Support> supports;
  Vec3 reaction = Vec3::Zero();  ///< force the body exerts on the supports at the last step
};

/// Mass-proportional (Rayleigh alpha) damping: force = -alpha(t) * m * v on the nodes in `nodes`
/// (all nodes when empty).
struct MassDamping {
  Real alpha = 0.0;  ///< 1/time
  bool has_curve = false;
  LoadCurve curve;
  std::vector<Index> nodes;

  /// alpha from a fraction of critical damping at a circular frequency: alpha = 2 zeta omega.
  static Real alpha_from_critical(Real fraction, Real omega) { return 2.0 * fraction * omega; }
  Real value(Real t) const { return has_curve ? alpha * curve(t) : alpha; }
};

}  // namespace slideline
