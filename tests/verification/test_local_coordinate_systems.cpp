// Local coordinate systems (*DEFINE_COORDINATE_SYSTEM, _NODES, _VECTOR; docs/keywords.md, "Local
// coordinate systems"). The check is the rotated copy: a free block of two hexahedra, started by
// *INITIAL_VELOCITY_GENERATION, pushed by *LOAD_NODE_POINT and *LOAD_BODY_Z, and the same deck
// turned by a rotation R whose cards give the same numbers in a local system CID that R turns
// the global axes into. Every node of the turned deck must then follow R times the first deck's
// motion, to round-off, whichever card defines the system (three points with an origin away from
// the block, three of the block's nodes with DIR = X or Y, two vectors of other lengths). The
// step is held by an LCTM curve below the stable step, so that the step does not depend on the
// round-off of the turned geometry. A *BOUNDARY_SPC_NODE in a system whose axes are global axes
// in another order holds the global axis it names, bit for bit; skew constraints, systems that
// move with nodes on cards that act through the run, and degenerate or missing systems are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "slideline/core/error.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/solver/build.hpp"
#include "slideline/solver/simulation.hpp"

using namespace slideline;

namespace {

Id node_id(int i, int j, int k) { return 1 + i + 3 * j + 6 * k; }

std::string num(Real v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

std::string vec(const Vec3& v) { return num(v[0]) + "," + num(v[1]) + "," + num(v[2]); }

/// The block 2 x 1 x 1 (node (i, j, k) at (i, j, k), turned by `r`), its loads given in system
/// `cid` (0: global) and the card(s) `systems` that define it.
std::string block_deck(const Mat3& r, Id cid, const std::string& systems, const std::string& extra = "") {
  std::string d = "*KEYWORD\n*CONTROL_TERMINATION\n0.5\n*CONTROL_TIMESTEP\n0,0.9,0,0,0,2\n";
  d += "*DEFINE_CURVE\n1\n0,0\n0.2,1\n10,1\n*DEFINE_CURVE\n2\n0,0.01\n10,0.01\n";
  d += "*SECTION_SOLID\n1,1\n*MAT_ELASTIC\n1,1.0,1000.0,0.3\n*PART\nblock\n1,1,1\n*NODE\n";
  for (int k = 0; k <= 1; ++k)
    for (int j = 0; j <= 1; ++j)
      for (int i = 0; i <= 2; ++i) d += std::to_string(node_id(i, j, k)) + "," + vec(r * Vec3(i, j, k)) + "\n";
  d += "*ELEMENT_SOLID\n";
  for (int i = 0; i < 2; ++i) {
    d += std::to_string(i + 1) + ",1";
    for (const auto& [a, b, c] : {std::array{i, 0, 0}, {i + 1, 0, 0}, {i + 1, 1, 0}, {i, 1, 0}, {i, 0, 1},
                                  {i + 1, 0, 1}, {i + 1, 1, 1}, {i, 1, 1}})
      d += "," + std::to_string(node_id(a, b, c));
    d += "\n";
  }
  const std::string c = std::to_string(cid);
  d += "*LOAD_NODE_POINT\n" + std::to_string(node_id(2, 0, 0)) + ",1,1,0.5," + c + "\n";
  d += std::to_string(node_id(2, 1, 1)) + ",2,1,-0.3," + c + "\n";
  d += "*LOAD_BODY_Z\n1,0.2,0,0,0,0," + c + "\n";
  d += "*INITIAL_VELOCITY_GENERATION\n1,2,0,0.1,0.05,-0.02,0," + c + "\n0,0,0,0,0,0\n";
  return d + systems + extra + "*END\n";
}

std::unique_ptr<Simulation> run(const std::string& deck) {
  auto sim = build_simulation(read_keyword_string(deck, "block.k"));
  sim->run({});
  return sim;
}

/// A rotation by `angle` about `axis`.
Mat3 rotation(const Vec3& axis, Real angle) { return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix(); }

/// The largest distance between the nodes of `b` and `r` times those of `a` (positions and
/// velocities).
Real largest_difference(const Simulation& a, const Simulation& b, const Mat3& r) {
  Real d = 0.0;
  for (Index n = 0; n < static_cast<Index>(a.nodes().size()); ++n) {
    d = std::max(d, (b.nodes().x.get(n) - r * a.nodes().x.get(n)).norm());
    d = std::max(d, (b.nodes().v.get(n) - r * a.nodes().v.get(n)).norm());
  }
  return d;
}

TEST(LocalCoordinateSystems, TurnedDeckFollowsTheTurnedMotionForEverySystemCard) {
  const auto global = run(block_deck(Mat3::Identity(), 0, ""));
  ASSERT_EQ(global->time(), 0.5);
  Real moved = 0.0;
  for (Index n = 0; n < static_cast<Index>(global->nodes().size()); ++n) moved = std::max(moved, global->nodes().displacement(n).norm());
  EXPECT_GT(moved, 0.05);  // the loads and the initial velocity move the block by this much

  const Mat3 r = rotation(Vec3(1.0, 2.0, 3.0), 0.7);
  const Vec3 o(0.3, -0.2, 0.5);
  const std::string points = "*DEFINE_COORDINATE_SYSTEM\n7," + vec(o) + "," + vec(o + 2.5 * r.col(0)) + "\n" +
                             vec(o + r * Vec3(0.3, 1.7, 0.0)) + "\n";
  // Node 1 at the origin, node 2 on the local x axis, node 4 on y, node 7 on z.
  const std::string nodes_x = "*DEFINE_COORDINATE_NODES\n7,1,2,4,0,X\n";
  const std::string nodes_y = "*DEFINE_COORDINATE_NODES_TITLE\nalong y\n7,1,4,7,0,Y\n";
  const std::string vectors = "*DEFINE_COORDINATE_VECTOR\n7," + vec(0.4 * r.col(0)) + "," +
                              vec(r * Vec3(-2.0, 0.5, 0.0)) + "\n";
  for (const auto& [name, card] : {std::pair{"points", points}, {"nodes, DIR = X", nodes_x},
                                   {"nodes, DIR = Y", nodes_y}, {"vectors", vectors}}) {
    SCOPED_TRACE(name);
    const auto turned = run(block_deck(r, 7, card));
    ASSERT_EQ(turned->cycle(), global->cycle());
    const Real d = largest_difference(*global, *turned, r);
    std::printf("%s: largest |x' - R x|, |v' - R v| %.3g (largest displacement %.3g, %ld cycles)\n", name, d, moved,
                turned->cycle());
    EXPECT_LT(d, 1e-12);
  }
  // The same numbers without the system: a different motion (the check can fail).
  const auto unturned_loads = run(block_deck(r, 0, ""));
  const Real off = largest_difference(*global, *unturned_loads, r);
  std::printf("the same numbers without the system: %.3g\n", off);
  EXPECT_GT(off, 0.01);
}

// *INITIAL_VELOCITY (ICID) and *INITIAL_VELOCITY_NODE (ICID): v(0) is r times the card's values.
TEST(LocalCoordinateSystems, InitialVelocitiesAreGivenInTheSystem) {
  const Mat3 r = rotation(Vec3(0.0, 0.0, 1.0), 0.5);
  const std::string sys = "*DEFINE_COORDINATE_VECTOR\n3," + vec(r.col(0)) + "," + vec(r.col(1)) + "\n";
  std::string deck = block_deck(Mat3::Identity(), 0, sys);
  const std::string gen = "*INITIAL_VELOCITY_GENERATION\n1,2,0,0.1,0.05,-0.02,0,0\n0,0,0,0,0,0\n";
  ASSERT_NE(deck.find(gen), std::string::npos);
  deck.replace(deck.find(gen), gen.size(),
               "*SET_NODE_LIST\n1\n1,2,3,4,5,6,7,8\n*INITIAL_VELOCITY\n1,0,0,0,3\n1.0,2.0,3.0\n"
               "*INITIAL_VELOCITY_NODE\n9,0.5,0,0,0,0,0,3\n10,0.5,0,0\n");
  const auto sim = build_simulation(read_keyword_string(deck, "iv.k"));
  for (Index n = 0; n < 8; ++n) EXPECT_LT((sim->nodes().v.get(n) - r * Vec3(1.0, 2.0, 3.0)).norm(), 1e-15) << n;
  EXPECT_LT((sim->nodes().v.get(8) - r * Vec3(0.5, 0.0, 0.0)).norm(), 1e-15);
  EXPECT_LT((sim->nodes().v.get(9) - Vec3(0.5, 0.0, 0.0)).norm(), 1e-15);
  EXPECT_GT(std::abs(sim->nodes().v.get(8)[1]), 0.2);  // turned: 0.5 sin 0.5
}

// A constraint in a system whose local x is the global y and local y the global -x: DOFX holds
// the global y, bit for bit the run that holds y globally.
TEST(LocalCoordinateSystems, ConstraintInAPermutedSystemHoldsTheGlobalAxisItNames) {
  const std::string sys = "*DEFINE_COORDINATE_VECTOR\n4,0,1,0,-1,0,0\n";
  const auto local = run(block_deck(Mat3::Identity(), 0, sys, "*BOUNDARY_SPC_NODE\n1,4,1,0,0\n"));
  const auto global = run(block_deck(Mat3::Identity(), 0, sys, "*BOUNDARY_SPC_NODE\n1,0,0,1,0\n"));
  ASSERT_EQ(local->cycle(), global->cycle());
  for (Index n = 0; n < static_cast<Index>(local->nodes().size()); ++n)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(local->nodes().x[c][n], global->nodes().x[c][n]) << n << " " << c;
  EXPECT_EQ(local->nodes().v.get(0)[1], 0.0);
  EXPECT_NE(local->nodes().v.get(0)[0], 0.0);
}

/// The message of the error build_simulation gives for `deck`.
template <class Error>
std::string error_of(const std::string& deck) {
  try {
    build_simulation(read_keyword_string(deck, "bad.k"));
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(LocalCoordinateSystems, WhatCannotBeRunIsRefusedNamingTheCard) {
  const Mat3 i = Mat3::Identity();
  // A skew constraint.
  const std::string skew = "*DEFINE_COORDINATE_VECTOR\n4,1,1,0,0,1,0\n";
  EXPECT_NE(error_of<NotImplementedError>(block_deck(i, 0, skew, "*BOUNDARY_SPC_NODE\n1,4,1,0,0\n"))
                .find("*BOUNDARY_SPC_NODE field CID = 4: constraints along axes that are not global axes"),
            std::string::npos);
  // A system that moves with its nodes, on a load.
  EXPECT_NE(error_of<NotImplementedError>(block_deck(i, 5, "*DEFINE_COORDINATE_NODES\n5,1,2,4,1\n"))
                .find("the system moves with its nodes (FLAG = 1)"),
            std::string::npos);
  // ... which is fine for the initial velocities alone (taken at t = 0).
  std::string deck = block_deck(i, 0, "*DEFINE_COORDINATE_NODES\n5,1,2,4,1\n");
  deck.replace(deck.find("0,0.1,0.05,-0.02,0,0\n"), 21, "0,0.1,0.05,-0.02,0,5\n");
  EXPECT_NO_THROW(build_simulation(read_keyword_string(deck, "ok.k")));
  // A spin with a local system.
  deck.replace(deck.find("1,2,0,0.1"), 9, "1,2,3,0.1");
  deck.replace(deck.find("\n0,0,0,0,0,0\n"), 13, "\n0,0,0,0,0,1\n");
  EXPECT_NE(error_of<NotImplementedError>(deck).find("field ICID with OMEGA != 0"), std::string::npos);
  // A system the deck does not define, and one whose points are collinear.
  EXPECT_NE(error_of<InputError>(block_deck(i, 9, "")).find(
                "*LOAD_NODE_POINT field CID refers to coordinate system 9, which the deck does not define"),
            std::string::npos);
  EXPECT_NE(error_of<InputError>(block_deck(i, 6, "*DEFINE_COORDINATE_SYSTEM\n6,0,0,0,1,0,0\n2,0,0\n"))
                .find("*DEFINE_COORDINATE_SYSTEM 6: its axis and plane directions do not span a plane"),
            std::string::npos);
}

}  // namespace
