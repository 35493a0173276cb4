#include "slideline/contact/make_contact_interface.hpp"

#include "slideline/contact/force_transducer.hpp"
#include "slideline/core/error.hpp"

namespace slideline {

std::unique_ptr<ContactAlgorithm> make_contact_interface(InterfaceSpec& spec, const ContactBuildContext& ctx) {
  using T = model::ContactType;
  const bool lagrange = spec.enforcement == model::Enforcement::lagrange;
  if (spec.form == model::ContactForm::force_transducer)
    return std::make_unique<ForceTransducer>(spec.title, spec.slave.nodes, spec.master.nodes);
  switch (spec.type) {
    case T::tied_surface:
    case T::tied_nodes:
    case T::tied_shell_edge:
      return make_tied_contact(spec);
    case T::sliding_only:
      return make_sliding_only_contact(spec, ctx);
    case T::surface_to_surface:
    case T::one_way:
      return lagrange ? make_lagrange_contact(spec, ctx) : make_sliding_contact(spec);
    case T::nodes_to_surface:
    case T::automatic:
      return lagrange ? make_lagrange_contact(spec, ctx) : make_node_and_automatic_contact(spec, ctx);
    case T::tiebreak_nodes:
    case T::tiebreak_surface:
      if (spec.form == model::ContactForm::automatic_surface_to_surface) return make_automatic_tiebreak_contact(spec, ctx);
      return make_tiebreak_contact(spec);
  }
  throw NotImplementedError(spec.where + ": unknown contact type");  // resolve_interface accepts none
}

}  // namespace slideline
