// Stub until its issue lands: penalty sliding interfaces (types 3 and 10) land with issue 8.
#include "slideline/contact/make_contact_interface.hpp"

namespace slideline {

std::unique_ptr<ContactAlgorithm> make_sliding_contact(const model::Contact& card, const std::string& /*title*/,
                                      const ContactBuildContext& /*ctx*/) {
  throw_contact_not_implemented(card);
}

}  // namespace slideline
