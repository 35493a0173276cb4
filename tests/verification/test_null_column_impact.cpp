// A *MAT_NULL column (linear polynomial EOS, C1 = K; TEROD / CEROD set, so its part can erode and
// the contact is an eroding one, while nothing erodes) strikes a held plate through
// *CONTACT_ERODING_NODES_TO_SURFACE with the column's nodes as a node set (SSTYP 4): the light-node
// contact of birdball.k (docs/contact_erosion.md) in a case with closed forms.
//
// Also turned (axes permuted: the column along x). Column: 20 unit cubes along z, lateral motion held (uniaxial strain: the null solid has no shear
// stiffness, so the wave speed is c = sqrt(K / rho)), moving at v towards the plate from a gap of
// 0.01. Acoustic closed forms for a rod on a rigid wall (impact stress rho c v = 0.0032 K, linear):
// - while the wave runs down and back, the wall force is rho c v A (A = 1);
// - the contact lasts 2 L / c; the column leaves at v (no dissipation but the bulk viscosity's);
// - the impulse on the column is 2 m v (m = rho L A).
// Exact (the central-difference identity): the impulse sum_k F^k (t_{k+1} - t_{k-1}) / 2 of the
// contact forces on the column equals its momentum change to round-off, and the forces on the
// plate are their reaction.
//
// The step (docs/solver.md, "The step of a node with elements and a contact spring"). The plate's
// face is 16 times a column cell's, so the spring on each column base node (k = SLSFAC K A^2 / V =
// 133) is stiffer than its element (omega_c = sqrt(k / m) = 1031 against the element's 2 c / L =
// 632, m = rho / 8): each vote alone allows TSSFAC 1, but the node feels both, omega^2 = omega_c^2 +
// omega_e^2, stable for TSSFAC <= 2 / (omega dt_c) = 0.85 (dt_c = 2 / omega_c the spring's vote).
// With each spring voting alone (SimulationControls::contact_step_with_elements off, the rule before
// session 16) 0.8 ran as below, but 0.84, 0.87 and the default 0.9 chattered (the base nodes
// bounced): the column left 10-20 % faster than it came, with negative contact and internal
// energies, while the ledger still closed to 2e-3 and the run exited 0. With the spring's vote
// counting the elements on its nodes, 1 / dt^2 = 1 / dt_e^2 + 1 / dt_c^2 (here the plate's dt_e =
// 2.73e-3, the smaller of the pair's; contact_step_with_elements, which these runs turn on), the
// default 0.9 runs the physics.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "slideline/core/parallel.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/solver/build.hpp"
#include "slideline/solver/simulation.hpp"

namespace slideline {
namespace {

constexpr int kCells = 20;
constexpr Real kRho = 1e-3, kK = 100.0, kV = 1.0, kGap = 0.01;

std::string column_deck(const Mat3& rotation, Real tssfac) {
  std::ostringstream o;
  o << std::setprecision(17) << "*KEYWORD\n*CONTROL_TIMESTEP\n0," << tssfac
    << "\n*CONTROL_TERMINATION\n0.17,\n*SECTION_SOLID\n1,1\n"
    << "*MAT_NULL\n1," << kRho << ",-1e10,0,10.0,0.01\n*EOS_LINEAR_POLYNOMIAL\n1,0," << kK << "\n"
    << "*PART\ncolumn\n1,1,1,1\n*MAT_ELASTIC\n2," << kRho << ",100.0,0.3\n*PART\nplate\n2,1,2\n*NODE\n";
  const auto node = [&](int id, Real x, Real y, Real z) {
    const Vec3 p = rotation * Vec3(x, y, z);
    o << id << "," << p.x() << "," << p.y() << "," << p.z() << "\n";
  };
  for (int k = 0; k <= kCells; ++k)
    for (int j = 0; j <= 1; ++j)
      for (int i = 0; i <= 1; ++i) node(1 + i + 2 * j + 4 * k, i, j, kGap + k);
  for (int k = 0; k <= 1; ++k)
    for (int j = 0; j <= 1; ++j)
      for (int i = 0; i <= 1; ++i) node(1001 + i + 2 * j + 4 * k, -1.5 + 4.0 * i, -1.5 + 4.0 * j, -1.0 + k);
  o << "*ELEMENT_SOLID\n";
  for (int k = 0; k < kCells; ++k) {
    const int b = 1 + 4 * k, t = b + 4;
    o << k + 1 << ",1," << b << "," << b + 1 << "," << b + 3 << "," << b + 2 << "," << t << "," << t + 1 << ","
      << t + 3 << "," << t + 2 << "\n";
  }
  o << "1001,2,1001,1002,1004,1003,1005,1006,1008,1007\n";
  o << "*SET_NODE_LIST_GENERATE\n1\n1," << 4 * kCells + 4 << "\n*SET_NODE_LIST_GENERATE\n2\n1001,1008\n";
  // The column's lateral motion held: the global axes its x and y go to (`rotation` maps axes to
  // axes: a support acts along global axes or a local system made of them).
  int held[3] = {0, 0, 0};
  for (int g = 0; g < 3; ++g) held[g] = std::abs(rotation(g, 0)) > 0.5 || std::abs(rotation(g, 1)) > 0.5 ? 1 : 0;
  o << "*BOUNDARY_SPC_SET\n1,0," << held[0] << "," << held[1] << "," << held[2] << "\n*BOUNDARY_SPC_SET\n2,0,1,1,1\n";
  const Vec3 v = rotation * Vec3(0.0, 0.0, -kV);
  o << "*INITIAL_VELOCITY\n1\n" << v.x() << "," << v.y() << "," << v.z() << "\n";
  o << "*CONTACT_ERODING_NODES_TO_SURFACE\n1,2,4,3\n\n\n0,1,0\n*END\n";
  return o.str();
}

struct ImpactRun {
  std::vector<Real> t, force;  ///< per step end: the contact force on the column along the axis (> 0 pushing it back)
  Real impulse = 0.0;          ///< sum_k F^k (t_{k+1} - t_{k-1}) / 2 over the recorded steps
  Real momentum0 = 0.0, momentum1 = 0.0;  ///< the column's along the axis
  Real worst_reaction = 0.0;   ///< largest |sum of all contact forces| (slaves and master)
  Real mass = 0.0;
  Real kinetic1 = 0.0, balance = 0.0, contact_energy = 0.0;  ///< at the end
  Real internal = 0.0, bulk_viscosity = 0.0, hourglass = 0.0;  ///< at the end
};

/// `with_elements`: SimulationControls::contact_step_with_elements (off: each spring votes alone).
ImpactRun run(const Mat3& rotation, Real tssfac = 0.6, bool with_elements = true) {
  SimulationSetup setup = build_setup(read_keyword_string(column_deck(rotation, tssfac), "column.k"));
  setup.controls.contact_step_with_elements = with_elements;
  auto sim = std::make_unique<Simulation>(std::move(setup));
  const NodalFields& nodes = sim->nodes();
  const Vec3 a = rotation * Vec3(0.0, 0.0, 1.0);
  std::vector<Index> column;
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (nodes.ids[i] < 1000) column.push_back(static_cast<Index>(i));
  const auto momentum = [&] {
    Real p = 0.0;
    for (Index n : column) p += nodes.mass[static_cast<std::size_t>(n)] * nodes.v.get(n).dot(a);
    return p;
  };
  ImpactRun r;
  while (sim->step()) {
    Real f = 0.0;
    Vec3 all = Vec3::Zero();
    for (Index n : column) f += nodes.f_contact.get(n).dot(a);
    for (std::size_t i = 0; i < nodes.size(); ++i) all += nodes.f_contact.get(static_cast<Index>(i));
    r.worst_reaction = std::max(r.worst_reaction, all.norm());
    r.t.push_back(sim->time());
    r.force.push_back(f);
  }
  r.momentum1 = momentum();  // v^{K - 1/2}: the last recorded force has not acted yet
  for (Index n : column) r.mass += nodes.mass[static_cast<std::size_t>(n)];  // lumped by the first step
  r.momentum0 = -r.mass * kV;                                               // every node at v towards the plate
  const EnergyReport& e = sim->energy();
  std::printf("energies at the end: kinetic %.6g internal %.6g hourglass %.6g bulk viscosity %.6g contact %.6g "
              "balance error %.3g (initial kinetic %.6g)\n",
              e.kinetic, e.internal, e.hourglass, e.bulk_viscosity, e.contact, e.balance_error(), 0.5 * r.mass * kV * kV);
  r.kinetic1 = e.kinetic;
  r.balance = e.balance_error();
  r.contact_energy = e.contact;
  r.internal = e.internal;
  r.bulk_viscosity = e.bulk_viscosity;
  r.hourglass = e.hourglass;
  for (std::size_t k = 0; k + 1 < r.t.size(); ++k) {
    const Real before = k == 0 ? 0.0 : r.t[k - 1];
    r.impulse += r.force[k] * (r.t[k + 1] - before) / 2.0;
  }
  return r;
}

TEST(NullColumnImpact, ImpulseIsTheMomentumChange) {
  for (const bool turned : {false, true}) {
    SCOPED_TRACE(turned ? "turned" : "straight");
    // Turned: the axes permuted (x -> y -> z -> x), the column along x: supports act along global
    // axes only (a skew support system is refused), so this is the turned copy the deck allows.
    Mat3 rot = Mat3::Identity();
    if (turned) rot << 0, 0, 1, 1, 0, 0, 0, 1, 0;
    const ImpactRun r = run(rot);
    const Real c = std::sqrt(kK / kRho), m = kRho * kCells, f_plateau = kRho * c * kV;
    // Contact window and plateau.
    std::size_t first = 0;
    while (first < r.force.size() && r.force[first] <= 0.0) ++first;
    std::size_t last = r.force.size();
    while (last > first && r.force[last - 1] <= 0.0) --last;
    ASSERT_LT(first, r.force.size());
    const Real t_on = r.t[first], t_off = r.t[last - 1];
    Real mean = 0.0;
    int count = 0;
    for (std::size_t k = first; k < last; ++k)
      if (r.t[k] > t_on + 0.25 * (t_off - t_on) && r.t[k] < t_on + 0.75 * (t_off - t_on)) mean += r.force[k], ++count;
    mean /= count;
    std::printf("%s: mass %.6g (closed form %.6g); contact from %.5g (gap / v = %.5g) to %.5g, duration %.5g (2 L / c = "
                "%.5g); mean force over its middle half %.5g (rho c v A = %.5g); impulse %.6g, momentum change %.6g "
                "(2 m v = %.6g); largest sum of all contact forces %.3g\n",
                turned ? "turned" : "straight", r.mass, m, t_on, kGap / kV, t_off, t_off - t_on, 2.0 * kCells / c, mean,
                f_plateau, r.impulse, r.momentum1 - r.momentum0, 2.0 * m * kV, r.worst_reaction);
    EXPECT_NEAR(r.mass, m, 1e-12 * m);
    EXPECT_NEAR(t_on, kGap / kV, 0.002);
    EXPECT_NEAR(t_off - t_on, 2.0 * kCells / c, 0.02 * 2.0 * kCells / c);
    EXPECT_NEAR(mean, f_plateau, 0.02 * f_plateau);
    // The identity to round-off; the acoustic answer within what the bulk viscosity takes.
    EXPECT_NEAR(r.impulse, r.momentum1 - r.momentum0, 1e-9 * m * kV);
    EXPECT_NEAR(r.momentum1 - r.momentum0, 2.0 * m * kV, 0.05 * 2.0 * m * kV);
    EXPECT_LE(r.worst_reaction, 1e-12 * f_plateau * 100.0);
    // No energy made: the column leaves with at most what it came with, and the ledger closes.
    const Real k0 = 0.5 * m * kV * kV;
    EXPECT_LE(r.kinetic1, k0);
    EXPECT_GE(r.contact_energy, 0.0);
    EXPECT_LT(std::abs(r.balance), 1e-3 * k0);
  }
}


/// The rebound speed of the column: its momentum after the contact over its mass (> 0: away from
/// the plate).
Real rebound_speed(const ImpactRun& r) { return r.momentum1 / r.mass; }

// At the default TSSFAC 0.9 (and 0.6): the column leaves with the speed the energy balance allows.
// Nothing but the contact acts on it, and the contact, the bulk viscosity and the hourglass
// viscosity only take energy, so its rigid-body speed is at most v_max = sqrt(2 (K0 - W_q - W_hg)
// / m) <= v (K0 = m v^2 / 2; the kinetic energy of the mean velocity is at most the kinetic
// energy); the acoustic answer is v (the bulk viscosity takes a little: within 5 %). Contact time
// 2 L / c (2 %), impulse = momentum change (round-off), the ledger closed, and the contact gives
// back at most what it took: its energy after the rebound at least -1 % of K0 (the spring's work
// over steps in which it engages or lets go part-way is not exact; measured -0.7 % at TSSFAC 0.8
// and +0.1 % at 0.9, against -570 % when the springs voted alone). Straight and turned.
TEST(NullColumnImpact, LeavesAtTheSpeedItCameWithAtTheDefaultStep) {
  for (const Real tssfac : {0.9, 0.6})
    for (const bool turned : {false, true}) {
      SCOPED_TRACE(std::string(turned ? "turned" : "straight") + " TSSFAC " + std::to_string(tssfac));
      Mat3 rot = Mat3::Identity();
      if (turned) rot << 0, 0, 1, 1, 0, 0, 0, 1, 0;
      const ImpactRun r = run(rot, tssfac);
      const Real c = std::sqrt(kK / kRho), m = kRho * kCells, k0 = 0.5 * m * kV * kV;
      std::size_t first = 0;
      while (first < r.force.size() && r.force[first] <= 0.0) ++first;
      std::size_t last = r.force.size();
      while (last > first && r.force[last - 1] <= 0.0) --last;
      ASSERT_LT(first, r.force.size());
      const Real duration = r.t[last - 1] - r.t[first];
      const Real v_out = rebound_speed(r);
      const Real v_max = std::sqrt(2.0 * (k0 - r.bulk_viscosity - r.hourglass) / m);
      std::printf("TSSFAC %.2g %s: %zu steps; contact %.5g (2 L / c = %.5g); rebound speed %.6g (v = %.6g, energy "
                  "bound %.6g); impulse %.6g, momentum change %.6g; energies at the end: kinetic %.6g of %.6g, "
                  "internal %.3g, contact %.3g, bulk viscosity %.3g, hourglass %.3g, balance %.3g\n",
                  tssfac, turned ? "turned" : "straight", r.t.size(), duration, 2.0 * kCells / c, v_out, kV, v_max,
                  r.impulse, r.momentum1 - r.momentum0, r.kinetic1, k0, r.internal, r.contact_energy, r.bulk_viscosity,
                  r.hourglass, r.balance);
      EXPECT_NEAR(duration, 2.0 * kCells / c, 0.02 * 2.0 * kCells / c);
      EXPECT_NEAR(r.impulse, r.momentum1 - r.momentum0, 1e-9 * m * kV);
      EXPECT_LE(v_out, v_max);
      EXPECT_NEAR(v_out, kV, 0.05 * kV);
      EXPECT_LE(r.kinetic1, k0);
      EXPECT_GE(r.contact_energy, -0.01 * k0);
      EXPECT_LT(std::abs(r.balance), 1e-3 * k0);
    }
}

// The same column with each spring voting alone (the rule before session 16) at TSSFAC 0.9: the
// base nodes chatter and the column leaves faster than it came, energy from nothing, while the
// ledger closes. Kept so that the test above is known to catch it.
TEST(NullColumnImpact, EachSpringVotingAloneChattersAtTheDefaultStep) {
  const ImpactRun r = run(Mat3::Identity(), 0.9, false);
  const Real m = kRho * kCells, k0 = 0.5 * m * kV * kV;
  std::printf("springs alone, TSSFAC 0.9: rebound speed %.6g (v = %.6g), kinetic energy %.6g of %.6g, contact %.3g\n",
              rebound_speed(r), kV, r.kinetic1, k0, r.contact_energy);
  EXPECT_GT(rebound_speed(r), 1.05 * kV);
  EXPECT_GT(r.kinetic1, k0);
}


// The combined votes are per pair and reduced in slave order: the steps and forces of the column
// at TSSFAC 0.9 are bitwise the same on 1, 2 and 3 threads.
TEST(NullColumnImpact, CombinedStepsDoNotDependOnTheThreadCount) {
  const int before = max_threads();
  set_threads(1);
  const ImpactRun one = run(Mat3::Identity(), 0.9);
  for (const int threads : {2, 3}) {
    set_threads(threads);
    const ImpactRun r = run(Mat3::Identity(), 0.9);
    EXPECT_EQ(r.t, one.t) << threads << " threads";
    EXPECT_EQ(r.force, one.force) << threads << " threads";
  }
  set_threads(before);
}

}  // namespace
}  // namespace slideline
