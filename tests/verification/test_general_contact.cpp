// Two identical elastic bars colliding end on (issue 18, part 1), with every interface type that
// applies (3, 5, 10, 12; penalty and Lagrange), flush (both sections equal: the striker's
// perimeter nodes lie on the target's side faces) and non-flush (target 0.1 % wider), each also
// rotated about an oblique axis. Closed form (1D elastic waves, nu = 0 so the hexahedra carry a
// plane wave exactly): contact lasts 2L/c, the force is the impedance plateau
// v0 Z1 Z2 / (Z1 + Z2) (rho c A v0 / 2 for equal bars), and the bars exchange velocities.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "general_contact_models.hpp"

namespace slideline {
namespace {

using test_support::add_box;
using test_support::add_elastic_part;
using test_support::BoxIds;
using test_support::ContactChoice;
using test_support::Frame;

// Bars: L = 1 along x, square section a = 0.2 meshed 2 x 2 (3 x 3 nodes on the end faces), 20
// elements along; E = 1000, rho = 1, nu = 0: c = sqrt(E / rho) = 31.62, 2L/c = 0.0632.
constexpr Real kA = 0.2, kE = 1000.0, kRho = 1.0;
constexpr Real kL = 1.0;
// v0 = 0.1: strain v0 / 2c = 1.6e-3. At v0 = 1 (strain 1.6e-2) the finite-strain response of the
// elastic material already lowers the plateau by 1.2 % (Lagrange, measured; 1.00002 at v0 = 0.01).
constexpr Real kV0 = 0.1;
constexpr int kAlong = 20, kAcross = 2;
constexpr Real kGap = 0.005;  // initial gap (0.1 element): contact starts at t0 = kGap / v0

struct BarCase {
  ContactChoice contact;
  bool flush = true;
  bool rotated = false;
  std::string name() const {
    return contact.name() + (flush ? "_flush" : "_wider") + (rotated ? "_rotated" : "");
  }
};

struct BarResult {
  Real plateau = 0.0;        ///< mean contact force over the middle half of 2L/c (force)
  Real duration = 0.0;       ///< time the force is above half the closed-form plateau (time)
  Real v_striker = 0.0, v_target = 0.0;  ///< mean velocities along the axis at the end
  Real max_penetration = 0.0;  ///< deepest striker end-face node into the target's end plane
  Real z_striker = 0.0, z_target = 0.0;  ///< impedances rho c A
};

BarResult run_bars(const BarCase& bc) {
  const Frame frame = bc.rotated ? test_support::oblique_frame() : Frame{};
  model::Model m;
  add_elastic_part(m, 1, kRho, kE, 0.0);
  add_elastic_part(m, 2, kRho, kE, 0.0);
  const Real wide = bc.flush ? kA : 1.001 * kA;
  const Real off = 0.5 * (wide - kA);
  const BoxIds striker = add_box(m, 1, Vec3(0.0, 0.0, 0.0), Vec3(kL, kA, kA), {kAlong, kAcross, kAcross}, frame);
  const BoxIds target =
      add_box(m, 2, Vec3(kL + kGap, -off, -off), Vec3(kL, wide, wide), {kAlong, kAcross, kAcross}, frame);
  const Vec3 e = frame.map(Vec3::UnitX());
  for (Id id : striker.node) m.initial_velocity_nodes.push_back({id, kV0 * e, Vec3::Zero(), 0, 0});
  std::vector<Id> striker_nodes = striker.node;
  m.node_sets.push_back({1, "striker", striker_nodes, {}});
  m.part_sets.push_back({2, "bars", {1, 2}, {}});
  m.contacts.push_back(test_support::contact_card(bc.contact, 1, 2, 1, 2, 0.0));
  const Real c = std::sqrt(kE / kRho);
  const Real t_contact = 2.0 * kL / c, t0 = kGap / kV0;
  m.termination.endtim = t0 + 1.6 * t_contact;
  // TSSFAC 0.5, as for an impact: the penalty springs set the step here, and at 0.9 of their
  // critical step the interface chatters at the Nyquist frequency (plateau 0.94-1.02, force
  // swinging 0-4x; docs/verification.md). Lagrange is the same at 0.9.
  m.timestep.tssfac = 0.5;

  test_support::Run run(m);
  BarResult r;
  r.z_striker = kRho * c * kA * kA;
  r.z_target = kRho * c * wide * wide;
  const Real f_exact = kV0 * r.z_striker * r.z_target / (r.z_striker + r.z_target);
  auto momentum = [&]() {
    Real p = 0.0;
    for (Id id : striker.node) p += run.mass(id) * run.v(id).dot(e);
    return p;
  };
  const std::vector<Id> face = striker.face_i(kAlong), tface = target.face_i(0);
  const Real ta = t0 + 0.25 * t_contact, tb = t0 + 0.75 * t_contact;
  Real p_prev = momentum(), t_prev = 0.0, pa = 0.0, pb = 0.0, ta_step = ta, tb_step = tb;
  Real first = -1.0, last = -1.0;
  while (run.sim->step()) {
    const Real t = run.sim->time(), p = momentum();
    const Real f = -(p - p_prev) / (t - t_prev);  // the contact force is the striker's only load
    if (f > 0.5 * f_exact) {
      if (first < 0.0) first = t;
      last = t;
    }
    if (t_prev < ta && t >= ta) pa = p, ta_step = t;  // the window is the steps' own times
    if (t_prev < tb && t >= tb) pb = p, tb_step = t;
    Real plane = 0.0;
    for (Id id : tface) plane += run.x(id).dot(e);
    plane /= static_cast<Real>(tface.size());
    for (Id id : face) r.max_penetration = std::max(r.max_penetration, run.x(id).dot(e) - plane);
    p_prev = p;
    t_prev = t;
  }
  r.plateau = (pa - pb) / (tb_step - ta_step);
  r.duration = last - first;
  r.v_striker = run.mean(striker.node, [&](Id id) { return run.v(id); }).dot(e);
  r.v_target = run.mean(target.node, [&](Id id) { return run.v(id); }).dot(e);
  return r;
}

class BarImpact : public ::testing::TestWithParam<BarCase> {};

// Tolerances (see docs/verification.md, "General contact"):
// - plateau 0.5 %: the mean over the middle half of the contact; the discrete wave rings behind
//   its front but has no systematic error (a 1D chain of the same elements: 1.0002); measured
//   0.998-0.999 for every type; OpenRadioss TYPE7 1.2 %.
// - duration 2.5 %: the half-height crossings of the front and of the unloading wave are each
//   smeared over about one element transit time (h / c = 2.5 % of 2L/c with 20 elements).
// - velocities 3 % of v0: the dispersive tail of the discrete wave still in the striker when it
//   separates (the 1D chain keeps 2.0 % of v0 in the striker).
// - penetration of the striker's end-face nodes (perimeter included) 5 % of an element length
//   (penalty: the plateau's share of a node over its spring, 0.4 % of h; Lagrange: none; with
//   the nearest-segment rule the perimeter nodes sank 20-30 % of h).
TEST_P(BarImpact, PlateauDurationAndExchangeMatchTheWaveSolution) {
  const BarCase bc = GetParam();
  const BarResult r = run_bars(bc);
  const Real c = std::sqrt(kE / kRho);
  const Real f_exact = kV0 * r.z_striker * r.z_target / (r.z_striker + r.z_target);
  const Real t_exact = 2.0 * kL / c;
  std::printf("%-34s plateau %.5f (x%.5f)  duration x%.4f  v_striker %.4f  v_target %.4f  penetration %.3e h\n",
              bc.name().c_str(), r.plateau, r.plateau / f_exact, r.duration / t_exact, r.v_striker / kV0,
              r.v_target / kV0, r.max_penetration / (kL / kAlong));
  EXPECT_NEAR(r.plateau / f_exact, 1.0, 0.005);
  EXPECT_NEAR(r.duration / t_exact, 1.0, 0.025);
  EXPECT_NEAR(r.v_striker / kV0, 0.0, 0.03);
  EXPECT_NEAR(r.v_target / kV0, 1.0, 0.03);
  EXPECT_LT(r.max_penetration, 0.05 * kL / kAlong);
}

std::vector<BarCase> bar_cases() {
  std::vector<BarCase> out;
  for (const ContactChoice& c : test_support::all_contact_choices())
    for (bool flush : {true, false})
      for (bool rotated : {false, true}) out.push_back({c, flush, rotated});
  return out;
}

INSTANTIATE_TEST_SUITE_P(EveryType, BarImpact, ::testing::ValuesIn(bar_cases()),
                         [](const ::testing::TestParamInfo<BarCase>& info) { return info.param.name(); });

}  // namespace
}  // namespace slideline
