// Type 1 (sliding only): a bilateral normal constraint, solved by the same forward-increment
// machinery as the Lagrange interfaces (contact/lagrange_contact.hpp) without friction. The slave
// nodes stay on the master surface in tension and compression and slide freely; the forces on
// the slave and master sides are equal and opposite to round-off (DYNA3D's Type 1 is not: report
// 6.1).
#include "slideline/contact/lagrange_contact.hpp"
#include "slideline/contact/make_contact_interface.hpp"
#include "slideline/core/error.hpp"
#include "slideline/solver/build.hpp"

namespace slideline {

std::unique_ptr<ContactAlgorithm> make_sliding_only_contact(const model::Contact& card, const std::string& title,
                                                            const ContactBuildContext& ctx) {
  if (card.fs != 0.0 || card.fd != 0.0)
    throw InputError(describe(card.src) + ": " + card.keyword +
                     ": a sliding-only (type 1) interface is frictionless; FS and FD must be 0");
  ContactSide slave = resolve_contact_side(card, true, ctx);
  ContactSide master = resolve_contact_side(card, false, ctx);
  if (master.surface.segment_count() == 0)
    throw InputError(describe(card.src) + ": MSID of " + card.keyword + " selects no master segments");
  LagrangeContactSettings s;
  s.title = title;
  s.shell_offsets = false;  // the slave nodes lie on the master surface itself
  return std::make_unique<SlidingOnlyContact>(std::move(s), std::move(master.surface), std::move(slave.nodes),
                                           std::move(slave.surface));
}

}  // namespace slideline
