// ErosionCriteria (element/erosion_criteria.hpp): the thresholds of *MAT_ADD_EROSION on one stress
// state, NCS, NUMFIP, and the invariants under rotation (a rotated copy of each state).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>

#include "slideline/element/erosion_criteria.hpp"

using namespace slideline;

namespace {

using Sym = std::array<Real, 6>;

/// R diag(a, b, c) R^T for the rotation R about the axis (1, 2, 3)/|.| by `angle`, as xx, yy, zz,
/// xy, yz, xz.
Sym rotated(Real a, Real b, Real c, Real angle) {
  const Real n = std::sqrt(14.0), ux = 1.0 / n, uy = 2.0 / n, uz = 3.0 / n;
  const Real co = std::cos(angle), si = std::sin(angle), t = 1.0 - co;
  const Real r[3][3] = {{co + ux * ux * t, ux * uy * t - uz * si, ux * uz * t + uy * si},
                        {uy * ux * t + uz * si, co + uy * uy * t, uy * uz * t - ux * si},
                        {uz * ux * t - uy * si, uz * uy * t + ux * si, co + uz * uz * t}};
  const Real d[3] = {a, b, c};
  auto s = [&](int i, int j) {
    Real v = 0.0;
    for (int k = 0; k < 3; ++k) v += r[i][k] * d[k] * r[j][k];
    return v;
  };
  return {s(0, 0), s(1, 1), s(2, 2), s(0, 1), s(1, 2), s(0, 2)};
}

}  // namespace

// The principal values, von Mises stress and pressure of diag(a, b, c) turned by R: the sorted
// (a, b, c), sqrt(((a-b)^2 + (b-c)^2 + (c-a)^2) / 2) and -(a+b+c)/3, to 1e-12 of the scale, for
// distinct, double and triple principal values. (The closed-form trigonometric root used before
// lost half its digits at a double largest value, cos 3 theta = -1: 4.0e-8 of the scale for
// (-2, 5, 5) turned by 1.2 rad at -O1; the symmetric QR solver has no such limit.)
TEST(ErosionCriteria, InvariantsOfARotatedStress) {
  for (const auto& [a, b, c] : {std::array<Real, 3>{3.0, -1.0, 0.5}, std::array<Real, 3>{-2.0, 5.0, 5.0},
                                std::array<Real, 3>{-4.0, -4.0, -4.0}, std::array<Real, 3>{0.0, -7.0, 1e-3},
                                std::array<Real, 3>{1.0, 1.0 + 1e-9, -3.0}}) {
    for (Real angle : {0.0, 0.3, 1.2, 2.9}) {
      const Sym s = rotated(a, b, c, angle);
      const Real scale = std::abs(a) + std::abs(b) + std::abs(c);
      std::array<Real, 3> sorted{a, b, c};
      std::sort(sorted.begin(), sorted.end(), std::greater<>());
      EXPECT_NEAR(ErosionCriteria::max_principal(s), sorted[0], 1e-12 * scale) << a << " " << b << " " << c << " " << angle;
      const std::array<Real, 3> p = ErosionCriteria::principal_values(s);
      for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(p[i], sorted[i], 1e-12 * scale) << a << " " << b << " " << c << " " << angle << " " << i;
      const Real vm = std::sqrt(0.5 * ((a - b) * (a - b) + (b - c) * (b - c) + (c - a) * (c - a)));
      EXPECT_NEAR(ErosionCriteria::von_mises(s), vm, 1e-12 * scale);
    }
  }
}

// Each threshold on its own (pressure positive in compression), NCS counting those that hold at
// once, FAILTM on the time, and no threshold: never.
TEST(ErosionCriteria, ThresholdsAndNcs) {
  ErosionCriteria k;
  const Sym tension = rotated(30.0, 0.0, 0.0, 0.7);  // p = -10, sigma_1 = 30, vm = 30
  EXPECT_FALSE(k.point_fails(tension, 1.0));
  k.mnpres = {true, -9.5};
  EXPECT_TRUE(k.point_fails(tension, 0.0));
  k.mnpres = {true, -10.5};
  EXPECT_FALSE(k.point_fails(tension, 0.0));
  k.mnpres = {};
  k.mxpres = {true, 9.0};
  EXPECT_FALSE(k.point_fails(tension, 0.0));
  EXPECT_TRUE(k.point_fails(rotated(-30.0, 0.0, 0.0, 0.7), 0.0));  // p = 10 >= 9
  k.mxpres = {};
  k.sigp1 = {true, 29.0};
  EXPECT_TRUE(k.point_fails(tension, 0.0));
  EXPECT_FALSE(k.point_fails(rotated(-30.0, 0.0, 0.0, 0.7), 0.0));  // sigma_1 = 0
  k.sigp1 = {};
  k.sigvm = {true, 31.0};
  EXPECT_FALSE(k.point_fails(tension, 0.0));
  k.sigvm = {true, 30.0 - 1e-9};
  EXPECT_TRUE(k.point_fails(tension, 0.0));
  k.failtm = {true, 2.0};
  EXPECT_EQ(k.thresholds_met(tension, 1.0), 1);
  EXPECT_EQ(k.thresholds_met(tension, 2.0), 2);
  k.ncs = 2;
  EXPECT_FALSE(k.point_fails(tension, 1.0));
  EXPECT_TRUE(k.point_fails(tension, 2.0));
  EXPECT_FALSE(k.point_fails(Sym{}, 5.0));  // only FAILTM holds
}

// A threshold holds once passed, strictly: every stress and strain threshold set to 0 (what EXCL
// != 0 keeps) holds nowhere at rest (zero stress, zero strain), and each holds at the first stress
// or strain of its sign. (MNPRES = 0 is the manual's "keep the material out of tension".)
TEST(ErosionCriteria, ZeroThresholdsHoldOnlyOncePassed) {
  ErosionCriteria k;
  const std::array<Real, 3> rest{0.0, 0.0, 0.0};
  for (ErosionCriteria::Threshold ErosionCriteria::*f :
       {&ErosionCriteria::mxpres, &ErosionCriteria::mnpres, &ErosionCriteria::sigp1, &ErosionCriteria::sigvm,
        &ErosionCriteria::mneps, &ErosionCriteria::effeps, &ErosionCriteria::mxeps, &ErosionCriteria::epssh}) {
    k = ErosionCriteria{};
    k.*f = {true, 0.0};
    EXPECT_EQ(k.thresholds_met(Sym{}, 0.0, rest), 0);
  }
  k = ErosionCriteria{};
  k.mnpres = {true, 0.0};
  EXPECT_TRUE(k.point_fails(rotated(1e-6, 0.0, 0.0, 0.3), 0.0));  // p = -3.3e-7 < 0
  EXPECT_FALSE(k.point_fails(rotated(-1e-6, 0.0, 0.0, 0.3), 0.0));
  k = ErosionCriteria{};
  k.mxeps = {true, 0.0};
  EXPECT_TRUE(k.point_fails(Sym{}, 0.0, {1e-9, 0.0, 0.0}));
  EXPECT_FALSE(k.point_fails(Sym{}, 0.0, {0.0, 0.0, -1e-9}));
  k = ErosionCriteria{};
  k.mneps = {true, 0.0};
  EXPECT_TRUE(k.point_fails(Sym{}, 0.0, {0.0, 0.0, -1e-9}));
}

// NUMFIP: a count (blank/0 read as 1), a percentage of the points (rounded up), or |NUMFIP| - 100.
TEST(ErosionCriteria, NumfipPointsNeeded) {
  ErosionCriteria k;
  EXPECT_EQ(k.points_needed(5), 1);
  k.numfip = 3;
  EXPECT_EQ(k.points_needed(5), 3);
  k.numfip = -40;
  EXPECT_EQ(k.points_needed(5), 2);
  k.numfip = -50;
  EXPECT_EQ(k.points_needed(5), 3);  // 2.5 rounded up
  k.numfip = -100;
  EXPECT_EQ(k.points_needed(3), 3);
  k.numfip = -102;
  EXPECT_EQ(k.points_needed(5), 2);
}
