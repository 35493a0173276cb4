// Types 3 (surface to surface) and 10 (one way): penalty interfaces (issue 8).
#include <memory>

#include "slideline/contact/make_contact_interface.hpp"
#include "slideline/contact/one_way_contact.hpp"
#include "slideline/contact/surface_to_surface_contact.hpp"
#include "slideline/contact/penalty_factory.hpp"

namespace slideline {

std::unique_ptr<ContactAlgorithm> make_sliding_contact(const model::Contact& card, const std::string& title,
                                                       const ContactBuildContext& ctx) {
  if (card.enforcement != model::Enforcement::penalty) throw_contact_not_implemented(card);
  if (card.sstyp == 4) throw_contact_not_implemented(card, "a node-set slave side (SSTYP 4) needs Type 5");
  ContactSide slave = resolve_contact_side(card, true, ctx);
  ContactSide master = resolve_contact_side(card, false, ctx);
  const bool thk = ctx.model.control_contact.shlthk > 0;
  // Slave nodes on master segments (stiffness factor SLSFAC x SFS).
  auto slave_pass = make_penalty_pass(slave, shell_half_thickness(slave, thk, card.sst, card.sfst), master.surface,
                                      penalty_pass_options(card, ctx, card.sfs, card.mst, card.sfmt));
  slave_pass->set_slave_orientation(SlaveOrientation(slave.surface, slave.nodes));
  if (card.type != model::ContactType::surface_to_surface)
    return make_penalty_interface<OneWayContact>(card, title, std::move(slave_pass));
  // Type 3's second pass: master nodes on slave segments (SLSFAC x SFM).
  auto master_pass = make_penalty_pass(master, shell_half_thickness(master, thk, card.mst, card.sfmt), slave.surface,
                                       penalty_pass_options(card, ctx, card.sfm, card.sst, card.sfst));
  master_pass->set_slave_orientation(SlaveOrientation(master.surface, master.nodes));
  return make_penalty_interface<SurfaceToSurfaceContact>(card, title, std::move(slave_pass), std::move(master_pass));
}

}  // namespace slideline
