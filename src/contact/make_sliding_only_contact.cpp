// Stub until its issue lands: sliding-only (type 1) lands with issue 10.
#include "slideline/contact/make_contact_interface.hpp"

namespace slideline {

std::unique_ptr<ContactAlgorithm> make_sliding_only_contact(const model::Contact& card, const std::string& /*title*/,
                                      const ContactBuildContext& /*ctx*/) {
  throw_contact_not_implemented(card);
}

}  // namespace slideline
