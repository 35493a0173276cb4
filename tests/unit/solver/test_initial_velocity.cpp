// *INITIAL_VELOCITY, _GENERATION and _NODE from deck to run: closed-form motions (free translation,
// rigid rotation), momentum in an impact through contact, the energy balance, and the refusals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "slideline/core/error.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/solver/build.hpp"
#include "slideline/solver/rigid_body.hpp"
#include "slideline/solver/simulation.hpp"
#include "slideline/solver/stability_monitor.hpp"

namespace slideline {
namespace {

/// Free-format deck text of an n x n x n block of hexahedra [o, o + size], node ids from
/// `node_base + 1`, element ids from `elem_base + 1`, part `pid`.
std::string block(Id pid, const Vec3& o, const Vec3& size, int n, Id node_base, Id elem_base) {
  const int np = n + 1;
  const auto id = [&](int i, int j, int k) { return node_base + 1 + i + np * (j + np * k); };
  std::string s = "*NODE\n";
  for (int k = 0; k < np; ++k)
    for (int j = 0; j < np; ++j)
      for (int i = 0; i < np; ++i)
        s += std::to_string(id(i, j, k)) + "," + std::to_string(o[0] + size[0] * i / n) + "," +
             std::to_string(o[1] + size[1] * j / n) + "," + std::to_string(o[2] + size[2] * k / n) + "\n";
  s += "*ELEMENT_SOLID\n";
  Id e = elem_base;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        s += std::to_string(++e) + "," + std::to_string(pid);
        for (Id q : {id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                     id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)})
          s += "," + std::to_string(q);
        s += "\n";
      }
  return s;
}

constexpr Real kRho = 2.0, kE = 1000.0, kNu = 0.3;

/// Controls, sections and materials: material 1 elastic, material 2 rigid (free).
std::string header(Real end_time) {
  return "*KEYWORD\n*CONTROL_TERMINATION\n" + std::to_string(end_time) +
         "\n*SECTION_SOLID\n1,1\n*MAT_ELASTIC\n1," + std::to_string(kRho) + "," + std::to_string(kE) + "," +
         std::to_string(kNu) + "\n*MAT_RIGID\n2," + std::to_string(kRho) + "," + std::to_string(kE) + "," +
         std::to_string(kNu) + "\n";
}

std::string part(Id pid, Id mid) { return "*PART\npart " + std::to_string(pid) + "\n" + std::to_string(pid) + ",1," + std::to_string(mid) + "\n"; }

std::unique_ptr<Simulation> build(const std::string& deck) {
  return build_simulation(read_keyword_string(deck, "deck.k"));
}

/// The InputError or NotImplementedError message of building `deck` ("" when it builds).
std::string refusal(const std::string& deck) {
  try {
    build(deck);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

Vec3 momentum(const Simulation& s) {
  Vec3 p = Vec3::Zero();
  for (std::size_t i = 0; i < s.nodes().size(); ++i) p += s.nodes().mass[i] * s.nodes().v.get(static_cast<Index>(i));
  return p;
}

TEST(InitialVelocity, FreeBlockTranslatesUniformlyWithConstantKineticEnergy) {
  // x = x0 + v t for every node, KE = M v^2 / 2 throughout, and the balance closes: the initial
  // kinetic energy is booked as kinetic0.
  const Vec3 v(1.5, -0.75, 0.25);
  const Real t_end = 0.2;
  auto sim = build(header(t_end) + part(1, 1) + block(1, {0, 0, 0}, {1, 1, 1}, 2, 0, 0) +
                   "*INITIAL_VELOCITY\n0\n1.5,-0.75,0.25\n*END\n");
  while (sim->step()) {
  }
  ASSERT_NEAR(sim->time(), t_end, 1e-12);
  const Real mass = kRho * 1.0;
  for (std::size_t i = 0; i < sim->nodes().size(); ++i) {
    const Index q = static_cast<Index>(i);
    EXPECT_LT((sim->nodes().x.get(q) - sim->nodes().x0.get(q) - v * t_end).norm(), 1e-12) << "node " << i;
  }
  const auto& e = sim->energy();
  EXPECT_NEAR(e.kinetic0, 0.5 * mass * v.squaredNorm(), 1e-12);
  EXPECT_NEAR(e.kinetic, 0.5 * mass * v.squaredNorm(), 1e-12);
  EXPECT_LT(std::abs(e.balance_error()), 1e-12 * e.kinetic0);
  EXPECT_LT(std::abs(e.internal) + std::abs(e.hourglass), 1e-12);
}

TEST(InitialVelocity, GenerationWithIdZeroMovesEveryNode) {
  auto sim = build(header(0.1) + part(1, 1) + block(1, {0, 0, 0}, {1, 1, 1}, 1, 0, 0) + part(2, 1) +
                   block(2, {3, 0, 0}, {1, 1, 1}, 1, 10, 10) + "*INITIAL_VELOCITY_GENERATION\n0,0,0,1,2,3\n\n*END\n");
  ASSERT_EQ(sim->nodes().size(), 16u);
  for (std::size_t i = 0; i < sim->nodes().size(); ++i) EXPECT_EQ(sim->nodes().v.get(static_cast<Index>(i)), Vec3(1, 2, 3));
}

TEST(InitialVelocity, ExemptedNodesBoxAndNodeCards) {
  // NSID = 0 gives every node V; NSIDEX's nodes take VE; *INITIAL_VELOCITY_NODE may give a node
  // that no other card reaches its own velocity; a box restricts a second card to its nodes.
  const std::string deck = header(0.1) + part(1, 1) + block(1, {0, 0, 0}, {1, 1, 1}, 1, 0, 0) +
                           part(2, 1) + block(2, {3, 0, 0}, {1, 1, 1}, 1, 10, 10) +
                           "*SET_NODE_LIST\n5\n1,2\n*SET_NODE_LIST\n6\n11,12,13,14,15,16,17,18\n"
                           "*DEFINE_BOX\n1,2.5,5,-1,0.5,-1,2\n"
                           "*INITIAL_VELOCITY\n0,5\n1,0,0\n-1,0,0\n"
                           "*INITIAL_VELOCITY\n6,0,1\n0,2,0\n*END\n";
  // Part 2's nodes get V from both cards with different values: refused, naming both cards.
  const std::string clash = refusal(deck);
  EXPECT_NE(clash.find("deck.k:"), std::string::npos) << clash;
  EXPECT_NE(clash.find("differs from the one"), std::string::npos) << clash;

  // Part 1 only for the first card: NSID = 3 (its other nodes), exempted 5.
  const std::string ok = header(0.1) + part(1, 1) + block(1, {0, 0, 0}, {1, 1, 1}, 1, 0, 0) + part(2, 1) +
                         block(2, {3, 0, 0}, {1, 1, 1}, 1, 10, 10) +
                         "*SET_NODE_LIST\n3\n3,4,5,6,7,8\n*SET_NODE_LIST\n5\n1,2\n"
                         "*SET_NODE_LIST\n6\n11,12,13,14,15,16,17,18\n"
                         "*DEFINE_BOX\n1,2.5,5,-1,0.5,-1,2\n"
                         "*INITIAL_VELOCITY\n3,5\n1,0,0\n-1,0,0\n"
                         "*INITIAL_VELOCITY\n6,0,1\n0,2,0\n"
                         "*INITIAL_VELOCITY_NODE\n17,0,0,-3\n*END\n";
  auto sim = build(ok);
  const auto v = [&](Id nid) {
    for (std::size_t i = 0; i < sim->nodes().size(); ++i)
      if (sim->nodes().ids[i] == nid) return sim->nodes().v.get(static_cast<Index>(i));
    return Vec3(NAN, NAN, NAN);
  };
  EXPECT_EQ(v(1), Vec3(-1, 0, 0));
  EXPECT_EQ(v(2), Vec3(-1, 0, 0));
  for (Id n : {3, 4, 5, 6, 7, 8}) EXPECT_EQ(v(n), Vec3(1, 0, 0)) << n;
  // Box y <= 0.5: the bottom face of part 2 (local j = 0: nodes 11, 12, 15, 16).
  for (Id n : {11, 12, 15, 16}) EXPECT_EQ(v(n), Vec3(0, 2, 0)) << n;
  for (Id n : {13, 14, 18}) EXPECT_EQ(v(n), Vec3(0, 0, 0)) << n;
  EXPECT_EQ(v(17), Vec3(0, 0, -3));
}

/// Block [0,1]^3 of part 1 spinning about the axis through (0.5, 0.5, 0) along (0, 0.6, 0.8),
/// translating with V: as a node set (elastic) or as a rigid part (STYP 2).
std::string spinning(Id mid, Real t_end, const std::string& target) {
  return header(t_end) + part(1, mid) + block(1, {0, 0, 0}, {1, 1, 1}, 2, 0, 0) +
         "*SET_NODE_LIST\n7\n1,2,3,4,5,6,7,8\n9,10,11,12,13,14,15,16\n17,18,19,20,21,22,23,24\n25,26,27\n"
         "*INITIAL_VELOCITY_GENERATION\n" + target + ",3.0,0.1,-0.2,0.3\n0.5,0.5,0,0,0.6,0.8\n*END\n";
}

TEST(InitialVelocity, GenerationGivesOmegaCrossR) {
  // v(0) = V + omega n x (x - xc) at every node (STYP 3, elastic).
  auto sim = build(spinning(1, 0.1, "7,3"));
  const Vec3 w = 3.0 * Vec3(0, 0.6, 0.8), v0(0.1, -0.2, 0.3), xc(0.5, 0.5, 0);
  ASSERT_EQ(sim->nodes().size(), 27u);
  for (std::size_t i = 0; i < sim->nodes().size(); ++i) {
    const Index q = static_cast<Index>(i);
    EXPECT_LT((sim->nodes().v.get(q) - v0 - w.cross(sim->nodes().x0.get(q) - xc)).norm(), 1e-14) << i;
  }
  // The first cycle starts from v(0) and books its kinetic energy.
  sim->step();
  Real k0 = 0.0;
  for (std::size_t i = 0; i < sim->nodes().size(); ++i) {
    const Index q = static_cast<Index>(i);
    k0 += 0.5 * sim->nodes().mass[i] * (v0 + w.cross(sim->nodes().x0.get(q) - xc)).squaredNorm();
  }
  EXPECT_NEAR(sim->energy().kinetic0, k0, 1e-13 * k0);
}

TEST(InitialVelocity, RigidPartRotatesKeepingItsRadius) {
  // A free rigid part given a rigid motion keeps it: omega = 3 n, the centre of mass moves with
  // V + omega x (c - xc), and every node keeps its distance from the (moving) axis.
  const Real t_end = 0.5;  // 1.5 rad of rotation
  auto sim = build(spinning(2, t_end, "1,2"));
  auto* body = dynamic_cast<RigidBody*>(sim->constraints().at(0).get());
  ASSERT_NE(body, nullptr);
  sim->initialize();
  const Vec3 n(0, 0.6, 0.8), w = 3.0 * n, v0(0.1, -0.2, 0.3), xc(0.5, 0.5, 0);
  const Vec3 c0(0.5, 0.5, 0.5);
  const Vec3 vc = v0 + w.cross(c0 - xc);
  EXPECT_LT((body->angular_velocity() - w).norm(), 1e-12);
  EXPECT_LT((body->velocity() - vc).norm(), 1e-12);
  const auto radius = [&](Index q, const Vec3& axis_point) {
    const Vec3 r = sim->nodes().x.get(q) - axis_point;
    return (r - r.dot(n) * n).norm();
  };
  std::vector<Real> r0(sim->nodes().size());
  for (std::size_t i = 0; i < r0.size(); ++i) r0[i] = radius(static_cast<Index>(i), c0);
  while (sim->step()) {
  }
  // The axis through the centre of mass moves with vc; the body spins about it.
  const Vec3 c = c0 + vc * sim->time();
  EXPECT_LT((body->center_of_mass() - c).norm(), 1e-9);
  for (std::size_t i = 0; i < r0.size(); ++i) EXPECT_NEAR(radius(static_cast<Index>(i), c), r0[i], 1e-9) << i;
  EXPECT_LT(std::abs(sim->energy().balance_error()), 1e-9 * sim->energy().kinetic0);
}

TEST(InitialVelocity, RigidPartNeedsOneRigidMotion) {
  // A velocity on one node of a rigid part would be averaged away by the body: refused.
  const std::string deck = header(0.1) + part(1, 2) + block(1, {0, 0, 0}, {1, 1, 1}, 1, 0, 0) +
                           "*INITIAL_VELOCITY_NODE\n5,0,0,-1\n*END\n";
  const std::string what = refusal(deck);
  EXPECT_NE(what.find("deck.k:"), std::string::npos) << what;
  EXPECT_NE(what.find("*INITIAL_VELOCITY_NODE"), std::string::npos) << what;
  EXPECT_NE(what.find("rigid part 1"), std::string::npos) << what;
  // The same velocity on every node is a rigid motion.
  EXPECT_EQ(refusal(header(0.1) + part(1, 2) + block(1, {0, 0, 0}, {1, 1, 1}, 1, 0, 0) +
                    "*INITIAL_VELOCITY\n0\n0,0,-1\n*END\n"),
            "");
}

TEST(InitialVelocity, UnsupportedFieldsAreRefusedWithTheirLine) {
  const std::string base = header(0.1) + part(1, 1) + block(1, {0, 0, 0}, {1, 1, 1}, 1, 0, 0);
  const auto check = [&](const std::string& cards, const char* field) {
    const std::string what = refusal(base + cards + "*END\n");
    EXPECT_NE(what.find("deck.k:"), std::string::npos) << what;
    EXPECT_NE(what.find(field), std::string::npos) << field << ": " << what;
  };
  check("*INITIAL_VELOCITY\n0,0,0,0,3\n1,0,0\n", "ICID");
  check("*INITIAL_VELOCITY\n0,0,9\n1,0,0\n", "*DEFINE_BOX 9");
  check("*INITIAL_VELOCITY\n44\n1,0,0\n", "node set 44");
  check("*INITIAL_VELOCITY\n0\n0,0,0,1,0,0\n", "rotational velocity");  // solid nodes have none
  check("*INITIAL_VELOCITY_GENERATION\n1,2,1,0,0,0,1\n0,0,0,0,0,1\n", "IVATN");
  check("*INITIAL_VELOCITY_GENERATION\n1,2,1,0,0,0,0,5\n0,0,0,0,0,1\n", "ICID");
  check("*INITIAL_VELOCITY_GENERATION\n1,2,1\n0,0,0,0,0,1,1\n", "PHASE");
  check("*INITIAL_VELOCITY_GENERATION\n1,4,1\n0,0,0,0,0,1\n", "STYP");
  check("*INITIAL_VELOCITY_GENERATION\n1,2,1\n0,0,0,0,0,0\n", "NX NY NZ");
  check("*INITIAL_VELOCITY_GENERATION\n9,2,1\n0,0,0,0,0,1\n", "part 9");
  check("*INITIAL_VELOCITY_NODE\n99,1,0,0\n", "node 99");
}

TEST(InitialVelocity, TheValidationLayerListsEveryBadCardAtOnce) {
  // validate_model (validate_initial.cpp) finds them before anything is built: both cards, each
  // with its line, in one error, and the bad input (STYP) makes it an InputError.
  const std::string deck = header(0.1) + part(1, 1) + block(1, {0, 0, 0}, {1, 1, 1}, 1, 0, 0) +
                           "*INITIAL_VELOCITY_GENERATION\n1,2,1,0,0,0,1\n0,0,0,0,0,1\n"
                           "*INITIAL_VELOCITY_GENERATION\n1,4,1\n0,0,0,0,0,1\n*END\n";
  try {
    build(deck);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("IVATN"), std::string::npos) << what;
    EXPECT_NE(what.find("STYP"), std::string::npos) << what;
    EXPECT_NE(what.find('\n'), std::string::npos) << what;
  }
}

TEST(InitialVelocity, SupportedComponentsStartAtRest) {
  // A support active at t = 0 wins: the fixed component starts at zero, the free ones move.
  auto sim = build(header(0.1) + part(1, 1) + block(1, {0, 0, 0}, {1, 1, 1}, 1, 0, 0) +
                   "*SET_NODE_LIST\n1\n1,2,3,4\n*BOUNDARY_SPC_SET\n1,0,0,1,0\n"
                   "*INITIAL_VELOCITY\n0\n1,2,3\n*END\n");
  for (std::size_t i = 0; i < sim->nodes().size(); ++i) {
    const bool fixed = sim->nodes().ids[i] <= 4;
    EXPECT_EQ(sim->nodes().v.get(static_cast<Index>(i)), Vec3(1, fixed ? 0 : 2, 3)) << i;
  }
}

/// A 2 x 2 plate of shells [0,1]^2 at z = 0 (nodes 1-9), part 1, material `mid`, thickness 0.1.
std::string plate(Id mid, Real t_end) {
  std::string s = header(t_end) + "*SECTION_SHELL\n2,2\n0.1\n*PART\nplate\n1,2," + std::to_string(mid) + "\n*NODE\n";
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      s += std::to_string(1 + i + 3 * j) + "," + std::to_string(0.5 * i) + "," + std::to_string(0.5 * j) + ",0\n";
  s += "*ELEMENT_SHELL\n1,1,1,2,5,4\n2,1,2,3,6,5\n3,1,4,5,8,7\n4,1,5,6,9,8\n";
  return s;
}

TEST(InitialVelocity, ShellNodesTakeRotationalVelocities) {
  // VXR..VZR set the rotational dofs of shell nodes, and their rotary kinetic energy is booked.
  auto sim = build(plate(1, 0.01) + "*INITIAL_VELOCITY\n0\n0,0,1,2,-1,0\n*END\n");
  for (std::size_t i = 0; i < sim->nodes().size(); ++i) {
    EXPECT_EQ(sim->nodes().v.get(static_cast<Index>(i)), Vec3(0, 0, 1));
    EXPECT_EQ(sim->nodes().omega.get(static_cast<Index>(i)), Vec3(2, -1, 0));
  }
  sim->step();
  Real k0 = 0.0;
  for (std::size_t i = 0; i < sim->nodes().size(); ++i) k0 += 0.5 * sim->nodes().mass[i] + 0.5 * sim->nodes().rot_inertia[i] * 5.0;
  EXPECT_GT(sim->nodes().rot_inertia[0], 0.0);
  EXPECT_NEAR(sim->energy().kinetic0, k0, 1e-14 * k0);

  // A rigid plate spun by a generation: its shell nodes' omega is the spin, the body takes it.
  auto rigid = build(plate(2, 0.01) + "*INITIAL_VELOCITY_GENERATION\n1,2,4.0\n0.5,0.5,0,1,1,0\n*END\n");
  const Vec3 w = 4.0 * Vec3(1, 1, 0).normalized();
  for (std::size_t i = 0; i < rigid->nodes().size(); ++i)
    EXPECT_LT((rigid->nodes().omega.get(static_cast<Index>(i)) - w).norm(), 1e-15);
  rigid->initialize();
  const auto* body = dynamic_cast<const RigidBody*>(rigid->constraints().at(0).get());
  ASSERT_NE(body, nullptr);
  EXPECT_LT((body->angular_velocity() - w).norm(), 1e-12);
  EXPECT_LT(body->velocity().norm(), 1e-12);  // the axis passes through the centre of mass
  // The same translations with another spin on the rotational dofs are not one rigid motion.
  const std::string what = refusal(plate(2, 0.01) + "*INITIAL_VELOCITY\n0\n0,0,0,1,0,0\n*END\n");
  EXPECT_NE(what.find("rigid part 1"), std::string::npos) << what;
}

/// Two blocks on the x axis: part 1 [0,1]^3 moving at +v1 towards part 2 [1.05, 2.05] x
/// [-0.25, 1.25]^2 at rest (wider, so that every striker node meets the inside of a target face),
/// through a type 3 penalty contact (part 1 slave, part 2 master; penalty scale 10 so that the
/// penetration stays a few % of an element), until they have separated.
std::string impact(Id mid1, Real v1, Real t_end) {
  return header(t_end) + part(1, mid1) + block(1, {0, 0, 0}, {1, 1, 1}, 2, 0, 0) + part(2, 1) +
         block(2, {1.05, -0.25, -0.25}, {1, 1.5, 1.5}, 2, 100, 100) +
         "*CONTACT_SURFACE_TO_SURFACE\n1,2,3,3\n\n10.0,10.0\n*INITIAL_VELOCITY_GENERATION\n1,2,0," +
         std::to_string(v1) + ",0,0\n0,0,0,0,0,0\n*END\n";
}

TEST(InitialVelocity, ImpactThroughContactConservesMomentum) {
  // Contact forces are equal and opposite, internal forces sum to zero and nothing else acts: the
  // total momentum stays m1 v1, i.e. the centre of mass moves at v' = m1 v1 / (m1 + m2) whatever
  // the blocks do. That is exact up to round-off (each force pair cancels in the sum, and the rigid
  // body conserves P to round-off): the 1e-9 bound is round-off over ~100 cycles, not a physical
  // tolerance. After separation the target leads the striker (v2 >= v1'), so m1 v1 = m1 v1' + m2 v2
  // <= (m1 + m2) v2: the target moves at least at v', the momentum went through the contact. The
  // energy balance closes to its trapezoidal O(dt) error (1%).
  const Real v1 = 0.5, t_end = 1.0;
  for (Id mid1 : {1, 2}) {  // elastic striker, then a rigid one
    SCOPED_TRACE(mid1 == 1 ? "elastic striker" : "rigid striker");
    auto sim = build(impact(mid1, v1, t_end));
    const Real m1 = kRho * 1.0, m2 = kRho * 1.5 * 1.5, p0 = m1 * v1;
    Real p_err = 0.0;
    while (sim->step()) p_err = std::max(p_err, (momentum(*sim) - Vec3(p0, 0, 0)).norm());
    EXPECT_LT(p_err, 1e-9 * p0);
    Vec3 p2 = Vec3::Zero();
    Real x1max = -1e9, x2min = 1e9;
    for (std::size_t i = 0; i < sim->nodes().size(); ++i) {
      const bool target = sim->nodes().ids[i] > 100;
      if (target) p2 += sim->nodes().mass[i] * sim->nodes().v.get(static_cast<Index>(i));
      (target ? x2min : x1max) = target ? std::min(x2min, sim->nodes().x.x[i]) : std::max(x1max, sim->nodes().x.x[i]);
    }
    EXPECT_GT(x2min, x1max) << "the blocks have separated";
    EXPECT_GE(p2[0], m2 / (m1 + m2) * p0);
    EXPECT_LT(std::abs(sim->energy().relative_balance_error()), 0.01);
  }
}

// Energy that contact creates is invisible to the balance (every ledger term is a nodal work): it
// shows as contact forces that did more work on the bodies than they took from them, and the run
// flags it once (StabilityMonitor::kContactEnergyWarning, 5 % of the largest energy in play) and
// runs on. The elastic striker above (penalty scale 10 on 2 x 2 x 2 blocks) ends with a contact
// term of -0.056 against the 0.25 it started with, dissipated again by its hourglass (0.063) and
// bulk viscosity (0.055); the rigid striker's contact term never goes below zero.
TEST(InitialVelocity, ContactThatCreatesEnergyIsFlagged) {
  const Real v1 = 0.5, t_end = 1.0;
  auto elastic = build(impact(1, v1, t_end));
  while (elastic->step()) {
  }
  EXPECT_NEAR(elastic->time(), t_end, 1e-12);  // flagged, not stopped
  const EnergyReport& e = elastic->energy();
  ASSERT_TRUE(elastic->contact_energy_warning().has_value());
  EXPECT_GT(elastic->contact_energy_warning()->relative_error, StabilityMonitor::kContactEnergyWarning);
  EXPECT_LT(e.contact + e.friction, -StabilityMonitor::kContactEnergyWarning * e.kinetic0);
  auto rigid = build(impact(2, v1, t_end));
  Real lowest = 0.0;
  while (rigid->step()) lowest = std::min(lowest, rigid->energy().contact + rigid->energy().friction);
  EXPECT_FALSE(rigid->contact_energy_warning().has_value());
  EXPECT_GE(lowest, -1e-12 * rigid->energy().kinetic0);
}

}  // namespace
}  // namespace slideline
