// ENMASS of *CONTROL_CONTACT (docs/contact_erosion.md, "ENMASS"): what becomes of the nodes that
// erosion frees of all their elements. 0: they leave the contact (and fly on as free masses of the
// mesh); 1: those of solids stay in the contact as free masses; 2: those of solids and shells.
//
// Deck: a plate, one elastic hexahedron 2 x 2 x 1 (part 2, every node held, its top face at z = 0,
// the master side), and above it, centred, a column of n cubes of edge a = 0.5 (part 1, *MAT_ELASTIC
// with *MAT_ADD_EROSION), its bottom a gap g above the plate, every node at the speed v towards the
// plate (*INITIAL_VELOCITY). Contact through the eroding cards (EROSOP 1), the slave side the
// column's nodes as a node set (SSTYP 4) or as its part.
//
// Closed forms.
// - Free masses (n = 1, FAILTM = 0.02 < g / v: the cube is deleted in free flight, at rest in its
//   own frame: no strain, no eroded energy). Its 8 nodes, each of mass m = rho a^3 / 8, meet the
//   plate one by one as free masses. The one-way pass takes the master face's spring,
//   k = SLSFAC K A^2 / V (K = E / (3 (1 - 2 nu)), A = 4, V = 4), undamped and frictionless: each node
//   comes back with its speed reversed (restitution 1), after pi sqrt(m / k) in contact; so the
//   column's momentum changes by 2 M v, which is the impulse of the contact forces, and the kinetic
//   energy M v^2 / 2 comes back whole. ENMASS 0: no node is in the contact once it is free: no force,
//   every node goes on at -v through the plate.
// - A column that erodes on impact (n = 3, MXPRES: the bottom cube goes under the contact
//   pressure): the impulse of the contact forces equals the column's momentum change (round-off:
//   the contact is the only force from outside the column), the balance closes with the eroded
//   energy booked, and each freed bottom node, a free mass on its spring from the deletion on,
//   leaves the plate with the speed its energy then gives: v_out^2 = v_n^2 + (k / m) d^2 (v_n its
//   normal speed, d its depth at the deletion; the rest of the column no longer touches it).
// Each in the deck turned 0.7 rad about (1, 2, 3) as well.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "slideline/core/types.hpp"
#include "slideline/element/element_erosion.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/solver/build.hpp"
#include "slideline/solver/simulation.hpp"

namespace slideline {
namespace {

constexpr Real kA = 0.5, kRho = 1.0, kE = 100.0, kNu = 0.3, kPlateRho = 1e-3;

/// The master face's spring per slave node (force / length): SLSFAC K A^2 / V of the plate.
Real plate_stiffness() { return 0.1 * kE / (3.0 * (1.0 - 2.0 * kNu)) * 16.0 / 4.0; }

struct Column {
  int n = 1;                 ///< cubes stacked
  int enmass = 1;
  std::string card = "*CONTACT_ERODING_NODES_TO_SURFACE";
  std::string sides = "1,2,4,3";  ///< SSID MSID SSTYP MSTYP
  std::string card4 = "0,1,0\n";  ///< the eroding cards' ISYM EROSOP IADJ (none on an automatic card)
  std::string erosion = "*MAT_ADD_EROSION\n1\n,,,,,,,0.02\n";  ///< FAILTM 0.02
  bool shell = false;        ///< a single shell square (part 1, thickness 0.1) instead of the column
  Real gap = 0.05, v = 1.0, end_time = 0.7;
  Mat3 rotation = Mat3::Identity();

  std::string text() const {
    std::ostringstream o;
    o << std::setprecision(17) << "*KEYWORD\n*CONTROL_TERMINATION\n" << end_time << ",\n*CONTROL_CONTACT\n0.1,0,1,0,1,0,1,"
      << enmass << "\n*SECTION_SOLID\n1,1\n";
    if (shell) o << "*SECTION_SHELL\n3,2,1.0,2\n0.1,0.1,0.1,0.1\n";
    o << "*MAT_ELASTIC\n1," << kRho << "," << kE << "," << kNu << "\n" << erosion << "*PART\ncolumn\n1,"
      << (shell ? 3 : 1) << ",1\n*MAT_ELASTIC\n2," << kPlateRho << "," << kE << "," << kNu
      << "\n*PART\nplate\n2,1,2\n*NODE\n";
    const auto node = [&](int id, Real x, Real y, Real z) {
      const Vec3 p = rotation * Vec3(x, y, z);
      o << id << "," << p.x() << "," << p.y() << "," << p.z() << "\n";
    };
    const int layers = shell ? 1 : n + 1;
    for (int k = 0; k < layers; ++k)
      for (int j = 0; j <= 1; ++j)
        for (int i = 0; i <= 1; ++i) node(1 + i + 2 * j + 4 * k, -0.5 * kA + kA * i, -0.5 * kA + kA * j, gap + kA * k);
    for (int k = 0; k <= 1; ++k)
      for (int j = 0; j <= 1; ++j)
        for (int i = 0; i <= 1; ++i) node(101 + i + 2 * j + 4 * k, -1.0 + 2.0 * i, -1.0 + 2.0 * j, -1.0 + 1.0 * k);
    if (shell) {
      o << "*ELEMENT_SHELL\n1,1,1,2,4,3\n";
    } else {
      o << "*ELEMENT_SOLID\n";
      for (int k = 0; k < n; ++k) {
        const int b = 4 * k;
        o << k + 1 << ",1," << b + 1 << "," << b + 2 << "," << b + 4 << "," << b + 3 << "," << b + 5 << "," << b + 6
          << "," << b + 8 << "," << b + 7 << "\n";
      }
    }
    o << "*ELEMENT_SOLID\n100,2,101,102,104,103,105,106,108,107\n*SET_NODE_LIST\n1\n";
    for (int i = 1; i <= 4 * layers; ++i) o << i << (i % 8 == 0 || i == 4 * layers ? "\n" : ",");
    o << "*SET_NODE_LIST\n2\n101,102,103,104,105,106,107,108\n*BOUNDARY_SPC_SET\n2,0,1,1,1\n";
    const Vec3 vel = rotation * Vec3(0.0, 0.0, -v);
    o << "*INITIAL_VELOCITY\n1\n" << vel.x() << "," << vel.y() << "," << vel.z() << "\n";
    o << card << "\n" << sides << "\n\n\n" << card4 << "*END\n";
    return o.str();
  }
};

/// What the checks read, in the deck's own frame (z towards the column).
struct ColumnRun {
  std::vector<Real> z0;                  ///< per column node: final height
  std::vector<Real> vz;                  ///< per column node: final normal speed (v^{N+1/2})
  std::vector<Real> mass;                ///< per column node
  std::vector<Real> first, last;         ///< per column node: first and last evaluation with a force
  std::vector<Real> del_speed, del_depth;  ///< per column node: normal speed and depth when freed (-1: not)
  std::vector<Real> del_force;           ///< per column node: normal contact force in the freeing evaluation
  Real impulse = 0.0;                    ///< normal impulse of the contact forces on the column
  Real momentum0 = 0.0, momentum1 = 0.0; ///< normal momentum of the column, start and end
  Real largest_force = 0.0, dt = 0.0;
  Real kinetic0 = 0.0, kinetic1 = 0.0, eroded = 0.0, contact = 0.0, balance = 0.0;
  Real deleted_at = -1.0;                ///< first deletion
};

ColumnRun run(const Column& deck) {
  auto sim = build_simulation(read_keyword_string(deck.text(), "enmass.k"));
  const NodalFields& nodes = sim->nodes();
  const Mat3 back = deck.rotation.transpose();
  const int count = deck.shell ? 4 : 4 * (deck.n + 1);
  std::vector<Index> idx;
  for (int id = 1; id <= count; ++id)
    for (std::size_t i = 0; i < nodes.size(); ++i)
      if (nodes.ids[i] == id) idx.push_back(static_cast<Index>(i));
  const auto n = static_cast<std::size_t>(count);
  ColumnRun r;
  r.first.assign(n, -1.0);
  r.last.assign(n, -1.0);
  r.del_speed.assign(n, -1.0);
  r.del_depth.assign(n, -1.0);
  r.del_force.assign(n, 0.0);
  const ElementErosion* er = nullptr;  // the column's (part 1)
  for (const auto& b : sim->blocks())
    if (b->part_id() == 1) er = std::as_const(*b).erosion();
  std::vector<char> freed(n, 0);
  // step() ends with the forces at its end positions, time() = t^{j+1}: f^{j+1}, which the next
  // step's velocity update uses, v^{j+3/2} = v^{j+1/2} + (t^{j+2} - t^j) / 2 f^{j+1} / m (the
  // first: v^{1/2} = v(0) + t^1 / 2 f^0 / m, f^0 = 0 here: nothing touches at t = 0).
  Real t_prev = 0.0, t_prev2 = 0.0, pending = 0.0;  // pending: the normal contact force on the column at t_prev
  while (sim->step()) {
    const Real t1 = sim->time();
    r.impulse += pending * 0.5 * (t1 - t_prev2);
    r.dt = std::max(r.dt, t1 - t_prev);
    pending = 0.0;
    for (std::size_t a = 0; a < n; ++a) {
      const Vec3 f = back * nodes.f_contact.get(idx[a]);
      pending += f.z();
      r.largest_force = std::max(r.largest_force, f.norm());
      if (f.norm() > 0.0) {
        if (r.first[a] < 0.0) r.first[a] = t1;
        r.last[a] = t1;
      }
    }
    // Freed nodes: every element holding them deleted (the bottom layer's only element is the first),
    // in the evaluation at t1.
    if (er && er->deleted(0) && !freed[0]) {
      r.deleted_at = t1;
      for (std::size_t a = 0; a < 4; ++a) {
        freed[a] = 1;
        // x at t1; the speed at t1 from v^{j+1/2} and half a step of this evaluation's force.
        const Vec3 x = back * nodes.x.get(idx[a]), v = back * nodes.v.get(idx[a]);
        const Real f = (back * nodes.f_contact.get(idx[a])).z();
        r.del_depth[a] = std::max(Real(0), -x.z());
        r.del_speed[a] = v.z() + 0.5 * (t1 - t_prev) * f / nodes.mass[idx[a]];
        r.del_force[a] = f;
      }
    }
    t_prev2 = t_prev;
    t_prev = t1;
  }
  // The masses are formed at the first step (and never change); the initial velocity is the deck's.
  for (std::size_t a = 0; a < n; ++a) {
    r.mass.push_back(nodes.mass[idx[a]]);
    r.momentum0 -= nodes.mass[idx[a]] * deck.v;
    r.z0.push_back((back * nodes.x.get(idx[a])).z());
    r.vz.push_back((back * nodes.v.get(idx[a])).z());
    r.momentum1 += nodes.mass[idx[a]] * r.vz.back();
  }
  const EnergyReport& e = sim->energy();
  r.kinetic0 = e.kinetic0;
  r.kinetic1 = e.kinetic;
  r.eroded = e.eroded();
  r.contact = e.contact;
  r.balance = e.balance_error();
  return r;
}

Mat3 turned() { return Eigen::AngleAxis<Real>(0.7, Vec3(1.0, 2.0, 3.0).normalized()).toRotationMatrix(); }

// ENMASS 1 (and 2: the same for solids): the cube's 8 nodes, free masses after FAILTM, bounce off
// the plate one by one with their speed reversed, each after pi sqrt(m / k) in contact.
TEST(ErodingEnmass, FreeMassesBounceOffThePlate) {
  struct Case {
    const char* name;
    std::string card, sides;
    int enmass;
    bool rotated;
  };
  const Case cases[] = {
      {"nodes to surface, node set, ENMASS 1", "*CONTACT_ERODING_NODES_TO_SURFACE", "1,2,4,3", 1, false},
      {"nodes to surface, node set, ENMASS 1, turned", "*CONTACT_ERODING_NODES_TO_SURFACE", "1,2,4,3", 1, true},
      {"nodes to surface, part, ENMASS 2", "*CONTACT_ERODING_NODES_TO_SURFACE", "1,2,3,3", 2, false},
      {"automatic nodes to surface, node set, ENMASS 1", "*CONTACT_AUTOMATIC_NODES_TO_SURFACE", "1,2,4,3", 1, false},
      {"surface to surface, ENMASS 1", "*CONTACT_ERODING_SURFACE_TO_SURFACE", "1,2,3,3", 1, false},
      {"single surface, ENMASS 1, turned", "*CONTACT_ERODING_SINGLE_SURFACE", ",,5", 1, true},
  };
  const Real k = plate_stiffness();
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    Column deck;
    deck.card = c.card;
    if (c.card == "*CONTACT_AUTOMATIC_NODES_TO_SURFACE") deck.card4 = "";
    deck.sides = c.sides;
    deck.enmass = c.enmass;
    if (c.rotated) deck.rotation = turned();
    const ColumnRun r = run(deck);
    const Real m = kRho * kA * kA * kA / 8.0, t_contact = M_PI * std::sqrt(m / k);
    Real worst_speed = 0.0, worst_duration = 0.0;
    for (std::size_t a = 0; a < r.vz.size(); ++a) {
      EXPECT_NEAR(r.mass[a], m, 1e-12 * m);
      worst_speed = std::max(worst_speed, std::abs(r.vz[a] - deck.v));
      EXPECT_GE(r.first[a], 0.0) << "node " << a + 1 << " never met the plate";
      const Real t_in = (deck.gap + (a >= 4 ? kA : 0.0)) / deck.v;  // free fall to the plate
      EXPECT_GE(r.first[a], t_in);  // the first evaluation past the plate's face
      EXPECT_LE(r.first[a], t_in + r.dt);
      // The last evaluation before the spring lets go: within one step of the closed form's exit
      // (so the measured duration is within two steps of it, one at each end).
      EXPECT_LE(r.last[a], t_in + t_contact + 0.01 * r.dt);
      EXPECT_GE(r.last[a], t_in + t_contact - 1.01 * r.dt);
      worst_duration = std::max(worst_duration, std::abs(r.last[a] - r.first[a] - t_contact));
    }
    const Real dp = r.momentum1 - r.momentum0, two_mv = 2.0 * kRho * kA * kA * kA * deck.v;
    std::printf("%s: deleted at %.4g; largest |v_out - v| %.3g of v = %.3g; contact %.5g (closed form %.5g, "
                "worst off by %.3g, step %.3g); impulse %.8g, momentum change %.8g (2 M v = %.8g); kinetic %.8g -> %.8g; "
                "contact energy %.3g; balance %.3g\n",
                c.name, r.deleted_at, worst_speed, deck.v, t_contact, t_contact, worst_duration, r.dt, r.impulse, dp,
                two_mv, r.kinetic0, r.kinetic1, r.contact, r.balance);
    EXPECT_GE(r.deleted_at, 0.02);  // the first evaluation at or after FAILTM
    EXPECT_LE(r.deleted_at, 0.02 + r.dt);
    EXPECT_LE(std::abs(r.eroded), 1e-12 * r.kinetic0);  // deleted at rest in its own frame
    // Restitution 1 of an undamped spring; the central difference's entry and exit, each within
    // one step of the spring's first and last instants (above), leave O((omega dt)^2) of the speed.
    EXPECT_LE(worst_speed, 0.01 * deck.v);
    EXPECT_NEAR(r.impulse, dp, 1e-12 * two_mv);
    EXPECT_NEAR(dp, two_mv, 0.01 * two_mv);
    EXPECT_NEAR(r.kinetic1, r.kinetic0, 0.02 * r.kinetic0);
    EXPECT_LE(std::abs(r.balance), 1e-9 * r.kinetic0);
  }
}

// ENMASS 0: a freed node leaves the contact, so no force ever acts and every node passes through.
TEST(ErodingEnmass, WithoutEnmassFreeNodesPassThrough) {
  Column deck;
  deck.enmass = 0;
  const ColumnRun r = run(deck);
  std::printf("ENMASS 0: largest contact force %.3g; bottom node ends at z = %.6g\n", r.largest_force, r.z0[0]);
  EXPECT_EQ(r.largest_force, 0.0);
  for (std::size_t a = 0; a < r.vz.size(); ++a) EXPECT_NEAR(r.vz[a], -deck.v, 1e-12 * deck.v);
  EXPECT_LT(r.z0[0], -0.5);  // deep inside the plate
}

// ENMASS 2 keeps a shell's freed nodes in the contact, ENMASS 1 does not (they are no solid's): a
// shell square deleted in free flight (FAILTM) bounces off the plate with ENMASS 2, the offset half
// its thickness, and passes through with ENMASS 1.
TEST(ErodingEnmass, ShellNodesStayWithEnmass2Only) {
  for (const int enmass : {1, 2}) {
    Column deck;
    deck.shell = true;
    deck.enmass = enmass;
    deck.gap = 0.15;  // the offset is half the thickness, 0.05
    deck.end_time = 0.3;
    deck.card = "*CONTACT_ERODING_NODES_TO_SURFACE";
    deck.sides = "1,2,3,3";
    const ColumnRun r = run(deck);
    std::printf("shell, ENMASS %d: deleted at %.4g; final speeds %.6g %.6g %.6g %.6g; largest force %.3g; "
                "first contact %.5g (closed form (gap - t/2) / v = %.5g)\n",
                enmass, r.deleted_at, r.vz[0], r.vz[1], r.vz[2], r.vz[3], r.largest_force, r.first[0],
                (deck.gap - 0.05) / deck.v);
    EXPECT_GE(r.deleted_at, 0.02);
    EXPECT_LE(r.deleted_at, 0.02 + r.dt);
    for (std::size_t a = 0; a < 4; ++a) {
      if (enmass == 2) {
        EXPECT_NEAR(r.vz[a], deck.v, 0.01 * deck.v);
        EXPECT_GE(r.first[a], (deck.gap - 0.05) / deck.v);
        EXPECT_LE(r.first[a], (deck.gap - 0.05) / deck.v + r.dt);
      } else {
        EXPECT_NEAR(r.vz[a], -deck.v, 1e-12 * deck.v);
      }
    }
    if (enmass == 1) EXPECT_EQ(r.largest_force, 0.0);
    EXPECT_LE(std::abs(r.balance), 1e-9 * r.kinetic0);
  }
}

// A column of three cubes that erodes on impact (MXPRES): impulse = momentum change, the balance
// closes with the eroded energy, and each freed bottom node leaves with the speed its energy at the
// deletion gives (v_out^2 = v_n^2 + (k / m) d^2). ENMASS 0: they leave the contact in the deleting
// evaluation (no force on them from then on) and fly on with the speed they had.
TEST(ErodingEnmass, ColumnErodingOnImpactKeepsItsFreedMassInContact) {
  const Real k = plate_stiffness();
  for (const int enmass : {1, 0}) {
    for (const bool rotated : {false, true}) {
      if (enmass == 0 && rotated) continue;
      SCOPED_TRACE(enmass);
      Column deck;
      deck.n = 3;
      deck.enmass = enmass;
      deck.erosion = "*MAT_ADD_EROSION\n1,,2.0\n\n";  // MXPRES 2
      deck.end_time = 0.4;
      if (rotated) deck.rotation = turned();
      const ColumnRun r = run(deck);
      ASSERT_GE(r.deleted_at, 0.0) << "the bottom cube did not erode";
      const Real dp = r.momentum1 - r.momentum0;
      std::printf("column, ENMASS %d%s: bottom cube deleted at %.5g (contact from %.5g); impulse %.10g, momentum "
                  "change %.10g; kinetic %.6g -> %.6g, eroded %.4g, contact %.4g, balance %.3g\n",
                  enmass, rotated ? ", turned" : "", r.deleted_at, r.first[0], r.impulse, dp, r.kinetic0, r.kinetic1,
                  r.eroded, r.contact, r.balance);
      EXPECT_NEAR(r.impulse, dp, 1e-12 * std::abs(r.momentum0));
      EXPECT_GT(r.eroded, 0.0);
      EXPECT_LE(std::abs(r.balance), 1e-3 * r.kinetic0);
      for (std::size_t a = 0; a < 4; ++a) {
        const Real m = r.mass[a];
        const Real predicted = std::sqrt(r.del_speed[a] * r.del_speed[a] + k / m * r.del_depth[a] * r.del_depth[a]);
        std::printf("  node %zu: freed at depth %.4g, speed %.5g; leaves at %.6g (balance: %.6g)\n", a + 1,
                    r.del_depth[a], r.del_speed[a], r.vz[a], predicted);
        if (enmass == 1) {
          EXPECT_GT(r.del_depth[a], 0.0) << "freed out of contact: the check says nothing";
          EXPECT_NEAR(r.vz[a], predicted, 0.01 * predicted);
        } else {
          EXPECT_EQ(r.del_force[a], 0.0);
          EXPECT_NEAR(r.vz[a], r.del_speed[a], 1e-12);
        }
      }
    }
  }
}

}  // namespace
}  // namespace slideline
