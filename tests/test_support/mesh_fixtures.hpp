#pragma once
// Small models for the surface and mesh-set tests, built through build_simulation so that the
// blocks and nodes are the ones the solver would use.
#include <cmath>
#include <functional>

#include "slideline/model/model.hpp"

namespace test_support {

using slideline::Id;
using slideline::Real;
using slideline::Vec3;
namespace model = slideline::model;

/// Node id of grid point (i, j, k) of an (nx+1) x (ny+1) x (nz+1) grid, first id 1.
inline Id grid_node(int i, int j, int k, int nx, int ny) {
  return 1 + i + (nx + 1) * (j + (ny + 1) * k);
}

/// nx x ny x nz unit hexahedra (LS-DYNA order) of part `pid`, *MAT_ELASTIC (rho 1, E 1000,
/// nu 0.3) unless the caller replaces the material; `warp` moves each grid point (distortion).
inline model::Model hex_grid_model(int nx, int ny, int nz, Id pid = 1,
                                   const std::function<Vec3(Vec3)>& warp = {}) {
  model::Model m;
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        Vec3 x(i, j, k);
        if (warp) x = warp(x);
        m.nodes.push_back({grid_node(i, j, k, nx, ny), x, 0, 0});
      }
  Id eid = 1;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        auto n = [&](int a, int b, int c) { return grid_node(i + a, j + b, k + c, nx, ny); };
        m.solids.push_back({eid++, pid, {n(0, 0, 0), n(1, 0, 0), n(1, 1, 0), n(0, 1, 0), n(0, 0, 1),
                                         n(1, 0, 1), n(1, 1, 1), n(0, 1, 1)}});
      }
  m.parts.push_back({pid, "block", 1, 1, 0, 0, {}});
  m.solid_sections.push_back({1, 1, {}});
  m.materials.push_back(model::MatElastic{1, 1.0, 1000.0, 0.3, "", {}});
  m.termination.endtim = 0.01;
  return m;
}

/// A 3 x 3 shell plate, 1 x 1 in x-z at y = 0 (part `pid`, t = 0.1, E 1000, nu 0.1), nodes 1-16
/// row by row in x then z, elements 1-9 with normal (x-edge) x (z-edge) = -y.
inline model::Model shell_plate_model(Id pid = 1) {
  model::Model m;
  Id nid = 1;
  for (int k = 0; k <= 3; ++k)
    for (int i = 0; i <= 3; ++i) m.nodes.push_back({nid++, Vec3(i / 3.0, 0.0, k / 3.0), 0, 0});
  Id eid = 1;
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 3; ++i) {
      const Id a = 1 + i + 4 * k;
      m.shells.push_back({eid++, pid, {a, a + 1, a + 5, a + 4}});
    }
  m.parts.push_back({pid, "plate", 1, 1, 0, 0, {}});
  m.shell_sections.push_back({1, 2, 5.0 / 6.0, 5, 1.0, {0.1, 0.1, 0.1, 0.1}, {}});
  m.materials.push_back(model::MatElastic{1, 0.1, 1000.0, 0.1, "", {}});
  m.termination.endtim = 0.01;
  return m;
}

}  // namespace test_support
