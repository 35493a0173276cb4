// Hexahedron force update and full explicit step, in ns per element-cycle, on cubes of 10^3 to
// 10^6 elements, 1 and 2 threads. The counter "per_elem_cycle" is the time per element-cycle
// (Google Benchmark prints it with an SI prefix: "180n" = 180 ns).
#include <benchmark/benchmark.h>

#include "slideline/core/parallel.hpp"
#include "slideline/element/hex_block.hpp"
#include "slideline/material/mooney_rivlin.hpp"
#include "slideline/solver/simulation.hpp"

using namespace slideline;

namespace {

/// n x n x n unit cube of the spec's rubber, bottom fixed in y, loaded by gravity-like body load;
/// stiffness damping `beta` (0 = none), hourglass form `hg` (default: the spec's type 10; QM 1, or
/// the default 0.1 for the viscous form).
std::unique_ptr<Simulation> make_cube(int n, Real beta = 0.0,
                                      HexHourglass::Kind hg = HexHourglass::Kind::physical_stiffness) {
  SimulationSetup setup;
  const int m = n + 1;
  const Index nn = m * m * m;
  setup.nodes.resize(nn);
  auto idx = [m](int i, int j, int k) { return static_cast<Index>(i + m * (j + m * k)); };
  const Real h = 1.0 / n;
  for (int k = 0; k < m; ++k)
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) {
        const Index a = idx(i, j, k);
        const Vec3 x(i * h, j * h, k * h);
        setup.nodes.ids[a] = a + 1;
        setup.nodes.x0.set(a, x);
        setup.nodes.x.set(a, x);
      }
  std::vector<Index> conn;
  std::vector<Id> ids;
  conn.reserve(8 * static_cast<std::size_t>(n) * n * n);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        conn.insert(conn.end(), {idx(i, j, k), idx(i + 1, j, k), idx(i + 1, j + 1, k), idx(i, j + 1, k),
                                 idx(i, j, k + 1), idx(i + 1, j, k + 1), idx(i + 1, j + 1, k + 1),
                                 idx(i, j + 1, k + 1)});
        ids.push_back(static_cast<Id>(ids.size() + 1));
      }
  setup.blocks.push_back(std::make_unique<HexBlock<MooneyRivlin>>(
      1, MooneyRivlin(0.01, 909.091, 0.0, 0.1),
      HexHourglass{hg, hg == HexHourglass::Kind::viscous ? 0.1 : 1.0}, BulkViscosity{}, std::move(conn),
      std::move(ids), StiffnessDamping{beta}));
  SupportGroup bottom{"bottom", {}, Vec3::Zero()};
  Support s;
  s.axis = Axis::y;
  for (int k = 0; k < m; ++k)
    for (int i = 0; i < m; ++i) s.nodes.push_back(idx(i, 0, k));
  bottom.supports.push_back(std::move(s));
  setup.supports.push_back(std::move(bottom));
  BodyLoad g;
  g.axis = Axis::y;
  g.scale = -10.0;
  g.curve = LoadCurve({{0.0, 0.0}, {0.1, 1.0}});
  setup.body_loads.push_back(std::move(g));
  MassDamping d;
  d.alpha = 15.0;
  setup.damping.push_back(d);
  setup.controls.end_time = 1e30;
  auto sim = std::make_unique<Simulation>(std::move(setup));
  sim->initialize();
  return sim;
}

void set_counters(benchmark::State& state, Index elements) {
  state.counters["elements"] = static_cast<double>(elements);
  state.counters["per_elem_cycle"] = benchmark::Counter(
      static_cast<double>(elements), benchmark::Counter::kIsIterationInvariantRate |
                                         benchmark::Counter::kInvert);
}

void BM_HexInternalForces(benchmark::State& state) {
  set_threads(static_cast<int>(state.range(1)));
  // Third argument: 1 = with stiffness damping, beta = 3.4e-6 (about 10% of critical at the
  // highest element frequency of n = 46), to price the damped kernel against the plain one.
  const Real beta = state.range(2) != 0 ? 3.4e-6 : 0.0;
  auto sim = make_cube(static_cast<int>(state.range(0)), beta);
  for (int i = 0; i < 20; ++i) sim->step();  // leave the reference state (bulk viscosity active)
  BlockEnergy e;
  // Reuse the simulation's own step but time only the element kernel via a private copy of the
  // buffers: build a corner buffer exactly as the simulation does.
  CornerBuffer cb;
  auto& block = *sim->blocks().front();
  cb.force.resize(block.connectivity().size());
  for (auto _ : state) {
    benchmark::DoNotOptimize(block.compute_forces(sim->nodes(), 1e-5, cb, e));
    benchmark::ClobberMemory();
  }
  set_counters(state, sim->element_count());
  set_threads(max_threads());
}

/// The element kernel with each hourglass form (argument: 0 viscous, 1 type 10, 2 types 4/5, 3 type 6).
void BM_HexHourglassForms(benchmark::State& state) {
  set_threads(1);
  const auto hg = static_cast<HexHourglass::Kind>(state.range(1));
  auto sim = make_cube(static_cast<int>(state.range(0)), 0.0, hg);
  for (int i = 0; i < 20; ++i) sim->step();
  BlockEnergy e;
  CornerBuffer cb;
  auto& block = *sim->blocks().front();
  cb.force.resize(block.connectivity().size());
  for (auto _ : state) {
    benchmark::DoNotOptimize(block.compute_forces(sim->nodes(), 1e-5, cb, e));
    benchmark::ClobberMemory();
  }
  set_counters(state, sim->element_count());
  set_threads(max_threads());
}

void BM_FullStep(benchmark::State& state) {
  set_threads(static_cast<int>(state.range(1)));
  auto sim = make_cube(static_cast<int>(state.range(0)));
  for (auto _ : state) sim->step();
  set_counters(state, sim->element_count());
  set_threads(max_threads());
}

void sizes(benchmark::internal::Benchmark* b) {
  for (int n : {10, 22, 46, 100})
    for (int t : {1, 2}) b->Args({n, t, 0});
  b->ArgNames({"n", "threads", "damped"});
  b->Unit(benchmark::kMillisecond);
  b->UseRealTime();
}

}  // namespace

BENCHMARK(BM_HexInternalForces)->Apply(sizes);
BENCHMARK(BM_HexInternalForces)
    ->Args({46, 1, 1})
    ->ArgNames({"n", "threads", "damped"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_HexHourglassForms)
    ->ArgsProduct({{46}, {0, 1, 2, 3}})
    ->ArgNames({"n", "hourglass"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_FullStep)->Apply(sizes);
