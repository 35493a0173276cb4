#pragma once
/// Helpers shared by the penalty factories (src/contact/make_sliding_contact.cpp for Types 3
/// and 10, src/contact/make_node_contact.cpp for Types 5 and 12): offsets, pass options and the
/// friction policy from a *CONTACT card.
#include <memory>
#include <utility>
#include <vector>

#include "slideline/contact/enforcement/penalty.hpp"
#include "slideline/contact/make_contact_interface.hpp"
#include "slideline/contact/search/fcl_broad_phase.hpp"

namespace slideline {

/// Half the shell thickness each node of `side` carries as a slave (length), one per side.nodes
/// entry: thickness = (override > 0 ? override : the largest shell thickness among the node's
/// segments) x scale; 0 for a node on solid faces only, or when shell thickness is off.
inline std::vector<Real> shell_half_thickness(const ContactSide& side, bool shell_thickness, Real override_t,
                                              Real scale) {
  std::vector<Real> out(side.nodes.size(), 0.0);
  if (!shell_thickness) return out;
  const Surface& s = side.surface;
  for (Index row = 0; row < s.node_count(); ++row) {
    Real t = 0.0;
    for (Index j = s.node_segments.begin(row); j < s.node_segments.end(row); ++j) {
      const std::size_t seg = static_cast<std::size_t>(s.node_segments.value[static_cast<std::size_t>(j)]);
      if (s.kind[seg] == SegmentKind::shell) t = std::max(t, override_t > 0.0 ? override_t : s.thickness[seg]);
    }
    out[static_cast<std::size_t>(row)] = 0.5 * t * scale;
  }
  return out;
}

/// The part of each node of `side` (the part of its first segment), one per side.nodes entry.
inline std::vector<Id> node_parts(const ContactSide& side) {
  std::vector<Id> out(side.nodes.size(), 0);
  const Surface& s = side.surface;
  for (Index row = 0; row < s.node_count(); ++row) {
    if (s.node_segments.begin(row) < s.node_segments.end(row))
      out[static_cast<std::size_t>(row)] =
          s.part[static_cast<std::size_t>(s.node_segments.value[static_cast<std::size_t>(s.node_segments.begin(row))])];
  }
  return out;
}

/// Pass options from the card: stiffness factor SLSFAC x `side_factor` (SFS for the pass whose
/// slaves are the card's slave side, SFM for the reverse pass), friction FS/FD/DC, shell offsets
/// (SHLTHK, or always for Type 12), the master-side thickness override and scale.
inline PenaltyPassOptions penalty_pass_options(const model::Contact& card, const ContactBuildContext& ctx,
                                               Real side_factor, Real thickness_override, Real thickness_scale) {
  PenaltyPassOptions o;
  o.stiffness_scale = ctx.model.control_contact.slsfac * side_factor;
  o.shell_thickness = card.type == model::ContactType::automatic || ctx.model.control_contact.shlthk > 0;
  o.master_thickness = thickness_override;
  o.master_thickness_scale = thickness_scale;
  o.sliding_only = card.sliding_only_option;
  o.automatic = card.type == model::ContactType::automatic;
  o.coupling = card.penalty_coupling == 1 ? PenaltyCoupling::mortar : PenaltyCoupling::node;
  return o;
}

/// A pass whose slaves are the nodes of `side` (with their offsets) against `master`; with the
/// mortar coupling it gets the side's surface (a node-set side has none: it keeps
/// DYNA3D's rule).
inline std::unique_ptr<PenaltyPass> make_penalty_pass(const ContactSide& side, std::vector<Real> offsets,
                                                      const Surface& master, PenaltyPassOptions options) {
  if (side.surface.node_count() == 0) options.coupling = PenaltyCoupling::node;  // a node set
  auto pass = std::make_unique<PenaltyPass>(side.nodes, std::move(offsets), master, std::make_unique<FclBroadPhase>(),
                                            options);
  if (options.coupling != PenaltyCoupling::node) pass->set_slave_surface(side.surface);
  return pass;
}

/// The card's friction law: FS, FD (FS when FD is 0), DC.
inline ExponentialCoulomb penalty_friction(const model::Contact& card) {
  return ExponentialCoulomb{card.fs, card.fd > 0.0 ? card.fd : card.fs, card.dc};
}

/// Interface<Friction>(args..., friction) with the card's friction policy: ExponentialCoulomb when
/// FS or FD is positive, else Frictionless (no tangential code at all).
template <template <class> class Interface, class... Args>
std::unique_ptr<ContactAlgorithm> make_penalty_interface(const model::Contact& card, Args&&... args) {
  const ExponentialCoulomb law = penalty_friction(card);
  if (law.mu_s > 0.0 || law.mu_k > 0.0)
    return std::make_unique<Interface<ExponentialCoulomb>>(std::forward<Args>(args)..., law);
  return std::make_unique<Interface<Frictionless>>(std::forward<Args>(args)..., Frictionless{});
}

}  // namespace slideline
