// Kinematic tied interfaces (Types 2, 6, 7): TiedSurfaceContact and TiedShellEdgeContact on small meshes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "slideline/contact/tied_contact.hpp"
#include "slideline/element/rigid_mass_block.hpp"
#include "slideline/solver/rigid_body.hpp"
#include "tie_fixtures.hpp"

using namespace slideline;
using namespace slideline::test;

namespace {

constexpr Real kE = 1000.0, kNu = 0.3, kRho = 1.0;

/// Largest |x_s - sum N x_m - d| and |v_s - sum N v_m| over the tie's links.
template <class Kind>
Real tie_drift(const TiedInterface<Kind>& tie, const NodalFields& nodes) {
  Real d = 0.0;
  for (const TiePoint& t : tie.links()) {
    d = std::max(d, (nodes.x.get(t.slave) - tie_point_value(t, nodes.x) - t.offset).norm());
    d = std::max(d, (nodes.v.get(t.slave) - tie_point_value(t, nodes.v)).norm());
  }
  return d;
}

/// Upper 3x1x3 block [0.1, 0.9] x [1, 1.4] x [0.1, 0.9] tied by its bottom nodes to the top face
/// of the lower 2x1x2 block [0, 1]^3 (slave and master nodes not coincident, 3:2).
struct TiedBlocks : test_support::StagedSimulation {
  TieBox lower, upper;
  TiedSurfaceContact* tie = nullptr;
  Real upper_mass = kRho * 0.8 * 0.4 * 0.8;

  explicit TiedBlocks(bool rigid_lower = false, Real shift = 0.0) {
    TieMesh mesh;
    lower = mesh.add_box({0, 0, 0}, {1, 1, 1}, 2, 1, 2);
    upper = mesh.add_box({0.1 + shift, 1.0, 0.1}, {0.8, 0.4, 0.8}, 3, 1, 3);
    mesh.fill(setup.nodes);
    if (rigid_lower) {
      setup.blocks.push_back(make_rigid_mass_block(1, kRho, kE, kNu, lower.conn(), {}, 0.0, {101, 102, 103, 104}));
      setup.constraints.push_back(make_rigid_body(1, lower.all(), {0, 0, 0, 0, 0, 0}));
    } else {
      setup.blocks.push_back(elastic_hexes(1, lower, kRho, kE, kNu));
    }
    setup.blocks.push_back(elastic_hexes(2, upper, kRho, kE, kNu));
    auto t = std::make_unique<TiedSurfaceContact>("tie", upper.layer(0), part_surface(setup, 1));
    tie = t.get();
    setup.contacts.add(std::move(t));
    setup.controls.end_time = 0.4;
    setup.controls.dt_scale = 0.8;
  }
};

struct LoadCase {
  const char* name;
  Real gy;  ///< body acceleration in y on the upper block (+: tension, pulls it off)
};

class TiedStatic : public ::testing::TestWithParam<LoadCase> {};

TEST_P(TiedStatic, HoldsTheLoadWithoutRelativeMotionAndBalancedForces) {
  const LoadCase lc = GetParam();
  TiedBlocks m;
  m.setup.supports.push_back(tie_support("bottom", m.lower.layer(0), {1, 1, 1}));
  MassDamping d;
  d.alpha = 20.0;  // near critical for the blocks' slowest (shear) mode, ~25 rad/s
  m.setup.damping = {d};
  m.setup.controls.end_time = 1.0;
  const Real gx = 0.3 * std::abs(lc.gy);
  m.setup.body_loads.push_back(ramped_load(Axis::y, lc.gy, 2, 0.0, 0.05));
  m.setup.body_loads.push_back(ramped_load(Axis::x, gx, 2, 0.05, 0.1));
  m.start();
  ASSERT_EQ(m.tie->links().size(), 16u);
  ASSERT_TRUE(m.tie->untied_nodes().empty());
  Real drift = 0.0, balance = 0.0, energy = 0.0;
  while (m.sim().step()) {
    drift = std::max(drift, tie_drift(*m.tie, m.sim().nodes()));
    const Vec3 fs = m.tie->slave_force(), fm = m.tie->master_force();
    if (fs.norm() > 0.0) balance = std::max(balance, (fs + fm).norm() / fs.norm());
    if (m.sim().time() > 0.05) energy = std::max(energy, std::abs(m.sim().energy().relative_balance_error()));
  }
  const Vec3 fs = m.tie->slave_force();
  const Vec3 load = m.upper_mass * Vec3(gx, lc.gy, 0.0);
  const Vec3 u = m.sim().nodes().displacement(m.upper.layer(0)[5]);
  std::printf("%s: drift %.2e, |Fs+Fm|/|Fs| %.2e, F_slave (%.5f, %.5f) vs -load (%.5f, %.5f), energy error %.2e, "
              "u_slave (%.2e, %.2e)\n",
              lc.name, drift, balance, fs[0], fs[1], -load[0], -load[1], energy, u[0], u[1]);
  EXPECT_LT(drift, 1e-6 * 0.5);             // below 1e-6 of the element size
  EXPECT_LT(balance, 1e-13);                // equal and opposite to round-off
  EXPECT_NEAR(fs[1], -load[1], 0.01 * std::abs(load[1]));
  EXPECT_NEAR(fs[0], -load[0], 0.01 * std::abs(load[0]));
  EXPECT_LT(energy, 0.01);
  EXPECT_GT(u.norm(), 1e-4);                // the slaves did move with the deforming master
}

INSTANTIATE_TEST_SUITE_P(Loads, TiedStatic,
                         ::testing::Values(LoadCase{"tension", 40.0}, LoadCase{"compression", -40.0}),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(TiedContact, SupportedMasterCarriesTheSlaveLoadIntoItsReaction) {
  TiedBlocks m;
  m.setup.supports.push_back(tie_support("bottom", m.lower.layer(0), {1, 1, 1}));
  m.setup.supports.push_back(tie_support("top", m.lower.layer(1), {1, 1, 1}));
  MassDamping d;
  d.alpha = 60.0;
  m.setup.damping = {d};
  const Real g = -30.0;
  m.setup.body_loads.push_back(ramped_load(Axis::y, g, 2, 0.0, 0.05));
  m.start();
  Real drift = 0.0;
  while (m.sim().step()) drift = std::max(drift, tie_drift(*m.tie, m.sim().nodes()));
  const Real load = m.upper_mass * g;
  EXPECT_NEAR(m.sim().supports()[1].reaction[1], load, 1e-3 * std::abs(load));
  EXPECT_NEAR(m.tie->slave_force()[1], -load, 1e-3 * std::abs(load));
  EXPECT_LT(drift, 1e-13);
  // Supported masters do not move: neither do their slaves.
  for (Index s : m.upper.layer(0)) EXPECT_LT(m.sim().nodes().displacement(s).norm(), 1e-13);
}

TEST(TiedContact, FollowsASpinningRigidMaster) {
  TiedBlocks m(/*rigid_lower=*/true);
  const Vec3 v0(0.3, 0.0, 0.0), w(0.0, 0.5, 0.0), c(0.5, 0.5, 0.5);
  for (std::size_t i = 0; i < m.setup.nodes.size(); ++i) {
    const Index n = static_cast<Index>(i);
    m.setup.nodes.v.set(n, v0 + w.cross(m.setup.nodes.x.get(n) - c));
  }
  m.setup.body_loads.push_back(ramped_load(Axis::y, 10.0, 2, 0.0, 0.02));
  m.setup.controls.end_time = 0.2;
  m.start();
  Real drift = 0.0;
  while (m.sim().step()) drift = std::max(drift, tie_drift(*m.tie, m.sim().nodes()));
  EXPECT_LT(drift, 1e-12);
  // The block turned with the body (0.1 rad about y): the tied nodes moved by much more than the drift.
  EXPECT_GT(m.sim().nodes().displacement(m.upper.layer(0)[0]).norm(), 0.03);
  const Vec3 fs = m.tie->slave_force(), fm = m.tie->master_force();
  EXPECT_LT((fs + fm).norm(), 1e-12 * std::max(1.0, fs.norm()));
}

TEST(TiedContact, ReportsAndFreesSlavesOutsideTheMaster) {
  TiedBlocks m(false, /*shift=*/0.5);  // the upper block overhangs the lower one by 0.4 in x
  m.setup.controls.end_time = 0.01;
  m.start();
  // Slave columns at x = 0.6, 0.867, 1.133, 1.4: the last two lie off the master (x <= 1).
  EXPECT_EQ(m.tie->links().size(), 8u);
  ASSERT_EQ(m.tie->untied_nodes().size(), 8u);
  for (Index s : m.tie->untied_nodes()) EXPECT_GT(m.sim().nodes().x.x[s], 1.0);
  EXPECT_EQ(m.tie->dictated_nodes().size(), 8u);
}

/// Type 7: a vertical shell plate (y-z plane, x = 0.375) whose bottom edge is tied to a horizontal
/// shell plate (x-z plane, y = 0) clamped along its four edges.
struct ShellEdgeTie : test_support::StagedSimulation {
  std::vector<Index> plate_edges, edge, top;
  Index master_first = 0, slave_first = 0;
  TiedShellEdgeContact* tie = nullptr;
  ShellEdgeTie() {
    TieMesh mesh;
    const int n = 4;
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i <= n; ++i) mesh.x.push_back(Vec3(Real(i) / n, 0.0, Real(k) / n));
    slave_first = static_cast<Index>(mesh.x.size());
    const int ny = 2, nz = 3;
    for (int k = 0; k <= nz; ++k)
      for (int j = 0; j <= ny; ++j) mesh.x.push_back(Vec3(0.375, 0.3 * j / ny, 0.2 + 0.6 * k / nz));
    mesh.fill(setup.nodes);
    std::vector<Index> mc, sc;
    auto mn = [&](int i, int k) { return static_cast<Index>(i + (n + 1) * k); };
    auto sn = [&](int j, int k) { return slave_first + static_cast<Index>(j + (ny + 1) * k); };
    for (int k = 0; k < n; ++k)
      for (int i = 0; i < n; ++i) mc.insert(mc.end(), {mn(i, k), mn(i, k + 1), mn(i + 1, k + 1), mn(i + 1, k)});
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j) sc.insert(sc.end(), {sn(j, k), sn(j + 1, k), sn(j + 1, k + 1), sn(j, k + 1)});
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i <= n; ++i)
        if (i == 0 || k == 0 || i == n || k == n) plate_edges.push_back(mn(i, k));
    for (int k = 0; k <= nz; ++k) edge.push_back(sn(0, k)), top.push_back(sn(ny, k));
    setup.blocks.push_back(elastic_shells(1, mc, 1.0, 1000.0, 0.1, 0.05));
    setup.blocks.push_back(elastic_shells(2, sc, 1.0, 1000.0, 0.1, 0.05));
    std::vector<Index> candidates(edge);
    candidates.insert(candidates.end(), top.begin(), top.end());  // too far from the surface: left free
    auto t = std::make_unique<TiedShellEdgeContact>("edge", candidates, part_surface(setup, 1));
    tie = t.get();
    setup.contacts.add(std::move(t));
    setup.supports.push_back(tie_support("edges", plate_edges, {1, 1, 1}));
    MassDamping d;
    d.alpha = 30.0;
    setup.damping = {d};
    setup.controls.end_time = 1.0;
    setup.controls.dt_scale = 0.8;
  }
};

void run_shell_edge(Axis axis, Real g, const char* name) {
  ShellEdgeTie m;
  m.setup.body_loads.push_back(ramped_load(axis, g, 2, 0.0, 0.1));
  m.start();
  ASSERT_EQ(m.tie->links().size(), m.edge.size());
  ASSERT_EQ(m.tie->untied_nodes().size(), m.top.size());
  Real drift = 0.0, spin = 0.0, energy = 0.0;
  while (m.sim().step()) {
    drift = std::max(drift, tie_drift(*m.tie, m.sim().nodes()));
    for (const TiePoint& t : m.tie->links())
      spin = std::max(spin, (m.sim().nodes().omega.get(t.slave) - tie_point_value(t, m.sim().nodes().omega)).norm());
    if (m.sim().time() > 0.05) energy = std::max(energy, std::abs(m.sim().energy().relative_balance_error()));
  }
  // The master plate's rotation about z under the edge (bending) or its deflection (tension).
  const TiePoint& mid = m.tie->links()[1];
  const Vec3 u_edge = m.sim().nodes().displacement(mid.slave);
  Real rot = 0.0;
  for (int a = 0; a < 4; ++a) rot += mid.shape[a] * m.sim().nodes().omega.z[mid.master[a]];
  const Real load = 1.0 * 0.05 * 0.3 * 0.6 * g;
  const Vec3 fs = m.tie->slave_force();
  std::printf("type 7 %s: drift %.2e, omega mismatch %.2e, u_edge (%.2e, %.2e, %.2e), F_slave (%.4e, %.4e) "
              "vs -load %.4e, energy error %.2e\n",
              name, drift, spin, u_edge[0], u_edge[1], u_edge[2], fs[0], fs[1], -load, energy);
  EXPECT_LT(drift, 1e-12);
  EXPECT_LT(spin, 1e-12);
  EXPECT_LT(energy, 0.01);
  const int c = static_cast<int>(axis);
  EXPECT_NEAR(fs[c], -load, 0.01 * std::abs(load));
  if (axis == Axis::y) EXPECT_GT(u_edge[1], 1e-4);       // the surface bulged up and the edge with it
  else EXPECT_GT(std::abs(m.sim().nodes().omega.z[mid.slave]) + std::abs(rot), 0.0);
  (void)rot;
}

TEST(TiedShellEdge, FollowsTheSurfaceInTension) { run_shell_edge(Axis::y, 40.0, "tension"); }

TEST(TiedShellEdge, TransfersBendingIntoTheSurface) {
  ShellEdgeTie m;
  m.setup.body_loads.push_back(ramped_load(Axis::x, 20.0, 2, 0.0, 0.1));
  m.start();
  Real drift = 0.0, spin = 0.0, max_rot = 0.0;
  while (m.sim().step()) {
    drift = std::max(drift, tie_drift(*m.tie, m.sim().nodes()));
    for (const TiePoint& t : m.tie->links())
      spin = std::max(spin, (m.sim().nodes().omega.get(t.slave) - tie_point_value(t, m.sim().nodes().omega)).norm());
  }
  // The plate's bending moment at the edge turned the master surface about z under the edge: the
  // master nodes beside the edge moved in y in opposite directions.
  const TiePoint& mid = m.tie->links()[1];
  Real uy_left = 0.0, uy_right = 0.0;
  for (int a = 0; a < 4; ++a) {
    const Index mn = mid.master[a];
    (m.sim().nodes().x0.x[mn] < 0.375 ? uy_left : uy_right) += m.sim().nodes().displacement(mn)[1];
  }
  max_rot = std::abs(uy_left - uy_right);
  const Vec3 u_top = m.sim().nodes().displacement(m.top[1]);
  std::printf("type 7 bending: drift %.2e, omega mismatch %.2e, master uy left %.3e right %.3e, top u_x %.3e\n",
              drift, spin, uy_left, uy_right, u_top[0]);
  EXPECT_LT(drift, 1e-12);
  EXPECT_LT(spin, 1e-12);
  EXPECT_GT(u_top[0], 1e-3);                   // the plate bent over in +x
  EXPECT_LT(uy_left * uy_right, 0.0);          // the surface turned under the edge (moment transferred)
  EXPECT_GT(max_rot, 1e-4);
}

}  // namespace
