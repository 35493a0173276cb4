#pragma once
/// Scalar, index and small fixed-size vector types used throughout slideline.
#include <Eigen/Dense>
#include <cstdint>

namespace slideline {

using Real = double;
/// Internal (dense, zero-based) index of a node, element or entity.
using Index = std::int32_t;
/// External identifier as written in a keyword deck (user ids, need not be dense).
using Id = std::int64_t;

using Vec3 = Eigen::Matrix<Real, 3, 1>;
using Mat3 = Eigen::Matrix<Real, 3, 3>;

/// Cartesian direction, used for loads, supports and output components.
enum class Axis : std::uint8_t { x = 0, y = 1, z = 2 };

inline constexpr const char* axis_name(Axis a) {
  switch (a) {
    case Axis::x: return "x";
    case Axis::y: return "y";
    case Axis::z: return "z";
  }
  return "?";
}

}  // namespace slideline
