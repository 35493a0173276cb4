// *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK, OPTION 6 (the stress criterion of OPTION 2 as
// the onset of damage; damage linear in the distance between the points initially in contact,
// complete at PARAM = CCRIT; mixed_mode_cohesive_law.hpp, `fixed_final`), against closed forms.
// The two one-hexahedron blocks of the OPTION 9 checks (1 x 0.5 x 1, E = 1e5, nu = 0.3; common face
// A = 1), the lower block's bottom fixed, the upper block's top nodes driven at v = 2e-3 (ramped in
// over 0.05) normal to the face (mode I) or along it (mode II; with a twentieth of the speed into
// the face, so that the interface stays closed: see below). The tie's spring is the penalty
// stiffness per area kappa = SLSFAC K A / V = 0.1 x 83333 x 1 / 0.5 = 1.6667e4 (K = E / (3 (1 -
// 2 nu))), 12 times softer than the block (E A / h = 2e5). Closed forms, A = 1:
// - mode I: peak traction NFLS = 2 at the separation NFLS / kappa = 1.2e-4; then linear to zero at
//   CCRIT = 1e-2 (the last tie released there); dissipated (1/2) NFLS CCRIT = 1e-2;
// - mode II: SFLS = 1.5 at 9.0e-5, zero at CCRIT, dissipated (1/2) SFLS CCRIT = 7.5e-3 (the
//   closing part of the stretch is contact, undamaged, and leaves the law's slip part alone).
// Mode II without the closing drive ran away: once D passes ~0.96 the interface nodes chatter
// normal to the face between the undamaged closing spring (c kappa) and the nearly fully damaged
// opening one, their energy grows (internal energy -9e-6 at t = 0.95, -0.95 at 4.05) and the run
// stopped at 5.5 % energy error (t = 4.32, D = 0.9998). OPTION 9's machinery, not OPTION 6's
// law: docs/contact.md ("OPTION 6") reports it.
// Mode I also runs in a copy rotated about an oblique axis. Tolerances: the top travels v dt =
// 2.8e-6 a step (dt ~ 1.4e-3), 2.3 % of the mode I onset separation (3.1 % in mode II): the
// separation at the peak is held to that plus 1 %; the peak (the falling branch moves by 3e-4 of
// NFLS a step) and the separation at release to 1 %; the work, integrated on that path, to 2 %.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "tiebreak_blocks.hpp"
#include "slideline/contact/automatic_tiebreak_contact.hpp"
#include "slideline/solver/energy_ledger.hpp"

namespace slideline {
namespace {

using test_support::add_tiebreak_blocks;
using test_support::BoxIds;
using test_support::Frame;
using test_support::tiebreak_card;
using test_support::TiebreakBlocks;

constexpr Real kE = 1e5, kNu = 0.3, kRho = 1.0;
constexpr Real kNfls = 2.0, kSfls = 1.5, kCcrit = 1e-2, kSpeed = 2e-3;
// The tie's penalty stiffness per unit area (tiebreak_contact.hpp): SLSFAC K A / V.
const Real kKappa = 0.1 * kE / (3.0 * (1.0 - 2.0 * kNu)) * 1.0 / 0.5;

struct Option6Case {
  bool shear = false;
  bool rotated = false;
  std::string name() const { return std::string(shear ? "mode_II" : "mode_I") + (rotated ? "_rotated" : ""); }
  Real peak() const { return shear ? kSfls : kNfls; }
  Real closing() const { return shear ? 0.05 : 0.0; }  ///< speed into the face / speed along it
  Real onset() const { return peak() / kKappa; }
  Real energy() const { return 0.5 * peak() * kCcrit; }
};

struct Option6Result {
  Real peak = 0.0, separation_at_peak = 0.0, separation_at_release = -1.0;
  Real dissipated = 0.0, energy = 0.0, energy_end = 0.0, tie_after = 0.0;
};

Option6Result run_option6(const Option6Case& cc) {
  const Frame frame = cc.rotated ? test_support::oblique_frame() : Frame{};
  model::Model m;
  const TiebreakBlocks blocks = add_tiebreak_blocks(m, frame, kRho, kE, kNu);
  const BoxIds& upper = blocks.upper;
  const BoxIds& lower = blocks.lower;
  model::Contact card = tiebreak_card("OPTION 6, " + cc.name(), 6);
  card.nfls = card.nflf = kNfls;
  card.sfls = card.sflf = kSfls;
  card.param = kCcrit;
  m.contacts.push_back(card);

  // dir: the law's direction (traction, separation); the top moves along dir, and into the face
  // at closing() of that speed.
  const Vec3 dir = frame.map(cc.shear ? Vec3::UnitX() : Vec3::UnitY());
  const Vec3 drive = dir - cc.closing() * frame.map(Vec3::UnitY());
  const Real end = 0.025 + 1.3 * kCcrit / kSpeed;
  m.curves.push_back({1, "velocity", 0, 1.0, 1.0, 0.0, 0.0, 0, {{0.0, 0.0}, {0.05, 1.0}, {end + 1.0, 1.0}}, {}});
  for (int d = 0; d < 3; ++d) {
    model::PrescribedMotion p;
    p.target = model::PrescribedMotion::Target::set;
    p.nsid = 3;
    p.dof = d + 1;
    p.vad = 0;
    p.lcid = 1;
    p.sf = kSpeed * drive[d];
    m.prescribed_motions.push_back(p);
  }
  m.termination.endtim = end;

  test_support::Run run(m);
  const auto& tiebreak = dynamic_cast<const AutomaticTiebreakContact&>(run.sim->contacts()[0]);
  const std::vector<Id> slave_nodes = upper.face_j(0), master_nodes = lower.face_j(1);
  const auto separation = [&] {
    return Vec3(run.mean(slave_nodes, [&](Id id) { return run.x(id); }) -
                run.mean(master_nodes, [&](Id id) { return run.x(id); }));
  };
  Option6Result r;
  while (run.sim->step()) {
    const Vec3 f = tiebreak.tie().slave_force();
    const bool released_before = r.separation_at_release >= 0.0;
    if (!released_before) {
      if (-f.dot(dir) > r.peak) {
        r.peak = -f.dot(dir);
        r.separation_at_peak = separation().dot(dir);
      }
      const auto& rel = tiebreak.tie().released();
      if (std::all_of(rel.begin(), rel.end(), [](std::uint8_t b) { return b != 0; }))
        r.separation_at_release = separation().dot(dir);
    } else {
      r.tie_after = std::max(r.tie_after, f.norm());
    }
    const EnergyReport& e = run.sim->energy();
    const Real work_in = std::abs(e.external + e.support);
    if (work_in > 0.0) {
      r.energy_end = std::abs(e.balance_error()) / work_in;
      if (run.sim->time() > 0.1 * end && !released_before) r.energy = std::max(r.energy, r.energy_end);
    }
  }
  r.dissipated = tiebreak.tie().cohesive_dissipation();
  return r;
}

class AutomaticTiebreakOption6 : public ::testing::TestWithParam<Option6Case> {};

TEST_P(AutomaticTiebreakOption6, SoftensLinearlyToTheCriticalDistance) {
  const Option6Case cc = GetParam();
  const Option6Result r = run_option6(cc);
  std::printf("%-16s peak %.5f (closed form %.5f) at separation %.4e (%.4e); released at %.4e (CCRIT %.4e)\n",
              cc.name().c_str(), r.peak, cc.peak(), r.separation_at_peak, cc.onset(), r.separation_at_release,
              kCcrit);
  std::printf("%-16s dissipated %.5e (NFLS or SFLS x CCRIT / 2 = %.5e); energy balance %.2e to the release, "
              "%.2e at the end\n",
              cc.name().c_str(), r.dissipated, cc.energy(), r.energy, r.energy_end);
  const Real travel = kSpeed * 1.4e-3 / cc.onset();  // one step's travel / the onset separation
  EXPECT_NEAR(r.peak / cc.peak(), 1.0, 1e-2);
  EXPECT_NEAR(r.separation_at_peak / cc.onset(), 1.0, travel + 1e-2);
  EXPECT_NEAR(r.separation_at_release / kCcrit, 1.0, 1e-2);
  EXPECT_NEAR(r.dissipated / cc.energy(), 1.0, 2e-2);
  EXPECT_LT(r.energy, 1e-3);
  EXPECT_LT(r.energy_end, 1e-3);
  EXPECT_EQ(r.tie_after, 0.0);
}

INSTANTIATE_TEST_SUITE_P(Closed, AutomaticTiebreakOption6,
                         ::testing::Values(Option6Case{false, false}, Option6Case{false, true},
                                           Option6Case{true, false}),
                         [](const ::testing::TestParamInfo<Option6Case>& info) { return info.param.name(); });

}  // namespace
}  // namespace slideline
