// *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK, OPTION 2, against closed forms. Two blocks of one
// hexahedron each (1 x 0.5 x 1) are tied across their common face (area A = 1; slave side: the
// upper block's bottom face, master side: the lower block's top face, as segment sets); the lower
// block's bottom is fixed and a ramped load acts on the upper block's top nodes.
// - Tension: a load F = r t pulls the blocks apart. The interface holds (stretch ~ F / (kappa A),
//   the tie force balances F) until F = NFLS A: failure at t_f = NFLS A / r. Afterwards the
//   contact carries no tension (the slave force is exactly zero, the blocks part).
// - Shear: a normal pressure P (ramped in, then held) and a tangential load T = r (t - t0): the
//   criterion sees no normal term (compression) and the tie fails at T = SFLS A,
//   t_f = t0 + SFLS A / r. Afterwards the block slides on the automatic contact with friction
//   mu: the tangential contact force is mu x the normal one.
// Each also in a copy rotated about an oblique axis (same failure time, same forces). Failure time
// tolerance: the load's inertial ripple, r / omega with omega ~ 180 rad/time the blocks' lowest
// mode, is 1 / (omega t_f) ~ 0.3 % of the failure load here; the failure is seen at a cycle
// boundary (dt ~ 3e-3, 0.15 % of t_f). Tolerance 1 %.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "tiebreak_blocks.hpp"
#include "slideline/solver/energy_ledger.hpp"
#include "slideline/contact/automatic_tiebreak_contact.hpp"

namespace slideline {
namespace {

using test_support::add_tiebreak_blocks;
using test_support::add_node_load;
using test_support::BoxIds;
using test_support::Frame;
using test_support::tiebreak_card;
using test_support::TiebreakBlocks;

constexpr Real kE = 1e4, kNu = 0.3, kRho = 1.0;
constexpr Real kNfls = 2.0, kSfls = 1.0, kMu = 0.1;
constexpr Real kRate = 1.0, kShearRate = 0.25;  // load rates r (force / time)
constexpr Real kPressure = 4.0, kShearStart = 0.3;

struct TieCase {
  bool shear = false;
  bool rotated = false;
  std::string name() const { return std::string(shear ? "shear" : "tension") + (rotated ? "_rotated" : ""); }
  Real failure_time() const { return shear ? kShearStart + kSfls / kShearRate : kNfls / kRate; }
};

struct TieResult {
  Real failure_time = -1.0;
  Real stretch = 0.0;         ///< largest tie stretch |x_s - x_m| of the interface nodes before 0.75 t_f
  Real balance = 0.0;         ///< largest |tie force - load| / load along the load, from 0.2 to 0.75 of failure
  Real after_force = 0.0;     ///< tension: largest |slave force| after failure
  Real opening = 0.0;         ///< tension: the interface's opening at the end
  Real friction_ratio = 0.0;  ///< shear: mean |tangential| / mean normal contact force after failure
  Real slip = 0.0;            ///< shear: the upper block's slip at the end
  Real energy = 0.0;          ///< largest |energy balance error| / external work, from 0.25 t_f to t_f
  Real energy_end = 0.0;      ///< the same at the end
  Real energy_release = 0.0;  ///< the largest after failure (the release: a force F gone in one step)
};

TieResult run_tie(const TieCase& tc) {
  const Frame frame = tc.rotated ? test_support::oblique_frame() : Frame{};
  model::Model m;
  const TiebreakBlocks blocks = add_tiebreak_blocks(m, frame, kRho, kE, kNu);
  const BoxIds& upper = blocks.upper;
  const BoxIds& lower = blocks.lower;
  model::Contact card = tiebreak_card(tc.name(), 2);
  card.fs = card.fd = kMu;
  card.sfs = card.sfm = 10.0;
  card.nfls = card.nflf = kNfls;
  card.sfls = card.sflf = kSfls;
  m.contacts.push_back(card);
  const Vec3 up = frame.map(Vec3::UnitY()), along = frame.map(Vec3::UnitX());
  const Real end = tc.failure_time() + (tc.shear ? 0.6 : 0.3);
  // Curve 1: r t (the ramped load); curve 2: the pressure, ramped in over 0.2, then held.
  m.curves.push_back({1, "ramp", 0, 1.0, 1.0, tc.shear ? kShearStart : 0.0, 0.0, 0, {{0.0, 0.0}, {100.0, 100.0}}, {}});
  if (tc.shear) {
    m.curves.push_back({2, "pressure", 0, 1.0, 1.0, 0.0, 0.0, 0, {{0.0, 0.0}, {0.2, 1.0}, {100.0, 1.0}}, {}});
    add_node_load(m, 3, 2, -up, kPressure / 4.0);
    add_node_load(m, 3, 1, along, kShearRate / 4.0);
  } else {
    add_node_load(m, 3, 1, up, kRate / 4.0);
  }
  m.termination.endtim = end;

  test_support::Run run(m);
  const auto& tiebreak = dynamic_cast<const AutomaticTiebreakContact&>(run.sim->contacts()[0]);
  const Vec3 load_dir = tc.shear ? along : up;
  const std::vector<Id> slave_nodes = upper.face_j(0), master_nodes = lower.face_j(1);
  TieResult r;
  Real ft_sum = 0.0, fn_sum = 0.0;
  while (run.sim->step()) {
    const Real t = run.sim->time();
    const Real tf = tc.failure_time();
    const EnergyReport& e = run.sim->energy();
    if (t > 0.25 * tf && r.failure_time < 0.0) r.energy = std::max(r.energy, std::abs(e.balance_error()) / e.external);
    r.energy_end = std::abs(e.balance_error()) / e.external;
    if (r.failure_time > 0.0) r.energy_release = std::max(r.energy_release, r.energy_end);
    const Vec3 f = tiebreak.slave_force();  // on the upper block, from the lower, this cycle
    // Failure found in this cycle (from this cycle's tie forces) acts from the next one.
    const bool failed_before = r.failure_time > 0.0;
    if (!failed_before && tiebreak.tie().failed_segments()[0]) r.failure_time = t;
    if (r.failure_time < 0.0 && t < 0.75 * tf) {
      for (std::size_t k = 0; k < slave_nodes.size(); ++k)
        r.stretch = std::max(r.stretch, (run.x(slave_nodes[k]) - run.x(master_nodes[k])).norm());
      const Real load = tc.shear ? kShearRate * (t - kShearStart) : kRate * t;
      if (load > 0.2 * (tc.shear ? kSfls : kNfls)) r.balance = std::max(r.balance, std::abs(-f.dot(load_dir) - load) / load);
    }
    if (failed_before && !tc.shear) r.after_force = std::max(r.after_force, f.norm());
    if (failed_before && tc.shear && t > r.failure_time + 0.1) {
      // In the frame of the upper block's bottom face: the block rocks (about 1e-3 rad) as it
      // slides, and its friction lies in its own tangent plane.
      const Vec3 n = (run.x(slave_nodes[3]) - run.x(slave_nodes[0])).cross(run.x(slave_nodes[2]) - run.x(slave_nodes[1]));
      const Vec3 nu = n.dot(up) > 0.0 ? Vec3(n.normalized()) : Vec3(-n.normalized());
      fn_sum += f.dot(nu);
      ft_sum += (f - f.dot(nu) * nu).norm();
    }
  }
  const Vec3 gap = run.mean(slave_nodes, [&](Id id) { return run.x(id); }) -
                   run.mean(master_nodes, [&](Id id) { return run.x(id); });
  r.opening = gap.dot(up);
  r.slip = gap.dot(along);
  r.friction_ratio = fn_sum > 0.0 ? ft_sum / fn_sum : 0.0;
  return r;
}

class AutomaticTiebreak : public ::testing::TestWithParam<TieCase> {};

TEST_P(AutomaticTiebreak, HoldsThenFailsAtTheStressCriterion) {
  const TieCase tc = GetParam();
  const TieResult r = run_tie(tc);
  std::printf("%-16s failure at t = %.5f (closed form %.5f)  stretch %.2e  balance %.2e\n", tc.name().c_str(),
              r.failure_time, tc.failure_time(), r.stretch, r.balance);
  std::printf("%-16s energy balance error / external work: %.2e before failure, %.2e after, %.2e at the end\n",
              tc.name().c_str(), r.energy, r.energy_release, r.energy_end);
  EXPECT_NEAR(r.failure_time / tc.failure_time(), 1.0, 1e-2);
  // Tied: the stretch is the tie spring's F / (kappa A), kappa = f K A / V (f = 1, K = E / 1.2,
  // V = 0.5), about 1e-4 at 0.75 t_f; the tie force is the load within its inertial ripple.
  EXPECT_LT(r.stretch, 3e-4);
  EXPECT_LT(r.balance, 2e-2);
  EXPECT_LT(r.energy, 2e-2);
  EXPECT_LT(r.energy_end, 1e-3);
  if (!tc.shear) {
    std::printf("%-16s after failure: largest slave force %.2e, opening %.4f\n", tc.name().c_str(), r.after_force,
                r.opening);
    EXPECT_EQ(r.after_force, 0.0);  // no tension after failure, not even a small one
    EXPECT_GT(r.opening, 1e-2);
  } else {
    std::printf("%-16s after failure: |f_t| / f_n %.5f (mu %.2f), slip %.4f\n", tc.name().c_str(), r.friction_ratio,
                kMu, r.slip);
    EXPECT_NEAR(r.friction_ratio / kMu, 1.0, 1e-2);
    EXPECT_GT(r.slip, 1e-2);
  }
}

INSTANTIATE_TEST_SUITE_P(Closed, AutomaticTiebreak,
                         ::testing::Values(TieCase{false, false}, TieCase{false, true}, TieCase{true, false},
                                           TieCase{true, true}),
                         [](const ::testing::TestParamInfo<TieCase>& info) { return info.param.name(); });

}  // namespace
}  // namespace slideline
