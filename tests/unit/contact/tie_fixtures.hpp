#pragma once
// Small block meshes for the tied-interface tests (Types 2, 6, 7, 8, 9) and bm_contact_tied: boxes
// of elastic hexahedra, plates of shells, supports and ramped body loads, assembled into a
// Simulation directly (no deck).
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "slideline/element/block_factory.hpp"
#include "slideline/element/hex_block.hpp"
#include "slideline/material/elastic.hpp"
#include "slideline/mesh/surface_builder.hpp"
#include "slideline/solver/simulation.hpp"
#include "test_support/hex_grid.hpp"
#include "test_support/staged_simulation.hpp"

namespace slideline::test {

using TieBox = test_support::HexGrid;
using TieMesh = test_support::GridMesh;

inline std::unique_ptr<ElementBlock> elastic_hexes(Id pid, const TieBox& b, Real rho, Real E, Real nu) {
  HexHourglass hg;
  // Physical (stiffness) hourglass control: a one-element-thick block under shear has no creeping
  // hourglass mode, so loaded tests come to rest.
  hg.kind = HexHourglass::Kind::physical_stiffness;
  hg.coefficient = 0.1;
  const auto conn = b.conn();
  std::vector<Id> ids(conn.size() / 8);
  for (std::size_t e = 0; e < ids.size(); ++e) ids[e] = static_cast<Id>(1000 * pid + e + 1);
  return std::make_unique<HexBlock<ElasticSolid>>(pid, ElasticSolid(rho, E, nu), hg, BulkViscosity{1.5, 0.06},
                                                  conn, ids);
}

/// Shells on the quads `conn` (4 per element).
inline std::unique_ptr<ElementBlock> elastic_shells(Id pid, std::vector<Index> conn, Real rho, Real E, Real nu,
                                                    Real t) {
  const ElasticShell m(rho, E, nu);
  ShellSection s;
  s.thickness = t;
  std::vector<Id> ids(conn.size() / 4);
  for (std::size_t e = 0; e < ids.size(); ++e) ids[e] = static_cast<Id>(1000 * pid + e + 1);
  return make_shell_block(pid, m, s, std::move(conn), ids);
}

inline SupportGroup tie_support(const std::string& name, const std::vector<Index>& nodes, std::array<int, 3> axes) {
  SupportGroup g;
  g.name = name;
  for (int c = 0; c < 3; ++c)
    if (axes[c]) {
      Support s;
      s.axis = static_cast<Axis>(c);
      s.nodes = nodes;
      g.supports.push_back(s);
    }
  return g;
}

/// Body load (acceleration) ramped from 0 at t0 to `scale` at t1, then held.
inline BodyLoad ramped_load(Axis axis, Real scale, Id part, Real t0, Real t1) {
  BodyLoad b;
  b.axis = axis;
  b.scale = scale;
  b.curve = t0 > 0.0 ? LoadCurve({{0.0, 0.0}, {t0, 0.0}, {t1, 1.0}, {1e9, 1.0}}, "ramp")
                     : LoadCurve({{0.0, 0.0}, {t1, 1.0}, {1e9, 1.0}}, "ramp");
  b.parts = {part};
  return b;
}

/// The exterior surface of `part` with its adjacency.
inline Surface part_surface(const SimulationSetup& setup, Id part) {
  const std::vector<Id> parts{part};
  Surface s = build_surface_from_parts(setup.blocks, setup.nodes, parts, "test");
  build_surface_adjacency(s);
  return s;
}

}  // namespace slideline::test
