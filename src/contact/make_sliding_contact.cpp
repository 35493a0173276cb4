// Types 3 (surface to surface) and 10 (one way): penalty interfaces (issue 8).
#include <memory>

#include "slideline/contact/make_contact_interface.hpp"
#include "slideline/contact/one_way_contact.hpp"
#include "slideline/contact/penalty_factory.hpp"
#include "slideline/contact/surface_to_surface_contact.hpp"

namespace slideline {

std::unique_ptr<ContactAlgorithm> make_sliding_contact(InterfaceSpec& spec) {
  const ContactSide& slave = spec.slave;
  const ContactSide& master = spec.master;
  // Slave nodes on master segments (stiffness factor SLSFAC x SFS).
  auto slave_pass = make_penalty_pass(slave, slave_node_offsets(slave, spec.slave_shells, 0.0), master.surface,
                                      penalty_pass_options(spec, spec.slave_stiffness, spec.master_shells));
  slave_pass->set_slave_orientation(SlaveOrientation(slave.surface, slave.nodes));
  if (spec.type != model::ContactType::surface_to_surface)
    return make_penalty_interface<OneWayContact>(spec, std::move(slave_pass));
  // Type 3's second pass: master nodes on slave segments (SLSFAC x SFM).
  auto master_pass = make_penalty_pass(master, slave_node_offsets(master, spec.master_shells, 0.0), slave.surface,
                                       penalty_pass_options(spec, spec.master_stiffness, spec.slave_shells));
  master_pass->set_slave_orientation(SlaveOrientation(master.surface, master.nodes));
  return make_penalty_interface<SurfaceToSurfaceContact>(spec, std::move(slave_pass), std::move(master_pass));
}

}  // namespace slideline
