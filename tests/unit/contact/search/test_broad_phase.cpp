// Broad phase: FCL diffed against brute force on random moving meshes, the box rules, the domain
// limit, thread-count independence, steady-state storage, and the search cadence.
#include <gtest/gtest.h>

#include <memory>
#include <numeric>
#include <random>

#include "slideline/contact/search/brute_force_broad_phase.hpp"
#include "slideline/contact/search/closest_point.hpp"
#include "slideline/contact/search/fcl_broad_phase.hpp"
#include "slideline/contact/search/search_cadence.hpp"
#include "unit/contact/plate_surface.hpp"

using namespace slideline;

namespace {

// A bumpy master plate (nx x ny, cell 1) and a cloud of slave nodes around it, in one field.
struct Scene {
  Vec3Field x;
  Surface master;
  std::vector<Index> slaves;
  std::vector<Index> all_nodes;
};

Scene make_scene(unsigned seed, Index nx, Index ny, Index nslave) {
  Scene sc;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  sc.master = test::make_plate(sc.x, nx, ny, 1.0, Vec3::Zero());
  for (std::size_t i = 0; i < sc.x.size(); ++i) {
    sc.x.x[i] += 0.2 * u(rng);
    sc.x.y[i] += 0.2 * u(rng);
    sc.x.z[i] += 0.3 * u(rng);
  }
  std::uniform_real_distribution<Real> ux(-1.0, nx + 1.0), uy(-1.0, ny + 1.0), uz(-1.0, 1.0);
  for (Index k = 0; k < nslave; ++k) {
    sc.slaves.push_back(static_cast<Index>(sc.x.size()));
    sc.x.x.push_back(ux(rng));
    sc.x.y.push_back(uy(rng));
    sc.x.z.push_back(uz(rng));
  }
  sc.all_nodes.resize(sc.x.size());
  std::iota(sc.all_nodes.begin(), sc.all_nodes.end(), 0);
  return sc;
}

// Every node moves by a random vector of length <= step, plus a common tangential drift.
void move(Scene& sc, std::mt19937& rng, Real step, const Vec3& drift) {
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  for (std::size_t i = 0; i < sc.x.size(); ++i) {
    Vec3 d(u(rng), u(rng), u(rng));
    d *= step / std::sqrt(3.0);
    sc.x.add(static_cast<Index>(i), d + drift);
  }
}

}  // namespace

TEST(BroadPhase, FclAndBruteForceGiveIdenticalCandidatesOnRandomMovingMeshes) {
  for (unsigned seed : {1u, 2u, 3u, 4u, 5u}) {
    Scene sc = make_scene(seed, 12 + seed, 9, 300);
    BroadPhaseOptions opt;
    opt.margin = 0.1 * seed;
    BruteForceBroadPhase brute;
    FclBroadPhase fcl;
    brute.build(sc.master, sc.x, opt);
    fcl.build(sc.master, sc.x, opt);
    EXPECT_GT(fcl.tree_height(), 3);
    std::vector<Candidate> a, b;
    std::mt19937 rng(100 + seed);
    std::size_t total = 0;
    for (int step = 0; step < 6; ++step) {
      const Real r = step % 2 == 0 ? 0.0 : 0.05;  // points and small boxes
      brute.query(sc.slaves, sc.x, r, a);
      fcl.query(sc.slaves, sc.x, r, b);
      ASSERT_EQ(a, b) << "seed " << seed << " step " << step;
      EXPECT_TRUE(std::is_sorted(a.begin(), a.end()));
      EXPECT_EQ(std::adjacent_find(a.begin(), a.end()), a.end());
      total += a.size();
      move(sc, rng, 0.3, Vec3(0.4, -0.2, 0.0));  // far more than the margin: refit must follow
      brute.update(sc.x);
      if (step == 3) {
        fcl.build(sc.master, sc.x, opt);  // a rebuild replaces the tree
      } else {
        fcl.update(sc.x);
      }
    }
    EXPECT_GT(total, 100u) << "seed " << seed;
  }
}

TEST(BroadPhase, CandidatesAreExactlyTheOverlappingInflatedBoxes) {
  Scene sc = make_scene(11, 8, 8, 200);
  BroadPhaseOptions opt;
  opt.margin = 0.25;
  FclBroadPhase fcl;
  fcl.build(sc.master, sc.x, opt);
  std::vector<Candidate> c;
  const Real r = 0.1;
  fcl.query(sc.slaves, sc.x, r, c);
  // Independent loop over corner coordinates.
  std::vector<Candidate> expected;
  for (Index n : sc.slaves) {
    const Vec3 p = sc.x.get(n);
    for (Index s = 0; s < sc.master.segment_count(); ++s) {
      const SegmentCorners k = segment_corners(sc.master, s, sc.x);
      bool hit = true;
      for (int d = 0; d < 3; ++d) {
        const Real lo = std::min({k[0][d], k[1][d], k[2][d], k[3][d]}) - opt.margin;
        const Real hi = std::max({k[0][d], k[1][d], k[2][d], k[3][d]}) + opt.margin;
        hit = hit && p[d] + r >= lo && p[d] - r <= hi;
      }
      if (hit) expected.push_back({n, s});
    }
  }
  EXPECT_EQ(c, expected);
  // Every segment within margin of a node (by true closest-point distance) is a candidate.
  int near_pairs = 0;
  for (Index n : sc.slaves) {
    for (Index s = 0; s < sc.master.segment_count(); ++s) {
      if (project_point_to_segment(sc.x.get(n), sc.master, s, sc.x).distance <= opt.margin) {
        ++near_pairs;
        EXPECT_TRUE(std::binary_search(c.begin(), c.end(), Candidate{n, s}));
      }
    }
  }
  EXPECT_GT(near_pairs, 10);
}

TEST(BroadPhase, DomainLimitExcludesSegmentsAndNodesOutsideTheBox) {
  Scene sc = make_scene(21, 10, 10, 400);
  BroadPhaseOptions opt;
  opt.margin = 0.2;
  opt.domain = Aabb{Vec3(2.0, 3.0, -0.5), Vec3(6.0, 7.0, 0.5)};
  BruteForceBroadPhase brute;
  FclBroadPhase fcl;
  brute.build(sc.master, sc.x, opt);
  fcl.build(sc.master, sc.x, opt);
  EXPECT_LT(fcl.active_segment_count(), sc.master.segment_count());
  EXPECT_GT(fcl.active_segment_count(), 10);
  std::mt19937 rng(5);
  for (int step = 0; step < 4; ++step) {
    std::vector<Candidate> a, b;
    brute.query(sc.slaves, sc.x, 0.0, a);
    fcl.query(sc.slaves, sc.x, 0.0, b);
    ASSERT_EQ(a, b);
    ASSERT_FALSE(a.empty());
    for (const Candidate& c : a) {
      EXPECT_TRUE(opt.domain->contains(sc.x.get(c.node)));
      Aabb raw;
      for (const Vec3& k : segment_corners(sc.master, c.segment, sc.x)) raw.expand(k);
      EXPECT_TRUE(opt.domain->overlaps(raw));
    }
    move(sc, rng, 0.2, Vec3(0.5, 0.0, 0.0));  // segments drift into and out of the domain
    brute.update(sc.x);
    fcl.update(sc.x);
  }
}

TEST(BroadPhase, ResultDoesNotDependOnTheThreadCountAndReusesStorage) {
  Scene sc = make_scene(31, 40, 40, 9000);  // above the parallel threshold
  BroadPhaseOptions opt;
  opt.margin = 0.1;
  FclBroadPhase fcl;
  fcl.build(sc.master, sc.x, opt);
  const int threads = max_threads();
  std::vector<Candidate> one, many;
  set_threads(1);
  fcl.query(sc.slaves, sc.x, 0.0, one);
  set_threads(std::max(2, threads));
  fcl.query(sc.slaves, sc.x, 0.0, many);
  set_threads(threads);
  EXPECT_EQ(one, many);
  ASSERT_FALSE(many.empty());
  // Steady state: the same query again neither moves nor grows the output.
  const Candidate* data = many.data();
  const std::size_t cap = many.capacity();
  fcl.update(sc.x);
  fcl.query(sc.slaves, sc.x, 0.0, many);
  EXPECT_EQ(many.data(), data);
  EXPECT_EQ(many.capacity(), cap);
  EXPECT_EQ(one, many);
}

TEST(BroadPhase, PerNodeRadiiMatchSingleNodeQueries) {
  Scene sc = make_scene(51, 9, 7, 150);
  FclBroadPhase fcl;
  BruteForceBroadPhase brute;
  fcl.build(sc.master, sc.x, BroadPhaseOptions{0.05, {}, false});
  brute.build(sc.master, sc.x, BroadPhaseOptions{0.05, {}, false});
  std::vector<Real> radius;
  for (std::size_t i = 0; i < sc.slaves.size(); ++i) radius.push_back(0.02 * static_cast<Real>(i % 7));
  std::vector<Candidate> a, b, one, joined;
  fcl.query(sc.slaves, sc.x, radius, a);
  brute.query(sc.slaves, sc.x, radius, b);
  EXPECT_EQ(a, b);
  for (std::size_t i = 0; i < sc.slaves.size(); ++i) {
    brute.query(std::span<const Index>(&sc.slaves[i], 1), sc.x, radius[i], one);
    joined.insert(joined.end(), one.begin(), one.end());
  }
  EXPECT_EQ(a, joined);
  EXPECT_GT(a.size(), 50u);
  EXPECT_THROW(fcl.query(sc.slaves, sc.x, std::span<const Real>(radius.data(), 3), a), Error);
}

TEST(BroadPhase, UseBeforeBuildThrows) {
  Vec3Field x;
  x.resize(2);
  FclBroadPhase fcl;
  std::vector<Candidate> c;
  const std::vector<Index> nodes{0};
  EXPECT_THROW(fcl.update(x), Error);
  EXPECT_THROW(fcl.query(nodes, x, 0.0, c), Error);
}

TEST(BroadPhase, EmptyMasterGivesNoCandidates) {
  Vec3Field x;
  x.resize(3);
  Surface empty;
  test::finish_surface(empty);
  FclBroadPhase fcl;
  fcl.build(empty, x, {});
  std::vector<Candidate> c{{1, 2}};
  const std::vector<Index> nodes{0, 1, 2};
  fcl.query(nodes, x, 1.0, c);
  EXPECT_TRUE(c.empty());
  EXPECT_EQ(fcl.tree_height(), 0);
  // One segment: the tree is a single leaf.
  Vec3Field y;
  const Surface one = test::make_plate(y, 1, 1, 1.0, Vec3::Zero());
  y.x.push_back(0.5);
  y.y.push_back(0.5);
  y.z.push_back(0.0);
  fcl.build(one, y, {});
  const std::vector<Index> slave{4};
  fcl.query(slave, y, 0.0, c);
  EXPECT_EQ(c, (std::vector<Candidate>{{4, 0}}));
}

TEST(SearchCadence, DueWhenTheLargestDisplacementReachesHalfTheMargin) {
  Vec3Field x;
  x.resize(5);
  const std::vector<Index> nodes{0, 2, 4};
  SearchCadence cadence(nodes, 0.2);
  EXPECT_TRUE(cadence.is_due(x));  // never searched
  cadence.mark_searched(x);
  EXPECT_FALSE(cadence.is_due(x));
  x.x[1] = 5.0;  // not watched
  EXPECT_FALSE(cadence.is_due(x));
  x.set(2, Vec3(0.05, 0.05, 0.0));
  EXPECT_NEAR(cadence.max_displacement(x), std::sqrt(0.005), 1e-15);
  EXPECT_FALSE(cadence.is_due(x));
  x.set(4, Vec3(0.0, 0.0, -0.1));
  EXPECT_TRUE(cadence.is_due(x));
  cadence.mark_searched(x);
  EXPECT_FALSE(cadence.is_due(x));
}

TEST(SearchCadence, CandidatesStayCompleteBetweenSearches) {
  // Bodies moving in opposite directions; search only when the cadence says so, and check at
  // every step that each pair within contact distance (here: the margin-free detection distance
  // 0, i.e. boxes that touch) is among the candidates of the last search.
  Scene sc = make_scene(41, 10, 10, 500);
  const Real margin = 0.3;
  BroadPhaseOptions opt;
  opt.margin = margin;
  FclBroadPhase fcl;
  fcl.build(sc.master, sc.x, opt);
  BruteForceBroadPhase tight;  // no margin: the pairs that touch now
  tight.build(sc.master, sc.x, {});
  SearchCadence cadence(sc.all_nodes, margin);
  std::vector<Candidate> cand, now;
  const Index nmaster_nodes = static_cast<Index>(sc.master.nodes.size());
  int searches = 0;
  std::mt19937 rng(9);
  for (int step = 0; step < 40; ++step) {
    if (cadence.is_due(sc.x)) {
      fcl.update(sc.x);
      fcl.query(sc.slaves, sc.x, 0.0, cand);
      cadence.mark_searched(sc.x);
      ++searches;
    }
    tight.update(sc.x);
    tight.query(sc.slaves, sc.x, 0.0, now);
    for (const Candidate& c : now) ASSERT_TRUE(std::binary_search(cand.begin(), cand.end(), c));
    // Master one way, slaves the other, 0.04 per step each.
    for (Index i = 0; i < static_cast<Index>(sc.x.size()); ++i) {
      sc.x.add(i, Vec3(i < nmaster_nodes ? 0.04 : -0.04, 0.0, 0.0));
    }
    (void)rng;
  }
  EXPECT_GT(searches, 5);
  EXPECT_LT(searches, 40);
}

TEST(BroadPhase, SkipIncidentLeavesOutANodesOwnSegments) {
  // Single-surface contact on one flat plate: with a margin below the cell size a node's boxes
  // are exactly those of its own segments, so it gets its node_segments row, or nothing when
  // incident segments are skipped.
  Vec3Field x;
  const Surface s = test::make_plate(x, 5, 4, 1.0, Vec3::Zero());
  for (bool skip : {false, true}) {
    BroadPhaseOptions opt;
    opt.margin = 0.3;
    opt.skip_incident = skip;
    FclBroadPhase fcl;
    BruteForceBroadPhase brute;
    fcl.build(s, x, opt);
    brute.build(s, x, opt);
    std::vector<Candidate> a, b;
    fcl.query(s.nodes, x, 0.0, a);
    brute.query(s.nodes, x, 0.0, b);
    EXPECT_EQ(a, b);
    std::vector<Candidate> expected;
    if (!skip) {
      for (Index i = 0; i < s.node_count(); ++i) {
        for (Index j = s.node_segments.begin(i); j < s.node_segments.end(i); ++j) {
          expected.push_back({s.nodes[static_cast<std::size_t>(i)], s.node_segments.value[static_cast<std::size_t>(j)]});
        }
      }
      ASSERT_EQ(expected.size(), 80u);  // 20 quads x 4 corners
    }
    EXPECT_EQ(a, expected);
  }
}
