// Automatic tiebreak OPTION 1 ties formed at t = 0 off the master surface, under a rigid spin: the
// tie's offset turns with the master segment (sticking_tiebreak_contact.hpp, tie_offset.hpp;
// docs/contact.md, "Automatic tiebreak, OPTION 1 and 3").
//
// Two elastic blocks 1 x 0.5 x 1 (2 x 1 x 2 hexahedra of 0.5, IHQ 10; E = 1e4, rho = 1, nu = 0.3),
// the upper one h = 5e-4 above the lower (within the card's 1e-3 of the segment's diagonal, 7.1e-4:
// in contact at t = 0), so all 9 nodes of its bottom face stick where they are, h off the master
// face; SFS = SFM = 10. No support, no load: every node starts at omega x (x - c), omega = 1 about
// z through the centre of mass (the gap's direction turns), to t = 2 (115 degrees).
// Closed forms: the ties are springs; the upper block's centripetal force M_u omega^2 r_u = 0.1251
// (M_u = 0.5, r_u = 0.25 + h / 2) goes through them, applied suddenly at t = 0: the tie force
// oscillates about it (undamped), its time average is it. An offset kept in global components stretches each tie by
// 2 h sin(theta / 2) (7.1e-4 at a quarter turn), a total force kappa A x 7.1e-4 (kappa = f K A_seg /
// V_el / A_seg = 6.7e4 with f = 1, A = 1: 47). The pair stays rigid: internal energy ~ 0. IHQ 4
// (incremental stiffness): IHQ 10's total-displacement form is not rotation-invariant (its
// hourglass energy went negative at t = 0.53 here).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "slideline/contact/sticking_tiebreak_contact.hpp"
#include "tiebreak_blocks.hpp"

namespace slideline {
namespace {

using test_support::add_box;
using test_support::add_elastic_part;
using test_support::BoxIds;
using test_support::Frame;

constexpr Real kGap = 5e-4, kOmega = 1.0, kEnd = 2.0;
/// The upper block's centripetal force M_u omega^2 r_u, what the ties carry on average.
constexpr Real kStatic = 0.5 * kOmega * kOmega * (0.25 + 0.5 * kGap);

struct StuckSpin {
  Real tie_force = 0.0;  ///< largest |total tie force on the slaves|
  Real mean_force = 0.0; ///< its time average
  Real internal = 0.0;   ///< largest |internal energy| / KE0
  Real balance = 0.0;    ///< largest |balance error| / KE0
  Real sides = 0.0;      ///< largest |slave + master force| / |slave force|
  Index tied = 0, released = 0;
  Real angle = 0.0;
};

StuckSpin run_stuck(const Frame& frame) {
  model::Model m;
  add_elastic_part(m, 1, 1.0, 1e4, 0.3, 4);
  add_elastic_part(m, 2, 1.0, 1e4, 0.3, 4);
  const test_support::TiebreakBlocks blocks = test_support::add_gapped_blocks(m, frame, kGap);
  const BoxIds& l = blocks.lower;
  model::Contact card = test_support::tiebreak_card("option 1, spun", 1);
  card.ssid = 2;
  card.msid = 1;
  card.sfs = card.sfm = 10.0;
  m.contacts.push_back(card);
  const Vec3 centre = frame.map(Vec3(0.5, 0.5 + 0.5 * kGap, 0.5));
  const Vec3 omega = kOmega * frame.map(Vec3::UnitZ());
  for (const auto& nd : m.nodes) m.initial_velocity_nodes.push_back({nd.id, omega.cross(nd.x - centre), Vec3::Zero(), 0, 0});
  m.termination.endtim = kEnd;
  test_support::Run run(m);
  const auto& tb = dynamic_cast<const StickingTiebreakContact&>(run.sim->contacts()[0]);
  StuckSpin r;
  const Vec3 e0 = run.x(l.at(2, 0, 0)) - run.x(l.at(0, 0, 0));
  Real t_prev = 0.0;
  while (run.sim->step()) {
    const EnergyReport& e = run.sim->energy();
    r.tie_force = std::max(r.tie_force, tb.tie_slave_force().norm());
    r.mean_force += tb.tie_slave_force().norm() * (run.sim->time() - t_prev);
    t_prev = run.sim->time();
    r.internal = std::max(r.internal, std::abs(e.internal + e.hourglass) / e.kinetic0);
    r.balance = std::max(r.balance, std::abs(e.balance_error()) / e.kinetic0);
    const Vec3 fs = tb.slave_force(), fm = tb.master_force();
    if (fs.norm() > 0.0) r.sides = std::max(r.sides, (fs + fm).norm() / fs.norm());
  }
  r.mean_force /= t_prev;
  r.tied = tb.tied_count();
  r.released = tb.released_count();
  const Vec3 e1 = run.x(l.at(2, 0, 0)) - run.x(l.at(0, 0, 0));
  r.angle = std::acos(std::clamp(e0.normalized().dot(e1.normalized()), -1.0, 1.0));
  return r;
}

void expect_stuck(const StuckSpin& r, const std::string& what) {
  SCOPED_TRACE(what);
  std::printf("%s: tied %d released %d, tie force mean %.5f (static %.5f), largest %.4f, |IE|/KE0 %.3e, balance %.3e, sides %.3e, "
              "angle %.4f\n",
              what.c_str(), static_cast<int>(r.tied), static_cast<int>(r.released), r.mean_force, kStatic, r.tie_force,
              r.internal, r.balance, r.sides, r.angle);
  EXPECT_EQ(r.tied, 9);
  EXPECT_EQ(r.released, 0);
  EXPECT_NEAR(r.angle, kOmega * kEnd, 2e-3);
  EXPECT_NEAR(r.mean_force, kStatic, 0.05 * kStatic);
  EXPECT_LT(r.tie_force, 4.0 * kStatic);  // global offsets: 47 at a quarter turn
  EXPECT_LT(r.internal, 1e-3);
  EXPECT_LT(r.balance, 1e-3);
  EXPECT_LT(r.sides, 1e-9);
}

TEST(StickingOffsetRotation, Option1TiesOffTheSurfaceTurnWithTheSpinningPair) {
  expect_stuck(run_stuck(Frame{}), "option 1");
}

TEST(StickingOffsetRotation, TurnedCopy) {
  expect_stuck(run_stuck(test_support::oblique_frame()), "option 1, turned");
}

}  // namespace
}  // namespace slideline
