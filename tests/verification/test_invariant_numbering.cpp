// Invariant node numbering (*CONTROL_ACCURACY INN; docs/solver.md, "Invariant node numbering").
// The same model with every element's nodes listed from another corner must give the same motion:
// the numbering is a bookkeeping choice, not physics. (1) A distorted 2 x 2 mesh of Belytschko-Tsay
// shells (isotropic, elastic) clamped at x = 0 and sheared and bent by the edge x = 2 to 25 % of
// its length: with INN = 2 each element's co-rotational frame comes from the lines joining
// opposite mid-sides, turns by exactly 90 degrees with the renumbering 1234 -> 2341, and the two
// runs agree to round-off; with INN = 1 (e1 along side 1-2, LS-DYNA's default) the frame follows
// a different material line in each run and the answers differ. Triangles likewise, with a frame
// carried by the polar rotation of their in-plane deformation. (2) The same for a distorted pair
// of one-point hexahedra (bottom 1234 -> 2341, top 5678 -> 6785): the solid kernels have no element
// frame and every solid law is isotropic, so they agree to round-off with INN = 1 already, which
// is why INN = 3 (solids) asks nothing more of them.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "slideline/core/error.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/solver/build.hpp"
#include "slideline/solver/simulation.hpp"

namespace slideline {
namespace {

/// The node ids of a quadrilateral from corner `shift` on (same orientation).
std::array<int, 4> rotated(std::array<int, 4> q, int shift) {
  std::rotate(q.begin(), q.begin() + shift, q.end());
  return q;
}

/// Nodes 1-9 on a distorted 3 x 3 grid over [0, 2] x [0, 1]; elements 1-4 listed from corner
/// `shift` (element k from corner (shift + k) mod 4 when `mixed`); with `triangles` the fourth
/// quadrilateral is split into triangles 4 and 5 (N3 = N4), listed from corner shift mod 3.
std::string shell_deck(int inn, int shift, bool mixed, bool triangles = false) {
  std::ostringstream o;
  o.precision(17);
  o << "*KEYWORD\n*CONTROL_TERMINATION\n0.05\n*CONTROL_ACCURACY\n0," << inn
    << "\n*SECTION_SHELL\n1,2,1.0,3\n0.05,0.05,0.05,0.05\n*MAT_ELASTIC\n1,1.0e-3,1000.0,0.3\n"
    << "*PART\nplate\n1,1,1\n*NODE\n";
  const double xs[9][2] = {{0, 0},    {1.1, 0.0},  {2, 0},    {0, 0.45}, {1.18, 0.62},
                           {2, 0.55}, {0, 1},      {0.9, 1.0}, {2, 1}};
  for (int i = 0; i < 9; ++i) o << i + 1 << "," << xs[i][0] << "," << xs[i][1] << ",0\n";
  const std::array<std::array<int, 4>, 4> quads = {{{1, 2, 5, 4}, {2, 3, 6, 5}, {4, 5, 8, 7}, {5, 6, 9, 8}}};
  o << "*ELEMENT_SHELL\n";
  for (int k = 0; k < (triangles ? 3 : 4); ++k) {
    const auto q = rotated(quads[k], (shift + (mixed ? k : 0)) % 4);
    o << k + 1 << ",1," << q[0] << "," << q[1] << "," << q[2] << "," << q[3] << "\n";
  }
  if (triangles) {
    const std::array<std::array<int, 3>, 2> tri = {{{5, 6, 9}, {5, 9, 8}}};
    for (int k = 0; k < 2; ++k) {
      std::array<int, 3> t = tri[k];
      std::rotate(t.begin(), t.begin() + shift % 3, t.end());
      o << k + 4 << ",1," << t[0] << "," << t[1] << "," << t[2] << "," << t[2] << "\n";
    }
  }
  o << "*SET_NODE_LIST\n1\n1,4,7\n*SET_NODE_LIST\n2\n3,6,9\n*BOUNDARY_SPC_SET\n1,0,1,1,1,1,1,1\n"
    << "*BOUNDARY_PRESCRIBED_MOTION_SET\n2,2,2,1,0.5\n*BOUNDARY_PRESCRIBED_MOTION_SET\n2,3,2,1,0.3\n"
    << "*DEFINE_CURVE\n1\n0,0\n0.05,1.0\n*END\n";
  return o.str();
}

/// Two one-point hexahedra side by side (nodes 1-12, distorted), the bottom face 1234 and the top
/// face 5678 of each listed from corner `shift`; clamped at x = 0, the face x = 2 sheared in y and
/// pulled in x.
std::string solid_deck(int shift) {
  std::ostringstream o;
  o.precision(17);
  // Bulk viscosity off (1e-12: 0 would mean the default): it acts only while tr D < 0, and in this
  // shear-dominated motion tr D crosses 0 where its round-off decides the sign; the step of an
  // element then jumps by the linear term (Q1 c, 6 % of the step), as in LS-DYNA, and the two runs
  // part by the time-discretisation error (5e-4 of the internal energy measured), not by the
  // numbering. With it off the element kernels are compared alone.
  o << "*KEYWORD\n*CONTROL_TERMINATION\n0.02\n*CONTROL_BULK_VISCOSITY\n1e-12,1e-12\n*SECTION_SOLID\n1,1\n"
    << "*MAT_ELASTIC\n1,1.0e-3,1000.0,0.3\n"
    << "*PART\nblock\n1,1,1\n*NODE\n";
  const double xs[12][3] = {{0, 0, 0}, {1.1, 0, 0.05}, {2, 0, 0}, {0, 1, 0}, {0.95, 1.1, 0}, {2, 1, 0},
                            {0, 0, 1}, {1.05, -0.1, 1}, {2, 0, 1}, {0, 1, 1}, {0.9, 1, 1.08}, {2, 1, 1}};
  for (int i = 0; i < 12; ++i) o << i + 1 << "," << xs[i][0] << "," << xs[i][1] << "," << xs[i][2] << "\n";
  const std::array<std::array<int, 4>, 2> bottom = {{{1, 2, 5, 4}, {2, 3, 6, 5}}};
  const std::array<std::array<int, 4>, 2> top = {{{7, 8, 11, 10}, {8, 9, 12, 11}}};
  o << "*ELEMENT_SOLID\n";
  for (int k = 0; k < 2; ++k) {
    const auto b = rotated(bottom[k], shift), t = rotated(top[k], shift);
    o << k + 1 << ",1," << b[0] << "," << b[1] << "," << b[2] << "," << b[3] << "," << t[0] << "," << t[1] << ","
      << t[2] << "," << t[3] << "\n";
  }
  o << "*SET_NODE_LIST\n1\n1,4,7,10\n*SET_NODE_LIST\n2\n3,6,9,12\n*BOUNDARY_SPC_SET\n1,0,1,1,1\n"
    << "*BOUNDARY_PRESCRIBED_MOTION_SET\n2,2,2,1,0.4\n*BOUNDARY_PRESCRIBED_MOTION_SET\n2,1,2,1,0.2\n"
    << "*DEFINE_CURVE\n1\n0,0\n0.02,1.0\n*END\n";
  return o.str();
}

struct Final {
  std::vector<Vec3> x;
  Real internal = 0.0;
};

Final run(const std::string& deck) {
  auto sim = build_simulation(read_keyword_string(deck, "inn.k"));
  while (sim->step()) {
  }
  Final f;
  for (Index i = 0; i < static_cast<Index>(sim->nodes().size()); ++i) f.x.push_back(sim->nodes().x.get(i));
  f.internal = sim->energy().internal;
  return f;
}

/// The largest distance between the two runs' final node positions, over the largest displacement.
Real difference(const Final& a, const Final& b, const Final& start) {
  Real d = 0.0, u = 0.0;
  for (std::size_t i = 0; i < a.x.size(); ++i) {
    d = std::max(d, (a.x[i] - b.x[i]).norm());
    u = std::max(u, (a.x[i] - start.x[i]).norm());
  }
  return d / u;
}

Final reference_shell() {
  Final f;
  auto sim = build_simulation(read_keyword_string(shell_deck(1, 0, false), "inn.k"));
  for (Index i = 0; i < static_cast<Index>(sim->nodes().size()); ++i) f.x.push_back(sim->nodes().x0.get(i));
  return f;
}

}  // namespace

TEST(InvariantNumbering, ShellsAgreeUnderRenumberingWithInn2) {
  const Final start = reference_shell();
  const Final a2 = run(shell_deck(2, 0, false)), a1 = run(shell_deck(1, 0, false));
  for (int shift : {1, 2, 3}) {
    const Final b2 = run(shell_deck(2, shift, true)), b1 = run(shell_deck(1, shift, true));
    const Real d2 = difference(a2, b2, start), d1 = difference(a1, b1, start);
    std::printf("shells renumbered from corner %d (+k per element): INN = 2 differs by %.3g, INN = 1 by %.3g of the "
                "largest displacement; internal energy %.9g / %.9g (INN 2), %.9g / %.9g (INN 1)\n",
                shift, d2, d1, a2.internal, b2.internal, a1.internal, b1.internal);
    EXPECT_LT(d2, 1e-10);
    EXPECT_NEAR(b2.internal, a2.internal, 1e-9 * a2.internal);
    EXPECT_GT(d1, 1e3 * d2);  // the default frame depends on the numbering: INN = 2 is what removes it
  }
}

// Triangles (N3 = N4): with INN = 2 their frame is the reference side 1-2 carried by the polar
// rotation of the in-plane deformation (shell_c0tri::invariant_e1), invariant as well; with -2
// (LS-DYNA: "except triangular shells") the quadrilaterals are invariant and the triangles keep
// side 1-2, so a renumbered mixed mesh differs. On a quadrilateral-only mesh -2 is 2.
TEST(InvariantNumbering, TrianglesAgreeWithInn2AndNotWithMinus2) {
  const Final start = reference_shell();
  const Final a2 = run(shell_deck(2, 0, false, true)), am = run(shell_deck(-2, 0, false, true));
  for (int shift : {1, 2}) {
    const Final b2 = run(shell_deck(2, shift, true, true)), bm = run(shell_deck(-2, shift, true, true));
    const Real d2 = difference(a2, b2, start), dm = difference(am, bm, start);
    std::printf("mixed mesh renumbered (quadrilaterals from corner %d, triangles from corner %d): INN = 2 differs "
                "by %.3g, INN = -2 by %.3g of the largest displacement\n",
                shift, shift % 3, d2, dm);
    EXPECT_LT(d2, 1e-10);
    EXPECT_NEAR(b2.internal, a2.internal, 1e-9 * a2.internal);
    EXPECT_GT(dm, 1e3 * d2);
  }
  const Final q = run(shell_deck(-2, 0, false)), c = run(shell_deck(2, 0, false));
  EXPECT_EQ(difference(q, c, start), 0.0);
  try {
    read_keyword_string(shell_deck(-3, 0, false), "inn.k");
    FAIL() << "INN = -3 read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("inn.k:5: *CONTROL_ACCURACY card 1: field INN = -3 must be 1 (off), 2 or -2 "
                                         "(shells), 3 (solids), 4 or -4 (both)"),
              std::string::npos)
        << e.what();
  }
}

TEST(InvariantNumbering, HexahedraAgreeUnderRenumberingWithoutAFrame) {
  Final start;
  {
    auto sim = build_simulation(read_keyword_string(solid_deck(0), "inn.k"));
    for (Index i = 0; i < static_cast<Index>(sim->nodes().size()); ++i) start.x.push_back(sim->nodes().x0.get(i));
  }
  const Final a = run(solid_deck(0));
  for (int shift : {1, 2, 3}) {
    const Final b = run(solid_deck(shift));
    const Real d = difference(a, b, start);
    std::printf("hexahedra renumbered from corner %d: differ by %.3g of the largest displacement\n", shift, d);
    EXPECT_LT(d, 1e-10);
    EXPECT_NEAR(b.internal, a.internal, 1e-9 * a.internal);
  }
}

}  // namespace slideline
