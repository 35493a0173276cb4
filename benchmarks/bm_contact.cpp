// Contact search costs: broad phase (FCL tree vs brute force), closest-point projection and local
// segment tracking. A flat master plate of nx x nx unit segments and a slave grid of nx x nx nodes
// 0.05 above it (offset so that no slave node sits over a master node), sliding tangentially.
// Rates are per slave node (or per projection): the counters with kInvert report time per item.
//   bm_contact --benchmark_min_time=0.05s
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <numeric>

#include "../tests/unit/contact/plate_surface.hpp"
#include "slideline/contact/search/brute_force_broad_phase.hpp"
#include "slideline/contact/search/fcl_broad_phase.hpp"
#include "slideline/contact/search/narrow_phase.hpp"

using namespace slideline;

namespace {

struct Scene {
  Vec3Field x;
  Surface master;
  std::vector<Index> slaves;
};

// Scenes are cached by size: building the 10^6-segment one takes longer than a benchmark run.
Scene& scene(Index nx) {
  static std::map<Index, std::unique_ptr<Scene>> cache;
  auto& s = cache[nx];
  if (!s) {
    s = std::make_unique<Scene>();
    s->master = test::make_plate(s->x, nx, nx, 1.0, Vec3::Zero());
    for (Index j = 0; j < nx; ++j) {
      for (Index i = 0; i < nx; ++i) {
        s->slaves.push_back(static_cast<Index>(s->x.size()));
        s->x.x.push_back(0.37 + i);
        s->x.y.push_back(0.41 + j);
        s->x.z.push_back(0.05);
      }
    }
  }
  return *s;
}

// Slides the slave nodes by dx in x per step, turning back every 8 steps (so they stay over the
// plate).
void slide(Scene& s, long step, Real dx) {
  if ((step / 8) % 2 != 0) dx = -dx;
  for (Index n : s.slaves) s.x.x[n] += dx;
}

void set_rate(benchmark::State& state, const char* name, double items) {
  state.counters[name] = benchmark::Counter(items, benchmark::Counter::kIsIterationInvariantRate |
                                                       benchmark::Counter::kInvert);
}

template <class BP>
void broad_phase_update_query(benchmark::State& state) {
  const Index nx = static_cast<Index>(state.range(0));
  Scene& s = scene(nx);
  BroadPhaseOptions opt;
  opt.margin = 0.1;
  BP bp;
  const auto t0 = std::chrono::steady_clock::now();
  bp.build(s.master, s.x, opt);
  const double build_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::vector<Candidate> out;
  const std::vector<Real> x0 = s.x.x;
  long step = 0;
  for (auto _ : state) {
    slide(s, step++, 0.01);
    bp.update(s.x);
    bp.query(s.slaves, s.x, 0.0, out);
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["segments"] = static_cast<double>(s.master.segment_count());
  state.counters["slave_nodes"] = static_cast<double>(s.slaves.size());
  state.counters["cand_per_node"] = static_cast<double>(out.size()) / static_cast<double>(s.slaves.size());
  state.counters["build_ms"] = 1e3 * build_s;
  s.x.x = x0;
  set_rate(state, "t_per_node", static_cast<double>(s.slaves.size()));
}

void BM_FclUpdateQuery(benchmark::State& state) { broad_phase_update_query<FclBroadPhase>(state); }
BENCHMARK(BM_FclUpdateQuery)->Arg(10)->Arg(32)->Arg(100)->Arg(316)->Arg(1000)->Unit(benchmark::kMillisecond);

void BM_BruteForceUpdateQuery(benchmark::State& state) {
  broad_phase_update_query<BruteForceBroadPhase>(state);
}
BENCHMARK(BM_BruteForceUpdateQuery)->Arg(10)->Arg(32)->Arg(100)->Unit(benchmark::kMillisecond);

// FCL query alone (no box update or refit), to split the cost.
void BM_FclQueryOnly(benchmark::State& state) {
  Scene& s = scene(static_cast<Index>(state.range(0)));
  FclBroadPhase bp;
  bp.build(s.master, s.x, BroadPhaseOptions{0.1, {}});
  std::vector<Candidate> out;
  for (auto _ : state) {
    bp.query(s.slaves, s.x, 0.0, out);
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["segments"] = static_cast<double>(s.master.segment_count());
  set_rate(state, "t_per_node", static_cast<double>(s.slaves.size()));
}
BENCHMARK(BM_FclQueryOnly)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

// One closest-point projection. Arg 0: a mildly warped quad (corners +-1 % of a side off-plane),
// points over the interior (Newton only); 1: the same, points beyond the edges (Newton + the
// closed-form edges); 2: a strongly warped quad (+-10 %), points over the interior (Newton, the
// edges and a Newton restart).
void BM_Projection(benchmark::State& state) {
  const Real w = state.range(0) == 2 ? 0.1 : 0.01;
  const SegmentCorners c{Vec3(0.0, 0.0, w), Vec3(1.1, 0.05, -w), Vec3(0.95, 0.9, w), Vec3(-0.1, 1.05, -w)};
  const Real spread = state.range(0) == 1 ? 2.5 : 0.8;
  std::vector<Vec3> pts;
  for (int k = 0; k < 1024; ++k) {
    const Real a = 0.5 + spread * (std::fmod(0.6180339887 * k, 1.0) - 0.5);
    const Real b = 0.5 + spread * (std::fmod(0.7548776662 * k, 1.0) - 0.5);
    pts.emplace_back(a, b, 0.05 * std::sin(k));
  }
  std::size_t k = 0;
  for (auto _ : state) {
    const Projection r = project_point_to_quad(pts[k++ & 1023], c);
    benchmark::DoNotOptimize(r.gap);
  }
  set_rate(state, "t_per_projection", 1.0);
}
BENCHMARK(BM_Projection)->Arg(0)->Arg(1)->Arg(2);

// Local tracking of every slave node on a 100 x 100 plate while sliding: per node, re-project on
// the current segment and walk to a neighbour when it leaves.
void BM_TrackingStep(benchmark::State& state) {
  Scene& s = scene(static_cast<Index>(state.range(0)));
  std::vector<Index> seg(s.slaves.size());
  const Index nx = static_cast<Index>(state.range(0));
  for (std::size_t i = 0; i < s.slaves.size(); ++i) {
    const Vec3 p = s.x.get(s.slaves[i]);
    seg[i] = std::min<Index>(nx - 1, static_cast<Index>(p[0])) + nx * std::min<Index>(nx - 1, static_cast<Index>(p[1]));
  }
  const std::vector<Real> x0 = s.x.x;
  long step = 0, moves = 0;
  for (auto _ : state) {
    slide(s, step++, 0.1);  // 0.8 per half period: every node crosses a segment edge
    for (std::size_t i = 0; i < s.slaves.size(); ++i) {
      const SegmentProjection r = track_segment(s.x.get(s.slaves[i]), seg[i], s.master, s.x);
      moves += r.segment != seg[i];
      seg[i] = r.segment;
    }
  }
  state.counters["slave_nodes"] = static_cast<double>(s.slaves.size());
  state.counters["moves_per_step"] = static_cast<double>(moves) / static_cast<double>(step);
  s.x.x = x0;
  set_rate(state, "t_per_node", static_cast<double>(s.slaves.size()));
}
BENCHMARK(BM_TrackingStep)->Arg(100)->Unit(benchmark::kMillisecond);

// A full search step: update + query + nearest candidate per node (the work done when the search
// cadence says a search is due).
void BM_FclSearchAndNearest(benchmark::State& state) {
  Scene& s = scene(static_cast<Index>(state.range(0)));
  FclBroadPhase bp;
  bp.build(s.master, s.x, BroadPhaseOptions{0.1, {}});
  std::vector<Candidate> cand;
  std::vector<SegmentProjection> nearest(s.slaves.size());
  const std::vector<Real> x0 = s.x.x;
  long step = 0;
  for (auto _ : state) {
    slide(s, step++, 0.01);
    bp.update(s.x);
    bp.query(s.slaves, s.x, 0.0, cand);
    assign_nearest_segments(s.slaves, cand, s.master, s.x, nearest);
    benchmark::DoNotOptimize(nearest.data());
  }
  s.x.x = x0;
  state.counters["segments"] = static_cast<double>(s.master.segment_count());
  set_rate(state, "t_per_node", static_cast<double>(s.slaves.size()));
}
BENCHMARK(BM_FclSearchAndNearest)->Arg(100)->Arg(316)->Unit(benchmark::kMillisecond);

}  // namespace

// Penalty contact per slave node and cycle: cadence check, search (amortised) or tracking,
// gap, normal and friction forces, serial scatter. nx x nx segments, nx x nx slaves sliding at
// 0.01 segment per cycle, turning back every 80 cycles (x within +-0.4 of the start). The search
// margin is 0.5 x the segment diagonal (0.71), so a search is due when a node has moved 0.35:
// about every 36 cycles; each run is whole periods (a fixed cycle count, below) to amortise it. The outermost rows
// hang up to 0.03 past the plate edge for a few cycles (no force there): negligible except at 10^2.
// Args: nx, threads. The FCL variant runs to 10^6 segments, the brute-force one (same pass, the
// broad phase swapped) to 10^4: beyond that one search costs seconds.
#include "../tests/unit/contact/penalty_scene.hpp"
#include "slideline/core/parallel.hpp"

namespace {
// Scenes are cached by (nx, broad phase): building and initialising 10^6 segments takes longer
// than a benchmark run. The slaves oscillate about their start, so a reused scene stays in contact.
// The issue-20 options (SOFT = 1, SOFSCL 0.1; VC capping the friction) on the same scene: their
// cost per slave node-cycle against the plain pass (Opts::plain).
struct PlainOptions {
  static PenaltyPassOptions get() { return {}; }
};
struct SoftVcOptions {
  static PenaltyPassOptions get() {
    PenaltyPassOptions o;
    o.soft_scale = 0.1;
    o.viscous_friction = 0.05;  // below mu N here: the cap acts
    return o;
  }
};

template <class BP, class Opts = PlainOptions>
test::PenaltyScene& penalty_scene(Index nx) {
  static std::map<Index, std::unique_ptr<test::PenaltyScene>> cache;
  auto& s = cache[nx];
  if (!s) {
    s = test::make_penalty_scene(nx, 0.01, 100.0, ExponentialCoulomb{0.3, 0.25, 2.0}, std::make_unique<BP>(),
                                 Opts::get());
    StepTimes t;
    t.dt_prev = 1e-3;
    t.dt_initial = 1e-3;
    s->pass->compute(s->nodes, t, s->friction);  // the first full search, not a sliding cycle
  }
  return *s;
}

template <class BP, class Opts = PlainOptions>
void penalty_pass(benchmark::State& state) {
  const Index nx = static_cast<Index>(state.range(0));
  set_threads(static_cast<int>(state.range(1)));
  test::PenaltyScene& s = penalty_scene<BP, Opts>(nx);
  Vec3Field f, m;
  f.resize(s.nodes.x.size());
  m.resize(s.nodes.x.size());
  StepTimes t;
  t.dt_prev = 1e-3;
  t.dt_initial = 1e-3;
  const Vec3Field x_start = s.nodes.x;
  long step = 0;
  for (auto _ : state) {
    test::move_slaves(s, Vec3(((step++ + 40) / 80) % 2 ? -0.01 : 0.01, 0.0, 0.0), 1e-3);
    s.pass->compute(s.nodes, t, s.friction);
    Vec3 a = Vec3::Zero(), b = Vec3::Zero();
    Real w = 0.0;
    s.pass->scatter(ContactForceView{f, m}, a, b, w);
    benchmark::DoNotOptimize(a);
  }
  s.nodes.x = x_start;  // a run may stop mid-period: the next one starts from the same place
  state.counters["segments"] = static_cast<double>(nx * nx);
  state.counters["threads"] = static_cast<double>(state.range(1));
  set_rate(state, "ns_per_slave_cycle", static_cast<double>(nx * nx) * 1e-9);
}

void BM_PenaltyPass(benchmark::State& state) { penalty_pass<FclBroadPhase>(state); }
void BM_PenaltyPassBruteForce(benchmark::State& state) { penalty_pass<BruteForceBroadPhase>(state); }
void BM_PenaltyPassSoftVc(benchmark::State& state) { penalty_pass<FclBroadPhase, SoftVcOptions>(state); }
// Fixed iteration counts, multiples of the 80-cycle sliding period, so that every size sees the
// same motion and the same number of searches per cycle (a run stopped early would skip some).
void penalty_args(benchmark::internal::Benchmark* b, std::initializer_list<int> sizes) {
  for (int nx : sizes) {
    for (int threads : {1, 2}) b->Args({nx, threads});
  }
}
void penalty_iterations(benchmark::internal::Benchmark* b) {
  b->Unit(benchmark::kMillisecond)->UseRealTime();
}
}  // namespace
// One registration per size: Iterations() applies to a whole registration.
#define SLIDELINE_PENALTY_BM(fn, nx, iters) \
  BENCHMARK(fn)->Apply([](benchmark::internal::Benchmark* b) { penalty_args(b, {nx}); })->Iterations(iters)->Apply(penalty_iterations)
SLIDELINE_PENALTY_BM(BM_PenaltyPass, 10, 8000);
SLIDELINE_PENALTY_BM(BM_PenaltyPass, 32, 800);
SLIDELINE_PENALTY_BM(BM_PenaltyPass, 100, 800);
SLIDELINE_PENALTY_BM(BM_PenaltyPass, 316, 160);
SLIDELINE_PENALTY_BM(BM_PenaltyPass, 1000, 80);
SLIDELINE_PENALTY_BM(BM_PenaltyPassSoftVc, 32, 800);
SLIDELINE_PENALTY_BM(BM_PenaltyPassSoftVc, 100, 800);
SLIDELINE_PENALTY_BM(BM_PenaltyPassSoftVc, 316, 160);
SLIDELINE_PENALTY_BM(BM_PenaltyPassBruteForce, 10, 8000);
SLIDELINE_PENALTY_BM(BM_PenaltyPassBruteForce, 32, 800);
SLIDELINE_PENALTY_BM(BM_PenaltyPassBruteForce, 100, 800);
