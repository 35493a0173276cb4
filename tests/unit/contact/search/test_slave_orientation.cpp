// The contact choice of search/slave_orientation.hpp on the two configurations it was made for:
// a node on a flush edge that has sunk into the master (it must get the end face, not the side
// face it lies on), and a master node just ahead of a sliding block's bottom edge (it must not
// take the block's leading face).
#include <gtest/gtest.h>

#include <numeric>

#include "slideline/contact/search/segment_tracking.hpp"
#include "slideline/contact/search/slave_orientation.hpp"
#include "unit/contact/plate_surface.hpp"

using namespace slideline;

namespace {

/// Grows x by `extra` points, keeping the existing ones (Vec3Field::resize does not).
void grow(Vec3Field& x, std::size_t extra) {
  std::vector<Vec3> old;
  for (std::size_t i = 0; i < x.size(); ++i) old.push_back(x.get(static_cast<Index>(i)));
  x.resize(old.size() + extra);
  for (std::size_t i = 0; i < old.size(); ++i) x.set(static_cast<Index>(i), old[i]);
}

/// Appends a cube [o, o + 1]^3 (8 nodes) to x and its 6 outward faces to s's conn, in the order
/// -x, +x, -y, +y, -z, +z (segment ids first_face + 0..5).
void add_cube(Vec3Field& x, Surface& s, const Vec3& o) {
  const Index b = static_cast<Index>(x.size());
  grow(x, 8);
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) x.set(b + i + 2 * j + 4 * k, o + Vec3(i, j, k));
  const auto n = [&](int i, int j, int k) { return b + i + 2 * j + 4 * k; };
  const Index faces[6][4] = {{n(0, 0, 0), n(0, 0, 1), n(0, 1, 1), n(0, 1, 0)},   // -x
                             {n(1, 0, 0), n(1, 1, 0), n(1, 1, 1), n(1, 0, 1)},   // +x
                             {n(0, 0, 0), n(1, 0, 0), n(1, 0, 1), n(0, 0, 1)},   // -y
                             {n(0, 1, 0), n(0, 1, 1), n(1, 1, 1), n(1, 1, 0)},   // +y
                             {n(0, 0, 0), n(0, 1, 0), n(1, 1, 0), n(1, 0, 0)},   // -z
                             {n(0, 0, 1), n(1, 0, 1), n(1, 1, 1), n(0, 1, 1)}};  // +z
  for (const auto& f : faces) s.conn.insert(s.conn.end(), f, f + 4);
}

std::vector<Candidate> all_candidates(Index node, const Surface& s) {
  std::vector<Candidate> c;
  for (Index seg = 0; seg < s.segment_count(); ++seg) c.push_back({node, seg});
  return c;
}

}  // namespace

TEST(SlaveOrientation, SunkFlushEdgeNodeTakesTheEndFaceNotTheSideFace) {
  Vec3Field x;
  Surface striker, target;
  add_cube(x, striker, Vec3(0, 0, 0));
  add_cube(x, target, Vec3(1, 0, 0));  // flush: same section, end faces at x = 1
  test::finish_surface(striker);
  test::finish_surface(target);
  const Index corner = 1;  // striker node (1, 0, 0): on the target's -y and -z side planes
  const Real depth = 0.05;
  x.set(corner, Vec3(1.0 + depth, 0.0, 0.0));
  const std::vector<Index> slaves{corner};
  const SlaveOrientation orientation(striker, slaves);
  EXPECT_TRUE(orientation.filtered(0));
  const auto cand = all_candidates(corner, target);
  const Vec3 p = x.get(corner);
  // Nearest alone: a side face at distance 0 (zero gap: no force).
  const SegmentProjection nearest = nearest_segment(p, std::span<const Candidate>(cand), target, x);
  EXPECT_TRUE(nearest.segment == 2 || nearest.segment == 4);
  EXPECT_NEAR(nearest.projection.distance, 0.0, 1e-12);
  // With orientation: the end face (-x, segment 0), at the penetration depth.
  const SegmentProjection chosen = nearest_segment(p, std::span<const Candidate>(cand), target, x, {},
                                                   FacingRule{&orientation, 0, &target, &x});
  EXPECT_EQ(chosen.segment, 0);
  EXPECT_NEAR(chosen.projection.gap, -depth, 1e-12);
  // Tracking from the end face does not hop onto the side faces across its edges.
  const SegmentProjection tracked = track_segment(p, 0, target, x, {}, FacingRule{&orientation, 0, &target, &x});
  EXPECT_EQ(tracked.segment, 0);
  EXPECT_NE(track_segment(p, 0, target, x).segment, 0);  // the nearest rule would
}

TEST(SlaveOrientation, NodeAheadOfASlidingBlockDoesNotTakeItsLeadingFace) {
  Vec3Field x;
  Surface block, plane;
  add_cube(x, block, Vec3(0, -0.001, 0));  // sunk 0.001 into the plane y = 0
  test::finish_surface(block);
  // The plane: one quadrilateral y = 0 (normal +y), x in [1, 3], z in [-1, 2].
  const Index b = static_cast<Index>(x.size());
  grow(x, 4);
  x.set(b, Vec3(1, 0, -1));
  x.set(b + 1, Vec3(1, 0, 2));
  x.set(b + 2, Vec3(3, 0, 2));
  x.set(b + 3, Vec3(3, 0, -1));
  plane.conn = {b, b + 1, b + 2, b + 3};
  test::finish_surface(plane);
  ASSERT_GT(segment_normal(plane, 0, x).y(), 0.99);
  // A plane node (corner b, moved within the plane y = 0) 0.01 ahead of the block's leading face (+x, segment 1), level with the plane.
  const Index node = b;
  x.set(node, Vec3(1.01, 0.0, 0.5));
  const std::vector<Index> slaves{node};
  const SlaveOrientation orientation(plane, slaves);
  const auto cand = all_candidates(node, block);
  const Vec3 p = x.get(node);
  EXPECT_EQ(nearest_segment(p, std::span<const Candidate>(cand), block, x).segment, 1);  // the leading face
  const SegmentProjection chosen = nearest_segment(p, std::span<const Candidate>(cand), block, x, {},
                                                   FacingRule{&orientation, 0, &block, &x});
  EXPECT_EQ(chosen.segment, 2);  // the bottom face, which it is beside until the block passes over it
  EXPECT_FALSE(is_over(p, chosen.projection));
  // Once the block's edge has passed over it, the node is over the bottom face, 0.001 inside.
  x.set(node, Vec3(0.99, 0.0, 0.5));
  const SegmentProjection under = nearest_segment(x.get(node), std::span<const Candidate>(cand), block, x, {},
                                                  FacingRule{&orientation, 0, &block, &x});
  EXPECT_EQ(under.segment, 2);
  EXPECT_TRUE(is_over(x.get(node), under.projection));
  EXPECT_NEAR(under.projection.gap, -0.001, 1e-12);
}

TEST(SlaveOrientation, ShellAndDiscreteNodesAreNotFiltered) {
  Vec3Field x;
  Surface cube;
  add_cube(x, cube, Vec3(0, 0, 0));
  test::finish_surface(cube);
  Surface shell = cube;
  std::fill(shell.kind.begin(), shell.kind.end(), SegmentKind::shell);
  const std::vector<Index> slaves{0, 100};  // node 100 is on no face
  const SlaveOrientation on_shell(shell, slaves), on_solid(cube, slaves);
  EXPECT_FALSE(on_shell.filtered(0));
  EXPECT_FALSE(on_shell.filtered(1));
  EXPECT_TRUE(on_solid.filtered(0));
  EXPECT_FALSE(on_solid.filtered(1));
  // Node 0's own faces are -x, -y, -z: the opposite +x face opposes its -x face; its own -x
  // face's plane does not face it.
  EXPECT_TRUE(on_solid.admits(0, cube, 1, x));
  EXPECT_FALSE(on_solid.admits(0, cube, 0, x));
  EXPECT_TRUE(on_shell.admits(0, cube, 1, x));
}
