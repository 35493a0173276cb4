#pragma once
/// The penalty interfaces (DYNA3D Types 3, 5, 10, 12): PenaltyInterface<Kind, Friction>
/// (penalty_interface.hpp), one final class per type and friction law (Frictionless or
/// ExponentialCoulomb), its pass logic in a PenaltyPasses member (penalty_passes.hpp):
/// - SurfaceToSurfaceContact (Type 3, surface_to_surface_contact.hpp): two passes;
/// - OneWayContact (Type 10, one_way_contact.hpp): one pass, optionally "sliding only";
/// - NodesToSurfaceContact (Type 5, nodes_to_surface_contact.hpp): one pass of nodes with a radius;
/// - AutomaticContact (Type 12, automatic_contact.hpp): one single-surface pass, transmitted force;
/// - AutomaticSurfaceContact (*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE, automatic_surface_contact.hpp).
/// The factories (src/contact/make_sliding_contact.cpp, make_node_contact.cpp) map a card to one
/// of them. penalty_passes_of() finds the passes of any of them behind a ContactAlgorithm.
#include "slideline/contact/automatic_contact.hpp"
#include "slideline/contact/automatic_surface_contact.hpp"
#include "slideline/contact/nodes_to_surface_contact.hpp"
#include "slideline/contact/one_way_contact.hpp"
#include "slideline/contact/surface_to_surface_contact.hpp"

namespace slideline {

namespace detail {
template <template <class> class Interface>
const PenaltyPasses* passes_if(const ContactAlgorithm& c) {
  if (const auto* p = dynamic_cast<const Interface<Frictionless>*>(&c)) return &p->passes();
  if (const auto* p = dynamic_cast<const Interface<ExponentialCoulomb>*>(&c)) return &p->passes();
  return nullptr;
}
}  // namespace detail

/// The passes of a penalty interface (any type, any friction policy); null for another interface.
inline const PenaltyPasses* penalty_passes_of(const ContactAlgorithm& c) {
  if (const auto* p = detail::passes_if<SurfaceToSurfaceContact>(c)) return p;
  if (const auto* p = detail::passes_if<OneWayContact>(c)) return p;
  if (const auto* p = detail::passes_if<NodesToSurfaceContact>(c)) return p;
  if (const auto* p = detail::passes_if<AutomaticSurfaceContact>(c)) return p;
  return detail::passes_if<AutomaticContact>(c);
}

/// The transmitted forces of an automatic (Type 12) interface; null for another interface.
inline const std::vector<Vec3>* transmitted_forces_of(const ContactAlgorithm& c) {
  if (const auto* p = dynamic_cast<const AutomaticContact<Frictionless>*>(&c)) return &p->kind().transmitted_forces();
  if (const auto* p = dynamic_cast<const AutomaticContact<ExponentialCoulomb>*>(&c)) return &p->kind().transmitted_forces();
  return nullptr;
}

}  // namespace slideline
