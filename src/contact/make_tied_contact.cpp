// Stub until its issue lands: tied interfaces (types 2, 6, 7) land with issue 10.
#include "slideline/contact/make_contact_interface.hpp"

namespace slideline {

std::unique_ptr<ContactAlgorithm> make_tied_contact(const model::Contact& card, const std::string& /*title*/,
                                      const ContactBuildContext& /*ctx*/) {
  throw_contact_not_implemented(card);
}

}  // namespace slideline
