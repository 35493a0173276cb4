// MixedModeCohesiveLaw (tiebreak OPTION 9) along proportional separation paths, against the
// closed forms of the bilinear law (mixed_mode_cohesive_law.hpp): the peak traction, the
// separation where the traction vanishes and the work to full separation per unit area:
//   mode I: peak T at T / EN, zero at 2 GIC / T, work GIC;  mode II: S, S / ET, 2 GIIC / S, GIIC;
//   45 degrees (opening = slip), EN = ET = K: onset delta_0 = d1 d2 sqrt(2 / (d1^2 + d2^2)),
//     power law XMU = 1: G = 2 / (1 / GIC + 1 / GIIC); XMU = 2: G = 2 / sqrt(1 / GIC^2 + 1 / GIIC^2)
//     (G_I = G_II = G / 2 on (G_I / GIC)^XMU + (G_II / GIIC)^XMU = 1);
//     B-K with exponent eta: G = GIC + (GIIC - GIC) (1 / 2)^eta.
// The work is the midpoint rule over 1e5 steps (error ~ 4e-5 of the total from the kink).
#include <gtest/gtest.h>

#include <cmath>

#include "slideline/contact/mixed_mode_cohesive_law.hpp"

namespace slideline {
namespace {

struct Path {
  Real peak = 0.0, at_peak = 0.0, zero_at = -1.0, work = 0.0;
};

/// Separation along (cos a, sin a) (opening, slip) from 0 to `end`.
Path walk(const MixedModeCohesiveLaw& law, Real a, Real end) {
  const int n = 100000;
  Path p;
  Real damage = 0.0, t_prev = 0.0;
  for (int i = 1; i <= n; ++i) {
    const Real dm = end * i / n;
    const Real dI = dm * std::cos(a), dII = dm * std::sin(a);
    damage = law.damage(dI, dII, damage);
    const Real tn = (1.0 - damage) * law.en * dI, ts = (1.0 - damage) * law.et * dII;
    const Real t = std::sqrt(tn * tn + ts * ts);
    // Work of the traction along the path: |t| is along the path when EN = ET or a is 0 or 90 deg.
    p.work += 0.5 * (t + t_prev) * (end / n);
    t_prev = t;
    if (t > p.peak) {
      p.peak = t;
      p.at_peak = dm;
    }
    if (p.zero_at < 0.0 && damage >= 1.0) p.zero_at = dm;
  }
  return p;
}

MixedModeCohesiveLaw law(Real xmu = 1.0, bool bk = false) {
  return MixedModeCohesiveLaw{1e3, 1e3, 2.0, 1.5, 1e-2, 1.2e-2, xmu, bk};
}

TEST(MixedModeCohesiveLaw, PureModesFollowTheBilinearCurve) {
  const MixedModeCohesiveLaw l = law();
  const Path one = walk(l, 0.0, 0.02);
  EXPECT_NEAR(one.peak, 2.0, 1e-3);
  EXPECT_NEAR(one.at_peak, 2e-3, 1e-6);
  EXPECT_NEAR(one.zero_at, 2.0 * 1e-2 / 2.0, 1e-6);
  EXPECT_NEAR(one.work / 1e-2, 1.0, 1e-4);
  const Path two = walk(l, std::acos(-1.0) / 2.0, 0.02);
  EXPECT_NEAR(two.peak, 1.5, 1e-3);
  EXPECT_NEAR(two.at_peak, 1.5e-3, 1e-6);
  EXPECT_NEAR(two.zero_at, 2.0 * 1.2e-2 / 1.5, 1e-6);
  EXPECT_NEAR(two.work / 1.2e-2, 1.0, 1e-4);
}

TEST(MixedModeCohesiveLaw, FortyFiveDegreesMeetsTheMixedModeCriteria) {
  const Real a = std::acos(-1.0) / 4.0;
  const Real d1 = 2e-3, d2 = 1.5e-3, onset = d1 * d2 * std::sqrt(2.0 / (d1 * d1 + d2 * d2));
  const Path power1 = walk(law(1.0), a, 0.03);
  EXPECT_NEAR(power1.at_peak / onset, 1.0, 1e-4);
  EXPECT_NEAR(power1.peak / (1e3 * onset), 1.0, 1e-4);
  EXPECT_NEAR(power1.work / (2.0 / (1.0 / 1e-2 + 1.0 / 1.2e-2)), 1.0, 1e-4);
  const Path power2 = walk(law(2.0), a, 0.03);
  EXPECT_NEAR(power2.work / (2.0 / std::sqrt(1.0 / 1e-4 + 1.0 / 1.44e-4)), 1.0, 1e-4);
  const Path bk = walk(law(1.5, true), a, 0.03);
  EXPECT_NEAR(bk.work / (1e-2 + (1.2e-2 - 1e-2) * std::pow(0.5, 1.5)), 1.0, 1e-4);
}

// Damage never heals: unloading to zero and reloading follows the damaged secant, and closing
// (no opening) is pure mode II.
TEST(MixedModeCohesiveLaw, DamageIsIrreversibleAndClosingIsModeTwo) {
  const MixedModeCohesiveLaw l = law();
  const Real d = l.damage(5e-3, 0.0, 0.0);  // half way down the softening branch
  EXPECT_NEAR(d, 1e-2 * (5e-3 - 2e-3) / (5e-3 * (1e-2 - 2e-3)), 1e-12);
  EXPECT_EQ(l.damage(1e-3, 0.0, d), d);
  EXPECT_EQ(l.damage(0.0, 0.0, d), d);
  Real d0 = 0.0, dF = 0.0;
  l.separations(0.0, 1e-3, d0, dF);
  EXPECT_DOUBLE_EQ(d0, 1.5e-3);
  EXPECT_DOUBLE_EQ(dF, 2.0 * 1.2e-2 / 1.5);
  EXPECT_EQ(l.damage(0.0, 1e-3, 0.0), 0.0);
  EXPECT_EQ(l.damage(0.0, 0.1, 0.0), 1.0);
}

// OPTION 6 (fixed_final = CCRIT, EN = ET = K, the tie's isotropic spring): onset by the stress
// criterion (sigma_n / NFLS)^2 + (sigma_s / SFLS)^2 = 1, then the traction falls linearly from its
// onset value sigma_0 to zero at CCRIT, whatever the mix. Closed forms along a proportional path at
// angle a (opening cos a, slip sin a), K = 1e3, NFLS = 2, SFLS = 1.5, CCRIT = 1e-2:
//   onset delta_0 = 1 / (K sqrt((cos a / NFLS)^2 + (sin a / SFLS)^2)), sigma_0 = K delta_0,
//   zero at CCRIT, work (the triangle 0 -> delta_0 -> CCRIT) = sigma_0 CCRIT / 2;
//   mode I: sigma_0 = 2 at 2e-3, work 1e-2; mode II: 1.5 at 1.5e-3, 7.5e-3;
//   45 deg: delta_0 = 1 / (K sqrt(0.5 / 4 + 0.5 / 2.25)) = 1.6971e-3, work 8.4853e-3.
// On the falling branch the traction is linear in the separation (the manual's damage, linear in
// the distance): checked at the midpoint between delta_0 and CCRIT, where it is sigma_0 / 2.
TEST(MixedModeCohesiveLaw, FixedFinalSeparationIsOptionSixLinearSoftening) {
  const Real K = 1e3, N = 2.0, S = 1.5, ccrit = 1e-2;
  MixedModeCohesiveLaw l{K, K, N, S, 0.0, 0.0, 1.0, false, ccrit};
  const Real pi = std::acos(-1.0);
  for (const Real a : {0.0, pi / 4.0, pi / 2.0, pi / 3.0}) {
    SCOPED_TRACE(a);
    const Real c = std::cos(a), s = std::sin(a);
    const Real d0 = 1.0 / (K * std::sqrt((c / N) * (c / N) + (s / S) * (s / S)));
    const Real sigma0 = K * d0;
    const Path p = walk(l, a, 0.012);
    EXPECT_NEAR(p.at_peak / d0, 1.0, 1e-4);
    EXPECT_NEAR(p.peak / sigma0, 1.0, 1e-4);
    EXPECT_NEAR(p.zero_at / ccrit, 1.0, 1e-4);
    EXPECT_NEAR(p.work / (0.5 * sigma0 * ccrit), 1.0, 1e-4);
    // Midway down the falling branch.
    const Real dm = 0.5 * (d0 + ccrit);
    const Real D = l.damage(dm * c, dm * s, 0.0);
    EXPECT_NEAR((1.0 - D) * K * dm / (0.5 * sigma0), 1.0, 1e-12);
  }
  // CCRIT at or below the onset separation: no falling branch, full damage at onset.
  MixedModeCohesiveLaw brittle{K, K, N, S, 0.0, 0.0, 1.0, false, 1e-3};
  EXPECT_EQ(brittle.damage(2.1e-3, 0.0, 0.0), 1.0);
  EXPECT_EQ(brittle.damage(1.9e-3, 0.0, 0.0), 0.0);
}

}  // namespace
}  // namespace slideline
