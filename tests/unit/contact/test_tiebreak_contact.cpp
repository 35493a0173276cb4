// Penalty ties with failure (Types 8, 9): TiebreakContact on a block tied to a fixed block.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "slideline/contact/tiebreak_contact.hpp"
#include "tie_fixtures.hpp"

using namespace slideline;
using namespace slideline::test;

namespace {

/// An upper block [0, 1] x [0.5, 0.8] x [0, 1] of nx x 1 x nx hexahedra (E = 1e4, nu = 0,
/// rho = 1, mass 0.3) tied to the top face of a 2x1x2 lower block [0, 1] x [0, 0.5] x [0, 1]
/// whose nodes are all fixed (no shear lag: the tie alone decides the load sharing). The upper
/// block is stiff next to the tie springs so that its own free-edge effect (no shear stress on its
/// free faces) does not unload the edge segments.
struct TiebreakBlocks {
  Simulation sim;
  TieBox lower, upper;
  TiebreakContact* tie = nullptr;
  static constexpr Real kMass = 0.3;

  TiebreakBlocks(TiebreakParameters p, int nx) {
    TieMesh mesh;
    lower = mesh.add_box({0, 0, 0}, {1, 0.5, 1}, 2, 1, 2);
    upper = mesh.add_box({0, 0.5, 0}, {1, 0.3, 1}, nx, 1, nx);
    mesh.fill(sim.nodes);
    sim.blocks.push_back(elastic_hexes(1, lower, 1.0, 1000.0, 0.3));
    sim.blocks.push_back(elastic_hexes(2, upper, 1.0, 1.0e4, 0.0));
    Surface slave_surface = p.unit == TiebreakParameters::FailureUnit::segment ? part_surface(sim, 2) : Surface{};
    auto t = std::make_unique<TiebreakContact>("tiebreak", upper.layer(0), std::move(slave_surface),
                                               part_surface(sim, 1), p);
    tie = t.get();
    sim.contacts.add(std::move(t));
    sim.supports.push_back(tie_support("lower", lower.all(), {1, 1, 1}));
    MassDamping d;
    d.alpha = 5.0;  // ~10 % of critical for the block on the tie springs (~24 rad/s)
    sim.damping = {d};
    sim.controls.dt_scale = 0.8;
  }
};

TiebreakParameters parameters(TiebreakParameters::FailureUnit unit, Real nflf, Real sflf) {
  TiebreakParameters p;
  p.unit = unit;
  p.penalty_factor = 0.1;  // the default: SLSFAC 0.1 x SFS 1
  p.normal_failure = nflf;
  p.shear_failure = sflf;
  return p;
}

struct FailureRun {
  Real peak = 0.0;          ///< largest |F| along the loaded axis before and at failure
  Real peak_time = 0.0;
  Real energy = 0.0;        ///< largest |relative balance error| while tied
  Real after = 0.0;         ///< |F| along the axis at the end
  bool all_released = false;
};

/// Ramps the load on the upper block along `axis` (tension: +y; shear: +x with a constant
/// compression of 3 held from t = 0.3) until the tie fails; returns the peak interface force.
FailureRun run_to_failure(TiebreakParameters p, int nx, Axis axis, Real peak_load) {
  TiebreakBlocks m(p, nx);
  const Real t0 = axis == Axis::x ? 0.3 : 0.0;
  const Real g = 2.0 * peak_load / TiebreakBlocks::kMass;  // reaches twice the failure load at t0 + 2
  m.sim.body_loads.push_back(ramped_load(axis, g, 2, t0, t0 + 2.0));
  if (axis == Axis::x) m.sim.body_loads.push_back(ramped_load(Axis::y, -10.0, 2, 0.0, 0.2));
  m.sim.controls.end_time = t0 + 1.6;
  m.sim.initialize();
  const int c = static_cast<int>(axis);
  FailureRun r;
  bool any = false;
  while (m.sim.step()) {
    const Real f = std::abs(m.tie->slave_force()[c]);
    bool released = false;
    for (auto b : m.tie->released()) released = released || b;
    if (!any && f > r.peak) r.peak = f, r.peak_time = m.sim.time();
    if (!any && m.sim.time() > 0.1) r.energy = std::max(r.energy, std::abs(m.sim.energy().relative_balance_error()));
    any = any || released;
  }
  r.after = std::abs(m.tie->slave_force()[c]);
  r.all_released = true;
  for (auto b : m.tie->released()) r.all_released = r.all_released && b;
  return r;
}

TEST(TiebreakSurface, UniformTractionGivesTheSameStressOnEverySegment) {
  TiebreakBlocks m(parameters(TiebreakParameters::FailureUnit::segment, 0.0, 0.0), 3);
  const Real g = 5.0;  // total 1.5 over the unit area
  m.sim.body_loads.push_back(ramped_load(Axis::y, g, 2, 0.0, 0.3));
  m.sim.controls.end_time = 2.0;
  m.sim.initialize();
  while (m.sim.step()) {
  }
  const auto& fs = m.tie->segment_forces();
  const auto& failed = m.tie->failed_segments();
  Real lo = 1e300, hi = -1e300, total = 0.0;
  int tied = 0;
  for (std::size_t j = 0; j < fs.size(); ++j) {
    if (failed[j]) continue;  // segments not on the interface (never tied)
    const Real stress = -fs[j][1] / (1.0 / 9.0);
    lo = std::min(lo, stress), hi = std::max(hi, stress), total += -fs[j][1];
    ++tied;
  }
  std::printf("type 9 uniform traction: %d segments, stress min %.5f max %.5f (spread %.2e), total %.5f vs %.5f\n",
              tied, lo, hi, (hi - lo) / hi, total, g * TiebreakBlocks::kMass);
  ASSERT_EQ(tied, 9);
  EXPECT_LT((hi - lo) / hi, 0.01);
  EXPECT_NEAR(total, g * TiebreakBlocks::kMass, 0.01 * g * TiebreakBlocks::kMass);
  EXPECT_NEAR(lo, g * TiebreakBlocks::kMass, 0.01 * g * TiebreakBlocks::kMass);
}

TEST(TiebreakSurface, FailsInTensionAtTheAnalyticalLoad) {
  const Real sigma = 2.0;  // x unit area
  const FailureRun r = run_to_failure(parameters(TiebreakParameters::FailureUnit::segment, sigma, 1e4), 3, Axis::y,
                                      sigma);
  std::printf("type 9 tension: peak %.4f at t %.3f vs %.4f (%.2f%%), energy error %.2e, |F| at end %.2e\n", r.peak,
              r.peak_time, sigma, 100.0 * (r.peak - sigma) / sigma, r.energy, r.after);
  EXPECT_NEAR(r.peak, sigma, 0.03 * sigma);
  EXPECT_LT(r.energy, 0.01);
  EXPECT_TRUE(r.all_released);
  EXPECT_LT(r.after, 1e-12);  // released in tension: no contact force
}

TEST(TiebreakSurface, FailsInShearAtTheAnalyticalLoad) {
  const Real tau = 1.0;
  const FailureRun r = run_to_failure(parameters(TiebreakParameters::FailureUnit::segment, 1e4, tau), 3, Axis::x,
                                      tau);
  std::printf("type 9 shear: peak %.4f at t %.3f vs %.4f (%.2f%%), energy error %.2e, |F_x| at end %.2e\n", r.peak,
              r.peak_time, tau, 100.0 * (r.peak - tau) / tau, r.energy, r.after);
  EXPECT_NEAR(r.peak, tau, 0.03 * tau);
  EXPECT_LT(r.energy, 0.01);
  EXPECT_TRUE(r.all_released);
}

TEST(TiebreakNodes, FailsInTensionAtTheAnalyticalLoad) {
  // One upper hexahedron: by symmetry each of its 4 tied nodes carries a quarter of the load.
  const Real fnf = 0.5;
  const FailureRun r = run_to_failure(parameters(TiebreakParameters::FailureUnit::node, fnf, 1e4), 1, Axis::y,
                                      4 * fnf);
  std::printf("type 8 tension: peak %.4f at t %.3f vs %.4f (%.2f%%), energy error %.2e\n", r.peak, r.peak_time,
              4 * fnf, 100.0 * (r.peak - 4 * fnf) / (4 * fnf), r.energy);
  EXPECT_NEAR(r.peak, 4 * fnf, 0.03 * 4 * fnf);
  EXPECT_LT(r.energy, 0.01);
  EXPECT_TRUE(r.all_released);
}

TEST(TiebreakNodes, FailsInShearAtTheAnalyticalLoad) {
  const Real fsf = 0.25;
  const FailureRun r = run_to_failure(parameters(TiebreakParameters::FailureUnit::node, 0.0, fsf), 1, Axis::x,
                                      4 * fsf);
  std::printf("type 8 shear: peak %.4f at t %.3f vs %.4f (%.2f%%), energy error %.2e\n", r.peak, r.peak_time,
              4 * fsf, 100.0 * (r.peak - 4 * fsf) / (4 * fsf), r.energy);
  EXPECT_NEAR(r.peak, 4 * fsf, 0.03 * 4 * fsf);
  EXPECT_LT(r.energy, 0.01);
  EXPECT_TRUE(r.all_released);
}

TEST(TiebreakNodes, SpringsVoteTheirStableStep) {
  TiebreakBlocks m(parameters(TiebreakParameters::FailureUnit::node, 1.0, 1.0), 1);
  m.sim.controls.end_time = 0.01;
  m.sim.initialize();
  // k = f K A / h of the master face (f = 0.1, K = 1000 / (3 (1 - 0.6)), A = 0.25, h = 0.5),
  // between a slave of mass 0.3 / 8 and the lightest master corner.
  const Real k = 0.1 * (1000.0 / 1.2) * 0.25 * 0.25 / (0.25 * 0.5);
  ASSERT_EQ(m.tie->links().size(), 4u);
  EXPECT_NEAR(m.tie->stiffness(0), k, 1e-9 * k);
  Real mm = 1e300;
  for (const TiePoint& t : m.tie->links())
    for (int a = 0; a < 4; ++a)
      if (t.shape[a] != 0.0) mm = std::min(mm, m.sim.nodes.mass[t.master[a]]);
  const Real ms = m.sim.nodes.mass[m.tie->links()[0].slave];
  EXPECT_NEAR(m.tie->stable_dt(), 2.0 / std::sqrt(k * (1.0 / ms + 1.0 / mm)), 1e-9);
}

}  // namespace
