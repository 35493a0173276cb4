// NullSolid (*MAT_NULL on solids, material/null_solid.hpp) and its equations of state
// (material/equation_of_state.hpp) against closed forms of our own, the law driven directly:
//
// - Hydrostatic compression F = J^(1/3) I from J = 1 to 0.9 in N equal steps of J (D volumetric,
//   so the viscous stress is zero). The pressure must equal the EOS at mu = 1/J - 1 and the law's
//   own E to round-off (1e-10 relative), and E must follow E0 - int_1^J p dJ':
//   * linear polynomial, E-free (C4 = C5 = C6 = 0): p = C1 mu + C2 mu^2 + C3 mu^3 and
//     int (1/J - 1) dJ = ln J - J, int (1/J - 1)^2 dJ = -1/J - 2 ln J + J,
//     int (1/J - 1)^3 dJ = -1/(2 J^2) + 3/J + 3 ln J - J;
//   * the gamma-law gas (C4 = C5 = gamma - 1): p = (gamma - 1) E / J, whose adiabat dE = -p dJ
//     gives E = E0 J^(1 - gamma), p = (gamma - 1) E0 J^(-gamma), sound speed c^2 = gamma p J / rho0;
//   * Gruneisen: with GAMAO = A = 0, p = rho0 C^2 mu (1 + mu) / den^2 (E-free), E against Simpson's
//     rule; with GAMAO, A != 0, E against a fine RK4 integration of dE/dJ = -p(J, E);
//   * tabulated: C and T linear in ln J between the points, extrapolated beyond them.
// - Expansion to J = 1.1: C2 mu^2 and C6 mu^2 drop out (mu < 0); Gruneisen's expanded branch;
//   the pressure cutoff PC holds the pressure at PC.
// - Simple shear at the rate g: the shear stress MU g, in any rotated frame, and E gains MU g^2
//   per unit time.
#include <gtest/gtest.h>

#include <cmath>

#include "slideline/material/laws.hpp"
#include "slideline/material/null_solid.hpp"

using namespace slideline;

static_assert(SolidMaterial<NullSolid>);

namespace {

constexpr Real kRho = 2.0e-3;

Tensor3<Real> scaled_identity(Real a) { return {{{a, 0.0, 0.0}, {0.0, a, 0.0}, {0.0, 0.0, a}}}; }

/// Drives `law` from J = 1 to `j_end` in `steps` equal steps of J over unit time each; returns
/// the pressure -tr(sigma)/3 at the end and leaves the state in `s`.
Real drive(const NullSolid& law, NullSolid::State<Real>& s, Real j_end, int steps) {
  Tensor3<Real> sigma{};
  for (int n = 1; n <= steps; ++n) {
    const Real j = 1.0 + (j_end - 1.0) * n / steps;
    const Real rate = (j_end - 1.0) / steps / j / 3.0;  // D = (dJ/dt) / (3 J) I, dt = 1
    sigma = law.update(s, scaled_identity(std::cbrt(j)), scaled_identity(rate), 1.0);
  }
  EXPECT_EQ(sigma[0][1], 0.0);
  EXPECT_DOUBLE_EQ(sigma[0][0], sigma[2][2]);
  return -(sigma[0][0] + sigma[1][1] + sigma[2][2]) / 3.0;
}

Real energy(const NullSolid& law, const NullSolid::State<Real>& s) { return law.energy_density(s); }

constexpr Real kNoCutoff = -1e30;

TEST(NullSolid, LinearPolynomialWithoutEnergyTermMatchesTheClosedForm) {
  const Real c1 = 2.0e3, c2 = 5.0e3, c3 = -1.0e3, e0 = 0.7;
  const NullSolid law(kRho, kNoCutoff, 0.0, EquationOfState::linear_polynomial({0.0, c1, c2, c3, 0.0, 0.0, 0.0}, e0));
  NullSolid::State<Real> s;
  const Real p = drive(law, s, 0.9, 2000);
  const Real mu = 1.0 / 0.9 - 1.0;
  EXPECT_NEAR(p, c1 * mu + c2 * mu * mu + c3 * mu * mu * mu, 1e-10 * p);
  const auto F = [&](Real j) {
    return c1 * (std::log(j) - j) + c2 * (-1.0 / j - 2.0 * std::log(j) + j) +
           c3 * (-0.5 / (j * j) + 3.0 / j + 3.0 * std::log(j) - j);
  };
  const Real e_exact = e0 + F(1.0) - F(0.9);  // E0 - int_1^0.9 p dJ
  EXPECT_NEAR(energy(law, s), e_exact, 1e-6 * (e_exact - e0));
  // The sound speed: dp/drho = (C1 + 2 C2 mu + 3 C3 mu^2) / rho0 (no E term).
  EXPECT_NEAR(s.sound_speed, std::sqrt((c1 + 2.0 * c2 * mu + 3.0 * c3 * mu * mu) / kRho), 1e-12 * s.sound_speed);
  EXPECT_DOUBLE_EQ(law.bulk_modulus(), c1);
  EXPECT_DOUBLE_EQ(law.wave_speed(), std::sqrt(c1 / kRho));
}

TEST(NullSolid, GammaLawGasFollowsItsAdiabat) {
  const Real gamma = 1.4, e0 = 2.5;
  const NullSolid law(kRho, kNoCutoff, 0.0,
                      EquationOfState::linear_polynomial({0.0, 0.0, 0.0, 0.0, gamma - 1.0, gamma - 1.0, 0.0}, e0));
  EXPECT_DOUBLE_EQ(law.reference_pressure(), (gamma - 1.0) * e0);
  NullSolid::State<Real> s;
  const Real p = drive(law, s, 0.9, 1000);
  // The EOS at the law's own E, to round-off; E and p on the adiabat to the trapezoid's error.
  EXPECT_NEAR(p, (gamma - 1.0) * energy(law, s) / 0.9, 1e-12 * p);
  EXPECT_NEAR(energy(law, s), e0 * std::pow(0.9, 1.0 - gamma), 1e-7 * e0);
  EXPECT_NEAR(p, (gamma - 1.0) * e0 * std::pow(0.9, -gamma), 1e-7 * p);
  EXPECT_NEAR(s.sound_speed * s.sound_speed, gamma * p * 0.9 / kRho, 1e-10 * gamma * p / kRho);
  // Back to J = 1 (the same path reversed): the adiabat returns E0 (to the trapezoid's error).
  Tensor3<Real> sigma{};
  for (int n = 1; n <= 1000; ++n) sigma = law.update(s, scaled_identity(std::cbrt(0.9 + 0.1 * n / 1000)), {}, 1.0);
  EXPECT_NEAR(energy(law, s), e0, 1e-7 * e0);
  EXPECT_NEAR(-sigma[0][0], (gamma - 1.0) * e0, 1e-6 * e0);
}

TEST(NullSolid, LinearPolynomialDropsC2AndC6InTension) {
  const std::array<Real, 7> c{10.0, 2.0e3, 5.0e3, 1.0e3, 0.5, 0.2, 0.3};
  const Real e0 = 1.0;
  const NullSolid law(kRho, kNoCutoff, 0.0, EquationOfState::linear_polynomial(c, e0));
  NullSolid::State<Real> s;
  const Real p = drive(law, s, 1.1, 1000);
  const Real mu = 1.0 / 1.1 - 1.0, e = energy(law, s);
  EXPECT_NEAR(p, c[0] + c[1] * mu + c[3] * mu * mu * mu + (c[4] + c[5] * mu) * e, 1e-10 * std::abs(p));
  EXPECT_GT(e, e0);  // expanding against a tensile pressure stores energy
  NullSolid::State<Real> q;
  const Real pc = drive(law, q, 0.9, 1000);
  const Real mc = 1.0 / 0.9 - 1.0, ec = energy(law, q);
  EXPECT_NEAR(pc, c[0] + mc * (c[1] + mc * (c[2] + mc * c[3])) + (c[4] + mc * (c[5] + mc * c[6])) * ec, 1e-10 * pc);
}

TEST(NullSolid, GruneisenCompressedAndExpanded) {
  const Real c = 0.4, s1 = 1.5, s2 = 0.2, s3 = 0.1, rc2 = kRho * c * c;
  // GAMAO = A = 0: p(mu) alone, E from Simpson's rule on it.
  const NullSolid plain(kRho, kNoCutoff, 0.0, EquationOfState::gruneisen(kRho, c, s1, s2, s3, 0.0, 0.0, 0.0));
  const auto hugoniot = [&](Real j) {
    const Real mu = 1.0 / j - 1.0, m1 = mu + 1.0;
    const Real den = 1.0 - (s1 - 1.0) * mu - s2 * mu * mu / m1 - s3 * mu * mu * mu / (m1 * m1);
    return rc2 * mu * (1.0 + mu) / (den * den);
  };
  NullSolid::State<Real> s;
  const Real p = drive(plain, s, 0.9, 2000);
  EXPECT_NEAR(p, hugoniot(0.9), 1e-10 * p);
  Real simpson = 0.0;
  const int n = 2000;
  for (int k = 0; k <= n; ++k) {
    const Real j = 0.9 + 0.1 * k / n;
    simpson += (k == 0 || k == n ? 1.0 : (k % 2 ? 4.0 : 2.0)) * hugoniot(j);
  }
  simpson *= 0.1 / n / 3.0;
  EXPECT_NEAR(energy(plain, s), simpson, 1e-6 * simpson);

  // GAMAO, A != 0: p = that + (GAMAO + A mu) E at the law's E; E against RK4 on dE/dJ = -p(J, E).
  const Real g0 = 2.0, a = 0.5, e0 = 1e-6;
  const NullSolid law(kRho, kNoCutoff, 0.0, EquationOfState::gruneisen(kRho, c, s1, s2, s3, g0, a, e0));
  const auto pressure = [&](Real j, Real e) {
    const Real mu = 1.0 / j - 1.0, m1 = mu + 1.0;
    const Real den = 1.0 - (s1 - 1.0) * mu - s2 * mu * mu / m1 - s3 * mu * mu * mu / (m1 * m1);
    const Real ph = mu > 0.0 ? rc2 * mu * (1.0 + (1.0 - 0.5 * g0) * mu - 0.5 * a * mu * mu) / (den * den) : rc2 * mu;
    return ph + (g0 + a * mu) * e;
  };
  for (const Real j_end : {0.9, 1.1}) {
    NullSolid::State<Real> t;
    const Real pt = drive(law, t, j_end, 2000);
    EXPECT_NEAR(pt, pressure(j_end, energy(law, t)), 1e-10 * std::abs(pt)) << j_end;
    Real e = e0, j = 1.0;
    const int m = 4000;
    const Real h = (j_end - 1.0) / m;
    for (int k = 0; k < m; ++k, j += h) {
      const Real k1 = -pressure(j, e), k2 = -pressure(j + h / 2, e + h / 2 * k1);
      const Real k3 = -pressure(j + h / 2, e + h / 2 * k2), k4 = -pressure(j + h, e + h * k3);
      e += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    EXPECT_NEAR(energy(law, t), e, 1e-6 * std::abs(e - e0)) << j_end;
  }
}

TEST(NullSolid, TabulatedInterpolatesInLogVolumeAndExtrapolates) {
  // EV descending; C, T linear between the points.
  const std::array<Real, 10> ev{0.1, 0.0, -0.05, -0.1, -0.15, -0.2, -0.25, -0.3, -0.4, -0.5};
  const std::array<Real, 10> cc{-50.0, 0.0, 20.0, 50.0, 90.0, 140.0, 200.0, 270.0, 450.0, 700.0};
  const std::array<Real, 10> tt{1.0, 1.0, 1.1, 1.2, 1.3, 1.4, 1.5, 1.6, 1.7, 1.8};
  const Real gamma = 0.5, e0 = 3.0;
  const NullSolid law(kRho, kNoCutoff, 0.0, EquationOfState::tabulated(ev, cc, tt, gamma, e0));
  EXPECT_TRUE(law.eos().problem().empty());
  // The reference state sits on EV2 = 0: its slopes are the compression side's, dC/d eps = 20 / -0.05
  // and dT/d eps = 0.1 / -0.05, so dA/dmu = 400, dB/dmu = GAMA 2 = 1 (d eps / d mu = -1 at J = 1);
  // c0^2 = (dA/dmu + dB/dmu E0 + B p0) / rho0 with B = GAMA T = 0.5, p0 = B E0 = 1.5.
  const Real p0 = gamma * 1.0 * e0;
  EXPECT_DOUBLE_EQ(law.reference_pressure(), p0);
  EXPECT_NEAR(law.wave_speed() * law.wave_speed(), (400.0 + 1.0 * e0 + gamma * p0) / kRho, 1e-9 * 400.0 / kRho);
  const auto table = [&](Real eps, const std::array<Real, 10>& y) {
    std::size_t i = 0;
    while (i < 8 && eps <= ev[i + 1]) ++i;
    return y[i] + (eps - ev[i]) * (y[i + 1] - y[i]) / (ev[i + 1] - ev[i]);
  };
  // Inside the table (ln 0.9 = -0.10536: between EV4 = -0.1 and EV5 = -0.15), beyond EV10 and
  // above EV1 (extrapolated from the end segments).
  for (const Real j_end : {0.9, std::exp(-0.6), std::exp(0.15)}) {
    NullSolid::State<Real> s;
    const Real p = drive(law, s, j_end, 1000);
    const Real eps = std::log(j_end);
    EXPECT_NEAR(p, table(eps, cc) + gamma * table(eps, tt) * energy(law, s), 1e-10 * std::abs(p)) << j_end;
  }
  // By hand, at J = 0.9: w = (ln 0.9 + 0.1) / -0.05.
  NullSolid::State<Real> s;
  const Real p = drive(law, s, 0.9, 1000);
  const Real w = (std::log(0.9) + 0.1) / -0.05;
  EXPECT_NEAR(p, 50.0 + 40.0 * w + gamma * (1.2 + 0.1 * w) * energy(law, s), 1e-10 * p);
  std::array<Real, 10> bad = ev;
  bad[4] = bad[3];
  EXPECT_NE(EquationOfState::tabulated(bad, cc, tt, gamma, e0).problem().find("EV4 .. EV10 must descend"),
            std::string::npos);
}

TEST(NullSolid, PressureCutoffHoldsTension) {
  const Real k = 1.0e3, pc = -20.0;
  const NullSolid law(kRho, pc, 0.0, EquationOfState::linear_polynomial({0.0, k, 0.0, 0.0, 0.0, 0.0, 0.0}, 0.0));
  NullSolid::State<Real> s;
  // K mu reaches pc at J = K / (K + pc): beyond it the pressure stays pc, and the energy is the
  // trapezoid of it (E = int of -p dJ: K (J - 1 - ln J) up to the cut, then -pc per unit J).
  const Real p = drive(law, s, 1.1, 1100);
  EXPECT_EQ(p, pc);
  const Real jc = k / (k + pc);
  const Real e_exact = -k * (std::log(jc) - jc + 1.0) - pc * (1.1 - jc);
  EXPECT_NEAR(energy(law, s), e_exact, 1e-3 * std::abs(e_exact));  // one step straddles the cut
  // Compression is not cut.
  NullSolid::State<Real> q;
  EXPECT_NEAR(drive(law, q, 0.95, 10), k * (1.0 / 0.95 - 1.0), 1e-12 * k);
}

TEST(NullSolid, ViscousShearStressAndItsWorkInAnyFrame) {
  const Real mu = 0.3, g = 2.0, dt = 1e-3;
  const NullSolid law(kRho, kNoCutoff, mu, EquationOfState::linear_polynomial({0.0, 1e3, 0.0, 0.0, 0.0, 0.0, 0.0}, 0.0));
  const Mat3 q = Eigen::AngleAxis<Real>(0.7, Vec3(1.0, 2.0, -0.5).normalized()).toRotationMatrix();
  for (const Mat3& rot : {Mat3(Mat3::Identity()), q}) {
    NullSolid::State<Real> s;
    Mat3 d = Mat3::Zero();
    d(0, 1) = d(1, 0) = 0.5 * g;
    const Mat3 dr = rot * d * rot.transpose();
    Tensor3<Real> sigma{};
    for (int n = 0; n < 10; ++n) sigma = law.update(s, scaled_identity(1.0), to_tensor3(dr), dt);
    const Mat3 back = rot.transpose() * to_mat3(sigma) * rot;
    EXPECT_NEAR(back(0, 1), mu * g, 1e-12);
    EXPECT_NEAR(back(0, 0), 0.0, 1e-12);
    EXPECT_NEAR(back(2, 2), 0.0, 1e-12);
    EXPECT_NEAR(energy(law, s), 10 * dt * mu * g * g, 1e-15);
  }
}

TEST(NullSolid, BatchLanesMatchOneElement) {
  const NullSolid law(kRho, -5.0, 0.1,
                      EquationOfState::tabulated({0.1, 0.0, -0.05, -0.1, -0.15, -0.2, -0.25, -0.3, -0.4, -0.5},
                                                 {-50.0, 0.0, 20.0, 50.0, 90.0, 140.0, 200.0, 270.0, 450.0, 700.0},
                                                 {1.0, 1.0, 1.1, 1.2, 1.3, 1.4, 1.5, 1.6, 1.7, 1.8}, 0.5, 1.0));
  NullSolid::State<Lanes> sl;
  std::array<NullSolid::State<Real>, kLanes> sr{};
  for (int n = 1; n <= 20; ++n) {
    Tensor3<Lanes> fl, dl;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        fl[i][j] = dl[i][j] = Lanes::Zero();
        for (int l = 0; l < kLanes; ++l) {
          fl[i][j][l] = (i == j ? 1.0 : 0.0) + (l - 3.5) * 0.002 * n * (i == j ? 1.0 : 0.3);
          dl[i][j][l] = (l - 3.5) * 0.002 * (i == j ? 1.0 : 0.3);
        }
      }
    const Tensor3<Lanes> sigma = law.update(sl, fl, dl, 1.0);
    for (int l = 0; l < kLanes; ++l) {
      Tensor3<Real> f, d;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          f[i][j] = fl[i][j][l];
          d[i][j] = dl[i][j][l];
        }
      const Tensor3<Real> one = law.update(sr[static_cast<std::size_t>(l)], f, d, 1.0);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)  // to round-off: the compiler may fuse multiply-adds differently
          EXPECT_NEAR(sigma[i][j][l], one[i][j], 1e-12 * (1.0 + std::abs(one[i][j]))) << l;
      EXPECT_NEAR(sl.sound_speed[l], sr[static_cast<std::size_t>(l)].sound_speed, 1e-12 * sl.sound_speed[l]);
    }
  }
}

}  // namespace
