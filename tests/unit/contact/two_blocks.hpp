#pragma once
// A small two-block model for the constraint-contact tests: an upper elastic block resting on the
// top face of a lower one (elastic or rigid), meshes not coincident, with the contact surfaces
// (the lower top face, normal +y; the upper bottom face, normal -y) as mesh/surface.hpp surfaces.
#include <array>
#include <memory>
#include <vector>

#include "unit/contact/plate_surface.hpp"
#include "slideline/element/hex_block.hpp"
#include "slideline/element/rigid_mass_block.hpp"
#include "slideline/material/elastic.hpp"
#include "slideline/solver/rigid_body.hpp"
#include "slideline/solver/simulation.hpp"
#include "test_support/hex_grid.hpp"
#include "test_support/staged_simulation.hpp"

namespace slideline::test {

constexpr Real kTwoBlockE = 1000.0, kTwoBlockNu = 0.3, kTwoBlockRho = 1.0;

/// An nx x ny x nz box of hexahedra with its faces as contact surfaces.
struct BlockGrid : test_support::HexGrid {
  /// The face of layer j as a surface: normal +y (up = true) or -y.
  Surface face(int j, bool up) const {
    Surface s;
    for (int k = 0; k < nz; ++k)
      for (int i = 0; i < nx; ++i) {
        const Index a = node(i, j, k), b = node(i + 1, j, k), c = node(i + 1, j, k + 1), d = node(i, j, k + 1);
        // Counter-clockwise seen from +y: a, d, c, b (x cross z points to -y, so reverse).
        if (up) s.conn.insert(s.conn.end(), {a, d, c, b});
        else s.conn.insert(s.conn.end(), {a, b, c, d});
      }
    finish_surface(s);
    return s;
  }
};

struct TwoBlocks : test_support::StagedSimulation {
  BlockGrid lower, upper;
  RigidBody* rigid = nullptr;

  /// Lower block [0, 2] x [0, 0.5] x [0, 1] (4 x 1 x 2), upper [0.3, 1.3] x [0.5, 1] x [0.2, 0.8]
  /// (3 x 1 x 3, its bottom on the lower top face; its left face at upper_x0). rigid_fixed: a rigid lower block with these
  /// fixed dofs (else elastic, bottom fixed).
  explicit TwoBlocks(const std::array<int, 6>* rigid_fixed = nullptr, Real upper_x0 = 0.3) {
    test_support::GridMesh mesh;
    const auto add = [&](const Vec3& o, const Vec3& size, int nx, int ny, int nz) {
      return BlockGrid{mesh.add_box(o, size, nx, ny, nz)};
    };
    lower = add({0, 0, 0}, {2, 0.5, 1}, 4, 1, 2);
    upper = add({upper_x0, 0.5, 0.2}, {1, 0.5, 0.6}, 3, 1, 3);
    mesh.fill(setup.nodes);
    if (rigid_fixed) {
      setup.blocks.push_back(make_rigid_mass_block(1, kTwoBlockRho, kTwoBlockE, kTwoBlockNu, lower.conn(), {}, 0.0,
                                                 {101, 102, 103, 104, 105, 106, 107, 108}));
      auto rb = make_rigid_body(1, lower.all(), *rigid_fixed);
      rigid = static_cast<RigidBody*>(rb.get());
      setup.constraints.push_back(std::move(rb));
    } else {
      setup.blocks.push_back(elastic(1, lower));
      SupportGroup g;
      g.name = "bottom";
      for (int c = 0; c < 3; ++c) {
        Support s;
        s.axis = static_cast<Axis>(c);
        s.nodes = lower.layer(0);
        g.supports.push_back(s);
      }
      setup.supports.push_back(g);
    }
    setup.blocks.push_back(elastic(2, upper));
    setup.sets.part_nodes[1] = lower.all();
    setup.sets.part_nodes[2] = upper.all();
    setup.controls.dt_scale = 0.8;
    setup.controls.dt_max = 2e-4;  // fine steps: the trapezoidal energy balance error is O(dt)
  }

  static std::unique_ptr<ElementBlock> elastic(Id pid, const BlockGrid& b) {
    HexHourglass hg;
    // Stiffness hourglass control (as the spec's blocks): with viscous control alone the
    // hourglass modes the contact loads excite creep under a sustained load.
    hg.kind = HexHourglass::Kind::physical_stiffness;
    hg.coefficient = 1.0;
    const auto conn = b.conn();
    std::vector<Id> ids(conn.size() / 8);
    for (std::size_t e = 0; e < ids.size(); ++e) ids[e] = static_cast<Id>(100 * pid + e + 1);
    return std::make_unique<HexBlock<ElasticSolid>>(pid, ElasticSolid(kTwoBlockRho, kTwoBlockE, kTwoBlockNu), hg,
                                                    BulkViscosity{1.5, 0.06}, conn, ids);
  }

  Real upper_mass() const { return kTwoBlockRho * 0.5 * 0.6; }

  /// Mean displacement of the upper block's nodes.
  Vec3 upper_displacement() const {
    Vec3 u = Vec3::Zero();
    for (Index n : upper.all()) u += sim().nodes().x.get(n) - sim().nodes().x0.get(n);
    return u / static_cast<Real>(upper.node_count());
  }
};

/// A body load on part `part` along `axis` (acceleration, length / time^2), ramped over [0, ramp]
/// (constant when ramp = 0), optionally starting at `start`.
inline BodyLoad ramped_body_load(Axis axis, Real scale, Id part, Real ramp, Real start = 0.0) {
  BodyLoad b;
  b.axis = axis;
  b.scale = scale;
  if (ramp <= 0.0) b.curve = LoadCurve::constant(1.0);
  else if (start <= 0.0) b.curve = LoadCurve({{0.0, 0.0}, {ramp, 1.0}, {1e9, 1.0}}, "ramp");
  else b.curve = LoadCurve({{0.0, 0.0}, {start, 0.0}, {start + ramp, 1.0}, {1e9, 1.0}}, "ramp");
  b.parts = {part};
  return b;
}

}  // namespace slideline::test
