// Belytschko-Tsay shell throughput: the block's internal-force update alone and a whole
// Simulation::step, on square plates of 10^3 .. 10^6 shells, at 1 and 2 threads.
// Reports ns per element-cycle ("ns_per_elem_cycle", wall clock; Google Benchmark prints the
// inverted rate with an "s" suffix: the number is nanoseconds because the count is scaled by 1e-9).
#include <benchmark/benchmark.h>

#include <cmath>

#include "slideline/core/parallel.hpp"
#include "slideline/element/block_factory.hpp"
#include "slideline/element/shell_block.hpp"
#include "slideline/solver/simulation.hpp"

using namespace slideline;

namespace {

/// A warped n x n plate of shells, loaded and moving so that every kernel term is active.
/// `dt2ms` != 0: mass scaling, every cycle when `every_cycle` (MS1ST = 0), else once (MS1ST = 1).
std::unique_ptr<Simulation> make_plate(int n, Real dt2ms = 0.0, bool every_cycle = false) {
  SimulationSetup setup;
  const int np = n + 1;
  setup.nodes.resize(static_cast<std::size_t>(np) * np);
  for (int j = 0; j < np; ++j)
    for (int i = 0; i < np; ++i) {
      const Index q = i + np * j;
      const Real x = static_cast<Real>(i) / n, y = static_cast<Real>(j) / n;
      const Vec3 p(x, y, 0.01 * std::sin(7.0 * x) * std::cos(5.0 * y));
      setup.nodes.ids[q] = q + 1;
      setup.nodes.x0.set(q, p);
      setup.nodes.x.set(q, p);
      setup.nodes.v.set(q, Vec3(0.01 * y, -0.02 * x, 0.05 * x * y));
      setup.nodes.omega.set(q, Vec3(0.1 * x, 0.05, -0.1 * y));
    }
  std::vector<Index> conn;
  conn.reserve(4 * static_cast<std::size_t>(n) * n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      conn.insert(conn.end(), {i + np * j, i + 1 + np * j, i + 1 + np * (j + 1), i + np * (j + 1)});
  std::vector<Id> ids(conn.size() / 4);
  for (std::size_t k = 0; k < ids.size(); ++k) ids[k] = static_cast<Id>(k + 1);
  setup.blocks.push_back(make_shell_block(1, ElasticShell(0.1, 1000.0, 0.3),
                                        ShellSection{.thickness = 0.01}, std::move(conn),
                                        std::move(ids)));
  BodyLoad bz;
  bz.axis = Axis::z;
  bz.scale = -10.0;
  setup.body_loads.push_back(bz);
  MassDamping d;
  d.alpha = 15.0;
  setup.damping.push_back(d);
  setup.controls.end_time = 1e30;
  setup.controls.dt2ms = dt2ms;
  setup.controls.mass_scaling_every_cycle = every_cycle;
  auto sim = std::make_unique<Simulation>(std::move(setup));
  return sim;
}

int side(std::int64_t elements) { return static_cast<int>(std::lround(std::sqrt(static_cast<double>(elements)))); }

void set_rate(benchmark::State& state, Index elements) {
  state.counters["elements"] = static_cast<double>(elements);
  state.counters["ns_per_elem_cycle"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * elements * 1e-9,
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_ShellInternalForces(benchmark::State& state) {
  set_threads(static_cast<int>(state.range(1)));
  auto sim = make_plate(side(state.range(0)));
  sim->initialize();
  ElementBlock& block = *sim->blocks()[0];
  CornerBuffer corners;
  corners.force.resize(4 * static_cast<std::size_t>(block.element_count()));
  corners.moment.resize(4 * static_cast<std::size_t>(block.element_count()));
  block.set_slot_base(0, 0);
  for (auto _ : state) {
    BlockEnergy e;
    benchmark::DoNotOptimize(block.compute_forces(sim->nodes(), 1e-6, corners, e));
    benchmark::ClobberMemory();
  }
  set_rate(state, block.element_count());
}

void BM_ShellSimulationStep(benchmark::State& state) {
  set_threads(static_cast<int>(state.range(1)));
  auto sim = make_plate(side(state.range(0)));
  sim->initialize();
  for (auto _ : state) benchmark::DoNotOptimize(sim->step());
  set_rate(state, sim->element_count());
}

/// The full step with mass scaling, DT2MS = -2 x the elements' step at rest (len = A / diagonal =
/// 1 / (sqrt 2 n), c = sqrt(E / (rho (1 - nu^2)))): every shell scaled x 4, mass and rotary inertia.
/// Argument 2: MS1ST (1 scaled once, 0 re-evaluated every cycle).
void BM_ShellStepMassScaling(benchmark::State& state) {
  set_threads(static_cast<int>(state.range(1)));
  const int n = side(state.range(0));
  const Real c = std::sqrt(1000.0 / (0.1 * (1.0 - 0.3 * 0.3)));
  auto sim = make_plate(n, -2.0 / (std::sqrt(2.0) * n * c), state.range(2) == 0);
  sim->initialize();
  for (auto _ : state) benchmark::DoNotOptimize(sim->step());
  set_rate(state, sim->element_count());
}

// Elements x threads. 10^6 runs only a few iterations (MinTime keeps it short).
void sizes(benchmark::internal::Benchmark* b) {
  for (std::int64_t n : {1000, 10000, 100000, 1000000})
    for (std::int64_t t : {1, 2}) b->Args({n, t});
  b->ArgNames({"elements", "threads"});
  b->Unit(benchmark::kMillisecond);
  b->MinTime(0.2);
  b->UseRealTime();
}

}  // namespace

BENCHMARK(BM_ShellInternalForces)->Apply(sizes);
BENCHMARK(BM_ShellSimulationStep)->Apply(sizes);
BENCHMARK(BM_ShellStepMassScaling)
    ->ArgsProduct({{10000, 100000}, {1}, {1, 0}})
    ->ArgNames({"elements", "threads", "ms1st"})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(0.2)
    ->UseRealTime();
