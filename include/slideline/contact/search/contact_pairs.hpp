#pragma once
/// ContactPairs: the contact-pairs stage every node-on-segment enforcement consumes (penalty
/// PenaltyPass, Lagrange LagrangeInterface). It owns the slave nodes, the master surface, the
/// offsets of both sides, the broad phase and its cadence, each slave's tracked segment and the
/// side memory, and yields each cycle one ContactPoint per slave. docs/architecture.md, "The
/// contact pipeline"; docs/contact.md, "Choosing a segment".
///
/// Per cycle, locate(x):
/// - a broad-phase search when one is due (SearchCadence, or force_search()): the boxes are
///   refitted and queried, and each slave takes among its candidates the one pick_rule chooses:
///   the segments its orientation admits (search/slave_orientation.hpp) and, with
///   ContactPairsOptions::skip_own_shell_part, not its own shell part; over before beside, then
///   nearer, then the lower index (is_better_contact);
/// - otherwise each slave tracks its segment across edges (track_segment with the same rule), or,
///   with ContactPairsOptions::repick_between_searches, picks again among the candidates of the
///   last search (the single-surface filters hold only over the candidate list).
/// The offsets: a slave's own (one per slave, given: a nodal radius or its shell offset) plus the
/// master segment's (ShellOffsetRule, shell_offset.hpp); ContactPoint::offset is their sum, so
/// the signed gap of the contact surfaces is side x projection.gap - offset.
/// Side memory: which side of a shell segment the slave is on (orient()); a solid face has one.
/// Nothing allocates after initialize() except a broad-phase query returning more candidates than
/// any before it; every per-slave loop is independent, so results do not depend on the threads.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "slideline/contact/search/broad_phase.hpp"
#include "slideline/contact/search/closest_point.hpp"
#include "slideline/contact/search/search_cadence.hpp"
#include "slideline/contact/search/segment_tracking.hpp"
#include "slideline/contact/search/slave_orientation.hpp"
#include "slideline/contact/shell_offset.hpp"
#include "slideline/core/parallel.hpp"
#include "slideline/element/element_block.hpp"
#include "slideline/mesh/segment_geometry.hpp"
#include "slideline/mesh/surface.hpp"

namespace slideline {

/// One slave against the master segment it meets this cycle.
struct ContactPoint {
  Index node = -1;        ///< the slave node (internal index)
  Index segment = -1;     ///< master segment, -1: none this cycle (the rest is then stale)
  Projection projection;  ///< closest point: point, shape functions, unit normal, gap (length)
  Real offset = 0.0;      ///< slave offset + the segment's offset (length)
};

/// What happens to a slave's side memory when it moves to another segment.
enum class SideMemory : std::uint8_t {
  /// Forgotten when a search gives it another segment or tracking moves it onto a segment of the
  /// other kind (solid face / shell): the side is read again from its next position (penalty).
  forget_on_new_segment,
  /// Kept across segments; re-picked only where orient() is told the slave is clear (Lagrange).
  keep_across_segments,
};

/// How a slave keeps its segment between searches.
enum class SegmentTracking : std::uint8_t {
  /// track_segment: across the edges its closest point lies on, up to 4 hops, to admitted segments
  /// by the pick rule (is_better_contact; penalty, Lagrange).
  walk_across_edges,
  /// Stay while the closest point is inside the segment; else the nearest (is_better_projection)
  /// of it and all its neighbours, one hop (tiebreak's contact after failure).
  stay_while_inside,
};

/// How the stage searches (the families differ only in these).
struct ContactPairsOptions {
  /// The search allowance: fraction x the smallest master segment diagonal (length).
  Real allowance_fraction = 0.5;
  /// Segment boxes are inflated by allowance + the largest master offset, and also by the largest
  /// slave offset when true (penalty); the query boxes carry each slave's own offset either way.
  bool boxes_cover_slave_offsets = true;
  /// A new search is due when a node moved half the box inflation (true, penalty) or half the
  /// allowance alone (false, Lagrange).
  bool cadence_uses_box_margin = true;
  /// Single surface: a node never gets a segment it is a corner of (broad phase).
  bool skip_incident = false;
  /// Single surface (penalty Type 12): a shell node or a shell segment never meets its own part
  /// (needs set_slave_parts()).
  bool skip_own_shell_part = false;
  /// Between searches, pick again among the last candidates instead of tracking (penalty Type 12,
  /// so that skip_own_shell_part holds).
  bool repick_between_searches = false;
  SideMemory side_memory = SideMemory::forget_on_new_segment;
  SegmentTracking tracking = SegmentTracking::walk_across_edges;
};

class ContactPairs {
 public:
  ContactPairs() = default;
  /// slaves: internal node indices, ascending; slave_offset: one per slave (length); master: the
  /// master surface (adjacency built); master_shells: the offset rule of its shell segments;
  /// broad_phase: a fresh broad phase, or nullptr for a stage that never searches: its slaves are
  /// given their segments by seed() (e.g. found once by the tie search) and only tracked.
  ContactPairs(std::vector<Index> slaves, std::vector<Real> slave_offset, Surface master, ShellOffsetRule master_shells,
               std::unique_ptr<BroadPhase> broad_phase, ContactPairsOptions options)
      : slaves_(std::move(slaves)), slave_offset_(std::move(slave_offset)), master_(std::move(master)),
        master_shells_(master_shells), broad_(std::move(broad_phase)), opt_(options) {}

  /// Which master segments each slave may meet (indexed like slaves()); before initialize().
  void set_orientation(SlaveOrientation orientation) { orientation_ = std::move(orientation); }
  /// Part of each slave node (skip_own_shell_part); before initialize().
  std::vector<Id>& slave_parts() { return slave_part_; }
  const std::vector<Id>& slave_parts() const { return slave_part_; }
  /// Two-sided automatic contact (*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE): the side of each slave
  /// (indexed like slaves()) and of each master segment, bit 1 the card's slave side, bit 2 its
  /// master side (both bits: on both sides). A slave meets a segment only when their masks
  /// together hold both sides: the cross pairs. Before initialize(); never called: no filter.
  void set_sides(std::vector<std::uint8_t> slave_sides, std::vector<std::uint8_t> segment_sides) {
    slave_side_mask_ = std::move(slave_sides);
    segment_side_mask_ = std::move(segment_sides);
  }
  /// Pairs a tie still holds (the automatic tiebreak card, automatic_tiebreak_contact.hpp): a
  /// slave whose node is nonzero in `held_nodes` (indexed by internal node) or a segment nonzero
  /// in `held_segments` (indexed like master segments) is not admitted. Views of the owner's
  /// arrays, which it updates between cycles; before initialize(); never called: nothing held.
  void set_held(std::span<const std::uint8_t> held_nodes, std::span<const std::uint8_t> held_segments) {
    held_node_ = held_nodes;
    held_segment_ = held_segments;
  }
  /// Contact with eroding parts (search/contact_erosion.hpp): slave i is admitted only while
  /// slave_active[i] != 0, segment s only while segment_active[s] != 0, and the orientation reads
  /// only the active own faces (own_active, per segment of the slaves' own surface). Views of the
  /// owner's flags, which it updates between cycles (then force_search()); before initialize();
  /// never called: everything is active. slave_free (ENMASS 1, 2; empty: none): a slave freed of
  /// its elements and kept as a free mass is not oriented (it has no face left).
  void set_erosion(std::span<const std::uint8_t> slave_active, std::span<const std::uint8_t> segment_active,
                   std::span<const std::uint8_t> own_active, std::span<const std::uint8_t> slave_free = {}) {
    slave_active_ = slave_active;
    segment_active_ = segment_active;
    slave_free_ = slave_free;
    orientation_.set_own_activity(own_active);
  }
  /// One offset per master segment (length) instead of the ShellOffsetRule's (a surface whose
  /// segments come from two sides with their own thickness rules); before initialize().
  void set_master_offsets(std::vector<Real> offsets) { master_offset_given_ = std::move(offsets); }
  /// THKCHG = 1 (FollowedOffsets, shell_offset.hpp): the slaves' offsets (indexed like slaves())
  /// and the master segments' follow the shells' current thickness; before initialize(). Never
  /// called: the offsets are those of initialize() for the run.
  void set_followed_offsets(FollowedOffsets slaves, FollowedOffsets segments) {
    follow_slave_ = std::move(slaves);
    follow_segment_ = std::move(segments);
  }
  /// After initialize(): reads each block's current thickness (ElementBlock::current_thickness; the
  /// views stay valid for the run); the offsets follow only where a block's thickness changes.
  void follow_thickness(const std::vector<std::unique_ptr<ElementBlock>>& blocks) {
    if (follow_slave_.size() != static_cast<Index>(slaves_.size()) || follow_segment_.size() != master_.segment_count())
      return;
    thickness_.clear();
    following_ = false;
    for (const auto& b : blocks) {
      thickness_.push_back(b->current_thickness());
      following_ = following_ || !thickness_.back().empty();
    }
  }
  /// Whether the offsets follow the thickness (set_followed_offsets, follow_thickness).
  bool follows_thickness() const { return following_; }

  /// Per master segment, the deepest contact (contact_depth_limit), from the element blocks at x;
  /// with xpene > 0 (PENCHK = 1) at most xpene x penetration_check_thickness. Without a call,
  /// depth_limit() is half the projection's segment size.
  void set_depth_limits(const Vec3Field& x, const std::vector<std::unique_ptr<ElementBlock>>& blocks,
                        Real xpene = 0.0);

  /// Offsets, margins, broad phase, cadence and the per-slave state at coordinates x. Allocates.
  void initialize(const Vec3Field& x);

  /// The segment and closest point of every slave at x (a search when due; see the file comment).
  void locate(const Vec3Field& x);
  /// A stage without a broad phase, after initialize(): the slaves become `slaves` with their
  /// offsets (length), starting segments and sides (+1 / -1). Allocates.
  void seed(std::vector<Index> slaves, std::vector<Real> slave_offset, std::span<const Index> segment,
            std::span<const std::int8_t> side) {
    slaves_ = std::move(slaves);
    slave_offset_ = std::move(slave_offset);
    points_.assign(slaves_.size(), ContactPoint{});
    for (std::size_t i = 0; i < slaves_.size(); ++i) points_[i].node = slaves_[i], points_[i].segment = segment[i];
    side_.assign(side.begin(), side.end());
  }
  /// Tracks slave i alone at x (a slave with a segment) and returns its point; no allocation.
  const ContactPoint& track(std::size_t i, const Vec3Field& x);
  /// The next locate() searches whatever the cadence says.
  void force_search() { force_search_ = true; }
  /// Moves slave i onto segment s (e.g. Lagrange's projection at the predicted positions): the
  /// next tracking starts there. The point's projection is left as it was.
  void move_to(std::size_t i, Index s) { points_[i].segment = s; }

  /// The side of its segment slave i is on (+1 / -1): on a solid face +1; on a shell the side
  /// remembered, picked from the sign of `raw` (its signed distance, length) when unknown or when
  /// |raw| >= clear (the slave is clear of the offset band; pass +inf never to re-pick).
  int orient(std::size_t i, Index s, Real raw, Real clear) {
    if (master_.kind[static_cast<std::size_t>(s)] != SegmentKind::shell) return side_[i] = 1;
    if (side_[i] == 0 || std::abs(raw) >= clear) side_[i] = raw >= 0.0 ? 1 : -1;
    return side_[i];
  }
  /// The remembered side of slave i (0: unknown).
  int side(std::size_t i) const { return side_[i]; }
  /// Forgets slave i's side (it is free: the side is read again at its next contact).
  void forget_side(std::size_t i) { side_[i] = 0; }

  std::span<const ContactPoint> points() const { return points_; }
  std::span<const Index> slaves() const { return slaves_; }
  const Surface& master() const { return master_; }
  /// Offset of slave i (length) and of master segment s (length); offset(i, s): their sum.
  Real slave_offset(std::size_t i) const { return slave_offset_[i]; }
  Real master_offset(Index s) const { return master_offset_[static_cast<std::size_t>(s)]; }
  Real offset(std::size_t i, Index s) const { return master_offset(s) + slave_offset_[i]; }
  /// The deepest a slave may be behind segment s and belong to it (length), `pr` its projection.
  Real depth_limit(Index s, const Projection& pr) const {
    return depth_.empty() ? 0.5 * pr.size : depth_[static_cast<std::size_t>(s)];
  }
  /// allowance_fraction x the smallest master segment diagonal at initialize() (length).
  Real allowance() const { return allowance_; }
  /// The smallest master segment diagonal at initialize() (length; 1 without segments).
  Real smallest_segment_size() const { return min_size_; }
  const SlaveOrientation& orientation() const { return orientation_; }

 private:
  void search(const Vec3Field& x);
  void pick_nearest_candidates(const Vec3Field& x);
  void track_all(const Vec3Field& x);
  SegmentProjection stay_while_inside(const Vec3& p, Index s, const Vec3Field& x) const;
  bool admits(std::size_t i, Index s, const Vec3Field& x) const;

  std::vector<Index> slaves_;
  std::vector<Real> slave_offset_;
  Surface master_;
  ShellOffsetRule master_shells_;
  std::unique_ptr<BroadPhase> broad_;
  ContactPairsOptions opt_;
  SlaveOrientation orientation_;
  SearchCadence cadence_;
  std::vector<Real> master_offset_;     ///< per master segment (length)
  std::vector<Real> depth_;             ///< per master segment (length; empty: half its size)
  std::vector<Candidate> candidates_;
  std::vector<std::size_t> run_begin_;  ///< per slave: its candidates [begin, end)
  std::vector<std::size_t> run_end_;
  std::vector<ContactPoint> points_;
  std::vector<std::int8_t> side_;       ///< shell side of each slave, 0 unknown
  std::vector<Id> slave_part_;
  std::vector<std::uint8_t> slave_side_mask_;    ///< set_sides(): per slave (empty: no side filter)
  std::vector<std::uint8_t> segment_side_mask_;  ///< set_sides(): per master segment
  std::vector<Real> master_offset_given_;        ///< set_master_offsets() (empty: the rule's)
  FollowedOffsets follow_slave_, follow_segment_;  ///< set_followed_offsets()
  std::vector<std::span<const Real>> thickness_;   ///< follow_thickness(): per block (empty: constant)
  bool following_ = false;
  std::span<const std::uint8_t> held_node_;      ///< set_held(): per internal node (empty: none held)
  std::span<const std::uint8_t> held_segment_;   ///< set_held(): per master segment
  std::span<const std::uint8_t> slave_active_;   ///< set_erosion(): per slave (empty: all active)
  std::span<const std::uint8_t> slave_free_;     ///< set_erosion(): per slave, 1 a free mass (ENMASS)
  std::span<const std::uint8_t> segment_active_; ///< set_erosion(): per master segment
  std::vector<std::uint8_t> slave_solid_;  ///< skip_own_shell_part: the node has only solid faces
  Real allowance_ = 0.0;
  Real min_size_ = 1.0;
  bool force_search_ = true;
};

inline void ContactPairs::set_depth_limits(const Vec3Field& x,
                                           const std::vector<std::unique_ptr<ElementBlock>>& blocks, Real xpene) {
  depth_.resize(static_cast<std::size_t>(master_.segment_count()));
  for (Index s = 0; s < master_.segment_count(); ++s) {
    Real limit = contact_depth_limit(master_, s, blocks, x);
    if (xpene > 0.0) limit = std::min(limit, xpene * penetration_check_thickness(master_, s, blocks, x));
    depth_[static_cast<std::size_t>(s)] = limit;
  }
}

inline void ContactPairs::initialize(const Vec3Field& x) {
  const Index ns = master_.segment_count();
  master_offset_.assign(static_cast<std::size_t>(ns), 0.0);
  Real min_diag = std::numeric_limits<Real>::max(), max_offset = 0.0;
  for (Index s = 0; s < ns; ++s) {
    // Under erosion the allowance is sized by the segments active at the start (the interior
    // faces that may become active later are not contact surface yet).
    if (segment_active_.empty() || segment_active_[static_cast<std::size_t>(s)] != 0)
      min_diag = std::min(min_diag, segment_max_diagonal(master_, s, x));
    master_offset_[static_cast<std::size_t>(s)] = master_offset_given_.empty()
                                                      ? segment_offset(master_, s, master_shells_)
                                                      : master_offset_given_[static_cast<std::size_t>(s)];
    max_offset = std::max(max_offset, master_offset_[static_cast<std::size_t>(s)]);
  }
  min_size_ = ns > 0 && min_diag < std::numeric_limits<Real>::max() ? min_diag : 1.0;
  allowance_ = opt_.allowance_fraction * min_size_;
  Real box_margin = allowance_ + max_offset;
  if (opt_.boxes_cover_slave_offsets) {
    Real max_slave_offset = 0.0;
    for (Real o : slave_offset_) max_slave_offset = std::max(max_slave_offset, o);
    box_margin += max_slave_offset;
  }
  BroadPhaseOptions bo;
  bo.margin = box_margin;
  bo.skip_incident = opt_.skip_incident;
  if (broad_) {
    broad_->build(master_, x, bo);
    std::vector<Index> watched(slaves_);
    watched.insert(watched.end(), master_.nodes.begin(), master_.nodes.end());
    std::sort(watched.begin(), watched.end());
    watched.erase(std::unique(watched.begin(), watched.end()), watched.end());
    cadence_ = SearchCadence(watched, opt_.cadence_uses_box_margin ? box_margin : allowance_);
  }

  const std::size_t n = slaves_.size();
  points_.assign(n, ContactPoint{});
  for (std::size_t i = 0; i < n; ++i) points_[i].node = slaves_[i];
  side_.assign(n, 0);
  run_begin_.assign(n, 0);
  run_end_.assign(n, 0);
  candidates_.reserve(4 * n);
  if (slave_part_.size() != n) slave_part_.assign(n, 0);
  slave_solid_.assign(n, 1);
  if (!opt_.skip_own_shell_part) return;
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

/// Which segments slave i may meet: with set_sides(), the cross pairs only; under erosion
/// (set_erosion()) an active slave and an active segment only; no pair a tie holds (set_held());
/// its orientation
/// (search/slave_orientation.hpp) and, with skip_own_shell_part, no self-contact of a shell part
/// (a shell node or a shell segment never meets its own part).
inline bool ContactPairs::admits(std::size_t i, Index s, const Vec3Field& x) const {
  const std::size_t su = static_cast<std::size_t>(s);
  if (!segment_side_mask_.empty() && (slave_side_mask_[i] | segment_side_mask_[su]) != 3) return false;
  if (!segment_active_.empty() && (slave_active_[i] == 0 || segment_active_[su] == 0)) return false;
  if (!held_node_.empty() && (held_node_[static_cast<std::size_t>(slaves_[i])] != 0 || held_segment_[su] != 0))
    return false;
  if (opt_.skip_own_shell_part && (!slave_solid_[i] || master_.kind[su] == SegmentKind::shell) &&
      slave_part_[i] == master_.part[su])
    return false;
  if (!slave_free_.empty() && slave_free_[i] != 0) return true;  // ENMASS 1, 2: no face to orient it
  return orientation_.admits(i, master_, s, x);
}

inline void ContactPairs::locate(const Vec3Field& x) {
  if (following_) {  // THKCHG = 1: this cycle's offsets (the elements updated their thickness before)
    for (std::size_t i = 0; i < slaves_.size(); ++i)
      slave_offset_[i] = follow_slave_.value(static_cast<Index>(i), thickness_);
    for (Index s = 0; s < master_.segment_count(); ++s)
      master_offset_[static_cast<std::size_t>(s)] = follow_segment_.value(s, thickness_);
  }
  const bool due = broad_ && (force_search_ || cadence_.is_due(x));  // a seeded stage only tracks
  force_search_ = false;
  if (due) {
    search(x);
  } else if (opt_.repick_between_searches) {
    pick_nearest_candidates(x);
  } else {
    track_all(x);
  }
}

inline void ContactPairs::search(const Vec3Field& x) {
  broad_->update(x);
  broad_->query(slaves_, x, std::span<const Real>(slave_offset_), candidates_);
  cadence_.mark_searched(x);
  std::size_t c = 0;
  for (std::size_t i = 0; i < slaves_.size(); ++i) {  // candidates are grouped by node in slave order
    run_begin_[i] = c;
    while (c < candidates_.size() && candidates_[c].node == slaves_[i]) ++c;
    run_end_[i] = c;
  }
  pick_nearest_candidates(x);
}

/// Per slave: the admitted segment of its candidate run chosen by is_better_contact. While the
/// best so far is one the node is over, a candidate whose corner box is already farther
/// (cannot_beat) cannot replace it and is not projected: the same pick, without most of the
/// Newton solves of a single-surface pass, whose nodes re-pick among all their candidates.
inline void ContactPairs::pick_nearest_candidates(const Vec3Field& x) {
  parallel_for(static_cast<Index>(slaves_.size()), [&](Index ii) {
    const std::size_t i = static_cast<std::size_t>(ii);
    const Vec3 p = x.get(slaves_[i]);
    SegmentProjection best;
    bool best_over = false;
    for (std::size_t k = run_begin_[i]; k < run_end_[i]; ++k) {
      const Index s = candidates_[k].segment;
      const SegmentCorners c = segment_corners(master_, s, x);
      if (best_over && cannot_beat(p, c, best.projection)) continue;  // cheaper than the filters
      if (!admits(i, s, x)) continue;
      const Projection pr = master_.is_triangle(s) ? project_point_to_triangle(p, c) : project_point_to_quad(p, c);
      if (best.segment < 0 || is_better_contact(p, pr, s, best.projection, best.segment)) {
        best.segment = s;
        best.projection = pr;
        best_over = is_over(p, pr);
      }
    }
    ContactPoint& cp = points_[i];
    if (best.segment != cp.segment && opt_.side_memory == SideMemory::forget_on_new_segment) side_[i] = 0;
    cp.segment = best.segment;
    cp.projection = best.projection;
    if (best.segment >= 0) cp.offset = offset(i, best.segment);
  });
}

/// Between searches: each slave with a segment tracks it (ContactPairsOptions::tracking).
inline void ContactPairs::track_all(const Vec3Field& x) {
  parallel_for(static_cast<Index>(slaves_.size()), [&](Index ii) {
    const std::size_t i = static_cast<std::size_t>(ii);
    if (points_[i].segment >= 0) track(i, x);
  });
}

inline const ContactPoint& ContactPairs::track(std::size_t i, const Vec3Field& x) {
  ContactPoint& cp = points_[i];
  const Vec3 p = x.get(slaves_[i]);
  const SegmentProjection sp =
      opt_.tracking == SegmentTracking::stay_while_inside
          ? stay_while_inside(p, cp.segment, x)
          : track_segment(p, cp.segment, master_, x, TrackingOptions{}, FacingRule{&orientation_, i, &master_, &x});
  if (sp.segment != cp.segment && opt_.side_memory == SideMemory::forget_on_new_segment &&
      master_.kind[static_cast<std::size_t>(sp.segment)] != master_.kind[static_cast<std::size_t>(cp.segment)])
    side_[i] = 0;
  cp.segment = sp.segment;
  cp.projection = sp.projection;
  cp.offset = offset(i, sp.segment);
  return cp;
}

/// SegmentTracking::stay_while_inside: segment s while p projects inside it, else the best of s
/// and its neighbours (surface.segment_neighbors order, is_better_projection's tie rule).
inline SegmentProjection ContactPairs::stay_while_inside(const Vec3& p, Index s, const Vec3Field& x) const {
  SegmentProjection best{s, project_point_to_segment(p, master_, s, x), 0};
  if (best.projection.interior() || master_.segment_neighbors.rows() <= s) return best;
  const Csr& nb = master_.segment_neighbors;
  for (Index r = nb.begin(s); r < nb.end(s); ++r) {
    const Index t = nb.value[static_cast<std::size_t>(r)];
    const Projection pr = project_point_to_segment(p, master_, t, x);
    if (is_better_projection(pr, t, best.projection, best.segment)) best.segment = t, best.projection = pr;
  }
  return best;
}

}  // namespace slideline
