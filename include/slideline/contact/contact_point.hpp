#pragma once
/// A slave node in contact with (or near) a master segment: what the narrow phase hands to an
/// enforcement (penalty springs, Lagrange multipliers, kinematic constraints).
#include <array>

#include "slideline/core/types.hpp"

namespace slideline {

struct ContactPoint {
  Index slave = -1;                  ///< slave node (internal index)
  Index segment = -1;                ///< master segment (index in the master Surface)
  std::array<Index, 4> master{};     ///< the segment's nodes (a triangle repeats the third)
  std::array<Real, 4> shape{};       ///< master shape functions at the contact point (sum 1)
  Real xi = 0.0, eta = 0.0;          ///< the contact point in the segment's parameters
  Vec3 normal = Vec3::Zero();        ///< unit normal at the point, pointing to the slave's side
  /// Signed normal gap (length): (x_slave - x_point) . normal less the offsets (shell half
  /// thicknesses, nodal radius); negative = penetration.
  Real gap = 0.0;
};

}  // namespace slideline
