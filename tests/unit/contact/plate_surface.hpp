#pragma once
// Small hand-built contact surfaces for the search tests and the contact benchmark: structured
// plates of quadrilaterals with the CSR adjacency of mesh/surface.hpp (the surface builder is
// written elsewhere; these do not depend on it).
#include <algorithm>
#include <vector>

#include "slideline/mesh/nodal_fields.hpp"
#include "slideline/mesh/surface.hpp"

namespace slideline::test {

/// Fills everything of `s` but `conn` from its connectivity: per-segment attributes (a solid
/// face of block 0), `nodes`, `node_segments` and `segment_neighbors` (edge sharing).
inline void finish_surface(Surface& s) {
  const Index ns = static_cast<Index>(s.conn.size() / 4);
  s.block.assign(static_cast<std::size_t>(ns), 0);
  s.element.resize(static_cast<std::size_t>(ns));
  for (Index i = 0; i < ns; ++i) s.element[static_cast<std::size_t>(i)] = i;
  s.part.assign(static_cast<std::size_t>(ns), 1);
  s.kind.assign(static_cast<std::size_t>(ns), SegmentKind::solid_face);
  s.thickness.assign(static_cast<std::size_t>(ns), 0.0);
  s.nodes = s.conn;
  std::sort(s.nodes.begin(), s.nodes.end());
  s.nodes.erase(std::unique(s.nodes.begin(), s.nodes.end()), s.nodes.end());
  const auto row_of = [&](Index node) {
    return static_cast<Index>(std::lower_bound(s.nodes.begin(), s.nodes.end(), node) - s.nodes.begin());
  };
  std::vector<std::vector<Index>> rows(s.nodes.size());
  for (Index seg = 0; seg < ns; ++seg) {
    for (int k = 0; k < 4; ++k) {
      auto& r = rows[static_cast<std::size_t>(row_of(s.conn[4 * static_cast<std::size_t>(seg) + k]))];
      if (r.empty() || r.back() != seg) r.push_back(seg);
    }
  }
  s.node_segments.offset.assign(1, 0);
  s.node_segments.value.clear();
  for (const auto& r : rows) {
    s.node_segments.value.insert(s.node_segments.value.end(), r.begin(), r.end());
    s.node_segments.offset.push_back(static_cast<Index>(s.node_segments.value.size()));
  }
  s.segment_neighbors.offset.assign(1, 0);
  s.segment_neighbors.value.clear();
  for (Index seg = 0; seg < ns; ++seg) {
    std::vector<Index> nb;
    for (int k = 0; k < 4; ++k) {
      const Index a = s.conn[4 * static_cast<std::size_t>(seg) + k];
      const Index b = s.conn[4 * static_cast<std::size_t>(seg) + (k + 1) % 4];
      if (a == b) continue;
      const auto& ra = rows[static_cast<std::size_t>(row_of(a))];
      const auto& rb = rows[static_cast<std::size_t>(row_of(b))];
      for (Index t : ra) {
        if (t != seg && std::find(rb.begin(), rb.end(), t) != rb.end()) nb.push_back(t);
      }
    }
    std::sort(nb.begin(), nb.end());
    nb.erase(std::unique(nb.begin(), nb.end()), nb.end());
    s.segment_neighbors.value.insert(s.segment_neighbors.value.end(), nb.begin(), nb.end());
    s.segment_neighbors.offset.push_back(static_cast<Index>(s.segment_neighbors.value.size()));
  }
}

/// Appends the (nx + 1) x (ny + 1) nodes of a plate with its lower-left corner at `origin`, cell
/// size h in x and y, to x; returns the nx x ny quads (segment i + nx j at cell (i, j), corners
/// counter-clockwise seen from +z, so the normal is +z) as a finished Surface.
inline Surface make_plate(Vec3Field& x, Index nx, Index ny, Real h, const Vec3& origin) {
  const Index first = static_cast<Index>(x.size());
  for (Index j = 0; j <= ny; ++j) {
    for (Index i = 0; i <= nx; ++i) {
      x.x.push_back(origin[0] + h * i);
      x.y.push_back(origin[1] + h * j);
      x.z.push_back(origin[2]);
    }
  }
  Surface s;
  const auto node = [&](Index i, Index j) { return first + i + (nx + 1) * j; };
  for (Index j = 0; j < ny; ++j) {
    for (Index i = 0; i < nx; ++i) {
      for (Index n : {node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)}) s.conn.push_back(n);
    }
  }
  finish_surface(s);
  return s;
}

}  // namespace slideline::test
