// Thin-plate bending with quadrilateral, triangular (C0 triangle, N3 = N4) and mixed shell meshes
// against Kirchhoff theory: a simply supported square plate under uniform pressure (Navier's
// series) and a clamped strip under uniform load (beam theory, nu = 0), each also in a copy
// turned about the plate normal. The pressure is a body load on the plate (lumped: each element
// gives its nodes their share of rho A t), run to rest under mass damping critical for the first
// mode.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>

#include "slideline/element/shell_block.hpp"
#include "slideline/solver/output_sink.hpp"
#include "slideline/solver/simulation.hpp"
#include "test_support/shell_mesh.hpp"

using namespace slideline;

namespace {

using Split = bool (*)(int, int);

struct PlateRun {
  Real w = 0.0;         ///< deflection of the measured point (along the load)
  Real w_theory = 0.0;  ///< Kirchhoff
  Real reaction = 0.0;  ///< support reaction along the load over the applied load
};

/// Runs `m` (part 1, one shell block) under the uniform pressure q along -n (n = frame column 2)
/// with `supports`, mass damping 2 omega1, to 14 / omega1; returns the mean -n displacement of
/// `measured` and the reaction of the group "edge" over the load.
PlateRun run_plate(test_support::ShellMesh m, const Mat3& frame, Real E, Real nu, Real t, Real q, Real omega1,
                   std::vector<SupportGroup> supports, const std::vector<Index>& measured) {
  const Real rho = 1.0;
  SimulationSetup setup;
  setup.nodes = std::move(m.nodes);
  ShellSection sec;
  sec.thickness = t;
  sec.nip = 3;
  setup.blocks.push_back(std::make_unique<ShellBlock>(1, ElasticShell(rho, E, nu), sec, m.conn, m.ids));
  BodyLoad load;
  load.axis = Axis::z;  // the plates lie in planes with normal z (turned about z only)
  load.scale = -q / (rho * t);
  const Real t_end = 14.0 / omega1;
  load.curve = LoadCurve({{0.0, 0.0}, {3.0 / omega1, 1.0}, {100.0 * t_end, 1.0}}, "ramp");
  load.parts = {1};
  setup.body_loads.push_back(load);
  setup.supports = std::move(supports);
  MassDamping d;
  d.alpha = 2.0 * omega1;
  setup.damping.push_back(d);
  setup.controls.end_time = t_end;
  setup.controls.history_interval = t_end / 100;
  History h;
  Simulation sim(std::move(setup));
  sim.run({&h});
  PlateRun r;
  for (Index i : measured) r.w -= sim.nodes().displacement(i).dot(frame.col(2)) / static_cast<Real>(measured.size());
  Real area = 0.0;
  for (Real v : sim.nodes().mass) area += v / (rho * t);
  r.reaction = -h.mean("supports/edge/reaction", 2, 0.95 * t_end, t_end) / (q * area);
  return r;
}

Support support(Axis a, std::vector<Index> nodes, bool rotational = false) {
  Support s;
  s.name = "edge";
  s.axis = a;
  s.rotational = rotational;
  s.nodes = std::move(nodes);
  return s;
}

/// Navier's series for the centre deflection of a simply supported square plate (side a, flexural
/// rigidity D) under uniform pressure q: 16 q a^4 / (pi^6 D) sum over odd m, n.
Real navier_centre(Real q, Real a, Real D) {
  Real s = 0.0;
  for (int m = 1; m < 400; m += 2)
    for (int n = 1; n < 400; n += 2) {
      const Real sign = ((m + n) / 2 - 1) % 2 == 0 ? 1.0 : -1.0;
      s += sign / (m * n * std::pow(m * m + n * n, 2));
    }
  return 16.0 * q * std::pow(a, 4) / (std::pow(M_PI, 6) * D) * s;
}

/// The simply supported square (side 1, a / t = 100, nu = 0.3) on an n x n mesh, turned by `turn`
/// about z: w = 0 on the edges, the edge nodes held in plane.
PlateRun simply_supported(int n, Split split, Real turn) {
  const Real a = 1.0, t = 0.01, E = 1.0e4, nu = 0.3;
  const Real D = E * t * t * t / (12.0 * (1.0 - nu * nu));
  const Real w_target = 1e-3 * t;  // linear
  const Real q = w_target / navier_centre(1.0, a, D);
  const Real omega1 = 2.0 * M_PI * M_PI / (a * a) * std::sqrt(D / t);
  const Mat3 frame = Eigen::AngleAxis<Real>(turn, Vec3::UnitZ()).toRotationMatrix();
  test_support::ShellMesh m = test_support::shell_mesh(n, n, a, a, 0.0, frame, split, Vec3(0.3, -0.2, 0.1));
  std::vector<Index> edge;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      if (i == 0 || j == 0 || i == n || j == n) edge.push_back(m.node(i, j));
  SupportGroup g;
  g.name = "edge";
  for (Axis ax : {Axis::x, Axis::y, Axis::z}) g.supports.push_back(support(ax, edge));
  PlateRun r = run_plate(m, frame, E, nu, t, q, omega1, {g}, {m.node(n / 2, n / 2)});
  r.w_theory = w_target;
  return r;
}

/// The clamped strip (length 1, width 0.1, t = 0.02, nu = 0) on an n x 2 mesh under uniform load,
/// turned by `turn` about z: tip deflection q L^4 / (8 E I).
PlateRun cantilever(int n, Split split, Real turn) {
  const Real L = 1.0, b = 0.1, t = 0.02, E = 1.0e4;
  const Real I = b * t * t * t / 12.0;
  const Real w_target = 1e-3 * L;
  const Real q = w_target * 8.0 * E * I / (b * std::pow(L, 4));  // pressure
  const Real omega1 = 3.516 * std::sqrt(E * I / (b * t * std::pow(L, 4)));
  const Mat3 frame = Eigen::AngleAxis<Real>(turn, Vec3::UnitZ()).toRotationMatrix();
  test_support::ShellMesh m = test_support::shell_mesh(n, 2, L, b, 0.0, frame, split, Vec3(-0.1, 0.4, 0.2));
  std::vector<Index> root, tip;
  for (int j = 0; j <= 2; ++j) {
    root.push_back(m.node(0, j));
    tip.push_back(m.node(n, j));
  }
  SupportGroup g;
  g.name = "edge";
  for (bool rot : {false, true})
    for (Axis ax : {Axis::x, Axis::y, Axis::z}) g.supports.push_back(support(ax, root, rot));
  PlateRun r = run_plate(m, frame, E, 0.0, t, q, omega1, {g}, tip);
  r.w_theory = w_target;
  return r;
}

struct MeshKind {
  const char* name;
  Split split;
};
const MeshKind kMeshes[] = {{"quads", test_support::no_split},
                            {"triangles", test_support::all_split},
                            {"mixed", test_support::checkerboard}};

}  // namespace

// 8 x 8 meshes (128 triangles), a / t = 100; the triangle mesh also turned by 0.5 rad about the
// normal (same numbers to round-off). Measured: quads +2.66 %, triangles -2.18 %, mixed +2.78 %
// (triangles -0.06 % at 16 x 16; without the stabilised shear factor -23.5 % at 8 x 8 and -2.7 %
// at 16 x 16: residual shear locking, shell_c0tri.hpp). 5 % is the first-order elements' error at
// this density, not a margin.
TEST(ShellTriangleVerification, SimplySupportedPlateAgainstNavier) {
  for (const MeshKind& mk : kMeshes)
    for (Real turn : {0.0, 0.5}) {
      if (turn != 0.0 && mk.split != test_support::all_split) continue;
      const PlateRun r = simply_supported(8, mk.split, turn);
      const Real err = r.w / r.w_theory - 1.0;
      std::printf("simply supported plate 8x8 %-9s turned %.1f: w_c %.6e vs Navier %.6e (%+.2f%%), "
                  "reaction/load %.5f\n",
                  mk.name, turn, r.w, r.w_theory, 100 * err, r.reaction);
      EXPECT_LT(std::abs(err), 0.05) << mk.name << " turned " << turn;
      EXPECT_NEAR(r.reaction, 1.0, 2e-3) << mk.name;
    }
}

// 8 x 2 meshes, nu = 0, L / t = 50. Measured: see the printed errors; 16 x 2: 0.02-0.08 %.
TEST(ShellTriangleVerification, ClampedStripAgainstBeamTheory) {
  for (const MeshKind& mk : kMeshes)
    for (Real turn : {0.0, 0.5}) {
      if (turn != 0.0 && mk.split != test_support::all_split) continue;
      const PlateRun r = cantilever(8, mk.split, turn);
      const Real err = r.w / r.w_theory - 1.0;
      std::printf("clamped strip 8x2 %-9s turned %.1f: tip %.6e vs qL^4/8EI %.6e (%+.2f%%), reaction/load %.5f\n",
                  mk.name, turn, r.w, r.w_theory, 100 * err, r.reaction);
      EXPECT_LT(std::abs(err), 0.05) << mk.name << " turned " << turn;
      EXPECT_NEAR(r.reaction, 1.0, 2e-3) << mk.name;
    }
}
