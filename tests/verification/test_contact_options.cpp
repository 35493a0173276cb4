// Contact options on a rigid cube dropped on a fixed rigid plate (issue 20).
// 1. Viscous contact damping (VDC, *CONTACT_... card 2): a rigid cube dropped on a fixed rigid plate
// through a penalty contact is a single mass on the springs k_i and dashpots c_i of its four
// bottom nodes (c_i = VDC/100 x 2 m omega_i, docs/contact.md "Viscous contact damping"). Closed
// form of that oscillator with a force that cannot pull (f = K x + C x' >= 0, x the penetration):
// x = v0/wd e^(-z wn t) sin(wd t) until f = 0 at wd t* = pi - atan(2 z sqrt(1 - z^2) / (1 - 2 z^2)),
// then the cube leaves at e v0, e = e^(-z wn t*) (z wn / wd sin(wd t*) - cos(wd t*)). VDC = 0
// gives e = 1; e falls as VDC rises. Each also in a rotated copy.
// 2. Zero means default: *CONTROL_CONTACT SLSFAC = 0.0 through *CONTACT_AUTOMATIC_SINGLE_SURFACE
// (the ball on a plate, which passed through with a zero stiffness) runs bitwise as 0.1
// and bounces.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "general_contact_models.hpp"
#include "slideline/contact/penalty_contact.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/io/keyword_writer.hpp"

namespace slideline {
namespace {

using test_support::add_box;
using test_support::BoxIds;
using test_support::Frame;

constexpr Real kV0 = 1.0;     // impact speed (length / time)
constexpr Real kGap = 0.01;   // initial gap: contact at t = 0.01

struct Bounce {
  Real restitution = 0.0;  ///< rebound speed / impact speed, measured
  Real expected = 0.0;     ///< the closed form above for the run's K, C and M
  Real zeta = 0.0;         ///< C / (2 sqrt(K M))
};

/// Restitution of the closed-form oscillator of mass m, stiffness k, damping c, force >= 0.
Real restitution(Real m, Real k, Real c) {
  const Real wn = std::sqrt(k / m), z = c / (2.0 * std::sqrt(k * m));
  const Real wd = wn * std::sqrt(1.0 - z * z);
  const Real t = (std::numbers::pi - std::atan2(2.0 * z * std::sqrt(1.0 - z * z), 1.0 - 2.0 * z * z)) / wd;
  return std::exp(-z * wn * t) * (z * wn / wd * std::sin(wd * t) - std::cos(wd * t));
}

/// The cube (part 1, nodes `cube`) above the plate (part 2), falling at v0; no contact yet.
model::Model cube_over_plate(const Frame& frame, BoxIds& cube) {
  model::Model m;
  // Part 1: the rigid unit cube (mass 1), free; part 2: a rigid 2 x 0.5 x 2 plate, held fixed.
  m.materials.push_back(model::MatRigid{1, 1.0, 1000.0, 0.25, 0.0, 0, 0, "cube", {}});
  m.materials.push_back(model::MatRigid{2, 1.0, 1000.0, 0.25, 1.0, 7, 7, "plate", {}});
  for (Id pid : {1, 2}) {
    m.solid_sections.push_back({pid, 1, {}});
    m.parts.push_back({pid, "part" + std::to_string(pid), pid, pid, 0, 0, {}});
  }
  add_box(m, 2, Vec3(0.0, 0.0, 0.0), Vec3(2.0, 0.5, 2.0), {1, 1, 1}, frame);
  cube = add_box(m, 1, Vec3(0.5, 0.5 + kGap, 0.5), Vec3(1.0, 1.0, 1.0), {1, 1, 1}, frame);
  const Vec3 up = frame.map(Vec3::UnitY());
  for (Id id : cube.node) m.initial_velocity_nodes.push_back({id, -kV0 * up, Vec3::Zero(), {}});
  m.termination.endtim = 0.12;  // contact lasts about 0.07
  // About 250 steps in contact: the closed form is the continuous oscillator.
  m.timestep.tssfac = 0.01;
  return m;
}

Bounce drop(Real vdc, const Frame& frame) {
  BoxIds cube;
  model::Model m = cube_over_plate(frame, cube);
  const Vec3 up = frame.map(Vec3::UnitY());
  test_support::ContactChoice one_way{model::ContactType::one_way, model::Enforcement::penalty};
  model::Contact card = test_support::contact_card(one_way, 1, 2, 0, 0, 0.0);
  card.sfs = card.sfm = 1.0;  // f = SLSFAC = 0.1
  card.vdc = vdc;
  m.contacts.push_back(card);

  test_support::Run run(m);
  const PenaltyPass& pass = penalty_passes_of(run.sim->contacts()[0])->pass(0);
  Bounce b;
  Real k_total = 0.0, c_total = 0.0, mass = 0.0;
  for (Id id : cube.node) mass += run.mass(id);
  while (run.sim->step()) {
    if (k_total > 0.0) continue;
    // The first cycle in contact: each engaged bottom node's spring and dashpot, from its master
    // point (the shape functions at its closest point on the plate's one segment).
    for (std::size_t i = 0; i < pass.slaves().size(); ++i) {
      const PenaltyRecord& r = pass.records()[i];
      if (r.segment < 0) continue;
      const Index s = pass.slaves()[i];
      const Real k = pass.segment_stiffness(r.segment);
      const Real ms = run.sim->nodes().mass[static_cast<std::size_t>(s)];
      Real inv_master = 0.0;
      const Index* c = &pass.master().conn[4 * static_cast<std::size_t>(r.segment)];
      for (int a = 0; a < 4; ++a) inv_master += r.shape[a] * r.shape[a] / run.sim->nodes().mass[c[a]];
      k_total += k;
      c_total += vdc / 100.0 * 2.0 * std::min(ms, 1.0 / inv_master) * std::sqrt(k * (1.0 / ms + inv_master));
    }
  }
  EXPECT_GT(k_total, 0.0);
  b.restitution = run.mean(cube.node, [&](Id id) { return run.v(id); }).dot(up) / kV0;
  b.expected = restitution(mass, k_total, c_total);
  b.zeta = c_total / (2.0 * std::sqrt(k_total * mass));
  return b;
}

// Tolerance 0.1 % of v0: the discrete oscillator (about 250 steps in contact, the dashpot on the
// velocity half a step behind, contact starting and ending within a step); measured 1e-4.
TEST(ContactDamping, RestitutionOfADroppedRigidCubeMatchesTheDampedOscillator) {
  for (const bool rotated : {false, true}) {
    const Frame frame = rotated ? test_support::oblique_frame() : Frame{};
    Real previous = 2.0;
    for (const Real vdc : {0.0, 10.0, 40.0}) {
      const Bounce b = drop(vdc, frame);
      std::printf("%s VDC %4.0f: zeta %.4f  restitution %.5f  closed form %.5f\n", rotated ? "rotated" : "aligned", vdc,
                  b.zeta, b.restitution, b.expected);
      EXPECT_NEAR(b.restitution, b.expected, 1e-3) << "VDC " << vdc << (rotated ? " rotated" : "");
      EXPECT_LT(b.restitution, previous);  // more damping, a lower bounce
      previous = b.restitution;
    }
  }
}

/// Rebound speed / v0 of the cube through Type 12 (both parts one single surface), the model
/// written to a deck with `slsfac` in *CONTROL_CONTACT and read back.
Real automatic_bounce(Real slsfac, Real& slsfac_read) {
  BoxIds cube;
  model::Model m = cube_over_plate(Frame{}, cube);
  m.part_sets.push_back({1, "both", {1, 2}, {}});
  test_support::ContactChoice automatic{model::ContactType::automatic, model::Enforcement::penalty};
  model::Contact card = test_support::contact_card(automatic, 1, 2, 0, 1, 0.0);
  card.sfs = card.sfm = 1.0;
  m.contacts.push_back(card);
  m.control_contact.slsfac = slsfac;
  const model::Model read = read_keyword_string(write_keyword_string(m), "ball_on_plate.k");
  slsfac_read = read.control_contact.slsfac;
  test_support::Run run(read);
  while (run.sim->step()) {
  }
  return run.mean(cube.node, [&](Id id) { return run.v(id); })[1] / kV0;
}

TEST(ContactZeroDefaults, SlsfacZeroBouncesAsTheDefault) {
  Real read_zero = 0.0, read_default = 0.0;
  const Real zero = automatic_bounce(0.0, read_zero), dflt = automatic_bounce(0.1, read_default);
  std::printf("SLSFAC 0.0 (read as %g): rebound %.6f; SLSFAC 0.1: rebound %.6f\n", read_zero, zero, dflt);
  EXPECT_EQ(read_zero, 0.1);
  EXPECT_EQ(zero, dflt);        // the same run, bit for bit
  EXPECT_NEAR(dflt, 1.0, 0.01);  // elastic bounce (the oscillator's e = 1), not a pass-through (-1)
}

}  // namespace
}  // namespace slideline
