// J2 plasticity at a shell point in plane stress (material/shell_plasticity.hpp), driven by strain
// rates, against closed forms: uniaxial stress (the lateral rate solved so that sigma_yy = 0),
// equibiaxial stress, pure shear (as tau_xy and, rotated by 45 degrees, as sigma_xx = -sigma_yy),
// tension-compression cycles with isotropic, kinematic and mixed hardening, a piecewise linear
// yield curve (material 24), Cowper-Symonds scaling and the plastic work.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "slideline/material/j2_plasticity.hpp"
#include "slideline/material/piecewise_plasticity.hpp"
#include "slideline/material/shell_plasticity.hpp"
#include "test_support/bilinear_curve.hpp"

using namespace slideline;

namespace {

constexpr Real kE = 1000.0, kNu = 0.3, kSy = 1.0, kEt = 10.0, kDt = 1e-3;

ShellPlasticity<J2Plasticity> bilinear_law(Real beta, Real tangent = kEt, Real c = 0.0, Real p = 0.0) {
  return ShellPlasticity<J2Plasticity>(J2Plasticity({1e-5, kE, kNu, kSy, tangent, beta, c, p}));
}

/// One step of uniaxial stress along x at the rate dxx: d_yy is solved (secant) so that sigma_yy
/// ends at zero. Returns sigma_xx.
template <class Law>
Real uniaxial_step(const Law& law, typename Law::State& s, Real dxx) {
  auto syy = [&](Real dyy) {
    typename Law::State trial = s;
    return law.update(trial, ShellRate{dxx, dyy, 0.0, 0.0, 0.0}, kDt, 5.0 / 6.0)[1];
  };
  Real a = -kNu * dxx, b = -0.5 * dxx, fa = syy(a), fb = syy(b);
  for (int it = 0; it < 50 && fb != 0.0 && fb != fa && std::abs(b - a) > 1e-15 * std::abs(dxx); ++it) {
    const Real c = b - fb * (b - a) / (fb - fa);
    a = b;
    fa = fb;
    b = c;
    fb = syy(b);
  }
  return law.update(s, ShellRate{dxx, b, 0.0, 0.0, 0.0}, kDt, 5.0 / 6.0)[0];
}

}  // namespace

TEST(ShellPlasticity, UniaxialStressFollowsTheBilinearCurve) {
  for (Real beta : {0.0, 0.5, 1.0}) {
    const auto law = bilinear_law(beta);
    const test_support::Bilinear curve{kE, kEt, kSy, beta};
    ShellPlasticity<J2Plasticity>::State s;
    Real eps = 0.0, worst = 0.0;
    for (int k = 0; k < 100; ++k) {  // to 5 times the yield strain in 100 steps
      const Real sxx = uniaxial_step(law, s, 5.0 * kSy / kE / (100 * kDt));
      eps += 5.0 * kSy / kE / 100;
      worst = std::max(worst, std::abs(sxx / curve.loading(eps) - 1.0));
    }
    EXPECT_LT(worst, 1e-10) << "beta " << beta;
    // The effective plastic strain of uniaxial stress, eps_p = eps - sigma / E, and the plastic work
    // W_p = integral of (sigma_y + Ep eps_p) d eps_p = sigma_y eps_p + Ep eps_p^2 / 2 (the update
    // books sigma_end d eps_p per step: first order in the step, 1e-3 here).
    const Real eps_p = eps - curve.loading(eps) / kE;
    EXPECT_NEAR(s.eps, eps_p, 1e-12);
    const Real wp = kSy * eps_p + 0.5 * curve.ep() * eps_p * eps_p;
    const Real sxx = s.sigma[0];
    EXPECT_NEAR(law.energy_density(s, 5.0 / 6.0), sxx * sxx / (2.0 * kE) + wp, 1e-3 * wp);
  }
}

TEST(ShellPlasticity, TensionCompressionCycleIsotropicKinematicAndMixed) {
  for (Real beta : {0.0, 0.5, 1.0}) {
    const auto law = bilinear_law(beta, 100.0);
    const test_support::Bilinear curve{kE, 100.0, kSy, beta};
    ShellPlasticity<J2Plasticity>::State s;
    const int n = 100;
    const Real e1 = 4.0 * kSy / kE, rate = e1 / (n * kDt);
    Real eps = 0.0;
    for (int k = 0; k < n; ++k) uniaxial_step(law, s, rate), eps += e1 / n;
    Real worst = 0.0;
    for (int k = 0; k < 2 * n; ++k) {  // back to -e1
      const Real sxx = uniaxial_step(law, s, -rate);
      eps -= e1 / n;
      worst = std::max(worst, std::abs(sxx - curve.reversed(e1, eps)) / kSy);
    }
    EXPECT_LT(worst, 1e-9) << "beta " << beta;
    // The reverse yield stress sets the end point: kinematic reaches a smaller |sigma| than isotropic.
    std::printf("beta %.1f: sigma at +e1 %.5f, at -e1 %.5f (closed form %.5f)\n", beta, curve.loading(e1),
                s.sigma[0], curve.reversed(e1, -e1));
  }
}

TEST(ShellPlasticity, EquibiaxialStressClosedForm) {
  // sigma_xx = sigma_yy = sigma, |sigma|_vm = sigma; the plastic strain splits as eps_p / 2 into
  // xx and yy, so eps = (1 - nu) sigma / E + (sigma - sigma_y) / (2 Ep) past yield.
  const auto law = bilinear_law(1.0);
  const Real ep = law.law().hardening_modulus();
  ShellPlasticity<J2Plasticity>::State s;
  Real eps = 0.0, worst = 0.0;
  for (int k = 0; k < 100; ++k) {
    law.update(s, ShellRate{0.05, 0.05, 0.0, 0.0, 0.0}, kDt, 5.0 / 6.0);
    eps += 0.05 * kDt;
    const Real el = kE / (1.0 - kNu) * eps;
    const Real ref = el <= kSy ? el : (eps + kSy / (2.0 * ep)) / ((1.0 - kNu) / kE + 1.0 / (2.0 * ep));
    worst = std::max({worst, std::abs(s.sigma[0] / ref - 1.0), std::abs(s.sigma[1] / ref - 1.0)});
  }
  EXPECT_LT(worst, 1e-10);
  EXPECT_GT(s.eps, 0.005);  // well past yield (equibiaxial yield strain 7e-4, total strain 0.005)
}

TEST(ShellPlasticity, PureShearClosedFormAndRotatedCopy) {
  // tau_xy = tau, |sigma|_vm = sqrt(3) tau, gamma_p = sqrt(3) eps_p: gamma = tau / G + sqrt(3)
  // (sqrt(3) tau - sigma_y) / Ep past yield. The same state rotated by 45 degrees is
  // sigma_xx = -sigma_yy = tau under d_xx = -d_yy = gamma' / 2.
  const auto law = bilinear_law(1.0);
  const Real ep = law.law().hardening_modulus(), g = kE / (2.0 * (1.0 + kNu));
  ShellPlasticity<J2Plasticity>::State a, b;
  Real gamma = 0.0, worst = 0.0, worst_rot = 0.0;
  const Real rate = 0.1;
  for (int k = 0; k < 100; ++k) {
    law.update(a, ShellRate{0.0, 0.0, rate, 0.0, 0.0}, kDt, 5.0 / 6.0);
    law.update(b, ShellRate{0.5 * rate, -0.5 * rate, 0.0, 0.0, 0.0}, kDt, 5.0 / 6.0);
    gamma += rate * kDt;
    const Real el = g * gamma;
    const Real ref = std::sqrt(3.0) * el <= kSy
                         ? el
                         : (gamma + std::sqrt(3.0) * kSy / ep) / (1.0 / g + 3.0 / ep);
    worst = std::max(worst, std::abs(a.sigma[2] / ref - 1.0));
    worst_rot = std::max({worst_rot, std::abs(b.sigma[0] / a.sigma[2] - 1.0), std::abs(b.sigma[1] / a.sigma[2] + 1.0)});
  }
  EXPECT_LT(worst, 1e-10);
  EXPECT_LT(worst_rot, 1e-12);
  EXPECT_NEAR(b.eps, a.eps, 1e-14);
  EXPECT_GT(a.eps, 0.25 * gamma);  // well past yield (gamma_y = 1.5e-3, gamma = 0.01)
}

TEST(ShellPlasticity, PiecewiseCurveMatchesItsPointsInUniaxialStress) {
  // Material 24 with a three-segment curve: in uniaxial stress sigma = curve(eps - sigma / E).
  PiecewisePlasticityConstants k{1e-5, kE, kNu, {{0.0, 1.0}, {0.002, 1.2}, {0.006, 1.3}, {0.02, 1.35}}, 0.0, 0.0, {}, false};
  const PiecewisePlasticity hex(k);
  const ShellPlasticity<PiecewisePlasticity> law(hex);
  ShellPlasticity<PiecewisePlasticity>::State s;
  Real worst = 0.0;
  for (int n = 0; n < 200; ++n) {
    const Real sxx = uniaxial_step(law, s, 0.015 / (200 * kDt));
    if (s.eps > 0.0) worst = std::max(worst, std::abs(sxx - hex.yield_stress(s.eps)));
  }
  EXPECT_GT(s.eps, 0.01);
  EXPECT_LT(worst, 1e-10);
  const Real eps_total = 0.015;
  EXPECT_NEAR(s.eps + s.sigma[0] / kE, eps_total, 1e-9);
}

TEST(ShellPlasticity, CowperSymondsScalesTheYieldStress) {
  // Equibiaxial at d_xx = d_yy = d: the effective rate with d_zz = -2 d is 2 d; the yield stress
  // and the hardening both scale by phi = 1 + (2 d / C)^(1/P) (J2Plasticity::yield_radius).
  const Real c = 40.0, p = 5.0, d = 0.05;
  const auto law = bilinear_law(1.0, kEt, c, p);
  const Real phi = 1.0 + std::pow(2.0 * d / c, 1.0 / p);
  const Real ep = phi * law.law().hardening_modulus();
  ShellPlasticity<J2Plasticity>::State s;
  Real eps = 0.0;
  for (int k = 0; k < 100; ++k) law.update(s, ShellRate{d, d, 0.0, 0.0, 0.0}, kDt, 5.0 / 6.0), eps += d * kDt;
  const Real ref = (eps + phi * kSy / (2.0 * ep)) / ((1.0 - kNu) / kE + 1.0 / (2.0 * ep));
  EXPECT_NEAR(s.sigma[0] / ref, 1.0, 1e-10);
  EXPECT_GT(phi, 1.2);
}

TEST(ShellPlasticity, TransverseShearStaysElastic) {
  const auto law = bilinear_law(1.0);
  ShellPlasticity<J2Plasticity>::State s;
  const Real g = kE / (2.0 * (1.0 + kNu));
  for (int k = 0; k < 10; ++k) law.update(s, ShellRate{0.0, 0.0, 0.0, 1.0, 0.5}, kDt, 5.0 / 6.0);
  EXPECT_NEAR(s.sigma[3], 5.0 / 6.0 * g * 0.01, 1e-12);  // past sigma_y / sqrt(3) and not returned
  EXPECT_NEAR(s.sigma[4], 5.0 / 6.0 * g * 0.005, 1e-12);
  EXPECT_EQ(s.eps, 0.0);
}
