#pragma once
// Flat shell meshes of quadrilaterals, triangles (N3 = N4) or both, for the shell tests.
#include <cmath>
#include <vector>

#include "slideline/core/types.hpp"
#include "slideline/mesh/nodal_fields.hpp"

namespace test_support {

/// An nx x ny grid of an lx x ly rectangle: nodes (i, j) numbered i + (nx + 1) j, connectivity 4
/// per element counter-clockwise about the frame's third column, a triangle repeating its third
/// node.
struct ShellMesh {
  slideline::NodalFields nodes;
  std::vector<slideline::Index> conn;
  std::vector<slideline::Id> ids;
  int nx = 0, ny = 0;
  slideline::Index node(int i, int j) const { return i + (nx + 1) * j; }
};

/// The grid in the plane of `frame`'s first two columns through `origin`, interior nodes moved by
/// up to `distort` times the spacing; quad (i, j) is split into two triangles along its diagonal
/// (i, j)-(i+1, j+1) where split(i, j) is true.
template <class Split>
ShellMesh shell_mesh(int nx, int ny, slideline::Real lx, slideline::Real ly, slideline::Real distort,
                     const slideline::Mat3& frame, Split split,
                     const slideline::Vec3& origin = slideline::Vec3::Zero()) {
  using slideline::Index;
  using slideline::Real;
  ShellMesh m;
  m.nx = nx;
  m.ny = ny;
  m.nodes.resize(static_cast<std::size_t>((nx + 1) * (ny + 1)));
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      Real x = lx * i / nx, y = ly * j / ny;
      if (i > 0 && i < nx && j > 0 && j < ny) {
        x += distort * lx / nx * std::sin(3.1 * i + 7.3 * j);
        y += distort * ly / ny * std::cos(5.7 * i - 2.9 * j);
      }
      const Index n = m.node(i, j);
      const slideline::Vec3 p = origin + frame * slideline::Vec3(x, y, 0.0);
      m.nodes.ids[n] = n + 1;
      m.nodes.x0.set(n, p);
      m.nodes.x.set(n, p);
    }
  slideline::Id eid = 1;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const Index a = m.node(i, j), b = m.node(i + 1, j), c = m.node(i + 1, j + 1), d = m.node(i, j + 1);
      if (split(i, j)) {
        m.conn.insert(m.conn.end(), {a, b, c, c, a, c, d, d});
        m.ids.insert(m.ids.end(), {eid, eid + 1});
        eid += 2;
      } else {
        m.conn.insert(m.conn.end(), {a, b, c, d});
        m.ids.push_back(eid++);
      }
    }
  return m;
}

/// Split patterns: none (quads), every quad (triangles), a checkerboard (mixed).
inline bool no_split(int, int) { return false; }
inline bool all_split(int, int) { return true; }
inline bool checkerboard(int i, int j) { return (i + j) % 2 == 0; }

}  // namespace test_support
