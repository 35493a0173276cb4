#pragma once
/// *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK, OPTION 2: the slave side's nodes that touch the
/// master side at t = 0 are tied by penalty springs until their slave segments fail by the stress
/// criterion (|sigma_n| / NFLS)^2 + (|sigma_s| / SFLS)^2 >= 1 (sigma_n tensile only); then the
/// two-sided automatic surface-to-surface contact with friction (FS, FD, DC) takes those nodes
/// over. docs/contact.md, "Automatic tiebreak".
///
/// Built from two existing parts, not a copy of either:
/// - the tie and its failure law are Type 9's (TiebreakContact with FailureUnit::segment and
///   TiebreakParameters::release_to_owner): the same springs (SLSFAC x SFS, stiffness per unit
///   area, tributary areas), the same per-segment criterion, a partly failed node's failed share
///   in Type 9's contact until the node is released;
/// - the contact is the card *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE's (AutomaticSurfaceContact: the
///   automatic pass over both sides, cross pairs only), with one more filter: a pair the tie still
///   holds is not admitted (ContactPairs::set_held): a slave node not yet released, and a slave
///   segment not yet failed (which keeps the master side's nodes off a tied segment). Each node
///   keeps its penetration at t = 0 as its spring's zero (IGNORE = 1), as the tie keeps its
///   stand-off, so that nothing jumps at release.
/// Held flags are refreshed at the start of each force evaluation from the tie's state, so a
/// failure found in one cycle hands the node over in the next (Type 9's rule): no cycle has both
/// the tie and the contact on the same node.
#include <algorithm>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "slideline/contact/contact_algorithm.hpp"
#include "slideline/contact/tiebreak_contact.hpp"

namespace slideline {

class AutomaticTiebreakContact final : public ContactAlgorithm, public ContactForces {
 public:
  /// tie: Type 9's tie (release_to_owner set); contact: the automatic surface-to-surface interface
  /// whose pass was given views of `held_nodes` (one per internal node) and `held_segments` (one
  /// per segment of the pass's surface) by set_held(); contact_segment: per slave segment of the
  /// tie, its index in the pass's surface. The held arrays are moved in (a moved vector keeps its
  /// buffer, so the pass's views stay valid) and never reallocated.
  AutomaticTiebreakContact(std::unique_ptr<TiebreakContact> tie, std::unique_ptr<ContactAlgorithm> contact,
                           std::vector<Index> contact_segment, std::vector<std::uint8_t> held_nodes,
                           std::vector<std::uint8_t> held_segments)
      : tie_(std::move(tie)), contact_(std::move(contact)), contact_segment_(std::move(contact_segment)),
        held_node_(std::move(held_nodes)), held_segment_(std::move(held_segments)) {}

  const std::string& name() const override { return tie_->name(); }
  void initialize(const ContactContext& c) override;
  ContactPhases phases() override { return {.forces = this}; }
  void apply_forces(const NodalFields& nodes, const StepTimes& times, ContactForceView out) override;
  Real stable_dt() const override { return std::min(tie_->stable_dt(), contact_->stable_dt()); }
  Vec3 slave_force() const override { return tie_->slave_force() + contact_->slave_force(); }
  Vec3 master_force() const override { return tie_->master_force() + contact_->master_force(); }
  Real friction_work() const override { return tie_->friction_work() + contact_->friction_work(); }
  /// Type 9's `first_failure_stress` channel (docs/output.md).
  void append_output_names(std::vector<std::string>& names) const override { tie_->append_output_names(names); }
  void write_output_values(std::span<Real> out) const override { tie_->write_output_values(out); }

  const TiebreakContact& tie() const { return *tie_; }
  const ContactAlgorithm& contact() const { return *contact_; }
  /// Slave nodes the tie still holds (1 per internal node).
  std::span<const std::uint8_t> held_nodes() const { return held_node_; }

 private:
  /// The held flags from the tie's state: tied nodes not released, tied slave segments not failed.
  void refresh_held();

  std::unique_ptr<TiebreakContact> tie_;
  std::unique_ptr<ContactAlgorithm> contact_;
  std::vector<Index> contact_segment_;
  std::vector<std::uint8_t> held_node_;     ///< per internal node: 1 while the tie holds it
  std::vector<std::uint8_t> held_segment_;  ///< per segment of the pass: 1 while the tie holds it
};

}  // namespace slideline
