#pragma once
/// The member definitions of PenaltyPass (enforcement/penalty.hpp, which includes this file at
/// its end; include that header, not this one). Kept apart so that the class and its contract
/// read on one page.
#include "slideline/contact/enforcement/penalty.hpp"

namespace slideline {

inline void PenaltyPass::initialize(const NodalFields& nodes,
                                    const std::vector<std::unique_ptr<ElementBlock>>& blocks) {
  const Index ns = master_.segment_count();
  k_seg_.assign(static_cast<std::size_t>(ns), 0.0);
  for (Index s = 0; s < ns; ++s) {
    const SegmentStiffnessData d = segment_stiffness_data(master_, s, blocks, nodes.x);
    const bool shell = master_.kind[static_cast<std::size_t>(s)] == SegmentKind::shell;
    Real k = 0.0;
    if (shell) {
      k = d.max_diagonal > 0.0 ? d.bulk_modulus * d.face_area / d.max_diagonal : 0.0;
    } else {
      k = d.element_volume > 0.0 ? d.bulk_modulus * d.face_area * d.face_area / d.element_volume : 0.0;
    }
    k_seg_[static_cast<std::size_t>(s)] = opt_.stiffness_scale * k;
  }
  set_depth_limits(nodes, blocks);
  initialize(nodes, std::move(k_seg_));
}

/// Per master segment, the deepest contact (contact_depth_limit, search/slave_orientation.hpp).
inline void PenaltyPass::set_depth_limits(const NodalFields& nodes,
                                          const std::vector<std::unique_ptr<ElementBlock>>& blocks) {
  depth_seg_.resize(static_cast<std::size_t>(master_.segment_count()));
  for (Index s = 0; s < master_.segment_count(); ++s)
    depth_seg_[static_cast<std::size_t>(s)] = contact_depth_limit(master_, s, blocks, nodes.x);
}

inline void PenaltyPass::initialize(const NodalFields& nodes, std::vector<Real> segment_stiffness) {
  const Index ns = master_.segment_count();
  if (static_cast<Index>(segment_stiffness.size()) != ns)
    throw Error("PenaltyPass::initialize: one stiffness per master segment");
  k_seg_ = std::move(segment_stiffness);
  kappa_.clear();
  mortar_.clear();
  if (opt_.coupling == PenaltyCoupling::mortar) {
    if (slave_surface_.nodes != slaves_)
      throw Error("PenaltyPass::initialize: the mortar coupling needs the slaves' own surface");
    mortar_.assign(slaves_.size(), MortarWeights{});
    kappa_.assign(static_cast<std::size_t>(ns), 0.0);
    for (Index s = 0; s < ns; ++s) {
      const Real a = segment_area(master_, s, nodes.x);
      kappa_[static_cast<std::size_t>(s)] = a > 0.0 ? k_seg_[static_cast<std::size_t>(s)] / a : 0.0;
    }
  }
  Real min_diag = std::numeric_limits<Real>::max();
  slip_seg_.assign(static_cast<std::size_t>(ns), 0.0);
  for (Index s = 0; s < ns; ++s) {
    const Real d = segment_max_diagonal(master_, s, nodes.x);
    min_diag = std::min(min_diag, d);
    slip_seg_[static_cast<std::size_t>(s)] = opt_.elastic_slip_fraction * d;
  }
  Real max_offset = 0.0;
  for (Index s = 0; s < ns; ++s) max_offset = std::max(max_offset, master_offset(s));
  Real max_slave_offset = 0.0;
  for (Real o : slave_offset_) max_slave_offset = std::max(max_slave_offset, o);
  const Real margin = opt_.margin_fraction * min_diag + max_offset + max_slave_offset;
  BroadPhaseOptions bo;
  bo.margin = margin;
  bo.skip_incident = opt_.automatic;
  broad_->build(master_, nodes.x, bo);
  std::vector<Index> watched(slaves_);
  watched.insert(watched.end(), master_.nodes.begin(), master_.nodes.end());
  std::sort(watched.begin(), watched.end());
  watched.erase(std::unique(watched.begin(), watched.end()), watched.end());
  cadence_ = std::make_unique<SearchCadence>(watched, margin);

  const std::size_t n = slaves_.size();
  segment_.assign(n, -1);
  proj_.assign(n, SegmentProjection{});
  side_.assign(n, 0);
  touched_.assign(n, 0);
  ue_.assign(n, Vec3::Zero());
  g0_.assign(n, 0.0);
  gap_.assign(n, std::numeric_limits<Real>::infinity());
  records_.assign(n, PenaltyRecord{});
  run_begin_.assign(n, 0);
  run_end_.assign(n, 0);
  if (slave_part_.size() != n) slave_part_.assign(n, 0);
  if (opt_.automatic) {
    slave_solid_.assign(n, 1);
    for (std::size_t i = 0; i < n; ++i) {
      const auto it = std::lower_bound(master_.nodes.begin(), master_.nodes.end(), slaves_[i]);
      if (it == master_.nodes.end() || *it != slaves_[i]) continue;
      const Index row = static_cast<Index>(it - master_.nodes.begin());
      for (Index j = master_.node_segments.begin(row); j < master_.node_segments.end(row); ++j) {
        const Index s = master_.node_segments.value[static_cast<std::size_t>(j)];
        if (master_.kind[static_cast<std::size_t>(s)] == SegmentKind::shell) slave_solid_[i] = 0;
      }
    }
  }
  initial_count_ = detect_initial_penetrations(nodes, initial_max_);
}

inline Index PenaltyPass::detect_initial_penetrations(const NodalFields& nodes, Real& deepest) {
  const std::size_t n = slaves_.size();
  std::fill(g0_.begin(), g0_.end(), 0.0);
  first_ = true;
  StepTimes t0;
  compute(nodes, t0);
  Index count = 0;
  deepest = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    // Round-off of a seated start (|g| <= 1e-9 x the segment size) is not a penetration.
    const Real tol = segment_[i] >= 0 ? 1e-9 * proj_[i].projection.size : 0.0;
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
  for (std::size_t i = 0; i < slaves_.size(); ++i) {
    if (!(g0_[i] > 0.0)) continue;
    const Index s = segment_[i];
    Vec3 n = proj_[i].projection.normal;  // the direction the spring would push the slave
    if (master_.kind[static_cast<std::size_t>(s)] == SegmentKind::shell && side_[i] < 0) n = -n;
    const Vec3 d = g0_[i] * n;
    nodes.x.add(slaves_[i], d);
    nodes.x0.add(slaves_[i], d);
    largest = std::max(largest, g0_[i]);
    ++moved;
  }
  if (moved > 0) redetect_initial_penetrations(nodes);
  return moved;
}

/// Which segments slave i may meet: the orientation rule (search/slave_orientation.hpp, set by
/// the factory with set_slave_orientation) and, in the automatic pass, no self-contact of a shell
/// part (a shell node or a shell segment never meets its own part).
inline bool PenaltyPass::accepted(std::size_t i, Index s, const Vec3Field& x) const {
  const std::size_t su = static_cast<std::size_t>(s);
  if (opt_.automatic && (!slave_solid_[i] || master_.kind[su] == SegmentKind::shell) &&
      slave_part_[i] == master_.part[su])
    return false;
  return orientation_.admits(i, master_, s, x);
}

inline void PenaltyPass::search(const Vec3Field& x) {
  broad_->update(x);
  broad_->query(slaves_, x, std::span<const Real>(slave_offset_), candidates_);
  cadence_->mark_searched(x);
  const std::size_t n = slaves_.size();
  std::size_t c = 0;
  for (std::size_t i = 0; i < n; ++i) {  // candidates are grouped by node in slave order
    run_begin_[i] = c;
    while (c < candidates_.size() && candidates_[c].node == slaves_[i]) ++c;
    run_end_[i] = c;
  }
  pick_nearest_candidates(x);
}

/// Per slave: the accepted segment of its candidate run chosen by is_better_contact (over before
/// beside, then nearer, then the lower index; search/slave_orientation.hpp); a change of segment
/// resets the side memory. While the best so far is one the node is over, a candidate whose
/// corner box is already farther (cannot_beat) cannot replace it and is not projected: the same
/// pick, without most of the Newton solves of an automatic pass, whose nodes re-pick among all
/// their candidates every cycle.
inline void PenaltyPass::pick_nearest_candidates(const Vec3Field& x) {
  parallel_for(static_cast<Index>(slaves_.size()), [&](Index ii) {
    const std::size_t i = static_cast<std::size_t>(ii);
    const Vec3 p = x.get(slaves_[i]);
    SegmentProjection best;
    bool best_over = false;
    for (std::size_t k = run_begin_[i]; k < run_end_[i]; ++k) {
      const Index s = candidates_[k].segment;
      const SegmentCorners c = segment_corners(master_, s, x);
      if (best_over && cannot_beat(p, c, best.projection)) continue;  // cheaper than the filters
      if (!accepted(i, s, x)) continue;
      const Projection pr = master_.is_triangle(s) ? project_point_to_triangle(p, c) : project_point_to_quad(p, c);
      if (best.segment < 0 || is_better_contact(p, pr, s, best.projection, best.segment)) {
        best.segment = s;
        best.projection = pr;
        best_over = is_over(p, pr);
      }
    }
    if (best.segment != segment_[i]) side_[i] = 0;
    proj_[i] = best;
    segment_[i] = best.segment;
  });
}

template <class Friction>
void PenaltyPass::compute(const NodalFields& nodes, const StepTimes& times, const Friction& friction) {
  locate(nodes.x);
  parallel_for(static_cast<Index>(slaves_.size()),
               [&](Index i) { evaluate(static_cast<std::size_t>(i), nodes, times, friction); });
  Real w2 = 0.0;
  for (const PenaltyRecord& r : records_) w2 = std::max(w2, r.dt_inv2);
  dt_ = w2 > 0.0 ? 1.0 / std::sqrt(w2) : std::numeric_limits<Real>::max();
}

/// Search (when due) or local tracking: the segment and closest point of every slave.
inline void PenaltyPass::locate(const Vec3Field& x) {
  const bool due = first_ || cadence_->is_due(x);
  if (due || opt_.automatic) {
    if (due) {
      search(x);
    } else {  // automatic: the nearest accepted candidate of the still valid list
      pick_nearest_candidates(x);
    }
    first_ = false;
  } else {
    parallel_for(static_cast<Index>(slaves_.size()), [&](Index ii) {
      const std::size_t i = static_cast<std::size_t>(ii);
      if (segment_[i] < 0) return;
      proj_[i] = track_segment(x.get(slaves_[i]), segment_[i], master_, x, TrackingOptions{},
                               FacingRule{&orientation_, i, &master_, &x});
      if (proj_[i].segment != segment_[i]) {
        if (master_.kind[static_cast<std::size_t>(proj_[i].segment)] !=
            master_.kind[static_cast<std::size_t>(segment_[i])])
          side_[i] = 0;
        segment_[i] = proj_[i].segment;
      }
    });
  }
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
  const Index s = segment_[i];
  if (s < 0) {
    gap_[i] = std::numeric_limits<Real>::infinity();
    ue_[i] = Vec3::Zero();
    return;
  }
  const Projection& pr = proj_[i].projection;
  const std::size_t su = static_cast<std::size_t>(s);
  const Index* c = &master_.conn[4 * su];
  const Index node = slaves_[i];
  const Vec3 p = nodes.x.get(node);
  // Mortar coupling: the gap and the force act on the weighted master point sum_a w_a x_a, and
  // the spring stands for the part W of the node's tributary area that lies over the master (so
  // a node just beyond the master's edge still carries its share of the area that is over it).
  const bool mortar = !mortar_.empty() && mortar_weights(slave_surface_, static_cast<Index>(i), node, master_, s,
                                                         nodes.x, mortar_[i]);
  const MortarWeights* mw = mortar ? &mortar_[i] : nullptr;
  const Real k = mw ? kappa_[su] * mw->area : k_seg_[su];
  // Spring of this pair for the step: omega^2 = k (1/m_s + sum N_a^2 / m_a); dt = 2 / omega.
  const CoupledPoint cp = coupled_point(node, pr, c, mw, nodes);
  const Real inv_m = cp.inv_mass;
  rec.dt_inv2 = 0.25 * k * inv_m;  // raised below by a stiffer stick spring

  const bool shell = master_.kind[su] == SegmentKind::shell;
  Vec3 n = mw ? mw->normal : pr.normal;
  Real raw = mw ? n.dot(cp.dx) : pr.gap;
  if (shell) {
    if (side_[i] == 0) side_[i] = raw >= 0.0 ? 1 : -1;
    if (side_[i] < 0) {
      n = -n;
      raw = -raw;
    }
  }
  // A point beside the segment (the closest point on an edge, the slave off to the side) or
  // deeper than its depth limit (set_depth_limits) is not in contact with it.
  const Real lateral = (p - pr.point - pr.gap * pr.normal).norm();
  const Real offsets = master_offset(s) + slave_offset_[i];
  Real gap = raw - offsets;
  if (g0_[i] > 0.0) {
    g0_[i] = std::min(g0_[i], std::max(Real(0), -gap));
    gap += g0_[i];
  }
  gap_[i] = gap;
  const bool beside = lateral > 1e-3 * pr.size;
  const bool too_deep = raw < -(depth_seg_.empty() ? 0.5 * pr.size : depth_seg_[su]);
  const bool engaged = (mw || !beside) && !too_deep && (gap < 0.0 || (opt_.sliding_only && touched_[i]));
  if (!engaged) {
    ue_[i] = Vec3::Zero();
    if (!beside && gap > 0.0 && !touched_[i]) side_[i] = 0;  // free: re-detect the side
    if (beside || too_deep) gap_[i] = std::numeric_limits<Real>::infinity();
    return;
  }
  touched_[i] = 1;
  const Real fn = -k * gap;  // > 0 compressive
  Vec3 f = fn * n;
  if constexpr (Friction::enabled) {
    const Friction& law = friction;
    const Real mu_ref = std::max(law.mu_s, law.mu_k);
    if (mu_ref > 0.0) {
      Vec3 ft = Vec3::Zero();
      Vec3 ue = Vec3::Zero();
      if (fn > 0.0) {
        const Vec3 vrel = cp.dv;
        const Vec3 vt = tangential_part(vrel, n);
        // Stick spring: DYNA3D's k_t = k, unless that lets the stick phase stretch more than
        // gamma before mu_s N (soft masters: shells); then k_t = mu_s N / gamma, so that every
        // node reaches its limit at the same elastic slip gamma whatever its share of the load
        // (no progressive slip of lightly loaded nodes), capped at 4 k (stable step at most
        // halved). The sticking point (not the force) is the history: in the N-proportional
        // range a dip of N lowers the force without dragging the point (no creep).
        const Real kt = std::min(std::max(k, mu_ref * fn / slip_seg_[su]), opt_.stick_stiffness_cap * k);
        rec.dt_inv2 = 0.25 * std::max(k, kt) * inv_m;
        ue = rotate_into_plane(ue_[i], n) + times.dt_prev * vt;
        // mu at the relative tangential speed (DYNA3D). Taking it at the last step's slip rate
        // instead (mu_s while sticking) lags the coefficient one step: the map F_n -> F_{n+1} then
        // oscillates with growth |a|, a = beta (mu_s - mu_k) N / (k_t dt), unstable for |a| > 1;
        // a backward-Euler slip rate is worse (unstable for a < -1/2). The relative speed feeds
        // back only through the masses.
        const StickSpringUpdate u = stick_spring_update(ue, kt, fn, law.coefficient(vt.norm()));
        ft = u.force;
        if (u.slipping) rec.dissipation = u.force.norm() * (ue.norm() - u.elastic_displacement.norm());
        ue = u.elastic_displacement;
      }
      ue_[i] = ue;
      f += ft;
    }
  }
  rec.segment = s;
  rec.force = f;
  rec.shape = pr.shape;
  rec.mortar = mortar;
}

inline void PenaltyPass::scatter(ContactForceView out, Vec3& slave_total, Vec3& master_total,
                                 Real& friction_work) const {
  for (std::size_t i = 0; i < slaves_.size(); ++i) {
    const PenaltyRecord& r = records_[i];
    if (r.segment < 0) continue;
    out.force.add(slaves_[i], r.force);
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
    const Index* c = &master_.conn[4 * static_cast<std::size_t>(r.segment)];
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
