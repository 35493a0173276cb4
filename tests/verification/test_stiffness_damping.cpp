// Verification of stiffness-proportional (Rayleigh) damping: a bar of hexahedra fixed at one end
// vibrating in its first mode decays with the closed-form logarithmic decrement, and the stable
// step is the damped limit of central differences.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "slideline/element/hex_block.hpp"
#include "slideline/material/elastic.hpp"
#include "slideline/solver/output_sink.hpp"
#include "slideline/solver/simulation.hpp"
#include "test_support/staged_simulation.hpp"

using namespace slideline;

namespace {

/// A bar along x of n cubes of side h (one element through y and z), elastic with nu = 0 (so the
/// axial motion is exactly a chain of springs E h between lumped masses rho h^3 / 4 per node),
/// fixed in x at x = 0, free at x = L; no bulk viscosity; stiffness damping beta.
struct DampedBar : test_support::StagedSimulation {
  int n;
  Real h, rho = 1.0, e = 1.0e4;
  DampedBar(int n_el, Real side, Real beta) : n(n_el), h(side) {
    setup.nodes.resize(static_cast<std::size_t>(4 * (n + 1)));
    for (int i = 0; i <= n; ++i)
      for (int c = 0; c < 4; ++c) {
        const Index k = 4 * i + c;
        const Vec3 x(i * h, (c == 1 || c == 2) ? h : 0.0, c >= 2 ? h : 0.0);
        setup.nodes.ids[k] = k + 1;
        setup.nodes.x0.set(k, x);
        setup.nodes.x.set(k, x);
      }
    std::vector<Index> conn;
    std::vector<Id> ids;
    for (int i = 0; i < n; ++i) {
      const Index a = 4 * i, b = 4 * (i + 1);
      conn.insert(conn.end(), {a + 0, b + 0, b + 1, a + 1, a + 3, b + 3, b + 2, a + 2});
      ids.push_back(i + 1);
    }
    setup.blocks.push_back(std::make_unique<HexBlock<ElasticSolid>>(
        1, ElasticSolid(rho, e, 0.0), HexHourglass{}, BulkViscosity{0.0, 0.0}, conn, ids,
        StiffnessDamping{beta}));
    SupportGroup fixed{"fixed", {}, Vec3::Zero()};
    Support s;
    s.axis = Axis::x;
    s.nodes = {0, 1, 2, 3};
    fixed.supports.push_back(s);
    setup.supports = {fixed};
    setup.history_nodes = {4 * n};  // a tip node
  }
  Real wave_speed() const { return std::sqrt(e / rho); }
  /// First circular frequency of the discrete chain (lumped masses, half mass at the free end):
  /// (2 c / h) sin(pi / (4 n)); the continuum's pi c / (2 L) is 0.03% above it for n = 20.
  Real omega1() const { return 2.0 * wave_speed() / h * std::sin(std::acos(-1.0) / (4.0 * n)); }
};

/// Positive peaks of a sampled signal, each refined by the parabola through the sample and its two
/// neighbours.
std::vector<Real> positive_peaks(const std::vector<Real>& u) {
  std::vector<Real> peaks;
  for (std::size_t r = 1; r + 1 < u.size(); ++r)
    if (u[r] > 0.0 && u[r] >= u[r - 1] && u[r] > u[r + 1]) {
      const Real a = 0.5 * (u[r - 1] + u[r + 1]) - u[r];
      const Real b = 0.5 * (u[r + 1] - u[r - 1]);
      peaks.push_back(a < 0.0 ? u[r] - b * b / (4.0 * a) : u[r]);
    }
  return peaks;
}

}  // namespace

// First mode of the fixed-free bar, started with the exact discrete mode shape as a velocity
// field. Stiffness damping gives it zeta = beta omega / 2, so the tip's positive peaks decay by
// delta = 2 pi zeta / sqrt(1 - zeta^2) per period. Tolerance 1%: the mode is exact in space (the
// discrete frequency is used); what remains is the explicit integration, whose period error is
// O((omega dt)^2) = 2e-4 here, and the damping stress being evaluated with the half-step-old
// velocity, a relative change of order zeta omega dt = 1e-3 at most; the parabolic peak
// interpolation at ~145 samples per period is good to 1e-5.
TEST(StiffnessDamping, BarFirstModeDecaysWithTheClosedFormDecrement) {
  const int n = 20;
  const Real h = 0.05;
  const Real zeta = 0.02;
  DampedBar probe(n, h, 0.0);
  const Real omega = probe.omega1();
  const Real beta = 2.0 * zeta / omega;
  DampedBar bar(n, h, beta);
  const Real theta = std::acos(-1.0) / (2.0 * n);
  for (int i = 0; i <= n; ++i)
    for (int c = 0; c < 4; ++c) bar.setup.nodes.v.x[4 * i + c] = 0.01 * std::sin(i * theta);
  const Real period = 2.0 * std::acos(-1.0) / omega;
  const int periods = 8;
  bar.setup.controls.end_time = (periods + 0.5) * period;
  History hist;
  bar.start();
  bar.sim().run({&hist});
  const auto u = hist.series("nodes/" + std::to_string(4 * n + 1) + "/displacement", 0);
  const auto peaks = positive_peaks(u);
  ASSERT_GE(peaks.size(), static_cast<std::size_t>(periods));
  const int k = periods - 1;
  const Real delta = std::log(peaks[0] / peaks[static_cast<std::size_t>(k)]) / k;
  const Real expected = 2.0 * std::acos(-1.0) * zeta / std::sqrt(1.0 - zeta * zeta);
  EXPECT_NEAR(delta, expected, 0.01 * expected);
  std::printf("stiffness damping: beta = %.6g, zeta_1 = %.4f, decrement %.6f (closed form %.6f, %+.3f%%)\n",
              beta, zeta, delta, expected, 100.0 * (delta / expected - 1.0));
  RecordProperty("log_decrement_relative_error", std::to_string(delta / expected - 1.0));
  // The damping stress's work is part of the stress work the simulation books from the nodal
  // forces, so the energy balance closes as tightly as the undamped bar's (SolidCore) while half
  // of the energy is dissipated.
  const auto err = hist.series("energy/balance_error");
  const auto ke = hist.series("energy/kinetic");
  Real worst = 0.0;
  for (Real v : err) worst = std::max(worst, std::abs(v) / ke.front());
  EXPECT_LT(worst, 0.01);
  EXPECT_LT(ke.back(), 0.5 * ke.front());
}

// The highest element frequency of a cube is omega_max = 2 c / h; stiffness damping gives it
// xi = beta c / h, and the stable step becomes (h / c)(sqrt(1 + xi^2) - xi). Here zeta_1 = 0.02
// means xi = 0.51 and a step 0.61 times the undamped one; the run is stable at TSSFAC 0.9.
TEST(StiffnessDamping, StableStepShrinksAsPredicted) {
  const int n = 20;
  const Real h = 0.05;
  DampedBar plain(n, h, 0.0);
  plain.setup.controls.end_time = 1.0;
  plain.start();
  const Real c = plain.wave_speed();
  EXPECT_NEAR(plain.sim().stable_dt(), h / c, 1e-12 * h / c);
  const Real beta = 2.0 * 0.02 / plain.omega1();
  DampedBar bar(n, h, beta);
  bar.setup.controls.end_time = 1.0;
  bar.start();
  const Real xi = beta * c / h;
  const Real expected = (h / c) * (std::sqrt(1.0 + xi * xi) - xi);
  EXPECT_NEAR(bar.sim().stable_dt(), expected, 1e-12 * expected);
  EXPECT_LT(bar.sim().stable_dt(), 0.62 * h / c);
}
