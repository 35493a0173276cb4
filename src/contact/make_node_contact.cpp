// Types 5 (nodes to surface) and 12 (automatic single surface): penalty interfaces (issue 9).
#include <memory>

#include "slideline/contact/automatic_contact.hpp"
#include "slideline/contact/make_contact_interface.hpp"
#include "slideline/contact/nodes_to_surface_contact.hpp"
#include "slideline/contact/penalty_factory.hpp"

namespace slideline {

namespace {

std::unique_ptr<ContactAlgorithm> make_nodes_to_surface(InterfaceSpec& spec, const ContactBuildContext& ctx) {
  const ContactSide& slave = spec.slave;
  // Slave offset: the nodal radius, at least the slave's own shell offset (a node set has no
  // shells of its own); master offset: half the master shell thickness (SHLTHK, MST, SFMT).
  auto pass = make_penalty_pass(slave, slave_node_offsets(slave, spec.slave_shells, spec.nodal_radius),
                                spec.master.surface, penalty_pass_options(spec, spec.slave_stiffness, spec.master_shells));
  // Orientation (search/slave_orientation.hpp): a node set by the faces of the parts it lies on.
  const Surface faces =
      spec.node_set_slaves ? node_set_faces(slave.nodes, ctx, spec.where + ": SSID") : slave.surface;
  pass->set_slave_orientation(SlaveOrientation(faces, slave.nodes));
  return make_penalty_interface<NodesToSurfaceContact>(spec, std::move(pass));
}

std::unique_ptr<ContactAlgorithm> make_automatic(InterfaceSpec& spec, const ContactBuildContext& ctx) {
  const ContactSide& side = spec.slave;
  // Single surface: spec.master_shells is spec.slave_shells (SST, SFST on both roles).
  auto pass = make_penalty_pass(side, slave_node_offsets(side, spec.slave_shells, 0.0), side.surface,
                                penalty_pass_options(spec, spec.slave_stiffness, spec.master_shells));
  pass->slave_part() = node_parts(side);
  pass->set_slave_orientation(SlaveOrientation(side.surface, side.nodes));
  if (spec.follow_thickness) {  // THKCHG = 1: the offsets follow the shells' current thickness
    FollowedOffsets segments;
    for (Index s = 0; s < side.surface.segment_count(); ++s) {
      Real floor = 0.0;
      segments.add_segment(side.surface, s, spec.master_shells, floor);
      segments.close(floor);
    }
    pass->set_followed_offsets(followed_node_offsets(side.nodes, side.surface, spec.slave_shells, 0.0),
                               std::move(segments));
  }
  // Eroding parts (docs/contact_erosion.md): the surface is its own slaves' surface.
  if (spec.eroding) {
    ContactErosion erosion(side.surface, nullptr, side.nodes);
    set_retained_slave_nodes(erosion, side.nodes, ctx, spec.enmass);
    pass->set_erosion(std::move(erosion));
  }
  std::vector<Id> parts = side.parts;
  return make_penalty_interface<AutomaticContact>(spec, std::move(pass), std::move(parts));
}

}  // namespace

std::unique_ptr<ContactAlgorithm> make_node_and_automatic_contact(InterfaceSpec& spec, const ContactBuildContext& ctx) {
  if (spec.type != model::ContactType::automatic) return make_nodes_to_surface(spec, ctx);
  if (spec.segment_based && spec.form == model::ContactForm::dyna3d) return make_segment_contact(spec);
  return spec.form == model::ContactForm::dyna3d ? make_automatic(spec, ctx) : make_automatic_surface_contact(spec, ctx);
}

}  // namespace slideline
