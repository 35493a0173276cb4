// Verification of the Belytschko-Tsay shell block in whole simulations: a cantilever against beam
// theory, the spec's shell plate on supports and the spec's shell layer bonded to a brick block
// (reactions against the applied loads), and thread-count independence.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "slideline/core/parallel.hpp"
#include "slideline/element/block_factory.hpp"
#include "slideline/element/hex_block.hpp"
#include "slideline/element/shell_block.hpp"
#include "slideline/material/mooney_rivlin.hpp"
#include "slideline/solver/output_sink.hpp"
#include "slideline/solver/simulation.hpp"

using namespace slideline;

namespace {

/// Adds point forces at nodes (the force divided by the nodal mass as an acceleration), ramped by
/// `curve`. Test-only: the simulation has no nodal point loads.
class PointLoads final : public NodalConstraint {
 public:
  PointLoads(std::vector<Index> nodes, std::vector<Vec3> forces, LoadCurve curve)
      : nodes_(std::move(nodes)), f_(std::move(forces)), curve_(std::move(curve)) {}
  void initialize(NodalFields&, std::span<const Real>) override {}
  void constrain_accelerations(const ConstraintLoads& loads, NodalFields& n, Real t) override {
    const Real s = curve_(t);
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
      const Index i = nodes_[k];
      n.a.set(i, loads.force(i) / loads.mass[i] + s * f_[k] / loads.mass[i]);
    }
  }
  void after_positions(std::span<const Real>, NodalFields&, Real) override {}

 private:
  std::vector<Index> nodes_;
  std::vector<Vec3> f_;
  LoadCurve curve_;
};

struct Grid {
  int nx, ny;
  Index node(int i, int j) const { return i + (nx + 1) * j; }
};

/// Fills `sim.nodes()` with a grid of the x-y plane (or, with `xz`, the x-z plane at height y0) and
/// returns the shell connectivity (counter-clockwise about +z, or about +y for xz).
std::vector<Index> shell_grid(NodalFields& nodes, const Grid& g, Real lx, Real ly, bool xz = false,
                              Real y0 = 0.0, Index first = 0) {
  for (int j = 0; j <= g.ny; ++j)
    for (int i = 0; i <= g.nx; ++i) {
      const Index n = first + g.node(i, j);
      const Real a = lx * i / g.nx, b = ly * j / g.ny;
      const Vec3 x = xz ? Vec3(a, y0, b) : Vec3(a, b, 0.0);
      nodes.ids[n] = n + 1;
      nodes.x0.set(n, x);
      nodes.x.set(n, x);
    }
  std::vector<Index> conn;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      if (xz)  // normal +y: order (x, z) counter-clockwise seen from +y means x then -z
        conn.insert(conn.end(), {first + g.node(i, j), first + g.node(i, j + 1),
                                 first + g.node(i + 1, j + 1), first + g.node(i + 1, j)});
      else
        conn.insert(conn.end(), {first + g.node(i, j), first + g.node(i + 1, j),
                                 first + g.node(i + 1, j + 1), first + g.node(i, j + 1)});
    }
  return conn;
}

std::vector<Id> iota_ids(std::size_t n, Id first = 1) {
  std::vector<Id> v(n);
  for (std::size_t k = 0; k < n; ++k) v[k] = first + static_cast<Id>(k);
  return v;
}

/// The spec's ramp (y: 0 -> 1 over [0, 0.1], then held) and the x ramp (0 until 0.3, 1 at 0.4).
LoadCurve ramp_y() { return LoadCurve({{0.0, 0.0}, {0.1, 1.0}, {10.0, 1.0}}, "y"); }
LoadCurve ramp_x() { return LoadCurve({{0.0, 0.0}, {0.3, 0.0}, {0.4, 1.0}, {10.0, 1.0}}, "x"); }

struct CantileverResult {
  Real tip = 0.0, tip_theory = 0.0;
  Real stress = 0.0, stress_theory = 0.0;
  Real reaction = 0.0;
};

/// Clamped plate, length L along x, width b, thickness t, tip load P (-z) shared by the tip nodes,
/// ramped over [0, 1] and held; mass damping critical for the first bending mode; run to rest.
CantileverResult run_cantilever(shell_bt::ThicknessRule::Kind rule) {
  const Real L = 1.0, b = 0.1, t = 0.02, E = 1.0e4, nu = 0.0, rho = 1.0;
  const Grid g{32, 2};
  SimulationSetup setup;
  setup.nodes.resize(static_cast<std::size_t>((g.nx + 1) * (g.ny + 1)));
  auto conn = shell_grid(setup.nodes, g, L, b);
  ShellSection sec;
  sec.thickness = t;
  sec.nip = 5;
  sec.rule = rule;
  const std::size_t ne = conn.size() / 4;
  setup.blocks.push_back(std::make_unique<ShellBlock>(1, ElasticShell(rho, E, nu), sec, conn,
                                                    iota_ids(ne)));
  // Beam theory (nu = 0: the plate's uniaxial bending is the beam's).
  const Real I = b * t * t * t / 12.0;
  const Real delta = 1e-3 * L;  // small: linear theory
  const Real P = 3.0 * E * I * delta / (L * L * L);
  std::vector<Index> tip;
  std::vector<Vec3> f;
  for (int j = 0; j <= g.ny; ++j) {
    tip.push_back(g.node(g.nx, j));
    const Real share = (j == 0 || j == g.ny) ? 0.5 / g.ny : 1.0 / g.ny;
    f.push_back(Vec3(0.0, 0.0, -P * share));
  }
  // First bending frequency; damping alpha = 2 omega1 is critical for it, so the run settles as
  // exp(-omega1 t): 14 / omega1 leaves ~1e-6 of the ramp's dynamic response.
  const Real omega1 = 3.516 * std::sqrt(E * I / (rho * b * t * L * L * L * L));
  const Real t_end = 14.0 / omega1;
  // PointLoads applies a load the energy ledger does not see (a test-only stand-in for nodal
  // loads): the balance check would stop the run.
  setup.controls.energy_error_limit = 0.0;
  setup.constraints.push_back(std::make_unique<PointLoads>(
      tip, f, LoadCurve({{0.0, 0.0}, {3.0 / omega1, 1.0}, {100.0 * t_end, 1.0}}, "tip")));
  // Clamp: every translation and rotation of the root nodes.
  SupportGroup clamp;
  clamp.name = "root";
  std::vector<Index> root;
  for (int j = 0; j <= g.ny; ++j) root.push_back(g.node(0, j));
  for (bool rot : {false, true})
    for (Axis a : {Axis::x, Axis::y, Axis::z}) {
      Support s;
      s.name = "root";
      s.axis = a;
      s.rotational = rot;
      s.nodes = root;
      clamp.supports.push_back(s);
    }
  setup.supports.push_back(clamp);
  MassDamping d;
  d.alpha = 2.0 * omega1;
  setup.damping.push_back(d);
  setup.controls.end_time = t_end;
  setup.controls.history_interval = t_end / 200;
  History h;
  Simulation sim(std::move(setup));
  sim.run({&h});
  CantileverResult r;
  for (Index i : tip) r.tip += -sim.nodes().displacement(i)[2] / static_cast<Real>(tip.size());
  r.tip_theory = delta;
  // Root elements (i = 0): the top-surface bending stress at the centroid x = L / (2 nx).
  const auto& blk = static_cast<const ShellBlock&>(*sim.blocks()[0]);
  const Real xc = 0.5 * L / g.nx;
  r.stress_theory = P * (L - xc) * (0.5 * t) / I;
  for (int j = 0; j < g.ny; ++j) r.stress += blk.surface_stress(g.nx * j, true)[0] / g.ny;
  r.reaction = h.mean("supports/root/reaction", 2, 0.95 * t_end, t_end) / P;
  return r;
}

}  // namespace

TEST(ShellVerification, CantileverTipLoadGauss) {
  const auto r = run_cantilever(shell_bt::ThicknessRule::Kind::gauss);
  const Real e_tip = r.tip / r.tip_theory - 1.0, e_s = r.stress / r.stress_theory - 1.0;
  std::printf("cantilever (5-point Gauss): tip %.6e vs PL^3/3EI %.6e (%+.3f%%); root outer-fibre "
              "stress %.6e vs %.6e (%+.3f%%); reaction/P %.5f\n",
              r.tip, r.tip_theory, 100 * e_tip, r.stress, r.stress_theory, 100 * e_s, r.reaction);
  EXPECT_LT(std::abs(e_tip), 0.02);
  EXPECT_LT(std::abs(e_s), 0.02);
  EXPECT_NEAR(r.reaction, -1.0, 0.005);
}

TEST(ShellVerification, CantileverTipLoadLobatto) {
  const auto r = run_cantilever(shell_bt::ThicknessRule::Kind::lobatto);
  const Real e_tip = r.tip / r.tip_theory - 1.0, e_s = r.stress / r.stress_theory - 1.0;
  std::printf("cantilever (5-point Lobatto): tip %+.3f%%, outer-fibre stress %+.3f%%\n",
              100 * e_tip, 100 * e_s);
  EXPECT_LT(std::abs(e_tip), 0.02);
  EXPECT_LT(std::abs(e_s), 0.02);
}

// The spec's upper shell plate (1 x 1 in x-z, 3 x 3 shells, t = 0.1, rho = 0.1: mass 0.01) resting
// on supports (every node held in y) under the body load P_y = 10 (-y), ramped over [0, 0.1],
// alpha = 15: the reaction equals the load.
TEST(ShellVerification, SpecPlateOnSupportsReactionEqualsLoad) {
  SimulationSetup setup;
  const Grid g{3, 3};
  setup.nodes.resize(16);
  auto conn = shell_grid(setup.nodes, g, 1.0, 1.0, true, 0.0);
  setup.blocks.push_back(make_shell_block(2, ElasticShell(0.1, 1000.0, 0.1),
                                        ShellSection{.thickness = 0.1}, conn, iota_ids(9)));
  const Real mass = 0.1 * 1.0 * 0.1;
  BodyLoad by;
  by.axis = Axis::y;
  by.scale = -10.0 / mass;
  by.curve = ramp_y();
  by.parts = {2};
  setup.body_loads.push_back(by);
  SupportGroup sg;
  sg.name = "plate";
  Support s;
  s.axis = Axis::y;
  for (Index i = 0; i < 16; ++i) s.nodes.push_back(i);
  sg.supports.push_back(s);
  setup.supports.push_back(sg);
  MassDamping d;
  d.alpha = 15.0;
  setup.damping.push_back(d);
  setup.controls.end_time = 0.3;
  setup.controls.history_interval = 0.005;
  History h;
  Simulation sim(std::move(setup));
  sim.run({&h});
  Real m = 0.0;
  for (Real v : sim.nodes().mass) m += v;
  EXPECT_NEAR(m, mass, 1e-15);
  const Real ry = h.mean("supports/plate/reaction", 1, 0.2, 0.3);
  std::printf("spec plate on supports: R_y = %.6f (load -10)\n", ry);
  EXPECT_NEAR(ry, -10.0, 0.05);
}

// The spec's lower block (1.51 x 1.0 x 1.02, 3 x 2 x 2 Mooney-Rivlin bricks) with a layer of
// shells sharing its top-face nodes; body loads on the shells (P_y = 10 down, P_x = 3.1 from
// t = 0.3), supports on the bottom face (y) and the right face (x): reactions equal the loads.
TEST(ShellVerification, SpecShellLayerOnBrickReactionsEqualLoads) {
  const int nx = 3, ny = 2, nz = 2;
  const Real lx = 1.51, ly = 1.0, lz = 1.02;
  SimulationSetup setup;
  auto id = [&](int i, int j, int k) { return static_cast<Index>(i + (nx + 1) * (j + (ny + 1) * k)); };
  setup.nodes.resize(static_cast<std::size_t>((nx + 1) * (ny + 1) * (nz + 1)));
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        const Index n = id(i, j, k);
        const Vec3 x(lx * i / nx, ly * j / ny, lz * k / nz);
        setup.nodes.ids[n] = n + 1;
        setup.nodes.x0.set(n, x);
        setup.nodes.x.set(n, x);
      }
  std::vector<Index> hex;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        hex.insert(hex.end(), {id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
                               id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1),
                               id(i, j + 1, k + 1)});
  setup.blocks.push_back(std::make_unique<HexBlock<MooneyRivlin>>(
      1, MooneyRivlin(0.01, 909.091, 0.0, 0.1),
      HexHourglass{HexHourglass::Kind::physical_stiffness, 0.1}, BulkViscosity{}, hex,
      iota_ids(hex.size() / 8)));
  std::vector<Index> quad;
  for (int k = 0; k < nz; ++k)
    for (int i = 0; i < nx; ++i)  // top face y = ly, normal +y
      quad.insert(quad.end(), {id(i, ny, k), id(i, ny, k + 1), id(i + 1, ny, k + 1), id(i + 1, ny, k)});
  setup.blocks.push_back(make_shell_block(2, ElasticShell(0.1, 1000.0, 0.1),
                                        ShellSection{.thickness = 0.1}, quad,
                                        iota_ids(quad.size() / 4, 100)));
  const Real shell_mass = 0.1 * lx * lz * 0.1;
  BodyLoad by, bx;
  by.axis = Axis::y;
  by.scale = -10.0 / shell_mass;
  by.curve = ramp_y();
  by.parts = {2};
  bx.axis = Axis::x;
  bx.scale = 3.1 / shell_mass;
  bx.curve = ramp_x();
  bx.parts = {2};
  setup.body_loads.push_back(by);
  setup.body_loads.push_back(bx);
  SupportGroup bottom, right;
  bottom.name = "bottom";
  right.name = "right";
  Support sy, sx;
  sy.axis = Axis::y;
  sx.axis = Axis::x;
  for (int k = 0; k <= nz; ++k) {
    for (int i = 0; i <= nx; ++i) sy.nodes.push_back(id(i, 0, k));
    for (int j = 0; j <= ny; ++j) sx.nodes.push_back(id(nx, j, k));
  }
  bottom.supports.push_back(sy);
  right.supports.push_back(sx);
  setup.supports.push_back(bottom);
  setup.supports.push_back(right);
  MassDamping d;
  d.alpha = 15.0;
  setup.damping.push_back(d);
  setup.controls.end_time = 0.5;
  setup.controls.history_interval = 0.0025;
  History h;
  Simulation sim(std::move(setup));
  sim.run({&h});
  const Real ry = h.mean("supports/bottom/reaction", 1, 0.2, 0.3);
  const Real rx = h.mean("supports/right/reaction", 0, 0.45, 0.5);
  const Real ry_late = h.mean("supports/bottom/reaction", 1, 0.45, 0.5);
  std::printf("shell layer on brick: R_y %.5f (load -10) in [0.2,0.3], %.5f in [0.45,0.5]; "
              "R_x %.5f (load 3.1) in [0.45,0.5]; energy balance error %.2e\n",
              ry, ry_late, rx, sim.energy().relative_balance_error());
  EXPECT_NEAR(ry, -10.0, 0.05);
  EXPECT_NEAR(ry_late, -10.0, 0.05);
  EXPECT_NEAR(rx, 3.1, 0.0155);
}

// The shell block's results do not depend on the thread count (a mesh above the parallel
// threshold, a few hundred cycles of a loaded, damped plate).
TEST(ShellVerification, ResultsIndependentOfThreadCount) {
  auto run = [](int threads) {
    set_threads(threads);
    SimulationSetup setup;
    const Grid g{96, 64};
    setup.nodes.resize(static_cast<std::size_t>((g.nx + 1) * (g.ny + 1)));
    auto conn = shell_grid(setup.nodes, g, 1.5, 1.0);
    // Warp it a little so that every term of the kernel is active.
    for (std::size_t i = 0; i < setup.nodes.size(); ++i) {
      const Real z = 0.01 * std::sin(7.0 * setup.nodes.x0.x[i]) * std::cos(5.0 * setup.nodes.x0.y[i]);
      setup.nodes.x0.z[i] = setup.nodes.x.z[i] = z;
    }
    const std::size_t ne = conn.size() / 4;
    setup.blocks.push_back(make_shell_block(1, ElasticShell(0.1, 1000.0, 0.3),
                                          ShellSection{.thickness = 0.01}, conn, iota_ids(ne)));
    BodyLoad bz;
    bz.axis = Axis::z;
    bz.scale = -50.0;
    setup.body_loads.push_back(bz);
    BodyLoad bx = bz;
    bx.axis = Axis::x;
    bx.scale = 20.0;
    setup.body_loads.push_back(bx);
    SupportGroup sg;
    sg.name = "edge";
    for (Axis a : {Axis::x, Axis::y, Axis::z}) {
      Support s;
      s.axis = a;
      for (int j = 0; j <= g.ny; ++j) s.nodes.push_back(g.node(0, j));
      sg.supports.push_back(s);
    }
    setup.supports.push_back(sg);
    setup.controls.end_time = 1.0;
    setup.controls.max_cycles = 300;
    Simulation sim(std::move(setup));
    sim.initialize();
    while (sim.step()) {
    }
    return sim.nodes();
  };
  const int hw = max_threads();
  const NodalFields a = run(1);
  const NodalFields b = run(2);
  set_threads(hw);
  ASSERT_GT(std::abs(a.x.z[a.size() - 1] - a.x0.z[a.size() - 1]), 0.0);
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(a.x[c], b.x[c]);
    EXPECT_EQ(a.v[c], b.v[c]);
    EXPECT_EQ(a.omega[c], b.omega[c]);
  }
}
