#pragma once
/// DYNA3D Type 5 (*CONTACT_NODES_TO_SURFACE), nodes impacting a surface, penalty enforcement:
/// one pass of a node set (or a surface's nodes) on the master segments, each node offset by the
/// nodal radius. docs/contact.md, "Penalty contact".
#include <cstddef>

#include "slideline/contact/penalty_interface.hpp"

namespace slideline {

/// Kind of PenaltyInterface for Type 5: one pass of the slave nodes (offsets = nodal radius).
/// A type of its own, not OneWayKind, so that a Type 5 and a Type 10 interface stay apart.
struct NodesToSurfaceKind {
  static constexpr std::size_t pass_count = 1;
};

/// Friction: Frictionless or ExponentialCoulomb (compile-time policy).
template <class Friction>
using NodesToSurfaceContact = PenaltyInterface<NodesToSurfaceKind, Friction>;

}  // namespace slideline
