// *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK OPTION 1 and 3: ties formed at t = 0 and at each
// node's first touch, then (OPTION 3) the stress criterion per node and the automatic pass. See
// include/slideline/contact/sticking_tiebreak_contact.hpp.
#include "slideline/contact/sticking_tiebreak_contact.hpp"

#include <algorithm>
#include <cmath>

#include "slideline/contact/search/tie_offset.hpp"
#include "slideline/mesh/segment_geometry.hpp"

namespace slideline {

namespace {

bool contains(const std::vector<Index>& sorted, Index i) { return std::binary_search(sorted.begin(), sorted.end(), i); }

}  // namespace

void StickingTiebreakContact::initialize(const ContactContext& c) {
  const NodalFields& nodes = c.nodes;
  // The pass first sees every pair (nothing held): each node's penetration at t = 0 becomes its
  // spring's zero (IGNORE = 1), a tied node's included, as OPTION 2.
  std::fill(held_node_.begin(), held_node_.end(), std::uint8_t{0});
  std::fill(held_segment_.begin(), held_segment_.end(), std::uint8_t{0});
  contact_->initialize(c);

  const Surface& surface = pass_->master();
  const Index nseg = surface.segment_count();
  kappa_.assign(static_cast<std::size_t>(nseg), 0.0);
  for (Index s = 0; s < nseg; ++s) {
    const Real a = segment_area(surface, s, nodes.x);
    kappa_[static_cast<std::size_t>(s)] = a > 0.0 ? pass_->segment_stiffness(s) / a : 0.0;
  }

  const std::span<const Index> slaves = pass_->slaves();
  const std::size_t n = slaves.size();
  state_.assign(n, State::never);
  tie_.assign(n, TiePoint{});
  area_.assign(n, 0.0);
  k_.assign(n, 0.0);
  kc_.assign(n, 0.0);
  tie_time_.assign(n, -1.0);
  force_.assign(n, Vec3::Zero());
  carried_.assign(n, 0);
  offset_local_.assign(n, Vec3::Zero());
  // Candidates: the slave side's nodes that are not also the master side's (a shared node is not
  // tied to itself), with their tributary areas on the slave surface.
  for (std::size_t i = 0; i < n; ++i)
    if (contains(slave_nodes_, slaves[i]) && !contains(master_nodes_, slaves[i])) state_[i] = State::free;
  k_reverse_.assign(n, 0.0);
  for (Index j = 0; j < slave_surface_.segment_count(); ++j) {
    const bool tri = slave_surface_.is_triangle(j);
    const Real share = segment_area(slave_surface_, j, nodes.x) / (tri ? 3.0 : 4.0);
    const Real k_pass = pass_->segment_stiffness(slave_to_pass_[static_cast<std::size_t>(j)]);
    for (int q = 0; q < (tri ? 3 : 4); ++q) {
      const Index node = slave_surface_.conn[4 * static_cast<std::size_t>(j) + static_cast<std::size_t>(q)];
      const auto it = std::lower_bound(slaves.begin(), slaves.end(), node);
      if (it == slaves.end() || *it != node) continue;
      const auto i = static_cast<std::size_t>(it - slaves.begin());
      area_[i] += share;
      k_reverse_[i] = std::max(k_reverse_[i], k_pass);
    }
  }

  tied_count_ = released_count_ = 0;
  dt_ = std::numeric_limits<Real>::max();
  tie_inv2_.assign(n, 0.0);
  slave_ = master_total_ = Vec3::Zero();
  // Nodes in contact at t = 0, tied where they are: within 1e-3 of the segment's size of it, along
  // and across (OPTION 2's search takes normal gaps up to 0.3 of it; here a node short of that
  // contact is tied when it touches).
  std::vector<Index> candidates;
  std::vector<std::size_t> slot;
  for (std::size_t i = 0; i < n; ++i)
    if (state_[i] == State::free) candidates.push_back(slaves[i]), slot.push_back(i);
  const std::vector<TiePoint> found = find_tie_points(candidates, master_, nodes.x, TieSearchOptions{1e-3, 1e-3});
  for (std::size_t k = 0; k < found.size(); ++k) {
    if (found[k].segment < 0) continue;
    TiePoint t = found[k];
    t.segment = master_to_pass_[static_cast<std::size_t>(t.segment)];
    tie(slot[k], t, 0.0, nodes);
  }
}

void StickingTiebreakContact::tie(std::size_t i, const TiePoint& t, Real time, const NodalFields& nodes) {
  const auto s = static_cast<std::size_t>(t.segment);
  state_[i] = State::tied;
  tie_[i] = t;
  tie_time_[i] = time;
  // The offset turns with the master segment (tie_offset.hpp), where it is not round-off.
  carried_[i] = carry_tie_offset(pass_->master(), t, nodes.x, offset_local_[i]) ? 1 : 0;
  held_node_[static_cast<std::size_t>(t.slave)] = 1;  // the pass leaves it from the next cycle
  ++tied_count_;
  // Tension and shear: kappa A_k (a uniform traction needs a uniform stretch); closing: the pass's
  // spring on this segment, so the normal force goes on as it was at the touch.
  k_[i] = kappa_[s] * area_[i];
  kc_[i] = std::max(k_[i], pass_->segment_stiffness(t.segment));
  // Stable step of the spring between the slave mass and its lightest master node (2 / omega), the
  // pass's springs of the master-side nodes on the slave segments around it counted alongside.
  Real mm = std::numeric_limits<Real>::max();
  for (int a = 0; a < 4; ++a)
    if (t.shape[static_cast<std::size_t>(a)] != 0.0 && nodes.mass[t.master[static_cast<std::size_t>(a)]] > 0.0)
      mm = std::min(mm, nodes.mass[t.master[static_cast<std::size_t>(a)]]);
  const Real ms = nodes.mass[t.slave];
  const Real w2 = (kc_[i] + k_reverse_[i]) * ((ms > 0.0 ? 1.0 / ms : 0.0) + (mm < std::numeric_limits<Real>::max() ? 1.0 / mm : 0.0));
  if (w2 > 0.0) dt_ = std::min(dt_, 2.0 / std::sqrt(w2));
  if (w2 > 0.0) tie_inv2_[i] = 0.25 * w2;
  vote_ = dt_;
}

void StickingTiebreakContact::update_step_vote(const ElementStepsView& elements) {
  if (elements.empty()) {
    vote_ = dt_;  // the springs alone, as tie() keeps them
    return;
  }
  // Every spring tie() has formed (as dt_ keeps them), with the elements on its nodes.
  Real w2 = 0.0;
  for (std::size_t i = 0; i < tie_inv2_.size(); ++i) {
    if (!(tie_inv2_[i] > 0.0)) continue;
    const TiePoint& t = tie_[i];
    w2 = std::max(w2, combined_step_inv2(tie_inv2_[i], elements.pair(t.slave, t.master.data(), t.shape, 4)));
  }
  vote_ = w2 > 0.0 ? 1.0 / std::sqrt(w2) : std::numeric_limits<Real>::max();
}

void StickingTiebreakContact::apply_forces(const NodalFields& nodes, const StepTimes& times, ContactForceView out) {
  // The automatic pass over the free and released nodes (the tied ones are held).
  contact_->phases().forces->apply_forces(nodes, times, out);

  const Surface& surface = pass_->master();
  const std::span<const Index> slaves = pass_->slaves();
  const std::size_t n = slaves.size();
  Vec3 slave = Vec3::Zero();
  master_total_ = Vec3::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    if (state_[i] != State::tied) continue;
    const TiePoint& t = tie_[i];
    const Vec3 offset = carried_[i] ? carried_tie_offset(surface, t.segment, nodes.x, offset_local_[i]) : t.offset;
    const Vec3 d = nodes.x.get(t.slave) - tie_point_value(t, nodes.x) - offset;
    const Vec3 nk = segment_normal(surface, t.segment, nodes.x);
    const Real dn = d.dot(nk);
    Vec3 f = -k_[i] * d;
    if (dn < 0.0) f -= ((kc_[i] - k_[i]) * dn) * nk;  // closing: the pass's stiffness
    out.force.add(t.slave, f);
    for (int a = 0; a < 4; ++a) {
      const Real na = t.shape[static_cast<std::size_t>(a)];
      if (na == 0.0) continue;
      out.force.add(t.master[static_cast<std::size_t>(a)], -na * f);
      master_total_ -= na * f;
    }
    slave += f;
    force_[i] = f;
    if (!p_.fails || !(area_[i] > 0.0)) continue;
    // OPTION 3: the stress criterion on this cycle's force; released from the next cycle.
    const Real sn = std::max(0.0, -f.dot(nk)) / area_[i];
    const Real ss = (f - f.dot(nk) * nk).norm() / area_[i];
    Real r = 0.0;
    if (p_.normal_failure > 0.0) r += (sn / p_.normal_failure) * (sn / p_.normal_failure);
    if (p_.shear_failure > 0.0) r += (ss / p_.shear_failure) * (ss / p_.shear_failure);
    if (r >= 1.0) {
      state_[i] = State::released;
      held_node_[static_cast<std::size_t>(t.slave)] = 0;
      ++released_count_;
    }
  }
  slave_ = slave;

  // Touches found by the pass this cycle (its spring pushes a free slave-side node out of a
  // master-side segment): tied from the next cycle at the contact point, the stretch's zero on
  // the surface (the node's penetration becomes the tie's compression).
  const std::span<const PenaltyRecord> records = pass_->records();
  for (std::size_t i = 0; i < n; ++i) {
    if (state_[i] != State::free) continue;
    const PenaltyRecord& r = records[i];
    if (r.segment < 0 || r.mortar || !(segment_side_[static_cast<std::size_t>(r.segment)] & 2)) continue;
    TiePoint t;
    t.slave = slaves[i];
    t.segment = r.segment;
    const Index* conn = &surface.conn[4 * static_cast<std::size_t>(r.segment)];
    for (int a = 0; a < 4; ++a) {
      t.master[static_cast<std::size_t>(a)] = conn[a];
      t.shape[static_cast<std::size_t>(a)] = r.shape[static_cast<std::size_t>(a)];
    }
    const Vec3 nk = segment_normal(surface, r.segment, nodes.x);
    const Real g = pass_->gap(i);  // < 0: the penetration past the pass's zero
    t.normal = nk;
    t.gap = g;
    t.offset = nodes.x.get(t.slave) - tie_point_value(t, nodes.x) - g * nk;
    tie(i, t, times.t, nodes);
  }
  update_step_vote(times.element_steps);
}

}  // namespace slideline
