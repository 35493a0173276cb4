// ContactPairs (search/contact_pairs.hpp): the contact-pairs stage against brute force (every
// segment projected), FCL against the brute-force broad phase, search against tracking, the side
// memory options, the seeded stage of the tiebreaks, and thread-count independence.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <numeric>
#include <vector>

#include "slideline/contact/search/brute_force_broad_phase.hpp"
#include "slideline/contact/search/contact_pairs.hpp"
#include "slideline/contact/search/fcl_broad_phase.hpp"
#include "slideline/core/parallel.hpp"
#include "unit/contact/plate_surface.hpp"

namespace slideline {
namespace {

/// A plate of n x n unit cells at z = 0 (master, nodes 0 .. (n+1)^2 - 1) and m x m slave nodes
/// over it at height h, spaced so that no slave lies over a master edge.
struct Scene {
  Vec3Field x;
  Surface master;
  std::vector<Index> slaves;
};

Scene make_scene(Index n, Index m, Real h) {
  Scene s;
  s.master = test::make_plate(s.x, n, n, 1.0, Vec3(0, 0, 0));
  const Index first = static_cast<Index>(s.x.size());
  const Real step = static_cast<Real>(n) / static_cast<Real>(m);
  for (Index j = 0; j < m; ++j)
    for (Index i = 0; i < m; ++i) {
      s.x.x.push_back((i + 0.37) * step);
      s.x.y.push_back((j + 0.41) * step);
      s.x.z.push_back(h);
    }
  s.slaves.resize(static_cast<std::size_t>(m * m));
  std::iota(s.slaves.begin(), s.slaves.end(), first);
  return s;
}

void make_shells(Surface& s, Real thickness) {
  s.kind.assign(s.kind.size(), SegmentKind::shell);
  s.thickness.assign(s.thickness.size(), thickness);
}

ContactPairs make_pairs(const Scene& s, std::unique_ptr<BroadPhase> broad, ContactPairsOptions o = {},
                        ShellOffsetRule rule = {}, Real slave_offset = 0.0) {
  return ContactPairs(s.slaves, std::vector<Real>(s.slaves.size(), slave_offset), s.master, rule, std::move(broad), o);
}

/// Moves every slave by d.
void move_slaves(Scene& s, const Vec3& d) {
  for (Index n : s.slaves) s.x.add(n, d);
}

TEST(ContactPairs, EachSlaveGetsTheNearestSegmentItIsOverWithBothOffsets) {
  Scene s = make_scene(4, 5, 0.3);
  make_shells(s.master, 0.2);
  ContactPairs pairs = make_pairs(s, std::make_unique<FclBroadPhase>(), {}, {true, 0.0, 1.0}, 0.05);
  pairs.initialize(s.x);
  pairs.locate(s.x);
  ASSERT_EQ(pairs.points().size(), 25u);
  for (std::size_t i = 0; i < pairs.points().size(); ++i) {
    const ContactPoint& p = pairs.points()[i];
    const Vec3 q = s.x.get(s.slaves[i]);
    EXPECT_EQ(p.node, s.slaves[i]);
    // Brute force: the plate cell under the slave.
    const Index expected = static_cast<Index>(std::floor(q[0])) + 4 * static_cast<Index>(std::floor(q[1]));
    EXPECT_EQ(p.segment, expected) << i;
    EXPECT_NEAR(p.projection.gap, 0.3, 1e-12);
    EXPECT_NEAR((p.projection.point - Vec3(q[0], q[1], 0.0)).norm(), 0.0, 1e-12);
    EXPECT_DOUBLE_EQ(p.offset, 0.1 + 0.05);  // half the shell thickness + the slave's own
  }
  EXPECT_DOUBLE_EQ(pairs.allowance(), 0.5 * std::sqrt(2.0));  // half the smallest diagonal
}

TEST(ContactPairs, FclAndBruteForceGiveTheSamePointsWhileSliding) {
  Scene a = make_scene(8, 11, 0.05);
  Scene b = make_scene(8, 11, 0.05);
  ContactPairs fcl = make_pairs(a, std::make_unique<FclBroadPhase>());
  ContactPairs brute = make_pairs(b, std::make_unique<BruteForceBroadPhase>());
  fcl.initialize(a.x);
  brute.initialize(b.x);
  int found = 0;
  for (int k = 0; k < 40; ++k) {  // searches and tracking in between (allowance 0.71)
    const Vec3 d(0.05 + 0.002 * k, -0.03, 0.001 * std::sin(k));
    move_slaves(a, d);
    move_slaves(b, d);
    fcl.locate(a.x);
    brute.locate(b.x);
    for (std::size_t i = 0; i < fcl.points().size(); ++i) {
      ASSERT_EQ(fcl.points()[i].segment, brute.points()[i].segment) << k << " " << i;
      if (fcl.points()[i].segment < 0) continue;
      ++found;
      ASSERT_EQ(fcl.points()[i].projection.point, brute.points()[i].projection.point) << k << " " << i;
    }
  }
  EXPECT_GT(found, 1000);
}

TEST(ContactPairs, TrackingAgreesWithAFreshSearch) {
  Scene a = make_scene(6, 7, 0.02);
  ContactPairs tracked = make_pairs(a, std::make_unique<FclBroadPhase>());
  tracked.initialize(a.x);
  tracked.locate(a.x);
  for (int k = 0; k < 6; ++k) {  // 0.1 per cycle: below the cadence's 0.35, so tracking
    move_slaves(a, Vec3(0.1, 0.07, 0.0));
    tracked.locate(a.x);
    ContactPairs fresh = make_pairs(a, std::make_unique<FclBroadPhase>());
    fresh.initialize(a.x);
    fresh.locate(a.x);
    for (std::size_t i = 0; i < tracked.points().size(); ++i)
      ASSERT_EQ(tracked.points()[i].segment, fresh.points()[i].segment) << k << " " << i;
  }
}

TEST(ContactPairs, ShellSideIsRememberedUntilClearOrForgotten) {
  Scene s = make_scene(2, 1, 0.03);
  make_shells(s.master, 0.1);
  ContactPairs pairs = make_pairs(s, std::make_unique<FclBroadPhase>());
  pairs.initialize(s.x);
  pairs.locate(s.x);
  const Index seg = pairs.points()[0].segment;
  ASSERT_GE(seg, 0);
  EXPECT_EQ(pairs.side(0), 0);
  EXPECT_EQ(pairs.orient(0, seg, 0.03, std::numeric_limits<Real>::infinity()), 1);
  // Through the shell: the remembered side holds while |raw| < clear, is re-picked beyond.
  EXPECT_EQ(pairs.orient(0, seg, -0.03, std::numeric_limits<Real>::infinity()), 1);
  EXPECT_EQ(pairs.orient(0, seg, -0.03, 0.05), 1);
  EXPECT_EQ(pairs.orient(0, seg, -0.06, 0.05), -1);
  pairs.forget_side(0);
  EXPECT_EQ(pairs.side(0), 0);
  EXPECT_EQ(pairs.orient(0, seg, 0.01, std::numeric_limits<Real>::infinity()), 1);
}

TEST(ContactPairs, SideMemoryOptionDecidesWhatANewSegmentDoes) {
  for (SideMemory memory : {SideMemory::forget_on_new_segment, SideMemory::keep_across_segments}) {
    Scene s = make_scene(2, 1, 0.03);  // the slave over cell 0 of a 2 x 2 shell plate
    make_shells(s.master, 0.1);
    ContactPairsOptions o;
    o.side_memory = memory;
    ContactPairs pairs = make_pairs(s, std::make_unique<FclBroadPhase>(), o);
    pairs.initialize(s.x);
    pairs.locate(s.x);
    ASSERT_EQ(pairs.points()[0].segment, 0);
    pairs.orient(0, 0, -0.03, std::numeric_limits<Real>::infinity());
    move_slaves(s, Vec3(1.0, 0.0, 0.0));  // over cell 1: a new segment
    pairs.force_search();
    pairs.locate(s.x);
    ASSERT_EQ(pairs.points()[0].segment, 1);
    EXPECT_EQ(pairs.side(0), memory == SideMemory::keep_across_segments ? -1 : 0);
  }
}

TEST(ContactPairs, SeededStageStaysWhileInsideThenTakesTheNearestNeighbour) {
  Scene s = make_scene(3, 1, 0.0);
  ContactPairsOptions o;
  o.tracking = SegmentTracking::stay_while_inside;
  ContactPairs pairs(std::vector<Index>{}, {}, s.master, {}, nullptr, o);
  pairs.initialize(s.x);
  const Index node = s.slaves[0];
  s.x.set(node, Vec3(1.5, 1.5, -0.01));  // inside cell 4 (the middle one)
  const std::vector<Index> segment{4};
  const std::vector<std::int8_t> side{-1};
  pairs.seed({node}, {-0.02}, segment, side);
  EXPECT_EQ(pairs.track(0, s.x).segment, 4);
  EXPECT_DOUBLE_EQ(pairs.points()[0].offset, -0.02);
  EXPECT_EQ(pairs.side(0), -1);
  s.x.set(node, Vec3(2.4, 1.5, -0.01));  // beyond the edge x = 2: cell 5
  EXPECT_EQ(pairs.track(0, s.x).segment, 5);
  EXPECT_NEAR(pairs.points()[0].projection.gap, -0.01, 1e-12);
}

// set_held (the automatic tiebreak card): a held slave gets no segment and no slave gets a held
// segment, at each search (and each re-pick); released, the pairs are those of a stage without it.
TEST(ContactPairs, HeldNodesAndSegmentsAreNotAdmittedUntilReleased) {
  Scene s = make_scene(4, 5, 0.1);
  ContactPairsOptions o;
  o.repick_between_searches = true;
  ContactPairs pairs = make_pairs(s, std::make_unique<FclBroadPhase>(), o);
  std::vector<std::uint8_t> held_node(s.x.size(), 0), held_segment(16, 0);
  held_node[static_cast<std::size_t>(s.slaves[0])] = 1;
  const Vec3 q = s.x.get(s.slaves[12]);  // the middle slave, over cell (2, 2)
  const Index under = static_cast<Index>(std::floor(q[0])) + 4 * static_cast<Index>(std::floor(q[1]));
  held_segment[static_cast<std::size_t>(under)] = 1;
  pairs.set_held(held_node, held_segment);
  pairs.initialize(s.x);
  pairs.locate(s.x);
  EXPECT_EQ(pairs.points()[0].segment, -1);
  EXPECT_NE(pairs.points()[12].segment, under);
  for (const ContactPoint& p : pairs.points()) EXPECT_NE(p.segment, under);
  held_node.assign(held_node.size(), 0);
  held_segment.assign(held_segment.size(), 0);
  pairs.locate(s.x);  // a re-pick between searches sees the release
  ContactPairs free = make_pairs(s, std::make_unique<FclBroadPhase>(), o);
  free.initialize(s.x);
  free.locate(s.x);
  for (std::size_t i = 0; i < free.points().size(); ++i) EXPECT_EQ(pairs.points()[i].segment, free.points()[i].segment) << i;
  EXPECT_EQ(pairs.points()[12].segment, under);
}

TEST(ContactPairs, ThreadCountIndependent) {
  std::vector<ContactPoint> points[2];
  const int threads_before = max_threads();
  for (int run = 0; run < 2; ++run) {
    set_threads(run + 1);
    Scene s = make_scene(40, 71, 0.01);  // 5041 slaves: parallel loops
    ContactPairs pairs = make_pairs(s, std::make_unique<FclBroadPhase>());
    pairs.initialize(s.x);
    for (int k = 0; k < 12; ++k) {
      move_slaves(s, Vec3(0.03 * k, 0.02, 0.001 * std::cos(k)));
      pairs.locate(s.x);
    }
    points[run].assign(pairs.points().begin(), pairs.points().end());
  }
  set_threads(threads_before);
  ASSERT_EQ(points[0].size(), points[1].size());
  for (std::size_t i = 0; i < points[0].size(); ++i) {
    ASSERT_EQ(points[0][i].segment, points[1][i].segment) << i;
    ASSERT_EQ(points[0][i].projection.point, points[1][i].projection.point) << i;
  }
}

}  // namespace
}  // namespace slideline
