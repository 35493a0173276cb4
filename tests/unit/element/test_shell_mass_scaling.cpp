// Mass scaling of a shell part with quadrilaterals and triangles (N3 = N4, the C0 triangle), once
// (MS1ST = 1) and every cycle (MS1ST = 0): each element's factor f_e = (T / dt_e)^2 (DT2MS > 0, so
// every element is scaled to T, mass added or removed) multiplies its mass rho A0 t / 4 per corner
// (a triangle: / 3, at its three nodes) and its rotary inertia (that mass x max(t^2, A0) / 12), and
// its step: the stable step is T. The steps dt_e are the block's reference steps (the formulas are
// checked by the strips of tests/verification/test_mass_rescaling_blocks.cpp); what is checked here
// is where the mass goes: node by node against the sum over the elements that hold the node.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "slideline/element/shell_block.hpp"
#include "slideline/material/elastic_shell.hpp"
#include "slideline/solver/simulation.hpp"
#include "test_support/staged_simulation.hpp"

using namespace slideline;

namespace {

constexpr Real kRho = 2.0, kE = 1000.0, kNu = 0.25, kT = 0.05;

/// A 3 x 1 strip of unit squares in the x-y plane: square 0 a quadrilateral, squares 1 and 2 two
/// triangles each (given as N1 N2 N3 N3); element lists in deck order (the block stores its
/// quadrilaterals first).
struct Plate : test_support::StagedSimulation {
  std::vector<std::vector<Index>> elements;
  explicit Plate(Real dt2ms, bool every_cycle) {
    setup.nodes.resize(8);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 2; ++j) {
        const Index k = 2 * i + j;
        const Vec3 p(i, j, 0.1 * i * j);  // slightly warped
        setup.nodes.ids[k] = k + 1;
        setup.nodes.x0.set(k, p);
        setup.nodes.x.set(k, p);
      }
    elements = {{0, 2, 3, 1}, {2, 4, 5, 5}, {2, 5, 3, 3}, {4, 6, 7, 7}, {4, 7, 5, 5}};
    std::vector<Index> conn;
    std::vector<Id> ids;
    for (const auto& e : elements) {
      conn.insert(conn.end(), e.begin(), e.end());
      ids.push_back(static_cast<Id>(ids.size() + 1));
    }
    ShellSection sec;
    sec.thickness = kT;
    setup.blocks.push_back(std::make_unique<ShellBlock>(1, ElasticShell(kRho, kE, kNu), sec, conn, ids));
    setup.controls.end_time = 0.0;
    setup.controls.max_cycles = 5;
    setup.controls.dt2ms = dt2ms;
    setup.controls.mass_scaling_every_cycle = every_cycle;
  }
};

Real area(const NodalFields& n, const std::vector<Index>& e) {
  const Vec3 a = n.x0.get(e[0]), b = n.x0.get(e[1]), c = n.x0.get(e[2]);
  if (e[2] == e[3]) return 0.5 * (b - a).cross(c - a).norm();
  return 0.5 * (c - a).cross(Vec3(n.x0.get(e[3])) - b).norm();
}

}  // namespace

TEST(ShellMassScaling, QuadrilateralsAndTrianglesGetTheirShareAtTheirOwnNodes) {
  // The reference steps (unscaled run) set T: 1.5 x the largest, so every element gains mass.
  Plate probe(0.0, false);
  probe.start();
  const ElementBlock& block = *probe.sim().blocks()[0];
  std::vector<Real> steps(5);
  block.reference_steps(probe.sim().nodes(), steps);
  // The block's order is the quadrilateral, then the triangles in deck order: the deck's order here.
  const Real target = 1.5 * *std::max_element(steps.begin(), steps.end());
  for (bool every_cycle : {false, true}) {
    SCOPED_TRACE(every_cycle ? "MS1ST = 0" : "MS1ST = 1");
    Plate plate(target, every_cycle);
    plate.start();
    const NodalFields& n = plate.sim().nodes();
    std::vector<Real> mass(8, 0.0), inertia(8, 0.0);
    Real added = 0.0;
    for (std::size_t e = 0; e < plate.elements.size(); ++e) {
      const auto& q = plate.elements[e];
      const bool tri = q[2] == q[3];
      const Real a0 = area(n, q), f = (target / steps[e]) * (target / steps[e]);
      const Real m = kRho * a0 * kT / (tri ? 3.0 : 4.0), j = m * std::max(kT * kT, a0) / 12.0;
      for (int k = 0; k < (tri ? 3 : 4); ++k) {
        mass[static_cast<std::size_t>(q[static_cast<std::size_t>(k)])] += f * m;
        inertia[static_cast<std::size_t>(q[static_cast<std::size_t>(k)])] += f * j;
      }
      added += (tri ? 3.0 : 4.0) * m * (f - 1.0);
    }
    for (std::size_t i = 0; i < 8; ++i) {
      EXPECT_NEAR(n.mass[i], mass[i], 1e-13 * mass[i]) << i;
      EXPECT_NEAR(n.rot_inertia[i], inertia[i], 1e-13 * inertia[i]) << i;
    }
    EXPECT_NEAR(plate.sim().added_mass().at(0).added, added, 1e-13 * added);
    EXPECT_EQ(plate.sim().added_mass().at(0).scaled, 5);
    // Every element's step, triangles included, is T.
    EXPECT_NEAR(plate.sim().stable_dt(), target, 1e-13 * target);
    // A few cycles at rest: nothing changes (MS1ST = 0 re-evaluates at the same geometry).
    while (plate.sim().step()) {
    }
    EXPECT_NEAR(plate.sim().stable_dt(), target, 1e-13 * target);
    EXPECT_NEAR(plate.sim().added_mass().at(0).added, added, 1e-13 * added);
  }
}
