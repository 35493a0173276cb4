// Penalty ties with failure (Types 8, 9): TiebreakContact on a block tied to a fixed block.
#include <gtest/gtest.h>

#include <algorithm>
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
struct TiebreakBlocks : test_support::StagedSimulation {
  TieBox lower, upper;
  TiebreakContact* tie = nullptr;
  static constexpr Real kMass = 0.3;

  TiebreakBlocks(TiebreakParameters p, int nx) {
    TieMesh mesh;
    lower = mesh.add_box({0, 0, 0}, {1, 0.5, 1}, 2, 1, 2);
    upper = mesh.add_box({0, 0.5, 0}, {1, 0.3, 1}, nx, 1, nx);
    mesh.fill(setup.nodes);
    setup.blocks.push_back(elastic_hexes(1, lower, 1.0, 1000.0, 0.3));
    setup.blocks.push_back(elastic_hexes(2, upper, 1.0, 1.0e4, 0.0));
    Surface slave_surface = p.unit == TiebreakParameters::FailureUnit::segment ? part_surface(setup, 2) : Surface{};
    auto t = std::make_unique<TiebreakContact>("tiebreak", upper.layer(0), std::move(slave_surface),
                                               part_surface(setup, 1), p);
    tie = t.get();
    setup.contacts.add(std::move(t));
    setup.supports.push_back(tie_support("lower", lower.all(), {1, 1, 1}));
    MassDamping d;
    d.alpha = 5.0;  // ~10 % of critical for the block on the tie springs (~24 rad/s)
    setup.damping = {d};
    setup.controls.dt_scale = 0.8;
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
  m.setup.body_loads.push_back(ramped_load(axis, g, 2, t0, t0 + 2.0));
  if (axis == Axis::x) m.setup.body_loads.push_back(ramped_load(Axis::y, -10.0, 2, 0.0, 0.2));
  m.setup.controls.end_time = t0 + 1.6;
  m.start();
  const int c = static_cast<int>(axis);
  FailureRun r;
  bool any = false;
  while (m.sim().step()) {
    const Real f = std::abs(m.tie->slave_force()[c]);
    bool released = false;
    for (auto b : m.tie->released()) released = released || b;
    if (!any && f > r.peak) r.peak = f, r.peak_time = m.sim().time();
    if (!any && m.sim().time() > 0.1) r.energy = std::max(r.energy, std::abs(m.sim().energy().relative_balance_error()));
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
  m.setup.body_loads.push_back(ramped_load(Axis::y, g, 2, 0.0, 0.3));
  m.setup.controls.end_time = 2.0;
  m.start();
  while (m.sim().step()) {
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

/// In compression a Type 9 tie pushes with the stiffness of the penalty contact that takes over
/// after failure: the total of the node springs kappa A_master (16 slave nodes on master faces of
/// 0.25: 16 x 166.7 x 0.25 = 666.7), spread by tributary area so that the gap stays uniform. The
/// same in a rotated copy (every node and the load turned by R; the lower block is fixed in x, y, z).
TEST(TiebreakSurface, CompressionUsesTheContactStiffnessSpreadByArea) {
  const Real kappa = 0.1 * (1000.0 / 1.2) / 0.5;  // f K / h of the lower block's top elements
  const Real expected = -1.5 / (16 * kappa * 0.25);
  for (const Mat3 r : {Mat3(Mat3::Identity()), Mat3(Eigen::AngleAxis<Real>(0.7, Vec3(1, 2, 3).normalized()))}) {
    TiebreakBlocks m(parameters(TiebreakParameters::FailureUnit::segment, 0.0, 0.0), 3);
    for (std::size_t i = 0; i < m.setup.nodes.size(); ++i) {
      m.setup.nodes.x0.set(static_cast<Index>(i), r * m.setup.nodes.x0.get(static_cast<Index>(i)));
      m.setup.nodes.x.set(static_cast<Index>(i), r * m.setup.nodes.x.get(static_cast<Index>(i)));
    }
    const Vec3 up = r * Vec3(0, 1, 0), g = -5.0 * up;  // total 1.5 pressing the upper block down
    for (int c = 0; c < 3; ++c) m.setup.body_loads.push_back(ramped_load(static_cast<Axis>(c), g[c], 2, 0.0, 0.3));
    m.setup.controls.end_time = 2.0;
    m.start();
    while (m.sim().step()) {
    }
    Real lo = 1e300, hi = -1e300;
    for (Index n : m.upper.layer(0)) {
      const Real gap = m.sim().nodes().x.get(n).dot(up) - 0.5;
      lo = std::min(lo, gap), hi = std::max(hi, gap);
    }
    const Real fn = m.tie->slave_force().dot(up);
    std::printf("type 9 compression: gap %.5e..%.5e vs %.5e, F_n %.5f\n", lo, hi, expected, fn);
    EXPECT_NEAR(fn, 1.5, 0.01 * 1.5);
    EXPECT_NEAR(lo, expected, 0.02 * std::abs(expected));
    EXPECT_NEAR(hi, expected, 0.02 * std::abs(expected));
  }
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
  // Each spring's own vote (SimulationControls::contact_step_with_elements off), then the default:
  // the same spring with the elements on its nodes, 1 / dt^2 = 1 / dt_e^2 + 1 / dt_c^2, dt_e the
  // smaller block vote (the slave's block and the masters' are the two blocks of the model).
  Real alone = 0.0;
  for (const bool with_elements : {false, true}) {
    TiebreakBlocks m(parameters(TiebreakParameters::FailureUnit::node, 1.0, 1.0), 1);
    m.setup.controls.end_time = 0.01;
    m.setup.controls.contact_step_with_elements = with_elements;
    m.start();
    // k = f K A / h of the master face (f = 0.1, K = 1000 / (3 (1 - 0.6)), A = 0.25, h = 0.5),
    // between a slave of mass 0.3 / 8 and the lightest master corner.
    const Real k = 0.1 * (1000.0 / 1.2) * 0.25 * 0.25 / (0.25 * 0.5);
    ASSERT_EQ(m.tie->links().size(), 4u);
    EXPECT_NEAR(m.tie->stiffness(0), k, 1e-9 * k);
    Real mm = 1e300;
    for (const TiePoint& t : m.tie->links())
      for (int a = 0; a < 4; ++a)
        if (t.shape[a] != 0.0) mm = std::min(mm, m.sim().nodes().mass[t.master[a]]);
    const Real ms = m.sim().nodes().mass[m.tie->links()[0].slave];
    const Real dt_c = 2.0 / std::sqrt(k * (1.0 / ms + 1.0 / mm));
    if (!with_elements) {
      alone = m.tie->stable_dt();
      EXPECT_NEAR(alone, dt_c, 1e-9);
    } else {
      const Real dt_e = m.sim().votes().elements;
      EXPECT_NEAR(m.tie->stable_dt(), 1.0 / std::sqrt(1.0 / (dt_e * dt_e) + 1.0 / (dt_c * dt_c)), 1e-12);
      EXPECT_LT(m.tie->stable_dt(), alone);
    }
  }
}

/// Type 9 between shells (issue 9, item: post-failure shell thickness): a 3 x 3 shell plate
/// (t = 0.1) on [0, 1]^2 tied to a fixed 4 x 4 shell plate (t = 0.1) on [-0.5, 1.5]^2 at the stand-off of their half
/// thicknesses, (0.1 + 0.1) / 2, pressed (3) and then sheared until the tie fails. After failure it
/// must behave as Type 3 with shell offsets: held by friction (mu 0.5 x 3 > the shear) at the same
/// stand-off, the mid-surfaces (t_s + t_m) / 2 apart.
TEST(TiebreakSurface, ShellsKeepTheirThicknessOffsetAfterFailure) {
  SimulationSetup setup;
  TieMesh mesh;
  const TieBox master = mesh.add_box({-0.5, 0.5, -0.5}, {2, 0, 2}, 4, 0, 4);  // larger: room to slide
  const Real standoff = 0.5 * (0.1 + 0.1);
  const TieBox slave = mesh.add_box({0, 0.5 + standoff, 0}, {1, 0, 1}, 3, 0, 3);
  mesh.fill(setup.nodes);
  auto quads = [](const TieBox& b) {
    std::vector<Index> c;
    for (int k = 0; k < b.nz; ++k)
      for (int i = 0; i < b.nx; ++i)
        c.insert(c.end(), {b.node(i, 0, k), b.node(i, 0, k + 1), b.node(i + 1, 0, k + 1), b.node(i + 1, 0, k)});
    return c;
  };
  setup.blocks.push_back(elastic_shells(1, quads(master), 1.0, 1000.0, 0.1, 0.1));
  setup.blocks.push_back(elastic_shells(2, quads(slave), 1.0, 1000.0, 0.1, 0.1));
  TiebreakParameters p = parameters(TiebreakParameters::FailureUnit::segment, 1e4, 1.0);
  p.penalty_factor = 2.0;
  p.friction.mu_s = p.friction.mu_k = 0.5;
  auto t = std::make_unique<TiebreakContact>("tiebreak", slave.layer(0), part_surface(setup, 2), part_surface(setup, 1), p);
  TiebreakContact* tie = t.get();
  setup.contacts.add(std::move(t));
  setup.supports.push_back(tie_support("master", master.layer(0), {1, 1, 1}));
  MassDamping d;
  d.alpha = 5.0;
  setup.damping = {d};
  setup.controls.dt_scale = 0.8;
  const Real mass = 1.0 * 0.1 * 1.0;
  setup.body_loads.push_back(ramped_load(Axis::y, -3.0 / mass, 2, 0.0, 0.2));
  setup.body_loads.push_back(ramped_load(Axis::x, 2.0 / mass, 2, 0.3, 2.3));  // 1.0 (the failure force) at t = 1.3
  setup.controls.end_time = 1.6;
  Simulation sim(std::move(setup));
  sim.initialize();
  ASSERT_EQ(tie->links().size(), slave.layer(0).size());
  Real failed_at = -1.0, x_at_failure = 0.0;
  Vec3 f_sum = Vec3::Zero();
  int n_sum = 0;
  const Index probe = slave.layer(0)[5];  // an interior node
  while (sim.step()) {
    bool all = true;
    for (auto r : tie->released()) all = all && r;
    if (all && failed_at < 0.0) failed_at = sim.time(), x_at_failure = sim.nodes().x.get(probe)[0];
    if (sim.time() >= 1.4) f_sum += tie->slave_force(), ++n_sum;  // after failure
  }
  Real lo = 1e300, hi = -1e300;
  for (Index n : slave.layer(0)) {
    const Real gap = sim.nodes().x.get(n)[1] - 0.5;
    lo = std::min(lo, gap), hi = std::max(hi, gap);
  }
  const Vec3 f = f_sum / std::max(n_sum, 1);
  const Real slip = sim.nodes().x.get(probe)[0] - x_at_failure;
  std::printf("type 9 shells: released at t %.3f, stand-off after failure %.5f..%.5f (expected %.3f), mean F on "
              "[1.4, 1.6] (%.3f %.3f), slip after failure %.2e\n",
              failed_at, lo, hi, standoff, f[0], f[1], slip);
  EXPECT_GT(failed_at, 1.25);  // the shear reaches the failure force 1.0 at t = 1.3
  EXPECT_LT(failed_at, 1.35);
  // The contact surfaces stay (t_s + t_m) / 2 apart, less the penalty's give under the load of 3.
  EXPECT_NEAR(lo, standoff, 0.05 * standoff);
  EXPECT_NEAR(hi, standoff, 0.05 * standoff);
  EXPECT_NEAR(f[1], 3.0, 0.02 * 3.0);   // the compression carried by the contact
  EXPECT_NEAR(f[0], -1.2, 0.05 * 1.2);  // friction holds the mean shear load on [1.4, 1.6]
  EXPECT_LT(std::abs(slip), 0.005);     // stuck: mu N = 1.5 > 1.3
}

/// Progressive Type 9 failure (issue 17): a 1 x 1 x 1 block (3 x 2 x 3 hexahedra) pressed (3) onto
/// the top of a deformable 1.5 x 0.5 x 1 block supported on its bottom (y, z) and its right face
/// (x), then sheared in +x. Shear lag (the lower block's top shortens towards its support) loads the
/// right column of segments most: it fails first, the rest later, so corner nodes are partly
/// failed for a while. The failed share of a node is in contact with the same stiffness as the tie:
/// the total normal force must not jump when segments fail (before the hand-over it dropped by the
/// failed share until the node's last segment failed), and the failed area keeps carrying friction.
TEST(TiebreakSurface, NormalForceIsContinuousThroughAProgressiveFailure) {
  SimulationSetup setup;
  TieMesh mesh;
  const TieBox lower = mesh.add_box({0, 0, 0}, {1.5, 0.5, 1}, 3, 1, 2);
  const TieBox upper = mesh.add_box({0.02, 0.5, 0.01}, {1, 1, 0.98}, 3, 2, 3);
  mesh.fill(setup.nodes);
  setup.blocks.push_back(elastic_hexes(1, lower, 1.0, 1000.0, 0.1));
  setup.blocks.push_back(elastic_hexes(2, upper, 1.0, 1000.0, 0.1));
  TiebreakParameters p = parameters(TiebreakParameters::FailureUnit::segment, 1e4, 0.7);
  p.penalty_factor = 1.0;
  p.friction.mu_s = p.friction.mu_k = 0.2;
  auto t = std::make_unique<TiebreakContact>("tiebreak", upper.layer(0), part_surface(setup, 2), part_surface(setup, 1), p);
  TiebreakContact* tie = t.get();
  setup.contacts.add(std::move(t));
  setup.supports.push_back(tie_support("bottom", lower.layer(0), {0, 1, 1}));
  std::vector<Index> right;
  for (Index n : lower.all())
    if (setup.nodes.x0.get(n)[0] > 1.5 - 1e-9) right.push_back(n);
  setup.supports.push_back(tie_support("right", right, {1, 0, 0}));
  MassDamping d;
  d.alpha = 20.0;
  setup.damping = {d};
  setup.controls.dt_scale = 0.8;
  const Real mass = 0.98;  // the upper block, rho = 1
  setup.body_loads.push_back(ramped_load(Axis::y, -3.0 / mass, 2, 0.0, 0.5));
  setup.body_loads.push_back(ramped_load(Axis::x, 1.0 / mass, 2, 1.0, 3.0));  // 1.0 at t = 3
  setup.controls.end_time = 3.0;
  Simulation sim(std::move(setup));
  sim.initialize();
  Real first = -1.0, last = -1.0, fy_lo = 1e300, fy_hi = -1e300, balance = 0.0, fx_partial = 0.0;
  while (sim.step()) {
    const auto& failed = tie->failed_segments();
    const auto& released = tie->released();
    const long n_failed = std::count(failed.begin(), failed.end(), std::uint8_t{1});
    const long n_released = std::count(released.begin(), released.end(), std::uint8_t{1});
    const Vec3 f = tie->slave_force();
    balance = std::max(balance, (f + tie->master_force()).norm() / std::max(f.norm(), 1e-30));
    const long n_tied = static_cast<long>(failed.size()) - 9;  // segments off the interface never tie
    if (n_failed > n_tied && first < 0.0) first = sim.time();
    if (first >= 0.0 && n_released < static_cast<long>(released.size())) {
      fy_lo = std::min(fy_lo, f[1]), fy_hi = std::max(fy_hi, f[1]);
      fx_partial = std::max(fx_partial, -f[0]);
    }
    if (n_released == static_cast<long>(released.size()) && last < 0.0) last = sim.time();
  }
  std::printf("type 9 progressive: first failure t %.4f, all released t %.4f, F_y during failure %.4f..%.4f, "
              "peak -F_x %.4f, balance %.1e\n",
              first, last, fy_lo, fy_hi, fx_partial, balance);
  ASSERT_GT(first, 1.0);
  ASSERT_GT(last, first + 0.02);  // progressive: the failure spreads over many cycles
  EXPECT_NEAR(fy_lo, 3.0, 0.02 * 3.0);
  EXPECT_NEAR(fy_hi, 3.0, 0.02 * 3.0);
  // The failed area keeps its friction, so the interface still reaches the failure load tau A
  // (0.559, 19 % short, when a failed share carried nothing until its node was released).
  EXPECT_NEAR(fx_partial, 0.7 * mass, 0.03 * 0.7 * mass);
  EXPECT_LT(balance, 1e-12);  // master force: the sum of what was added to the master nodes
}

}  // namespace
