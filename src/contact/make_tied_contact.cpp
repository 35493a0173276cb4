// Kinematic tied interfaces (DYNA3D Types 2, 6, 7): issue 10.
#include "slideline/contact/make_contact_interface.hpp"
#include "slideline/contact/tied_contact.hpp"
#include "slideline/core/error.hpp"
#include "slideline/solver/build.hpp"

namespace slideline {

std::unique_ptr<ContactAlgorithm> make_tied_contact(const model::Contact& card, const std::string& title,
                                                    const ContactBuildContext& ctx) {
  if (card.enforcement == model::Enforcement::lagrange)
    throw_contact_not_implemented(card, "tied interfaces are kinematic; Lagrange enforcement is not run");
  ContactSide slave = resolve_contact_side(card, true, ctx);
  ContactSide master = resolve_contact_side(card, false, ctx);
  if (master.surface.segment_count() == 0)
    throw InputError(describe(card.src) + ": MSID of " + card.keyword + " selects no master segments");
  const bool shell_edge = card.type == model::ContactType::tied_shell_edge;
  if (shell_edge)
    for (Index s = 0; s < master.surface.segment_count(); ++s)
      if (master.surface.kind[s] != SegmentKind::shell)
        throw InputError(describe(card.src) + ": " + card.keyword +
                         " (DYNA3D type 7) needs a shell master surface; MSID selects solid faces");
  if (shell_edge) return std::make_unique<TiedShellEdgeContact>(title, std::move(slave.nodes), std::move(master.surface));
  if (card.type == model::ContactType::tied_nodes)
    return std::make_unique<TiedNodesContact>(title, std::move(slave.nodes), std::move(master.surface));
  return std::make_unique<TiedSurfaceContact>(title, std::move(slave.nodes), std::move(master.surface));
}

}  // namespace slideline
