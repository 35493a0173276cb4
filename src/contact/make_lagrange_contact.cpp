// Types 3, 5, 10 and 12 with Lagrange-multiplier enforcement (the _LAGRANGE keyword suffix):
// the card's sides and options become a LagrangeContact (contact/lagrange_contact.hpp).
#include <variant>

#include "slideline/contact/lagrange_contact.hpp"
#include "slideline/contact/make_contact_interface.hpp"
#include "slideline/core/error.hpp"
#include "slideline/solver/build.hpp"

namespace slideline {

namespace {

ExponentialCoulomb friction_of(const model::Contact& card) {
  if (card.fs < 0.0 || card.fd < 0.0 || card.dc < 0.0)
    throw InputError(describe(card.src) + ": " + card.keyword + ": FS, FD and DC must not be negative");
  ExponentialCoulomb f;
  f.mu_s = card.fs;
  f.mu_k = card.fd > 0.0 ? card.fd : card.fs;  // FD = 0: constant coefficient FS
  f.beta = card.dc;
  return f;
}

/// Translations held by the *MAT_RIGID constraints (CMO = +1, CON1 coded as in LS-DYNA: 1 x,
/// 2 y, 3 z, 4 xy, 5 yz, 6 zx, 7 xyz) of every rigid part; the builder has validated the codes.
std::vector<std::pair<Id, std::array<int, 3>>> rigid_fixed_translations(const model::Model& model) {
  static constexpr std::array<std::array<int, 3>, 8> codes{
      {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}, {1, 1, 1}}};
  std::vector<std::pair<Id, std::array<int, 3>>> out;
  for (const auto& part : model.parts)
    for (const auto& mat : model.materials)
      if (const auto* r = std::get_if<model::MatRigid>(&mat); r && r->mid == part.mid && r->cmo == 1.0 &&
                                                             r->con1 >= 0 && r->con1 <= 7)
        out.emplace_back(part.pid, codes[static_cast<std::size_t>(r->con1)]);
  return out;
}

}  // namespace

std::unique_ptr<ContactAlgorithm> make_lagrange_contact(const model::Contact& card, const std::string& title,
                                                        const ContactBuildContext& ctx) {
  using T = model::ContactType;
  if (card.type != T::surface_to_surface && card.type != T::one_way && card.type != T::nodes_to_surface &&
      card.type != T::automatic)
    throw_contact_not_implemented(card);
  if (card.sliding_only_option)
    throw_contact_not_implemented(card, "the sliding-only option with Lagrange enforcement is not implemented");
  if (card.vc != 0.0 || card.vdc != 0.0)
    throw_contact_not_implemented(card, "viscous friction (VC) and viscous damping (VDC) with Lagrange enforcement");
  const bool automatic = card.type == T::automatic;
  ContactSide slave = resolve_contact_side(card, true, ctx);
  // Type 12 (single surface): every node a slave, every segment a master, unless a master side
  // is given.
  ContactSide master = (automatic && card.msid == 0) ? slave : resolve_contact_side(card, false, ctx);
  if (master.surface.segment_count() == 0)
    throw InputError(describe(card.src) + ": MSID of " + card.keyword + " selects no master segments");

  LagrangeContactSettings s;
  s.title = title;
  s.friction = friction_of(card);
  s.shell_offsets = automatic || ctx.model.control_contact.shlthk >= 1;
  s.slave_thickness = card.sst;
  s.master_thickness = card.mst;
  s.slave_thickness_scale = card.sfst;
  s.master_thickness_scale = card.sfmt;
  // Node-set slaves (Type 5) stand off by the nodal radius, else half the SST thickness.
  if (slave.surface.nodes.empty()) s.nodal_radius = card.radius > 0.0 ? card.radius : 0.5 * card.sst;
  s.skip_incident = automatic;
  s.one_constraint_per_mutual_pair = automatic;  // no over-constrained pairs (lagrange_contact.hpp)
  s.rigid_fixed_translations = rigid_fixed_translations(ctx.model);
  s.transmitted_output = automatic;
  std::vector<Index> first;
  if (automatic && !slave.parts.empty())
    first = ctx.sets.nodes_of_part(slave.parts.front(), describe(card.src) + ": SSID of " + card.keyword);
  // Node-set slaves (Type 5) are oriented by the faces of the parts they lie on
  // (search/slave_orientation.hpp); a slave surface orients its own nodes.
  Surface faces;
  if (slave.surface.nodes.empty())
    faces = node_set_faces(slave.nodes, ctx, describe(card.src) + ": SSID of " + card.keyword);
  auto contact = std::make_unique<LagrangeContact>(std::move(s), std::move(master.surface), std::move(slave.nodes),
                                                   std::move(slave.surface), std::move(first));
  contact->set_orientation_surface(std::move(faces));
  return contact;
}

}  // namespace slideline
