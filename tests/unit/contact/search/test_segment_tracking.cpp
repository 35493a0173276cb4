// Local segment tracking on a flat plate, against a full search over every segment.
#include <gtest/gtest.h>

#include <numeric>

#include "slideline/contact/search/segment_tracking.hpp"
#include "unit/contact/plate_surface.hpp"

using namespace slideline;

namespace {
std::vector<Index> all_segments(const Surface& s) {
  std::vector<Index> v(static_cast<std::size_t>(s.segment_count()));
  std::iota(v.begin(), v.end(), 0);
  return v;
}
}  // namespace

TEST(SegmentTracking, NeighbourAcrossEachEdgeOfAPlate) {
  Vec3Field x;
  const Surface s = test::make_plate(x, 3, 2, 1.0, Vec3::Zero());  // segments 0 1 2 / 3 4 5
  EXPECT_EQ(neighbor_across_edge(s, 4, 0), 1);   // eta = -1
  EXPECT_EQ(neighbor_across_edge(s, 4, 1), 5);   // xi = +1
  EXPECT_EQ(neighbor_across_edge(s, 4, 2), -1);  // top boundary
  EXPECT_EQ(neighbor_across_edge(s, 4, 3), 3);   // xi = -1
  EXPECT_EQ(neighbor_across_edge(s, 0, 3), -1);
  EXPECT_EQ(neighbor_across_edge(s, 0, 2), 3);
}

TEST(SegmentTracking, DraggedPointFollowsTheFullSearch) {
  Vec3Field x;
  const Surface s = test::make_plate(x, 6, 4, 1.0, Vec3(0, 0, 0));
  const std::vector<Index> all = all_segments(s);
  // A diagonal-ish path at two heights, in steps of 0.125 so that it lands exactly on edges and
  // on a corner (x = 1, 2, ..., y = 1 at t = 8), and ends beyond the plate.
  for (Real z : {0.2, -0.05}) {
    Index seg = 0;
    int moves = 0, max_hops = 0;
    for (int t = 0; t <= 60; ++t) {
      const Vec3 p(0.125 * t, 0.0625 * t + 0.5, z);
      const SegmentProjection tr = track_segment(p, seg, s, x);
      const SegmentProjection full = nearest_segment(p, all, s, x);
      ASSERT_EQ(tr.segment, full.segment) << "step " << t;
      EXPECT_NEAR(tr.projection.distance, full.projection.distance, 1e-14);
      EXPECT_NEAR(tr.projection.gap, z, 1e-14);  // flat plate: the normal is +z everywhere
      moves += tr.segment != seg;
      max_hops = std::max(max_hops, tr.hops);
      seg = tr.segment;
    }
    // Columns change at x = 1..5 and rows at y = 1, 2, 3, which the path reaches at x = 1, 3, 5
    // (exactly over mesh nodes): 5 moves, three of them across a corner.
    EXPECT_EQ(moves, 5);
    EXPECT_GE(max_hops, 2);
    EXPECT_EQ(seg, 23);  // ends beyond the far corner on the last segment
  }
}

TEST(SegmentTracking, JumpOverSeveralSegmentsInOneCall) {
  Vec3Field x;
  const Surface s = test::make_plate(x, 6, 4, 1.0, Vec3(0, 0, 0));
  const Vec3 p(3.4, 2.6, 0.1);  // cell (3, 2): segment 15
  const SegmentProjection tr = track_segment(p, 0, s, x, TrackingOptions{.max_hops = 7});
  EXPECT_EQ(tr.segment, 15);
  EXPECT_EQ(tr.hops, 5);  // 3 columns + 2 rows
  EXPECT_TRUE(tr.projection.interior());
  // With too few hops it stops on the way, still nearer than where it started.
  const SegmentProjection short_walk = track_segment(p, 0, s, x, TrackingOptions{.max_hops = 2});
  EXPECT_EQ(short_walk.hops, 2);
  EXPECT_NE(short_walk.segment, 15);
  EXPECT_LT(short_walk.projection.distance, project_point_to_segment(p, s, 0, x).distance);
}

// Near a curved surface (a contact configuration: the distance small against the radius of
// curvature) the walk agrees with the full search. Far above a wavy surface the distance has
// several local minima and a local walk may stop in one of them; that is what the periodic broad
// phase search is for.
TEST(SegmentTracking, WarpedPlateAgreesWithFullSearch) {
  Vec3Field x;
  const Surface s = test::make_plate(x, 5, 5, 1.0, Vec3(0, 0, 0));
  for (std::size_t i = 0; i < x.size(); ++i) x.z[i] = 0.15 * std::sin(1.3 * x.x[i]) * std::cos(0.9 * x.y[i]);
  const std::vector<Index> all = all_segments(s);
  Index seg = 12;
  int moves = 0;
  for (int t = 0; t <= 80; ++t) {
    const Real a = 0.08 * t;
    const Real px = 2.5 + 2.0 * std::cos(a), py = 2.5 + 2.0 * std::sin(a);
    const Vec3 p(px, py, 0.15 * std::sin(1.3 * px) * std::cos(0.9 * py) + (t % 2 ? 0.03 : -0.02));
    const SegmentProjection tr = track_segment(p, seg, s, x);
    const SegmentProjection full = nearest_segment(p, all, s, x);
    ASSERT_EQ(tr.segment, full.segment) << "step " << t;
    moves += tr.segment != seg;
    seg = tr.segment;
  }
  EXPECT_GE(moves, 8);
}

namespace {
// The plate of make_plate with every quad split into two triangles along its 0-2 diagonal
// (stored as quads with corner 3 = corner 2, counter-clockwise, normal +z).
Surface triangulated_plate(Vec3Field& x, Index nx, Index ny) {
  const Surface quads = test::make_plate(x, nx, ny, 1.0, Vec3::Zero());
  Surface s;
  for (Index q = 0; q < quads.segment_count(); ++q) {
    const Index* c = &quads.conn[4 * static_cast<std::size_t>(q)];
    for (Index n : {c[0], c[1], c[2], c[2]}) s.conn.push_back(n);
    for (Index n : {c[0], c[2], c[3], c[3]}) s.conn.push_back(n);
  }
  test::finish_surface(s);
  return s;
}
}  // namespace

TEST(SegmentTracking, TriangulatedPlateAgreesWithFullSearch) {
  Vec3Field x;
  const Surface s = triangulated_plate(x, 4, 3);
  ASSERT_TRUE(s.is_triangle(0));
  // Triangle 0 (cell 0, lower right half): edges 0 (0-1), 1 (1-2, the x = 1 side, shared with
  // the upper-left triangle 3 of cell 1) and 3 (2-0, the diagonal, shared with triangle 1); the
  // collapsed edge 2 has no neighbour.
  EXPECT_EQ(neighbor_across_edge(s, 0, 1), 3);
  EXPECT_EQ(neighbor_across_edge(s, 0, 2), -1);
  EXPECT_EQ(neighbor_across_edge(s, 0, 3), 1);
  const std::vector<Index> all = all_segments(s);
  Index seg = nearest_segment(Vec3(3.6, 1.5, 0.1), all, s, x).segment;
  int moves = 0;
  for (int t = 0; t <= 70; ++t) {
    const Real a = 0.09 * t;
    const Vec3 p(2.0 + 1.6 * std::cos(a), 1.5 + 1.2 * std::sin(a), 0.1);
    const SegmentProjection tr = track_segment(p, seg, s, x);
    const SegmentProjection full = nearest_segment(p, all, s, x);
    ASSERT_EQ(tr.segment, full.segment) << "step " << t;
    EXPECT_NEAR(tr.projection.gap, 0.1, 1e-14);
    EXPECT_EQ(tr.projection.shape[3], 0.0);
    moves += tr.segment != seg;
    seg = tr.segment;
  }
  EXPECT_GE(moves, 10);
}

TEST(SegmentTracking, NearestOverOneNodesBroadPhaseRun) {
  Vec3Field x;
  const Surface s = test::make_plate(x, 3, 3, 1.0, Vec3::Zero());
  const std::vector<Candidate> cand{{7, 0}, {7, 1}, {7, 4}, {9, 4}, {9, 5}};
  EXPECT_EQ(candidate_run_end(cand, 0), 3u);
  EXPECT_EQ(candidate_run_end(cand, 3), 5u);
  const std::span<const Candidate> run(cand.data(), 3);
  EXPECT_EQ(nearest_segment(Vec3(1.5, 1.5, 0.2), run, s, x).segment, 4);
  EXPECT_EQ(nearest_segment(Vec3(1.0, 0.5, 0.2), run, s, x).segment, 0);  // tie on the 0-1 edge
}

TEST(SegmentTracking, CoincidentSegmentsDoNotHideTheNeighbourAcross) {
  // A shell layer lying on a solid face: every quad twice, the copies (0..11) numbered before the
  // originals (12..23), so the lowest segment sharing an edge of an original is often its own
  // coincident copy. The walk must still cross edges and agree with the full search, which picks
  // the copies (lower indices) on ties.
  Vec3Field x;
  const Surface plate = test::make_plate(x, 4, 3, 1.0, Vec3::Zero());
  Surface s;
  s.conn = plate.conn;
  s.conn.insert(s.conn.end(), plate.conn.begin(), plate.conn.end());
  test::finish_surface(s);
  EXPECT_EQ(neighbor_across_edge(s, 12 + 5, 1), 6);  // not its own copy 5
  EXPECT_EQ(neighbor_across_edge(s, 5, 1), 6);
  const std::vector<Index> all = all_segments(s);
  Index seg = 12;
  int moves = 0;
  for (int t = 0; t <= 40; ++t) {
    const Vec3 p(0.3 + 0.09 * t, 0.2 + 0.065 * t, 0.05);
    const SegmentProjection tr = track_segment(p, seg, s, x);
    ASSERT_EQ(tr.segment, nearest_segment(p, all, s, x).segment) << "step " << t;
    moves += tr.segment != seg;
    seg = tr.segment;
  }
  EXPECT_GE(moves, 5);
  EXPECT_LT(seg, 12);
}
