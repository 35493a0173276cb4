// *RIGIDWALL_PLANAR_FINITE from a deck (reader, builder, solver/rigid_wall.hpp): two elastic cubes
// fly at a wall of finite extent, one inside its rectangle and one beside it. The one inside stops
// on the plane (no node ever crosses it) and bounces back; the one beside it passes the plane
// untouched, at its initial speed. The wall's force channel integrates (with the central-difference
// weights) to the momentum the first cube lost, and the same deck rotated gives the rotated force.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "slideline/io/keyword_reader.hpp"
#include "slideline/solver/build.hpp"
#include "slideline/solver/output_sink.hpp"
#include "slideline/solver/simulation.hpp"

using namespace slideline;

namespace {

constexpr Real kV0 = 1.0;  // initial speed towards the wall (length/time)

/// A rotation that moves every axis (the same deck rotated as a whole).
Mat3 rotation() { return Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, 3.0).normalized()).toRotationMatrix(); }

/// The deck, its points mapped by `rot`: the wall is the plane x = 0 (normal +x), finite: the tail
/// at the origin, the l edge along +y (LENL = 2), m = n x l = +z (LENM = 2). Cube 1 (nodes 1-8)
/// spans y, z in [0.5, 1.5]: inside the rectangle; cube 2 (nodes 11-18) spans y in [3, 4]: beside
/// it. Both start at x in [0.1, 1.1] moving at -V0 x; elastic, E = 1e4, rho = 1 (c = 100), so cube 1
/// hits at t = 0.1 and leaves within about 2 L / c = 0.02; the run ends at 0.3.
std::string wall_deck(const Mat3& rot) {
  auto p = [&](const Vec3& x) {
    const Vec3 y = rot * x;
    char s[96];
    std::snprintf(s, sizeof s, "%.17g,%.17g,%.17g", y[0], y[1], y[2]);
    return std::string(s);
  };
  // Bulk viscosity all but off (0 would read as the defaults 1.5, 0.06): its linear term enters the
  // stable step where tr(D) < 0, and in free flight tr(D) is round-off of either sign, so with it
  // the rotated copy would take other steps than the original (and the records not line up).
  std::string d = "*KEYWORD\n*CONTROL_TERMINATION\n0.3\n*CONTROL_BULK_VISCOSITY\n1e-12,1e-12\n";
  d += "*SECTION_SOLID\n1,1\n*MAT_ELASTIC\n1,1.0,1.0e4,0.0\n";
  d += "*PART\ncubes\n1,1,1\n*NODE\n";
  const Vec3 corner[2] = {Vec3(0.1, 0.5, 0.5), Vec3(0.1, 3.0, 0.5)};
  const Vec3 unit[8] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (int c = 0; c < 2; ++c)
    for (int k = 0; k < 8; ++k) d += std::to_string(10 * c + k + 1) + "," + p(corner[c] + unit[k]) + "\n";
  d += "*ELEMENT_SOLID\n1,1,1,2,3,4,5,6,7,8\n2,1,11,12,13,14,15,16,17,18\n*INITIAL_VELOCITY_NODE\n";
  for (int c = 0; c < 2; ++c)
    for (int k = 0; k < 8; ++k) d += std::to_string(10 * c + k + 1) + "," + p(Vec3(-kV0, 0.0, 0.0)) + "\n";
  d += "*RIGIDWALL_PLANAR_FINITE_ID\n1,finite_wall\n0\n" + p(Vec3::Zero()) + "," + p(Vec3(1.0, 0.0, 0.0)) + "\n";
  d += p(Vec3(0.0, 1.0, 0.0)) + ",2.0,2.0\n*END\n";
  return d;
}

/// What the tests read from one run.
struct WallRun {
  History h;
  std::unique_ptr<Simulation> sim;
  Real min_front_gap = 1e9;  ///< smallest distance of cube 1's nodes ahead of the plane, over the run
};

/// Runs the deck, stepping so as to watch cube 1's nodes against the plane (normal rot x).
std::unique_ptr<WallRun> run_wall(const Mat3& rot) {
  auto r = std::make_unique<WallRun>();
  r->sim = build_simulation(read_keyword_string(wall_deck(rot), "finite_wall.k"));
  const Vec3 n = rot * Vec3::UnitX();
  const auto& nodes = r->sim->nodes();
  r->sim->run({&r->h}, [&](const Simulation&) {
    for (Index i = 0; i < 8; ++i) r->min_front_gap = std::min(r->min_front_gap, nodes.x.get(i).dot(n));
  }, 1);
  return r;
}

/// Momentum of the nodes with deck ids in [first, first + 8) (mass length/time).
Vec3 cube_momentum(const NodalFields& nodes, Id first) {
  Vec3 p = Vec3::Zero();
  for (Index i = 0; i < static_cast<Index>(nodes.size()); ++i)
    if (nodes.ids[i] >= first && nodes.ids[i] < first + 8) p += nodes.mass[i] * nodes.v.get(i);
  return p;
}

/// The wall's impulse: each record's force (the constraint phase's at t^n) over the velocity step
/// it changed, (t^{n+1} - t^{n-1}) / 2 (histories are recorded every cycle).
Vec3 impulse(const History& h) {
  const auto& t = h.time();
  Vec3 j = Vec3::Zero();
  for (std::size_t k = 1; k + 1 < t.size(); ++k)
    for (int c = 0; c < 3; ++c) j[c] += h.value("rigidwalls/finite_wall/force", k, c) * 0.5 * (t[k + 1] - t[k - 1]);
  return j;
}

void expect_wall_physics(const WallRun& r, const Mat3& rot) {
  const Vec3 n = rot * Vec3::UnitX();
  const NodalFields& nodes = r.sim->nodes();
  // Cube 1 never crosses the plane (to round-off) and leaves it moving away.
  EXPECT_GT(r.min_front_gap, -1e-12);
  const Real m = 1.0;  // rho x volume of each cube
  const Vec3 p1 = cube_momentum(nodes, 1);
  EXPECT_GT(p1.dot(n), 0.5 * m * kV0);
  // Cube 2, beside the rectangle, passed the plane untouched: every node at x0 - V0 t, at speed V0,
  // its front face (x0 = 0.1) now behind the plane.
  for (Index i = 0; i < static_cast<Index>(nodes.size()); ++i) {
    if (nodes.ids[i] < 11) continue;
    EXPECT_NEAR(nodes.v.get(i).dot(n), -kV0, 1e-10);
    EXPECT_NEAR(nodes.x.get(i).dot(n), nodes.x0.get(i).dot(n) - kV0 * r.sim->time(), 1e-9);
    if (nodes.x0.get(i).dot(n) < 0.5) EXPECT_LT(nodes.x.get(i).dot(n), -0.1);
  }
  // The force the nodes put on the wall integrates to the momentum cube 1 lost.
  const Vec3 p0 = -m * kV0 * n;
  const Vec3 j = impulse(r.h);
  EXPECT_LT((j - (p0 - p1)).norm(), 1e-9 * m * kV0) << j.transpose() << " vs " << (p0 - p1).transpose();
  // Only cube 1's four front nodes ever touch it, and they push (normal force >= 0).
  Real peak = 0.0, most = 0.0;
  for (std::size_t k = 0; k < r.h.records(); ++k) {
    peak = std::max(peak, r.h.value("rigidwalls/finite_wall/normal_force", k, 0));
    most = std::max(most, r.h.value("rigidwalls/finite_wall/normal_force", k, 2));
    EXPECT_GE(r.h.value("rigidwalls/finite_wall/normal_force", k, 0), 0.0);
  }
  EXPECT_EQ(most, 4.0);
  EXPECT_GT(peak, 0.0);
}

}  // namespace

TEST(RigidWallFinite, InsideTheRectangleStopsBesideItPasses) {
  const auto r = run_wall(Mat3::Identity());
  expect_wall_physics(*r, Mat3::Identity());
}

// The same deck rotated: the same physics, and the force channel is the rotated force of the
// unrotated run record by record (the runs take the same steps).
TEST(RigidWallFinite, RotatedDeckGivesTheRotatedForce_rotated) {
  const Mat3 rot = rotation();
  const auto a = run_wall(Mat3::Identity()), b = run_wall(rot);
  expect_wall_physics(*b, rot);
  ASSERT_EQ(a->h.records(), b->h.records());
  Real peak = 0.0, worst = 0.0;
  for (std::size_t k = 0; k < a->h.records(); ++k) {
    Vec3 fa, fb;
    for (int c = 0; c < 3; ++c) {
      fa[c] = a->h.value("rigidwalls/finite_wall/force", k, c);
      fb[c] = b->h.value("rigidwalls/finite_wall/force", k, c);
    }
    peak = std::max(peak, fa.norm());
    worst = std::max(worst, (fb - rot * fa).norm());
  }
  EXPECT_GT(peak, 0.0);
  EXPECT_LT(worst, 1e-6 * peak);
}
