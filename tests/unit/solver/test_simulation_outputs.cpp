// Output times: history records sit exactly on multiples of the interval and the run ends exactly
// at the end time, whatever the scale of the units (Simulation::step lands on them).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "slideline/element/hex_block.hpp"
#include "slideline/material/elastic.hpp"
#include "slideline/solver/simulation.hpp"
#include "test_support/staged_simulation.hpp"

using namespace slideline;

namespace {

/// One hexahedron, a cube of side `h`, elastic, its bottom face (z = 0) fixed in x, y and z, under
/// a base acceleration `g` along -z; TSSFAC 0.5.
struct OneHex : test_support::StagedSimulation {
  OneHex(Real h, Real rho, Real e, Real nu, Real g) {
    const Vec3 c[8] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    setup.nodes.resize(8);
    for (Index i = 0; i < 8; ++i) {
      setup.nodes.ids[i] = i + 1;
      setup.nodes.x0.set(i, h * c[i]);
      setup.nodes.x.set(i, h * c[i]);
    }
    setup.blocks.push_back(std::make_unique<HexBlock<ElasticSolid>>(
        1, ElasticSolid(rho, e, nu), HexHourglass{}, BulkViscosity{},
        std::vector<Index>{0, 1, 2, 3, 4, 5, 6, 7}, std::vector<Id>{1}));
    SupportGroup bottom{"bottom", {}, Vec3::Zero()};
    for (int a = 0; a < 3; ++a) {
      Support s;
      s.axis = static_cast<Axis>(a);
      s.nodes = {0, 1, 2, 3};
      bottom.supports.push_back(s);
    }
    setup.supports.push_back(bottom);
    BodyLoad bl;
    bl.axis = Axis::z;
    bl.scale = -g;
    setup.body_loads.push_back(bl);
    setup.history_nodes = {6};
    setup.controls.dt_scale = 0.5;
  }
};

/// Starts `m` and runs it to `end` with history interval `interval` and checks the record times: record k at
/// exactly k * interval (the product as the solver forms it) while that is before the end, and a
/// last record at exactly `end`.
void expect_exact_output_times(OneHex& m, Real end, Real interval, const char* label) {
  m.setup.controls.end_time = end;
  m.setup.controls.history_interval = interval;
  m.start();
  Simulation& sim = m.sim();
  History h;
  Real dt_min = std::numeric_limits<Real>::max();  // the smallest scaled stable step of the run
  sim.run({&h}, [&](const Simulation& s) { dt_min = std::min(dt_min, s.controls().dt_scale * s.stable_dt()); }, 1);
  // Multiples k * interval before the end (one that rounds onto the end is the end record).
  const long n = static_cast<long>(std::ceil(end / interval - 1e-9));
  std::printf("%s: dt %.4e, %ld cycles, %zu records, last at %.17g (end %.17g)\n", label,
              sim.controls().dt_scale * sim.stable_dt(), sim.cycle(), h.records(), h.time().back(), end);
  ASSERT_EQ(h.records(), static_cast<std::size_t>(n + 1)) << label;
  for (long k = 0; k < n; ++k) EXPECT_EQ(h.time()[k], static_cast<Real>(k) * interval) << label << " record " << k;
  EXPECT_EQ(h.time().back(), end) << label;
  EXPECT_EQ(sim.time(), end) << label;
  // The run took the scaled stable step between the outputs (only the landing steps are shorter).
  EXPECT_LE(sim.cycle(), std::ceil(end / dt_min) + n + 1) << label;
}

}  // namespace

// mm-tonne-s steel, a 1 mm cube: dt ~ 8e-8 s, end time 1e-4 s.
TEST(SimulationOutputs, TinyScaleRecordsAtExactMultiplesAndEndsAtTheEndTime) {
  for (Real interval : {1e-5, 2e-6, 1e-6, 3e-6}) {
    OneHex m(1.0, 7.85e-9, 2.1e5, 0.3, 9810.0);
    expect_exact_output_times(m, 1e-4, interval, "mm-t-s steel");
  }
}

// Unitless: unit cube, rho 1, E 1000.
TEST(SimulationOutputs, UnitlessRecordsAtExactMultiplesAndEndsAtTheEndTime) {
  for (auto [end, interval] : {std::pair<Real, Real>{1.0, 0.1}, {0.7, 0.1}, {0.3, 0.1}, {2.0, 0.03}}) {
    OneHex m(1.0, 1.0, 1000.0, 0.3, 1.0);
    expect_exact_output_times(m, end, interval, "unitless");
  }
}
