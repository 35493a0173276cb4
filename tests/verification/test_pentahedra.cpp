// Verification of pentahedra (*ELEMENT_SOLID N1 N2 N3 N4 N5 N5 N6 N6) and pyramids (N1 N2 N3 N4
// N5 N5 N5 N5) in ELFORM 1 parts, run as hexahedra with the collapsed nodes (docs/solver.md,
// "Elements"): the first axial mode of a bar of pentahedra (straight and rotated) and of a bar
// of pyramids, read from decks, against the bar wave speed, with the energy balance; a block of hexahedra, pentahedra and
// pyramids under gravity on its support (reaction = weight); a block of pentahedra resting on a
// plate through a contact, on either side of the interface (interface force = weight).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>
#include <string>

#include <Eigen/Geometry>

#include "general_contact_models.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "test_support/bar_mode.hpp"
#include "test_support/collapsed_hex.hpp"

namespace slideline {
namespace {

using test_support::add_box;
using test_support::add_elastic_part;
using test_support::BoxIds;
using test_support::Frame;

constexpr Real kE = 1000.0, kRho = 2.0;

/// A bar along x of n cubic cells of side h (one through y and z), each cut into two pentahedra
/// (test_support::split_into_pentahedra) or, with `pyramids`, into six pyramids about a node at
/// its centre (test_support::split_into_pyramids), elastic with nu = 0, clamped at x = L, free at
/// x = 0, started in its first axial (quarter-wave) mode v = v0 cos(pi x / 2L) e_x; turned by R.
std::string penta_bar_deck(int n, Real h, Real v0, Real t_end, const Mat3& R = Mat3::Identity(), int elform = 1,
                           bool pyramids = false) {
  ::test_support::BarCells cells;
  cells.centres = pyramids;
  cells.elements = [pyramids](std::ostream& s, int& eid, const std::array<int, 8>& cell, int centre) {
    const auto write = [&](const std::array<int, 8>& e) {
      s << eid++ << ",1";
      for (int node : e) s << "," << node;
      s << "\n";
    };
    if (pyramids)
      for (const auto& y : ::test_support::split_into_pyramids(cell, centre)) write(y);
    else
      for (const auto& w : ::test_support::split_into_pentahedra(cell)) write(w);
  };
  return ::test_support::bar_deck(n, h, v0, t_end, R, elform, kRho, kE, cells);
}

using ::test_support::BarRun;

/// The bar's run (test_support/bar_mode.hpp), its deck named in error messages.
BarRun run_bar(const std::string& deck, const Mat3& R = Mat3::Identity()) {
  return ::test_support::run_bar(deck, "penta_bar.k", R);
}

}  // namespace

// L = 1 in 20 cells of 0.05 (40 pentahedra). The quarter-wave mode of a free-clamped bar has
// period 4 L / c, c = sqrt(E / rho): the free end is back at zero at t = 2 L / c. A pentahedron
// is exact for the linear axial field of each cell, and the cut puts equal lumped masses on the
// two faces of a cell (::test_support::split_into_pentahedra), so the bar is the hexahedron bar:
// discrete frequency (2 c / h) sin(k h / 2), 0.08% low at 20 cells; we allow 0.5%.
TEST(Pentahedra, BarOfPentahedraVibratesAtTheBarWaveSpeed) {
  const int n = 20;
  const Real h = 0.05, length = n * h, c = std::sqrt(kE / kRho);
  const Real expected = 2.0 * length / c;
  const BarRun straight = run_bar(penta_bar_deck(n, h, 0.01, 1.2 * expected));
  std::printf("pentahedron bar: half period %.6g (2 L / c = %.6g, ratio %.5f), energy error %.2e, %ld cycles\n",
              straight.half_period, expected, straight.half_period / expected, straight.balance, straight.cycles);
  RecordProperty("half_period_over_closed_form", std::to_string(straight.half_period / expected));
  ASSERT_GT(straight.half_period, 0.0);
  EXPECT_NEAR(straight.half_period / expected, 1.0, 0.005);
  EXPECT_LT(straight.balance, 1e-3);
}

// The bar of 120 pyramids (20 cells of 6 about a centre node, which carries half of each cell's
// lumped mass: rho V0 / 8 at each of a pyramid's four collapsed apex corners). The centre node
// adds a degree of freedom per cell; we allow 0.5% on the period, as for the pentahedra.
TEST(Pentahedra, BarOfPyramidsVibratesAtTheBarWaveSpeed) {
  const int n = 20;
  const Real h = 0.05, length = n * h, c = std::sqrt(kE / kRho);
  const Real expected = 2.0 * length / c;
  const BarRun r = run_bar(penta_bar_deck(n, h, 0.01, 1.2 * expected, Mat3::Identity(), 1, true));
  std::printf("pyramid bar: half period %.6g (2 L / c = %.6g, ratio %.5f), energy error %.2e, %ld cycles\n",
              r.half_period, expected, r.half_period / expected, r.balance, r.cycles);
  ASSERT_GT(r.half_period, 0.0);
  EXPECT_NEAR(r.half_period / expected, 1.0, 0.005);
  EXPECT_LT(r.balance, 1e-3);
}

// The same deck turned by a large rotation: the same physics to round-off (Release run only:
// the straight bar covers the code path).
TEST(Pentahedra, RotatedBarOfPentahedraMatchesTheStraightOne) {
  const int n = 20;
  const Real h = 0.05, expected = 2.0 * n * h / std::sqrt(kE / kRho);
  const BarRun straight = run_bar(penta_bar_deck(n, h, 0.01, 1.2 * expected));
  const Mat3 R = Eigen::AngleAxis<Real>(0.7, Vec3(0.3, 1.0, -0.6).normalized()).toRotationMatrix();
  const BarRun turned = run_bar(penta_bar_deck(n, h, 0.01, 1.2 * expected, R), R);
  EXPECT_NEAR(turned.half_period, straight.half_period, 1e-9 * expected);
  EXPECT_LT(turned.balance, 1e-3);
}

namespace {

constexpr Real kG = 10.0, kRamp = 0.1;

/// Replaces the hexahedra of `box` (the last elements of m.solids, added by add_box) by
/// pentahedra (cells with (i + j + k) % 3 == 1 when `mixed`, every cell otherwise) and pyramids
/// about a new centre node (cells with (i + j + k) % 3 == 2 when `mixed`).
void cut_cells(model::Model& m, const BoxIds& box, bool mixed) {
  const std::size_t cells = static_cast<std::size_t>(box.nx * box.ny * box.nz);
  std::vector<model::SolidElement> hexes(m.solids.end() - static_cast<std::ptrdiff_t>(cells), m.solids.end());
  m.solids.resize(m.solids.size() - cells);
  Id next_node = 1, next_elem = 1;
  for (const auto& nd : m.nodes) next_node = std::max(next_node, nd.id + 1);
  for (const auto& e : m.solids) next_elem = std::max(next_elem, e.id + 1);
  auto add = [&](const model::SolidElement& like, const std::array<Id, 8>& n) {
    model::SolidElement e = like;
    e.id = next_elem++;
    e.n = n;
    m.solids.push_back(e);
  };
  for (std::size_t c = 0; c < cells; ++c) {
    const int i = static_cast<int>(c) % box.nx, j = static_cast<int>(c) / box.nx % box.ny;
    const int k = static_cast<int>(c) / (box.nx * box.ny);
    const int kind = mixed ? (i + j + k) % 3 : 1;
    const model::SolidElement& h = hexes[c];
    if (kind == 1) {
      for (const auto& w : ::test_support::split_into_pentahedra(h.n)) add(h, w);
    } else if (kind == 2) {
      Vec3 centre = Vec3::Zero();
      for (Id id : h.n)
        for (const auto& nd : m.nodes)
          if (nd.id == id) centre += nd.x / 8.0;
      m.nodes.push_back({next_node, centre, 0, 0});
      for (const auto& y : ::test_support::split_into_pyramids(h.n, next_node)) add(h, y);
      ++next_node;
    } else {
      add(h, h.n);
    }
  }
}

/// Gravity g along -z of `frame` on the parts of part set `psid` (0: every part), ramped over
/// kRamp and held; mass-proportional damping alpha.
void add_gravity(model::Model& m, const Frame& frame, Id psid, Real alpha) {
  const Vec3 g = frame.map(Vec3(0.0, 0.0, -kG));
  m.curves.push_back({1, "ramp", 0, 1.0, 1.0, 0.0, 0.0, 0, {{0.0, 0.0}, {kRamp, 1.0}, {100.0, 1.0}}, {}});
  // *LOAD_BODY is a base acceleration: the force on a node is -m sf curve(t) along the axis.
  const Axis axes[3] = {Axis::x, Axis::y, Axis::z};
  for (int k = 0; k < 3; ++k) m.body_loads.push_back({axes[k], 1, -g[k], 0, 0, 0, 0, 0, {}});
  if (psid != 0) m.body_load_parts = model::LoadBodyParts{psid, {}};
  m.damping_global = model::DampingGlobal{0, alpha, {0, 0, 0, 0, 0, 0}, {}};
}

/// The nodes of the face k = const of a box.
std::vector<Id> face_k(const BoxIds& b, int k) {
  std::vector<Id> out;
  for (int j = 0; j <= b.ny; ++j)
    for (int i = 0; i <= b.nx; ++i) out.push_back(b.at(i, j, k));
  return out;
}

struct Settled {
  Vec3 reaction = Vec3::Zero();  ///< the support's reaction at the end
  Vec3 interface = Vec3::Zero();  ///< force on the block through the contact (zero without one)
  Real weight = 0.0;             ///< g times the loaded nodes' mass
  Real energy_error = 0.0;
  bool finite = true;
};

/// Runs `m` to its end; `block` the loaded nodes, `block_is_slave` which side of contact 0 the
/// block is on.
Settled run_settled(const model::Model& m, const std::vector<Id>& block, bool block_is_slave) {
  test_support::Run run(m);
  while (run.sim->step()) {
  }
  Settled r;
  for (Id id : block) r.weight += kG * run.mass(id);
  r.reaction = run.sim->supports().at(0).reaction;
  if (!run.sim->contacts().empty())
    r.interface = block_is_slave ? run.sim->contacts()[0].slave_force() : run.sim->contacts()[0].master_force();
  for (std::size_t i = 0; i < run.sim->nodes().ids.size(); ++i)
    r.finite = r.finite && run.sim->nodes().x.get(static_cast<Index>(i)).allFinite();
  r.energy_error = run.sim->energy_error_fraction();
  return r;
}

/// A 1 x 1 x 1 block of 2 x 2 x 2 cells (hexahedra, pentahedra and pyramids: cut_cells), E = 1e3,
/// rho = 1, nu = 0.3, held at its face z = 0, under gravity.
model::Model mixed_block(const Frame& frame, std::vector<Id>& nodes) {
  model::Model m;
  add_elastic_part(m, 1, 1.0, 1000.0, 0.3);
  const BoxIds b = add_box(m, 1, Vec3::Zero(), Vec3(1.0, 1.0, 1.0), {2, 2, 2}, frame);
  cut_cells(m, b, true);
  m.node_sets.push_back({1, "bottom", face_k(b, 0), {}});
  m.spcs.push_back({1, "bottom", 1, 0, {1, 1, 1, 0, 0, 0}, {}});
  // Critically damped near the block's first modes (tens of rad/s): settled well before the end.
  add_gravity(m, frame, 0, 60.0);
  m.termination.endtim = 1.0;
  nodes.clear();
  for (const auto& nd : m.nodes) nodes.push_back(nd.id);
  return m;
}

}  // namespace

// The support carries the block's weight, rho V g, straight and turned (a pyramid's apex is a
// node of its own, so every node of the model is loaded): the block is at rest at the end.
TEST(Pentahedra, MixedBlockUnderGravityLoadsItsSupportWithItsWeight) {
  for (const bool turned : {false, true}) {
    const Frame frame = turned ? test_support::oblique_frame() : Frame{};
    std::vector<Id> nodes;
    const Settled r = run_settled(mixed_block(frame, nodes), nodes, true);
    const Vec3 expected = frame.map(Vec3(0.0, 0.0, -1.0 * kG));  // rho V g along -z
    std::printf("mixed block%s: weight %.9g, reaction (%.6g %.6g %.6g), energy error %.2e\n", turned ? " (turned)" : "",
                r.weight, r.reaction[0], r.reaction[1], r.reaction[2], r.energy_error);
    EXPECT_NEAR(r.weight, kG, 1e-12);
    EXPECT_LT((r.reaction - expected).norm(), 1e-4 * kG) << (turned ? "turned" : "straight");
    EXPECT_LT(r.energy_error, 1e-3);
  }
}

namespace {

struct RestingCase {
  test_support::ContactChoice contact;
  bool block_is_slave = true;
  std::string name() const { return contact.name() + (block_is_slave ? "_block_slave" : "_block_master"); }
};

/// A 0.8 x 0.8 x 0.4 block of 2 x 2 x 1 cells, each cut into two pentahedra (their triangles on
/// the faces z = 0 and z = 0.4), resting on a fixed 1.5 x 1.5 x 0.25 plate of 3 x 3 x 1
/// hexahedra (no block node on a plate node or edge), under gravity on the block only; E = 1e4,
/// rho = 1, Coulomb friction 0.3.
model::Model resting_block(const RestingCase& rc, std::vector<Id>& block_nodes) {
  model::Model m;
  add_elastic_part(m, 1, 1.0, 1e4, 0.3);
  add_elastic_part(m, 2, 1.0, 1e4, 0.3);
  const BoxIds block = add_box(m, 1, Vec3(0.1, 0.15, 0.0), Vec3(0.8, 0.8, 0.4), {2, 2, 1}, Frame{});
  cut_cells(m, block, false);
  const BoxIds plate = add_box(m, 2, Vec3(-0.25, -0.25, -0.25), Vec3(1.5, 1.5, 0.25), {3, 3, 1}, Frame{});
  m.node_sets.push_back({1, "block", block.node, {}});
  m.node_sets.push_back({2, "plate", plate.node, {}});
  m.node_sets.push_back({3, "plate_nodes_as_slaves", plate.node, {}});
  m.part_sets.push_back({2, "pair", {1, 2}, {}});
  m.part_sets.push_back({4, "loaded", {1}, {}});
  m.spcs.push_back({1, "plate_fixed", 2, 0, {1, 1, 1, 0, 0, 0}, {}});
  const Real mu = 0.3;  // friction keeps the block from drifting on the mesh's asymmetry
  m.contacts.push_back(rc.block_is_slave ? test_support::contact_card(rc.contact, 1, 2, 1, 2, mu)
                                         : test_support::contact_card(rc.contact, 2, 1, 3, 2, mu));
  add_gravity(m, Frame{}, 4, 100.0);
  m.termination.endtim = 0.5;
  block_nodes = block.node;
  return m;
}

}  // namespace

class RestingPentahedra : public ::testing::TestWithParam<RestingCase> {};

// The block's triangles and quadrilaterals (its collapsed faces dropped) make a contact surface
// (slave and master segments of Type 3 and of the automatic card);
// at rest the interface carries the block's weight to the plate and the plate's support: force on
// the block + W e_z, support reaction - W e_z, within 1e-3 W (the residual motion under the
// damping), every position finite.
TEST_P(RestingPentahedra, InterfaceCarriesTheBlocksWeight) {
  const RestingCase rc = GetParam();
  std::vector<Id> nodes;
  const Settled r = run_settled(resting_block(rc, nodes), nodes, rc.block_is_slave);
  std::printf("%-34s weight %.6g interface (%.6g %.6g %.6g) reaction z %.6g energy error %.2e\n", rc.name().c_str(),
              r.weight, r.interface[0], r.interface[1], r.interface[2], r.reaction[2], r.energy_error);
  ASSERT_TRUE(r.finite);
  EXPECT_NEAR(r.weight, kG * 0.8 * 0.8 * 0.4, 1e-12);
  EXPECT_LT((r.interface - Vec3(0.0, 0.0, r.weight)).norm(), 1e-3 * r.weight);
  EXPECT_LT((r.reaction - Vec3(0.0, 0.0, -r.weight)).norm(), 1e-3 * r.weight);
}

std::vector<RestingCase> resting_cases() {
  using T = model::ContactType;
  std::vector<RestingCase> out;
  // Type 3 is two-pass (either side's nodes on the other's segments): the block's triangles are
  // slave and master segments whichever side it is on.
  for (const bool slave : {true, false}) out.push_back({{T::surface_to_surface, model::Enforcement::penalty}, slave});
  out.push_back({{T::automatic, model::Enforcement::penalty, model::ContactForm::automatic_surface_to_surface}, true});
  return out;
}

INSTANTIATE_TEST_SUITE_P(Contacts, RestingPentahedra, ::testing::ValuesIn(resting_cases()),
                         [](const auto& info) { return info.param.name(); });

}  // namespace slideline
