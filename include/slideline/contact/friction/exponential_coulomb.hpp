#pragma once
/// Coulomb friction with an exponential decay from the static to the kinetic coefficient
/// (DYNA3D, spec Table 2):  mu(v) = mu_k + (mu_s - mu_k) exp(-beta |v|),
/// with v the relative tangential (sliding) velocity, and the return mapping of a tangential
/// stick spring: a trial force from the elastic predictor, capped at mu N.
///
/// All functions are pure: the caller owns the friction history (the elastic tangential
/// displacement, equivalently the sticking point, or the previous tangential force) per slave node.
#include <algorithm>
#include <cmath>

#include "slideline/core/types.hpp"

namespace slideline {

/// The friction law's parameters.
struct ExponentialCoulomb {
  /// As a penalty interface's friction policy (Frictionless is the other one): tangential forces on.
  static constexpr bool enabled = true;
  Real mu_s = 0.0;  ///< static coefficient (dimensionless)
  Real mu_k = 0.0;  ///< kinetic coefficient (dimensionless)
  Real beta = 0.0;  ///< decay coefficient (time / length: 1 / speed)

  /// mu at slip speed |v| (length / time); mu_s at rest, tends to mu_k as |v| grows.
  Real coefficient(Real slip_speed) const {
    return mu_k + (mu_s - mu_k) * std::exp(-beta * std::abs(slip_speed));
  }
  /// mu at the relative tangential velocity v_t (length / time).
  Real coefficient(const Vec3& tangential_velocity) const {
    return coefficient(tangential_velocity.norm());
  }
};

/// v minus its component along the unit normal n.
inline Vec3 tangential_part(const Vec3& v, const Vec3& n) { return v - v.dot(n) * n; }

/// v turned into the plane normal to the unit vector n, keeping |v| (used to carry a friction
/// history vector over when the contact normal rotates). Zero if v is parallel to n.
inline Vec3 rotate_into_plane(const Vec3& v, const Vec3& n) {
  const Vec3 t = tangential_part(v, n);
  const Real tn = t.norm();
  return tn > 0.0 ? Vec3(t * (v.norm() / tn)) : Vec3::Zero();
}

/// The result of a Coulomb return mapping.
struct TangentialReturn {
  Vec3 force = Vec3::Zero();  ///< tangential force after the mapping (force)
  bool slipping = false;      ///< true when the trial force exceeded the limit mu N
  Real limit = 0.0;           ///< mu N (force)
};

/// Coulomb return mapping. trial: trial tangential force (force, in the tangent plane);
/// normal_force: magnitude of the compressive normal force N (force; <= 0 means no contact and
/// gives the limit 0); mu: friction coefficient. Stick (force = trial) when |trial| <= mu N,
/// otherwise slip: force = mu N trial / |trial| (direction kept, magnitude capped).
inline TangentialReturn coulomb_return_map(const Vec3& trial, Real normal_force, Real mu) {
  TangentialReturn r;
  r.limit = mu * std::max(normal_force, Real(0));
  const Real t = trial.norm();
  if (t <= r.limit) {
    r.force = trial;
    r.slipping = false;
  } else {
    r.force = trial * (r.limit / t);
    r.slipping = true;
  }
  return r;
}

/// The result of a stick-spring update.
struct StickSpringUpdate {
  Vec3 force = Vec3::Zero();                 ///< tangential force on the slave node (force)
  bool slipping = false;
  Vec3 elastic_displacement = Vec3::Zero();  ///< the new history: -force / k_t (length)
};

/// Tangential stick spring with the sticking point as history. elastic_displacement: tangential
/// vector from the sticking point to the slave node's contact point (length, in the tangent
/// plane); k_t: tangential stiffness (force / length, > 0); normal_force, mu as in
/// coulomb_return_map. Trial force -k_t elastic_displacement, then the return mapping. On slip
/// the sticking point is dragged along so that |k_t u_e| = mu N: the new sticking point is
/// (contact point - returned elastic_displacement).
inline StickSpringUpdate stick_spring_update(const Vec3& elastic_displacement, Real k_t,
                                             Real normal_force, Real mu) {
  const TangentialReturn r = coulomb_return_map(-k_t * elastic_displacement, normal_force, mu);
  StickSpringUpdate u;
  u.force = r.force;
  u.slipping = r.slipping;
  u.elastic_displacement = r.slipping ? Vec3(-r.force / k_t) : elastic_displacement;
  return u;
}

/// Incremental (DYNA3D-style) elastic predictor with the previous tangential force as history:
/// trial = rotate_into_plane(previous_force, n) - k_t * tangential_part(du, n), with n the
/// current unit normal, k_t the tangential stiffness (force / length) and du the increment of
/// the slave point's displacement relative to the master surface over the step (length).
inline Vec3 tangential_trial_force(const Vec3& previous_force, const Vec3& n, Real k_t,
                                   const Vec3& du) {
  return rotate_into_plane(previous_force, n) - k_t * tangential_part(du, n);
}

}  // namespace slideline
