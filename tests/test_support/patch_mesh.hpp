#pragma once
// The distorted 2x2x2 patch of the unit cube the solid element tests share: 27 nodes, 8
// hexahedra, or 48 tetrahedra (six per cell, test_support::kuhn_tets) on the same nodes.
#include <vector>

#include "slideline/mesh/nodal_fields.hpp"
#include "test_support/kuhn_tets.hpp"

namespace test_support {

using slideline::Id;
using slideline::Index;
using slideline::NodalFields;
using slideline::Vec3;

/// A 2x2x2 mesh of the unit cube with its centre node and mid-face nodes moved (distorted).
struct PatchMesh {
  NodalFields nodes;
  std::vector<Index> conn;
  std::vector<Id> ids;
  std::vector<int> interior;  // node indices not on the boundary
};

inline PatchMesh make_patch_mesh() {
  PatchMesh p;
  auto idx = [](int i, int j, int k) { return i + 3 * (j + 3 * k); };
  p.nodes.resize(27);
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        Vec3 x(0.5 * i, 0.5 * j, 0.5 * k);
        if (i == 1 && j == 1 && k == 1) x += Vec3(0.12, -0.08, 0.1);
        else if (i == 1 && j == 1) x += Vec3(0.07, -0.05, 0.0);   // mid nodes of z faces
        else if (j == 1 && k == 1) x += Vec3(0.0, 0.06, -0.09);   // mid nodes of x faces
        const Index n = idx(i, j, k);
        p.nodes.ids[n] = n + 1;
        p.nodes.x0.set(n, x);
        p.nodes.x.set(n, x);
        if (i == 1 && j == 1 && k == 1) p.interior.push_back(n);
      }
  Id eid = 1;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        const Index c[8] = {idx(i, j, k),         idx(i + 1, j, k),         idx(i + 1, j + 1, k),
                            idx(i, j + 1, k),     idx(i, j, k + 1),         idx(i + 1, j, k + 1),
                            idx(i + 1, j + 1, k + 1), idx(i, j + 1, k + 1)};
        p.conn.insert(p.conn.end(), c, c + 8);
        p.ids.push_back(eid++);
      }
  return p;
}

/// The same 8 cells of a PatchMesh as 48 tetrahedra (4 node indices each, positive volume).
inline std::vector<Index> patch_tets() {
  auto idx = [](int i, int j, int k) { return i + 3 * (j + 3 * k); };
  std::vector<Index> conn;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
        for (const auto& t : kuhn_tets())
          for (int c : t) conn.push_back(idx(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1)));
  return conn;
}

}  // namespace test_support
