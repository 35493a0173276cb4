#pragma once
/// Helpers shared by the penalty factories (src/contact/make_sliding_contact.cpp for Types 3
/// and 10, src/contact/make_node_contact.cpp for Types 5 and 12): pass options and the friction
/// policy from a resolved card (InterfaceSpec).
#include <memory>
#include <utility>
#include <vector>

#include "slideline/contact/enforcement/penalty.hpp"
#include "slideline/contact/interface_spec.hpp"
#include "slideline/contact/search/fcl_broad_phase.hpp"

namespace slideline {

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

/// Pass options: stiffness factor `stiffness` (spec.slave_stiffness for the pass whose slaves are
/// the card's slave side, spec.master_stiffness for the reverse pass), the offsets of the pass's
/// master shells, the sliding-only, automatic and coupling options.
inline PenaltyPassOptions penalty_pass_options(const InterfaceSpec& spec, Real stiffness,
                                               const ShellOffsetRule& master_shells) {
  PenaltyPassOptions o;
  o.stiffness_scale = stiffness;
  o.master_shells = master_shells;
  o.sliding_only = spec.sliding_only;
  o.automatic = spec.type == model::ContactType::automatic;
  o.coupling = spec.mortar_coupling ? PenaltyCoupling::mortar : PenaltyCoupling::node;
  o.viscous_damping = spec.viscous_damping;
  o.keep_initial_penetrations = spec.keep_initial_penetrations;
  o.soft_scale = spec.soft_scale;
  o.viscous_friction = spec.viscous_friction;
  o.penetration_check = spec.penetration_check;
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

/// Interface<Friction>(args..., friction) with the spec's friction policy: ExponentialCoulomb when
/// FS or FD is positive, else Frictionless (no tangential code at all).
template <template <class> class Interface, class... Args>
std::unique_ptr<ContactAlgorithm> make_penalty_interface(const InterfaceSpec& spec, Args&&... args) {
  if (spec.frictional())
    return std::make_unique<Interface<ExponentialCoulomb>>(spec.title, std::forward<Args>(args)..., spec.friction);
  return std::make_unique<Interface<Frictionless>>(spec.title, std::forward<Args>(args)..., Frictionless{});
}

}  // namespace slideline
