// Penalty ties with failure (DYNA3D Types 8 and 9): issue 9.
#include "slideline/contact/make_contact_interface.hpp"
#include "slideline/contact/tiebreak_contact.hpp"

namespace slideline {

std::unique_ptr<ContactAlgorithm> make_tiebreak_contact(InterfaceSpec& spec) {
  const bool by_segment = spec.type == model::ContactType::tiebreak_surface;
  TiebreakParameters p;
  p.unit = by_segment ? TiebreakParameters::FailureUnit::segment : TiebreakParameters::FailureUnit::node;
  p.penalty_factor = spec.slave_stiffness;
  p.normal_failure = spec.failure.normal;
  p.shear_failure = spec.failure.shear;
  p.normal_exponent = spec.failure.normal_exponent;
  p.shear_exponent = spec.failure.shear_exponent;
  p.friction = spec.friction;
  return std::make_unique<TiebreakContact>(spec.title, std::move(spec.slave.nodes),
                                           by_segment ? std::move(spec.slave.surface) : Surface{},
                                           std::move(spec.master.surface), p);
}

}  // namespace slideline
