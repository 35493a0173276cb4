// A tie at a real stand-off carries its offset in the master segment's frame (TiebreakContact::
// tie_stretch; docs/contact.md, "Tie offsets under rotation"): two parallel shell plates, the
// slave plate h = 0.1 above the master (within the tie search's 0.3 x the segment's diagonal),
// tied by Type 8 / Type 9 (the class of the automatic tiebreak OPTIONs 2-6, 9), then the pair is
// turned rigidly about an axis by up to 90 degrees, positions set by hand (a kinematic check: no
// dynamics to spoil the rigid motion).
// Closed form: a rigid motion leaves every tie unstretched, so the tie force is zero (round-off of
// k h). An offset kept in global components stretches each tie by |(Q - I) d| = 2 h sin(theta / 2)
// (h sqrt 2 = 0.141 at 90 degrees), a force of k h sqrt 2.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "slideline/contact/tiebreak_contact.hpp"
#include "tie_fixtures.hpp"

using namespace slideline;
using namespace slideline::test;

namespace {

constexpr Real kStandOff = 0.1;

struct TwoPlates {
  SimulationSetup setup;
  std::vector<Index> slaves;
  std::vector<Vec3> x0;  // the positions before the spin (after `place`)

  /// Master plate 2 x 2 quads on [0, 1]^2 in the x-z plane, slave plate the same at y = h, both
  /// placed by `place` (a rigid motion).
  explicit TwoPlates(const Eigen::Matrix3d& place) {
    TieMesh mesh;
    const int n = 2;
    for (int layer = 0; layer < 2; ++layer)
      for (int k = 0; k <= n; ++k)
        for (int i = 0; i <= n; ++i) mesh.x.push_back(place * Vec3(Real(i) / n, layer * kStandOff, Real(k) / n));
    mesh.fill(setup.nodes);
    std::vector<Index> mc, sc;
    auto node = [&](int layer, int i, int k) { return static_cast<Index>(layer * (n + 1) * (n + 1) + i + (n + 1) * k); };
    for (int k = 0; k < n; ++k)
      for (int i = 0; i < n; ++i) {
        mc.insert(mc.end(), {node(0, i, k), node(0, i, k + 1), node(0, i + 1, k + 1), node(0, i + 1, k)});
        sc.insert(sc.end(), {node(1, i, k), node(1, i + 1, k), node(1, i + 1, k + 1), node(1, i, k + 1)});
      }
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i <= n; ++i) slaves.push_back(node(1, i, k));
    setup.blocks.push_back(elastic_shells(1, mc, 1.0, 1000.0, 0.3, 0.05));
    setup.blocks.push_back(elastic_shells(2, sc, 1.0, 1000.0, 0.3, 0.05));
    for (auto& b : setup.blocks) b->initialize(setup.nodes);
    for (Index i = 0; i < static_cast<Index>(setup.nodes.size()); ++i) x0.push_back(setup.nodes.x.get(i));
  }
};

/// Ties the plates (`unit`), turns them rigidly about `axis` through `centre` in steps up to 90
/// degrees and returns the largest tie force on any node over the steps, over k h (k the stiffest
/// link's spring).
Real largest_force_under_spin(TiebreakParameters::FailureUnit unit, const Eigen::Matrix3d& place, const Vec3& axis) {
  TwoPlates m(place);
  TiebreakParameters p;
  p.unit = unit;
  p.penalty_factor = 0.1;
  Surface slave_surface = unit == TiebreakParameters::FailureUnit::segment ? part_surface(m.setup, 2) : Surface{};
  TiebreakContact tie("standoff", m.slaves, std::move(slave_surface), part_surface(m.setup, 1), p);
  NodalFields& nodes = m.setup.nodes;
  tie.initialize(ContactContext{nodes, m.setup.blocks});
  EXPECT_EQ(tie.links().size(), m.slaves.size());
  Real k = 0.0;
  for (std::size_t l = 0; l < tie.links().size(); ++l) k = std::max(k, tie.stiffness(l));
  EXPECT_GT(k, 0.0);
  Vec3Field f, moment;
  f.resize(nodes.size());
  moment.resize(nodes.size());
  const Vec3 centre = place * Vec3(0.3, 0.5, 0.2);
  StepTimes times;
  times.dt_avg = times.dt_next = 1e-3;
  Real worst = 0.0;
  for (int s = 0; s <= 18; ++s) {
    const Eigen::Matrix3d q = Eigen::AngleAxisd(0.5 * M_PI * s / 18.0, axis.normalized()).toRotationMatrix();
    for (Index i = 0; i < static_cast<Index>(nodes.size()); ++i) nodes.x.set(i, centre + q * (m.x0[i] - centre) + Vec3(0.4, -0.2, 0.1));
    f.fill(0.0);
    moment.fill(0.0);
    times.t = 1e-3 * s;
    times.cycle = s;
    tie.apply_forces(nodes, times, ContactForceView{f, moment});
    for (Index i = 0; i < static_cast<Index>(nodes.size()); ++i) worst = std::max(worst, f.get(i).norm());
  }
  for (auto r : tie.released()) EXPECT_EQ(r, 0);
  return worst / (k * kStandOff);
}

Eigen::Matrix3d turned() { return Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, 3.0).normalized()).toRotationMatrix(); }

}  // namespace

TEST(TiebreakStandOff, RigidSpinOfTiedPlatesLeavesTheTiesUnstretched) {
  for (const auto unit : {TiebreakParameters::FailureUnit::node, TiebreakParameters::FailureUnit::segment}) {
    // About the plates' normal (in-plane spin), about an in-plane axis (the stand-off turns) and a skew one.
    for (const Vec3& axis : {Vec3(0, 1, 0), Vec3(1, 0, 0), Vec3(1, 1, 1)}) {
      const Real r = largest_force_under_spin(unit, Eigen::Matrix3d::Identity(), axis);
      EXPECT_LT(r, 1e-12) << "axis " << axis.transpose();
    }
  }
}

TEST(TiebreakStandOff, TurnedCopyRigidSpinLeavesTheTiesUnstretched) {
  for (const auto unit : {TiebreakParameters::FailureUnit::node, TiebreakParameters::FailureUnit::segment}) {
    for (const Vec3& axis : {Vec3(0, 1, 0), Vec3(1, 0, 0), Vec3(1, 1, 1)}) {
      const Real r = largest_force_under_spin(unit, turned(), turned() * axis);
      EXPECT_LT(r, 1e-12) << "axis " << axis.transpose();
    }
  }
}
