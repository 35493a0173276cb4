// The step towards the next output time: equal steps, exact landing, and the stability of the
// central-difference update under the resulting step pattern.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "slideline/solver/step_control.hpp"

using namespace slideline;

namespace {

/// Shortens only the last step before the target (the rule Simulation::step used): the reference
/// that the equal-step rule is compared with.
StepChoice last_step_only(Real t, Real target, Real dt_stable, Real tol) {
  if (target > t + tol && t + dt_stable >= target - tol) return {target - t, true};
  return {dt_stable, false};
}

/// Largest |x| (after the first output period) of x'' = -w^2 x integrated with the simulation's
/// central difference (v^{n+1/2} = v^{n-1/2} + (dt^{n-1/2} + dt^{n+1/2}) / 2 a^n,
/// x^{n+1} = x^n + dt^{n+1/2} v^{n+1/2}), outputs every `interval`, stable step `dt_stable`.
/// Starts from x = 1 at rest.
template <class Rule>
Real max_amplitude(Rule rule, Real w, Real dt_stable, Real interval, long cycles) {
  Real t = 0.0, x = 1.0, v = 0.0, dt_prev = 0.0, xmax = 0.0;
  for (long n = 0; n < cycles; ++n) {
    const Real target = (std::floor(t / interval + 1e-9) + 1.0) * interval;
    const StepChoice s = rule(t, target, dt_stable, 1e-12 * interval);
    const Real dt_avg = n == 0 ? 0.5 * s.dt : 0.5 * (dt_prev + s.dt);
    v += dt_avg * (-w * w * x);
    x += s.dt * v;
    t = s.lands ? target : t + s.dt;
    dt_prev = s.dt;
    if (t > interval) xmax = std::max(xmax, std::abs(x));
  }
  return xmax;
}

}  // namespace

TEST(StepControl, EqualStepsLandExactlyOnTheTarget) {
  const Real dt = 0.3, target = 1.0;
  Real t = 0.0;
  int n = 0;
  StepChoice s;
  do {
    s = step_towards(t, target, dt, 1e-12);
    EXPECT_LE(s.dt, dt);
    EXPECT_NEAR(s.dt, 0.25, 1e-15);  // 1.0 in ceil(1.0 / 0.3) = 4 equal steps
    t = s.lands ? target : t + s.dt;
    ++n;
  } while (!s.lands);
  EXPECT_EQ(n, 4);
  EXPECT_EQ(t, target);
}

TEST(StepControl, NoTargetOrTargetReached) {
  const Real inf = std::numeric_limits<Real>::infinity();
  EXPECT_EQ(step_towards(0.5, inf, 0.1, 1e-12).dt, 0.1);
  EXPECT_FALSE(step_towards(0.5, inf, 0.1, 1e-12).lands);
  // Already on the target (within the tolerance): a full step.
  EXPECT_EQ(step_towards(1.0 - 1e-14, 1.0, 0.1, 1e-12).dt, 0.1);
  // Within one step: land.
  const StepChoice s = step_towards(0.95, 1.0, 0.1, 1e-12);
  EXPECT_TRUE(s.lands);
  EXPECT_NEAR(s.dt, 0.05, 1e-15);
}

// An exact multiple of the stable step stays one: round-off in t must not turn n steps into n+1
// (the step would then jump by 1/n from one cycle to the next).
TEST(StepControl, ExactMultipleKeepsTheFullStep) {
  const Real dt = 0.1;
  Real t = 0.0;
  for (int k = 0; k < 9; ++k) {
    const StepChoice s = step_towards(t, 1.0, dt, 1e-12);
    EXPECT_NEAR(s.dt, dt, 1e-15) << "step " << k;
    t += s.dt;
  }
  EXPECT_TRUE(step_towards(t, 1.0, dt, 1e-12).lands);
}

// The cause of the long-hold shell failures: with the last step alone shortened, a mode at
// w dt = 1.67 (the nu = 0 shell's transverse-shear mode at scale 0.9) grows without bound when
// outputs come every 28.58 steps; with equal steps the step is constant and the central
// difference reproduces x_n = cos(n W), cos W = 1 - (w dt)^2 / 2, from rest at x = 1: |x| <= 1.
TEST(StepControl, EqualStepsKeepTheCentralDifferenceStable) {
  const Real w = 1.0, dt = 1.67, interval = 28.58 * dt;
  const long cycles = 20000;
  const Real grown = max_amplitude(last_step_only, w, dt, interval, cycles);
  const Real held = max_amplitude(step_towards, w, dt, interval, cycles);
  std::printf("w dt 1.67, output every 28.58 steps: max |x| %.3e (last step shortened), %.12f "
              "(equal steps)\n", grown, held);
  EXPECT_GT(grown, 1e6);
  EXPECT_LE(held, 1.0 + 1e-9);
  // And over a sweep of intervals and frequencies up to the 0.9 scale factor's w dt = 1.8.
  for (Real wdt : {1.0, 1.4, 1.8})
    for (Real per = 1.3; per < 40.0; per += 1.7)
      EXPECT_LE(max_amplitude(step_towards, wdt, 1.0, per, 5000), 1.0 + 1e-9)
          << "w dt " << wdt << ", interval " << per;
}
