// Kinematic ties (Types 2, 6, 7) keep a tie-time offset in the master segment's frame
// (tied_contact.hpp, tie_offset.hpp; docs/contact.md, "Tied offsets that turn"): positions set by
// hand, no dynamics.
// Closed forms: under a rigid rotation Q of the master nodes the slave goes to sum N x_a + Q d
// (d the tie-time offset); a slave on its master surface (zero offset) is not carried and goes to
// sum N x_a + d exactly as before; the slave's velocity is its master point's, sum N v_a (the
// offset's own rate left out), as for a zero offset.
#include <gtest/gtest.h>

#include <cmath>

#include "slideline/contact/tied_contact.hpp"
#include "tie_fixtures.hpp"

using namespace slideline;
using namespace slideline::test;

namespace {

constexpr Real kGap = 0.01;

/// A unit cube (master: its top face) and a 1 x 0.5 x 1 block above it, the first `gapped` of its
/// bottom nodes kGap above the face (the others on it); Type 2 ties the bottom nodes.
struct GappedPair {
  SimulationSetup setup;
  TieBox lower, upper;
  explicit GappedPair(const Eigen::Matrix3d& place) {
    TieMesh mesh;
    lower = mesh.add_box({0, 0, 0}, {1, 1, 1}, 1, 1, 1);
    upper = mesh.add_box({0, 1, 0}, {1, 0.5, 1}, 1, 1, 1);
    const std::vector<Index> bottom = upper.layer(0);
    for (std::size_t k = 0; k < 2; ++k) mesh.x[static_cast<std::size_t>(bottom[k])].y() += kGap;
    for (Vec3& p : mesh.x) p = place * p;
    mesh.fill(setup.nodes);
    setup.blocks.push_back(elastic_hexes(1, lower, 1.0, 1e3, 0.3));
    setup.blocks.push_back(elastic_hexes(2, upper, 1.0, 1e3, 0.3));
    for (auto& b : setup.blocks) b->initialize(setup.nodes);
  }
};

void check_turning_offsets(const Eigen::Matrix3d& place) {
  GappedPair m(place);
  NodalFields& nodes = m.setup.nodes;
  TiedSurfaceContact tie("tie", m.upper.layer(0), part_surface(m.setup, 1));
  tie.initialize(ContactContext{nodes, m.setup.blocks});
  ASSERT_EQ(tie.links().size(), 4u);
  const std::size_t n = nodes.size();
  std::vector<Vec3> x0(n);
  for (std::size_t i = 0; i < n; ++i) x0[i] = nodes.x.get(static_cast<Index>(i));
  int carried = 0;
  for (std::size_t k = 0; k < 4; ++k) {
    const TiePoint& t = tie.links()[k];
    const bool gapped = t.slave == m.upper.layer(0)[0] || t.slave == m.upper.layer(0)[1];
    EXPECT_EQ(tie.offset_carried(k), gapped);
    if (gapped) EXPECT_NEAR(t.offset.norm(), kGap, 1e-14);
    carried += tie.offset_carried(k) ? 1 : 0;
  }
  EXPECT_EQ(carried, 2);
  // Three rigid placements of every node (a turn about an axis in the face's plane, so the gap's
  // direction turns).
  const Vec3 c = place * Vec3(0.3, 0.5, 0.6), axis = place * Vec3(1.0, 0.0, 0.4).normalized();
  auto rotation = [&](Real a) { return Eigen::AngleAxisd(a, axis).toRotationMatrix().eval(); };
  auto put = [&](const Eigen::Matrix3d& q) {
    for (std::size_t i = 0; i < n; ++i) nodes.x.set(static_cast<Index>(i), c + q * (x0[i] - c));
  };
  std::vector<Real> mass(nodes.mass);
  std::vector<Real> rot(nodes.rot_inertia);
  Vec3Field force, moment;
  force.resize(n, 0.0);
  moment.resize(n, 0.0);
  const Real a1 = 0.4, a2 = 0.9;  // rad
  tie.condense(nodes, CondenseView{mass, force, rot, moment});
  put(rotation(a1));
  tie.follow_positions(nodes);
  for (std::size_t k = 0; k < 4; ++k) {
    const TiePoint& t = tie.links()[k];
    const Vec3 want = tie_point_value(t, nodes.x) + (tie.offset_carried(k) ? Vec3(rotation(a1) * t.offset) : t.offset);
    EXPECT_LT((nodes.x.get(t.slave) - want).norm(), 1e-14) << "link " << k;
    if (!tie.offset_carried(k)) EXPECT_EQ(nodes.x.get(t.slave), Vec3(tie_point_value(t, nodes.x) + t.offset));
    // Against the rigid placement: the carried slave is where the rigid motion put it.
    if (tie.offset_carried(k)) EXPECT_LT((nodes.x.get(t.slave) - (c + rotation(a1) * (x0[t.slave] - c))).norm(), 1e-14);
  }
  // A second turn, from a1 to a2, with a velocity field: the slave takes its master point's
  // velocity (the offset's own rate is left out), exactly as a zero-offset tie.
  put(rotation(a2));
  tie.follow_positions(nodes);
  for (std::size_t i = 0; i < n; ++i) nodes.v.set(static_cast<Index>(i), Vec3(0.1 * Real(i), -0.2, 0.05 * Real(i * i)));
  tie.condense(nodes, CondenseView{mass, force, rot, moment});
  tie.follow_velocities(nodes);
  for (std::size_t k = 0; k < 4; ++k) {
    const TiePoint& t = tie.links()[k];
    EXPECT_LT((nodes.x.get(t.slave) - (c + rotation(a2) * (x0[t.slave] - c))).norm(), 1e-14 * (tie.offset_carried(k) ? 1.0 : 1e12));
    EXPECT_EQ(nodes.v.get(t.slave), tie_point_value(t, nodes.v));
    EXPECT_LT((tie.offset_now(k) - (tie.offset_carried(k) ? Vec3(rotation(a2) * t.offset) : t.offset)).norm(), 1e-14);
  }
}

TEST(TiedOffsetFrame, GapTurnsWithTheMasterSegmentAndZeroOffsetsStayAsBefore) {
  check_turning_offsets(Eigen::Matrix3d::Identity());
}

TEST(TiedOffsetFrame, TurnedCopy) {
  check_turning_offsets(Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, 3.0).normalized()).toRotationMatrix());
}

}  // namespace
