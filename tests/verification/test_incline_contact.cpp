// A block sliding down an inclined plane under gravity with Coulomb friction (issue 18, part 2),
// with every interface type that applies (3, 5, 10, 12; penalty and Lagrange), each also rotated
// about an oblique axis. The plane's nodes form rows every 0.5 across the slope; the block's
// edges cross three of them. Closed form (rigid block, constant mu): the acceleration along the
// slope is a = g (sin theta - mu cos theta) while sliding; gravity is ramped up over t_r, so
// x(t) = a (t^2 / 2 - t_r t / 2 + t_r^2 / 6) for t >= t_r. For tan theta < mu the block sticks and
// friction carries m g sin theta.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "general_contact_models.hpp"

namespace slideline {
namespace {

using test_support::add_box;
using test_support::add_elastic_part;
using test_support::BoxIds;
using test_support::ContactChoice;
using test_support::Frame;

constexpr Real kG = 10.0, kMu = 0.3, kRamp = 0.02, kEnd = 1.0;

struct InclineCase {
  ContactChoice contact;
  Real degrees = 35.0;
  bool rotated = false;
  std::string name() const {
    return contact.name() + "_" + std::to_string(static_cast<int>(degrees)) + "deg" + (rotated ? "_rotated" : "");
  }
};

struct InclineResult {
  Real slide = 0.0;      ///< mean block displacement along the slope at kEnd (length)
  Real lift = 0.0;       ///< largest mean displacement of the block off the plane (length)
  Real half = 0.0;       ///< the slide at kEnd / 2 (length)
  Real exact = 0.0;      ///< closed-form slide (0 when sticking)
  Real mass = 0.0;       ///< the block's mass
  Real friction = 0.0;   ///< friction dissipation at kEnd (energy)
  Real energy_error = 0.0;  ///< |balance error| / largest energy (Simulation::energy_error_fraction)
  Vec3 slave_force = Vec3::Zero(), master_force = Vec3::Zero();  ///< interface forces at kEnd
  Vec3 e = Vec3::UnitX(), n = Vec3::UnitY();  ///< down the slope, the plane's normal
};

// The plane: 3.0 x 0.25 x 1.0 (x along the slope, y its normal), 6 x 1 x 2 elements, every node
// fixed, top at y = 0. The block: 0.4 x 0.2 x 0.4, 2 x 1 x 2 elements, seated on the plane at
// x in [0.32, 0.72], z in [0.28, 0.68] (no node on a plane node or edge). Gravity in the plane's
// frame: g (sin theta, -cos theta, 0). Stiff elastic material (E = 1e5, rho = 1): the block's
// elastic deflection under its weight is 1e-6 of its size.
InclineResult run_incline(const InclineCase& ic) {
  const Frame frame = ic.rotated ? test_support::oblique_frame() : Frame{};
  model::Model m;
  // Stiffness hourglass control (the spec's type 10): with the default viscous form the friction
  // load drives the block's hourglass modes at a constant rate, which reads as a creep of
  // 4.9e-5 per unit time while every contact node sticks (measured, Types 3 and 12 alike).
  add_elastic_part(m, 1, 1.0, 1e5, 0.3, 10);
  add_elastic_part(m, 2, 1.0, 1e5, 0.3, 10);
  const BoxIds block = add_box(m, 1, Vec3(0.32, 0.0, 0.28), Vec3(0.4, 0.2, 0.4), {2, 1, 2}, frame);
  const BoxIds plane = add_box(m, 2, Vec3(0.0, -0.25, 0.0), Vec3(3.0, 0.25, 1.0), {6, 1, 2}, frame);
  m.node_sets.push_back({1, "block", block.node, {}});
  m.node_sets.push_back({3, "plane", plane.node, {}});
  m.part_sets.push_back({2, "pair", {1, 2}, {}});
  m.part_sets.push_back({4, "loaded", {1}, {}});
  m.spcs.push_back({1, "plane_fixed", 3, 0, {1, 1, 1, 0, 0, 0}, {}});
  m.contacts.push_back(test_support::contact_card(ic.contact, 1, 2, 1, 2, kMu));
  const Real th = ic.degrees * std::numbers::pi / 180.0;
  const Vec3 g = frame.map(kG * Vec3(std::sin(th), -std::cos(th), 0.0));
  m.curves.push_back({1, "ramp", 0, 1.0, 1.0, 0.0, 0.0, 0, {{0.0, 0.0}, {kRamp, 1.0}, {100.0, 1.0}}, {}});
  // *LOAD_BODY is a base acceleration: the force on a node is -m sf curve(t) along the axis.
  const Axis axes[3] = {Axis::x, Axis::y, Axis::z};
  for (int k = 0; k < 3; ++k) m.body_loads.push_back({axes[k], 1, -g[k], 0, 0, 0, 0, 0, {}});
  m.body_load_parts = model::LoadBodyParts{4, {}};
  m.termination.endtim = kEnd;
  m.timestep.tssfac = 0.9;

  test_support::Run run(m);
  const Vec3 e = frame.map(Vec3::UnitX()), n = frame.map(Vec3::UnitY());
  const Vec3 x0 = run.mean(block.node, [&](Id id) { return run.x(id); });
  InclineResult r;
  while (run.sim->step()) {
    const Vec3 d = run.mean(block.node, [&](Id id) { return run.x(id); }) - x0;
    r.lift = std::max(r.lift, d.dot(n));
    if (r.half == 0.0 && run.sim->time() >= 0.5 * kEnd) r.half = d.dot(e);
  }
  r.slide = (run.mean(block.node, [&](Id id) { return run.x(id); }) - x0).dot(e);
  for (Id id : block.node) r.mass += run.mass(id);
  r.friction = run.sim->energy().friction;
  r.energy_error = run.sim->energy_error_fraction();
  r.slave_force = run.sim->contacts()[0].slave_force();
  r.master_force = run.sim->contacts()[0].master_force();
  r.e = e;
  r.n = n;
  const Real a = kG * (std::sin(th) - kMu * std::cos(th));
  r.exact = a > 0.0 ? a * (kEnd * kEnd / 2 - kRamp * kEnd / 2 + kRamp * kRamp / 6) : 0.0;
  return r;
}

class Incline : public ::testing::TestWithParam<InclineCase> {};

// Tolerances (docs/verification.md, "Beyond the spec"):
// - 35 deg: 0.05 % of the slide. The penalty stick spring lags by at most its elastic slip
//   gamma = 1e-3 x the master's diagonal (7e-4, 4e-4 of the slide); Lagrange has none. Measured
//   3e-6 (penalty) and 1e-6 (Lagrange); OpenRadioss TYPE7 0.2 %.
// - 20 deg: 0.5 % (the same gamma is 0.24 % of this slide; measured 2.0e-4 to 2.4e-4; TYPE7 +1.3 %).
// - sticking (15 deg): the block moves less than 1e-5 (its elastic shear under the friction,
//   tau h / G = 2.7e-6 at its top, and the stick spring's F_t / k_t; measured 0.9e-6 to 1.1e-6)
//   and does not creep: |x(t) - x(t/2)| < 2e-7 (the residual elastic vibration; measured
//   3e-8 to 6e-8; 2.4e-5 with viscous hourglass control, see run_incline).
// - lift of the block off the plane below 1e-4 (a snag at a node row lifted it by 1e-3..5e-3).
TEST_P(Incline, SlidesAsTheRigidBlockSolution) {
  const InclineCase ic = GetParam();
  const InclineResult r = run_incline(ic);
  std::printf("%-36s slide %.6e exact %.6e (x%.6f)  lift %.2e  slide at t/2 %.3e\n", ic.name().c_str(), r.slide,
              r.exact, r.exact > 0 ? r.slide / r.exact : 0.0, r.lift, r.half);
  if (r.exact > 0.0) {
    EXPECT_NEAR(r.slide / r.exact, 1.0, ic.degrees > 30.0 ? 5e-4 : 5e-3);
  } else {
    EXPECT_LT(std::abs(r.slide), 1e-5);
    EXPECT_LT(std::abs(r.slide - r.half), 2e-7);
  }
  EXPECT_LT(r.lift, 1e-4);
}

std::vector<InclineCase> incline_cases() {
  std::vector<InclineCase> out;
  for (const ContactChoice& c : test_support::all_contact_choices())
    for (Real deg : {35.0, 20.0, 15.0})
      for (bool rotated : {false, true}) out.push_back({c, deg, rotated});
  return out;
}

INSTANTIATE_TEST_SUITE_P(EveryType, Incline, ::testing::ValuesIn(incline_cases()),
                         [](const ::testing::TestParamInfo<InclineCase>& info) { return info.param.name(); });

// *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE on the 35 deg incline, plain and rotated: the energy
// balance with its contact and friction terms, the friction dissipation against the closed form
// mu m g cos(theta) x slide, and the interface forces against the rigid block's: the plane pushes
// the block with m g cos(theta) along n and brakes it with mu m g cos(theta) up the slope (the
// block slides from kRamp on); the master side gets the opposite.
// Tolerances: dissipation 0.5 % (the stick spring's elastic slip, 1e-3 x the diagonal, is stored,
// not dissipated: 2e-3 of the slide); force 1 % of m g (the block rings on its contact springs;
// measured below); energy balance 1e-3 of the largest energy.
TEST(InclineAutomaticSurfaceToSurface, EnergyFrictionWorkAndForceBalance) {
  for (bool rotated : {false, true}) {
    InclineCase ic;
    ic.contact = {model::ContactType::automatic, model::Enforcement::penalty,
                  model::ContactForm::automatic_surface_to_surface};
    ic.rotated = rotated;
    const InclineResult r = run_incline(ic);
    const Real th = ic.degrees * std::numbers::pi / 180.0;
    const Real normal = r.mass * kG * std::cos(th);
    const Vec3 expected = normal * r.n - kMu * normal * r.e;
    const Real dissipated = kMu * normal * r.slide;
    std::printf("%s: friction work %.6e closed form %.6e (x%.5f)  energy error %.2e  force error %.2e m g  "
                "balance %.1e\n",
                ic.name().c_str(), r.friction, dissipated, r.friction / dissipated, r.energy_error,
                (r.slave_force - expected).norm() / (r.mass * kG), (r.slave_force + r.master_force).norm());
    EXPECT_NEAR(r.friction / dissipated, 1.0, 5e-3);
    EXPECT_LT(r.energy_error, 1e-3);
    EXPECT_LT((r.slave_force - expected).norm(), 1e-2 * r.mass * kG);
    EXPECT_LT((r.slave_force + r.master_force).norm(), 1e-12 * r.mass * kG);
  }
}

}  // namespace
}  // namespace slideline
