// Contact's share of a full explicit step (issue 8, "Benchmark"): a two-block model of 10^5
// hexahedra, the upper block pressed onto the lower one by a body load and pushed sideways past
// the friction limit (sliding), a Type 3 penalty interface with Coulomb friction between the upper
// bottom face and the lower top face (non-coincident meshes). Built directly as a Simulation, as
// tests/unit/contact/test_penalty_initial_penetration.cpp does. A separate program from
// bm_contact so that neither compile unit pulls in both the element and the search templates.
//   bm_contact_step --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <memory>

#include "../tests/unit/contact/two_blocks.hpp"
#include "slideline/contact/search/fcl_broad_phase.hpp"
#include "slideline/contact/surface_to_surface_contact.hpp"
#include "slideline/core/parallel.hpp"

using namespace slideline;

namespace {

using test::BlockGrid;

// Lower block 60 x 14 x 60 (element 0.1), upper 40 x 31 x 40 (element 0.0975 in x and z, so no
// upper node sits over a lower node): 50 400 + 49 600 = 100 000 hexahedra. Slaves: the upper
// bottom face (1 681 nodes, 1 600 segments); the second pass: the lower top face (3 721, 3 600).
constexpr int kLowerN = 60, kLowerNy = 14, kUpperN = 40, kUpperNy = 31;

std::unique_ptr<ElementBlock> elastic(Id pid, const BlockGrid& b) {
  HexHourglass hg;  // as two_blocks.hpp: stiffness hourglass control (the spec's blocks)
  hg.kind = HexHourglass::Kind::physical_stiffness;
  hg.coefficient = 1.0;
  const auto conn = b.conn();
  std::vector<Id> ids(conn.size() / 8);
  for (std::size_t e = 0; e < ids.size(); ++e) ids[e] = static_cast<Id>(1000000 * pid + e + 1);
  return std::make_unique<HexBlock<ElasticSolid>>(pid, ElasticSolid(test::kTwoBlockRho, test::kTwoBlockE, test::kTwoBlockNu),
                                                  hg, BulkViscosity{1.5, 0.06}, conn, ids);
}

// The face of node layer j as a surface of block `block`, part `part`, its segments mapped to the
// elements of element layer je (BlockGrid::face numbers them i + nx k, right only for ny = 1).
Surface face(const BlockGrid& g, int j, bool up, int je, Index block, Id part) {
  Surface s = g.face(j, up);
  for (int k = 0; k < g.nz; ++k)
    for (int i = 0; i < g.nx; ++i)
      s.element[static_cast<std::size_t>(i + g.nx * k)] = i + g.nx * (je + g.ny * k);
  s.block.assign(s.block.size(), block);
  s.part.assign(s.part.size(), part);
  return s;
}

std::unique_ptr<Simulation> make_two_block_model() {
  SimulationSetup setup;
  test_support::GridMesh mesh;
  const BlockGrid lower{mesh.add_box({0, 0, 0}, {6.0, 1.4, 6.0}, kLowerN, kLowerNy, kLowerN)};
  const BlockGrid upper{mesh.add_box({1.03, 1.4, 1.03}, {3.9, 3.1, 3.9}, kUpperN, kUpperNy, kUpperN)};
  mesh.fill(setup.nodes);
  setup.blocks.push_back(elastic(1, lower));
  setup.blocks.push_back(elastic(2, upper));
  SupportGroup g;
  g.name = "bottom";
  for (int c = 0; c < 3; ++c) {
    Support s;
    s.axis = static_cast<Axis>(c);
    s.nodes = lower.layer(0);
    g.supports.push_back(s);
  }
  setup.supports.push_back(g);
  setup.sets.part_nodes[1] = lower.all();
  setup.sets.part_nodes[2] = upper.all();
  // Pressed down (g = 30) and pushed along x at 0.5 g > mu g: the interface slides.
  setup.body_loads.push_back(test::ramped_body_load(Axis::y, -30.0, 2, 0.0));
  setup.body_loads.push_back(test::ramped_body_load(Axis::x, 15.0, 2, 0.0));
  setup.controls.end_time = 1e9;  // the benchmark decides how many cycles

  std::vector<Index> slaves = upper.layer(0), masters = lower.layer(kLowerNy);
  std::sort(slaves.begin(), slaves.end());
  std::sort(masters.begin(), masters.end());
  const PenaltyPassOptions o;  // SLSFAC 0.1, the CLI's default
  setup.contacts.add(std::make_unique<SurfaceToSurfaceContact<ExponentialCoulomb>>(
      "type3",
      std::make_unique<PenaltyPass>(slaves, std::vector<Real>(slaves.size(), 0.0),
                                    face(lower, kLowerNy, true, kLowerNy - 1, 0, 1), std::make_unique<FclBroadPhase>(),
                                    o),
      std::make_unique<PenaltyPass>(masters, std::vector<Real>(masters.size(), 0.0), face(upper, 0, false, 0, 1, 2),
                                    std::make_unique<FclBroadPhase>(), o),
      ExponentialCoulomb{0.3, 0.3, 0.0}));
  auto sim = std::make_unique<Simulation>(std::move(setup));
  sim->initialize();
  return sim;
}

// Arg: threads. Fixed iterations: each repetition builds its own model (the upper block slides,
// so a reused one would drift towards the lower block's edge), runs kWarmUp cycles, then times
// state.iterations() cycles of Simulation::step().
constexpr int kWarmUp = 30;

void BM_TwoBlockFullStep(benchmark::State& state) {
  set_threads(static_cast<int>(state.range(0)));
  auto sim = make_two_block_model();
  for (int c = 0; c < kWarmUp; ++c) sim->step();
  const Real contact0 = sim->contact_seconds(), element0 = sim->element_seconds();
  const auto t0 = std::chrono::steady_clock::now();
  for (auto _ : state) sim->step();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double elements = static_cast<double>(sim->element_count());
  state.counters["elements"] = elements;
  state.counters["threads"] = static_cast<double>(state.range(0));
  state.counters["contact_share_pct"] = 100.0 * (sim->contact_seconds() - contact0) / wall;
  state.counters["element_share_pct"] = 100.0 * (sim->element_seconds() - element0) / wall;
  state.counters["friction_work"] = sim->contacts()[0].friction_work();
  state.counters["ns_per_element_cycle"] = benchmark::Counter(
      elements * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

}  // namespace

BENCHMARK(BM_TwoBlockFullStep)->Arg(1)->Arg(2)->Iterations(150)->Unit(benchmark::kMillisecond)->UseRealTime();
