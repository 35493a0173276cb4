// Mass scaling (DT2MS of *CONTROL_TIMESTEP, solver/mass_scaling.hpp) against closed forms: the
// added mass per element is m_e ((T / dt_e)^2 - 1) with dt_e = len / c, the run takes the step
// TSSFAC x T, and a bar whose every element is scaled by f behaves as the same bar of density f rho
// (wave speed c / sqrt(f)), with the energy balance kept on the scaled mass.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "slideline/element/hex_block.hpp"
#include "slideline/material/elastic.hpp"
#include "slideline/solver/simulation.hpp"
#include "test_support/staged_simulation.hpp"

using namespace slideline;

namespace {

/// A bar along x of hexahedra of cross-section h x h and lengths `lengths` (one element through y
/// and z), elastic with nu = 0 (wave speed sqrt(E / rho)), no bulk viscosity.
struct ScaledBar : test_support::StagedSimulation {
  Real h, rho, e = 1.0e4, length = 0.0;
  int n;
  ScaledBar(const std::vector<Real>& lengths, Real side, Real density = 1.0)
      : h(side), rho(density), n(static_cast<int>(lengths.size())) {
    setup.nodes.resize(4 * (n + 1));
    Real x = 0.0;
    for (int i = 0; i <= n; ++i) {
      for (int c = 0; c < 4; ++c) {
        const Index k = 4 * i + c;
        const Vec3 p(x, (c == 1 || c == 2) ? h : 0.0, c >= 2 ? h : 0.0);
        setup.nodes.ids[k] = k + 1;
        setup.nodes.x0.set(k, p);
        setup.nodes.x.set(k, p);
      }
      if (i < n) x += lengths[static_cast<std::size_t>(i)];
    }
    length = x;
    std::vector<Index> conn;
    std::vector<Id> ids;
    for (int i = 0; i < n; ++i) {
      const Index a = 4 * i, b = 4 * (i + 1);
      conn.insert(conn.end(), {a + 0, b + 0, b + 1, a + 1, a + 3, b + 3, b + 2, a + 2});
      ids.push_back(i + 1);
    }
    setup.blocks.push_back(std::make_unique<HexBlock<ElasticSolid>>(
        1, ElasticSolid(rho, e, 0.0), HexHourglass{}, BulkViscosity{0.0, 0.0}, conn, ids));
    setup.controls.end_time = 1.0;
  }
  Real wave_speed() const { return std::sqrt(e / rho); }
  std::vector<Index> end_nodes(int i) const { return {4 * i, 4 * i + 1, 4 * i + 2, 4 * i + 3}; }
  Real total_mass() const {
    Real m = 0.0;
    for (Real v : sim().nodes().mass) m += v;
    return m;
  }
  /// End x = 0 held in x; every other node moves at -v0 (the bar hits a wall it sticks to).
  void impact(Real v0) {
    SupportGroup wall{"wall", {}, Vec3::Zero()};
    Support fix;
    fix.axis = Axis::x;
    fix.nodes = end_nodes(0);
    wall.supports.push_back(fix);
    setup.supports = {wall};
    for (Index k = 4; k < static_cast<Index>(setup.nodes.size()); ++k) setup.nodes.v.x[k] = -v0;
  }
};

std::vector<Real> one_small_element(Real h) {
  std::vector<Real> l(10, h);
  l[4] = h / 4;  // its step h / (4c) is a quarter of the others'
  return l;
}

}  // namespace

// DT2MS < 0: only the small element (step h/4c < T = h/2c) is scaled, by (T / (h/4c))^2 = 4: the
// added mass is 3 rho h^2 (h/4), and the run takes the step TSSFAC x T.
TEST(MassScaling, NegativeDt2msScalesOnlyTheSmallElementToTheRequestedStep) {
  const Real h = 0.1;
  ScaledBar bar(one_small_element(h), h);
  const Real c = bar.wave_speed(), target = 0.5 * h / c;
  bar.setup.controls.dt2ms = -target;
  bar.setup.controls.dt_scale = 0.9;
  bar.setup.controls.end_time = 50 * 0.9 * target;
  bar.start();
  const auto& report = bar.sim().added_mass();
  ASSERT_EQ(report.size(), 1u);
  EXPECT_EQ(report[0].scaled, 1);
  EXPECT_EQ(report[0].elements, 10);
  const Real m_small = bar.rho * h * h * h / 4;
  EXPECT_NEAR(report[0].mass, bar.rho * h * h * bar.length, 1e-12 * report[0].mass);
  EXPECT_NEAR(report[0].added, 3.0 * m_small, 1e-12 * m_small);
  EXPECT_NEAR(report[0].smallest_step, h / (4 * c), 1e-12 * h / c);
  EXPECT_NEAR(bar.total_mass(), report[0].mass + 3.0 * m_small, 1e-12 * report[0].mass);
  EXPECT_NEAR(bar.sim().stable_dt(), target, 1e-12 * target);
  while (bar.sim().step()) {
  }
  EXPECT_NEAR(bar.sim().dt(), 0.9 * target, 1e-12 * target);
}

// DT2MS > 0: every element is scaled to the step T (mass removed from the regular elements, whose
// step h/c is above T = h/2c: factor 1/4; added to the small one: factor 4).
TEST(MassScaling, PositiveDt2msScalesEveryElementToTheStep) {
  const Real h = 0.1;
  ScaledBar bar(one_small_element(h), h);
  const Real c = bar.wave_speed(), target = 0.5 * h / c;
  bar.setup.controls.dt2ms = target;
  bar.start();
  const auto& p = bar.sim().added_mass().at(0);
  const Real m_cube = bar.rho * h * h * h;
  EXPECT_EQ(p.scaled, 10);
  EXPECT_NEAR(p.added, 9 * m_cube * (0.25 - 1.0) + 3.0 * m_cube / 4, 1e-12 * m_cube);
  EXPECT_NEAR(bar.sim().stable_dt(), target, 1e-12 * target);
}

// A bar of elements all scaled by f = 4 is the bar of density 4 rho: same steps, same motion (to
// round-off), and the unscaled bar slowed down by 2 = sqrt(f) (wave speed c / 2): its steps are
// twice as long and its free end reverses at exactly twice the time. Bulk viscosity is off: it
// uses the material density, which mass scaling leaves alone. The kinetic energy is that of the
// scaled mass and the energy balance is the denser bar's.
TEST(MassScaling, UniformlyScaledBarIsTheDenserBar) {
  const int n = 20;
  const Real h = 0.05, v0 = 0.01;
  ScaledBar scaled(std::vector<Real>(n, h), h), dense(std::vector<Real>(n, h), h, 4.0),
      plain(std::vector<Real>(n, h), h);
  const Real c = scaled.wave_speed();
  scaled.setup.controls.dt2ms = -2.0 * h / c;  // f = (2 h/c / (h/c))^2 = 4
  const Real t_end = 1.5 * scaled.length / (c / 2);
  for (ScaledBar* b : {&scaled, &dense, &plain}) {
    b->impact(v0);
    b->setup.controls.end_time = b == &plain ? t_end / 2 : t_end;
    b->start();
  }
  ASSERT_EQ(scaled.sim().added_mass().at(0).scaled, n);
  EXPECT_NEAR(scaled.sim().stable_dt(), dense.sim().stable_dt(), 1e-12 * dense.sim().stable_dt());
  EXPECT_NEAR(scaled.sim().stable_dt(), 2.0 * plain.sim().stable_dt(), 1e-12 * dense.sim().stable_dt());
  const Index tip = 4 * n;
  const auto reversal = [tip](ScaledBar& b) {
    Real t = -1.0;
    while (b.sim().step())
      if (t < 0.0 && b.sim().nodes().v.x[tip] > 0.0) t = b.sim().time();
    return t;
  };
  Real worst = 0.0, t_reverse = -1.0;
  for (bool more = true; more;) {
    const bool a = scaled.sim().step(), b = dense.sim().step();  // both, to the same last cycle
    more = a && b;
    worst = std::max(worst, std::abs(scaled.sim().nodes().x.x[tip] - dense.sim().nodes().x.x[tip]));
    if (t_reverse < 0.0 && scaled.sim().nodes().v.x[tip] > 0.0) t_reverse = scaled.sim().time();
  }
  EXPECT_LT(worst, 1e-9 * v0 * t_end);
  const Real t_plain = reversal(plain);
  ASSERT_GT(t_reverse, 0.0);
  EXPECT_NEAR(t_reverse, 2.0 * t_plain, 1e-9 * t_reverse);
  // The lumped chain's free end reverses about one element transit after L / c (1.18 measured, in
  // both bars alike): the wave speed itself is in the factor 2 above.
  EXPECT_NEAR(t_reverse, scaled.length / (c / 2), 1.5 * h / (c / 2)) << "reversal at " << t_reverse;
  // Kinetic energy from the scaled mass (as LS-DYNA): the moving nodes carry 4 rho h^2 (L - h/2).
  const Real ke0 = 0.5 * 4.0 * scaled.rho * h * h * (scaled.length - 0.5 * h) * v0 * v0;
  EXPECT_NEAR(scaled.sim().energy().kinetic0, ke0, 1e-12 * ke0);
  EXPECT_NEAR(scaled.sim().energy_error_fraction(), dense.sim().energy_error_fraction(), 1e-6);
  RecordProperty("tip_reversal_time", std::to_string(t_reverse));
  RecordProperty("energy_error", std::to_string(scaled.sim().energy_error_fraction()));
}
