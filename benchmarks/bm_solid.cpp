// Hexahedron force update and full explicit step, in ns per element-cycle, on cubes of 10^3 to
// 10^6 elements, 1 and 2 threads (or the list in SLIDELINE_BENCH_THREADS). The counter "per_elem_cycle" is the time per element-cycle
// (Google Benchmark prints it with an SI prefix: "180n" = 180 ns).
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "slideline/core/parallel.hpp"
#include "slideline/element/block_factory.hpp"
#include "slideline/element/hex_block.hpp"
#include "slideline/material/mooney_rivlin.hpp"
#include "slideline/solver/simulation.hpp"
#include "test_support/kuhn_tets.hpp"

using namespace slideline;

namespace {

/// n x n x n unit cube of the spec's rubber, bottom fixed in y, loaded by gravity-like body load;
/// stiffness damping `beta` (0 = none), hourglass form `hg` (default: the spec's type 10; QM 1, or
/// the default 0.1 for the viscous form).
/// `ms1st` >= 0: mass scaling with DT2MS = -2 h / c (every element's mass x 4), once (1) or every
/// cycle (0).
std::unique_ptr<Simulation> make_cube(int n, Real beta = 0.0,
                                      HexHourglass::Kind hg = HexHourglass::Kind::physical_stiffness,
                                      int ms1st = -1) {
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
  if (ms1st >= 0) {
    setup.controls.dt2ms = -2.0 * h / MooneyRivlin(0.01, 909.091, 0.0, 0.1).wave_speed();
    setup.controls.mass_scaling_every_cycle = ms1st == 0;
  }
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

/// The full step with mass scaling (DT2MS = -2 h / c, every element x 4): MS1ST = 1 (argument 1,
/// scaled once) against MS1ST = 0 (argument 0, factors and nodal masses rebuilt every cycle).
void BM_FullStepMassScaling(benchmark::State& state) {
  set_threads(static_cast<int>(state.range(1)));
  auto sim = make_cube(static_cast<int>(state.range(0)), 0.0, HexHourglass::Kind::physical_stiffness,
                       static_cast<int>(state.range(2)));
  for (auto _ : state) sim->step();
  set_counters(state, sim->element_count());
  set_threads(max_threads());
}

/// The element kernel of each solid form on the n^3 cube of the spec's rubber, at rest after a
/// small homogeneous stretch (argument: 1 the one-point hexahedron with the type 10 hourglass,
/// 2 the fully integrated hexahedron, 10 the tetrahedron, six per cube cell). The counter is per
/// element: a tetrahedron mesh has six times the elements of the hexahedron mesh on the same nodes.
void BM_SolidForms(benchmark::State& state) {
  set_threads(1);
  const int n = static_cast<int>(state.range(0)), form = static_cast<int>(state.range(1)), m = n + 1;
  NodalFields nodes;
  nodes.resize(static_cast<std::size_t>(m) * m * m);
  auto idx = [m](int i, int j, int k) { return static_cast<Index>(i + m * (j + m * k)); };
  for (int k = 0; k < m; ++k)
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) {
        const Vec3 x(Real(i) / n, Real(j) / n, Real(k) / n);
        nodes.ids[idx(i, j, k)] = idx(i, j, k) + 1;
        nodes.x0.set(idx(i, j, k), x);
        nodes.x.set(idx(i, j, k), Vec3(1.01 * x[0], x[1], x[2]));
      }
  std::vector<Index> conn;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const auto corner = [&](int c) { return idx(i + (c & 1), j + ((c >> 1) & 1), k + (c >> 2)); };
        if (form == 10)
          for (const auto& t : test_support::kuhn_tets())
            for (int c : t) conn.push_back(corner(c));
        else
          for (int c : {0, 1, 3, 2, 4, 5, 7, 6}) conn.push_back(corner(c));
      }
  std::vector<Id> ids(conn.size() / (form == 10 ? 4 : 8));
  for (std::size_t e = 0; e < ids.size(); ++e) ids[e] = static_cast<Id>(e + 1);
  const SolidLaw law = MooneyRivlin(0.01, 909.091, 0.0, 0.1);
  std::unique_ptr<ElementBlock> block =
      form == 10  ? make_tet_block(1, law, BulkViscosity{}, std::move(conn), std::move(ids))
      : form == 2 ? make_full_hex_block(1, law, BulkViscosity{}, std::move(conn), std::move(ids))
                  : make_hex_block(1, law, HexHourglass{HexHourglass::Kind::physical_stiffness, 1.0},
                                   BulkViscosity{}, std::move(conn), std::move(ids));
  block->initialize(nodes);
  CornerBuffer cb;
  cb.force.resize(block->connectivity().size());
  BlockEnergy e;
  for (auto _ : state) {
    benchmark::DoNotOptimize(block->compute_forces(nodes, 1e-5, cb, e));
    benchmark::ClobberMemory();
  }
  set_counters(state, block->element_count());
  set_threads(max_threads());
}

/// The thread counts of the size sweeps: 1 and 2 (this project's 2-core machine), or the
/// comma-separated list in SLIDELINE_BENCH_THREADS for a scaling run on a larger machine
/// (docs/benchmarks.md, "Thread scaling").
std::vector<int> thread_counts() {
  std::vector<int> out;
  if (const char* env = std::getenv("SLIDELINE_BENCH_THREADS")) {
    std::stringstream list(env);
    for (std::string item; std::getline(list, item, ',');)
      if (const int t = std::atoi(item.c_str()); t > 0) out.push_back(t);
  }
  if (out.empty()) out = {1, 2};
  return out;
}

void sizes(benchmark::internal::Benchmark* b) {
  for (int n : {10, 22, 46, 100})
    for (int t : thread_counts()) b->Args({n, t, 0});
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
BENCHMARK(BM_FullStepMassScaling)
    ->ArgsProduct({{22, 46}, {1, 2}, {1, 0}})
    ->ArgNames({"n", "threads", "ms1st"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_SolidForms)
    ->ArgsProduct({{22}, {1, 2, 10}})
    ->ArgNames({"n", "elform"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
