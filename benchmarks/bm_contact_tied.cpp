// Kinematic tie cost (Types 2, 6, 7): one cycle of a TiedSurfaceContact (condense the slaves' mass and
// force onto their masters, then follow_velocities and follow_positions) on a flat master plate of
// nx x nx unit segments with nx x nx slave nodes on it (no slave over a master node or edge).
// Rate: time per tied slave node and cycle. The one-time tie search is reported as init_ms.
//   bm_contact_tied --benchmark_min_time=0.05
#include <benchmark/benchmark.h>

#include <chrono>
#include <memory>
#include <vector>

#include "../tests/unit/contact/plate_surface.hpp"
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

}  // namespace
