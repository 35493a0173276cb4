// The Taylor bar (issue 21), read from a deck: tests/data/decks/taylor_bar.k (written by
// scripts/taylor_bar_deck.py 2 2 40). A copper bar L0 = 32.4 mm, R0 = 3.2 mm strikes a
// frictionless rigid wall (*RIGIDWALL_PLANAR, z = 0) at 227 m/s; E = 117 GPa, nu = 0.35,
// rho = 8930 kg/m^3, bilinear isotropic hardening SIGY = 400 MPa, ETAN = 100 MPa
// (*MAT_PLASTIC_KINEMATIC, BETA = 1); 80 us after the impact. A quarter bar of one-point hexahedra
// (O-grid section, 4 cells across the radius, 40 along: 480 elements) on two symmetry planes
// (*BOUNDARY_SPC_SET), default viscous hourglass control (IHQ 1, QM 0.1) and bulk viscosity.
//
// Published figures (docs/verification.md, "Taylor bar against published figures", with the
// source read): final radius of the impact face 7.22 mm (the converged Q1/P0 hexahedron of Foulk
// et al. 2021), 7.12 mm (Simo 1992), 7.11 mm (Zienkiewicz et al. 1998), 7.22-7.23 mm (the
// composite tetrahedron of Sierra/SM and TET15-P1 of Carina on their finest meshes); final length
// 21.42-21.48 mm (the same runs). Our refinement study of the same deck (4, 6, 8 cells across the
// radius, scripts/taylor_bar_deck.py) is in docs/verification.md; the tolerances below come from it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "slideline/io/keyword_reader.hpp"
#include "slideline/solver/build.hpp"
#include "slideline/solver/simulation.hpp"

using namespace slideline;

namespace {

struct TaylorResult {
  Real length = 0.0;        ///< extent of the bar along its axis
  Real radius = 0.0;        ///< largest distance from the bar axis of a node of the impact face
  Real max_eps = 0.0;       ///< largest effective plastic strain
  Real plastic_work = 0.0;  ///< over the initial kinetic energy
  Real hourglass = 0.0;     ///< over the initial kinetic energy
  Real energy_error = 0.0;  ///< |balance error| over the largest energy in play
};

model::Model taylor_deck() {
  return read_keyword_file(std::string(SLIDELINE_SOURCE_DIR) + "/tests/data/decks/taylor_bar.k");
}

/// The references' condition instead of the wall: the impact face (the nodes nearest the wall)
/// held along the axis z from the start, as Simo 1992 and the Carina write-up hold it (nodes that
/// reach the wall stay on it); the face starts 0.01 mm above the plane, which changes nothing here.
model::Model hold_face(model::Model m) {
  Real z0 = 1.0;
  for (const auto& n : m.nodes) z0 = std::min(z0, n.x[2]);
  model::NodeSet face{99, "impact face", {}, {}};
  for (const auto& n : m.nodes)
    if (n.x[2] == z0) face.nodes.push_back(n.id);
  m.node_sets.push_back(face);
  model::BoundarySpc spc;
  spc.nsid = face.sid;
  spc.dof = {0, 0, 1, 0, 0, 0};
  m.spcs.push_back(spc);
  m.rigid_walls.clear();
  return m;
}

/// Runs `m` to `end` (0: the deck's end time) and measures along the bar axis `axis` (the wall
/// normal; the wall plane passes through the origin).
TaylorResult run_taylor(model::Model m, const Vec3& axis, Real end = 0.0) {
  if (end > 0.0) m.termination.endtim = end;
  auto sim = build_simulation(m);
  // The impact face: the nodes nearest the wall at the start.
  const auto& x0 = sim->nodes().x;
  Real d0 = 1.0;
  for (std::size_t i = 0; i < x0.x.size(); ++i) d0 = std::min(d0, Vec3(x0.x[i], x0.y[i], x0.z[i]).dot(axis));
  std::vector<Index> face;
  for (std::size_t i = 0; i < x0.x.size(); ++i)
    if (Vec3(x0.x[i], x0.y[i], x0.z[i]).dot(axis) < d0 + 1e-9) face.push_back(static_cast<Index>(i));
  sim->run({});
  TaylorResult r;
  const auto& x = sim->nodes().x;
  Real lo = 1.0, hi = -1.0;
  for (std::size_t i = 0; i < x.x.size(); ++i) {
    lo = std::min(lo, Vec3(x.x[i], x.y[i], x.z[i]).dot(axis));
    hi = std::max(hi, Vec3(x.x[i], x.y[i], x.z[i]).dot(axis));
  }
  r.length = hi - lo;
  for (Index i : face) {
    const Vec3 p(x.x[i], x.y[i], x.z[i]);
    r.radius = std::max(r.radius, (p - p.dot(axis) * axis).norm());
  }
  Real wp = 0.0;
  for (const auto& b : sim->blocks()) {
    const PlasticityTotals t = b->plasticity_totals(sim->nodes());
    r.max_eps = std::max(r.max_eps, t.max_plastic_strain);
    wp += t.plastic_work;
  }
  const EnergyReport& e = sim->energy();
  r.plastic_work = wp / e.kinetic0;
  r.hourglass = e.hourglass / e.kinetic0;
  r.energy_error = sim->energy_error_fraction();
  return r;
}

void record(const char* tag, const TaylorResult& r) {
  ::testing::Test::RecordProperty(std::string(tag) + "_final_length_mm", std::to_string(1e3 * r.length));
  ::testing::Test::RecordProperty(std::string(tag) + "_mushroom_radius_mm", std::to_string(1e3 * r.radius));
  ::testing::Test::RecordProperty(std::string(tag) + "_max_effective_plastic_strain", std::to_string(r.max_eps));
  std::printf("%s: final length %.3f mm, mushroom radius %.3f mm, max effective plastic strain %.3f, "
              "plastic work %.4f and hourglass %.4f of KE0, energy error %.2e\n",
              tag, 1e3 * r.length, 1e3 * r.radius, r.max_eps, r.plastic_work, r.hourglass, r.energy_error);
}

/// The published bands with the tolerances the refinement study justifies (below): length within
/// 1% of 21.42-21.48 mm, radius within 2% of 7.11-7.23 mm, largest plastic strain above 2, plastic
/// work 0.9-1 and hourglass energy under 5% of the initial kinetic energy, the balance error under
/// `energy_tol` of it.
void expect_within_published_bands(const TaylorResult& r, double energy_tol) {
  EXPECT_GT(1e3 * r.length, 21.42 * (1.0 - 0.01));
  EXPECT_LT(1e3 * r.length, 21.48 * (1.0 + 0.01));
  EXPECT_GT(1e3 * r.radius, 7.11 * (1.0 - 0.02));
  EXPECT_LT(1e3 * r.radius, 7.23 * (1.0 + 0.02));
  EXPECT_GT(r.max_eps, 2.0);
  EXPECT_GT(r.plastic_work, 0.9);
  EXPECT_LT(r.plastic_work, 1.0);
  EXPECT_LT(r.hourglass, 0.05);
  EXPECT_LT(r.energy_error, energy_tol);
}

}  // namespace

// The coarse deck against the published figures. Tolerances, from our refinement study
// (docs/verification.md, "Taylor bar against published figures"): the final length within 1% of
// the published 21.42-21.48 mm (4, 6, 8 cells across the radius: 21.62, 21.55, 21.52 mm, converging
// from above towards about 21.45), the radius within 2% of the published 7.11-7.23 mm (7.06, 7.22,
// 7.28 mm: the coarse mesh is 0.7% below the band, the finest 0.7% above it). No published largest
// plastic strain was retrieved: only a floor (ours 2.7, 3.1, 3.4). Nearly all the kinetic energy
// ends as plastic work (the bar is almost at rest after 80 us; the rest went to hourglass and bulk
// viscosity, and into the wall when the face layer stopped on it).
TEST(TaylorBar, CopperBarAgainstPublishedFigures) {
  const TaylorResult r = run_taylor(taylor_deck(), Vec3(0.0, 0.0, 1.0));
  record("coarse_2+2x40", r);
  expect_within_published_bands(r, 0.01);
}

// The same deck with the references' condition (the face held in z instead of the wall): the
// coarse mesh is 0.7% over the length band and 1.6% under the radius band (our finer meshes land
// inside both: 21.474 mm and 7.144 mm at 8 cells across the radius; docs/verification.md). The
// same tolerances as above.
TEST(TaylorBar, FaceHeldAsInTheReferences) {
  const TaylorResult r = run_taylor(hold_face(taylor_deck()), Vec3(0.0, 0.0, 1.0));
  record("face_held_2+2x40", r);
  expect_within_published_bands(r, 1e-3);
}

// The same deck with the assumed-strain stiffness hourglass control (IHQ 6, QM 0.1:
// tests/data/decks/taylor_bar_ihq6.k). Its forces are integrated from the hourglass rates in the
// element's corotational frame (docs/solver.md, "Hexahedron"), so the plastic crush of the foot
// is not taken for elastic hourglass strain: the hourglass energy stays positive and small and
// the crush lands in the same bands as with the viscous control (4 across: 21.537 mm, 6.983 mm).
// Before that form, this deck created energy (hourglass energy -5.5 KE0, a 13.9 mm "foot").
TEST(TaylorBar, AssumedStrainHourglassControlCrushesWithinTheBands) {
  const TaylorResult r = run_taylor(
      read_keyword_file(std::string(SLIDELINE_SOURCE_DIR) + "/tests/data/decks/taylor_bar_ihq6.k"),
      Vec3(0.0, 0.0, 1.0));
  record("ihq6_2+2x40", r);
  EXPECT_GT(r.hourglass, 0.0);
  expect_within_published_bands(r, 0.01);
}

// The rotated copy: the same deck turned by the rotation Q that takes z to x, x to y and y to z
// (the bar along x, the wall x = 0, the symmetry planes y = 0 and z = 0 held in y and z). The
// symmetry supports name global components, so a rotation that maps axes onto axes is the one a
// quarter model allows (a skew support is refused). The run must give the same length, radius and
// plastic strain at 20 us (the early, fast part of the crush, to keep the test short).
TEST(TaylorBar, RotatedCopyGivesTheSameCrush) {
  const model::Model m = taylor_deck();
  model::Model q = m;
  const auto turn = [](const Vec3& v) { return Vec3(v[2], v[0], v[1]); };
  for (auto& n : q.nodes) n.x = turn(n.x);
  for (auto& w : q.rigid_walls) {
    w.tail = turn(w.tail);
    w.head = turn(w.head);
  }
  for (auto& v : q.initial_velocities) v.v = turn(v.v);
  for (auto& s : q.spcs) s.dof = {s.dof[2], s.dof[0], s.dof[1], s.dof[5], s.dof[3], s.dof[4]};
  const TaylorResult a = run_taylor(m, Vec3(0.0, 0.0, 1.0), 20e-6);
  const TaylorResult b = run_taylor(q, Vec3(1.0, 0.0, 0.0), 20e-6);
  record("at_20us", a);
  record("rotated_at_20us", b);
  EXPECT_GT(a.max_eps, 1.0);  // well into the crush
  EXPECT_NEAR(b.length, a.length, 1e-9 * a.length);
  EXPECT_NEAR(b.radius, a.radius, 1e-9 * a.radius);
  EXPECT_NEAR(b.max_eps, a.max_eps, 1e-9 * a.max_eps);
  EXPECT_NEAR(b.plastic_work, a.plastic_work, 1e-9);
}
