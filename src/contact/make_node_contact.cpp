// Stub until its issue lands: node, tiebreak and automatic interfaces land with issue 9.
#include "slideline/contact/make_contact_interface.hpp"

namespace slideline {

std::unique_ptr<ContactAlgorithm> make_node_and_automatic_contact(const model::Contact& card, const std::string& /*title*/,
                                      const ContactBuildContext& /*ctx*/) {
  throw_contact_not_implemented(card);
}

}  // namespace slideline
