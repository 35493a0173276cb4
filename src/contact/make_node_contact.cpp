// Types 5 (nodes to surface) and 12 (automatic single surface): penalty interfaces (issue 9).
// Types 8 and 9 (tiebreaks) are another family's and land here at merge time.
#include <memory>

#include "slideline/contact/make_contact_interface.hpp"
#include "slideline/contact/automatic_contact.hpp"
#include "slideline/contact/nodes_to_surface_contact.hpp"
#include "slideline/contact/penalty_factory.hpp"
#include "slideline/core/error.hpp"
#include "slideline/solver/build.hpp"

namespace slideline {

namespace {

std::unique_ptr<ContactAlgorithm> make_nodes_to_surface(const model::Contact& card, const std::string& title,
                                                        const ContactBuildContext& ctx) {
  ContactSide slave = resolve_contact_side(card, true, ctx);
  ContactSide master = resolve_contact_side(card, false, ctx);
  // Slave offset: the nodal radius (RADIUS; SST when no radius is given: a node set has no shell
  // of its own), master offset: half the master shell thickness (SHLTHK, MST, SFMT).
  const Real radius = card.radius > 0.0 ? card.radius : 0.5 * card.sst * card.sfst;
  std::vector<Real> offsets(slave.nodes.size(), radius);
  if (card.sstyp != 4) {
    const auto half = shell_half_thickness(slave, ctx.model.control_contact.shlthk > 0, card.sst, card.sfst);
    for (std::size_t i = 0; i < offsets.size(); ++i) offsets[i] = std::max(offsets[i], half[i]);
  }
  auto pass = make_penalty_pass(slave, std::move(offsets), master.surface,
                               penalty_pass_options(card, ctx, card.sfs, card.mst, card.sfmt));
  // Orientation (search/slave_orientation.hpp): a node set by the faces of the parts it lies on.
  const Surface faces = card.sstyp == 4 ? node_set_faces(slave.nodes, ctx, describe(card.src) + ": SSID of " + card.keyword)
                                        : slave.surface;
  pass->set_slave_orientation(SlaveOrientation(faces, slave.nodes));
  return make_penalty_interface<NodesToSurfaceContact>(card, title, std::move(pass));
}

std::unique_ptr<ContactAlgorithm> make_automatic(const model::Contact& card, const std::string& title,
                                                 const ContactBuildContext& ctx) {
  if (card.sstyp == 4)
    throw InputError(describe(card.src) + ": " + card.keyword + ": SSTYP = 4 (node set) is not a surface");
  ContactSide side = resolve_contact_side(card, true, ctx);
  auto pass = make_penalty_pass(side, shell_half_thickness(side, true, card.sst, card.sfst), side.surface,
                               penalty_pass_options(card, ctx, card.sfs, card.sst, card.sfst));
  pass->slave_part() = node_parts(side);
  pass->set_slave_orientation(SlaveOrientation(side.surface, side.nodes));
  std::vector<Id> parts = side.parts;
  return make_penalty_interface<AutomaticContact>(card, title, std::move(pass), std::move(parts));
}

}  // namespace

std::unique_ptr<ContactAlgorithm> make_node_and_automatic_contact(const model::Contact& card,
                                                                  const std::string& title,
                                                                  const ContactBuildContext& ctx) {
  if (card.enforcement != model::Enforcement::penalty) throw_contact_not_implemented(card);
  switch (card.type) {
    case model::ContactType::nodes_to_surface:
      return make_nodes_to_surface(card, title, ctx);
    case model::ContactType::automatic:
      return make_automatic(card, title, ctx);
    default:
      throw_contact_not_implemented(card);
  }
}

}  // namespace slideline
