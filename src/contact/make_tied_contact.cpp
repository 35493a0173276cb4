// Kinematic tied interfaces (DYNA3D Types 2, 6, 7): issue 10.
#include "slideline/contact/make_contact_interface.hpp"
#include "slideline/contact/tied_contact.hpp"

namespace slideline {

std::unique_ptr<ContactAlgorithm> make_tied_contact(InterfaceSpec& spec) {
  if (spec.type == model::ContactType::tied_shell_edge)
    return std::make_unique<TiedShellEdgeContact>(spec.title, std::move(spec.slave.nodes), std::move(spec.master.surface));
  if (spec.type == model::ContactType::tied_nodes)
    return std::make_unique<TiedNodesContact>(spec.title, std::move(spec.slave.nodes), std::move(spec.master.surface));
  return std::make_unique<TiedSurfaceContact>(spec.title, std::move(spec.slave.nodes), std::move(spec.master.surface));
}

}  // namespace slideline
