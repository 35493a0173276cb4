#pragma once
/// DYNA3D Type 3 (*CONTACT_SURFACE_TO_SURFACE), sliding with voids and friction, penalty
/// enforcement: two passes, the slave nodes on the master segments and the master nodes on the
/// slave segments (symmetric treatment), each at the full penalty stiffness of the segment it
/// meets (its springs are distinct node/segment pairs: nothing acts twice). docs/contact.md,
/// "Penalty contact".
#include <cstddef>

#include "slideline/contact/penalty_interface.hpp"

namespace slideline {

/// Kind of PenaltyInterface for Type 3: slave pass, then the reverse (master nodes) pass.
struct SurfaceToSurfaceKind {
  static constexpr std::size_t pass_count = 2;
};

/// Friction: Frictionless or ExponentialCoulomb (compile-time policy).
template <class Friction>
using SurfaceToSurfaceContact = PenaltyInterface<SurfaceToSurfaceKind, Friction>;

}  // namespace slideline
