// The two shortcuts of the nearest-segment pick must not change a single bit:
// - quad_newton's stop at a fixed point or 2-cycle of its clamped iterate, against the plain loop
//   of max_iterations steps (quad_newton_step, the same step);
// - cannot_beat, against projecting the candidate and applying is_better_projection.
// Points are drawn around flat, sheared and warped quads (near, far beyond the Newton clamp, above
// corners and edges), at coordinates of order 1 and far from the origin.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>

#include "slideline/contact/search/closest_point.hpp"

using namespace slideline;

namespace {

// max_iterations Newton steps, stopping only on convergence or a singular step: the loop the
// shortcut must reproduce.
bool plain_newton(const Vec3& p, const SegmentCorners& c, const Vec3& x_xe, int max_iterations, Real& xi, Real& eta) {
  for (int it = 0; it < max_iterations; ++it) {
    const detail::NewtonStep s = detail::quad_newton_step(p, c, x_xe, xi, eta);
    if (s == detail::NewtonStep::singular) return false;
    if (s == detail::NewtonStep::converged) return true;
  }
  return false;
}

std::uint64_t bits(Real v) { return std::bit_cast<std::uint64_t>(v); }

// A unit-ish quad at `origin`, sheared by `shear` and with corner 2 lifted by `warp` (0: flat).
SegmentCorners quad(const Vec3& origin, Real shear, Real warp) {
  return {origin + Vec3(0, 0, 0), origin + Vec3(1, 0, 0), origin + Vec3(1 + shear, 1, warp),
          origin + Vec3(shear, 1, 0)};
}

struct Scene {
  SegmentCorners c;
  Vec3 p;
};

std::vector<Scene> scenes() {
  std::mt19937_64 rng(20261123);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  std::vector<Scene> out;
  for (const Vec3 origin : {Vec3(0.37, 1.0, 0.41), Vec3(1234.567, -890.1, 4321.0)}) {
    for (Real shear : {0.0, 0.3}) {
      for (Real warp : {0.0, 0.05, 0.6}) {
        const SegmentCorners c = quad(origin, shear, warp);
        for (int k = 0; k < 400; ++k) {
          // Reach 0.5 to 8 segment sizes: inside, beside, and beyond the clamp at |xi| = 2.
          const Real reach = k < 100 ? 0.5 : (k < 300 ? 2.5 : 8.0);
          out.push_back({c, origin + Vec3(0.5 + reach * u(rng), 0.5 + reach * u(rng), 0.3 * reach * u(rng))});
        }
      }
    }
  }
  return out;
}

TEST(ProjectionShortcuts, NewtonStopAtARepeatedIterateGivesThePlainLoopsBits) {
  int stopped_early = 0;
  for (const Scene& s : scenes()) {
    const Vec3 x_xe = 0.25 * (s.c[0] - s.c[1] + s.c[2] - s.c[3]);
    for (int max_iterations : {19, 20}) {  // both parities of a 2-cycle's last member
      Real xi = 0.0, eta = 0.0, xi_ref = 0.0, eta_ref = 0.0;
      const bool conv = detail::quad_newton(s.p, s.c, x_xe, max_iterations, xi, eta);
      const bool conv_ref = plain_newton(s.p, s.c, x_xe, max_iterations, xi_ref, eta_ref);
      ASSERT_EQ(conv, conv_ref);
      ASSERT_EQ(bits(xi), bits(xi_ref)) << s.p.transpose();
      ASSERT_EQ(bits(eta), bits(eta_ref)) << s.p.transpose();
      if (!conv_ref && (std::abs(xi_ref) == 2.0 || std::abs(eta_ref) == 2.0)) ++stopped_early;
    }
  }
  // The scenes do exercise the shortcut: many points sit beyond the clamp.
  EXPECT_GT(stopped_early, 1000);
}

TEST(ProjectionShortcuts, CannotBeatOnlyWhereTheProjectionWouldLose) {
  // Pairs of scenes' segments: best = the projection onto the first segment, candidate = a copy
  // of the same quad moved by an offset, its index below or above best's (the tie rule).
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  int skipped = 0, kept = 0;
  for (const Scene& s : scenes()) {
    const Projection best = project_point_to_quad(s.p, s.c);
    const Vec3 shift(2.0 * u(rng), 2.0 * u(rng), 0.5 * u(rng));
    SegmentCorners moved = s.c;
    for (Vec3& v : moved) v += shift;
    const Projection cand = project_point_to_quad(s.p, moved);
    if (!cannot_beat(s.p, moved, best)) {
      ++kept;
      continue;
    }
    ++skipped;
    EXPECT_FALSE(is_better_projection(cand, 0, best, 1)) << s.p.transpose();
    EXPECT_FALSE(is_better_projection(cand, 2, best, 1)) << s.p.transpose();
  }
  EXPECT_GT(skipped, 1000);
  EXPECT_GT(kept, 1000);
  // A candidate at the same distance as best (the tie rule decides) is never skipped.
  const SegmentCorners c = quad(Vec3::Zero(), 0.0, 0.0);
  const Vec3 p(0.5, 0.5, 0.25);
  EXPECT_FALSE(cannot_beat(p, c, project_point_to_quad(p, c)));
}

}  // namespace
