#pragma once
/// DYNA3D Type 10 (*CONTACT_ONE_WAY_SURFACE_TO_SURFACE), penalty enforcement: one pass of the
/// slave nodes on the master segments; with "sliding only" (_SLIDING_ONLY, set in the pass's
/// options) a node that has touched does not separate. docs/contact.md, "Penalty contact".
#include <cstddef>

#include "slideline/contact/penalty_interface.hpp"

namespace slideline {

/// Kind of PenaltyInterface for Type 10: one pass of the card's slave nodes.
struct OneWayKind {
  static constexpr std::size_t pass_count = 1;
};

/// Friction: Frictionless or ExponentialCoulomb (compile-time policy).
template <class Friction>
using OneWayContact = PenaltyInterface<OneWayKind, Friction>;

}  // namespace slideline
