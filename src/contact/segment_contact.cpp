// Segment-based penalty contact (SOFT = 2): contact/segment_contact.hpp, docs/contact.md
// "Segment-based contact (SOFT = 2)".
#include "slideline/contact/segment_contact.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "slideline/contact/search/closest_point.hpp"
#include "slideline/core/error.hpp"
#include "slideline/core/parallel.hpp"
#include "slideline/mesh/segment_geometry.hpp"

namespace slideline {

namespace {

constexpr Real kGauss = 0.57735026918962576;  // 1 / sqrt(3)
constexpr Real kXi[4] = {-kGauss, kGauss, kGauss, -kGauss};
constexpr Real kEta[4] = {-kGauss, -kGauss, kGauss, kGauss};

/// |dx/dxi x dx/deta| of the bilinear map of corners c at (xi, eta) (length^2).
Real jacobian(const SegmentCorners& c, Real xi, Real eta) {
  const Vec3 dxi = 0.25 * ((1 - eta) * (c[1] - c[0]) + (1 + eta) * (c[2] - c[3]));
  const Vec3 deta = 0.25 * ((1 - xi) * (c[3] - c[0]) + (1 + xi) * (c[2] - c[1]));
  return dxi.cross(deta).norm();
}

bool share_node(const Index* a, const Index* b) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      if (a[i] == b[j]) return true;
  return false;
}

}  // namespace

SegmentContact::SegmentContact(std::string title, Surface surface, std::vector<std::uint8_t> sides,
                               std::unique_ptr<BroadPhase> broad_phase, Real stiffness_scale)
    : name_(std::move(title)),
      surface_(std::move(surface)),
      side_(std::move(sides)),
      broad_phase_(std::move(broad_phase)),
      scale_(stiffness_scale) {
  if (side_.size() != static_cast<std::size_t>(surface_.segment_count()))
    throw Error("SegmentContact: one side mask per segment");
}

void SegmentContact::set_offsets(std::vector<Real> offsets) {
  if (offsets.size() != side_.size()) throw Error("SegmentContact: one offset per segment");
  offset_ = std::move(offsets);
  max_offset_ = 0.0;
  for (Real o : offset_) max_offset_ = std::max(max_offset_, o);
}

void SegmentContact::set_single_surface(std::vector<Id> parts) {
  parts_ = std::move(parts);
  const std::size_t n = parts_.size();
  transmitted_.assign(n >= 2 ? n * (n - 1) / 2 : 0, Vec3::Zero());
}

void SegmentContact::set_friction(const ExponentialCoulomb& law, Real viscous_damping) {
  friction_ = law;
  frictional_ = std::max(law.mu_s, law.mu_k) > 0.0;
  viscous_damping_ = viscous_damping;
}

void SegmentContact::append_output_names(std::vector<std::string>& names) const {
  if (transmitted_.size() == 1) {
    names.emplace_back("transmitted_force");
    return;
  }
  for (std::size_t a = 0; a < parts_.size(); ++a)
    for (std::size_t b = a + 1; b < parts_.size(); ++b)
      names.push_back("transmitted_force/" + std::to_string(parts_[a]) + "_" + std::to_string(parts_[b]));
}

void SegmentContact::write_output_values(std::span<Real> out) const {
  for (std::size_t k = 0; k < transmitted_.size(); ++k)
    for (int c = 0; c < 3; ++c) out[3 * k + static_cast<std::size_t>(c)] = transmitted_[k][c];
}

void SegmentContact::initialize(const ContactContext& context) {
  const NodalFields& nodes = context.nodes;
  const Index ns = surface_.segment_count();
  const auto n = static_cast<std::size_t>(ns);
  mass_.assign(n, 0.0);
  depth_limit_.assign(n, 0.0);
  for (Index s = 0; s < ns; ++s) {
    const Index* c = &surface_.conn[4 * static_cast<std::size_t>(s)];
    Real m = 0.0;
    for (int a = 0; a < 4; ++a)
      if (a < 3 || c[3] != c[2]) m += nodes.mass[static_cast<std::size_t>(c[a])];  // a triangle's node once
    mass_[static_cast<std::size_t>(s)] = m;
    depth_limit_[static_cast<std::size_t>(s)] = 0.5 * segment_max_diagonal(surface_, s, nodes.x);
  }
  index_.resize(n);
  for (Index s = 0; s < ns; ++s) index_[static_cast<std::size_t>(s)] = s;
  centroid_.resize(n);
  normal_.resize(n);
  radius_.assign(n, 0.0);
  first_.assign(n + 1, 0);
  records_.assign(4 * n, SegmentContactRecord{});
  baseline_.assign(4 * n, 0.0);
  memory_.assign(4 * n, 0);
  memory_of_.assign(4 * n, -1);
  slip_.assign(frictional_ ? 4 * n : 0, Vec3::Zero());
  slip_on_.assign(frictional_ ? 4 * n : 0, -1);
  friction_work_ = 0.0;
  BroadPhaseOptions o;
  o.margin = 0.0;  // the allowance goes on the query boxes (search_ahead), the segment boxes stay tight
  broad_phase_->build(surface_, nodes.x, o);
  candidates_.reserve(16 * n);
  box_.assign(interval_ > 1 ? n : 0, Aabb{});
  query_radius_.assign(interval_ > 1 ? n : 0, 0.0);
  if (interval_ > 1) watch_ = SearchCadence(surface_.nodes, 1.0);  // its max_displacement only
  Real half_diagonals = 0.0;
  for (Real d : depth_limit_) half_diagonals += d;
  allowance_floor_ = ns > 0 ? 1e-3 * half_diagonals / static_cast<Real>(ns) : 0.0;
  allowance_ = 0.0;
  searches_ = 0;
  update_geometry(nodes.x);
  search(nodes.x, 0.0);      // exact: the baseline below
  since_search_ = interval_;  // the first cycle searches with its allowance
  // LS-DYNA's SOFT = 2 keeps what penetrates at t = 0 as the baseline (no node is moved).
  for (Index a = 0; a < ns; ++a) evaluate(a, nodes, true, 0.0);
  initial_count_ = 0;
  initial_max_ = 0.0;
  for (Real d : baseline_)
    if (d > 0.0) {
      ++initial_count_;
      initial_max_ = std::max(initial_max_, d);
    }
  std::fill(records_.begin(), records_.end(), SegmentContactRecord{});
  if (initial_count_ > 0)
    warn(context.diagnostics, "contact '%s': %ld segment Gauss point(s) penetrating at t = 0, deepest %.6g: kept as "
                              "the baseline (SOFT = 2)",
         name_.c_str(), static_cast<long>(initial_count_), initial_max_);
}

void SegmentContact::set_search_interval(int cycles) {
  if (cycles < 0) throw Error("SegmentContact: the search interval (BSORT) must not be negative");
  interval_ = cycles == 0 ? kDefaultSearchInterval : cycles;
}

void SegmentContact::update_geometry(const Vec3Field& x) {
  const bool boxes = !box_.empty();
  parallel_for(surface_.segment_count(), [&](Index s) {
    const SegmentCorners c = segment_corners(surface_, s, x);
    const Vec3 m = 0.25 * (c[0] + c[1] + c[2] + c[3]);
    Real r = 0.0;
    for (const Vec3& p : c) r = std::max(r, (p - m).norm());
    centroid_.set(s, m);
    normal_.set(s, segment_normal(surface_, s, x));
    // A shell's contact surface lies o_s off its mid-surface; the other segment's o_b <= max.
    if (!offset_.empty()) r += offset_[static_cast<std::size_t>(s)] + max_offset_;
    radius_[static_cast<std::size_t>(s)] = r;
    if (boxes) {  // the broad phase's box of s (BroadPhase::compute_boxes, margin 0), bit for bit
      Aabb b;
      for (const Vec3& p : c) b.expand(p);
      box_[static_cast<std::size_t>(s)] = b;
    }
  });
}

void SegmentContact::search(const Vec3Field& x, Real inflation) {
  broad_phase_->update(x);
  inflated_ = inflation > 0.0;
  if (inflated_) {
    for (std::size_t s = 0; s < radius_.size(); ++s) query_radius_[s] = radius_[s] + inflation;
    broad_phase_->query(index_, centroid_, query_radius_, candidates_);
  } else {
    broad_phase_->query(index_, centroid_, radius_, candidates_);
  }
  ++searches_;
  if (admit_.size() < candidates_.size()) admit_.resize(candidates_.capacity());  // grows as candidates_ does
  std::fill(first_.begin(), first_.end(), 0);
  for (const Candidate& c : candidates_) ++first_[static_cast<std::size_t>(c.node) + 1];
  for (std::size_t s = 0; s + 1 < first_.size(); ++s) first_[s + 1] += first_[s];
}

void SegmentContact::search_ahead(const NodalFields& nodes, Real dt) {
  // The allowance a: 1.5 x the distance the fastest surface node covers in BSORT steps at its
  // present speed (a floor a_min for bodies at rest). Candidates: the boxes around each segment's
  // sphere grown by 5 a. Until a node has moved a, the every-cycle search's pairs are among them:
  // a segment's centre moves < a, its radius grows < 2 a, the other's box grows < a: 4 a < 5 a,
  // the 1 a left over for round-off (a >= a_min = 1e-3 x the mean half diagonal).
  Real v2 = 0.0;
  for (Index i : surface_.nodes) v2 = std::max(v2, nodes.v.get(i).squaredNorm());
  const Real step = dt > 0.0 && std::isfinite(dt) ? dt : dt_c_;
  allowance_ = std::max(1.5 * std::sqrt(v2) * step * static_cast<Real>(interval_), allowance_floor_);
  search(nodes.x, 5.0 * allowance_);
  watch_.mark_searched(nodes.x);
  since_search_ = 0;
}

void SegmentContact::evaluate(Index a, const NodalFields& nodes, bool baseline, Real dt_prev) {
  const auto au = static_cast<std::size_t>(a);
  const Index* ca = &surface_.conn[4 * au];
  const SegmentCorners xa = segment_corners(surface_, a, nodes.x);
  const Vec3 na = normal_.get(a);
  Real jac[4], area = 0.0;
  for (int q = 0; q < 4; ++q) area += (jac[q] = jacobian(xa, kXi[q], kEta[q]));
  const bool a_shell = surface_.kind[au] == SegmentKind::shell;
  const Real o_a = offset_.empty() ? 0.0 : offset_[au];
  // The candidates a may meet, whatever the Gauss point (flags admit_, a's range only): of an
  // inflated search, those passing the every-cycle search's box test on this cycle's boxes; then
  // the other side, no shared node, not a's element, facing.
  const Aabb reach = inflated_ ? Aabb::around(centroid_.get(a), radius_[au]) : Aabb{};
  for (Index k = first_[au]; k < first_[au + 1]; ++k) {
    const auto ku = static_cast<std::size_t>(k);
    admit_[ku] = 0;
    const Index b = candidates_[ku].segment;
    const auto bu = static_cast<std::size_t>(b);
    if (inflated_ && !reach.overlaps(box_[bu])) continue;
    const bool cross = ((side_[au] & 1) && (side_[bu] & 2)) || ((side_[au] & 2) && (side_[bu] & 1));
    if (!cross || b == a || share_node(ca, &surface_.conn[4 * bu])) continue;
    // Faces of one element never meet (a one-element-thick layer's top and bottom share no node).
    if (surface_.element[au] == surface_.element[bu] && surface_.block[au] == surface_.block[bu]) continue;
    const bool b_shell = surface_.kind[bu] == SegmentKind::shell;
    const Real nn = na.dot(normal_.get(b));
    // a must face b: normals within 60 deg of opposite. A point of a face that meets b only
    // at b's edge (a side face beside an end face, n_a . n_b ~ 0) would otherwise read the
    // distance to b's plane as a penetration (x_b - x_q = d n_b, so (x_b - x_q) . n_a < -d / 2
    // is the same test: b's point lies inside a as well). A shell has two sides: within 60 deg
    // of parallel or opposite, the side checked below once it is known.
    if (!a_shell && !b_shell) {
      if (!(nn < -0.5)) continue;
    } else if (!(std::abs(nn) > 0.5)) {
      continue;
    }
    admit_[ku] = 1;
  }
  for (int q = 0; q < 4; ++q) {
    const std::size_t g = 4 * au + static_cast<std::size_t>(q);
    SegmentContactRecord& rec = records_[g];
    rec = SegmentContactRecord{};
    const std::array<Real, 4> shape_a = detail::bilinear_shape(kXi[q], kEta[q]);
    const Vec3 p = detail::combine(xa, shape_a);
    // The least-penetrated admitted segment that the point lies over.
    Index best = -1;
    Projection best_pr;
    Real best_raw = 0.0;
    int best_side = 1;
    for (Index k = first_[au]; k < first_[au + 1]; ++k) {
      if (!admit_[static_cast<std::size_t>(k)]) continue;
      const Index b = candidates_[static_cast<std::size_t>(k)].segment;
      const auto bu = static_cast<std::size_t>(b);
      const bool b_shell = surface_.kind[bu] == SegmentKind::shell;
      const Real nn = na.dot(normal_.get(b));
      // Every point of b lies within radius_[b] of its centre (a convex combination of its
      // corners), and b is met only by a point within |g| <= max(half diagonal, o_a + o_b) of it,
      // 1e-3 of its diagonal (< 2 radius_[b]) aside: a point farther from b's centre cannot pass
      // the tests below, so it is not projected (the same outcome, without the Newton solve).
      const Real o_b = offset_.empty() ? 0.0 : offset_[bu];
      const Real within = radius_[bu] * (1.0 + 2e-3) + std::max(depth_limit_[bu], o_a + o_b);
      if ((p - centroid_.get(b)).squaredNorm() > within * within * (1.0 + 1e-6)) continue;  // 1e-6: round-off
      const Projection pr = project_point_to_segment(p, surface_, b, nodes.x);
      const Real lateral = (p - pr.point - pr.gap * pr.normal).norm();
      if (lateral > 1e-3 * pr.size) continue;  // beside b
      Real raw = -pr.gap;
      int side = 1;
      if (b_shell || o_a > 0.0) {
        const Real o = o_a + (offset_.empty() ? 0.0 : offset_[bu]);
        if (b_shell) {  // the side of b's mid-surface: remembered while within o of it
          side = pr.gap >= 0.0 ? 1 : -1;
          if (memory_[g] != 0 && std::abs(pr.gap) < o) {
            // Remembered on b, or on a shell segment next to b (sharing a node) that the point has
            // slid off: the side carries over, in b's orientation (a shell's normal may point
            // either way, so a neighbour's may be opposite).
            const Index m = memory_of_[g];
            if (m == b)
              side = memory_[g];
            else if (share_node(&surface_.conn[4 * static_cast<std::size_t>(m)], &surface_.conn[4 * bu]))
              side = normal_.get(m).dot(normal_.get(b)) >= 0.0 ? memory_[g] : -memory_[g];
          }
          if (!a_shell && !(side * nn < -0.5)) continue;  // a solid face must face b's side
        } else if (!(pr.gap > -o_a)) {
          // A shell's mid-surface at most o_a behind a solid face (penetration < 2 o_a, as a solid
          // face's behind a shell's mid-surface is bounded by the side memory): deeper, the point
          // would read the far face of a thin solid (its top, seen from a shell under it) as met.
          continue;
        }
        raw = o - side * pr.gap;
      }
      if (!(raw > 0.0) || side * pr.gap < -depth_limit_[bu]) continue;  // not into b, or through it
      if (best < 0 || raw < best_raw) {
        best = b;
        best_pr = pr;
        best_raw = raw;
        best_side = side;
      }
    }
    // The side memory follows the pair; a point in contact with nothing reads its side again.
    if (best >= 0 && surface_.kind[static_cast<std::size_t>(best)] == SegmentKind::shell) {
      memory_of_[g] = best;
      memory_[g] = static_cast<std::int8_t>(best_side);
    } else {
      memory_of_[g] = -1;
      memory_[g] = 0;
    }
    // The stick spring's segment: set again below while the point stays in contact.
    const Index held = frictional_ ? slip_on_[g] : -1;
    if (frictional_) slip_on_[g] = -1;
    if (best < 0) continue;
    const Real raw = best_raw;  // > 0
    Real& d0 = baseline_[g];
    if (baseline) {
      if (raw > 1e-9 * best_pr.size) d0 = raw;
      continue;
    }
    if (d0 > 0.0) d0 = std::min(d0, raw);  // separating: the baseline follows (LS-DYNA)
    const Real d = raw - d0;
    if (!(d > 0.0)) continue;
    const auto bu = static_cast<std::size_t>(best);
    const Index* cb = &surface_.conn[4 * bu];
    const Real ma = mass_[au], mb = mass_[bu];
    const Real k = 0.5 * scale_ * ma * mb / (ma + mb) / (dt_c_ * dt_c_);
    rec.other = best;
    rec.weight = 0.5 * jac[q] / area;
    rec.penetration = d;
    rec.stiffness = k;
    rec.shape_a = shape_a;
    rec.shape_b = best_pr.shape;
    rec.side = best_side;
    rec.force = best_side > 0 ? Vec3(rec.weight * k * d * best_pr.normal)
                              : Vec3(-(rec.weight * k * d) * best_pr.normal);
    // The point's spring between a's and b's interpolated points: omega^2 = k_q sum N^2 / m.
    Real inv_m = 0.0;
    for (int i = 0; i < 4; ++i) {
      inv_m += shape_a[static_cast<std::size_t>(i)] * shape_a[static_cast<std::size_t>(i)] /
               nodes.mass[static_cast<std::size_t>(ca[i])];
      inv_m += best_pr.shape[static_cast<std::size_t>(i)] * best_pr.shape[static_cast<std::size_t>(i)] /
               nodes.mass[static_cast<std::size_t>(cb[i])];
    }
    rec.dt_inv2 = 0.25 * rec.weight * k * inv_m;
    rec.normal_force = rec.weight * k * d;
    if (frictional_ || viscous_damping_ > 0.0)
      add_damping_and_friction(g, held, rec, best_side > 0 ? Vec3(best_pr.normal) : Vec3(-best_pr.normal), ca, cb,
                               inv_m, nodes, dt_prev);
  }
}

void SegmentContact::add_damping_and_friction(std::size_t g, Index held, SegmentContactRecord& rec, const Vec3& n,
                                              const Index* ca, const Index* cb, Real inv_m, const NodalFields& nodes,
                                              Real dt_prev) {
  // Relative velocity of a's point against b's (v^{n-1/2}).
  Vec3 dv = Vec3::Zero();
  Real inv_a = 0.0;
  for (int i = 0; i < 4; ++i) {
    const auto iu = static_cast<std::size_t>(i);
    dv += rec.shape_a[iu] * nodes.v.get(ca[i]) - rec.shape_b[iu] * nodes.v.get(cb[i]);
    inv_a += rec.shape_a[iu] * rec.shape_a[iu] / nodes.mass[static_cast<std::size_t>(ca[i])];
  }
  const Real kq = rec.weight * rec.stiffness;  // the point's normal spring (force / length)
  Real fn = rec.normal_force;
  if (viscous_damping_ > 0.0) {
    // LS-DYNA's VDC as on the penalty passes: c = VDC/100 x 2 m omega, omega^2 = k_q (1/m_a + 1/m_b),
    // m the smaller of the two points' masses (1 / sum N^2 / m); the normal force stays >= 0.
    const Real inv_b = inv_m - inv_a;
    const Real m = std::min(1.0 / inv_a, inv_b > 0.0 ? 1.0 / inv_b : 1.0 / inv_a);
    const Real c = viscous_damping_ * 2.0 * m * std::sqrt(kq * inv_m);
    fn = std::max(Real(0), fn - c * n.dot(dv));  // n . dv > 0: separating
    // Central differences with the velocity half a step behind: omega dt <= 2 (sqrt(1 + z^2) - z).
    const Real zeta = viscous_damping_ * m * inv_m;
    const Real factor = std::sqrt(1.0 + zeta * zeta) - zeta;
    rec.dt_inv2 /= factor * factor;
  }
  rec.normal_force = fn;
  rec.force = fn * n;
  if (!frictional_) return;
  // Friction: a stick spring k_t = k_q from the sticking point (kept while the point stays in
  // contact, also as it slides from one segment b onto the next: released there, the friction
  // would drop for the steps the spring takes to stretch again), the exponential Coulomb law at
  // the tangential slip speed.
  const Vec3 vt = tangential_part(dv, n);
  const Vec3 ue = (held >= 0 ? rotate_into_plane(slip_[g], n) : Vec3(Vec3::Zero())) + dt_prev * vt;
  const StickSpringUpdate u = stick_spring_update(ue, kq, fn, friction_.coefficient(vt.norm()));
  if (u.slipping) rec.dissipation = u.force.norm() * (ue.norm() - u.elastic_displacement.norm());
  slip_[g] = u.elastic_displacement;
  slip_on_[g] = rec.other;
  rec.friction = u.force;
  rec.force += u.force;
}

void SegmentContact::apply_forces(const NodalFields& nodes, const StepTimes& times, ContactForceView out) {
  if (dt_c_ == 0.0) {
    if (!(times.dt_initial > 0.0 && std::isfinite(times.dt_initial)))
      throw Error("SegmentContact: SOFT = 2 needs the run's initial step (StepTimes::dt_initial)");
    dt_c_ = times.dt_initial;
  }
  // LS-DYNA: the step the springs are sized by follows the step when that grows more than 5 %
  // (dt_prev: the step just taken; the coming one is not known while the interfaces vote).
  if (times.dt_prev > 1.05 * dt_c_) dt_c_ = times.dt_prev;
  update_geometry(nodes.x);
  if (interval_ <= 1)
    search(nodes.x, 0.0);
  else if (++since_search_ >= interval_ || watch_.max_displacement(nodes.x) >= allowance_)
    search_ahead(nodes, times.dt_prev);
  parallel_for(surface_.segment_count(), [&](Index a) { evaluate(a, nodes, false, times.dt_prev); });
  scatter(out, times.element_steps);
}

void SegmentContact::add_transmitted(Id on, Id from, const Vec3& force) {
  // rec.force acts on a's part (`on`), its opposite on b's (`from`); pair k = (parts_[i], parts_[j]),
  // i < j, holds the force of parts_[j] on parts_[i].
  if (on == from) return;
  const auto index = [&](Id part) {
    return static_cast<std::size_t>(std::lower_bound(parts_.begin(), parts_.end(), part) - parts_.begin());
  };
  const std::size_t i = index(std::min(on, from)), j = index(std::max(on, from));
  if (j >= parts_.size()) return;
  const std::size_t n = parts_.size();
  const std::size_t k = i * n - i * (i + 1) / 2 + (j - i - 1);
  if (on < from)
    transmitted_[k] += force;
  else
    transmitted_[k] -= force;
}

void SegmentContact::scatter(ContactForceView out, const ElementStepsView& elements) {
  slave_ = Vec3::Zero();
  for (Vec3& t : transmitted_) t.setZero();
  Real w2 = 0.0;
  for (std::size_t r = 0; r < records_.size(); ++r) {
    const SegmentContactRecord& rec = records_[r];
    if (rec.other < 0) continue;
    const std::size_t a = r / 4;
    const Index* ca = &surface_.conn[4 * a];
    const Index* cb = &surface_.conn[4 * static_cast<std::size_t>(rec.other)];
    for (int i = 0; i < 4; ++i) {
      const auto iu = static_cast<std::size_t>(i);
      if (rec.shape_a[iu] != 0.0) out.force.add(ca[i], rec.shape_a[iu] * rec.force);
      if (rec.shape_b[iu] != 0.0) out.force.add(cb[i], -rec.shape_b[iu] * rec.force);
    }
    // Only cross pairs: a on the master side alone means b is on the slave side.
    if (side_[a] == 2)
      slave_ -= rec.force;
    else
      slave_ += rec.force;
    // The spring's vote with the elements on the nodes it joins (element_steps_view.hpp).
    const Real e2 =
        elements.empty() ? 0.0 : std::max(elements.largest(ca, rec.shape_a, 4), elements.largest(cb, rec.shape_b, 4));
    w2 = std::max(w2, combined_step_inv2(rec.dt_inv2, e2));
    friction_work_ += rec.dissipation;
    if (!transmitted_.empty())
      add_transmitted(surface_.part[a], surface_.part[static_cast<std::size_t>(rec.other)], rec.force);
  }
  dt_ = w2 > 0.0 ? 1.0 / std::sqrt(w2) : std::numeric_limits<Real>::max();
}

}  // namespace slideline
