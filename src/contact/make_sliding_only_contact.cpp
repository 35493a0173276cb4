// Type 1 (sliding only): a bilateral normal constraint, solved by the same forward-increment
// machinery as the Lagrange interfaces (contact/lagrange_contact.hpp) without friction. The slave
// nodes stay on the master surface in tension and compression and slide freely; the forces on
// the slave and master sides are equal and opposite to round-off (DYNA3D's Type 1 is not: report
// 6.1).
#include "slideline/contact/lagrange_contact.hpp"
#include "slideline/contact/make_contact_interface.hpp"

namespace slideline {

std::unique_ptr<ContactAlgorithm> make_sliding_only_contact(InterfaceSpec& spec, const ContactBuildContext& ctx) {
  LagrangeContactSettings s;
  s.title = spec.title;
  s.shell_offsets = false;  // the slave nodes lie on the master surface itself
  set_rigid_master_constraints(s, ctx.model);  // a rigid master moves in the solve as its body may
  return std::make_unique<SlidingOnlyContact>(std::move(s), std::move(spec.master.surface), std::move(spec.slave.nodes),
                                              std::move(spec.slave.surface));
}

}  // namespace slideline
