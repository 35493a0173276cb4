#pragma once
/// LagrangeInterface<Kind>: contact enforced by forward-increment Lagrange multipliers
/// (enforcement/lagrange.hpp) between slave nodes and a master surface. The kind is a
/// compile-time policy, one final class per interface type:
///  - LagrangeContact (Types 3, 5, 10 and 12 with the _LAGRANGE option): unilateral,
///    lambda >= 0, Coulomb friction with mu = mu_k + (mu_s - mu_k) exp(-beta |v_rel|);
///  - SlidingOnlyContact (Type 1): a bilateral normal constraint, no friction: the slave nodes
///    keep their normal gap to the master surface in tension and compression and slide freely.
/// Everything else (sides, offsets, friction coefficients, Type 12's single-surface options) is
/// in LagrangeContactSettings, which the factories make_lagrange_contact and
/// make_sliding_only_contact set from the card.
///
/// Per cycle, in enforce() (t^n, accelerations formed, ties, rigid bodies and supports done):
///  1. pairs: one ContactPairs stage (search/contact_pairs.hpp; an FCL tree, a search when the
///     cadence says one is due, else local tracking): among the segments that face the slave (its
///     own faces' normals oppose theirs, search/slave_orientation.hpp), the one it is over, else the
///     nearest, by closest-point projection at x^n. Options: allowance = a quarter of the smallest
///     segment diagonal, boxes padded by the master offsets only, the cadence by the allowance,
///     the shell side kept across segments;
///  2. a constraint for each slave whose projection is over the segment (lateral offset below
///     2 % of the segment size), not deeper than contact_depth_limit (half the segment size; for
///     a solid face also half its element's thickness) and within the search allowance;
///  3. the multipliers, warm-started from the previous cycle, by projected Gauss-Seidel;
///  4. friction work, forces and the history (multipliers, slip speed) for the next cycle.
/// The interface imposes no time step. Immovable nodes (fixed components, rigid bodies) take the
/// master forces into f_contact only; the simulation re-runs the rigid bodies afterwards.
/// No allocation per cycle (storage is sized in initialize(); the broad phase's candidate list
/// grows only when a search finds more candidates than any earlier one).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "slideline/contact/contact_algorithm.hpp"
#include "slideline/contact/enforcement/lagrange.hpp"
#include "slideline/contact/enforcement/mortar_weights.hpp"
#include "slideline/contact/enforcement/rigid_master_groups.hpp"
#include "slideline/contact/friction/exponential_coulomb.hpp"
#include "slideline/contact/search/contact_pairs.hpp"
#include "slideline/contact/search/fcl_broad_phase.hpp"
#include "slideline/contact/shell_offset.hpp"
#include "slideline/core/error.hpp"
#include "slideline/mesh/mesh_sets.hpp"

namespace slideline {

struct LagrangeContactSettings {
  std::string title;
  ExponentialCoulomb friction;    ///< mu_s = mu_k = 0: frictionless
  bool shell_offsets = false;     ///< offset shell segments by half their thickness (both sides)
  Real slave_thickness = 0.0;     ///< SST: overrides the slave shells' thickness (0: elements')
  Real master_thickness = 0.0;    ///< MST
  Real slave_thickness_scale = 1.0, master_thickness_scale = 1.0;  ///< SFST, SFMT
  Real nodal_radius = 0.0;        ///< least offset of every slave (node-set slaves, Type 5), length
  bool skip_incident = false;     ///< single surface (Type 12): a node never meets its own segments
  bool transmitted_output = false;  ///< write interfaces/<title>/transmitted_force
  LagrangeSolveOptions solve;       ///< tolerance relative to the smallest master segment size
  /// Solves per cycle: after the first, each constrained slave is projected again at the
  /// predicted positions x^{n+1} (its segment, shape functions and normal) and the system solved
  /// once more, warm-started: the gap then holds on the surface as it will be, also where a
  /// sliding node crosses onto a segment of another slope within the step.
  int projection_passes = 2;
  /// Single surface (Type 12): where two nodes constrain each other's segments (node s on segment
  /// T of the other body, a node of T on a segment holding s), both constraints hold the same gap
  /// and the system is nearly singular: the split of the load between them is almost free, and
  /// Gauss-Seidel crawls (sslide12l: 130 sweeps per solve instead of 13, sslide12l_vec hitting
  /// the 300-sweep cap). Only one of such a pair is kept: the finer side's node on the coarser
  /// side's segment (the larger master segment wins; on a tie the lower node index).
  bool one_constraint_per_mutual_pair = false;
  /// Translations a rigid master part's body holds fixed (*MAT_RIGID CMO/CON1), by part id: the
  /// solve keeps the body immovable in them. Rigid parts not listed translate freely.
  std::vector<std::pair<Id, std::array<int, 3>>> rigid_fixed_translations;
  /// Rotations a rigid master part's body holds fixed (*MAT_RIGID CMO/CON2), by part id.
  std::vector<std::pair<Id, std::array<int, 3>>> rigid_fixed_rotations;
  /// Prescribed motions of rigid parts (*BOUNDARY_PRESCRIBED_MOTION_RIGID): the solve holds the
  /// driven dof of a rigid master while the drive acts (the drive, not the contact, sets it).
  std::vector<RigidMasterDrive> rigid_drives;
  /// The solve turns each rigid master body about its centre of mass under the contact forces
  /// (RigidGroups::spin, enforcement/lagrange.hpp), as well as translating it. Off: the rotation is
  /// left to the rigid-body update after the solve (the behaviour before 2026-11-27; kept for
  /// comparisons, docs/contact.md "Rigid masters").
  bool rigid_master_rotation = true;
  /// Mortar transfer (a deck's _MORTAR with _LAGRANGE; needs the slave surface, and not the
  /// mutual-pair rule): each slave node's constraint holds the weighted master point
  /// sum_a w_a x_a of its mortar weights (enforcement/mortar_weights.hpp: the nodes of every master
  /// segment under the node's tributary area) and the weights' normal, instead of its closest
  /// point on one segment; it engages when part of its area is over the master. A uniform pressure
  /// then reaches the master as consistent nodal forces (docs/contact.md, "The contact patch test").
  bool mortar = false;
};

/// Totals of the Gauss-Seidel solves of a run.
struct LagrangeSolveStats {
  long solves = 0;          ///< cycles with at least one constraint
  long sweeps = 0;          ///< total sweeps
  int max_sweeps = 0;
  long unconverged = 0;     ///< cycles that hit the sweep cap
  long constraints = 0;     ///< constraints summed over the solves
};

/// Kinds (compile-time policies) of LagrangeInterface.
struct LagrangeContactKind {
  static constexpr bool bilateral = false;  ///< contact: lambda >= 0, friction per the settings
};
struct SlidingOnlyKind {
  static constexpr bool bilateral = true;  ///< Type 1: tension and compression, never friction
};

template <class Kind>
class LagrangeInterface final : public ContactAlgorithm, public ContactConstraint {
 public:
  /// master: the master surface; slaves: slave node indices; slave_surface: the surface the slaves
  /// come from (empty for a node set); first_part_nodes: nodes of the first body, for the
  /// transmitted force (any order).
  LagrangeInterface(LagrangeContactSettings settings, Surface master, std::vector<Index> slaves,
                    Surface slave_surface, std::vector<Index> first_part_nodes = {})
      : s_(std::move(settings)), slave_surface_(std::move(slave_surface)),
        first_part_nodes_(std::move(first_part_nodes)) {
    std::sort(slaves.begin(), slaves.end());
    slaves.erase(std::unique(slaves.begin(), slaves.end()), slaves.end());
    // Node-set slaves stand off by the nodal radius, surface slaves by their shell offsets.
    std::vector<Real> offsets = node_offsets(slaves, slave_surface_,
                                             {s_.shell_offsets, s_.slave_thickness, s_.slave_thickness_scale},
                                             s_.nodal_radius);
    pairs_ = ContactPairs(std::move(slaves), std::move(offsets), std::move(master),
                          {s_.shell_offsets, s_.master_thickness, s_.master_thickness_scale},
                          std::make_unique<FclBroadPhase>(), pairs_options(s_));
  }

  const std::string& name() const override { return s_.title; }
  ContactPhases phases() override { return {.constraint = this}; }

  /// The faces that orient node-set slaves (Type 5: the exterior faces of the parts the nodes
  /// belong to; search/slave_orientation.hpp); set before initialize(). Slaves of a slave
  /// surface are oriented by that surface.
  void set_orientation_surface(Surface faces) { orientation_surface_ = std::move(faces); }

  void initialize(const ContactContext& c) override {
    diagnostics_ = c.diagnostics;
    const std::size_t ns = pairs_.slaves().size();
    pairs_.set_orientation(
        SlaveOrientation(orientation_surface_.nodes.empty() ? slave_surface_ : orientation_surface_, pairs_.slaves()));
    pairs_.set_depth_limits(c.nodes.x, c.blocks);
    pairs_.initialize(c.nodes.x);
    tolerance_ = s_.solve.tolerance * pairs_.smallest_segment_size();
    lambda_.assign(ns, 0.0);
    tau_.assign(ns, Vec3::Zero());
    slip_speed_.assign(ns, 0.0);
    constraints_.clear();
    constraints_.reserve(ns);
    owner_.clear();
    owner_.reserve(ns);
    rigid_.setup(master(), c, s_.rigid_fixed_translations, s_.rigid_fixed_rotations, s_.rigid_master_rotation, s_.rigid_drives);
    predicted_.resize(c.nodes.size());
    constraint_of_.assign(c.nodes.size(), -1);
    keep_.reserve(ns);
    master_size_.reserve(ns);
    workspace_.dx.assign(c.nodes.size(), Vec3::Zero());
    workspace_.rows.clear();
    workspace_.rows.reserve(ns);
    in_first_.assign(c.nodes.size(), 0);
    for (Index n : first_part_nodes_) in_first_[static_cast<std::size_t>(n)] = 1;
    mortar_.clear();
    if (s_.mortar) {
      static_assert(MortarWeights::capacity <= LagrangeConstraint::max_masters);
      if (!std::ranges::equal(slave_surface_.nodes, pairs_.slaves()) || s_.one_constraint_per_mutual_pair)
        throw Error("LagrangeInterface::initialize: the mortar transfer needs the slaves' own surface and "
                    "no mutual-pair rule");
      mortar_.assign(ns, MortarWeights{});
    }
  }

  void enforce(ConstraintView view, const StepTimes& times) override {
    slave_force_.setZero();
    master_force_.setZero();
    transmitted_.setZero();
    constraints_.clear();
    owner_.clear();
    if (!(times.dt_next > 0.0)) return;  // birth and death: ContactManager
    pairs_.locate(view.nodes.x);
    form_constraints(view.nodes.x, times);
    if (s_.one_constraint_per_mutual_pair) drop_mutual_duplicates(view.nodes.x);
    if (constraints_.empty()) {
      std::fill(slip_speed_.begin(), slip_speed_.end(), 0.0);
      return;
    }
    LagrangeSolveOptions opt = s_.solve;
    opt.tolerance = tolerance_;
    rigid_.update(view, times);
    const RigidGroups* groups = rigid_.groups();
    LagrangeSolveResult r = solve_forward_increment(constraints_, view, times, opt, groups, &workspace_, &master_force_);
    for (int pass = 1; pass < s_.projection_passes; ++pass) {
      reproject(view, times, groups);
      const LagrangeSolveResult r2 =
          solve_forward_increment(constraints_, view, times, opt, groups, &workspace_, &master_force_);
      r.sweeps += r2.sweeps;
      r.correction = r2.correction;
      r.converged = r2.converged;
    }
    record(r);
    finish(view, times);
  }

  Vec3 slave_force() const override { return slave_force_; }
  Vec3 master_force() const override { return master_force_; }
  Real friction_work() const override { return friction_work_; }
  void append_output_names(std::vector<std::string>& names) const override {
    if (s_.transmitted_output) names.push_back("transmitted_force");
  }
  void write_output_values(std::span<Real> out) const override {
    if (!s_.transmitted_output) return;
    out[0] = transmitted_[0];
    out[1] = transmitted_[1];
    out[2] = transmitted_[2];
  }

  const LagrangeSolveStats& solve_stats() const { return stats_; }
  /// Largest penetration (length) of a constrained slave at x^n over the run: -gap for contact,
  /// |gap| for a bilateral (Type 1) constraint. It is what the previous cycle's solve left.
  Real max_penetration() const { return max_penetration_; }
  /// The constraints of the last cycle (for tests and diagnostics).
  std::span<const LagrangeConstraint> constraints() const { return constraints_; }
  const LagrangeContactSettings& settings() const { return s_; }
  std::size_t slave_count() const { return pairs_.slaves().size(); }
  /// The contact-pairs stage (search, tracking, offsets, side memory) the interface consumes.
  const ContactPairs& pairs() const { return pairs_; }
  /// The rigid master groups (centres and rotational compliances of the last cycle).
  const RigidMasterGroups& rigid_groups() const { return rigid_; }

 private:
  /// The stage's options: a quarter of the smallest segment as the allowance, boxes padded by the
  /// master offsets (the query boxes carry the slave's), the cadence by the allowance, the shell
  /// side kept across segments; a single surface skips incident segments.
  static ContactPairsOptions pairs_options(const LagrangeContactSettings& s) {
    ContactPairsOptions o;
    o.allowance_fraction = 0.25;
    o.boxes_cover_slave_offsets = false;
    o.cadence_uses_box_margin = false;
    o.skip_incident = s.skip_incident;
    o.side_memory = SideMemory::keep_across_segments;
    return o;
  }

  const Surface& master() const { return pairs_.master(); }

  void form_constraints(const Vec3Field& x, const StepTimes& /*times*/) {
    const std::span<const ContactPoint> points = pairs_.points();
    for (std::size_t i = 0; i < points.size(); ++i) {
      const ContactPoint& p = points[i];
      bool formed = false;
      if (p.segment >= 0) formed = s_.mortar ? try_mortar_constraint(i, p, x) : try_constraint(i, p, x);
      if (!formed) {
        lambda_[i] = 0.0;
        tau_[i].setZero();
        slip_speed_[i] = 0.0;
      }
    }
  }

  bool try_constraint(std::size_t i, const ContactPoint& p, const Vec3Field& x) {
    const Index seg = p.segment;
    const Index* conn = &master().conn[4 * static_cast<std::size_t>(seg)];
    const Index slave = p.node;
    if (conn[0] == slave || conn[1] == slave || conn[2] == slave || conn[3] == slave) return false;
    const Projection& pr = p.projection;
    const Real target = p.offset;
    // The side: re-picked whenever the slave is clear of the offset band (|gap| >= target).
    const Real side = static_cast<Real>(pairs_.orient(i, seg, pr.gap, target));
    const Vec3 nseg = segment_normal(seg, x);
    const Vec3 n = side * nseg;
    const Real gap = side * (x.get(slave) - pr.point).dot(nseg) - target;
    const Vec3 d = x.get(slave) - pr.point;
    if ((d - pr.gap * pr.normal).norm() > 0.02 * pr.size) return false;  // beside the segment
    if (gap < -pairs_.depth_limit(seg, pr)) return false;                 // far behind it
    const Real allowance = pairs_.allowance();
    if (Kind::bilateral ? std::abs(gap) > allowance : gap > allowance) return false;
    LagrangeConstraint k;
    k.slave = slave;
    for (int a = 0; a < 4; ++a) k.master[static_cast<std::size_t>(a)] = conn[a];
    k.shape = pr.shape;
    if (master().is_triangle(seg)) k.shape[3] = 0.0;
    k.normal = n;
    k.target = target;
    add_constraint(i, k, gap);
    return true;
  }

  /// The mortar constraint of slave i (LagrangeContactSettings::mortar): on its weighted master
  /// point, whether or not its own closest point is over the segment.
  bool try_mortar_constraint(std::size_t i, const ContactPoint& p, const Vec3Field& x) {
    const Index seg = p.segment;
    const Index slave = p.node;
    MortarWeights& mw = mortar_[i];
    if (!mortar_weights(slave_surface_, static_cast<Index>(i), slave, master(), seg, x, mw)) return false;
    Vec3 q = x.get(slave);
    for (int a = 0; a < mw.count; ++a) {
      if (mw.node[static_cast<std::size_t>(a)] == slave) return false;
      q -= mw.weight[static_cast<std::size_t>(a)] * x.get(mw.node[static_cast<std::size_t>(a)]);
    }
    const Real target = p.offset;
    const Real raw = mw.normal.dot(q);
    const Real side = static_cast<Real>(pairs_.orient(i, seg, raw, target));
    const Real gap = side * raw - target;
    if (gap < -pairs_.depth_limit(seg, p.projection)) return false;  // far behind the master
    if (Kind::bilateral ? std::abs(gap) > pairs_.allowance() : gap > pairs_.allowance()) return false;
    LagrangeConstraint k;
    k.slave = slave;
    const Index* conn = &master().conn[4 * static_cast<std::size_t>(seg)];
    for (int a = 0; a < 4; ++a) k.master[static_cast<std::size_t>(a)] = conn[a];  // the pair's segment
    k.mortar_node = mw.node.data();
    k.mortar_weight = mw.weight.data();
    k.mortar_count = mw.count;
    k.normal = side * mw.normal;
    k.target = target;
    add_constraint(i, k, gap);
    return true;
  }

  /// Completes constraint k of slave i (gap `gap` at x^n) and adds it: friction coefficient and
  /// the warm start from the previous cycle.
  void add_constraint(std::size_t i, LagrangeConstraint& k, Real gap) {
    const Vec3& n = k.normal;
    k.bilateral = Kind::bilateral;
    k.mu = Kind::bilateral ? 0.0 : s_.friction.coefficient(slip_speed_[i]);
    // Warm start from the previous cycle's multipliers, turned into the current tangent plane.
    k.lambda = lambda_[i];
    k.tau = k.mu > 0.0 ? rotate_into_plane(tau_[i], n) : Vec3::Zero();
    const Real limit = k.mu * std::max(k.lambda, Real(0));
    if (k.tau.norm() > limit) k.tau *= limit / k.tau.norm();
    if (!Kind::bilateral) max_penetration_ = std::max(max_penetration_, -gap);
    else max_penetration_ = std::max(max_penetration_, std::abs(gap));
    constraints_.push_back(k);
    owner_.push_back(static_cast<Index>(i));
  }

  /// See LagrangeContactSettings::one_constraint_per_mutual_pair. No allocation (storage reserved).
  void drop_mutual_duplicates(const Vec3Field& x) {
    const std::size_t nc = constraints_.size();
    master_size_.clear();
    for (std::size_t k = 0; k < nc; ++k) {
      constraint_of_[static_cast<std::size_t>(constraints_[k].slave)] = static_cast<Index>(k);
      master_size_.push_back(detail::segment_size(segment_corners(master(), segment_of(owner_[k]), x)));
    }
    const auto holds = [&](Index seg, Index node) {
      const Index* c = &master().conn[4 * static_cast<std::size_t>(seg)];
      return c[0] == node || c[1] == node || c[2] == node || c[3] == node;
    };
    keep_.assign(nc, 1);
    for (std::size_t k = 0; k < nc; ++k) {
      const Index s = constraints_[k].slave;
      const Index seg = segment_of(owner_[k]);
      const Index* conn = &master().conn[4 * static_cast<std::size_t>(seg)];
      for (int a = 0; a < 4 && keep_[k]; ++a) {
        const Index j = constraint_of_[static_cast<std::size_t>(conn[a])];
        if (j < 0 || static_cast<std::size_t>(j) == k) continue;
        if (!holds(segment_of(owner_[static_cast<std::size_t>(j)]), s)) continue;
        const Real mine = master_size_[k], theirs = master_size_[static_cast<std::size_t>(j)];
        const bool other_wins = theirs > mine || (theirs == mine && constraints_[static_cast<std::size_t>(j)].slave < s);
        if (other_wins) keep_[k] = 0;
      }
    }
    std::size_t out = 0;
    for (std::size_t k = 0; k < nc; ++k) {
      constraint_of_[static_cast<std::size_t>(constraints_[k].slave)] = -1;
      if (!keep_[k]) {
        const auto i = static_cast<std::size_t>(owner_[k]);
        lambda_[i] = 0.0;
        tau_[i].setZero();
        slip_speed_[i] = 0.0;
        continue;
      }
      constraints_[out] = constraints_[k];
      owner_[out++] = owner_[k];
    }
    constraints_.resize(out);
    owner_.resize(out);
  }

  /// Moves every constraint to the closest point of the predicted slave position on the predicted
  /// master surface (see LagrangeContactSettings::projection_passes), forces withdrawn first.
  void reproject(const ConstraintView& view, const StepTimes& times, const RigidGroups* groups) {
    for (Index n : master().nodes) predicted_.set(n, predicted_position(view, times, groups, n));
    for (Index n : pairs_.slaves()) predicted_.set(n, predicted_position(view, times, groups, n));
    withdraw_constraint_forces(constraints_, view, times, groups, &master_force_);
    for (std::size_t k = 0; k < constraints_.size(); ++k) {
      LagrangeConstraint& c = constraints_[k];
      const auto i = static_cast<std::size_t>(owner_[k]);
      const SegmentProjection sp =
          track_segment(predicted_.get(c.slave), segment_of(owner_[k]), master(), predicted_, TrackingOptions{},
                        FacingRule{&pairs_.orientation(), i, &master(), &predicted_});
      const Index seg = sp.segment;
      const Index* conn = &master().conn[4 * static_cast<std::size_t>(seg)];
      if (conn[0] == c.slave || conn[1] == c.slave || conn[2] == c.slave || conn[3] == c.slave) continue;
      if (s_.mortar) {
        reproject_mortar(c, i, seg);
        continue;
      }
      pairs_.move_to(i, seg);
      for (int a = 0; a < 4; ++a) c.master[static_cast<std::size_t>(a)] = conn[a];
      c.shape = sp.projection.shape;
      if (master().is_triangle(seg)) c.shape[3] = 0.0;
      c.normal = static_cast<Real>(pairs_.side(i)) * segment_normal(seg, predicted_);
      c.target = pairs_.offset(i, seg);
      if (c.mu > 0.0) c.tau = rotate_into_plane(c.tau, c.normal);
    }
  }

  /// reproject() of mortar constraint c (slave i, now over segment seg): the weights at the
  /// predicted positions; the constraint stays as it was where they cannot be formed.
  void reproject_mortar(LagrangeConstraint& c, std::size_t i, Index seg) {
    MortarWeights w;
    if (!mortar_weights(slave_surface_, static_cast<Index>(i), c.slave, master(), seg, predicted_, w)) return;
    for (int a = 0; a < w.count; ++a)
      if (w.node[static_cast<std::size_t>(a)] == c.slave) return;
    pairs_.move_to(i, seg);
    mortar_[i] = w;
    c.mortar_count = w.count;
    c.normal = static_cast<Real>(pairs_.side(i)) * w.normal;
    c.target = pairs_.offset(i, seg);
    if (c.mu > 0.0) c.tau = rotate_into_plane(c.tau, c.normal);
  }

  /// The segment slave i is on (its contact point's).
  Index segment_of(Index i) const { return pairs_.points()[static_cast<std::size_t>(i)].segment; }

  Vec3 segment_normal(Index seg, const Vec3Field& x) const {
    const auto c = segment_corners(master(), seg, x);
    return (c[2] - c[0]).cross(c[3] - c[1]).normalized();
  }

  void record(const LagrangeSolveResult& r) {
    ++stats_.solves;
    stats_.sweeps += r.sweeps;
    stats_.max_sweeps = std::max(stats_.max_sweeps, r.sweeps);
    stats_.constraints += static_cast<long>(constraints_.size());
    if (r.converged) return;
    if (stats_.unconverged++ == 0)
      warn(diagnostics_,
                   "slideline: warning: contact interface '%s': the Lagrange-multiplier solve did not reach "
                   "its tolerance %.3g in %d sweeps (correction %.3g); later occurrences are counted, not "
                   "reported",
                   s_.title.c_str(), tolerance_, r.sweeps, r.correction);
  }

  void finish(const ConstraintView& view, const StepTimes& times) {
    for (std::size_t k = 0; k < constraints_.size(); ++k) {
      const LagrangeConstraint& c = constraints_[k];
      const auto i = static_cast<std::size_t>(owner_[k]);
      const Vec3 f = c.lambda * c.normal + c.tau;
      slave_force_ += f;
      if (s_.transmitted_output && in_first_[static_cast<std::size_t>(c.slave)]) transmitted_ += f;
      Vec3 v_rel = view.nodes.v.get(c.slave);
      for_each_master(c, [&](int, Index m, Real w) {
        if (s_.transmitted_output && in_first_[static_cast<std::size_t>(m)]) transmitted_ += -w * f;
        v_rel -= w * view.nodes.v.get(m);
      });
      // Trapezoidal work of the friction force on the relative sliding, as the energy ledger
      // books the contact forces: half with v^{n-1/2} over dt_prev, half with v^{n+1/2} over dt_next.
      if (c.mu > 0.0) {
        const Vec3 before = tangential_part(v_rel, c.normal) * times.dt_prev;
        friction_work_ -= 0.5 * c.tau.dot(before + c.slip);
      }
      lambda_[i] = c.lambda;
      tau_[i] = c.tau;
      slip_speed_[i] = c.slip.norm() / times.dt_next;
    }
  }

  LagrangeContactSettings s_;
  Surface slave_surface_, orientation_surface_;
  std::vector<Index> first_part_nodes_;
  ContactPairs pairs_;
  std::vector<std::uint8_t> in_first_;
  Real tolerance_ = 0.0;
  std::vector<Real> lambda_, slip_speed_;
  std::vector<Vec3> tau_;
  std::vector<LagrangeConstraint> constraints_;
  std::vector<Index> owner_;
  Vec3 slave_force_ = Vec3::Zero(), master_force_ = Vec3::Zero(), transmitted_ = Vec3::Zero();
  Real friction_work_ = 0.0;
  Real max_penetration_ = 0.0;
  LagrangeSolveStats stats_;
  RigidMasterGroups rigid_;  ///< the rigid master parts, moved as rigid bodies by the solve
  Vec3Field predicted_;  ///< x^{n+1} of the interface's nodes during reproject()
  std::vector<Index> constraint_of_;  ///< per node: its constraint this cycle, -1 (mutual-pair check)
  std::vector<std::uint8_t> keep_;
  std::vector<Real> master_size_;
  LagrangeWorkspace workspace_;  ///< scratch of the solve, sized in initialize()
  std::vector<MortarWeights> mortar_;  ///< per slave: its mortar weights (LagrangeContactSettings::mortar)
  DiagnosticSink* diagnostics_ = nullptr;  ///< from the ContactContext
};

/// Types 3, 5, 10 and 12 with the _LAGRANGE option.
using LagrangeContact = LagrangeInterface<LagrangeContactKind>;
/// Type 1 sliding only.
using SlidingOnlyContact = LagrangeInterface<SlidingOnlyKind>;

}  // namespace slideline
