#pragma once
/// The step towards the next output time.
///
/// Landing on an output time by shortening only the last step before it (steps 1, 1, ..., 1, f
/// of the stable step, repeated every output) makes the central-difference update parametrically
/// unstable: the per-step transfer matrices are each stable, but their periodic product is not.
/// For x'' = -w^2 x with w dt = 1.67 (the transverse-shear mode of a nu = 0 Belytschko-Tsay shell
/// at the 0.9 scale factor) a pattern of 28 full steps and one of 0.58 amplifies by 1.49 per
/// output period; even at w dt = 1.2 the worst pattern gives 1.11. Undamped high modes then grow
/// from round-off over 10^3-10^4 cycles (tests/unit/solver/test_step_control.cpp). Dividing the
/// remaining time into equal steps keeps the step constant between outputs, so it changes only
/// as slowly as the stable step itself.
#include <cmath>

#include "slideline/core/types.hpp"

namespace slideline {

struct StepChoice {
  Real dt = 0.0;       ///< the step to take (time)
  bool lands = false;  ///< true when t + dt is the target itself (set the time to it, not t + dt)
};

/// The step from time `t` towards `target` (the next output or end time; +inf when there is
/// none): the remaining time divided into the fewest equal steps no longer than `dt_stable` (the
/// scaled stable step; to a relative 1e-9, so that round-off does not switch the count between
/// two steps), or `dt_stable` itself without a target. `tol` is the time tolerance within which
/// t already is on the target.
inline StepChoice step_towards(Real t, Real target, Real dt_stable, Real tol) {
  if (!std::isfinite(target) || !(target > t + tol)) return {dt_stable, false};
  const Real remaining = target - t;
  if (t + dt_stable >= target - tol) return {remaining, true};
  const Real steps = std::ceil(remaining / dt_stable * (1.0 - 1e-9));
  if (steps <= 1.0) return {remaining, true};
  return {remaining / steps, false};
}

/// The first output time strictly after `after` (0 when `after` < 0, i.e. nothing was written
/// yet): output times are exact multiples of `interval` (> 0), and a time that already sits on a
/// multiple, to round-off, counts as that multiple.
inline Real next_output_time(Real interval, Real after) {
  if (after < 0.0) return 0.0;
  const Real k = std::floor(after / interval + 1e-9) + 1.0;
  return k * interval;
}

}  // namespace slideline
