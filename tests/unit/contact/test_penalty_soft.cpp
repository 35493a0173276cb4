// PenaltyPass options of issue 20 on a hand-built plate (unit masses, segment springs k = 100):
// SOFT = 1 (each pair's spring max(k, 0.5 SOFSCL m* / dt_c^2)) and VC (friction capped at VC x the
// master segment's area).
#include <gtest/gtest.h>

#include <cmath>

#include "penalty_scene.hpp"
#include "slideline/core/error.hpp"

namespace slideline {
namespace {

struct Totals {
  Vec3 slave = Vec3::Zero(), master = Vec3::Zero();
  Real friction = 0.0;
};

Totals step(test::PenaltyScene& s, const StepTimes& t) {
  s.pass->compute(s.nodes, t, s.friction);
  Vec3Field f, m;
  f.resize(s.nodes.x.size());
  m.resize(s.nodes.x.size());
  Totals r;
  s.pass->scatter(ContactForceView{f, m}, r.slave, r.master, r.friction);
  return r;
}

TEST(PenaltySoft, SpringIsTheLargerOfTheSegmentsAndTheMassOverTheInitialStepSquared) {
  PenaltyPassOptions o;
  o.soft_scale = 0.1;
  StepTimes t;
  t.dt_prev = 1e-3;
  for (const Real dt_c : {1e-2, 1e-1}) {
    // 16 slaves 0.01 deep; m* = 1: k1 = 0.05 / dt_c^2 = 500 (dt_c 0.01) or 5 (0.1, below k = 100).
    auto s = test::make_penalty_scene(4, 0.01, 100.0, {}, nullptr, o);
    t.dt_initial = dt_c;
    const Totals r = step(*s, t);
    const Real k = std::max(100.0, 0.5 * 0.1 * 1.0 / (dt_c * dt_c));
    EXPECT_NEAR(r.slave[2], 16.0 * k * 0.01, 1e-9 * k) << dt_c;
    EXPECT_LT((r.slave + r.master).norm(), 1e-12 * k);
    // The pair's step: omega^2 = k (1/m_s + sum N^2 / m_a) <= 2 k / m* = SOFSCL / dt_c^2 at the
    // SOFT = 1 spring: never below 2 dt_c / sqrt(SOFSCL).
    if (k > 100.0) EXPECT_GE(s->pass->stable_dt(), 2.0 * dt_c / std::sqrt(0.1));
  }
  // Without the run's initial step the spring is unknown: refused, not guessed.
  auto s = test::make_penalty_scene(4, 0.01, 100.0, {}, nullptr, o);
  t.dt_initial = 0.0;
  EXPECT_THROW(step(*s, t), Error);
}

TEST(PenaltyViscousFriction, TangentialForceOfEachNodeIsCappedAtVcTimesTheSegmentArea) {
  // Unit segments (area 1), N = k g = 1 per node, mu = 0.5: Coulomb 0.5 per node; VC = 0.2 caps
  // it at 0.2. The nodes slide 0.01 per step (far beyond the stick range).
  const ExponentialCoulomb law{0.5, 0.5, 0.0};
  for (const Real vc : {0.0, 0.2, 1.0}) {
    PenaltyPassOptions o;
    o.viscous_friction = vc;
    auto s = test::make_penalty_scene(4, 0.01, 100.0, law, nullptr, o);
    StepTimes t;
    t.dt_prev = 1e-3;
    Totals r;
    for (int k = 0; k < 5; ++k) {
      test::move_slaves(*s, Vec3(0.01, 0.0, 0.0), 1e-3);
      r = step(*s, t);
    }
    const Real per_node = vc > 0.0 ? std::min(0.5, vc * 1.0) : 0.5;
    EXPECT_NEAR(-r.slave[0], 16.0 * per_node, 1e-9) << "VC " << vc;
    EXPECT_GT(r.friction, 0.0);
  }
}

}  // namespace
}  // namespace slideline
