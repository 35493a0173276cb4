// SOFT = 2 (segment-based contact, SegmentContact) against Type 3 (*CONTACT_SURFACE_TO_SURFACE,
// two penalty passes): cost per contact node-cycle of the contact update, on solids and on
// shells, at about 1e3, 1e4 and 1e5 segments; SOFT = 2 with a search every cycle (BSORT 1) and
// every BSORT = 0 (the default, 10) cycles.
//
// Solids: two blocks of n x 1 x n and (n-1) x 1 x (n-1) unit hexahedra, the upper one on the
// lower one, pressed 1e-3 into it after initialize (the geometry of bm_contact_automatic; SOFT = 2
// would keep a penetration at t = 0 as its baseline). Shells: two plates of n x n and
// (n-1) x (n-1) unit shells, t = 0.1, their offsets touching at t = 0 (Type 3: their mid-surfaces,
// it takes no shell thickness by default), then pressed 1e-3. The upper body slides 0.01 per
// cycle in x with nodal speed 0.01 / dt and
// turns back every 80 cycles (bm_contact's motion: the timed cycles include the searches both
// cadences trigger); dt = 1e-3. Built through the deck model and build_setup, as a user's deck would
// be. One benchmark iteration is kCycles contact updates. `ns_per_node_cycle`: CPU time per surface
// node (every node of both bodies is a surface node, and a slave of one of Type 3's two passes).
#include <benchmark/benchmark.h>

#include <array>
#include <cstdint>
#include <vector>

#include "slideline/solver/build.hpp"
#include "test_support/mesh_fixtures.hpp"

using namespace slideline;

namespace {

constexpr int kCycles = 5;  // contact updates per benchmark iteration

enum class Body { blocks = 0, plates = 1 };
enum class Card { type3 = 0, soft2_every_cycle = 1, soft2_default = 2 };

void add_plate(model::Model& m, Id pid, int n, Real x0, Real y, Real z0, bool normal_down) {
  m.materials.push_back(model::MatElastic{pid, 1.0, 1000.0, 0.3, "", {}});
  model::SectionShell sec;
  sec.secid = pid;
  sec.t = {0.1, 0.1, 0.1, 0.1};
  m.shell_sections.push_back(sec);
  m.parts.push_back({pid, "plate", pid, pid, 0, 0, {}});
  const Id first = static_cast<Id>(m.nodes.size()) + 1;
  const auto id = [&](int i, int k) { return first + i + (n + 1) * k; };
  for (int k = 0; k <= n; ++k)
    for (int i = 0; i <= n; ++i) m.nodes.push_back({id(i, k), Vec3(x0 + i, y, z0 + k), 0, 0});
  Id eid = static_cast<Id>(m.shells.size()) + 1;
  for (int k = 0; k < n; ++k)
    for (int i = 0; i < n; ++i) {
      const Id a = id(i, k), b = id(i + 1, k), c = id(i + 1, k + 1), d = id(i, k + 1);
      m.shells.push_back({eid++, pid, normal_down ? std::array<Id, 4>{a, b, c, d} : std::array<Id, 4>{a, d, c, b}, {}});
    }
}

model::Model two_bodies(int n, Body body, Card card) {
  model::Model m;
  if (body == Body::blocks) {
    m = test_support::hex_grid_model(n, 1, n, 1);
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
  } else {
    add_plate(m, 1, n, 0.0, 0.0, 0.0, false);
    // SOFT = 2 offsets the shells by half their thickness; Type 3 here takes no thickness
    // (*CONTROL_CONTACT SHLTHK 0): its mid-surfaces meet.
    add_plate(m, 2, n - 1, 0.37, card == Card::type3 ? 0.0 : 0.1, 0.41, true);
    m.termination.endtim = 0.01;
  }
  model::Contact c;
  const bool soft2 = card != Card::type3;
  c.keyword = soft2 ? "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE" : "*CONTACT_SURFACE_TO_SURFACE";
  c.type = soft2 ? model::ContactType::automatic : model::ContactType::surface_to_surface;
  c.form = soft2 ? model::ContactForm::automatic_surface_to_surface : model::ContactForm::dyna3d;
  c.ssid = 2;
  c.sstyp = 3;
  c.msid = 1;
  c.mstyp = 3;
  c.soft = soft2 ? 2 : 0;
  c.bsort = card == Card::soft2_every_cycle ? 1 : 0;
  m.contacts.push_back(c);
  return m;
}

void BM_SegmentBasedVsType3(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto body = static_cast<Body>(state.range(1));
  const auto card = static_cast<Card>(state.range(2));
  SimulationSetup setup = build_setup(two_bodies(n, body, card));
  NodalFields& nodes = setup.nodes;
  for (auto& b : setup.blocks) b->initialize(nodes);
  const std::vector<std::uint8_t> rigid(nodes.size(), 0);
  ContactManager& contacts = setup.contacts;
  contacts.initialize(ContactContext{nodes, setup.blocks, &setup.sets, rigid});
  contacts.resolve_initial_penetrations(nodes);
  const Index first_upper =
      static_cast<Index>(body == Body::blocks ? (n + 1) * 2 * (n + 1) : (n + 1) * (n + 1));
  const Index count = static_cast<Index>(nodes.size());
  for (Index i = first_upper; i < count; ++i) nodes.x.y[i] -= 1e-3;
  StepTimes t;
  t.dt_prev = t.dt_avg = t.dt_next = 1e-3;
  t.dt_initial = 1e-3;
  long step = 0;
  for (auto _ : state) {
    for (int c = 0; c < kCycles; ++c) {
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
  }
  Real load = 0.0;
  for (Index i = first_upper; i < count; ++i) load += nodes.f_contact.y[i];
  state.counters["upper_force_y"] = load;  // > 0: the bodies are in contact
  state.counters["surface_nodes"] = static_cast<double>(count);
  state.counters["ns_per_node_cycle"] =
      benchmark::Counter(static_cast<double>(count) * kCycles * 1e-9,
                         benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

}  // namespace

// Segments (two sides): blocks 2 n^2 + 4 n + 2 (n-1)^2 + 4 (n-1), plates n^2 + (n-1)^2.
// Blocks n = 16, 50, 158: 1.1e3, 1.0e4, 1.0e5; plates n = 24, 71, 224: 1.1e3, 9.9e3, 1.0e5.
// Iterations: 16 x 5 = 80 cycles (one sliding period), 8 at 1e5.
BENCHMARK(BM_SegmentBasedVsType3)
    ->ArgsProduct({{16, 50}, {0}, {0, 1, 2}})
    ->ArgsProduct({{24, 71}, {1}, {0, 1, 2}})
    ->Iterations(16)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SegmentBasedVsType3)
    ->ArgsProduct({{158}, {0}, {0, 1, 2}})
    ->ArgsProduct({{224}, {1}, {0, 1, 2}})
    ->Iterations(8)
    ->Unit(benchmark::kMillisecond);
