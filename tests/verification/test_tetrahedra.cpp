// Verification of the one-point tetrahedron (*SECTION_SOLID ELFORM 10, tetrahedra written as
// degenerate *ELEMENT_SOLID N1 N2 N3 N4 N4 N4 N4 N4), read from a deck: the first axial mode of a
// bar of tetrahedra against the bar wave speed sqrt(E / rho), in a straight and a rotated copy,
// with the energy balance.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>
#include <string>

#include <Eigen/Geometry>

#include "slideline/io/keyword_reader.hpp"
#include "test_support/bar_mode.hpp"
#include "slideline/solver/build.hpp"
#include "test_support/kuhn_tets.hpp"

namespace slideline {
namespace {

constexpr Real kE = 1000.0, kRho = 2.0;

/// A bar along x of n cubic cells of side h (one through y and z), six tetrahedra per cell,
/// elastic with nu = 0 (so the bar speed sqrt(E / rho) is also the dilatational speed), clamped at
/// x = L, free at x = 0, started in its first axial (quarter-wave) mode: v = v0 cos(pi x / 2L) e_x.
/// The whole deck may be turned by R. `elform` is the section's form (10 for the tetrahedra).
std::string tet_bar_deck(int n, Real h, Real v0, Real t_end, const Mat3& R = Mat3::Identity(), int elform = 10) {
  test_support::BarCells cells;
  cells.elements = [](std::ostream& s, int& eid, const std::array<int, 8>& corner, int) {
    for (const auto& t : test_support::kuhn_tets()) {
      int nd[4];  // corner (dx, dy, dz) of the cell is node corner[0] + 4 dx + dy + 2 dz
      for (int k = 0; k < 4; ++k) nd[k] = corner[0] + 4 * (t[k] & 1) + ((t[k] >> 1) & 3);
      s << eid++ << ",1," << nd[0] << "," << nd[1] << "," << nd[2];
      for (int k = 3; k < 8; ++k) s << "," << nd[3];
      s << "\n";
    }
  };
  return test_support::bar_deck(n, h, v0, t_end, R, elform, kRho, kE, cells);
}

using test_support::BarRun;

/// The bar's run (test_support/bar_mode.hpp), its deck named in error messages.
BarRun run_bar(const std::string& deck, const Mat3& R = Mat3::Identity()) {
  return test_support::run_bar(deck, "tet_bar.k", R);
}

}  // namespace

// L = 1 in 20 cells of 0.05 (120 tetrahedra). The quarter-wave mode of a free-clamped bar has
// period 4 L / c, c = sqrt(E / rho): the free end's displacement v0 / w sin(w t) is back at zero at
// t = 2 L / c. A bar of constant-strain elements with lumped mass has the discrete frequency
// (2 c / h) sin(k h / 2), k = pi / 2L: 0.08% low at 20 cells (the central-difference step at
// 0.9 of the stable one lowers the period by a similar amount); we allow 0.5%.
TEST(Tetrahedra, BarOfTetrahedraVibratesAtTheBarWaveSpeed) {
  const int n = 20;
  const Real h = 0.05, length = n * h, c = std::sqrt(kE / kRho);
  const Real expected = 2.0 * length / c;
  const BarRun straight = run_bar(tet_bar_deck(n, h, 0.01, 1.2 * expected));
  std::printf("tet bar: half period %.6g (2 L / c = %.6g, ratio %.5f), energy error %.2e, %ld cycles\n",
              straight.half_period, expected, straight.half_period / expected, straight.balance, straight.cycles);
  RecordProperty("half_period_over_closed_form", std::to_string(straight.half_period / expected));
  ASSERT_GT(straight.half_period, 0.0);
  EXPECT_NEAR(straight.half_period / expected, 1.0, 0.005);
  EXPECT_LT(straight.balance, 1e-3);
  // The same deck turned by a large rotation: the same physics to round-off.
  const Mat3 R = Eigen::AngleAxis<Real>(0.7, Vec3(0.3, 1.0, -0.6).normalized()).toRotationMatrix();
  const BarRun turned = run_bar(tet_bar_deck(n, h, 0.01, 1.2 * expected, R), R);
  EXPECT_NEAR(turned.half_period, straight.half_period, 1e-9 * expected);
  EXPECT_LT(turned.balance, 1e-3);
}

// tests/data/decks/reader/tet_mesh.k, a pre-processor's deck: a 6 x 6 x 6 cube of 1080 tetrahedra
// with N5-N8 blank, under gravity, held at four nodes. With ELFORM 1 it is refused
// (ValidateModel.TetrahedralMeshIsOneLineNamingTheElementKind); with ELFORM 10 it runs (to 0.2,
// 140 cycles, as it hangs from its four held nodes): its mass is rho V = 0.01 x 216 and the energy
// balances.
TEST(Tetrahedra, PreprocessorTetMeshRunsWithElform10) {
  model::Model m = read_keyword_file(std::string(SLIDELINE_SOURCE_DIR) + "/tests/data/decks/reader/tet_mesh.k");
  ASSERT_EQ(m.solid_sections.size(), 1u);
  m.solid_sections[0].elform = 10;
  m.termination.endtim = 0.2;  // the deck's 0.01 is 7 cycles
  auto sim = build_simulation(m);
  sim->initialize();
  ASSERT_EQ(sim->blocks().size(), 1u);
  EXPECT_EQ(sim->blocks()[0]->kind(), "tet4");
  EXPECT_EQ(sim->blocks()[0]->element_count(), 1080);
  Real mass = 0.0;
  for (Real mi : sim->nodes().mass) mass += mi;
  EXPECT_NEAR(mass, 0.01 * 216.0, 1e-12);
  while (sim->step()) {
  }
  const auto& e = sim->energy();
  std::printf("tet_mesh.k with ELFORM 10: %ld cycles, kinetic %.4g, internal %.4g, external work %.4g, balance %.2e\n",
              sim->cycle(), e.kinetic, e.internal, e.external, e.balance_error());
  EXPECT_GT(e.external, 0.0);
  EXPECT_LT(std::abs(e.balance_error()), 1e-3 * e.external);
}

// A tetrahedron in an ELFORM 1 part and a hexahedron in an ELFORM 10 part are both refused,
// naming the element; another form is refused naming the field.
TEST(Tetrahedra, WrongShapeForTheFormIsRefusedNamingTheElement) {
  try {
    build_simulation(read_keyword_string(tet_bar_deck(2, 0.5, 0.0, 1.0, Mat3::Identity(), 1), "tets_as_hex.k"));
    FAIL() << "tetrahedra in an ELFORM 1 part were accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("use ELFORM 10"), std::string::npos) << e.what();
  }
  try {
    model::Model m = read_keyword_string(tet_bar_deck(2, 0.5, 0.0, 1.0), "hex_in_tets.k");
    m.solids[4].n = {1, 5, 7, 3, 2, 6, 8, 4};  // eight distinct nodes in the ELFORM 10 part
    build_simulation(m);
    FAIL() << "a hexahedron in an ELFORM 10 part was accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("*ELEMENT_SOLID 5 is in a part of *SECTION_SOLID ELFORM 10 but is not a "
                                         "tetrahedron"),
              std::string::npos)
        << e.what();
  }
  try {
    build_simulation(read_keyword_string(tet_bar_deck(2, 0.5, 0.0, 1.0, Mat3::Identity(), 3), "form3.k"));
    FAIL() << "ELFORM 3 was accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("field ELFORM of *SECTION_SOLID: 3"), std::string::npos) << e.what();
  }
}

}  // namespace slideline
