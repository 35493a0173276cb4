// A kinematic tie that imposes a velocity jump at t = 0 (docs/contact.md, "A tie that starts with
// a relative velocity"): the energy ledger books the tie's first-cycle impulse.
//
// Two unit cubes (one hexahedron each, rho = 1, E = 1e4, nu = 0.3), the upper one on top of the
// lower one, its bottom face tied to the lower one's top face (Type 2). The upper cube starts at
// v0 = 1e-2 along x, the lower at rest; no support, no load. Each slave node coincides with a
// master node (N = 1 there), so the tie's impulse at t = 0 takes each of the 4 slave nodes (mass
// m = 1/8) from v0 to its master's velocity v^{1/2} (about 2 % of v0 after the half step).
// TSSFAC 0.6: this one-element-wide column (tied or merged alike) is unstable at the default 0.9
// (an element inverts by cycle 25), docs/contact.md.
// Closed forms: the first cycle is a half step from v(0) (dt_avg = dt / 2); the velocity update's
// sums book the tie's impulse J = m dv over x^1 - x^0 only, J v^{1/2}, where the kinetic energy
// changes by J (v(0) + v^{1/2}) / 2: without the first-cycle term the balance is off by
// -sum m dv^2 / 2 ~ -4 m v0^2 / 2 = -2.5e-5, half the initial kinetic energy 5e-5 (the rigid wall's
// first-cycle gap, docs/solver.md). With it the balance closes to the central difference's
// residual. The same deck with the cubes merged into one mesh (no tie) is the reference for that
// residual: the tied run's balance may differ from it by no more than 1e-2 of KE0.
// Momentum: the condensation carries the slaves' mass onto the masters at the masters' velocity, so
// 4 m v0 = 5e-3 of P0 = 1e-2 is dropped in the first cycle (reported, not fixed: docs/contact.md).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "general_contact_models.hpp"

namespace slideline {
namespace {

using test_support::add_box;
using test_support::add_elastic_part;
using test_support::BoxIds;
using test_support::Frame;

constexpr Real kV0 = 1e-2;

struct FirstCycle {
  Real kinetic0 = 0.0, momentum = 0.0;  ///< after the first cycle
  Real balance_end = 0.0;                              ///< largest |balance| over 60 cycles
};

FirstCycle run_jump(bool tied) {
  model::Model m;
  add_elastic_part(m, 1, 1.0, 1e4, 0.3);
  add_elastic_part(m, 2, 1.0, 1e4, 0.3);
  std::vector<Id> moving;
  if (tied) {
    const BoxIds l = add_box(m, 1, Vec3(0.0, 0.0, 0.0), Vec3(1.0, 1.0, 1.0), {1, 1, 1}, Frame{});
    const BoxIds u = add_box(m, 2, Vec3(0.0, 1.0, 0.0), Vec3(1.0, 1.0, 1.0), {1, 1, 1}, Frame{});
    m.segment_sets.push_back({1, "master", {{l.at(0, 1, 0), l.at(0, 1, 1), l.at(1, 1, 1), l.at(1, 1, 0)}}, {}});
    m.segment_sets.push_back({2, "slave", {{u.at(0, 0, 0), u.at(1, 0, 0), u.at(1, 0, 1), u.at(0, 0, 1)}}, {}});
    model::Contact card;
    card.type = model::ContactType::tied_surface;
    card.enforcement = model::Enforcement::kinematic;
    card.keyword = "*CONTACT_TIED_SURFACE_TO_SURFACE";
    card.title = "tie";
    card.ssid = 2;
    card.msid = 1;
    m.contacts.push_back(card);
    moving = u.node;
  } else {
    // The merged column: its middle layer is shared, at rest (the tie stops the slaves there).
    const BoxIds b = add_box(m, 1, Vec3(0.0, 0.0, 0.0), Vec3(1.0, 2.0, 1.0), {1, 2, 1}, Frame{});
    moving = b.face_j(2);
  }
  for (Id id : moving) m.initial_velocity_nodes.push_back({id, Vec3(kV0, 0.0, 0.0), Vec3::Zero(), 0, 0});
  m.timestep.tssfac = 0.6;
  m.termination.endtim = 1.0;
  test_support::Run run(m);
  const NodalFields& nodes = run.sim->nodes();
  FirstCycle r;
  run.sim->step();
  r.kinetic0 = run.sim->energy().kinetic0;
  for (std::size_t i = 0; i < nodes.size(); ++i) r.momentum += nodes.mass[i] * nodes.v.x[i];
  for (int c = 0; c < 60; ++c) {
    run.sim->step();
    r.balance_end = std::max(r.balance_end, std::abs(run.sim->energy().balance_error()));
  }
  return r;
}

TEST(TiedFirstCycle, TheTiesImpulseAtTimeZeroIsBooked) {
  const FirstCycle tied = run_jump(true), merged = run_jump(false);
  std::printf("tied: KE0 %.6e, largest balance error over 60 cycles %.3e (%.2e of KE0); momentum %.6e (P0 %.6e)\n"
              "merged: KE0 %.6e, largest balance error over 60 cycles %.3e\n",
              tied.kinetic0, tied.balance_end, tied.balance_end / tied.kinetic0, tied.momentum, kV0, merged.kinetic0,
              merged.balance_end);
  EXPECT_NEAR(tied.kinetic0, 0.5 * kV0 * kV0, 1e-15);
  // Unbooked, the largest balance error is 2.457e-5 = 0.49 KE0 (measured with the term switched off).
  EXPECT_LT(std::abs(tied.balance_end - merged.balance_end), 1e-2 * tied.kinetic0);
  EXPECT_LT(tied.balance_end, 0.1 * tied.kinetic0);
  // The dropped momentum (not fixed): the slaves' 4 m v0, less what the half step gave the masters.
  EXPECT_NEAR(tied.momentum, kV0 - 0.5 * kV0, 0.05 * kV0);
}

}  // namespace
}  // namespace slideline
