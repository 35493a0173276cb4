// Kinematic tie cost (Types 2, 6, 7): one cycle of a TiedSurfaceContact (condense the slaves' mass and
// force onto their masters, then follow_velocities and follow_positions) on a flat master plate of
// nx x nx unit segments with nx x nx slave nodes on it (no slave over a master node or edge).
// Rate: time per tied slave node and cycle. The one-time tie search is reported as init_ms.
// BM_TiebreakCycle (below): the penalty ties with failure, Types 8 and 9.
//   bm_contact_tied --benchmark_min_time=0.05
#include <benchmark/benchmark.h>

#include <chrono>
#include <memory>
#include <vector>

#include "../tests/unit/contact/plate_surface.hpp"
#include "../tests/unit/contact/tie_fixtures.hpp"
#include "slideline/contact/tiebreak_contact.hpp"
#include "slideline/contact/tied_contact.hpp"
#include "slideline/element/element_block.hpp"

using namespace slideline;

namespace {

void BM_TiedCycle(benchmark::State& state) {
  const Index nx = static_cast<Index>(state.range(0));
  Vec3Field x;
  Surface master = test::make_plate(x, nx, nx, 1.0, Vec3::Zero());
  std::vector<Index> slaves;
  for (Index j = 0; j < nx; ++j)
    for (Index i = 0; i < nx; ++i) {
      slaves.push_back(static_cast<Index>(x.size()));
      x.x.push_back(0.37 + i);
      x.y.push_back(0.41 + j);
      x.z.push_back(0.0);
    }
  NodalFields nodes;
  nodes.resize(x.size());
  nodes.x = x;
  nodes.x0 = x;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    nodes.ids[i] = static_cast<Id>(i + 1);
    nodes.mass[i] = 1.0;
    nodes.a.set(static_cast<Index>(i), Vec3(0.0, 0.0, -1.0));
  }
  std::vector<std::unique_ptr<ElementBlock>> blocks;
  std::vector<std::uint8_t> rigid(nodes.size(), 0);
  TiedSurfaceContact tie("tie", slaves, master);
  const auto t0 = std::chrono::steady_clock::now();
  tie.initialize(ContactContext{nodes, blocks, nullptr, rigid});
  const double init_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (tie.links().size() != slaves.size()) state.SkipWithError("not every slave tied");
  std::vector<Real> mass = nodes.mass, rot = nodes.rot_inertia;
  Vec3Field force, moment;
  force.resize(nodes.size(), 1.0);
  moment.resize(nodes.size(), 0.0);
  for (auto _ : state) {
    tie.condense(nodes, CondenseView{mass, force, rot, moment});
    tie.follow_velocities(nodes);
    tie.follow_positions(nodes);
    benchmark::DoNotOptimize(nodes.x.x.data());
  }
  state.counters["slave_nodes"] = static_cast<double>(slaves.size());
  state.counters["init_ms"] = 1e3 * init_s;
  state.counters["t_per_node"] = benchmark::Counter(static_cast<double>(slaves.size()),
                                                    benchmark::Counter::kIsIterationInvariantRate |
                                                        benchmark::Counter::kInvert);
}
BENCHMARK(BM_TiedCycle)->Arg(10)->Arg(32)->Arg(100)->Arg(316)->Unit(benchmark::kMicrosecond);

// Penalty ties with failure (Types 8, 9): one apply_forces of a TiebreakContact between an
// (n-1) x 1 x (n-1) cubic hexahedron layer (its n x n bottom nodes the slaves) and the top of an
// (n-2) x 1 x (n-2) block below it (meshes that do not match, as in the sslide decks), no
// failure. Type 9 ties every bottom segment and checks its failure each cycle; its slave surface
// is the whole upper block's boundary (the segments off the interface are skipped). Rate: time
// per tied slave node and cycle; init_ms is the one-time tie search and stiffness set-up.
//   bm_contact_tied --benchmark_filter=Tiebreak --benchmark_min_time=0.05

void BM_TiebreakCycle(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const bool type9 = state.range(1) == 9;
  test::TieMesh mesh;
  // Cubic elements: the tie search bins the master segments by the largest one, so a block much
  // taller than its elements are wide would put every top segment into one bin.
  const Real hl = 1.0 / (n - 2), hu = 1.0 / (n - 1);
  const test::TieBox lower = mesh.add_box({0, 0, 0}, {1, hl, 1}, n - 2, 1, n - 2);
  const test::TieBox upper = mesh.add_box({0, hl, 0}, {1, hu, 1}, n - 1, 1, n - 1);
  NodalFields nodes;
  mesh.fill(nodes);
  std::vector<std::unique_ptr<ElementBlock>> blocks;
  blocks.push_back(test::elastic_hexes(1, lower, 1.0, 1000.0, 0.3));
  blocks.push_back(test::elastic_hexes(2, upper, 1.0, 1000.0, 0.3));
  for (std::size_t i = 0; i < nodes.size(); ++i) nodes.mass[i] = 1.0;
  const std::vector<Id> lower_part{1}, upper_part{2};
  Surface master = build_surface_from_parts(blocks, nodes, lower_part, "bm");
  build_surface_adjacency(master);
  Surface slave_surface;
  if (type9) {
    slave_surface = build_surface_from_parts(blocks, nodes, upper_part, "bm");
    build_surface_adjacency(slave_surface);
  }
  TiebreakParameters p;
  p.unit = type9 ? TiebreakParameters::FailureUnit::segment : TiebreakParameters::FailureUnit::node;
  p.penalty_factor = 0.1;
  p.normal_failure = p.shear_failure = 1e30;  // never fails: the tied cost
  const std::vector<Index> slaves = upper.layer(0);
  TiebreakContact tie("tiebreak", slaves, std::move(slave_surface), std::move(master), p);
  std::vector<std::uint8_t> rigid(nodes.size(), 0);
  const auto t0 = std::chrono::steady_clock::now();
  tie.initialize(ContactContext{nodes, blocks, nullptr, rigid});
  const double init_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (tie.links().size() != slaves.size()) state.SkipWithError("not every slave tied");
  // Stretch the ties a little so that the forces are not all zero.
  for (Index s : slaves) nodes.x.add(s, Vec3(1e-4, 2e-4, -1e-4));
  Vec3Field force, moment;
  force.resize(nodes.size(), 0.0);
  moment.resize(nodes.size(), 0.0);
  StepTimes times;
  times.dt_prev = times.dt_avg = times.dt_next = 1e-4;
  for (auto _ : state) {
    tie.apply_forces(nodes, times, ContactForceView{force, moment});
    benchmark::DoNotOptimize(force.x.data());
  }
  state.counters["slave_nodes"] = static_cast<double>(slaves.size());
  state.counters["init_ms"] = 1e3 * init_s;
  state.counters["t_per_node"] = benchmark::Counter(static_cast<double>(slaves.size()),
                                                    benchmark::Counter::kIsIterationInvariantRate |
                                                        benchmark::Counter::kInvert);
}
BENCHMARK(BM_TiebreakCycle)
    ->ArgsProduct({{10, 32, 100, 316}, {8, 9}})
    ->ArgNames({"n", "type"})
    ->Unit(benchmark::kMicrosecond);

}  // namespace
