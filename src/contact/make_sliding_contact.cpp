// Types 3 (surface to surface) and 10 (one way): penalty interfaces (issue 8).
#include <memory>
#include <string>
#include <utility>

#include "slideline/contact/make_contact_interface.hpp"
#include "slideline/contact/one_way_contact.hpp"
#include "slideline/contact/penalty_factory.hpp"
#include "slideline/contact/surface_to_surface_contact.hpp"
#include "slideline/core/error.hpp"

namespace slideline {

namespace {

/// SOFT = 2 on Type 3 (*CONTACT_SURFACE_TO_SURFACE): the automatic card's segment pass
/// (segment_contact.hpp) on solid faces, whose outward orientation leaves the two cards nothing to
/// differ on; a shell segment (one-sided on the non-automatic card, two-sided on the automatic
/// one) is refused by name.
std::unique_ptr<ContactAlgorithm> make_type3_segment_contact(InterfaceSpec& spec) {
  for (const auto& [side, name] : {std::pair{&spec.slave, "SSID"}, std::pair{&spec.master, "MSID"}})
    for (Index s = 0; s < side->surface.segment_count(); ++s)
      if (side->surface.kind[static_cast<std::size_t>(s)] == SegmentKind::shell)
        throw NotImplementedError(spec.where + ": SOFT = 2 (segment-based contact) on *CONTACT_SURFACE_TO_SURFACE " +
                                  "with shell segments (" + name + ", part " +
                                  std::to_string(side->surface.part[static_cast<std::size_t>(s)]) +
                                  ") is not implemented (solid faces only); *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE "
                                  "takes shells with SOFT = 2");
  return make_segment_contact(spec);
}

}  // namespace

std::unique_ptr<ContactAlgorithm> make_sliding_contact(InterfaceSpec& spec) {
  if (spec.segment_based) return make_type3_segment_contact(spec);  // the reader admits Type 3 only
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
