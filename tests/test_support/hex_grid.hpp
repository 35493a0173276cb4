#pragma once
// A box of nodes and hexahedra appended to a node list, shared by the tests that assemble a
// Simulation directly (no deck): the tied and constraint-contact fixtures and the constraint-order
// tests.
#include <cstddef>
#include <vector>

#include "slideline/core/types.hpp"
#include "slideline/mesh/nodal_fields.hpp"

namespace slideline::test_support {

/// An nx x ny x nz box of nodes numbered from `first`, i fastest, then j (y), then k (z).
struct HexGrid {
  Index first = 0;
  int nx = 1, ny = 1, nz = 1;
  Index node(int i, int j, int k) const { return first + i + (nx + 1) * (j + (ny + 1) * k); }
  Index node_count() const { return (nx + 1) * (ny + 1) * (nz + 1); }
  /// Eight nodes per hexahedron: the bottom face (y = j) counter-clockwise seen from +y, then the
  /// face above it.
  std::vector<Index> conn() const {
    std::vector<Index> c;
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
          c.insert(c.end(), {node(i, j, k), node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j, k),
                             node(i, j + 1, k), node(i, j + 1, k + 1), node(i + 1, j + 1, k + 1),
                             node(i + 1, j + 1, k)});
    return c;
  }
  /// Nodes of the layer j (constant y).
  std::vector<Index> layer(int j) const {
    std::vector<Index> out;
    for (int k = 0; k <= nz; ++k)
      for (int i = 0; i <= nx; ++i) out.push_back(node(i, j, k));
    return out;
  }
  /// Every node of the box, layer by layer.
  std::vector<Index> all() const {
    std::vector<Index> out;
    for (int j = 0; j <= ny; ++j)
      for (Index n : layer(j)) out.push_back(n);
    return out;
  }
};

/// Node positions of the boxes added so far.
struct GridMesh {
  std::vector<Vec3> x;
  /// Box [origin, origin + size] with nx x ny x nz cells (ny = 0: a plate of nodes in x-z).
  HexGrid add_box(const Vec3& origin, const Vec3& size, int nx, int ny, int nz) {
    HexGrid b{static_cast<Index>(x.size()), nx, ny, nz};
    for (int k = 0; k <= nz; ++k)
      for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i)
          x.push_back(origin + Vec3(size[0] * i / nx, ny ? size[1] * j / ny : 0.0, size[2] * k / nz));
    return b;
  }
  /// Sizes `nodes` and sets x0 = x to the positions; deck ids 1, 2, ...
  void fill(NodalFields& nodes) const {
    nodes.resize(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
      nodes.ids[i] = static_cast<Id>(i + 1);
      nodes.x0.set(static_cast<Index>(i), x[i]);
      nodes.x.set(static_cast<Index>(i), x[i]);
    }
  }
};

}  // namespace slideline::test_support
