// *NODE TC/RC constraint codes: a plate held on one edge by TC codes is the same plate held by
// *BOUNDARY_SPC_NODE, bit for bit, and both give the static bar answer; the same in a copy of the
// deck rotated 90 degrees about y (where the codes name the rotated axes).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "slideline/io/keyword_reader.hpp"
#include "slideline/solver/build.hpp"
#include "slideline/solver/simulation.hpp"

using namespace slideline;

namespace {

constexpr Real kF = 0.01;  // force per unit of the loaded edge's nodal weights
enum class Hold { spc, codes };

/// A 3 x 3 shell plate, 1 x 1 (t = 0.1, E = 1000, nu = 0.1), node id 1 + i + 4k at (i/3, 0, k/3)
/// (rotated: x -> -z, z -> x, i.e. 90 degrees about y). The edge x = 0 (nodes 1, 5, 9, 13) is held
/// in x and y (node 1 also in z, which takes out the rigid motion); the edge x = 1 carries the
/// consistent nodal loads of a uniform traction 3F along +x, ramped in 0.2 and then held; heavy
/// mass damping brings it to rest by t = 0.5.
std::string plate_deck(Hold hold, bool rotated) {
  std::string d = "*KEYWORD\n*CONTROL_TERMINATION\n0.5\n*DAMPING_GLOBAL\n0,300\n";
  d += "*SECTION_SHELL\n1,2,0.8333333333333334,5,1\n0.1,0.1,0.1,0.1\n*MAT_ELASTIC\n1,0.1,1000,0.1\n";
  d += "*PART\nplate\n1,1,1\n*DEFINE_CURVE\n2\n0,0\n0.2,1\n10,1\n";
  // The held components: x and y (TC 4); rotated, the plate's x is the global -z: y and z (TC 5).
  const int edge_code = rotated ? 5 : 4;
  d += "*NODE\n";
  for (int k = 0; k <= 3; ++k)
    for (int i = 0; i <= 3; ++i) {
      const Id id = 1 + i + 4 * k;
      const Real x = i / 3.0, z = k / 3.0;
      const int tc = hold == Hold::codes && i == 0 ? (id == 1 ? 7 : edge_code) : 0;
      char line[128];
      std::snprintf(line, sizeof line, "%d,%.17g,0,%.17g,%d,0\n", static_cast<int>(id), rotated ? z : x,
                    rotated ? -x : z, tc);
      d += line;
    }
  d += "*ELEMENT_SHELL\n";
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 3; ++i) {
      const Id a = 1 + i + 4 * k;
      d += std::to_string(1 + i + 3 * k) + ",1," + std::to_string(a) + "," + std::to_string(a + 1) + "," +
           std::to_string(a + 5) + "," + std::to_string(a + 4) + "\n";
    }
  if (hold == Hold::spc)
    for (Id nid : {1, 5, 9, 13}) {
      const bool z_held = nid == 1 || rotated;   // rotated: the plate's x is global z
      const bool x_held = nid == 1 || !rotated;
      d += "*BOUNDARY_SPC_NODE\n" + std::to_string(nid) + ",0," + (x_held ? "1" : "0") + ",1," +
           (z_held ? "1" : "0") + "\n";
    }
  const int dof = rotated ? 3 : 1;
  const Real sign = rotated ? -1.0 : 1.0;  // +x of the plate is -z rotated
  d += "*LOAD_NODE_POINT\n";
  for (Id nid : {4, 16}) d += std::to_string(nid) + "," + std::to_string(dof) + ",2," + std::to_string(sign * 0.5 * kF) + "\n";
  for (Id nid : {8, 12}) d += std::to_string(nid) + "," + std::to_string(dof) + ",2," + std::to_string(sign * kF) + "\n";
  return d + "*END\n";
}

std::unique_ptr<Simulation> run_plate(Hold hold, bool rotated) {
  const auto m = read_keyword_string(plate_deck(hold, rotated), "plate.k");
  auto sim = build_simulation(m);
  sim->run({});
  return sim;
}

Vec3 total_reaction(const Simulation& s) {
  Vec3 r = Vec3::Zero();
  for (const auto& g : s.supports()) r += g.reaction;
  return r;
}

void expect_static_bar(const Simulation& s, bool rotated) {
  const int axis = rotated ? 2 : 0;
  const Real sign = rotated ? -1.0 : 1.0;
  EXPECT_NEAR(total_reaction(s)[axis], sign * 3.0 * kF, 1e-5 * kF);
  // The loaded edge moves 3F L / (E A), A = width x thickness (its mean: the default viscous
  // hourglass control leaves a zero-energy pattern along the edge that carries no stress).
  const Real expected = 3.0 * kF * 1.0 / (1000.0 * (1.0 * 0.1));
  Real mean = 0.0;
  for (Index i : {3, 7, 11, 15}) mean += 0.25 * sign * s.nodes().displacement(i)[axis];
  EXPECT_NEAR(mean, expected, 1e-3 * expected);
}

TEST(NodeConstraintCodes, HoldAPlateAsBoundarySpcNodeDoesBitForBit) {
  for (bool rotated : {false, true}) {
    SCOPED_TRACE(rotated ? "rotated 90 degrees about y" : "as built");
    const auto spc = run_plate(Hold::spc, rotated);
    const auto codes = run_plate(Hold::codes, rotated);
    ASSERT_EQ(spc->cycle(), codes->cycle());
    for (Index i = 0; i < 16; ++i)
      for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(codes->nodes().x[c][i], spc->nodes().x[c][i]) << "node " << i + 1 << " component " << c;
        EXPECT_EQ(codes->nodes().v[c][i], spc->nodes().v[c][i]) << "node " << i + 1 << " component " << c;
      }
    // One support group per pair of codes: node 1 (TC 7) and the rest of the edge.
    ASSERT_EQ(codes->supports().size(), 2u);
    EXPECT_EQ(codes->supports()[0].name, rotated ? "node_tc5_rc0" : "node_tc4_rc0");
    EXPECT_EQ(codes->supports()[1].name, "node_tc7_rc0");
    const Vec3 r_spc = total_reaction(*spc), r_codes = total_reaction(*codes);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(r_codes[c], r_spc[c], 1e-12 * kF);
    expect_static_bar(*codes, rotated);
    expect_static_bar(*spc, rotated);
  }
}

TEST(NodeConstraintCodes, BadCodeIsAnErrorNamingTheNodeAndField) {
  try {
    std::string deck = plate_deck(Hold::codes, false);
    const std::string held = "\n1,0,0,0,7,0\n";
    ASSERT_NE(deck.find(held), std::string::npos);
    deck.replace(deck.find(held), held.size(), "\n1,0,0,0,8,0\n");
    build_simulation(read_keyword_string(deck, "p.k"));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("*NODE 1: field TC must be 0-7"), std::string::npos) << e.what();
  }
}

TEST(NodeConstraintCodes, CodesOnARigidPartAreRefusedNamingTheNode) {
  std::string deck = plate_deck(Hold::codes, false);
  const std::string elastic = "*MAT_ELASTIC\n1,0.1,1000,0.1\n";
  ASSERT_NE(deck.find(elastic), std::string::npos);
  deck.replace(deck.find(elastic), elastic.size(), "*MAT_RIGID\n1,0.1,1000,0.1\n");
  try {
    build_simulation(read_keyword_string(deck, "p.k"));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("*NODE 1: field TC/RC constrains node 1 of rigid part 1"), std::string::npos)
        << e.what();
  }
}

}  // namespace
