// PenaltyPass (contact/enforcement/penalty.hpp) on hand-built plates: normal spring, shell side
// and offsets, Coulomb stick/slip with the static peak, action = reaction, and thread-count
// independence on a surface large enough for the parallel loops (> 4096 slaves).
#include <gtest/gtest.h>

#include <cmath>

#include "penalty_scene.hpp"
#include "slideline/core/parallel.hpp"

namespace slideline {
namespace {

Vec3Field zero_forces(std::size_t n) {
  Vec3Field f;
  f.resize(n);
  return f;
}

struct Totals {
  Vec3 slave = Vec3::Zero(), master = Vec3::Zero();
  Real friction = 0.0;
};

Totals step(test::PenaltyScene& s, Real dt, Vec3Field* forces = nullptr) {
  StepTimes t;
  t.dt_prev = dt;
  s.pass->compute(s.nodes, t, s.friction);
  Vec3Field f = zero_forces(s.nodes.x.size());
  Vec3Field m = zero_forces(s.nodes.x.size());
  Totals r;
  s.pass->scatter(ContactForceView{f, m}, r.slave, r.master, r.friction);
  if (forces) *forces = f;
  return r;
}

TEST(PenaltyPass, NormalSpringIsStiffnessTimesPenetrationAndBalanced) {
  auto s = test::make_penalty_scene(4, 0.01, 100.0, {});
  Vec3Field f;
  const Totals r = step(*s, 1e-3, &f);
  ASSERT_EQ(s->pass->initial_penetration_count(), 0);
  for (Index n : s->slaves) EXPECT_NEAR(f.z[n], 1.0, 1e-12);  // k g = 100 x 0.01, along +z
  EXPECT_NEAR(r.slave[2], 16.0, 1e-12);
  EXPECT_LT((r.slave + r.master).norm(), 1e-13);
  EXPECT_EQ(r.friction, 0.0);
  // The stable step of a pair: 2 / sqrt(k (1/m_s + sum N^2/m_a)) with unit masses.
  Real worst = 0.0;
  for (const auto& rec : s->pass->records()) worst = std::max(worst, rec.dt_inv2);
  EXPECT_NEAR(s->pass->stable_dt(), 1.0 / std::sqrt(worst), 1e-15);
  EXPECT_LT(s->pass->stable_dt(), 2.0 / std::sqrt(100.0));
}

TEST(PenaltyPass, NoForceWhenSeparated) {
  auto s = test::make_penalty_scene(4, -0.01, 100.0, {});
  const Totals r = step(*s, 1e-3);
  EXPECT_EQ(r.slave.norm(), 0.0);
  EXPECT_EQ(r.master.norm(), 0.0);
}

// Ramped tangential pull on nodes pressed with N = 1 each: stick (F = k_t u_e, k_t =
// max(k, mu_s N / gamma)) up to mu N, then slip at mu(v) N; the dissipation is the slip times the
// force.
TEST(PenaltyPass, CoulombStickThenSlipWithTheStaticPeak) {
  const ExponentialCoulomb law{0.3, 0.25, 2.0};
  auto s = test::make_penalty_scene(2, 0.01, 100.0, law);
  const Real dt = 1e-3;
  step(*s, dt);
  Real peak = 0.0, last = 0.0, work = 0.0;
  int stick_steps = 0;
  for (int k = 0; k < 400; ++k) {
    test::move_slaves(*s, Vec3(1e-5, 0.0, 0.0), dt);  // slip speed 0.01
    const Totals r = step(*s, dt);
    peak = std::max(peak, -r.slave[0] / 4.0);
    last = -r.slave[0] / 4.0;
    work += r.friction;
    if (r.friction == 0.0) ++stick_steps;
  }
  // Stick spring: gamma = 1e-3 x the unit segment's diagonal, k_t = mu_s N / gamma = 212 (N = k g
  // = 1), above k = 100 and below the cap 4 k. The trial grows by k_t du a step while the relative speed is 0.01, so
  // mu(0.01) caps it (the relative speed sets mu: DYNA3D's law); steady slip at the same mu.
  // Work: slip x force, the slip being the imposed motion less the elastic slip mu N / k_t.
  const Real mu = law.coefficient(0.01);
  const Real kt = 0.3 * 1.0 / (1e-3 * std::sqrt(2.0));
  const int expected_stick = static_cast<int>(std::floor(mu / (kt * 1e-5)));
  const Real expected_work = 4.0 * mu * (400 * 1e-5 - mu / kt);
  std::printf("stick/slip: peak %.6f (mu(0.01) N = %.6f), last %.6f, work %.6e (expected %.6e), %d stick steps "
              "(expected %d)\n", peak, mu, last, work, expected_work, stick_steps, expected_stick);
  EXPECT_NEAR(peak, mu, 1e-12);
  EXPECT_NEAR(last, mu, 1e-12);
  EXPECT_EQ(stick_steps, expected_stick);
  EXPECT_NEAR(work, expected_work, 1e-3 * expected_work);
}

// The sticking point, not the force, is the history: on a soft master (k = 60, so that
// k_t = mu_s N / gamma lies in [k, 4 k] for N in [0.5, 1]) the node is held at 0.9 of its elastic
// limit while N dips to half and recovers 20 times. The force follows N (0.9 mu_s N: stick at the
// dip too) and comes back to its value: no creep. A force history would be capped at mu_s N at each
// dip (0.27 -> 0.15) and come back at the dip's value.
TEST(PenaltyPass, StickDoesNotCreepUnderAnOscillatingNormalForce) {
  const ExponentialCoulomb law{0.3, 0.3, 0.0};  // constant mu: the offset is imposed in one step
  const Real k = 60.0, g = 1.0 / k;  // N = k g = 1
  auto s = test::make_penalty_scene(2, g, k, law);
  const Real dt = 1e-3;
  step(*s, dt);
  const Real gamma = 1e-3 * std::sqrt(2.0);
  test::move_slaves(*s, Vec3(0.9 * gamma, 0.0, 0.0), dt);
  const Real f0 = -step(*s, dt).slave[0];
  EXPECT_NEAR(f0, 4.0 * 0.9 * 0.3 * 1.0, 1e-9);
  test::move_slaves(*s, Vec3::Zero(), dt);  // at rest from here on
  for (int cycle = 0; cycle < 20; ++cycle) {
    for (Index n : s->slaves) s->nodes.x.z[n] = -0.5 * g;  // N = 0.5
    const Totals dip = step(*s, dt);
    EXPECT_NEAR(-dip.slave[0], 4.0 * 0.9 * 0.3 * 0.5, 1e-9);
    EXPECT_EQ(dip.friction, 0.0);
    for (Index n : s->slaves) s->nodes.x.z[n] = -g;
  }
  const Totals r = step(*s, dt);
  EXPECT_NEAR(-r.slave[0], f0, 1e-12);
  EXPECT_EQ(r.friction, 0.0);
}

TEST(PenaltyPass, ShellMasterPushesTowardsTheSideTheSlaveIsOn) {
  for (const Real side : {1.0, -1.0}) {
    Vec3Field x;
    Surface plate = test::make_plate(x, 2, 2, 1.0, Vec3::Zero());
    plate.kind.assign(4, SegmentKind::shell);
    plate.thickness.assign(4, 0.1);
    const Index slave = static_cast<Index>(x.size());
    x.x.push_back(0.6);
    x.y.push_back(0.7);
    x.z.push_back(side * 0.5);
    NodalFields nodes;
    nodes.resize(x.size());
    nodes.x = x;
    nodes.mass.assign(x.size(), 1.0);
    PenaltyPass pass({slave}, {0.02}, std::move(plate), std::make_unique<FclBroadPhase>(), PenaltyPassOptions{});
    pass.initialize(nodes, std::vector<Real>(4, 10.0));
    nodes.x.z[slave] = side * 0.06;  // offsets 0.05 + 0.02: penetration 0.01
    StepTimes t;
    pass.compute(nodes, t);
    EXPECT_NEAR(pass.gap(0), -0.01, 1e-12);
    ASSERT_GE(pass.records()[0].segment, 0);
    EXPECT_NEAR(pass.records()[0].force[2], side * 0.1, 1e-12);
  }
}

// Frictional sliding of 22 500 slaves over 10^4 segments: records bitwise equal with 1 and 2
// threads.
TEST(PenaltyPass, ThreadCountIndependent) {
  const ExponentialCoulomb law{0.3, 0.25, 2.0};
  std::vector<PenaltyRecord> records[2];
  Real friction[2] = {0, 0};
  const int threads_before = max_threads();
  for (int run = 0; run < 2; ++run) {
    set_threads(run + 1);
    auto s = test::make_penalty_scene(150, 0.01, 100.0, law);
    for (int k = 0; k < 30; ++k) {
      test::move_slaves(*s, Vec3(0.011 + 0.001 * k, 0.004, 1e-4 * std::sin(k)), 1e-3);
      friction[run] += step(*s, 1e-3).friction;
    }
    records[run].assign(s->pass->records().begin(), s->pass->records().end());
  }
  set_threads(threads_before);
  ASSERT_EQ(records[0].size(), records[1].size());
  ASSERT_GT(records[0].size(), 4096u);
  for (std::size_t i = 0; i < records[0].size(); ++i) {
    ASSERT_EQ(records[0][i].segment, records[1][i].segment) << i;
    ASSERT_EQ(records[0][i].force, records[1][i].force) << i;
    ASSERT_EQ(records[0][i].dissipation, records[1][i].dissipation) << i;
  }
  EXPECT_EQ(friction[0], friction[1]);
  EXPECT_GT(friction[0], 0.0);
}

}  // namespace
}  // namespace slideline
