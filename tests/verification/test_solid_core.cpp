// Verification of the explicit solid core against closed-form answers: wave speed, energy
// conservation in free vibration, and static equilibrium of the spec's merged two-block body.
#include <gtest/gtest.h>

#include <cmath>

#include "slideline/core/parallel.hpp"
#include "slideline/element/hex_block.hpp"
#include "slideline/material/elastic.hpp"
#include "slideline/scenarios/two_block.hpp"
#include "slideline/solver/build.hpp"
#include "test_support/staged_simulation.hpp"

using namespace slideline;

namespace {

/// A bar along x of n cubic elements of side h (one element through y and z), elastic, nu = 0.
struct Bar : test_support::StagedSimulation {
  Real h, length, rho = 1.0, e = 1.0e4;
  int n;
  Bar(int n_el, Real side) : h(side), length(n_el * side), n(n_el) {
    const Index nn = 4 * (n + 1);
    setup.nodes.resize(nn);
    for (int i = 0; i <= n; ++i)
      for (int c = 0; c < 4; ++c) {
        const Index k = 4 * i + c;
        const Vec3 x(i * h, (c == 1 || c == 2) ? h : 0.0, c >= 2 ? h : 0.0);
        setup.nodes.ids[k] = k + 1;
        setup.nodes.x0.set(k, x);
        setup.nodes.x.set(k, x);
      }
    // node c: 0 (y0,z0), 1 (y1,z0), 2 (y1,z1), 3 (y0,z1); element nodes ordered x-y-z as the unit hex
    std::vector<Index> conn;
    std::vector<Id> ids;
    for (int i = 0; i < n; ++i) {
      const Index a = 4 * i, b = 4 * (i + 1);
      conn.insert(conn.end(), {a + 0, b + 0, b + 1, a + 1, a + 3, b + 3, b + 2, a + 2});
      ids.push_back(i + 1);
    }
    setup.blocks.push_back(std::make_unique<HexBlock<ElasticSolid>>(
        1, ElasticSolid(rho, e, 0.0), HexHourglass{}, BulkViscosity{}, conn, ids));
  }
  std::vector<Index> end_nodes(int i) const { return {4 * i, 4 * i + 1, 4 * i + 2, 4 * i + 3}; }
  Real wave_speed() const { return std::sqrt(e / rho); }  // nu = 0: lambda = 0, mu = E/2
};

}  // namespace

TEST(SolidCore, StepLoadWaveArrivesWithinOneElementOfLOverC) {
  Bar bar(40, 0.025);
  const Real c = bar.wave_speed(), v0 = 0.01;
  // The left end moves at constant velocity v0 from t = 0 (a step in particle velocity, i.e. a
  // step stress rho c v0); the right end is fixed and its reaction records the arrival.
  SupportGroup left{"left", {}, Vec3::Zero()};
  Support drive;
  drive.axis = Axis::x;
  drive.nodes = bar.end_nodes(0);
  drive.has_curve = true;
  drive.curve = LoadCurve({{0.0, 0.0}, {1.0, v0}});
  left.supports.push_back(drive);
  SupportGroup right{"right", {}, Vec3::Zero()};
  Support fix;
  fix.axis = Axis::x;
  fix.nodes = bar.end_nodes(bar.n);
  right.supports.push_back(fix);
  bar.setup.supports = {left, right};
  const Real t_arrive = bar.length / c;
  bar.setup.controls.end_time = 1.5 * t_arrive;
  // At rest (no bulk viscosity) the stable step is the element transit time h / c.
  bar.start();
  EXPECT_NEAR(bar.sim().stable_dt(), bar.h / c, 1e-12 * bar.h / c);
  History h;
  bar.sim().run({&h});
  const Real sigma_area = bar.rho * c * v0 * bar.h * bar.h;
  // Arrival: first time the fixed-end reaction reaches the incident force (it doubles on reflection).
  Real t_hit = -1.0;
  for (std::size_t r = 0; r < h.records(); ++r)
    if (std::abs(h.value("supports/right/reaction", r, 0)) >= sigma_area) {
      t_hit = h.time()[r];
      break;
    }
  ASSERT_GT(t_hit, 0.0);
  EXPECT_NEAR(t_hit, t_arrive, bar.h / c) << "arrival " << t_hit << " expected " << t_arrive;
}

TEST(SolidCore, UndampedFreeVibrationConservesEnergyWithinOnePercent) {
  Bar bar(20, 0.05);
  // Fixed at x = L, free at x = 0: first mode cos(pi x / 2L). Start it with a velocity field.
  SupportGroup right{"right", {}, Vec3::Zero()};
  Support fix;
  fix.axis = Axis::x;
  fix.nodes = bar.end_nodes(bar.n);
  right.supports.push_back(fix);
  bar.setup.supports = {right};
  const Real pi = std::acos(-1.0);
  for (Index k = 0; k < static_cast<Index>(bar.setup.nodes.size()); ++k)
    bar.setup.nodes.v.x[k] = 0.05 * std::cos(pi * bar.setup.nodes.x0.x[k] / (2 * bar.length));
  for (Index k : bar.end_nodes(bar.n)) bar.setup.nodes.v.x[k] = 0.0;
  const Real period = 4 * bar.length / bar.wave_speed();
  bar.setup.controls.end_time = 5 * period;
  History h;
  bar.start();
  bar.sim().run({&h});
  const auto err = h.series("energy/balance_error");
  const auto ke = h.series("energy/kinetic");
  const Real e0 = ke.front();
  ASSERT_GT(e0, 0.0);
  Real worst = 0.0, ke_min = e0;
  for (std::size_t r = 0; r < err.size(); ++r) {
    worst = std::max(worst, std::abs(err[r]) / e0);
    ke_min = std::min(ke_min, ke[r]);
  }
  EXPECT_LT(worst, 0.01);
  EXPECT_LT(ke_min, 0.05 * e0);  // the energy really moved into strain energy and back
  RecordProperty("max_relative_energy_error", std::to_string(worst));
}

namespace {
History run_merged_blocks(int threads) {
  set_threads(threads);
  scenarios::TwoBlockOptions o;
  o.merged = true;
  auto sim = build_simulation(scenarios::make_solid_pair_model(o));
  History h;
  sim->run({&h});
  set_threads(max_threads());
  return h;
}
}  // namespace

TEST(SolidCore, MergedSpecBlocksCarryTheSpecLoadsIntoTheSupports) {
  const History h = run_merged_blocks(0);
  const Real ry = h.mean("supports/bottom_y/reaction", 1, 0.2, 0.3);
  const Real rx = h.mean("supports/right_x/reaction", 0, 0.45, 0.5);
  EXPECT_NEAR(ry, -10.0, 0.005 * 10.0) << "mean R_y over [0.2, 0.3]";
  EXPECT_NEAR(rx, 3.1, 0.01 * 3.1) << "mean R_x over [0.45, 0.5]";
  // The supports take only the directions they fix.
  EXPECT_EQ(h.value("supports/bottom_y/reaction", h.records() - 1, 0), 0.0);
  EXPECT_EQ(h.value("supports/right_x/reaction", h.records() - 1, 1), 0.0);
  EXPECT_EQ(h.time().back(), 0.5);
  std::printf("merged blocks: mean R_y[0.2,0.3] = %.6f, mean R_x[0.45,0.5] = %.6f\n", ry, rx);
}

TEST(SolidCore, ResultsDoNotDependOnTheThreadCount) {
  const History one = run_merged_blocks(1);
  const History two = run_merged_blocks(2);
  ASSERT_EQ(one.records(), two.records());
  for (const auto& ch : one.channels())
    for (int c = 0; c < ch.components; ++c)
      for (std::size_t r = 0; r < one.records(); ++r)
        ASSERT_EQ(one.value(ch.path, r, c), two.value(ch.path, r, c)) << ch.path << " record " << r;
}
