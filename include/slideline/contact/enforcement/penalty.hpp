#pragma once
/// One penalty contact pass: a list of slave nodes against one master Surface, with Coulomb
/// friction (exponential decay) on a tangential stick spring. The building block of every
/// penalty interface (Types 3 and 10: one or two passes; 5: node-set slaves; 12: all nodes
/// against all segments with the single-surface filters). See docs/contact.md, "Penalty contact".
///
/// Per cycle (compute(), then scatter()):
/// - Pairs: the pass holds one ContactPairs stage (search/contact_pairs.hpp: broad phase and its
///   cadence, tracking, offsets, side memory): each slave's segment and closest point. Options:
///   allowance = margin_fraction x the smallest segment diagonal, boxes padded by the largest
///   offsets, the side forgotten on a new segment; the automatic pass skips incident segments and
///   its own shell part and re-picks among its candidates between searches.
/// - Gap: g = s (x_s - x_p) . n - o_m - o_s + g_0, with n the segment normal at the closest point
///   x_p, s = +1 for a solid face and the side the slave is on for a shell (frozen while in
///   contact), o_m half the master shell thickness, o_s the slave offset (half the slave shell
///   thickness, or the nodal radius), g_0 the initial-penetration allowance (below).
/// - Normal force on the slave: f_n = -k g n for g < 0 (also for g > 0 on a "sliding only" pass
///   once the node has touched), k the master segment's stiffness (force / length):
///   solid face k = f K A^2 / V, shell k = f K A / (max diagonal), f = SLSFAC x SFS (or SFM);
///   with the mortar coupling (PenaltyCoupling), k / A x the slave node's tributary area over the
///   master, and the gap and forces on mortar-weighted master points.
///   A slave beside its segment (default coupling), or deeper behind it than half its diagonal (a
///   solid face: also half its element's thickness V / A), has no force from it.
/// - Damping (VDC > 0): f_n -= c v_n, v_n the relative normal velocity (separating > 0), c a
///   fraction VDC/100 of the pair's critical damping; f_n >= 0 (no adhesion) unless sliding only.
/// - Friction: trial = (previous tangential force turned into the current tangent plane)
///   - k_t du_t, du_t the tangential slave-minus-master-point displacement over the last step
///   (dt_prev v^{n-1/2}), k_t = k; mu = mu_k + (mu_s - mu_k) exp(-beta |du_t| / dt_prev);
///   Coulomb return mapping; dissipation |F_t| (|trial| - |F_t|) / k_t per slip. The history is a
///   global vector, so a slave changing segment carries its tangential force across unchanged.
/// - Scatter (serial, fixed order): f on the slave, -N_a f on the segment's corners.
/// Nothing allocates after initialize() except a broad-phase query returning more candidates
/// than any before it.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <vector>

#include "slideline/contact/contact_algorithm.hpp"
#include "slideline/contact/enforcement/mortar_weights.hpp"
#include "slideline/contact/friction/exponential_coulomb.hpp"
#include "slideline/contact/friction/frictionless.hpp"
#include "slideline/contact/search/contact_erosion.hpp"
#include "slideline/contact/search/contact_pairs.hpp"
#include "slideline/contact/shell_offset.hpp"
#include "slideline/core/parallel.hpp"
#include "slideline/element/element_block.hpp"
#include "slideline/mesh/segment_geometry.hpp"
#include "slideline/mesh/segment_stiffness.hpp"
#include "slideline/mesh/surface.hpp"

namespace slideline {

/// How a slave node's spring is sized and its force shared (docs/contact.md, "The contact patch
/// test"):
/// - node: DYNA3D's rule: every slave node on master segment s gets the segment's spring k_s, and
///   its force goes to the segment's corners with the shape functions at its closest point;
/// - mortar: the spring is k_s / A_s (A_s the master segment's area at initialize()) times the
///   part W of the slave node's tributary area that lies over the master, and the gap, normal and
///   force use mortar weights (mortar_weights.hpp) over the master nodes under the node's slave
///   segments: a uniform pressure reaches both sides as consistent nodal forces. Needs the slave
///   surface (set_slave_surface()); a node it cannot integrate (a triangle, nothing over the
///   master) falls back to the node rule for that cycle.
enum class PenaltyCoupling : std::uint8_t { node, mortar };

/// How a pass is set up (the factory fills it from the card).
struct PenaltyPassOptions {
  Real stiffness_scale = 0.1;        ///< f = SLSFAC x SFS (dimensionless)
  /// Offsets of the master's shell segments (shell_offset.hpp): on, thickness MST/SST, scale
  /// SFMT/SFST.
  ShellOffsetRule master_shells{true, 0.0, 1.0};
  bool sliding_only = false;         ///< Type 10 "sliding only": no separation once in contact
  bool automatic = false;            ///< Type 12: skip own segments and faces not facing the node
  Real margin_fraction = 0.5;        ///< broad-phase margin = fraction x smallest segment diagonal
  /// Stick law: largest elastic slip at the static limit, gamma = fraction x the master segment's
  /// largest diagonal (dimensionless); the stick stiffness is k_t = max(k, mu_s N / gamma),
  /// capped at stick_stiffness_cap x k (docs/contact.md, "Penalty contact", Friction).
  Real elastic_slip_fraction = 1e-3;
  Real stick_stiffness_cap = 4.0;    ///< k_t <= cap x k: the pair's stable step at most halved
  PenaltyCoupling coupling = PenaltyCoupling::node;  ///< stiffness rule and force distribution
  /// Viscous contact damping (VDC / 100): a dashpot c = fraction x 2 m omega on the relative
  /// normal velocity of each engaged pair, omega^2 = k (1/m_s + sum N_a^2 / m_a), m = min(m_s,
  /// master point mass); the normal force stays compressive (docs/contact.md, "Viscous contact
  /// damping"). 0: no dashpot (no arithmetic of it at all).
  Real viscous_damping = 0.0;
  /// IGNORE = 1 or 2 (*CONTACT_... optional card C, or *CONTROL_CONTACT card 4): initial
  /// penetrations stay where they are as the springs' zero (the allowance g_0, shrinking as the
  /// node moves out) instead of being moved out before the first step.
  bool keep_initial_penetrations = false;
  /// SOFT = 1 (LS-DYNA's soft constraint): each pair's spring is the larger of the segment's k and
  /// 0.5 x soft_scale x m* / dt_c^2, m* = min(slave node mass, smallest mass of the segment's
  /// nodes), dt_c = StepTimes::dt_initial (fixed for the run). soft_scale = SOFSCL; 0: SOFT = 0.
  Real soft_scale = 0.0;
  /// VC (stress): the tangential force of a slave node is capped at VC x the area of its master
  /// segment (at initialize()), below the Coulomb limit mu f_n. 0: no cap.
  Real viscous_friction = 0.0;
  /// PENCHK = 1 (LS-DYNA): XPENE; a node deeper than XPENE x its master segment's thickness (a
  /// shell's thickness, 1/20 of a solid face's shorter diagonal) is released, on top of the
  /// geometric limit every pass applies (contact_depth_limit). 0: that limit alone.
  Real penetration_check = 0.0;
};

/// The per-slave result of one cycle, kept for the serial scatter.
struct PenaltyRecord {
  Index segment = -1;           ///< -1: no force this cycle
  Vec3 force = Vec3::Zero();    ///< force on the slave node (force)
  std::array<Real, 4> shape{};  ///< master shape functions
  Real dissipation = 0.0;       ///< friction work of this cycle (energy, >= 0)
  Real dt_inv2 = 0.0;           ///< omega^2 / 4 of this pair's spring (1 / time^2), 0 if no segment
  /// 1 / dt_e^2 of the elements on the pair's nodes (the slave and the master nodes it is coupled
  /// to; 0 without StepTimes::element_steps): the pass votes 1 / sqrt(dt_inv2 + element_inv2).
  Real element_inv2 = 0.0;
  bool mortar = false;          ///< the force is shared by the slave's MortarWeights, not `shape`
};

class PenaltyPass {
 public:
  /// slaves: internal node indices (ascending); slave_offset: one offset per slave (length);
  /// master: the master surface (adjacency built); broad_phase: a fresh broad phase.
  PenaltyPass(std::vector<Index> slaves, std::vector<Real> slave_offset, Surface master,
              std::unique_ptr<BroadPhase> broad_phase, PenaltyPassOptions options)
      : pairs_(std::move(slaves), std::move(slave_offset), std::move(master), options.master_shells,
               std::move(broad_phase), pairs_options(options)),
        opt_(options) {}
  PenaltyPass(const PenaltyPass&) = delete;
  PenaltyPass& operator=(const PenaltyPass&) = delete;

  /// Stiffness per segment, search structures and state; detects initial penetrations (they
  /// become the spring's zero, see initial_penetrations()). Allocates.
  void initialize(const NodalFields& nodes, const std::vector<std::unique_ptr<ElementBlock>>& blocks);
  /// The same with the stiffness of each master segment given (force / length, one per segment,
  /// already scaled: stiffness_scale is not applied), e.g. for surfaces without element blocks.
  void initialize(const NodalFields& nodes, std::vector<Real> segment_stiffness);

  /// Moves every slave found below the master surface (by initialize(), or by the last call of
  /// this function) out to it along the master normal at its closest point, x and x0 together
  /// (LS-DYNA IGNORE = 0: no element starts strained), then re-reads the gaps at the new
  /// positions; a slave still below (a curved master) keeps its depth as the spring's zero.
  /// Returns the number of nodes moved; `largest` gets the largest move (length). Allocates nothing.
  /// With keep_initial_penetrations (IGNORE = 1, 2) nothing moves and 0 is returned.
  Index resolve_initial_penetrations(NodalFields& nodes, Real& largest);
  bool keeps_initial_penetrations() const { return opt_.keep_initial_penetrations; }
  /// Re-reads the initial penetrations at the current positions (after another pass moved nodes).
  void redetect_initial_penetrations(const NodalFields& nodes);

  /// Search or tracking, gaps, normal and friction forces for every slave at x^n, v^{n-1/2}
  /// (parallel over slaves; writes records()). No allocation in a steady state. Friction: the
  /// interface's compile-time friction policy (Frictionless or ExponentialCoulomb).
  template <class Friction = Frictionless>
  void compute(const NodalFields& nodes, const StepTimes& times, const Friction& friction = {});

  /// Adds the forces of the last compute() into out (serial, slave order), and accumulates the
  /// slave and master totals (force) and the friction work (energy).
  void scatter(ContactForceView out, Vec3& slave_total, Vec3& master_total, Real& friction_work) const;

  /// Largest stable step of the pass's springs (time): 2 / omega, omega^2 = k (1/m_s + sum N^2/m_a),
  /// over every slave with a segment at the last compute(); with StepTimes::element_steps, each
  /// pair's 1 / dt^2 = omega^2 / 4 + 1 / dt_e^2 of its nodes' elements (element_steps_view.hpp).
  Real stable_dt() const { return dt_; }

  std::span<const Index> slaves() const { return pairs_.slaves(); }
  const Surface& master() const { return pairs_.master(); }
  /// The contact-pairs stage (search, tracking, offsets, side memory) this pass consumes.
  const ContactPairs& pairs() const { return pairs_; }
  std::span<const PenaltyRecord> records() const { return records_; }
  /// Stiffness of master segment s (force / length).
  Real segment_stiffness(Index s) const { return k_seg_[static_cast<std::size_t>(s)]; }
  /// Initial penetrations found by initialize(): count and largest depth (length).
  Index initial_penetration_count() const { return initial_count_; }
  Real largest_initial_penetration() const { return initial_max_; }
  /// Current signed gap of slave i (length; +inf without a segment).
  Real gap(std::size_t i) const { return gap_[i]; }
  /// The surface the slaves come from (its nodes are the slaves, in order), for the mortar
  /// coupling (PenaltyPassOptions::coupling); call before initialize().
  void set_slave_surface(Surface surface) { slave_surface_ = std::move(surface); }
  /// Which master segments each slave may meet (search/slave_orientation.hpp; indexed like
  /// slaves()), set by the factory before initialize(); default: no orientation filter.
  void set_slave_orientation(SlaveOrientation orientation) { pairs_.set_orientation(std::move(orientation)); }
  /// Two-sided automatic pass: the side masks of slaves and master segments and the master
  /// segments' offsets (ContactPairs::set_sides, set_master_offsets); before initialize().
  void set_sides(std::vector<std::uint8_t> slave_sides, std::vector<std::uint8_t> segment_sides,
                 std::vector<Real> segment_offsets) {
    pairs_.set_sides(std::move(slave_sides), std::move(segment_sides));
    pairs_.set_master_offsets(std::move(segment_offsets));
  }
  /// THKCHG = 1: the offsets of the slaves and master segments follow the shells' current
  /// thickness (ContactPairs::set_followed_offsets); before initialize().
  void set_followed_offsets(FollowedOffsets slaves, FollowedOffsets segments) {
    pairs_.set_followed_offsets(std::move(slaves), std::move(segments));
  }
  /// The pairs a tie still holds (ContactPairs::set_held); before initialize().
  void set_held(std::span<const std::uint8_t> held_nodes, std::span<const std::uint8_t> held_segments) {
    pairs_.set_held(held_nodes, held_segments);
  }
  /// Contact with eroding parts (search/contact_erosion.hpp; the automatic passes): the slaves and
  /// segments are admitted only while active, the flags re-read at the start of each compute()
  /// (a new search when one changed). Before initialize() and after set_slave_orientation().
  void set_erosion(ContactErosion erosion) {
    erosion_ = std::move(erosion);
    eroding_ = true;
    pairs_.set_erosion(erosion_.slave_active(), erosion_.segment_active(), erosion_.own_active(),
                       erosion_.slave_free());
  }
  /// The erosion state (null without set_erosion()).
  const ContactErosion* erosion() const { return eroding_ ? &erosion_ : nullptr; }
  /// Part of each slave node (automatic pass: its own-part filter), set by the owner.
  std::vector<Id>& slave_part() { return pairs_.slave_parts(); }
  const std::vector<Id>& slave_part() const { return pairs_.slave_parts(); }

 private:
  /// The stage's options for a pass: the search allowance, Type 12's single-surface filters, and
  /// the side forgotten on a new segment.
  static ContactPairsOptions pairs_options(const PenaltyPassOptions& o) {
    ContactPairsOptions p;
    p.allowance_fraction = o.margin_fraction;
    p.skip_incident = o.automatic;
    p.skip_own_shell_part = o.automatic;
    p.repick_between_searches = o.automatic;
    return p;
  }
  struct CoupledPoint {
    Vec3 dx, dv;     ///< slave minus coupled master point: position (length), velocity
    Real inv_mass;   ///< 1/m_s + sum weight^2 / m_a (1 / mass)
  };
  /// The normal force fn (force, > 0 compressive) with the viscous dashpot of the pair added
  /// (opt_.viscous_damping > 0), and the factor r (<= 1) by which the dashpot shortens the pair's
  /// stable step: 2 / omega x (sqrt(1 + zeta^2) - zeta).
  struct Damped {
    Real fn, step_factor;
  };
  Damped damp_normal_force(Real fn, Real k, const CoupledPoint& cp, const Vec3& n, Real slave_mass) const;
  static CoupledPoint coupled_point(Index node, const Projection& pr, const Index* c, const MortarWeights* mw,
                                    const NodalFields& nodes);
  /// What the stick spring of one slave needs: the oriented normal, the normal force (force), the
  /// spring k (force / length), 1/m of the coupled pair, gamma (length), the relative velocity,
  /// and the VC cap of the tangential force (force; +inf without VC).
  struct StickInputs {
    Vec3 normal;
    Real fn, k, inv_mass, slip;
    Vec3 dv;
    Real cap;
  };
  /// The pair's spring (force / length): the segment's `k`, or with SOFT = 1 the larger of it and
  /// 0.5 SOFSCL m* / dt_c^2 (PenaltyPassOptions::soft_scale).
  Real pair_stiffness(Real k, Real slave_mass, std::size_t segment, Real dt_initial) const {
    if (!(opt_.soft_scale > 0.0)) return k;
    const Real m = std::min(slave_mass, soft_mass_seg_[segment]);
    return std::max(k, 0.5 * opt_.soft_scale * m / (dt_initial * dt_initial));
  }
  template <class Friction>
  void add_friction(std::size_t i, const StickInputs& in, const StepTimes& times, const Friction& law,
                    PenaltyRecord& rec, Vec3& f);
  template <class Friction>
  void evaluate(std::size_t i, const NodalFields& nodes, const StepTimes& times, const Friction& friction);
  /// Search and gaps at t = 0; each slave below the surface (beyond round-off) keeps its depth as
  /// the spring's zero (g0_). Returns the count; `deepest` gets the largest depth.
  Index detect_initial_penetrations(const NodalFields& nodes, Real& deepest);

  ContactPairs pairs_;
  PenaltyPassOptions opt_;
  ContactErosion erosion_;  ///< set_erosion(): the activity flags pairs_ reads
  bool eroding_ = false;
  std::vector<Real> k_seg_;
  std::vector<Real> kappa_;             ///< mortar coupling: k_s / A_s per segment (else empty)
  Surface slave_surface_;               ///< mortar coupling: the slaves' own surface
  std::vector<MortarWeights> mortar_;   ///< mortar coupling: per slave, this cycle's weights
  std::vector<std::uint8_t> touched_;   ///< sliding only: has been in contact
  std::vector<Vec3> ue_;                ///< elastic slip: contact point - sticking point (length)
  std::vector<Real> slip_seg_;          ///< per master segment: gamma (length)
  std::vector<Real> soft_mass_seg_;     ///< SOFT = 1: per master segment, its smallest nodal mass
  std::vector<Real> friction_cap_seg_;  ///< VC: per master segment, VC x its area (force)
  std::vector<Real> g0_;                ///< initial-penetration allowance (length)
  /// Eroding passes: per slave, the segment it was on last cycle in contact or at its spring's zero
  /// (gap <= 0), -1 none: the sudden-penetration rule (docs/contact_erosion.md) acts on a change.
  std::vector<Index> held_segment_;
  std::vector<Real> gap_;
  std::vector<PenaltyRecord> records_;
  Real dt_ = std::numeric_limits<Real>::max();
  Index initial_count_ = 0;
  Real initial_max_ = 0.0;
};

}  // namespace slideline

#include "slideline/contact/enforcement/penalty_pass_impl.hpp"
