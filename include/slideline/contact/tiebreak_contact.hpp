#pragma once
/// TiebreakContact: DYNA3D's penalty ties with failure, Type 8 (nodes spotwelded to a surface:
/// failure per slave node) and Type 9 (tied surfaces with failure: failure per slave segment).
/// One class serves both: they share the tie springs and the post-failure contact and differ only
/// in the failure unit (FailureUnit).
///
/// Tie: each slave node s is held at its master point (found once, tie_search.hpp) by an
/// isotropic penalty spring on delta = x_s - sum N_a x_a - d_s (d_s the offset at tie time):
/// f_s = -k_s delta on the slave, -N_a f_s on each master node. The stiffness per unit area of the
/// master segment is that of penalty contact with f = SLSFAC x SFS:
///   solid face  kappa = f K A / V     (so kappa A = f K A^2 / V, LS-DYNA's segment stiffness)
///   shell       kappa = f K / max diagonal
/// Type 8: k_s = kappa A_master (the per-node spring of penalty contact).
/// Type 9: k_s = kappa x (the slave node's tributary area over the slave segments not yet failed):
///   each slave segment j contributes kappa_s A_j / 4 (A_j / 3 on a triangle) to each corner.
///   A uniform traction then needs a uniform gap, so corner, edge and interior segments carry the
///   same stress (DYNA3D uses the master segment stiffness for every node, which puts 21 % too much
///   force on corner nodes at factor 10, report 6.8.1). The force of segment j is the sum of its
///   corners' shares -kappa_s (A_j / 4) delta_s.
/// Compression: the normal part of the spring pushes c times stiffer when the slave is pressed
///   into the master, c = sum over the links of kappa A_master / sum of kappa x tributary area
///   (>= 1): the total stiffness of the penalty node springs of the contact that takes over after
///   failure (Type 3 / 5, kappa A_master per slave node, DYNA3D's rule), spread by tributary area so
///   that a uniform pressure still needs a uniform gap. c = 1 for Type 8 (its spring is already
///   kappa A_master); 4.1 on sslide9ps (16 slave nodes on master faces of 0.257, unit area).
///
/// Failure: F_n = tensile normal part (0 in compression: a compressed tie does not fail in
/// tension), F_s = |tangential part|, with n the master normal oriented towards the slave side.
///   Type 8 (per node):    (F_n / NFLF)^NEN + (F_s / SFLF)^MES >= 1
///   Type 9 (per segment): (F_n / (NFLF A_j))^2 + (F_s / (SFLF A_j))^2 >= 1
/// A zero or negative failure force or stress disables its term. Failure is permanent; it takes
/// effect from the next cycle.
///
/// Hand-over: a failed segment's share of each corner's area leaves the tie and enters penalty
/// node-on-segment contact with exponential Coulomb friction (Type 8 then behaves as Type 5,
/// Type 9 as Type 3), with the same stiffnesses per unit area (normal c kappa, stick kappa, times
/// the failed share). So a Type 9
/// node with some of its segments failed is tied on the rest of its area and in contact on the
/// failed part: in compression the normal force c kappa (tied + failed area) x gap does not jump
/// when a segment fails, and the failed area keeps carrying friction (mu N of its share) instead of
/// nothing. The tie's tangential force on the failed share starts the contact's friction stick
/// force (capped at mu N by the next cycle's return map). A node is released (tie gone) when all
/// of its slave segments failed. The contact is one ContactPairs stage (search/contact_pairs.hpp)
/// without a broad phase: seeded with the tie points' segments and sides, its offset the tie-time
/// gap, it tracks the node's segment (SegmentTracking::stay_while_inside), pushes out along the normal when the node penetrates the surface through its tie
/// point (gap below the tie-time gap) and carries a stick spring in the tangent plane.
/// master_force() is the sum of the forces added to master nodes (tie and contact).
#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "slideline/contact/contact_algorithm.hpp"
#include "slideline/contact/friction/exponential_coulomb.hpp"
#include "slideline/contact/mixed_mode_cohesive_law.hpp"
#include "slideline/contact/search/closest_point.hpp"
#include "slideline/contact/search/contact_pairs.hpp"
#include "slideline/contact/search/tie_offset.hpp"
#include "slideline/contact/search/tie_search.hpp"
#include "slideline/contact/shell_offset.hpp"
#include "slideline/mesh/segment_geometry.hpp"
#include "slideline/mesh/segment_stiffness.hpp"
#include "slideline/mesh/surface.hpp"

namespace slideline {

struct TiebreakParameters {
  enum class FailureUnit : std::uint8_t { node, segment };
  FailureUnit unit = FailureUnit::node;
  Real penalty_factor = 1.0;  ///< f = SLSFAC x SFS
  Real normal_failure = 0.0;  ///< NFLF: force (Type 8) or stress (Type 9); <= 0: no normal failure
  Real shear_failure = 0.0;   ///< SFLF: likewise
  Real normal_exponent = 2.0; ///< NEN (Type 8; Type 9 uses 2)
  Real shear_exponent = 2.0;  ///< MES (Type 8; Type 9 uses 2)
  ExponentialCoulomb friction;
  /// A released node (all of its area failed) leaves this class: its contact is the owner's (the
  /// automatic pass of *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK, automatic_tiebreak_contact.hpp).
  /// Until then the failed share of a partly failed node is in contact here, as in Type 9.
  bool release_to_owner = false;
  /// The contact taking over is two-sided (the automatic card): its master side's nodes that lie
  /// on tied slave segments push too, each with its slave segment's stiffness kappa_s A_s. Those
  /// springs join the compression factor c, so that the normal force does not jump at release.
  bool two_sided_contact = false;
  /// OPTION 9 (and 6) of the automatic card (release_to_owner set): each tie spring follows the mixed-mode
  /// traction-separation law `cohesive` (damage per tied node, mixed_mode_cohesive_law.hpp) instead
  /// of the stress criterion; a node is released when its damage reaches 1, a slave segment fails
  /// when all of its nodes are released. cohesive.en <= 0: the tie's penalty stiffness per unit
  /// area (LS-DYNA's default for CN); cohesive.et is set per node to ct2cn x en.
  bool mixed_mode = false;
  /// OPTION 4 of the automatic card: the tie holds the normal direction only (tension and
  /// compression, failure by the normal stress; set shear_failure 0); tangentially a tied node
  /// slides with Coulomb friction (`friction`) on the compressive part of its normal tie force,
  /// through a stick spring of the tie's stiffness (no friction in tension).
  bool normal_only = false;
  MixedModeCohesiveLaw cohesive;
  Real ct2cn = 1.0;
  /// OPTION 8 of the automatic card (mixed_mode set): shell segments with thickness offsets
  /// (shell_offset.hpp; each side's rule, on). The tie search ties a slave within its tolerance of
  /// the two contact surfaces (|gap| <= 0.3 x size + both offsets); the tie keeps its tie-time
  /// offset in the master segment's frame (TiebreakContact::tie_stretch), as every tie here does.
  /// Off (both rules off): the solid faces' tie search.
  ShellOffsetRule slave_shells, master_shells;
  bool offset_shells() const { return slave_shells.on || master_shells.on; }
};

class TiebreakContact final : public ContactAlgorithm, public ContactForces {
 public:
  /// slaves: slave node indices (Type 8: a node set; Type 9: the slave surface's nodes);
  /// slave_surface: the slave segments (Type 9; empty for Type 8); master: with adjacency built.
  TiebreakContact(std::string name, std::vector<Index> slaves, Surface slave_surface, Surface master,
                  TiebreakParameters p)
      : name_(std::move(name)), candidates_(std::move(slaves)), slave_surface_(std::move(slave_surface)),
        pairs_({}, {}, std::move(master), ShellOffsetRule{}, nullptr, pairs_options()), p_(p) {}

  const std::string& name() const override { return name_; }

  void initialize(const ContactContext& c) override;
  ContactPhases phases() override { return {.forces = this}; }
  void apply_forces(const NodalFields& nodes, const StepTimes& times, ContactForceView out) override;
  /// The ties' springs' vote (2 / omega, omega^2 = k (1/m_s + 1/m_lightest master)), each with
  /// the elements on its nodes when StepTimes::element_steps is given (element_steps_view.hpp).
  Real stable_dt() const override { return vote_; }
  Vec3 slave_force() const override { return slave_; }
  Vec3 master_force() const override { return master_total_; }
  Real friction_work() const override { return friction_work_; }
  /// Type 9: `first_failure_stress` = (max, mean, max/mean) of the slave segments' normal traction
  /// (stress) in the cycle the first segment fails; zero until then (docs/output.md).
  void append_output_names(std::vector<std::string>& names) const override {
    if (p_.unit == TiebreakParameters::FailureUnit::segment) names.push_back("first_failure_stress");
  }
  void write_output_values(std::span<Real> out) const override {
    if (p_.unit != TiebreakParameters::FailureUnit::segment) return;
    for (int c = 0; c < 3; ++c) out[static_cast<std::size_t>(c)] = first_failure_stress_[c];
  }

  /// Slave nodes tied at initialize (each with its master point).
  const std::vector<TiePoint>& links() const { return links_; }
  const std::vector<Index>& untied_nodes() const { return untied_nodes_; }
  /// Per link: 1 once the node is released from its tie (all of its area in contact).
  const std::vector<std::uint8_t>& released() const { return released_; }
  /// Per slave segment (Type 9): 1 once it failed.
  const std::vector<std::uint8_t>& failed_segments() const { return segment_failed_; }
  /// Per link: the current tie spring stiffness (force / length).
  Real stiffness(std::size_t k) const { return kappa_[k] * area_[k]; }
  /// Mixed mode (OPTION 6, 9): per link, the damage D in [0, 1].
  const std::vector<Real>& damage() const { return damage_; }
  /// Mixed mode: the energy the cohesive springs dissipated so far (their work less the elastic
  /// energy they still hold); also in the energy ledger's contact term.
  Real cohesive_dissipation() const { return cohesive_work_ - cohesive_stored_; }
  /// Per slave segment (Type 9): the force of the tie on it at the last cycle (on the slave side).
  const std::vector<Vec3>& segment_forces() const { return segment_force_; }

 private:
  Real failure_index(const Vec3& f, const Vec3& n, Real fn_fail, Real fs_fail, Real en, Real es) const {
    const Real fn = std::max(0.0, -f.dot(n));
    const Real fs = (f - f.dot(n) * n).norm();
    Real r = 0.0;
    if (fn_fail > 0.0) r += std::pow(fn / fn_fail, en);
    if (fs_fail > 0.0) r += std::pow(fs / fs_fail, es);
    return r;
  }
  Vec3 oriented_normal(std::size_t k, const Vec3Field& x) const {
    return static_cast<Real>(pairs_.side(k)) * segment_normal(master(), links_[k].segment, x);
  }
  const Surface& master() const { return pairs_.master(); }
  /// vote_ for this cycle: the springs alone (empty `elements`), else each with its nodes' elements.
  void update_step_vote(const ElementStepsView& elements);
  /// The contact after failure: no search (the tie search seeds it), one-hop tracking, the side
  /// fixed at tie time.
  static ContactPairsOptions pairs_options() {
    ContactPairsOptions o;
    o.side_memory = SideMemory::keep_across_segments;
    o.tracking = SegmentTracking::stay_while_inside;
    return o;
  }
  /// Adds f to master node i and to the master total (master_force: what the masters received).
  void add_to_master(ContactForceView out, Index i, const Vec3& f) {
    out.force.add(i, f);
    master_total_ += f;
  }
  /// Seeds the contact-pairs stage with the tie points (segments, sides per link: +1 / -1).
  void seed_contact(const Vec3Field& x, const std::vector<std::int8_t>& side);
  /// Type 9: the tie force on slave segment j (slave side) and the sum of its links' oriented normals.
  void segment_tie_force(Index j, const Vec3Field& x, Vec3& fj, Vec3& nj) const;
  void record_first_failure_stress(const Vec3Field& x);
  /// Sum of kappa A_master over the links (the one-sided contact's springs), and the springs of
  /// the master side's nodes on tied slave segments (two_sided_contact); force / length.
  Real tie_springs(const Surface& master, const Vec3Field& x) const;
  Real reverse_springs(const ContactContext& c) const;
  /// Moves `share` of link k's area from the tie to the contact, handing its tangential force
  /// over to the friction stick force; releases the node when no tied area is left.
  void hand_over(std::size_t k, Real share, const Vec3& n);
  /// Penalty contact with friction of link k's failed share (normal stiffness kn, stick kk);
  /// returns the force on the slave node (the master side goes through add_to_master).
  Vec3 contact_after_failure(std::size_t k, Real kn, Real kk, const NodalFields& nodes, const StepTimes& times,
                             ContactForceView out);
  /// Mixed mode (OPTION 9): the law of link k (its normal stiffness per area and ct2cn x it).
  MixedModeCohesiveLaw cohesive_law(std::size_t k) const {
    MixedModeCohesiveLaw l = p_.cohesive;
    l.en = p_.cohesive.en > 0.0 ? p_.cohesive.en : kappa_[k];
    l.et = p_.ct2cn * l.en;
    return l;
  }
  /// Mixed mode: the tie forces from the cohesive law, damage, releases (tiebreak_cohesive.cpp).
  void apply_cohesive(const NodalFields& nodes, ContactForceView out);
  /// Link k's tie stretch at x: x_slave - x_point - the tie-time offset, carried in the master
  /// segment's frame (segment_frame: it turns with the segment, so a rigid rotation of a pair tied
  /// at a stand-off h does not stretch the tie by about h theta). An offset of round-off size
  /// (below kCarriedTieOffset of the segment's diagonal: the slave on the surface) has no direction
  /// to carry and is subtracted as it was at tie time.
  Vec3 tie_stretch(std::size_t k, const Vec3Field& x) const {
    const TiePoint& t = links_[k];
    if (!carried_[k]) return x.get(t.slave) - tie_point_value(t, x) - t.offset;
    return x.get(t.slave) - tie_point_value(t, x) - carried_tie_offset(master(), t.segment, x, offset_local_[k]);
  }
  /// offset_shells: the tie search's options with the shell offsets (per master segment and per
  /// node index; the tables are filled here and must outlive the options).
  TieSearchOptions offset_search(const Surface& onto, const ShellOffsetRule& onto_rule, const Surface& from,
                                 const ShellOffsetRule& from_rule, std::size_t node_count,
                                 std::vector<Real>& segment_table, std::vector<Real>& node_table) const;
  /// normal_only (OPTION 4): link k's tie force on the slave for stretch d: the normal spring and
  /// the friction of the tied share (tiebreak_cohesive.cpp).
  Vec3 normal_tie_force(std::size_t k, const Vec3& d, const NodalFields& nodes, const StepTimes& times);

  std::string name_;
  std::vector<Index> candidates_;  ///< the nodes the tie search may tie
  Surface slave_surface_;
  ContactPairs pairs_;  ///< the tied nodes on the master: contact points after failure, sides
  TiebreakParameters p_;
  std::vector<TiePoint> links_;
  std::vector<Index> untied_nodes_;
  std::vector<Real> kappa_;          ///< per link: stiffness per unit area (force / length^3)
  std::vector<Real> area_;           ///< per link: area its spring stands for (unfailed tributary area)
  std::vector<Real> area0_;          ///< per link: the same at tie time
  std::vector<std::uint8_t> released_;
  std::vector<Vec3> delta_;          ///< per link: tie stretch at the last cycle
  std::vector<Index> segment_links_; ///< 4 per slave segment: link indices (-1 if untied/repeated)
  std::vector<Real> segment_area_;   ///< per slave segment: area at tie time
  std::vector<Real> segment_share_;  ///< per slave segment: area per corner (A/4, A/3 on triangles)
  std::vector<std::uint8_t> segment_failed_;
  std::vector<Vec3> segment_force_;
  std::vector<Vec3> friction_force_; ///< per link: tangential force of the contact share (history)
  std::vector<Vec3> tie_friction_;   ///< normal_only: per link, the tied share's friction force (history)
  Real compression_ = 1.0;           ///< normal stiffness in compression / kappa x area (>= 1)
  Real dt_ = std::numeric_limits<Real>::max();    ///< the springs alone (initialize())
  std::vector<Real> link_inv2_;  ///< per link: omega^2 / 4 of its spring (1 / time^2; 0: no spring)
  Real vote_ = std::numeric_limits<Real>::max();  ///< stable_dt(): the last update_step_vote()
  Real friction_work_ = 0.0;
  Vec3 slave_ = Vec3::Zero(), master_total_ = Vec3::Zero();
  Vec3 first_failure_stress_ = Vec3::Zero();  ///< Type 9: (max, mean, max/mean) normal traction
  /// Per link: whether its tie-time offset is carried in the master segment's frame, and its
  /// components there (segment_frame at tie time: e1, e2, n).
  std::vector<std::uint8_t> carried_;
  std::vector<Vec3> offset_local_;
  std::vector<Real> damage_;         ///< mixed mode: per link, the damage
  std::vector<Vec3> tie_force_;      ///< mixed mode: per link, the force on the slave at the last cycle
  Real cohesive_work_ = 0.0;         ///< mixed mode: work done on the cohesive springs (trapezoidal)
  Real cohesive_stored_ = 0.0;       ///< mixed mode: elastic energy the springs hold now
};

}  // namespace slideline
