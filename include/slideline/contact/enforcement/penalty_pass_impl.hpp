#pragma once
/// The member definitions of PenaltyPass (enforcement/penalty.hpp, which includes this file at
/// its end; include that header, not this one). Kept apart so that the class and its contract
/// read on one page.
#include "slideline/contact/enforcement/penalty.hpp"

namespace slideline {

inline void PenaltyPass::initialize(const NodalFields& nodes,
                                    const std::vector<std::unique_ptr<ElementBlock>>& blocks) {
  if (eroding_) erosion_.bind(blocks);  // the flags at t = 0, before the first search
  const Surface& master = pairs_.master();
  const Index ns = master.segment_count();
  k_seg_.assign(static_cast<std::size_t>(ns), 0.0);
  for (Index s = 0; s < ns; ++s) {
    const SegmentStiffnessData d = segment_stiffness_data(master, s, blocks, nodes.x);
    const bool shell = master.kind[static_cast<std::size_t>(s)] == SegmentKind::shell;
    Real k = 0.0;
    if (shell) {
      k = d.max_diagonal > 0.0 ? d.bulk_modulus * d.face_area / d.max_diagonal : 0.0;
    } else {
      k = d.element_volume > 0.0 ? d.bulk_modulus * d.face_area * d.face_area / d.element_volume : 0.0;
    }
    k_seg_[static_cast<std::size_t>(s)] = opt_.stiffness_scale * k;
  }
  pairs_.set_depth_limits(nodes.x, blocks, opt_.penetration_check);
  initialize(nodes, std::move(k_seg_));
  pairs_.follow_thickness(blocks);  // THKCHG = 1: from the first cycle on
}

inline void PenaltyPass::initialize(const NodalFields& nodes, std::vector<Real> segment_stiffness) {
  const Surface& master = pairs_.master();
  const Index ns = master.segment_count();
  if (static_cast<Index>(segment_stiffness.size()) != ns)
    throw Error("PenaltyPass::initialize: one stiffness per master segment");
  k_seg_ = std::move(segment_stiffness);
  const std::size_t n = pairs_.slaves().size();
  kappa_.clear();
  mortar_.clear();
  if (opt_.coupling == PenaltyCoupling::mortar) {
    if (!std::ranges::equal(slave_surface_.nodes, pairs_.slaves()))
      throw Error("PenaltyPass::initialize: the mortar coupling needs the slaves' own surface");
    mortar_.assign(n, MortarWeights{});
    kappa_.assign(static_cast<std::size_t>(ns), 0.0);
    for (Index s = 0; s < ns; ++s) {
      const Real a = segment_area(master, s, nodes.x);
      kappa_[static_cast<std::size_t>(s)] = a > 0.0 ? k_seg_[static_cast<std::size_t>(s)] / a : 0.0;
    }
  }
  soft_mass_seg_.clear();
  if (opt_.soft_scale > 0.0) {
    soft_mass_seg_.assign(static_cast<std::size_t>(ns), std::numeric_limits<Real>::max());
    for (Index s = 0; s < ns; ++s)
      for (int a = 0; a < 4; ++a) {
        const Real m = nodes.mass[static_cast<std::size_t>(master.conn[4 * static_cast<std::size_t>(s) + a])];
        soft_mass_seg_[static_cast<std::size_t>(s)] = std::min(soft_mass_seg_[static_cast<std::size_t>(s)], m);
      }
  }
  friction_cap_seg_.clear();
  if (opt_.viscous_friction > 0.0) {
    friction_cap_seg_.assign(static_cast<std::size_t>(ns), 0.0);
    for (Index s = 0; s < ns; ++s)
      friction_cap_seg_[static_cast<std::size_t>(s)] = opt_.viscous_friction * segment_area(master, s, nodes.x);
  }
  slip_seg_.assign(static_cast<std::size_t>(ns), 0.0);
  for (Index s = 0; s < ns; ++s)
    slip_seg_[static_cast<std::size_t>(s)] = opt_.elastic_slip_fraction * segment_max_diagonal(master, s, nodes.x);
  pairs_.initialize(nodes.x);
  touched_.assign(n, 0);
  ue_.assign(n, Vec3::Zero());
  g0_.assign(n, 0.0);
  held_segment_.assign(eroding_ ? n : 0, -1);
  gap_.assign(n, std::numeric_limits<Real>::infinity());
  records_.assign(n, PenaltyRecord{});
  initial_count_ = detect_initial_penetrations(nodes, initial_max_);
}

inline Index PenaltyPass::detect_initial_penetrations(const NodalFields& nodes, Real& deepest) {
  const std::size_t n = pairs_.slaves().size();
  std::fill(g0_.begin(), g0_.end(), 0.0);
  pairs_.force_search();
  StepTimes t0;
  t0.dt_initial = std::numeric_limits<Real>::infinity();  // gaps only: SOFT = 1 adds nothing here
  compute(nodes, t0);
  Index count = 0;
  deepest = 0.0;
  const std::span<const ContactPoint> points = pairs_.points();
  for (std::size_t i = 0; i < n; ++i) {
    // Round-off of a seated start (|g| <= 1e-9 x the segment size) is not a penetration.
    const Real tol = points[i].segment >= 0 ? 1e-9 * points[i].projection.size : 0.0;
    if (gap_[i] < -tol && std::isfinite(gap_[i])) {
      g0_[i] = -gap_[i];
      ++count;
      deepest = std::max(deepest, -gap_[i]);
      gap_[i] = 0.0;
    }
    records_[i] = PenaltyRecord{};
    ue_[i] = Vec3::Zero();
    touched_[i] = 0;
  }
  return count;
}

inline void PenaltyPass::redetect_initial_penetrations(const NodalFields& nodes) {
  Real deepest = 0.0;
  detect_initial_penetrations(nodes, deepest);
}

inline Index PenaltyPass::resolve_initial_penetrations(NodalFields& nodes, Real& largest) {
  Index moved = 0;
  largest = 0.0;
  if (opt_.keep_initial_penetrations) return 0;  // IGNORE = 1, 2: g0_ keeps them as the zero
  const std::span<const ContactPoint> points = pairs_.points();
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!(g0_[i] > 0.0)) continue;
    const Index s = points[i].segment;
    Vec3 n = points[i].projection.normal;  // the direction the spring would push the slave
    if (pairs_.master().kind[static_cast<std::size_t>(s)] == SegmentKind::shell && pairs_.side(i) < 0) n = -n;
    const Vec3 d = g0_[i] * n;
    nodes.x.add(points[i].node, d);
    nodes.x0.add(points[i].node, d);
    largest = std::max(largest, g0_[i]);
    ++moved;
  }
  if (moved > 0) redetect_initial_penetrations(nodes);
  return moved;
}

template <class Friction>
void PenaltyPass::compute(const NodalFields& nodes, const StepTimes& times, const Friction& friction) {
  if (opt_.soft_scale > 0.0 && !(times.dt_initial > 0.0))
    throw Error("PenaltyPass::compute: SOFT = 1 needs the run's initial step (StepTimes::dt_initial)");
  // The elements of this cycle have run (and deleted what fails): a segment or slave that changed
  // activity needs a new search (the candidates of the last one may miss a new face).
  if (eroding_ && erosion_.update()) pairs_.force_search();
  pairs_.locate(nodes.x);
  parallel_for(static_cast<Index>(pairs_.slaves().size()),
               [&](Index i) { evaluate(static_cast<std::size_t>(i), nodes, times, friction); });
  Real w2 = 0.0;
  for (const PenaltyRecord& r : records_) w2 = std::max(w2, combined_step_inv2(r.dt_inv2, r.element_inv2));
  dt_ = w2 > 0.0 ? 1.0 / std::sqrt(w2) : std::numeric_limits<Real>::max();
}

/// The slave `node` against the master point it is coupled to (sum N_a x_a at the closest point,
/// or sum w_a x_a with mortar weights): relative position and velocity, and 1/m_s + sum w^2 / m_a
/// for the pair's stable step (accumulated in that order: the node rule's arithmetic of before).
inline PenaltyPass::CoupledPoint PenaltyPass::coupled_point(Index node, const Projection& pr, const Index* c,
                                                            const MortarWeights* mw, const NodalFields& nodes) {
  CoupledPoint cp{nodes.x.get(node), nodes.v.get(node), 1.0 / nodes.mass[static_cast<std::size_t>(node)]};
  const auto add = [&](Index m, Real w) {
    cp.dx -= w * nodes.x.get(m);
    cp.dv -= w * nodes.v.get(m);
    cp.inv_mass += w * w / nodes.mass[static_cast<std::size_t>(m)];
  };
  if (mw) {
    for (int a = 0; a < mw->count; ++a) add(mw->node[static_cast<std::size_t>(a)], mw->weight[static_cast<std::size_t>(a)]);
  } else {
    for (int a = 0; a < 4; ++a)
      if (pr.shape[static_cast<std::size_t>(a)] != 0.0) add(c[a], pr.shape[static_cast<std::size_t>(a)]);
  }
  return cp;
}

template <class Friction>
void PenaltyPass::evaluate(std::size_t i, const NodalFields& nodes, const StepTimes& times,
                           [[maybe_unused]] const Friction& friction) {
  PenaltyRecord& rec = records_[i];
  rec.segment = -1;
  rec.dissipation = 0.0;
  rec.dt_inv2 = 0.0;
  rec.element_inv2 = 0.0;
  const ContactPoint& point = pairs_.points()[i];
  const Index s = point.segment;
  if (s < 0) {
    gap_[i] = std::numeric_limits<Real>::infinity();
    ue_[i] = Vec3::Zero();
    if (eroding_) held_segment_[i] = -1;
    return;
  }
  const Surface& master = pairs_.master();
  const Projection& pr = point.projection;
  const std::size_t su = static_cast<std::size_t>(s);
  const Index* c = &master.conn[4 * su];
  const Index node = point.node;
  const Vec3 p = nodes.x.get(node);
  // Mortar coupling: the gap and the force act on the weighted master point sum_a w_a x_a, and
  // the spring stands for the part W of the node's tributary area that lies over the master (so
  // a node just beyond the master's edge still carries its share of the area that is over it).
  const bool mortar = !mortar_.empty() && mortar_weights(slave_surface_, static_cast<Index>(i), node, master, s,
                                                         nodes.x, mortar_[i]);
  const MortarWeights* mw = mortar ? &mortar_[i] : nullptr;
  const Real k = pair_stiffness(mw ? kappa_[su] * mw->area : k_seg_[su], nodes.mass[static_cast<std::size_t>(node)], su,
                                 times.dt_initial);
  // Spring of this pair for the step: omega^2 = k (1/m_s + sum N_a^2 / m_a); dt = 2 / omega.
  const CoupledPoint cp = coupled_point(node, pr, c, mw, nodes);
  const Real inv_m = cp.inv_mass;
  rec.dt_inv2 = 0.25 * k * inv_m;  // raised below by a stiffer stick spring
  // The elements on the pair's nodes: the spring's vote adds their 1 / dt_e^2 (element_steps_view.hpp).
  const ElementStepsView& es = times.element_steps;
  if (!es.empty())
    rec.element_inv2 = mw ? es.pair(node, mw->node.data(), mw->weight, mw->count) : es.pair(node, c, pr.shape, 4);

  const bool shell = master.kind[su] == SegmentKind::shell;
  Vec3 n = mw ? mw->normal : pr.normal;
  Real raw = mw ? n.dot(cp.dx) : pr.gap;
  // A shell's side is remembered until the slave is free again (below).
  if (shell && pairs_.orient(i, s, raw, std::numeric_limits<Real>::infinity()) < 0) {
    n = -n;
    raw = -raw;
  }
  // A point beside the segment (the closest point on an edge, the slave off to the side) or
  // deeper than its depth limit (ContactPairs::depth_limit) is not in contact with it.
  const Real lateral = (p - pr.point - pr.gap * pr.normal).norm();
  Real gap = raw - point.offset;
  // Eroding passes (docs/contact_erosion.md, "Sudden penetrations"): a slave behind a segment it
  // was not on last cycle (free then, or on another segment), deeper than the penetration it had
  // there plus twice its approach over the step, came in from the side or was laid bare inside (a
  // node out of a crater under its rim, a face uncovered in a body), not through this face: the
  // excess becomes the spring's zero, as LS-DYNA's shooting-node logic and IGNORE = 1 do, and only
  // further penetration is resisted. On a change of segment the old zero goes.
  if (eroding_ && gap < 0.0 && s != held_segment_[i] && times.dt_prev > 0.0) {
    const Real reach = std::max(Real(0), -n.dot(cp.dv)) * times.dt_prev;
    const Real before = held_segment_[i] >= 0 ? std::max(Real(0), -gap_[i]) : 0.0;
    const Real excess = -gap - before;
    g0_[i] = excess > 2.0 * reach ? excess : 0.0;
  }
  if (g0_[i] > 0.0) {
    g0_[i] = std::min(g0_[i], std::max(Real(0), -gap));
    gap += g0_[i];
  }
  gap_[i] = gap;
  const bool beside = lateral > 1e-3 * pr.size;
  const bool too_deep = raw < -pairs_.depth_limit(s, pr);
  const bool engaged = (mw || !beside) && !too_deep && (gap < 0.0 || (opt_.sliding_only && touched_[i]));
  if (!engaged) {
    ue_[i] = Vec3::Zero();
    if (!beside && gap > 0.0 && !touched_[i]) pairs_.forget_side(i);  // free: re-detect the side
    if (beside || too_deep) gap_[i] = std::numeric_limits<Real>::infinity();
    if (eroding_) held_segment_[i] = gap_[i] <= 0.0 ? s : -1;
    return;
  }
  touched_[i] = 1;
  if (eroding_) held_segment_[i] = s;
  Real fn = -k * gap;  // > 0 compressive
  Real step_factor = 1.0;
  if (opt_.viscous_damping > 0.0) {
    const Damped d = damp_normal_force(fn, k, cp, n, nodes.mass[static_cast<std::size_t>(node)]);
    fn = d.fn;
    step_factor = d.step_factor;
  }
  Vec3 f = fn * n;
  if constexpr (Friction::enabled) {
    const Real cap = friction_cap_seg_.empty() ? std::numeric_limits<Real>::infinity() : friction_cap_seg_[su];
    add_friction(i, StickInputs{n, fn, k, inv_m, slip_seg_[su], cp.dv, cap}, times, friction, rec, f);
  }
  if (step_factor < 1.0) rec.dt_inv2 /= step_factor * step_factor;
  rec.segment = s;
  rec.force = f;
  rec.shape = pr.shape;
  rec.mortar = mortar;
}

inline PenaltyPass::Damped PenaltyPass::damp_normal_force(Real fn, Real k, const CoupledPoint& cp, const Vec3& n,
                                                          Real slave_mass) const {
  // LS-DYNA's VDC: c = VDC/100 x 2 m omega, omega^2 = k (1/m_s + 1/m_m), m = min(m_s, m_m); here
  // m_m is the mass of the coupled master point (1 / sum N_a^2 / m_a).
  const Real inv_master = cp.inv_mass - 1.0 / slave_mass;
  const Real m = inv_master > 0.0 ? std::min(slave_mass, 1.0 / inv_master) : slave_mass;
  const Real omega = std::sqrt(k * cp.inv_mass);
  const Real c = opt_.viscous_damping * 2.0 * m * omega;
  const Real damped = fn - c * n.dot(cp.dv);  // n.dot(dv) > 0: separating
  // The pair's damping ratio c / (2 sqrt(k m_eff)), m_eff = 1 / inv_mass; central differences
  // with the velocity half a step behind are stable for omega dt <= 2 (sqrt(1 + zeta^2) - zeta).
  const Real zeta = opt_.viscous_damping * m * cp.inv_mass;
  return {opt_.sliding_only ? damped : std::max(Real(0), damped), std::sqrt(1.0 + zeta * zeta) - zeta};
}

/// The friction of slave i on its stick spring (Friction::enabled): adds the tangential force to
/// f, updates the elastic slip ue_[i], and raises rec.dt_inv2 for a stiffer stick spring.
template <class Friction>
void PenaltyPass::add_friction(std::size_t i, const StickInputs& in, const StepTimes& times, const Friction& law,
                               PenaltyRecord& rec, Vec3& f) {
  const Real mu_ref = std::max(law.mu_s, law.mu_k);
  if (!(mu_ref > 0.0)) return;
  const Real fn = in.fn, k = in.k;
  const Vec3& n = in.normal;
  Vec3 ft = Vec3::Zero();
  Vec3 ue = Vec3::Zero();
  if (fn > 0.0) {
    const Vec3 vt = tangential_part(in.dv, n);
    // Stick spring: DYNA3D's k_t = k, unless that lets the stick phase stretch more than
    // gamma before mu_s N (soft masters: shells); then k_t = mu_s N / gamma, so that every
    // node reaches its limit at the same elastic slip gamma whatever its share of the load
    // (no progressive slip of lightly loaded nodes), capped at 4 k (stable step at most
    // halved). The sticking point (not the force) is the history: in the N-proportional
    // range a dip of N lowers the force without dragging the point (no creep).
    const Real kt = std::min(std::max(k, mu_ref * fn / in.slip), opt_.stick_stiffness_cap * k);
    rec.dt_inv2 = 0.25 * std::max(k, kt) * in.inv_mass;
    ue = rotate_into_plane(ue_[i], n) + times.dt_prev * vt;
    // mu at the relative tangential speed (DYNA3D). Taking it at the last step's slip rate
    // instead (mu_s while sticking) lags the coefficient one step: the map F_n -> F_{n+1} then
    // oscillates with growth |a|, a = beta (mu_s - mu_k) N / (k_t dt), unstable for |a| > 1;
    // a backward-Euler slip rate is worse (unstable for a < -1/2). The relative speed feeds
    // back only through the masses.
    // VC: the limit min(mu f_n, VC A) (LS-DYNA's viscous friction), as a coefficient.
    const Real mu = std::min(law.coefficient(vt.norm()), in.cap / fn);
    const StickSpringUpdate u = stick_spring_update(ue, kt, fn, mu);
    ft = u.force;
    if (u.slipping) rec.dissipation = u.force.norm() * (ue.norm() - u.elastic_displacement.norm());
    ue = u.elastic_displacement;
  }
  ue_[i] = ue;
  f += ft;
}

inline void PenaltyPass::scatter(ContactForceView out, Vec3& slave_total, Vec3& master_total,
                                 Real& friction_work) const {
  const std::span<const Index> slaves = pairs_.slaves();
  for (std::size_t i = 0; i < slaves.size(); ++i) {
    const PenaltyRecord& r = records_[i];
    if (r.segment < 0) continue;
    out.force.add(slaves[i], r.force);
    slave_total += r.force;
    if (r.mortar) {
      const MortarWeights& mw = mortar_[i];
      for (int a = 0; a < mw.count; ++a) {
        const Vec3 fm = -mw.weight[static_cast<std::size_t>(a)] * r.force;
        out.force.add(mw.node[static_cast<std::size_t>(a)], fm);
        master_total += fm;
      }
      friction_work += r.dissipation;
      continue;
    }
    const Index* c = &pairs_.master().conn[4 * static_cast<std::size_t>(r.segment)];
    for (int a = 0; a < 4; ++a) {
      if (r.shape[a] == 0.0) continue;
      const Vec3 fm = -r.shape[a] * r.force;
      out.force.add(c[a], fm);
      master_total += fm;
    }
    friction_work += r.dissipation;
  }
}

}  // namespace slideline
