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
  BroadPhaseOptions o;
  o.margin = 0.0;  // a new search every cycle
  broad_phase_->build(surface_, nodes.x, o);
  candidates_.reserve(16 * n);
  search(nodes.x);
  // LS-DYNA's SOFT = 2 keeps what penetrates at t = 0 as the baseline (no node is moved).
  for (Index a = 0; a < ns; ++a) evaluate(a, nodes, true);
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

void SegmentContact::search(const Vec3Field& x) {
  const Index ns = surface_.segment_count();
  for (Index s = 0; s < ns; ++s) {
    const SegmentCorners c = segment_corners(surface_, s, x);
    const Vec3 m = 0.25 * (c[0] + c[1] + c[2] + c[3]);
    Real r = 0.0;
    for (const Vec3& p : c) r = std::max(r, (p - m).norm());
    centroid_.set(s, m);
    normal_.set(s, segment_normal(surface_, s, x));
    radius_[static_cast<std::size_t>(s)] = r;
  }
  broad_phase_->update(x);
  broad_phase_->query(index_, centroid_, radius_, candidates_);
  std::fill(first_.begin(), first_.end(), 0);
  for (const Candidate& c : candidates_) ++first_[static_cast<std::size_t>(c.node) + 1];
  for (std::size_t s = 0; s + 1 < first_.size(); ++s) first_[s + 1] += first_[s];
}

void SegmentContact::evaluate(Index a, const NodalFields& nodes, bool baseline) {
  const auto au = static_cast<std::size_t>(a);
  const Index* ca = &surface_.conn[4 * au];
  const SegmentCorners xa = segment_corners(surface_, a, nodes.x);
  const Vec3 na = normal_.get(a);
  Real jac[4], area = 0.0;
  for (int q = 0; q < 4; ++q) area += (jac[q] = jacobian(xa, kXi[q], kEta[q]));
  for (int q = 0; q < 4; ++q) {
    SegmentContactRecord& rec = records_[4 * au + static_cast<std::size_t>(q)];
    rec = SegmentContactRecord{};
    const std::array<Real, 4> shape_a = detail::bilinear_shape(kXi[q], kEta[q]);
    const Vec3 p = detail::combine(xa, shape_a);
    // The nearest admitted segment of the other side that the point lies over.
    Index best = -1;
    Projection best_pr;
    for (Index k = first_[au]; k < first_[au + 1]; ++k) {
      const Index b = candidates_[static_cast<std::size_t>(k)].segment;
      const auto bu = static_cast<std::size_t>(b);
      const bool cross = ((side_[au] & 1) && (side_[bu] & 2)) || ((side_[au] & 2) && (side_[bu] & 1));
      if (!cross || b == a || share_node(ca, &surface_.conn[4 * bu])) continue;
      // a must face b: normals within 60 deg of opposite. A point of a face that meets b only
      // at b's edge (a side face beside an end face, n_a . n_b ~ 0) would otherwise read the
      // distance to b's plane as a penetration (x_b - x_q = d n_b, so (x_b - x_q) . n_a < -d / 2
      // is the same test: b's point lies inside a as well).
      if (!(na.dot(normal_.get(b)) < -0.5)) continue;
      const Projection pr = project_point_to_segment(p, surface_, b, nodes.x);
      const Real lateral = (p - pr.point - pr.gap * pr.normal).norm();
      if (lateral > 1e-3 * pr.size) continue;                              // beside b
      if (!(pr.gap < 0.0) || -pr.gap > depth_limit_[bu]) continue;          // not into b, or through it
      if (best < 0 || -pr.gap < -best_pr.gap) {
        best = b;
        best_pr = pr;
      }
    }
    if (best < 0) continue;
    const Real raw = -best_pr.gap;  // > 0
    Real& d0 = baseline_[4 * au + static_cast<std::size_t>(q)];
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
    rec.force = rec.weight * k * d * best_pr.normal;
    // The point's spring between a's and b's interpolated points: omega^2 = k_q sum N^2 / m.
    Real inv_m = 0.0;
    for (int i = 0; i < 4; ++i) {
      inv_m += shape_a[static_cast<std::size_t>(i)] * shape_a[static_cast<std::size_t>(i)] /
               nodes.mass[static_cast<std::size_t>(ca[i])];
      inv_m += best_pr.shape[static_cast<std::size_t>(i)] * best_pr.shape[static_cast<std::size_t>(i)] /
               nodes.mass[static_cast<std::size_t>(cb[i])];
    }
    rec.dt_inv2 = 0.25 * rec.weight * k * inv_m;
  }
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
  search(nodes.x);
  parallel_for(surface_.segment_count(), [&](Index a) { evaluate(a, nodes, false); });
  scatter(out);
}

void SegmentContact::scatter(ContactForceView out) {
  slave_ = Vec3::Zero();
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
    w2 = std::max(w2, rec.dt_inv2);
  }
  dt_ = w2 > 0.0 ? 1.0 / std::sqrt(w2) : std::numeric_limits<Real>::max();
}

}  // namespace slideline
