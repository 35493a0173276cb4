// Forward-increment Lagrange solve (enforcement/lagrange.hpp): a slave grid of n x n nodes resting
// on a master plate of n x n unit segments (z normal), every slave pressed into the plate by its
// load (one constraint each, shared master nodes couple them), cold start each iteration (the
// worst case; in a run the previous cycle warm-starts it). Reports ns per constrained node per
// solve and the Gauss-Seidel sweeps per solve.
//   bm_contact_lagrange --benchmark_min_time=0.05
#include <benchmark/benchmark.h>

#include <cstdint>
#include <vector>

#include "../tests/unit/contact/plate_surface.hpp"
#include "slideline/contact/enforcement/lagrange.hpp"

using namespace slideline;

namespace {

void lagrange_solve(benchmark::State& state, bool cached) {
  const Index n = static_cast<Index>(state.range(0));
  NodalFields nodes;
  Vec3Field x;
  const Surface master = test::make_plate(x, n, n, 1.0, Vec3::Zero());
  const Index nm = static_cast<Index>(x.size());
  std::vector<LagrangeConstraint> cs;
  for (Index j = 0; j < n; ++j)
    for (Index i = 0; i < n; ++i) {
      LagrangeConstraint c;
      c.slave = static_cast<Index>(x.size());
      x.x.push_back(0.37 + i);
      x.y.push_back(0.41 + j);
      x.z.push_back(0.0);
      const Index s = i + n * j;
      for (int a = 0; a < 4; ++a) c.master[static_cast<std::size_t>(a)] = master.conn[4 * static_cast<std::size_t>(s) + a];
      const Real u = 2 * 0.37 - 1, v = 2 * 0.41 - 1;
      c.shape = {0.25 * (1 - u) * (1 - v), 0.25 * (1 + u) * (1 - v), 0.25 * (1 + u) * (1 + v), 0.25 * (1 - u) * (1 + v)};
      c.normal = Vec3::UnitZ();
      c.mu = 0.3;
      cs.push_back(c);
    }
  const std::size_t nn = x.size();
  nodes.resize(nn);
  nodes.x = x;
  std::vector<Real> mass(nn, 1.0), damping(nn, 15.0);
  std::vector<std::uint8_t> fixed(nn, 0), rigid(nn, 0);
  Vec3Field a, force, fc;
  a.resize(nn);
  force.resize(nn);
  fc.resize(nn);
  const StepTimes t{0.1, 1e-3, 1e-3, 1e-3, 100, 1e-3};
  long sweeps = 0, solves = 0;
  LagrangeWorkspace ws;
  ws.dx.assign(nn, Vec3::Zero());
  ws.rows.reserve(cs.size());
  for (auto _ : state) {
    for (Index k = 0; k < static_cast<Index>(nn); ++k) a.set(k, Vec3(0.1, 0.0, k >= nm ? -10.0 : 0.0));
    for (auto& c : cs) {
      c.lambda = 0.0;
      c.tau.setZero();
    }
    ConstraintView view{nodes, mass, damping, {fixed, fixed, fixed}, rigid, a, force, fc};
    const auto r = solve_forward_increment(cs, view, t, {}, nullptr, cached ? &ws : nullptr);
    sweeps += r.sweeps;
    ++solves;
    benchmark::DoNotOptimize(a.z.data());
  }
  state.counters["ns_per_node"] = benchmark::Counter(static_cast<double>(cs.size()),
                                                     benchmark::Counter::kIsIterationInvariantRate |
                                                         benchmark::Counter::kInvert);
  state.counters["sweeps"] = static_cast<double>(sweeps) / static_cast<double>(solves);
}

/// The reference loop (no workspace) and the cached sweeps LagrangeContact uses.
void BM_LagrangeSolve(benchmark::State& state) { lagrange_solve(state, false); }
void BM_LagrangeSolveCached(benchmark::State& state) { lagrange_solve(state, true); }

}  // namespace

BENCHMARK(BM_LagrangeSolve)->Arg(10)->Arg(32)->Arg(100)->Arg(316)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LagrangeSolveCached)->Arg(10)->Arg(32)->Arg(100)->Arg(316)->Unit(benchmark::kMicrosecond);
