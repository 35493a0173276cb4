// Segment geometry (mesh/segment_geometry.hpp) on a hand-made quad and triangle.
#include <gtest/gtest.h>

#include <cmath>

#include "slideline/mesh/segment_geometry.hpp"

using namespace slideline;

namespace {

/// Nodes: 0 (0,0,0), 1 (2,0,0), 2 (2,1,0), 3 (0,1,0), 4 (0,0,3). Segment 0 is the 2 x 1 quad
/// 0-1-2-3 (normal +z); segment 1 the triangle 0-1-4 (4 repeated), in the x-z plane, normal -y.
struct Fixture {
  Vec3Field x;
  Surface surf;
  Fixture() {
    x.resize(5);
    x.set(1, Vec3(2, 0, 0));
    x.set(2, Vec3(2, 1, 0));
    x.set(3, Vec3(0, 1, 0));
    x.set(4, Vec3(0, 0, 3));
    surf.conn = {0, 1, 2, 3, 0, 1, 4, 4};
    surf.block = {0, 0};
    surf.element = {0, 1};
    surf.part = {1, 1};
    surf.kind = {SegmentKind::shell, SegmentKind::shell};
    surf.thickness = {0.1, 0.1};
  }
};

}  // namespace

TEST(SegmentGeometry, QuadAndTriangle) {
  const Fixture f;
  EXPECT_NEAR((segment_area_vector(f.surf, 0, f.x) - Vec3(0, 0, 2)).norm(), 0.0, 1e-15);
  EXPECT_NEAR(segment_area(f.surf, 1, f.x), 3.0, 1e-15);  // 2 x 3 / 2
  EXPECT_NEAR((segment_normal(f.surf, 1, f.x) - Vec3(0, -1, 0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((segment_centroid(f.surf, 0, f.x) - Vec3(1, 0.5, 0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((segment_centroid(f.surf, 1, f.x) - Vec3(2.0 / 3, 0, 1)).norm(), 0.0, 1e-15);
  EXPECT_NEAR(segment_max_diagonal(f.surf, 0, f.x), std::sqrt(5.0), 1e-15);
  EXPECT_NEAR(segment_max_diagonal(f.surf, 1, f.x), std::sqrt(13.0), 1e-15);  // side 1-4
  EXPECT_EQ(segment_coordinates(f.surf, 1, f.x).row(3), segment_coordinates(f.surf, 1, f.x).row(2));
}

TEST(SegmentGeometry, AllNormalsAtOnce) {
  const Fixture f;
  Vec3Field n;
  compute_segment_normals(f.surf, f.x, n);
  ASSERT_EQ(n.size(), 2u);
  EXPECT_EQ(n.get(0), Vec3(0, 0, 1));
  EXPECT_EQ(n.get(1), segment_normal(f.surf, 1, f.x));
}
