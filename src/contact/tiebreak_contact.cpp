// TiebreakContact (DYNA3D Types 8 and 9): penalty ties with failure, then frictional penalty
// contact. See include/slideline/contact/tiebreak_contact.hpp for the formulation.
#include "slideline/contact/tiebreak_contact.hpp"


#include "slideline/element/element_block.hpp"

namespace slideline {

namespace {

/// Stiffness per unit master area of segment s (force / length^3), penalty-contact style.
Real stiffness_per_area(const Surface& master, Index s, const ContactContext& c, Real factor) {
  const SegmentStiffnessData d = segment_stiffness_data(master, s, c.blocks, c.nodes.x);
  if (master.kind[s] == SegmentKind::shell)
    return d.max_diagonal > 0.0 ? factor * d.bulk_modulus / d.max_diagonal : 0.0;
  return d.element_volume > 0.0 ? factor * d.bulk_modulus * d.face_area / d.element_volume : 0.0;
}

/// In compression: the total of the penalty node springs kappa A_master that the contact taking
/// over (Type 3 / 5) gives these slave nodes, over their tie springs' total kappa x area (1 for
/// Type 8, whose area is A_master; never below 1).
Real compression_factor(const std::vector<TiePoint>& links, const std::vector<Real>& kappa,
                        const std::vector<Real>& area, const Surface& master, const Vec3Field& x) {
  Real springs = 0.0, tied = 0.0;
  for (std::size_t k = 0; k < links.size(); ++k) {
    springs += kappa[k] * segment_area(master, links[k].segment, x);
    tied += kappa[k] * area[k];
  }
  return tied > 0.0 ? std::max(1.0, springs / tied) : 1.0;
}

}  // namespace

Real TiebreakContact::tie_springs(const Surface& master, const Vec3Field& x) const {
  Real springs = 0.0;
  for (std::size_t k = 0; k < links_.size(); ++k) springs += kappa_[k] * segment_area(master, links_[k].segment, x);
  return springs > 0.0 ? springs : 1.0;
}

Real TiebreakContact::reverse_springs(const ContactContext& c) const {
  // The master side's nodes on tied slave segments (the tie search's tolerances), each with the
  // stiffness a penalty pass gives it there: kappa_s x the slave segment's area.
  const Surface& m = pairs_.master();
  std::vector<Real> segment_table, node_table;
  const TieSearchOptions opt = p_.offset_shells()
                                   ? offset_search(slave_surface_, p_.slave_shells, m, p_.master_shells,
                                                   c.nodes.size(), segment_table, node_table)
                                   : TieSearchOptions{};
  const std::vector<TiePoint> on_slave = find_tie_points(m.nodes, slave_surface_, c.nodes.x, opt);
  Real springs = 0.0;
  for (const TiePoint& t : on_slave) {
    if (t.segment < 0 || segment_failed_[static_cast<std::size_t>(t.segment)]) continue;
    springs += stiffness_per_area(slave_surface_, t.segment, c, p_.penalty_factor) * segment_area(slave_surface_, t.segment, c.nodes.x);
  }
  return springs;
}

TieSearchOptions TiebreakContact::offset_search(const Surface& onto, const ShellOffsetRule& onto_rule,
                                                const Surface& from, const ShellOffsetRule& from_rule,
                                                std::size_t node_count, std::vector<Real>& segment_table,
                                                std::vector<Real>& node_table) const {
  segment_table.assign(static_cast<std::size_t>(onto.segment_count()), 0.0);
  for (Index s = 0; s < onto.segment_count(); ++s) segment_table[static_cast<std::size_t>(s)] = segment_offset(onto, s, onto_rule);
  node_table.assign(node_count, 0.0);
  for (Index r = 0; r < static_cast<Index>(from.nodes.size()); ++r)
    node_table[static_cast<std::size_t>(from.nodes[static_cast<std::size_t>(r)])] = node_offset(from, r, from_rule);
  TieSearchOptions opt;
  opt.master_offset = segment_table;
  opt.node_offset = node_table;
  return opt;
}

void TiebreakContact::initialize(const ContactContext& c) {
  const NodalFields& nodes = c.nodes;
  const Surface& master = pairs_.master();
  if (p_.offset_shells()) {
    std::vector<Real> segment_table, node_table;
    const TieSearchOptions opt =
        offset_search(master, p_.master_shells, slave_surface_, p_.slave_shells, nodes.size(), segment_table, node_table);
    tie_candidates(name_, candidates_, master, nodes, opt, links_, untied_nodes_, c.diagnostics);
  } else {
    tie_candidates(name_, candidates_, master, nodes, {}, links_, untied_nodes_, c.diagnostics);
  }
  const std::size_t n = links_.size();
  // Each offset in the master segment's frame at tie time (tie_stretch), where it is not round-off.
  carried_.assign(n, 0);
  offset_local_.assign(n, Vec3::Zero());
  for (std::size_t k = 0; k < n; ++k) {
    if (carry_tie_offset(master, links_[k], nodes.x, offset_local_[k])) carried_[k] = 1;
  }
  std::vector<Index> link_of(nodes.size(), -1);
  for (std::size_t k = 0; k < n; ++k) link_of[links_[k].slave] = static_cast<Index>(k);

  kappa_.assign(n, 0.0);
  area_.assign(n, 0.0);
  std::vector<std::int8_t> side(n, 1);
  std::vector<Vec3> slave_side(n, Vec3::Zero());  // sum of the slave segments' outward normals
  for (std::size_t k = 0; k < n; ++k) kappa_[k] = stiffness_per_area(master, links_[k].segment, c, p_.penalty_factor);

  const bool by_segment = p_.unit == TiebreakParameters::FailureUnit::segment;
  const Index nseg = by_segment ? slave_surface_.segment_count() : 0;
  segment_links_.assign(4 * static_cast<std::size_t>(nseg), -1);
  segment_area_.assign(nseg, 0.0);
  segment_share_.assign(nseg, 0.0);
  segment_failed_.assign(nseg, 0);
  segment_force_.assign(nseg, Vec3::Zero());
  if (by_segment) {
    for (Index j = 0; j < nseg; ++j) {
      const Real a = segment_area(slave_surface_, j, nodes.x);
      const bool tri = slave_surface_.is_triangle(j);
      segment_area_[j] = a;
      segment_share_[j] = a / (tri ? 3.0 : 4.0);
      const Vec3 nj = segment_normal(slave_surface_, j, nodes.x);
      // Only segments whose corners are all tied carry a tie (a side face of a slave block, with
      // one edge on the interface, does not).
      bool tied = true;
      for (int q = 0; q < (tri ? 3 : 4); ++q) tied = tied && link_of[slave_surface_.conn[4 * static_cast<std::size_t>(j) + q]] >= 0;
      if (!tied) {
        segment_failed_[j] = 1;  // never evaluated
        continue;
      }
      for (int q = 0; q < (tri ? 3 : 4); ++q) {
        const Index l = link_of[slave_surface_.conn[4 * static_cast<std::size_t>(j) + q]];
        segment_links_[4 * static_cast<std::size_t>(j) + q] = l;
        if (l < 0) continue;
        area_[l] += segment_share_[j];
        slave_side[l] += nj;
      }
    }
  } else {
    for (std::size_t k = 0; k < n; ++k) area_[k] = segment_area(master, links_[k].segment, nodes.x);
  }
  // The master normal oriented towards the slave: from the tie-time gap when the slave stands off
  // the surface, else against the slave segments' outward normal, else the master's own normal.
  for (std::size_t k = 0; k < n; ++k) {
    const TiePoint& t = links_[k];
    if (std::abs(t.gap) > 1e-6 * t.size) side[k] = t.gap > 0.0 ? 1 : -1;
    else if (slave_side[k].squaredNorm() > 0.0) side[k] = slave_side[k].dot(t.normal) > 0.0 ? -1 : 1;
  }
  area0_ = area_;
  compression_ = compression_factor(links_, kappa_, area_, master, nodes.x);
  if (p_.two_sided_contact) compression_ *= 1.0 + reverse_springs(c) / tie_springs(master, nodes.x);
  released_.assign(n, 0);
  delta_.assign(n, Vec3::Zero());
  friction_force_.assign(n, Vec3::Zero());
  tie_friction_.assign(p_.normal_only ? n : 0, Vec3::Zero());
  seed_contact(nodes.x, side);
  damage_.assign(p_.mixed_mode ? n : 0, 0.0);
  tie_force_.assign(p_.mixed_mode ? n : 0, Vec3::Zero());
  cohesive_work_ = cohesive_stored_ = 0.0;
  friction_work_ = 0.0;
  slave_ = master_total_ = first_failure_stress_ = Vec3::Zero();
  // Stable step of each spring between the slave mass and its lightest master (2 / omega).
  dt_ = std::numeric_limits<Real>::max();
  link_inv2_.assign(n, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    Real kk = compression_ * kappa_[k] * area_[k];
    if (p_.mixed_mode) {
      const MixedModeCohesiveLaw l = cohesive_law(k);
      kk = std::max(kk, std::max(l.en, l.et) * area_[k]);
    }
    if (!(kk > 0.0)) continue;
    Real mm = std::numeric_limits<Real>::max();
    for (int a = 0; a < 4; ++a)
      if (links_[k].shape[a] != 0.0 && nodes.mass[links_[k].master[a]] > 0.0)
        mm = std::min(mm, nodes.mass[links_[k].master[a]]);
    const Real ms = nodes.mass[links_[k].slave];
    const Real w2 = kk * ((ms > 0.0 ? 1.0 / ms : 0.0) + (mm < std::numeric_limits<Real>::max() ? 1.0 / mm : 0.0));
    if (w2 > 0.0) dt_ = std::min(dt_, 2.0 / std::sqrt(w2));
    if (w2 > 0.0) link_inv2_[k] = 0.25 * w2;
  }
  vote_ = dt_;
}

void TiebreakContact::update_step_vote(const ElementStepsView& elements) {
  if (elements.empty()) {
    vote_ = dt_;  // the springs alone, as at initialize()
    return;
  }
  // Each tie's spring with the elements on its nodes (element_steps_view.hpp).
  Real w2 = 0.0;
  for (std::size_t k = 0; k < links_.size(); ++k) {
    const TiePoint& t = links_[k];
    w2 = std::max(w2, combined_step_inv2(link_inv2_[k], elements.pair(t.slave, t.master.data(), t.shape, 4)));
  }
  vote_ = w2 > 0.0 ? 1.0 / std::sqrt(w2) : std::numeric_limits<Real>::max();
}

void TiebreakContact::seed_contact(const Vec3Field& x, const std::vector<std::int8_t>& side) {
  // The contact after failure: each tied node from its tie segment, on its side, its offset the
  // tie-time stand-off (so contact starts when the node passes through its tie point).
  const std::size_t n = links_.size();
  std::vector<Index> tied(n), segment(n);
  std::vector<Real> stand_off(n);
  for (std::size_t k = 0; k < n; ++k) {
    tied[k] = links_[k].slave;
    segment[k] = links_[k].segment;
    stand_off[k] = static_cast<Real>(side[k]) * links_[k].gap;
  }
  pairs_.initialize(x);
  pairs_.seed(std::move(tied), std::move(stand_off), segment, side);
}

void TiebreakContact::apply_forces(const NodalFields& nodes, const StepTimes& times, ContactForceView out) {
  update_step_vote(times.element_steps);
  if (p_.mixed_mode) {
    apply_cohesive(nodes, out);
    return;
  }
  Vec3 slave = Vec3::Zero();
  master_total_ = Vec3::Zero();  // summed where forces are added to master nodes
  const std::size_t n = links_.size();
  for (std::size_t k = 0; k < n; ++k) {
    const TiePoint& t = links_[k];
    // The failed share of the node's area is in contact (normal penalty and friction) with the
    // same stiffnesses per unit area as the tie: the normal force is continuous through a failure.
    const Real contact_area = area0_[k] - area_[k];
    if (contact_area > 0.0 && !(released_[k] && p_.release_to_owner)) {
      const Real kk = kappa_[k] * contact_area;
      slave += contact_after_failure(k, compression_ * kk, kk, nodes, times, out);
    }
    if (released_[k]) continue;
    const Vec3 d = tie_stretch(k, nodes.x);
    delta_[k] = d;
    if (p_.normal_only) {
      const Vec3 f = normal_tie_force(k, d, nodes, times);
      out.force.add(t.slave, f);
      for (int a = 0; a < 4; ++a)
        if (t.shape[a] != 0.0) add_to_master(out, t.master[a], -t.shape[a] * f);
      slave += f;
      continue;
    }
    Vec3 f = -(kappa_[k] * area_[k]) * d;
    if (compression_ > 1.0) {  // the normal part pushes compression_ times stiffer in compression
      const Vec3 nk = oriented_normal(k, nodes.x);
      const Real dn = d.dot(nk);
      if (dn < 0.0) f -= ((compression_ - 1.0) * kappa_[k] * area_[k] * dn) * nk;
    }
    out.force.add(t.slave, f);
    for (int a = 0; a < 4; ++a)
      if (t.shape[a] != 0.0) add_to_master(out, t.master[a], -t.shape[a] * f);
    slave += f;
  }
  slave_ = slave;

  // Failure checks on this cycle's forces (effective from the next cycle).
  if (p_.unit == TiebreakParameters::FailureUnit::node) {
    for (std::size_t k = 0; k < n; ++k) {
      if (released_[k]) continue;
      const Vec3 f = -(kappa_[k] * area_[k]) * delta_[k];
      const Vec3 nk = oriented_normal(k, nodes.x);
      if (failure_index(f, nk, p_.normal_failure, p_.shear_failure, p_.normal_exponent, p_.shear_exponent) >= 1.0)
        hand_over(k, area_[k], nk);
    }
    return;
  }
  const Index nseg = slave_surface_.segment_count();
  for (Index j = 0; j < nseg; ++j) {
    if (segment_failed_[j]) continue;
    Vec3 fj = Vec3::Zero(), nj = Vec3::Zero();
    segment_tie_force(j, nodes.x, fj, nj);
    segment_force_[j] = fj;
    const Real nn = nj.norm();
    if (!(nn > 0.0)) continue;
    const Real a = segment_area_[j];
    if (failure_index(fj, nj / nn, p_.normal_failure * a, p_.shear_failure * a, 2.0, 2.0) < 1.0) continue;
    if (!(first_failure_stress_.z() > 0.0)) record_first_failure_stress(nodes.x);
    segment_failed_[j] = 1;
    segment_force_[j] = Vec3::Zero();
    for (int q = 0; q < 4; ++q) {
      const Index l = segment_links_[4 * static_cast<std::size_t>(j) + q];
      if (l < 0) continue;
      const auto k = static_cast<std::size_t>(l);
      hand_over(k, segment_share_[j], oriented_normal(k, nodes.x));
    }
  }
}

void TiebreakContact::segment_tie_force(Index j, const Vec3Field& x, Vec3& fj, Vec3& nj) const {
  for (int q = 0; q < 4; ++q) {
    const Index l = segment_links_[4 * static_cast<std::size_t>(j) + q];
    if (l < 0) continue;
    fj -= kappa_[l] * segment_share_[j] * delta_[l];
    nj += oriented_normal(static_cast<std::size_t>(l), x);
  }
}

void TiebreakContact::record_first_failure_stress(const Vec3Field& x) {
  Real largest = 0.0, sum = 0.0;
  int count = 0;
  for (Index j = 0; j < slave_surface_.segment_count(); ++j) {
    if (segment_failed_[j]) continue;
    Vec3 fj = Vec3::Zero(), nj = Vec3::Zero();
    segment_tie_force(j, x, fj, nj);
    const Real nn = nj.norm();
    const Real sn = nn > 0.0 ? std::max(0.0, -fj.dot(nj / nn)) / segment_area_[j] : 0.0;
    largest = std::max(largest, sn);
    sum += sn;
    ++count;
  }
  const Real mean = count > 0 ? sum / count : 0.0;
  first_failure_stress_ = {largest, mean, mean > 0.0 ? largest / mean : 0.0};
}

void TiebreakContact::hand_over(std::size_t k, Real share, const Vec3& n) {
  // The friction stick force of the contact share starts from the tie's last tangential force on
  // that share (the return map of the next cycle caps it at mu N): the shear the tie carried is
  // handed over instead of dropping to zero and being rebuilt, which would jolt the bodies.
  if (p_.normal_only) {  // the tied share's friction (not a spring's shear) goes with the share
    const Real part = area_[k] > 0.0 ? share / area_[k] : 1.0;
    friction_force_[k] += part * tie_friction_[k];
    tie_friction_[k] *= 1.0 - part;
  } else {
    const Vec3 f = -(kappa_[k] * share) * delta_[k];
    friction_force_[k] += f - f.dot(n) * n;
  }
  area_[k] -= share;
  if (area_[k] <= 1e-12 * area0_[k]) {
    area_[k] = 0.0;
    released_[k] = 1;
  }
}

Vec3 TiebreakContact::contact_after_failure(std::size_t k, Real kn, Real kk, const NodalFields& nodes,
                                           const StepTimes& times, ContactForceView out) {
  const TiePoint& t = links_[k];
  // Track the segment: stay on the current one while the point projects inside it, else take the
  // best of it and its edge neighbours (ContactPairs, SegmentTracking::stay_while_inside).
  const ContactPoint& cp = pairs_.track(k, nodes.x);
  const Projection& best = cp.projection;
  const Index best_s = cp.segment;
  const Real tangential = std::sqrt(std::max(0.0, best.distance * best.distance - best.gap * best.gap));
  const Real side = static_cast<Real>(pairs_.side(k));
  const Real gap = side * best.gap - cp.offset;  // penetration past the tie-time stand-off
  if (gap >= 0.0 || tangential > 1e-3 * best.size || !(kk > 0.0)) {
    friction_force_[k] = Vec3::Zero();
    return Vec3::Zero();
  }
  const Vec3 n = side * best.normal;
  const Real fn = -kn * gap;  // > 0, pushes the slave out along n
  const Index* m = &master().conn[4 * static_cast<std::size_t>(best_s)];
  Vec3 vm = Vec3::Zero();
  for (int a = 0; a < 4; ++a) vm += best.shape[a] * nodes.v.get(m[a]);
  const Vec3 vt = tangential_part(nodes.v.get(t.slave) - vm, n);
  const Vec3 trial = rotate_into_plane(friction_force_[k], n) - kk * times.dt_prev * vt;
  const TangentialReturn r = coulomb_return_map(trial, fn, p_.friction.coefficient(vt));
  if (r.slipping) friction_work_ += (trial.norm() - r.force.norm()) / kk * r.force.norm();
  friction_force_[k] = r.force;
  const Vec3 f = fn * n + r.force;
  out.force.add(t.slave, f);
  for (int a = 0; a < 4; ++a)
    if (best.shape[a] != 0.0) add_to_master(out, m[a], -best.shape[a] * f);
  return f;
}

}  // namespace slideline
