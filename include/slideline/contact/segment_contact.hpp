#pragma once
/// Segment-based penalty contact (LS-DYNA SOFT = 2 on *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE and
/// *CONTACT_AUTOMATIC_SINGLE_SURFACE, flat segments, surface penetration only: SBOPT 2, DEPTH 2).
/// Contact is between segments, not between a node and a segment: for every segment a and each of
/// its 2 x 2 Gauss points x_q, the candidates b are the segments a may meet (the other side's on
/// the two-sided card, every other segment on the single-surface card; never b = a, a segment
/// sharing a node with a, or another face of a's own element) that face a (normals within 60 deg
/// of opposite for two solid faces, of parallel or opposite where a shell is involved) and that
/// x_q lies over. With g = (x_q - x_b) . n_b the signed distance from b's (mid-)surface and s the
/// side of b that x_q is on (+1 for a solid face; for a shell the sign of g, remembered while the
/// point stays within o_a + o_b of it, the automatic pass's side memory; a shell's point meets a
/// solid face only while its mid-surface lies less than o_a behind it), the penetration is
///   d_q = max(0, o_a + o_b - s g - d0_q),
/// o_s the segment's offset (half a shell's contact thickness: SST / MST or the section's, times
/// SFST / SFMT; 0 for a solid face) and d0_q the penetration found at t = 0 (LS-DYNA's SOFT = 2
/// baseline, shrinking as the segments separate). The least-penetrated admitted b is the pair.
/// The force f = 0.5 w_q k_ab d_q s n_b acts on a's nodes with a's shape functions at the Gauss
/// point and, opposite, on b's nodes with b's at the projection (w_q: the Gauss point's share of
/// a's area; 0.5: every pair is seen from both of its segments). Two flat segments pressed
/// uniformly by d therefore carry k_ab d. Stiffness (LS-DYNA theory manual, segment-based contact):
///   k_ab = 0.5 SLSFAC SFS m_a m_b / (m_a + m_b) / dt_c^2,
/// m_s = the sum of the lumped masses of segment s's nodes (solid or shell), dt_c the run's initial
/// step (StepTimes::dt_initial), replaced by the step just taken when that is more than 5 % above it.
/// Friction (FS, FD, DC) on a stick spring per Gauss point and VDC on each point's normal spring
/// (set_friction). The search: the broad phase's segment boxes against each segment's bounding
/// sphere box grown by the offsets, every cycle (BSORT 1) or every BSORT cycles with an allowance
/// (set_search_interval) that keeps the candidates a superset of the every-cycle search's, which
/// each cycle's exact box test then narrows to the same set: the same forces, bit for bit. Forces
/// per segment in parallel, scattered serially in segment order (thread-count independent).
/// docs/contact.md, "Segment-based contact (SOFT = 2)".
#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "slideline/contact/contact_algorithm.hpp"
#include "slideline/contact/friction/exponential_coulomb.hpp"
#include "slideline/contact/search/broad_phase.hpp"
#include "slideline/contact/search/search_cadence.hpp"
#include "slideline/mesh/surface.hpp"

namespace slideline {

/// One Gauss point of one segment in contact at the last cycle.
struct SegmentContactRecord {
  Index other = -1;               ///< segment b it presses on (-1: none this cycle)
  Vec3 force = Vec3::Zero();      ///< force on segment a's point (force)
  std::array<Real, 4> shape_a{};  ///< a's shape functions at the Gauss point
  std::array<Real, 4> shape_b{};  ///< b's shape functions at the projection
  Real weight = 0.0;              ///< 0.5 w_q (dimensionless)
  Real penetration = 0.0;         ///< d_q beyond the baseline (length, >= 0)
  Real stiffness = 0.0;           ///< k_ab (force / length)
  Real dt_inv2 = 0.0;             ///< omega^2 / 4 of this point's spring (1 / time^2)
  int side = 1;                   ///< s: the side of b the point is on (+1 on a solid face)
  Real normal_force = 0.0;        ///< f_n after the VDC damping (force, >= 0)
  Vec3 friction = Vec3::Zero();   ///< the tangential (friction) part of `force` (force)
  Real dissipation = 0.0;         ///< friction work of this point this cycle (energy, >= 0)
};

class SegmentContact final : public ContactAlgorithm, public ContactForces {
 public:
  /// surface: the union of both sides' segments (adjacency built); sides: per segment, bit 1 the
  /// card's slave side, bit 2 its master side; stiffness_scale = SLSFAC x SFS.
  SegmentContact(std::string title, Surface surface, std::vector<std::uint8_t> sides,
                 std::unique_ptr<BroadPhase> broad_phase, Real stiffness_scale);

  /// Per segment: its offset o_s (length; half a shell's contact thickness, 0 for a solid face).
  /// Before initialize(); never called: every offset 0.
  void set_offsets(std::vector<Real> offsets);
  /// Single surface (*CONTACT_AUTOMATIC_SINGLE_SURFACE): every segment is on both sides (sides all
  /// 3); `parts` (ascending deck ids) name the "transmitted_force" channels, the force of the
  /// second part of a pair on the first (as Type 12 reports it), for two parts or more.
  void set_single_surface(std::vector<Id> parts);
  /// Friction (FS, FD, DC: the exponential Coulomb law on a stick spring per Gauss point, k_t =
  /// the point's normal spring) and VDC (`viscous_damping` = VDC / 100, of critical, on each
  /// point's normal spring). Before initialize(); never called: frictionless, undamped.
  void set_friction(const ExponentialCoulomb& law, Real viscous_damping);
  /// BSORT (optional card A): cycles between broad-phase searches, >= 0; 0 is
  /// kDefaultSearchInterval, 1 a search every cycle (the candidates exact, no allowance). Between
  /// two searches the candidates found with an allowance 5 a (a = max(1.5 v_max dt BSORT, a_min),
  /// v_max the largest surface nodal speed at the search) serve; a search comes early when any
  /// surface node has moved a since the last one (see docs/contact.md, "Search cadence"). Before
  /// initialize(); never called: every cycle.
  void set_search_interval(int cycles);
  /// BSORT = 0: LS-DYNA "determines the interval"; here the early re-search decides, this caps it.
  static constexpr int kDefaultSearchInterval = 10;
  /// Broad-phase searches run so far (initialize()'s included).
  Index search_count() const { return searches_; }
  /// a: the displacement a surface node may make before the next search is due (length; 0 with
  /// BSORT 1).
  Real search_allowance() const { return allowance_; }
  Real friction_work() const override { return friction_work_; }

  const std::string& name() const override { return name_; }
  void initialize(const ContactContext& context) override;
  ContactPhases phases() override { return {.forces = this}; }
  void apply_forces(const NodalFields& nodes, const StepTimes& times, ContactForceView out) override;
  Real stable_dt() const override { return dt_; }
  Vec3 slave_force() const override { return slave_; }
  Vec3 master_force() const override { return -slave_; }
  void append_output_names(std::vector<std::string>& names) const override;
  void write_output_values(std::span<Real> out) const override;
  /// Per part pair (a < b in parts order, set_single_surface): the force part b exerts on part a.
  const std::vector<Vec3>& transmitted_forces() const { return transmitted_; }

  const Surface& surface() const { return surface_; }
  /// m_s: the sum of the lumped masses of segment s's nodes at initialize() (mass).
  Real segment_mass(Index s) const { return mass_[static_cast<std::size_t>(s)]; }
  /// o_s (length).
  Real segment_offset(Index s) const { return offset_.empty() ? 0.0 : offset_[static_cast<std::size_t>(s)]; }
  /// The step the springs are sized by (time): 0 before the first cycle.
  Real sizing_step() const { return dt_c_; }
  /// 4 records per segment (Gauss points in the order (-,-), (+,-), (+,+), (-,+)).
  std::span<const SegmentContactRecord> records() const { return records_; }
  /// Gauss points found penetrating at t = 0 (their depth kept as the baseline) and the deepest.
  Index initial_penetration_count() const { return initial_count_; }
  Real largest_initial_penetration() const { return initial_max_; }

 private:
  void update_geometry(const Vec3Field& x);
  void search(const Vec3Field& x, Real inflation);
  void search_ahead(const NodalFields& nodes, Real dt);
  void evaluate(Index a, const NodalFields& nodes, bool baseline, Real dt_prev);
  void add_damping_and_friction(std::size_t g, Index held, SegmentContactRecord& rec, const Vec3& n, const Index* ca,
                                const Index* cb, Real inv_m, const NodalFields& nodes, Real dt_prev);
  /// The forces into `out`, the part-pair totals, and the step vote: per point 1 / dt^2 = its
  /// dt_inv2 + the largest 1 / dt_e^2 of the two segments' nodes it joins (`elements`, empty: 0).
  void scatter(ContactForceView out, const ElementStepsView& elements);
  void add_transmitted(Id on, Id from, const Vec3& force);

  std::string name_;
  Surface surface_;
  std::vector<std::uint8_t> side_;
  std::unique_ptr<BroadPhase> broad_phase_;
  Real scale_ = 0.1;
  std::vector<Real> mass_;
  std::vector<Real> depth_limit_;     ///< per segment: half its longer diagonal at t = 0
  std::vector<Index> index_;          ///< 0 .. segments - 1, the broad-phase query list
  Vec3Field centroid_;                ///< per segment, at the last search
  Vec3Field normal_;                  ///< per segment: its unit normal at the last search
  std::vector<Real> radius_;          ///< per segment: largest centroid-to-corner distance
  std::vector<Candidate> candidates_; ///< (segment a, segment b) of the last search
  std::vector<Index> first_;          ///< per segment a: its first candidate (CSR, segments + 1)
  std::vector<std::uint8_t> admit_;   ///< per candidate: a may meet b (evaluate, a's range only)
  std::vector<SegmentContactRecord> records_;
  std::vector<Real> baseline_;        ///< per Gauss point: d0 (length)
  std::vector<Index> baseline_of_;    ///< per Gauss point: the segment d0 was measured on
  Real dt_c_ = 0.0;
  Real dt_ = std::numeric_limits<Real>::max();
  Vec3 slave_ = Vec3::Zero();
  Index initial_count_ = 0;
  Real initial_max_ = 0.0;
  std::vector<Real> offset_;          ///< per segment: o_s (empty: all 0)
  Real max_offset_ = 0.0;
  std::vector<std::int8_t> memory_;   ///< per Gauss point: remembered side of a shell b (0: none)
  std::vector<Index> memory_of_;      ///< per Gauss point: the shell segment memory_ refers to
  std::vector<Id> parts_;             ///< single surface: the parts (transmitted forces)
  std::vector<Vec3> transmitted_;     ///< per part pair
  ExponentialCoulomb friction_;
  bool frictional_ = false;
  Real viscous_damping_ = 0.0;        ///< VDC / 100
  std::vector<Vec3> slip_;            ///< per Gauss point: elastic slip from the sticking point (length)
  std::vector<Index> slip_on_;        ///< per Gauss point: the segment slip_ refers to (-1: none)
  Real friction_work_ = 0.0;          ///< accumulated (energy)
  // Search cadence (BSORT): see set_search_interval.
  int interval_ = 1;                  ///< cycles between searches (1: every cycle, exact)
  int since_search_ = 0;              ///< cycles since the last search
  bool inflated_ = false;             ///< the candidates came from an inflated search: box-test them
  Real allowance_ = 0.0;              ///< a (length)
  Real allowance_floor_ = 0.0;        ///< a_min: 1e-3 x the mean half diagonal (length)
  Index searches_ = 0;
  std::vector<Aabb> box_;             ///< per segment: its corners' box this cycle (BSORT > 1)
  std::vector<Real> query_radius_;    ///< per segment: radius_ + 5 a at the last search
  SearchCadence watch_;               ///< the surface nodes' displacement since the last search
};

}  // namespace slideline
