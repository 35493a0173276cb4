#pragma once
/// *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK, OPTION 1 (and blank / 0, its default) and 3:
/// "tracked nodes in contact and those that come into contact will permanently stick; tangential
/// motion is inhibited" (OPTION 1); "as 1 above but with failure after sticking" (OPTION 3, NFLS and
/// SFLS the failure stresses). docs/contact.md, "Automatic tiebreak, OPTION 1 and 3".
///
/// The slave side's nodes are tied one by one to the master side's segments:
/// - at t = 0, the nodes in contact (within 1e-3 of the segment size, along and across) where they are;
/// - during the run, a node the automatic pass finds penetrating a master-side segment (its pass
///   spring pushes this cycle) is tied from the next cycle at its contact point (the pass's
///   segment and shape functions), its reference state the touch: the stretch's zero is the point
///   on the surface, so the node's current penetration g is the tie's compression and the normal
///   force c k g goes on where the pass's k g left off (c k = the pass's spring on that segment).
/// The stretch is x_s - x_point - d, d the offset at the tie (a touch's tangential remainder, a
/// node tied at t = 0 off the surface): carried in the master segment's frame (tie_offset.hpp), so
/// a tied pair that turns as a rigid body keeps its ties unstretched.
/// Each tied node has an isotropic spring kappa A_k (kappa = the master segment's penalty stiffness
/// per unit area f K A / V, as the other OPTIONs; A_k the node's tributary area on the slave
/// surface, a quarter of each quadrilateral around it, a third of each triangle), its normal part
/// pushing with the pass's stiffness kappa A_master (at least kappa A_k) when closed. Nothing is
/// allocated in a step: every slave-side node of the pass has its tie slot from initialize().
///
/// OPTION 3: per tied node, (sigma_n / NFLS)^2 + (sigma_s / SFLS)^2 >= 1 with sigma = the tie force
/// over A_k (sigma_n tensile only; a zero field leaves its term out): the node is released from the
/// next cycle and the automatic pass takes it for good (it does not stick again). OPTION 1: no
/// failure. The pass never sees a tied node (ContactPairs::set_held); master-side nodes on tied
/// slave segments stay in the pass (the tie is one-way, as OPTION 2's), pushing in compression only.
#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "slideline/contact/contact_algorithm.hpp"
#include "slideline/contact/enforcement/penalty.hpp"
#include "slideline/contact/search/tie_search.hpp"
#include "slideline/mesh/surface.hpp"

namespace slideline {

struct StickingTieParameters {
  bool fails = false;         ///< OPTION 3: the stress criterion releases a tied node
  Real normal_failure = 0.0;  ///< NFLS (stress); <= 0: no normal term
  Real shear_failure = 0.0;   ///< SFLS (stress); <= 0: no shear term
};

class StickingTiebreakContact final : public ContactAlgorithm, public ContactForces {
 public:
  enum class State : std::uint8_t { free, tied, released, never };

  /// contact: the automatic surface-to-surface interface over both sides; pass: its one pass
  /// (owned by `contact`), given views of `held_nodes` (per internal node) and `held_segments` (per
  /// segment of the pass's surface) by set_held(); segment_sides: per segment of the pass's surface,
  /// bit 1 slave side, bit 2 master side; slave_nodes, master_nodes: the card's sides' nodes
  /// (ascending); slave_surface: the slave side's segments (tributary areas) and slave_to_pass the
  /// index of each in the pass's surface; master: the master side's segments and master_to_pass
  /// likewise (ties at t = 0).
  StickingTiebreakContact(std::string name, std::unique_ptr<ContactAlgorithm> contact, const PenaltyPass* pass,
                          std::vector<std::uint8_t> segment_sides, std::vector<Index> slave_nodes,
                          std::vector<Index> master_nodes, Surface slave_surface, std::vector<Index> slave_to_pass,
                          Surface master, std::vector<Index> master_to_pass, std::vector<std::uint8_t> held_nodes,
                          std::vector<std::uint8_t> held_segments, StickingTieParameters p)
      : name_(std::move(name)), contact_(std::move(contact)), pass_(pass), segment_side_(std::move(segment_sides)),
        slave_nodes_(std::move(slave_nodes)), master_nodes_(std::move(master_nodes)),
        slave_surface_(std::move(slave_surface)), slave_to_pass_(std::move(slave_to_pass)), master_(std::move(master)),
        master_to_pass_(std::move(master_to_pass)), held_node_(std::move(held_nodes)),
        held_segment_(std::move(held_segments)), p_(p) {}

  const std::string& name() const override { return name_; }
  void initialize(const ContactContext& c) override;
  ContactPhases phases() override { return {.forces = this}; }
  void apply_forces(const NodalFields& nodes, const StepTimes& times, ContactForceView out) override;
  /// The smaller of the pass's vote and the ties' springs' (each with the elements on its nodes
  /// when StepTimes::element_steps is given: element_steps_view.hpp).
  Real stable_dt() const override { return std::min(vote_, contact_->stable_dt()); }
  Vec3 slave_force() const override { return slave_ + contact_->slave_force(); }
  Vec3 master_force() const override { return master_total_ + contact_->master_force(); }
  Real friction_work() const override { return contact_->friction_work(); }

  const ContactAlgorithm& contact() const { return *contact_; }
  /// Per slave of the pass (pass().slaves() order): its state, tie point (segment of the pass's
  /// surface), the time it was tied (-1: never), its tie force on the slave at the last cycle.
  std::span<const State> states() const { return state_; }
  std::span<const TiePoint> ties() const { return tie_; }
  std::span<const Real> tie_times() const { return tie_time_; }
  std::span<const Vec3> tie_forces() const { return force_; }
  /// Per slave of the pass: tributary area on the slave surface (0 off the slave side).
  std::span<const Real> areas() const { return area_; }
  std::span<const Index> pass_slaves() const { return pass_->slaves(); }
  /// The pass's surface (both sides' segments): the surface of ties()' segments.
  const Surface& pass_surface() const { return pass_->master(); }
  /// Ties formed so far (at t = 0 included) and released so far (OPTION 3).
  Index tied_count() const { return tied_count_; }
  Index released_count() const { return released_count_; }
  /// The force of the ties alone on the slave side at the last cycle.
  Vec3 tie_slave_force() const { return slave_; }

 private:
  /// Ties pass slave i at `t` (a segment of the pass's surface) from the next cycle, at time `time`.
  void tie(std::size_t i, const TiePoint& t, Real time, const NodalFields& nodes);
  /// vote_ for this cycle: the springs alone (empty `elements`), else each with its nodes' elements.
  void update_step_vote(const ElementStepsView& elements);

  std::string name_;
  std::unique_ptr<ContactAlgorithm> contact_;
  const PenaltyPass* pass_;
  std::vector<std::uint8_t> segment_side_;
  std::vector<Index> slave_nodes_, master_nodes_;
  Surface slave_surface_;
  std::vector<Index> slave_to_pass_;
  Surface master_;
  std::vector<Index> master_to_pass_;
  std::vector<std::uint8_t> held_node_;     ///< per internal node: 1 while tied (the pass's view)
  std::vector<std::uint8_t> held_segment_;  ///< per segment of the pass: always 0 (nothing held)
  StickingTieParameters p_;

  std::vector<Real> kappa_;     ///< per segment of the pass's surface: stiffness per unit area
  std::vector<State> state_;    ///< per pass slave
  std::vector<TiePoint> tie_;   ///< per pass slave (segment: of the pass's surface)
  std::vector<Real> area_;      ///< per pass slave: tributary slave area A_k
  std::vector<Real> k_;         ///< per pass slave: kappa A_k (force / length)
  std::vector<Real> kc_;        ///< per pass slave: normal stiffness when closed (force / length)
  /// per pass slave: the stiffest pass spring of a slave segment around it (force / length): the
  /// master-side nodes on those segments stay in the pass and push alongside the tie when closed,
  /// so the tie's step vote counts it (as OPTION 2's two-sided compression factor does).
  std::vector<Real> k_reverse_;
  std::vector<Real> tie_time_;  ///< per pass slave
  std::vector<Vec3> force_;     ///< per pass slave: tie force on the slave, last cycle
  /// per pass slave: whether its tie's offset turns with the master segment, and its components in
  /// the segment's frame at the tie (tie_offset.hpp; the stretch's zero turns with the segment).
  std::vector<std::uint8_t> carried_;
  std::vector<Vec3> offset_local_;
  Index tied_count_ = 0, released_count_ = 0;
  Real dt_ = std::numeric_limits<Real>::max();  ///< the ties' springs alone
  std::vector<Real> tie_inv2_;  ///< per pass slave: omega^2 / 4 of its tie's spring (0: never tied)
  Real vote_ = std::numeric_limits<Real>::max();  ///< the ties' vote of the last update_step_vote()
  Vec3 slave_ = Vec3::Zero(), master_total_ = Vec3::Zero();
};

}  // namespace slideline
