// A rigid ball dropped on an elastic block through *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE (issue
// 20). The ball is a coarse hexahedral sphere (a 2 x 2 x 2 cube mapped onto the sphere: 8
// hexahedra, 27 nodes), radius 0.25, falling at v0 = 1 onto a 1 x 0.2 x 1 block of 4 x 1 x 4
// elastic hexahedra fixed at its base; no gravity. Energy balance of the impact: once the ball has
// left, its kinetic energy is what it brought in less what stays in the block (its kinetic,
// strain, hourglass and bulk-viscosity energies, each measured on the block alone) and less what
// the contact kept (the dashpot's work with VDC > 0; zero otherwise): restitution^2 =
// 1 - (E_block + E_contact) / E_0. Checked with VDC = 0 (elastic: the restitution just below 1 by
// the energy left ringing in the block) and VDC = 20 (lower), aligned and rotated.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "general_contact_models.hpp"

namespace slideline {
namespace {

using test_support::add_box;
using test_support::add_elastic_part;
using test_support::BoxIds;
using test_support::Frame;

constexpr Real kRadius = 0.25, kV0 = 1.0, kGap = 0.01;

struct Drop {
  Real restitution = 0.0;  ///< rebound speed of the ball's centre / v0
  Real ball = 0.0;         ///< the ball's kinetic energy after the impact
  Real predicted = 0.0;    ///< E_0 - E_block - E_contact
  Real e0 = 0.0;           ///< the ball's kinetic energy before
  Real block = 0.0;        ///< energy left in the block
  Real contact = 0.0;      ///< energy kept by the contact (dashpot work)
};

/// The ball's nodes (deck ids), centred at `centre`, placed by `frame`.
std::vector<Id> add_ball(model::Model& m, const Vec3& centre, const Frame& frame) {
  const std::size_t first = m.nodes.size();
  const BoxIds cube = add_box(m, 1, Vec3(-1.0, -1.0, -1.0), Vec3(2.0, 2.0, 2.0), {2, 2, 2}, Frame{});
  for (std::size_t k = first; k < m.nodes.size(); ++k) {
    const Vec3 p = m.nodes[k].x;
    const Real n = p.norm();
    // The cube-to-sphere map: each node keeps its direction; its distance becomes r x its
    // largest coordinate (the centre stays, face centres land on the sphere, corners too).
    const Vec3 s = n > 0.0 ? Vec3(kRadius * p.cwiseAbs().maxCoeff() / n * p) : Vec3::Zero();
    m.nodes[k].x = frame.map(centre + s);
  }
  return cube.node;
}

Drop drop(Real vdc, const Frame& frame) {
  model::Model m;
  m.materials.push_back(model::MatRigid{1, 1.0, 1000.0, 0.3, 0.0, 0, 0, "ball", {}});
  m.solid_sections.push_back({1, 1, {}});
  m.parts.push_back({1, "ball", 1, 1, 0, 0, {}});
  add_elastic_part(m, 2, 1.0, 1000.0, 0.3);
  const BoxIds block = add_box(m, 2, Vec3(0.0, 0.0, 0.0), Vec3(1.0, 0.2, 1.0), {4, 1, 4}, frame);
  // The lowest point of the ball over the inside of a block segment (not on a node or edge).
  const std::vector<Id> ball = add_ball(m, Vec3(0.53, 0.2 + kRadius + kGap, 0.47), frame);
  m.node_sets.push_back({3, "block_base", block.face_j(0), {}});
  m.spcs.push_back({1, "block_base_fixed", 3, 0, {1, 1, 1, 0, 0, 0}, {}});
  const Vec3 up = frame.map(Vec3::UnitY());
  for (Id id : ball) m.initial_velocity_nodes.push_back({id, -kV0 * up, Vec3::Zero(), {}});
  model::Contact card;
  card.keyword = "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE";
  card.title = "ball_on_block";
  card.type = model::ContactType::automatic;
  card.form = model::ContactForm::automatic_surface_to_surface;
  card.ssid = 1;
  card.sstyp = 3;
  card.msid = 2;
  card.mstyp = 3;
  card.vdc = vdc;
  m.contacts.push_back(card);
  m.termination.endtim = 0.5;  // contact over by about 0.3 (measured below: the ball is free again)
  m.timestep.tssfac = 0.6;     // Type 12's (the spec's)

  test_support::Run run(m);
  const auto kinetic = [&](const std::vector<Id>& ids) {
    Real e = 0.0;
    for (Id id : ids) e += 0.5 * run.mass(id) * run.v(id).squaredNorm();
    return e;
  };
  Drop d;
  d.e0 = kinetic(ball);
  while (run.sim->step()) {
  }
  EXPECT_EQ(run.sim->contacts()[0].slave_force().norm(), 0.0) << "the ball has not left";
  const EnergyReport& e = run.sim->energy();
  d.ball = kinetic(ball);
  d.block = kinetic(block.node) + e.internal + e.hourglass + e.bulk_viscosity + e.damping;
  d.contact = e.contact;
  d.predicted = d.e0 - d.block - d.contact;
  d.restitution = run.mean(ball, [&](Id id) { return run.v(id); }).dot(up) / kV0;
  return d;
}

// Tolerance: the ball's energy within 1e-3 of E_0 of the prediction (the run's energy balance
// error; measured below).
TEST(BallDrop, ReboundMatchesTheEnergyLeftInTheBlockAndTheContact) {
  for (const bool rotated : {false, true}) {
    const Frame frame = rotated ? test_support::oblique_frame() : Frame{};
    const Drop elastic = drop(0.0, frame), damped = drop(20.0, frame);
    for (const auto& [vdc, d] : {std::pair{0, elastic}, std::pair{20, damped}}) {
      std::printf("%s VDC %2d: restitution %.5f  E_ball %.6e  predicted %.6e (E_0 %.6e, block %.3e, contact %.3e)\n",
                  rotated ? "rotated" : "aligned", vdc, d.restitution, d.ball, d.predicted, d.e0, d.block,
                  d.contact);
      EXPECT_NEAR(d.ball, d.predicted, 1e-3 * d.e0) << "VDC " << vdc;
    }
    EXPECT_GT(elastic.restitution, 0.5);
    EXPECT_LT(elastic.restitution, 1.0);
    EXPECT_LT(damped.restitution, elastic.restitution);
    EXPECT_GT(damped.contact, 0.0);
  }
}

}  // namespace
}  // namespace slideline
