// The cached Gauss-Seidel path of solve_forward_increment (a LagrangeWorkspace) against the
// reference loop: the same iteration, so the same sweep count and the same multipliers, forces and
// accelerations to round-off. A slave grid on a master plate, shared master nodes coupling the
// constraints, friction on, some components fixed.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

#include "plate_surface.hpp"
#include "slideline/contact/enforcement/lagrange.hpp"

namespace slideline {
namespace {

struct Plate {
  NodalFields nodes;
  std::vector<LagrangeConstraint> cs;
  std::vector<Real> mass, damping;
  std::vector<std::uint8_t> fixed_y, free_, rigid;
  Vec3Field a, force, fc;

  explicit Plate(Index n) {
    Vec3Field x;
    const Surface master = test::make_plate(x, n, n, 1.0, Vec3::Zero());
    const Index nm = static_cast<Index>(x.size());
    for (Index j = 0; j < n; ++j)
      for (Index i = 0; i < n; ++i) {
        LagrangeConstraint c;
        c.slave = static_cast<Index>(x.size());
        // Slaves 1e-4 above or below the plate (some in contact, some not), off the grid lines.
        x.x.push_back(0.37 + i);
        x.y.push_back(0.41 + j);
        x.z.push_back((i + j) % 3 == 0 ? 1e-4 : -1e-4);
        const Index s = i + n * j;
        for (int k = 0; k < 4; ++k) c.master[static_cast<std::size_t>(k)] = master.conn[4 * static_cast<std::size_t>(s) + k];
        const Real u = 2 * 0.37 - 1, v = 2 * 0.41 - 1;
        c.shape = {0.25 * (1 - u) * (1 - v), 0.25 * (1 + u) * (1 - v), 0.25 * (1 + u) * (1 + v), 0.25 * (1 - u) * (1 + v)};
        c.normal = Vec3::UnitZ();
        c.mu = 0.3;
        c.lambda = (i % 2) ? 0.5 : 0.0;  // a partial warm start
        cs.push_back(c);
      }
    const std::size_t nn = x.size();
    nodes.resize(nn);
    nodes.x = x;
    for (std::size_t k = 0; k < nn; ++k) nodes.v.set(static_cast<Index>(k), Vec3(0.2, -0.1, 0.0));
    mass.assign(nn, 1.0);
    for (std::size_t k = 0; k < nn; ++k) mass[k] = 1.0 + 0.1 * static_cast<Real>(k % 7);
    damping.assign(nn, 15.0);
    fixed_y.assign(nn, 0);
    for (Index k = 0; k < nm; k += 5) fixed_y[static_cast<std::size_t>(k)] = 1;
    free_.assign(nn, 0);
    rigid.assign(nn, 0);
    a.resize(nn);
    force.resize(nn);
    fc.resize(nn);
    for (Index k = 0; k < static_cast<Index>(nn); ++k) a.set(k, Vec3(3.0, 0.5, k >= nm ? -10.0 : 0.0));
  }
  ConstraintView view() { return {nodes, mass, damping, {free_, fixed_y, free_}, rigid, a, force, fc}; }
};

TEST(LagrangeSolve, CachedSweepsMatchTheReferenceLoop) {
  Plate ref(12), fast(12);
  const StepTimes t{0.1, 1e-3, 1e-3, 1e-3, 100, 1e-3};
  LagrangeSolveOptions opt;
  opt.tolerance = 1e-13;
  const auto r1 = solve_forward_increment(ref.cs, ref.view(), t, opt);
  LagrangeWorkspace ws;
  ws.dx.assign(fast.nodes.size(), Vec3::Zero());
  ws.rows.reserve(fast.cs.size());
  const auto r2 = solve_forward_increment(fast.cs, fast.view(), t, opt, nullptr, &ws);
  ASSERT_TRUE(r1.converged);
  EXPECT_TRUE(r2.converged);
  EXPECT_EQ(r1.sweeps, r2.sweeps);
  Real lmax = 0.0;
  for (const auto& c : ref.cs) lmax = std::max(lmax, c.lambda);
  ASSERT_GT(lmax, 1.0);  // loaded: the constraints carry the slaves' weight
  for (std::size_t k = 0; k < ref.cs.size(); ++k) {
    EXPECT_NEAR(ref.cs[k].lambda, fast.cs[k].lambda, 1e-9 * lmax) << k;
    EXPECT_NEAR((ref.cs[k].tau - fast.cs[k].tau).norm(), 0.0, 1e-9 * lmax) << k;
    EXPECT_NEAR((ref.cs[k].slip - fast.cs[k].slip).norm(), 0.0, 1e-12) << k;
  }
  for (Index i = 0; i < static_cast<Index>(ref.nodes.size()); ++i) {
    EXPECT_NEAR((ref.a.get(i) - fast.a.get(i)).norm(), 0.0, 1e-9 * lmax) << i;
    EXPECT_NEAR((ref.fc.get(i) - fast.fc.get(i)).norm(), 0.0, 1e-9 * lmax) << i;
  }
}

/// The interface's master_force is what the solve added to master nodes: the change of their
/// contact force, summed (not the slave forces negated), on both paths and through a withdrawal.
TEST(LagrangeSolve, MasterAddedIsTheForceTheMasterNodesReceived) {
  for (const bool cached : {false, true}) {
    Plate p(6);
    const StepTimes t{0.1, 1e-3, 1e-3, 1e-3, 100, 1e-3};
    LagrangeWorkspace ws;
    ws.dx.assign(p.nodes.size(), Vec3::Zero());
    ws.rows.reserve(p.cs.size());
    Vec3 master_added = Vec3::Zero();
    solve_forward_increment(p.cs, p.view(), t, {}, nullptr, cached ? &ws : nullptr, &master_added);
    const Index nm = p.cs.front().slave;  // master nodes come first (Plate)
    Vec3 on_masters = Vec3::Zero(), on_slaves = Vec3::Zero();
    for (Index k = 0; k < static_cast<Index>(p.nodes.size()); ++k) (k < nm ? on_masters : on_slaves) += p.fc.get(k);
    ASSERT_GT(on_slaves.norm(), 1.0) << cached;
    EXPECT_LT((master_added - on_masters).norm(), 1e-12 * on_slaves.norm()) << cached;
    EXPECT_LT((on_slaves + on_masters).norm(), 1e-12 * on_slaves.norm()) << cached;
    withdraw_constraint_forces(p.cs, p.view(), t, nullptr, &master_added);
    EXPECT_LT(master_added.norm(), 1e-12 * on_slaves.norm()) << cached;
  }
}

// A mortar constraint (LagrangeConstraint::mortar_count > 0) whose node list is its segment's
// nodes with their shape functions is the segment constraint: the same multipliers, forces and
// accelerations, bit for bit, on both paths.
TEST(LagrangeSolve, MortarListOfOneSegmentIsTheSegmentConstraint) {
  for (const bool cached : {false, true}) {
    Plate ref(6), mortar(6);
    std::vector<std::array<Index, 4>> nodes(mortar.cs.size());
    std::vector<std::array<Real, 4>> weights(mortar.cs.size());
    for (std::size_t k = 0; k < mortar.cs.size(); ++k) {
      LagrangeConstraint& c = mortar.cs[k];
      nodes[k] = c.master;
      weights[k] = c.shape;
      c.master = {0, 0, 0, 0};  // not used by a mortar constraint
      c.shape = {0.0, 0.0, 0.0, 0.0};
      c.mortar_node = nodes[k].data();
      c.mortar_weight = weights[k].data();
      c.mortar_count = 4;
    }
    const StepTimes t{0.1, 1e-3, 1e-3, 1e-3, 100};
    LagrangeWorkspace ws1, ws2;
    for (auto* w : {&ws1, &ws2}) {
      w->dx.assign(ref.nodes.size(), Vec3::Zero());
      w->rows.reserve(ref.cs.size());
    }
    Vec3 added_ref = Vec3::Zero(), added_mortar = Vec3::Zero();
    const auto r1 = solve_forward_increment(ref.cs, ref.view(), t, {}, nullptr, cached ? &ws1 : nullptr, &added_ref);
    const auto r2 =
        solve_forward_increment(mortar.cs, mortar.view(), t, {}, nullptr, cached ? &ws2 : nullptr, &added_mortar);
    EXPECT_EQ(r1.sweeps, r2.sweeps) << cached;
    ASSERT_GT(r1.sweeps, 1) << cached;
    for (std::size_t k = 0; k < ref.cs.size(); ++k) {
      EXPECT_EQ(ref.cs[k].lambda, mortar.cs[k].lambda) << k;
      EXPECT_EQ(ref.cs[k].tau, mortar.cs[k].tau) << k;
      EXPECT_EQ(ref.cs[k].slip, mortar.cs[k].slip) << k;
    }
    for (Index i = 0; i < static_cast<Index>(ref.nodes.size()); ++i) {
      EXPECT_EQ(ref.a.get(i), mortar.a.get(i)) << i;
      EXPECT_EQ(ref.fc.get(i), mortar.fc.get(i)) << i;
    }
    EXPECT_EQ(added_ref, added_mortar);
  }
}

}  // namespace
}  // namespace slideline
