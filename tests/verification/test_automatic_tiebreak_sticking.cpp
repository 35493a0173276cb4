// *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK, OPTION 1 (blank / 0) and 3: ties formed at the
// first touch, against closed forms. docs/contact.md, "Automatic tiebreak, OPTION 1 and 3".
//
// Driven: a block (1 x 0.5 x 1, one hexahedron, the slave side its bottom face, area A = 1) stands
// g0 = 4e-3 above the middle of a plate (2 x 0.5 x 2, one hexahedron, fixed at its bottom; the
// master side its top face): not in contact at t = 0 (the tie search for OPTION 1 and 3 takes
// gaps up to 1e-3 of the segment's diagonal, 2.8e-3 here). The block's top is driven down (4 v to
// t = 0.6, then v = 1e-3), then from t = 2.35 back up at v (reversing over 0.1).
// - Touch: the bottom face has travelled g0 at t_c = 2.15 (kTouch); each node is tied in the very
//   cycle it is first below the plate's face (found by the pass: within one step, dt <= 3.3e-3, of
//   t_c), at the face's point below it (the shape functions the pass found). Tilted copy: the
//   block's x = 0 edge raised by 1e-4: that edge touches later than the other (by less than the
//   rigid block's 1e-4 / v: the elastic block pivots on its tied edge), each node again tied in the
//   cycle it first touches.
// - OPTION 1: the pull (up to 3 NFLS A at the end) never breaks the tie; the tie's force equals the
//   drive's reaction and the plate's support reaction (quasi-static: inertia m a ~ 0).
// - OPTION 3 (NFLS = 2): by symmetry the four ties carry the same force, so all fail in the cycle
//   their total tension reaches NFLS A = 2 (within one step's increase of it: the series stiffness
//   of tie, block and plate, ~9e3, x v dt ~ 1.3e-5: 0.7 %); afterwards
//   nothing holds the block (slave force exactly 0 in tension) and the interface opens.
// Both sides' forces are opposite (master_force = -slave_force to round-off); the energy balance
// counts the tie's work in the contact term. Each case also rotated about an oblique axis.
//
// Tied from t = 0: the two blocks of the other OPTIONs' checks (tiebreak_blocks.hpp, touching),
// OPTION 3 with SFLS = 1 and a tangential load T = 0.5 on the top (ramped over 0.1): the four
// nodes are tied at t = 0 and the block does not slide: the interface slip stays at the tie
// springs' T / (kappa A) = 3e-5 (kappa = f K A / V), where a frictionless contact would let the block
// slide T t^2 / (2 m) = 0.5 by t = 1.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <array>
#include <map>

#include "tiebreak_blocks.hpp"
#include "slideline/contact/sticking_tiebreak_contact.hpp"
#include "slideline/core/parallel.hpp"
#include "slideline/solver/energy_ledger.hpp"

namespace slideline {
namespace {

using test_support::add_box;
using test_support::add_elastic_part;
using test_support::BoxIds;
using test_support::Frame;
using test_support::tiebreak_card;
using State = StickingTiebreakContact::State;

constexpr Real kE = 1e4, kNu = 0.3, kRho = 1.0;
constexpr Real kGap = 4e-3, kSpeed = 1e-3, kRamp = 0.05, kTurn = 2.35;
// The drive: 4 v from 0.05 to 0.6, slowing to v by 0.7: the bottom face has then travelled
// 4 v (0.6 - kRamp / 2) + 2.5 v 0.1 and touches after the rest of g0 at v.
constexpr Real kTouch = 0.7 + (kGap - 4.0 * kSpeed * (0.6 - 0.5 * kRamp) - 2.5 * kSpeed * 0.1) / kSpeed;
constexpr Real kNfls = 2.0;

struct DriveCase {
  int option = 1;
  bool rotated = false;
  Real tilt = 0.0;  ///< the bottom face's x = 0 edge raised by this (length)
  std::string name() const {
    return "option" + std::to_string(option) + (tilt > 0.0 ? "_tilted" : "") + (rotated ? "_rotated" : "");
  }
};

struct DriveResult {
  Real first_tie = -1.0, last_tie = -1.0;  ///< earliest and latest tie time of the four nodes
  Real raised_tie = -1.0;     ///< tilted: the latest tie time of the raised edge's nodes
  Real tie_point = 0.0;       ///< largest |sum N_a x_a - the face's point below x_s| when tied
  Real first_touch = 0.0;     ///< largest |tie time - the first time the node was below the face|
  Index tied = 0, released = 0;
  Real failure_force = -1.0;  ///< OPTION 3: the ties' total tension in the cycle they failed
  Real pull = 0.0;            ///< the largest tie tension
  Real reaction = 0.0;        ///< |impulse of (tie force - drive reaction)|, likewise + support, / tension impulse, pulled
  Real side_balance = 0.0;    ///< largest |slave_force + master_force| / |slave_force|
  Real after = 0.0;           ///< OPTION 3: largest |slave force| after the failure
  Real opening = 0.0;         ///< the interface's opening at the end
  Real energy = 0.0;          ///< largest |energy balance error| / largest |support work|, touch to release
  Real energy_end = 0.0;      ///< the same at the end (OPTION 3: after the release)
  Real work = 0.0;            ///< the largest |support work|
  Real touch_error = 0.0;     ///< |energy balance error| when tied / kinetic energy before the touch
  std::vector<Real> history;  ///< the slave force per cycle (thread check)
};

DriveResult run_drive(const DriveCase& dc) {
  const Frame frame = dc.rotated ? test_support::oblique_frame() : Frame{};
  model::Model m;
  add_elastic_part(m, 1, kRho, kE, kNu, 10);
  add_elastic_part(m, 2, kRho, kE, kNu, 10);
  const BoxIds u = add_box(m, 1, Vec3(0.5, 0.5 + kGap, 0.5), Vec3(1.0, 0.5, 1.0), {1, 1, 1}, frame);
  for (auto& nd : m.nodes)
    if (nd.id == u.at(0, 0, 0) || nd.id == u.at(0, 0, 1)) nd.x += dc.tilt * frame.map(Vec3::UnitY());
  const BoxIds l = add_box(m, 2, Vec3(0.0, 0.0, 0.0), Vec3(2.0, 0.5, 2.0), {1, 1, 1}, frame);
  m.segment_sets.push_back({1, "slave", {{u.at(0, 0, 0), u.at(1, 0, 0), u.at(1, 0, 1), u.at(0, 0, 1)}}, {}});
  m.segment_sets.push_back({2, "master", {{l.at(0, 1, 0), l.at(0, 1, 1), l.at(1, 1, 1), l.at(1, 1, 0)}}, {}});
  m.node_sets.push_back({3, "top", u.face_j(1), {}});
  m.node_sets.push_back({4, "bottom", l.face_j(0), {}});
  m.spcs.push_back({1, "fixed", 4, 0, {1, 1, 1, 1, 1, 1}, {}});
  model::Contact card = tiebreak_card(dc.name(), dc.option);
  card.sfs = card.sfm = 10.0;
  if (dc.option == 3) card.nfls = card.nflf = kNfls;
  m.contacts.push_back(card);
  const Vec3 up = frame.map(Vec3::UnitY());
  const Real end = dc.option == 3 ? 3.3 : 3.8;
  m.curves.push_back({1, "velocity", 0, 1.0, 1.0, 0.0, 0.0, 0,
                      {{0.0, 0.0}, {kRamp, -4.0}, {0.6, -4.0}, {0.7, -1.0}, {kTurn, -1.0}, {kTurn + 0.1, 1.0},
                       {end + 1.0, 1.0}},
                      {}});
  for (int d = 0; d < 3; ++d) {
    model::PrescribedMotion p;
    p.target = model::PrescribedMotion::Target::set;
    p.nsid = 3;
    p.dof = d + 1;
    p.vad = 0;
    p.lcid = 1;
    p.sf = kSpeed * up[d];
    m.prescribed_motions.push_back(p);
  }
  m.termination.endtim = end;
  // The run's energy stop (5 % of the largest energy in play by default) is set to 50 %: this test
  // judges the balance itself, after the touch, against the work done then (r.energy below). The
  // energy in play at the touch is small (the drive has slowed to v: 2.9e-7 against the 4.3e-6 of
  // the 4 v phase), and the cycle a tie forms kicks the node back to the face with a spring at
  // omega dt ~ 1.8, which leaves the central difference's own term m (dv)^2 / 8 in the balance
  // (docs/solver.md, "The discrete energy identity"): 1.1 % of that largest energy in the straight
  // OPTION 3 case and 5.5 % in the turned one, whose touch falls at another phase of the step
  // (measured 2026-11-27 with the contact step counting the elements; each spring voting alone
  // left it below 5 %).
  m.termination.endeng = 50.0;

  test_support::Run run(m);
  const auto& tb = dynamic_cast<const StickingTiebreakContact&>(run.sim->contacts()[0]);
  const std::vector<Id> slave_nodes = u.face_j(0), master_nodes = l.face_j(1);
  const Real t_touch = kTouch;
  DriveResult r;
  bool pulling = false;
  Vec3 tie_impulse = Vec3::Zero(), drive_impulse = Vec3::Zero(), support_impulse = Vec3::Zero();
  Real tension_impulse = 0.0, largest_work = 0.0, largest_error = 0.0, end_error = 0.0, kinetic_before = 0.0, touch_error = -1.0;
  // Each slave node against the plate's face as it is (its plane: the face's centroid and normal):
  // the first time it is below it. A step ends with the force evaluation at its new positions,
  // where the pass finds a touch and the tie forms: those are the positions seen after it.
  const std::array<Id, 4> face{l.at(0, 1, 0), l.at(0, 1, 1), l.at(1, 1, 1), l.at(1, 1, 0)};
  std::map<Id, Vec3> prev;
  const auto snapshot = [&] {
    for (Id id : slave_nodes) prev[id] = run.x(id);
    for (Id id : face) prev[id] = run.x(id);
  };
  const auto gap = [&](const std::map<Id, Vec3>& x, Id id, Vec3& n) {
    n = (x.at(face[2]) - x.at(face[0])).cross(x.at(face[3]) - x.at(face[1])).normalized();
    const Vec3 c = 0.25 * (x.at(face[0]) + x.at(face[1]) + x.at(face[2]) + x.at(face[3]));
    return (x.at(id) - c).dot(n);
  };
  std::map<Id, Real> below;  // the first time each slave node was below the face
  std::map<Id, bool> checked;
  while (run.sim->step()) {
    snapshot();
    for (Id id : slave_nodes) {
      Vec3 n;
      if (!below.count(id) && gap(prev, id, n) < 0.0) below[id] = run.sim->time();
    }
    for (std::size_t i = 0; i < tb.pass_slaves().size(); ++i) {
      const Id id = run.sim->nodes().ids[tb.pass_slaves()[i]];
      if (tb.tie_times()[i] < 0.0 || checked[id]) continue;
      checked[id] = true;
      Vec3 n;
      const Real g = gap(prev, id, n);
      const TiePoint& tp = tb.ties()[i];
      Vec3 xp = Vec3::Zero();
      for (int a = 0; a < 4; ++a)
        xp += tp.shape[static_cast<std::size_t>(a)] * prev.at(run.sim->nodes().ids[tp.master[static_cast<std::size_t>(a)]]);
      r.tie_point = std::max(r.tie_point, (xp - (prev.at(id) - g * n)).norm());  // the face's point below it
      if (tb.tie_times()[i] > 0.0)
        r.first_touch = std::max(r.first_touch, std::abs(tb.tie_times()[i] - (below.count(id) ? below[id] : -1.0)));
    }

    const Real t = run.sim->time();
    const Vec3 f = tb.slave_force();
    for (int d = 0; d < 3; ++d) r.history.push_back(f[d]);
    if (f.norm() > 0.0) r.side_balance = std::max(r.side_balance, (f + tb.master_force()).norm() / f.norm());
    const Real tension = -tb.tie_slave_force().dot(up);  // the ties pull the block down when stretched
    if (dc.option == 3 && r.failure_force < 0.0 && tb.released_count() > 0) r.failure_force = tension;
    if (r.failure_force < 0.0 || dc.option == 1) r.pull = std::max(r.pull, tension);
    if (dc.option == 3 && r.failure_force >= 0.0 && tb.released_count() == 4 && tension == 0.0)
      r.after = std::max(r.after, std::abs(f.dot(up)));
    // Pulled (from a tension of a quarter of NFLS A to the failure or the end): the impulses of the
    // ties' force, the drive's reaction and the plate's support reaction (momentum balance of each
    // block; the blocks' ringing on the ties averages out of these sums).
    if (tension > 0.25 * kNfls) pulling = true;
    if (pulling && tb.released_count() == 0) {
      const auto& supports = run.sim->supports();
      Vec3 drive = Vec3::Zero();
      for (std::size_t g = 1; g < supports.size(); ++g) drive += supports[g].reaction;
      const Real dt = run.sim->dt();
      tie_impulse += dt * tb.slave_force();  // on the block, from the plate
      drive_impulse += dt * drive;            // what the block exerts on the drive
      support_impulse += dt * supports[0].reaction;
      tension_impulse += dt * tension;
    }
    const EnergyReport& e = run.sim->energy();
    if (t > t_touch) largest_work = std::max(largest_work, std::abs(e.external + e.support));
    if (t > t_touch && tb.released_count() == 0) largest_error = std::max(largest_error, std::abs(e.balance_error()));
    end_error = std::abs(e.balance_error());
    if (t < t_touch - 0.01) kinetic_before = e.kinetic;
    if (tb.tied_count() > 0 && touch_error < 0.0) touch_error = std::abs(e.balance_error());
  }
  r.reaction = std::max((tie_impulse - drive_impulse).norm(), (tie_impulse + support_impulse).norm()) / tension_impulse;
  r.energy = largest_error / largest_work;
  r.energy_end = end_error / largest_work;
  r.work = largest_work;
  r.touch_error = touch_error / kinetic_before;
  r.tied = tb.tied_count();
  r.released = tb.released_count();
  const auto slaves = tb.pass_slaves();
  for (std::size_t i = 0; i < slaves.size(); ++i) {
    if (tb.tie_times()[i] < 0.0) continue;
    const Real tt = tb.tie_times()[i];
    const Id sid = run.sim->nodes().ids[slaves[i]];
    if (sid == u.at(0, 0, 0) || sid == u.at(0, 0, 1)) r.raised_tie = std::max(r.raised_tie, tt);
    r.first_tie = r.first_tie < 0.0 ? tt : std::min(r.first_tie, tt);
    r.last_tie = std::max(r.last_tie, tt);
  }
  r.opening = (run.mean(slave_nodes, [&](Id id) { return run.x(id); }) -
               run.mean(master_nodes, [&](Id id) { return run.x(id); })).dot(up);
  return r;
}

class AutomaticTiebreakSticking : public ::testing::TestWithParam<DriveCase> {};

TEST_P(AutomaticTiebreakSticking, TiesAtTheTouchThenHoldsOrFails) {
  const DriveCase dc = GetParam();
  const DriveResult r = run_drive(dc);
  const Real t_touch = kTouch;
  std::printf("%-16s tied %ld at t = %.5f..%.5f (closed form %.5f), tie point off by %.2e, tie time - first "
              "time below the face %.1e\n",
              dc.name().c_str(), static_cast<long>(r.tied), r.first_tie, r.last_tie, t_touch, r.tie_point,
              r.first_touch);
  std::printf("%-16s largest pull %.4f, failure at %.5f (NFLS A %.1f), released %ld, reaction mismatch %.2e, "
              "sides %.1e, after %.1e, opening %.3e, energy %.2e, at the end %.2e of %.3e (at the touch %.2e of the kinetic energy)\n",
              dc.name().c_str(), r.pull, r.failure_force, kNfls, static_cast<long>(r.released), r.reaction,
              r.side_balance, r.after, r.opening, r.energy, r.energy_end, r.work, r.touch_error);
  EXPECT_EQ(r.tied, 4);
  EXPECT_GT(r.first_tie, t_touch - 1e-3);  // not before (the ramp's ringing moves the face by ~1e-8)
  if (dc.tilt > 0.0) {
    // The raised edge touches later; when depends on how the block pivots on its tied edge (the
    // rigid figure tilt / v is an upper bound: the elastic block's free edge runs ahead of its top).
    std::printf("%-16s raised edge tied at t = %.5f (rigid block: %.5f)\n", dc.name().c_str(), r.raised_tie,
                t_touch + dc.tilt / kSpeed);
    EXPECT_LT(r.first_tie, t_touch + 4e-3);
    EXPECT_GT(r.raised_tie, t_touch + 0.25 * dc.tilt / kSpeed);
    EXPECT_LT(r.raised_tie, t_touch + dc.tilt / kSpeed);
  } else {
    EXPECT_LT(r.last_tie, t_touch + 4e-3);  // the cycle of the first penetration (dt <= 3.3e-3)
  }
  EXPECT_LT(r.tie_point, 1e-9);
  EXPECT_EQ(r.first_touch, 0.0);  // tied in the cycle it is first found below the face
  EXPECT_LT(r.side_balance, 1e-12);
  EXPECT_LT(r.reaction, 2e-2);  // the blocks' ringing momentum at the window's ends (short for OPTION 3)
  EXPECT_LT(r.energy, 2e-3);  // the interface ringing on the stiff closing spring (omega dt ~ 1.7)
  if (dc.option != 3) {
    EXPECT_EQ(r.released, 0);
    EXPECT_GT(r.pull, 3.0 * kNfls);  // far past what OPTION 3 below holds
    EXPECT_LT(r.opening, 1e-3);      // held: the tie stretch only (pull / (kappa A) ~ 1e-4)
  } else {
    EXPECT_EQ(r.released, 4);
    EXPECT_NEAR(r.failure_force / kNfls, 1.0, 1e-2);
    // The release drops the ties' stored energy F^2 / (2 kappa A) (kappa A = f K A_plate / V_plate x
    // A = 1.67e4) in one step: the balance moves by a small part of it.
    const Real held = kNfls * kNfls / (2.0 * kE / (3.0 * (1.0 - 2.0 * kNu)) * 4.0 / 2.0);
    std::printf("%-16s energy balance error at the end %.3e, %.2e of the energy the ties held (%.3e)\n",
                dc.name().c_str(), r.energy_end * r.work, r.energy_end * r.work / held, held);
    EXPECT_LT(r.energy_end * r.work, 2e-2 * held);
    EXPECT_EQ(r.after, 0.0);
    EXPECT_GT(r.opening, 1e-4);
  }
}

INSTANTIATE_TEST_SUITE_P(Closed, AutomaticTiebreakSticking,
                         ::testing::Values(DriveCase{1, false}, DriveCase{1, true}, DriveCase{3, false},
                                           DriveCase{3, true}, DriveCase{0, false}, DriveCase{1, false, 1e-4},
                                           DriveCase{1, true, 1e-4}),
                         [](const ::testing::TestParamInfo<DriveCase>& info) { return info.param.name(); });

TEST(AutomaticTiebreakStickingThreads, OneAndThreeThreadsGiveTheSameBits) {
  const int before = max_threads();
  set_threads(1);
  const DriveResult one = run_drive(DriveCase{3, true});
  set_threads(3);
  const DriveResult three = run_drive(DriveCase{3, true});
  set_threads(before);
  EXPECT_EQ(one.history, three.history);
}

// Tied from t = 0, loaded along the face below SFLS A: no slide.
TEST(AutomaticTiebreakStickingRest, TiedAtTheStartHoldsAShearLoadBelowSfls) {
  for (const bool rotated : {false, true}) {
    SCOPED_TRACE(rotated ? "rotated" : "plain");
    const Frame frame = rotated ? test_support::oblique_frame() : Frame{};
    model::Model m;
    const test_support::TiebreakBlocks b = test_support::add_tiebreak_blocks(m, frame, kRho, kE, kNu);
    model::Contact card = tiebreak_card("rest", 3);
    card.sfs = card.sfm = 10.0;
    card.nfls = card.nflf = kNfls;
    card.sfls = card.sflf = 1.0;
    m.contacts.push_back(card);
    const Vec3 along = frame.map(Vec3::UnitX());
    constexpr Real kLoad = 0.5;
    m.curves.push_back({1, "ramp", 0, 1.0, 1.0, 0.0, 0.0, 0, {{0.0, 0.0}, {0.1, 1.0}, {10.0, 1.0}}, {}});
    test_support::add_node_load(m, 3, 1, along, kLoad / 4.0);
    m.termination.endtim = 1.0;
    test_support::Run run(m);
    const auto& tb = dynamic_cast<const StickingTiebreakContact&>(run.sim->contacts()[0]);
    EXPECT_EQ(tb.tied_count(), 4);
    for (std::size_t i = 0; i < tb.tie_times().size(); ++i)
      if (tb.states()[i] == State::tied) EXPECT_EQ(tb.tie_times()[i], 0.0);
    const std::vector<Id> slave_nodes = b.upper.face_j(0), master_nodes = b.lower.face_j(1);
    Real slip = 0.0, shear = 0.0, window = 0.0;
    while (run.sim->step()) {
      const Vec3 s = run.mean(slave_nodes, [&](Id id) { return run.x(id); }) -
                     run.mean(master_nodes, [&](Id id) { return run.x(id); });
      slip = std::max(slip, std::abs(s.dot(along)));

      if (run.sim->time() > 0.5) {
        shear += run.sim->dt() * tb.tie_slave_force().dot(along);
        window += run.sim->dt();
      }
    }
    shear = std::abs(shear / window + kLoad) / kLoad;  // the mean over [0.5, 1]: the ringing averages out
    // kappa A = f K A^2 / V, f = SLSFAC x SFS = 1, K = E / (3 (1 - 2 nu)), V = 0.5: 1.67e4; the
    // springs' slip T / (kappa A) = 3e-5; twice that covers the load's dynamic overshoot.
    const Real spring = kLoad / (kE / (3.0 * (1.0 - 2.0 * kNu)) / 0.5);
    std::printf("rest %-8s slip %.3e (spring %.3e, free sliding 0.5), released %ld, mean tie shear force off %.2e\n",
                rotated ? "rotated" : "plain", slip, spring, static_cast<long>(tb.released_count()), shear);
    EXPECT_EQ(tb.released_count(), 0);
    EXPECT_LT(slip, 2.0 * spring);
    EXPECT_LT(shear, 2e-2);
  }
}

}  // namespace
}  // namespace slideline

namespace slideline {
namespace {

// Tied from t = 0, a shear load T = r t on the top (r = 0.25) until a node fails. The load at height
// h = 0.5 above the interface tips the block: the normal tie forces balance T h with the two rows of
// nodes a unit apart, N = T h / 2 per node (tension on the trailing row), and each node carries T / 4
// along: over A_k = 1/4, sigma_n = 2 T h = T, sigma_s = T. The trailing nodes fail at
// (T / NFLS)^2 + (T / SFLS)^2 = 1: T_f = 1 / sqrt(1 / 4 + 1) = 0.8944 (NFLS = 2, SFLS = 1).
TEST(AutomaticTiebreakStickingRest, ShearFailsAtTheMixedCriterion) {
  constexpr Real kRate = 0.25, kSfls = 1.0;
  const Real closed = 1.0 / std::sqrt(1.0 / (kNfls * kNfls) + 1.0 / (kSfls * kSfls));
  for (const bool rotated : {false, true}) {
    SCOPED_TRACE(rotated ? "rotated" : "plain");
    const Frame frame = rotated ? test_support::oblique_frame() : Frame{};
    model::Model m;
    test_support::add_tiebreak_blocks(m, frame, kRho, kE, kNu);
    // The incremental stiffness form (IHQ 4): the blocks' total-displacement IHQ 10 creates 1.06 %
    // of the energy in play once the released block rattles (its hourglass work -0.0048 against
    // 0.45 at t = 4.24, on the trapezoid since 2026-11-27; docs/solver.md, "Energies"), and the run
    // stops there; the failure this test times comes before.
    for (auto& h : m.hourglasses) h.ihq = 4;
    model::Contact card = tiebreak_card("mixed", 3);
    card.sfs = card.sfm = 10.0;
    card.nfls = card.nflf = kNfls;
    card.sfls = card.sflf = kSfls;
    m.contacts.push_back(card);
    m.curves.push_back({1, "ramp", 0, 1.0, 1.0, 0.0, 0.0, 0, {{0.0, 0.0}, {100.0, 100.0}}, {}});
    test_support::add_node_load(m, 3, 1, frame.map(Vec3::UnitX()), kRate / 4.0);
    m.termination.endtim = 1.2 * closed / kRate;
    test_support::Run run(m);
    const auto& tb = dynamic_cast<const StickingTiebreakContact&>(run.sim->contacts()[0]);
    Real failed = -1.0;
    Index first = 0;
    while (run.sim->step())
      if (failed < 0.0 && tb.released_count() > 0) {
        failed = run.sim->time();
        first = tb.released_count();
      }
    std::printf("mixed %-8s first release at T = %.5f (closed form %.5f), %ld node(s) then, %ld at the end\n",
                rotated ? "rotated" : "plain", kRate * failed, closed, static_cast<long>(first),
                static_cast<long>(tb.released_count()));
    EXPECT_NEAR(kRate * failed / closed, 1.0, 1e-2);
    EXPECT_EQ(first, 2);  // the trailing row
  }
}

}  // namespace
}  // namespace slideline
