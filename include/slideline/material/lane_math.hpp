#pragma once
/// The scalar functions an incremental law needs, written for T = Real (one element) and
/// T = Lanes (a batch, one element per lane), so that the law's formula is written once on T:
/// a zero, the larger of two values, square root, power, and a tensor's largest magnitude.
#include <algorithm>
#include <cmath>
#include <type_traits>

#include "slideline/core/lanes.hpp"
#include "slideline/core/tensor3.hpp"
#include "slideline/core/types.hpp"

namespace slideline::lane_math {

template <class T>
T zero() {
  if constexpr (std::is_same_v<T, Real>)
    return 0.0;
  else
    return T::Zero();
}

template <class T>
Tensor3<T> zero_tensor() {
  const T z = zero<T>();
  return {{{z, z, z}, {z, z, z}, {z, z, z}}};
}

inline Real larger(Real a, Real b) { return std::max(a, b); }
inline Lanes larger(const Lanes& a, const Lanes& b) { return a.max(b); }

inline Real root(Real a) { return std::sqrt(a); }
inline Lanes root(const Lanes& a) { return lane_sqrt(a); }

/// a^p for a >= 0.
inline Real power(Real a, Real p) { return std::pow(a, p); }
inline Lanes power(const Lanes& a, Real p) {
  return a.unaryExpr([p](Real v) { return std::pow(v, p); });
}

/// |a|^(1/3).
inline Real abs_cbrt(Real a) { return std::cbrt(std::abs(a)); }
inline Lanes abs_cbrt(const Lanes& a) {
  return a.unaryExpr([](Real v) { return std::cbrt(std::abs(v)); });
}

/// a ? b : c per lane.
inline Real choose(bool a, Real b, Real c) { return a ? b : c; }
inline Lanes choose(const LaneMask& a, const Lanes& b, const Lanes& c) { return a.select(b, c); }

}  // namespace slideline::lane_math
