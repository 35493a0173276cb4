// *DEFINE_COORDINATE_SYSTEM, _NODES and _VECTOR (src/io/keyword_coordinate_systems.cpp) and their
// axes (src/solver/coordinate_axes.cpp): the fields as the model keeps them, written back and read
// again to the same model, malformed fields refused naming file, line and field; the axes of each
// form against the rotation they were written from, DIR = Y and Z, CIDL, and a signed permutation.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "slideline/core/error.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/io/keyword_writer.hpp"
#include "slideline/solver/coordinate_axes.hpp"

using namespace slideline;
using Kind = model::CoordinateSystem::Kind;

namespace {

std::string vec(const Vec3& v) {
  char b[100];
  std::snprintf(b, sizeof b, "%.17g,%.17g,%.17g", v[0], v[1], v[2]);
  return b;
}

const Mat3 kR = Eigen::AngleAxisd(1.1, Vec3(-1.0, 0.5, 2.0).normalized()).toRotationMatrix();

/// Nodes 1-3 at the origin and on the turned x and y axes (scaled), then `cards`.
std::string deck(const std::string& cards) {
  return "*KEYWORD\n*NODE\n1," + vec(Vec3(1.0, 2.0, 3.0)) + "\n2," + vec(Vec3(1.0, 2.0, 3.0) + 3.0 * kR.col(0)) +
         "\n3," + vec(Vec3(1.0, 2.0, 3.0) + 0.5 * kR.col(1) - 0.2 * kR.col(0)) + "\n" + cards + "*END\n";
}

std::string thrown(const std::string& text) {
  try {
    read_keyword_string(text, "c.k", nullptr);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST(KeywordCoordinateSystems, EachFormReadWrittenAndReadAgain) {
  const std::string cards = "*DEFINE_COORDINATE_SYSTEM_TITLE\nframe a\n11,0,0,0,1,0,0,12\n0,1,0\n"
                            "*DEFINE_COORDINATE_NODES\n12,1,2,3,1,Z\n13,1,3,2\n"
                            "*DEFINE_COORDINATE_VECTOR\n14,1,1,0,0,1,0,3\n";
  const model::Model m = read_keyword_string(deck(cards), "c.k", nullptr);
  ASSERT_EQ(m.coordinate_systems.size(), 4u);
  const auto& a = m.coordinate_systems[0];
  EXPECT_EQ(a.kind, Kind::points);
  EXPECT_EQ(a.title, "frame a");
  EXPECT_EQ(a.cid, 11);
  EXPECT_EQ(a.axis, Vec3(1.0, 0.0, 0.0));
  EXPECT_EQ(a.plane, Vec3(0.0, 1.0, 0.0));
  EXPECT_EQ(a.cidl, 12);
  EXPECT_EQ(a.src.line, 8);
  const auto& b = m.coordinate_systems[1];
  EXPECT_EQ(b.kind, Kind::nodes);
  EXPECT_EQ(b.nodes, (std::array<Id, 3>{1, 2, 3}));
  EXPECT_EQ(b.flag, 1);
  EXPECT_EQ(b.dir, 2);
  EXPECT_TRUE(b.moves());
  const auto& c = m.coordinate_systems[2];  // two systems under one keyword; DIR blank: X
  EXPECT_EQ(c.cid, 13);
  EXPECT_EQ(c.dir, 0);
  EXPECT_FALSE(c.moves());
  const auto& d = m.coordinate_systems[3];
  EXPECT_EQ(d.kind, Kind::vectors);
  EXPECT_EQ(d.nodes[0], 3);
  EXPECT_TRUE(d.moves());
  const model::Model again = read_keyword_string(write_keyword_string(m), "again.k", nullptr);
  ASSERT_EQ(again.coordinate_systems.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    model::CoordinateSystem x = again.coordinate_systems[k], y = m.coordinate_systems[k];
    x.src = y.src = {};
    EXPECT_EQ(x, y) << k;
  }
}

TEST(KeywordCoordinateSystems, MalformedFieldsAreRefusedNamingTheLine) {
  EXPECT_NE(thrown(deck("*DEFINE_COORDINATE_VECTOR\n0,1,0,0,0,1,0\n")).find("c.k:7: *DEFINE_COORDINATE_VECTOR: field "
                                                                             "CID must be a positive id (got 0)"),
            std::string::npos);
  EXPECT_NE(thrown(deck("*DEFINE_COORDINATE_NODES\n3,1,2,3,0,W\n")).find("c.k:7: *DEFINE_COORDINATE_NODES: field DIR "
                                                                          "must be X, Y or Z"),
            std::string::npos);
  EXPECT_NE(thrown(deck("*DEFINE_COORDINATE_NODES\n3,1,2,3,2\n")).find("field FLAG must be 0"), std::string::npos);
  EXPECT_NE(thrown(deck("*DEFINE_COORDINATE_SYSTEM\n3,0,0,0,1,0,0\n")).find("missing XP YP ZP card"),
            std::string::npos);
}

// The axes of each form are the rotation the deck was written from, to round-off: three points
// (origin away from 0, scaled axis), three nodes with DIR = X (N2 on x, N3 in x-y), Y (N2 on y, N3 in
// y-z) and Z (N2 on z, N3 in z-x), two vectors; CIDL turns a system given in another one.
TEST(CoordinateAxes, EveryFormGivesTheRotationItWasWrittenFrom) {
  const Vec3 o(1.0, 2.0, 3.0);
  std::string cards = "*DEFINE_COORDINATE_SYSTEM\n1," + vec(o) + "," + vec(o + 4.0 * kR.col(0)) + "\n" +
                      vec(o + kR * Vec3(-1.0, 0.2, 0.0)) + "\n";
  cards += "*DEFINE_COORDINATE_NODES\n2,1,2,3\n";
  cards += "*DEFINE_COORDINATE_VECTOR\n5," + vec(kR.col(0)) + "," + vec(kR * Vec3(3.0, 2.0, 0.0)) + "\n";
  // In system 1, the points of the global axes turned back: system 6 is the global frame.
  cards += "*DEFINE_COORDINATE_SYSTEM\n6," + vec(kR.transpose() * (-o)) + "," + vec(kR.transpose() * (Vec3(1, 0, 0) - o)) +
           ",1\n" + vec(kR.transpose() * (Vec3(0, 1, 0) - o)) + "\n";
  // DIR = Y: N2 along y, N3 in the y-z plane (node 2 is on the turned x: the system is the
  // rotation whose y is R x and whose z is in the plane of R x and R y: columns (R z, R x, R y)).
  cards += "*DEFINE_COORDINATE_NODES\n7,1,2,3,0,Y\n*DEFINE_COORDINATE_NODES\n8,1,2,3,0,Z\n";
  const model::Model m = read_keyword_string(deck(cards), "c.k", nullptr);
  for (Id cid : {1, 2, 5}) EXPECT_LT((local_axes(m, cid, "test").r - kR).norm(), 1e-14) << cid;
  EXPECT_LT((local_axes(m, 1, "test").origin - o).norm(), 1e-15);
  EXPECT_LT((local_axes(m, 6, "test").r - Mat3::Identity()).norm(), 1e-14);
  Mat3 y;
  y << kR.col(2), kR.col(0), kR.col(1);
  EXPECT_LT((local_axes(m, 7, "test").r - y).norm(), 1e-14);
  Mat3 z;
  z << kR.col(1), kR.col(2), kR.col(0);  // z along R x, x in the plane of R x and R y
  EXPECT_LT((local_axes(m, 8, "test").r - z).norm(), 1e-14);
  EXPECT_NEAR(local_axes(m, 8, "test").r.determinant(), 1.0, 1e-14);
}

TEST(CoordinateAxes, SignedPermutationsAreRecognised) {
  Mat3 p;
  p << 0, -1, 0, 0, 0, 1, 1, 0, 0;
  EXPECT_EQ(axis_permutation(p), (std::array<int, 3>{2, 0, 1}));
  EXPECT_EQ(axis_permutation(Mat3::Identity()), (std::array<int, 3>{0, 1, 2}));
  EXPECT_FALSE(axis_permutation(kR));
  const model::Model m = read_keyword_string(deck("*DEFINE_COORDINATE_NODES\n4,1,9,3\n"), "c.k", nullptr);
  try {
    local_axes(m, 4, "c.k:9: *LOAD_NODE_POINT field CID");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("*DEFINE_COORDINATE_NODES 4: field N2 refers to node 9, which the deck does "
                                         "not define"),
              std::string::npos)
        << e.what();
  }
}
