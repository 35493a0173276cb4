// Type 12 (automatic single surface, penalty, friction): cost per surface node-cycle of the contact
// update (cadence check, search amortised, local tracking, gap, normal and friction forces,
// scatter) when every surface node is a slave and every segment a master.
//
// Two blocks of n x 1 x n unit hexahedra, the upper one (n - 1 wide) resting on the lower one and
// pressed 1e-3 into it, sliding back and forth in x by 0.01 per cycle with a direction change every
// 80 cycles (as bm_contact's BM_PenaltyPass: the search re-runs when a node has moved half the
// search margin, so the timed cycles include searches). Built through the deck model and build_setup, as a user's deck would be.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <vector>

#include "slideline/solver/build.hpp"
#include "test_support/mesh_fixtures.hpp"

using namespace slideline;

namespace {

/// Which card joins the two blocks (the last two frictionless: SOFT = 2 has no friction yet).
enum class Card { single_surface, automatic_surface_to_surface, type3, automatic_soft0, automatic_soft2 };

/// Lower block n x 1 x n (part 1) and upper block (n-1) x 1 x (n-1) on top of it (part 2), one
/// contact with the spec's friction: *CONTACT_AUTOMATIC_SINGLE_SURFACE over both parts, or
/// *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE / Type 3 *CONTACT_SURFACE_TO_SURFACE with the upper block
/// the slave side and the lower one the master side.
model::Model two_block_automatic(int n, Card card = Card::single_surface) {
  model::Model m = test_support::hex_grid_model(n, 1, n, 1);
  const Id first = static_cast<Id>(m.nodes.size()) + 1;
  const int u = n - 1;
  const auto id = [&](int i, int j, int k) { return first + i + (u + 1) * (j + 2 * k); };
  for (int k = 0; k <= u; ++k)
    for (int j = 0; j <= 1; ++j)
      for (int i = 0; i <= u; ++i) m.nodes.push_back({id(i, j, k), Vec3(0.37 + i, 1.0 + j, 0.41 + k), 0, 0});
  Id eid = static_cast<Id>(m.solids.size()) + 1;
  for (int k = 0; k < u; ++k)
    for (int i = 0; i < u; ++i)
      m.solids.push_back({eid++, 2, {id(i, 0, k), id(i + 1, 0, k), id(i + 1, 1, k), id(i, 1, k), id(i, 0, k + 1),
                                     id(i + 1, 0, k + 1), id(i + 1, 1, k + 1), id(i, 1, k + 1)}});
  m.parts.push_back({2, "upper", 1, 1, 0, 0, {}});
  m.part_sets.push_back({1, "both", {1, 2}, {}});
  model::Contact c;
  c.keyword = "*CONTACT_AUTOMATIC_SINGLE_SURFACE";
  c.type = model::ContactType::automatic;
  c.ssid = 1;
  c.sstyp = 2;
  if (card != Card::single_surface) {
    const bool automatic = card != Card::type3;
    c.keyword = automatic ? "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE" : "*CONTACT_SURFACE_TO_SURFACE";
    c.type = automatic ? model::ContactType::automatic : model::ContactType::surface_to_surface;
    c.form = automatic ? model::ContactForm::automatic_surface_to_surface : model::ContactForm::dyna3d;
    c.ssid = 2;
    c.sstyp = 3;
    c.msid = 1;
    c.mstyp = 3;
  }
  if (card == Card::automatic_soft0 || card == Card::automatic_soft2) {
    c.soft = card == Card::automatic_soft2 ? 2 : 0;
  } else {
    c.fs = 0.3;
    c.fd = 0.25;
    c.dc = 2.0;
  }
  m.contacts.push_back(c);
  return m;
}

/// The timed contact phase of `card` on the two blocks of size n (see the file comment).
void run_contact_cycles(benchmark::State& state, int n, Card card) {
  // The deck's setup, with the two things the contact update needs from Simulation::initialize():
  // the lumped masses and the initialised interfaces. The timed loop is the contact phase alone.
  SimulationSetup setup = build_setup(two_block_automatic(n, card));
  NodalFields& nodes = setup.nodes;
  for (auto& b : setup.blocks) b->initialize(nodes);
  const std::vector<std::uint8_t> rigid(nodes.size(), 0);
  ContactManager& contacts = setup.contacts;
  contacts.initialize(ContactContext{nodes, setup.blocks, &setup.sets, rigid});
  contacts.resolve_initial_penetrations(nodes);
  const Index first_upper = static_cast<Index>((n + 1) * 2 * (n + 1));
  const Index count = static_cast<Index>(nodes.size());
  for (Index i = first_upper; i < count; ++i) nodes.x.y[i] -= 1e-3;
  StepTimes t;
  t.dt_prev = t.dt_avg = t.dt_next = 1e-3;
  t.dt_initial = 1e-3;  // SOFT = 2 sizes its springs by it; the other cards do not read it
  long step = 0;
  for (auto _ : state) {
    const Real dx = (step++ / 80) % 2 != 0 ? -0.01 : 0.01;
    for (Index i = first_upper; i < count; ++i) {
      nodes.x.x[i] += dx;
      nodes.v.x[i] = dx / t.dt_prev;
    }
    nodes.f_contact.fill(0.0);
    nodes.m_contact.fill(0.0);
    const Real dt = contacts.apply_forces(nodes, t, ContactForceView{nodes.f_contact, nodes.m_contact});
    benchmark::DoNotOptimize(dt);
  }
  // Every node of an n x 1 x n block is on its surface: all nodes are slaves.
  state.counters["surface_nodes"] = static_cast<double>(count);
  state.counters["ns_per_node_cycle"] =
      benchmark::Counter(static_cast<double>(count) * 1e-9,
                         benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  // Surface segments of the two blocks: 2 n^2 + 4 n and 2 (n-1)^2 + 4 (n-1).
  const double segments = 2.0 * n * n + 4.0 * n + 2.0 * (n - 1) * (n - 1) + 4.0 * (n - 1);
  state.counters["ns_per_segment_cycle"] = benchmark::Counter(
      segments * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_AutomaticContactCycle(benchmark::State& state) {
  run_contact_cycles(state, static_cast<int>(state.range(0)), Card::single_surface);
}

/// *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE (arg 1 = 1) against Type 3's two passes (arg 1 = 2) and
/// the single surface (0) on the same blocks: ns per surface node-cycle (every surface node is a
/// slave of one of Type 3's passes, and of the automatic pass).
void BM_AutomaticSurfaceVsType3(benchmark::State& state) {
  run_contact_cycles(state, static_cast<int>(state.range(0)), static_cast<Card>(state.range(1)));
}

/// *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE frictionless with SOFT = 0 (arg 1 = 3) against SOFT = 2,
/// segment-based (arg 1 = 4): ns per surface segment-cycle on the same blocks.
void BM_SegmentBasedVsSoftZero(benchmark::State& state) {
  run_contact_cycles(state, static_cast<int>(state.range(0)), static_cast<Card>(state.range(1)));
}

}  // namespace

// Surface segments: about 4 n^2 (top and bottom faces of both blocks) + the sides: 10^3 .. 10^5.
BENCHMARK(BM_AutomaticContactCycle)->Arg(16)->Arg(50)->Arg(158)->Iterations(160)->Unit(benchmark::kMillisecond);
// 1.2e3, 1.05e4 and 1.0e5 segments (n = 16, 50, 158).
BENCHMARK(BM_AutomaticSurfaceVsType3)
    ->ArgsProduct({{16, 50, 158}, {0, 1, 2}})
    ->Iterations(160)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SegmentBasedVsSoftZero)->ArgsProduct({{16, 50}, {3, 4}})->Iterations(160)->Unit(benchmark::kMillisecond);
