// TiebreakContact's ties of the automatic tiebreak's other OPTIONs: the mixed-mode cohesive ties
// (OPTION 9, and 6 with a fixed final separation; MixedModeCohesiveLaw, mixed_mode_cohesive_law.hpp)
// and the normal-only tie with friction (OPTION 4). See tiebreak_contact.hpp.
#include "slideline/contact/tiebreak_contact.hpp"

namespace slideline {

void TiebreakContact::apply_cohesive(const NodalFields& nodes, ContactForceView out) {
  Vec3 slave = Vec3::Zero();
  master_total_ = Vec3::Zero();
  Real stored = 0.0;
  const std::size_t n = links_.size();
  for (std::size_t k = 0; k < n; ++k) {
    if (released_[k]) continue;
    const TiePoint& t = links_[k];
    const Vec3 d = tie_stretch(k, nodes.x);
    const Vec3 nk = oriented_normal(k, nodes.x);
    const Real dn = d.dot(nk);
    const Vec3 dt = d - dn * nk;
    const Real opening = std::max(0.0, dn), slip = dt.norm();
    const MixedModeCohesiveLaw law = cohesive_law(k);
    damage_[k] = law.damage(opening, slip, damage_[k]);
    const Real a = area_[k], keep = 1.0 - damage_[k];
    // Opening and slip soften with the damage; closing is contact (the tie's compression stiffness,
    // as the stress-criterion tie has), never damaged.
    const Real kn = dn > 0.0 ? keep * law.en : compression_ * kappa_[k];
    const Vec3 f = -(a * keep * law.et) * dt - (a * kn * dn) * nk;
    // Work done on the spring over the step (trapezoidal rule on its force-stretch path).
    cohesive_work_ -= 0.5 * (f + tie_force_[k]).dot(d - delta_[k]);
    stored += 0.5 * a * (keep * law.et * slip * slip + kn * dn * dn);
    delta_[k] = d;
    tie_force_[k] = f;
    out.force.add(t.slave, f);
    for (int q = 0; q < 4; ++q)
      if (t.shape[q] != 0.0) add_to_master(out, t.master[q], -t.shape[q] * f);
    slave += f;
    if (damage_[k] >= 1.0) {  // fully damaged: the automatic contact takes the node from the next cycle
      // A closed node's compression goes with it to the automatic pass (whose spring takes the same
      // load from the next cycle): its closing spring's energy is handed over, not dissipated.
      if (dn < 0.0) {
        const Real closing = 0.5 * a * kn * dn * dn;
        cohesive_work_ -= closing;
        stored -= closing;
      }
      area_[k] = 0.0;
      released_[k] = 1;
    }
  }
  slave_ = slave;
  cohesive_stored_ = stored;
  // A slave segment fails (the automatic pass may use it) once all of its tied nodes are released.
  const Index nseg = slave_surface_.segment_count();
  for (Index j = 0; j < nseg; ++j) {
    if (segment_failed_[j]) continue;
    bool all = true;
    for (int q = 0; q < 4; ++q) {
      const Index l = segment_links_[4 * static_cast<std::size_t>(j) + q];
      if (l >= 0 && !released_[static_cast<std::size_t>(l)]) all = false;
    }
    if (all) segment_failed_[j] = 1;
  }
}

Vec3 TiebreakContact::normal_tie_force(std::size_t k, const Vec3& d, const NodalFields& nodes,
                                        const StepTimes& times) {
  const TiePoint& t = links_[k];
  const Vec3 nk = oriented_normal(k, nodes.x);
  const Real dn = d.dot(nk);
  const Real kk = kappa_[k] * area_[k];
  // Normal: the tie's spring (compression_ times stiffer closing); the compressive part presses.
  const Real fn = -(dn < 0.0 ? compression_ * kk : kk) * dn;  // along nk on the slave; > 0 pressed
  // Tangential: Coulomb friction on the pressing force, a stick spring of the tie's stiffness
  // (as the contact after failure, contact_after_failure): no friction while the tie is in tension.
  Vec3 vm = Vec3::Zero();
  for (int a = 0; a < 4; ++a)
    if (t.shape[a] != 0.0) vm += t.shape[a] * nodes.v.get(t.master[a]);
  const Vec3 vt = tangential_part(nodes.v.get(t.slave) - vm, nk);
  const Vec3 trial = rotate_into_plane(tie_friction_[k], nk) - kk * times.dt_prev * vt;
  const TangentialReturn r = coulomb_return_map(trial, std::max(0.0, fn), p_.friction.coefficient(vt));
  if (r.slipping && kk > 0.0) friction_work_ += (trial.norm() - r.force.norm()) / kk * r.force.norm();
  tie_friction_[k] = r.force;
  return fn * nk + r.force;
}

}  // namespace slideline
