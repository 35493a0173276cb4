// Closest-point projection onto a segment, against an independent computation: dense sampling of
// the parametrisation followed by a shrinking pattern search (no derivatives, no edge logic).
#include <gtest/gtest.h>

#include <random>

#include "slideline/contact/search/closest_point.hpp"
#include "slideline/contact/search/segment_tracking.hpp"
#include "unit/contact/plate_surface.hpp"

using namespace slideline;

namespace {

struct Reference {
  Real xi, eta, distance;
  Vec3 point;
};

Vec3 eval(const SegmentCorners& c, Real xi, Real eta) {
  return 0.25 * ((1 - xi) * (1 - eta) * c[0] + (1 + xi) * (1 - eta) * c[1] +
                 (1 + xi) * (1 + eta) * c[2] + (1 - xi) * (1 + eta) * c[3]);
}

// Minimises |x(xi, eta) - p| over [-1, 1]^2 by brute force: a 201 x 201 grid, then a compass
// search from the best few grid points with the step halved down to 1e-13.
Reference reference_projection(const Vec3& p, const SegmentCorners& c) {
  const int n = 200;
  std::vector<std::pair<Real, std::pair<Real, Real>>> grid;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      const Real xi = -1 + 2.0 * i / n, eta = -1 + 2.0 * j / n;
      grid.push_back({(eval(c, xi, eta) - p).norm(), {xi, eta}});
    }
  }
  std::partial_sort(grid.begin(), grid.begin() + 4, grid.end(),
                    [](const auto& a, const auto& b) { return a.first < b.first; });
  Reference best{0, 0, std::numeric_limits<Real>::infinity(), Vec3::Zero()};
  for (int s = 0; s < 4; ++s) {
    Real xi = grid[s].second.first, eta = grid[s].second.second;
    Real d = grid[s].first;
    for (Real h = 2.0 / n; h > 1e-13; h *= 0.5) {
      bool moved = true;
      while (moved) {
        moved = false;
        for (auto [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {-1, -1}, {1, -1}, {-1, 1}}) {
          const Real a = std::clamp(xi + dx * h, -1.0, 1.0), b = std::clamp(eta + dy * h, -1.0, 1.0);
          const Real dd = (eval(c, a, b) - p).norm();
          if (dd < d) {
            d = dd;
            xi = a;
            eta = b;
            moved = true;
          }
        }
      }
    }
    if (d < best.distance) best = {xi, eta, d, eval(c, xi, eta)};
  }
  return best;
}

SegmentCorners unit_square() {
  return {Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0)};
}

SegmentCorners warped_quad() {
  // Corners off a plane by +-0.25, uneven edge lengths.
  return {Vec3(0.0, 0.0, 0.25), Vec3(2.2, 0.1, -0.25), Vec3(1.9, 1.7, 0.25), Vec3(-0.2, 1.4, -0.25)};
}

void expect_consistent(const Projection& r, const Vec3& p, const SegmentCorners& c) {
  Real sum = 0.0;
  Vec3 x = Vec3::Zero();
  for (int a = 0; a < 4; ++a) {
    sum += r.shape[a];
    x += r.shape[a] * c[a];
  }
  EXPECT_NEAR(sum, 1.0, 1e-14);
  EXPECT_NEAR((x - r.point).norm(), 0.0, 1e-13);
  EXPECT_NEAR(r.distance, (p - r.point).norm(), 1e-14);
  EXPECT_NEAR(r.normal.norm(), 1.0, 1e-14);
  EXPECT_NEAR(r.gap, (p - r.point).dot(r.normal), 1e-14);
  EXPECT_LE(std::abs(r.xi), 1.0);
  EXPECT_LE(std::abs(r.eta), 1.0);
}

}  // namespace

TEST(ClosestPoint, FlatSquareInteriorIsTheOrthogonalFoot) {
  const SegmentCorners c = unit_square();
  const Vec3 p(0.3, -0.2, 0.5);
  const Projection r = project_point_to_quad(p, c);
  EXPECT_NEAR(r.xi, 0.3, 1e-14);
  EXPECT_NEAR(r.eta, -0.2, 1e-14);
  EXPECT_NEAR(r.distance, 0.5, 1e-14);
  EXPECT_NEAR(r.gap, 0.5, 1e-14);
  EXPECT_TRUE(r.interior());
  EXPECT_NEAR((r.normal - Vec3(0, 0, 1)).norm(), 0.0, 1e-14);
  expect_consistent(r, p, c);
  // Below the segment: same foot, negative gap.
  const Projection below = project_point_to_quad(Vec3(0.3, -0.2, -0.5), c);
  EXPECT_NEAR(below.gap, -0.5, 1e-14);
}

TEST(ClosestPoint, ClockwiseCornersFlipTheNormal) {
  SegmentCorners c = unit_square();
  std::swap(c[1], c[3]);
  const Projection r = project_point_to_quad(Vec3(0.1, 0.1, 1.0), c);
  EXPECT_NEAR(r.normal[2], -1.0, 1e-14);
  EXPECT_NEAR(r.gap, -1.0, 1e-14);
}

TEST(ClosestPoint, EdgeAndCornerRegions) {
  const SegmentCorners c = unit_square();
  // Beyond edge 1 (xi = +1): foot on the edge, flagged on edge 1 only.
  const Projection e = project_point_to_quad(Vec3(1.7, 0.25, 0.3), c);
  EXPECT_DOUBLE_EQ(e.xi, 1.0);
  EXPECT_NEAR(e.eta, 0.25, 1e-14);
  EXPECT_EQ(e.edges, 2u);
  EXPECT_NEAR(e.distance, std::hypot(0.7, 0.3), 1e-14);
  // Beyond corner 3 (-1, +1): both edges 2 and 3.
  const Projection k = project_point_to_quad(Vec3(-1.5, 1.2, -0.1), c);
  EXPECT_DOUBLE_EQ(k.xi, -1.0);
  EXPECT_DOUBLE_EQ(k.eta, 1.0);
  EXPECT_EQ(k.edges, 4u | 8u);
  EXPECT_NEAR(k.shape[3], 1.0, 1e-15);
  // Exactly above an edge: inclusive, on the segment and on the edge.
  const Projection on = project_point_to_quad(Vec3(-0.4, -1.0, 0.2), c);
  EXPECT_DOUBLE_EQ(on.eta, -1.0);
  EXPECT_EQ(on.edges, 1u);
  EXPECT_NEAR(on.gap, 0.2, 1e-14);
  for (const auto& r : {e, k, on}) EXPECT_FALSE(r.interior());
}

TEST(ClosestPoint, SymmetricPointsGiveSymmetricAnswers) {
  const SegmentCorners c = unit_square();
  const Projection centre = project_point_to_quad(Vec3(0, 0, 2), c);
  EXPECT_NEAR(centre.xi, 0.0, 1e-15);
  EXPECT_NEAR(centre.eta, 0.0, 1e-15);
  for (Real s : {0.9, 1.3}) {
    const Projection a = project_point_to_quad(Vec3(s, 0.4, 0.2), c);
    const Projection b = project_point_to_quad(Vec3(-s, 0.4, 0.2), c);
    EXPECT_NEAR(a.xi, -b.xi, 1e-14);
    EXPECT_NEAR(a.eta, b.eta, 1e-14);
    EXPECT_NEAR(a.distance, b.distance, 1e-14);
  }
}

TEST(ClosestPoint, RandomPointsMatchTheSampledMinimumOnFlatAndWarpedQuads) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  const SegmentCorners trapezoid{Vec3(0, 0, 0), Vec3(3, 0, 0), Vec3(2, 1.5, 0), Vec3(0.5, 1.2, 0)};
  int interior = 0, boundary = 0;
  for (const SegmentCorners& c : {unit_square(), trapezoid, warped_quad()}) {
    const Vec3 centre = 0.25 * (c[0] + c[1] + c[2] + c[3]);
    for (int t = 0; t < 60; ++t) {
      const Vec3 p = centre + Vec3(2.5 * u(rng), 2.5 * u(rng), 0.8 * u(rng));
      const Projection r = project_point_to_quad(p, c);
      const Reference ref = reference_projection(p, c);
      expect_consistent(r, p, c);
      EXPECT_NEAR(r.distance, ref.distance, 1e-9) << "point " << p.transpose();
      EXPECT_LE(r.distance, ref.distance + 1e-12);  // never worse than the sampled minimum
      EXPECT_NEAR((r.point - ref.point).norm(), 0.0, 1e-5) << "point " << p.transpose();
      (r.interior() ? interior : boundary)++;
    }
  }
  EXPECT_GT(interior, 20);  // both branches exercised
  EXPECT_GT(boundary, 20);
}

TEST(ClosestPoint, StronglyWarpedQuadsFindTheGlobalMinimum) {
  // Corners up to half a side off-plane: the distance can have an interior local minimum that is
  // not the global one (the edge check and the Newton restart handle it).
  std::mt19937 rng(11);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  for (int q = 0; q < 12; ++q) {
    const SegmentCorners c{Vec3(0, 0, 0.5 * u(rng)), Vec3(1 + 0.3 * u(rng), 0.3 * u(rng), 0.5 * u(rng)),
                           Vec3(1 + 0.3 * u(rng), 1 + 0.3 * u(rng), 0.5 * u(rng)),
                           Vec3(0.3 * u(rng), 1 + 0.3 * u(rng), 0.5 * u(rng))};
    for (int t = 0; t < 10; ++t) {
      const Vec3 p(0.5 + 1.5 * u(rng), 0.5 + 1.5 * u(rng), u(rng));
      const Projection r = project_point_to_quad(p, c);
      expect_consistent(r, p, c);
      EXPECT_LE(r.distance, reference_projection(p, c).distance + 1e-9) << "quad " << q << " point " << t;
    }
  }
}

TEST(ClosestPoint, WarpedQuadNormalIsTheLocalTangentCrossProduct) {
  const SegmentCorners c = warped_quad();
  const Projection r = project_point_to_quad(Vec3(1.0, 0.8, 1.0), c);
  ASSERT_TRUE(r.interior());
  // Central differences of the parametrisation give the tangents independently.
  const Real h = 1e-6;
  const Vec3 t1 = (eval(c, r.xi + h, r.eta) - eval(c, r.xi - h, r.eta)) / (2 * h);
  const Vec3 t2 = (eval(c, r.xi, r.eta + h) - eval(c, r.xi, r.eta - h)) / (2 * h);
  EXPECT_NEAR((t1.cross(t2).normalized() - r.normal).norm(), 0.0, 1e-8);
  // At an interior minimum p - x is normal to the surface: |gap| = distance.
  EXPECT_NEAR(std::abs(r.gap), r.distance, 1e-12);
  EXPECT_NEAR(t1.dot(Vec3(1.0, 0.8, 1.0) - r.point), 0.0, 1e-8);
}

TEST(ClosestPoint, TriangleInteriorEdgesAndCorners) {
  const SegmentCorners c{Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0), Vec3(0, 2, 0)};
  const Projection in = project_point_to_segment(Vec3(0.5, 0.5, 1.0), c);
  EXPECT_TRUE(in.interior());
  EXPECT_NEAR(in.gap, 1.0, 1e-14);
  EXPECT_NEAR(in.shape[0], 0.5, 1e-14);
  EXPECT_NEAR(in.shape[1], 0.25, 1e-14);
  EXPECT_NEAR(in.shape[2], 0.25, 1e-14);
  EXPECT_EQ(in.shape[3], 0.0);
  EXPECT_NEAR(in.eta, -0.5, 1e-14);                  // 2 l2 - 1
  EXPECT_NEAR(in.xi, (0.25 - 0.5) / 0.75, 1e-14);    // (l1 - l0) / (l0 + l1)
  EXPECT_NEAR((eval(c, in.xi, in.eta) - in.point).norm(), 0.0, 1e-14);  // collapsed-quad map
  // Beyond the hypotenuse (edge 1-2, flag bit 1).
  const Projection hyp = project_point_to_segment(Vec3(2, 2, 0.0), c);
  EXPECT_EQ(hyp.edges, 2u);
  EXPECT_NEAR((hyp.point - Vec3(1, 1, 0)).norm(), 0.0, 1e-14);
  // Beyond corner 0.
  const Projection k = project_point_to_segment(Vec3(-1, -1, 0.5), c);
  EXPECT_EQ(k.edges, 1u | 8u);
  EXPECT_NEAR(k.shape[0], 1.0, 1e-15);
  std::mt19937 rng(3);
  std::uniform_real_distribution<Real> u(-1.5, 2.5);
  for (int t = 0; t < 40; ++t) {
    const Vec3 p(u(rng), u(rng), 0.5 * u(rng));
    const Projection r = project_point_to_segment(p, c);
    expect_consistent(r, p, c);
    EXPECT_NEAR(r.distance, reference_projection(p, c).distance, 1e-9);
  }
}

TEST(ClosestPoint, TiesBetweenSegmentsGoToTheLowestIndex) {
  Vec3Field x;
  const Surface s = test::make_plate(x, 2, 2, 1.0, Vec3(0, 0, 0));
  // Above the middle node: all four segments at the same distance.
  const Vec3 corner(1.0, 1.0, 0.3);
  for (const std::vector<Index> order : {std::vector<Index>{0, 1, 2, 3}, {3, 2, 1, 0}, {2, 3, 0, 1}}) {
    const SegmentProjection r = nearest_segment(corner, order, s, x);
    EXPECT_EQ(r.segment, 0);
    EXPECT_NEAR(r.projection.distance, 0.3, 1e-14);
  }
  // Above the edge between segments 1 and 3 (x in (1,2), y = 1).
  for (const std::vector<Index> order : {std::vector<Index>{1, 3}, {3, 1}}) {
    EXPECT_EQ(nearest_segment(Vec3(1.5, 1.0, -0.2), order, s, x).segment, 1);
  }
  // A strictly nearer segment beats a lower index.
  EXPECT_EQ(nearest_segment(Vec3(1.5, 1.01, 0.2), std::vector<Index>{1, 3}, s, x).segment, 3);
}
