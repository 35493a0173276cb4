// The declared element topologies (mesh/element_topology.hpp): face tables, outward normals and
// measures on unit elements, runs of a block (mesh/block_topology.hpp), and cells by topology.
// Mesh-level only: no element/ header, as the layer order requires.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <utility>
#include <vector>

#include "slideline/core/error.hpp"
#include "slideline/mesh/block_topology.hpp"
#include "slideline/mesh/element_topology.hpp"
#include "slideline/mesh/mesh_block.hpp"

using namespace slideline;

namespace {

/// A field of the given points, one node each.
Vec3Field field(const std::vector<Vec3>& p) {
  Vec3Field f;
  f.resize(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) f.set(static_cast<Index>(i), p[i]);
  return f;
}

std::vector<Index> iota_conn(int n) {
  std::vector<Index> c(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) c[static_cast<std::size_t>(i)] = i;
  return c;
}

/// Area vector (x2 - x0) x (x3 - x1) / 2 of local face f: the segment convention.
Vec3 face_area_vector(const Vec3Field& x, const LocalFace& f) {
  return 0.5 * (x.get(f[2]) - x.get(f[0])).cross(x.get(f[3]) - x.get(f[1]));
}

Vec3 mean_of(const Vec3Field& x, const std::vector<int>& nodes) {
  Vec3 s = Vec3::Zero();
  for (int k : nodes) s += x.get(k);
  return s / static_cast<Real>(nodes.size());
}

// LS-DYNA's unit hexahedron (1-4 the bottom counter-clockwise seen from the top) and the unit
// tetrahedron (1-3 the base counter-clockwise seen from the apex 4).
const std::vector<Vec3> kUnitHex{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                 {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
const std::vector<Vec3> kUnitTet{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

/// Every face points out of the element (away from the element's centroid, through the face's
/// centroid), and the faces close: the area vectors sum to zero and every edge is run once each
/// way, so the table is consistently oriented.
void expect_closed_and_outward(const ElementTopology& t, const Vec3Field& x) {
  std::vector<int> all;
  for (int k = 0; k < t.nodes; ++k) all.push_back(k);
  const Vec3 c = mean_of(x, all);
  Vec3 sum = Vec3::Zero();
  std::map<std::pair<int, int>, int> edges;
  for (const LocalFace& f : t.faces) {
    const int n = f[2] == f[3] ? 3 : 4;
    const Vec3 a = face_area_vector(x, f);
    const Vec3 fc = mean_of(x, std::vector<int>(f.begin(), f.begin() + n));
    EXPECT_GT(a.dot(fc - c), 0.0) << t.name << " face " << f[0] << f[1] << f[2] << f[3];
    sum += a;
    for (int k = 0; k < n; ++k) ++edges[{f[k], f[(k + 1) % n]}];
  }
  EXPECT_NEAR(sum.norm(), 0.0, 1e-14) << t.name;
  for (const auto& [e, count] : edges) {
    EXPECT_EQ(count, 1) << t.name << " edge " << e.first << "-" << e.second;
    EXPECT_EQ(edges.count({e.second, e.first}), 1u) << t.name << " edge " << e.first << "-" << e.second;
  }
}

}  // namespace

// --- The descriptors ----------------------------------------------------------------------------

TEST(ElementTopology, CountsAndOutputCellTypes) {
  EXPECT_EQ(hex8_topology.nodes, 8);
  EXPECT_EQ(hex8_topology.faces.size(), 6u);
  EXPECT_EQ(hex8_topology.dimension, 3);
  EXPECT_EQ(hex8_topology.xdmf_cell, "Hexahedron");
  EXPECT_EQ(hex8_topology.vtk_cell, 12);
  EXPECT_EQ(hex8_topology.cell_set, "hexahedra");
  EXPECT_EQ(tet4_topology.nodes, 4);
  EXPECT_EQ(tet4_topology.faces.size(), 4u);
  EXPECT_EQ(tet4_topology.dimension, 3);
  EXPECT_EQ(tet4_topology.xdmf_cell, "Tetrahedron");
  EXPECT_EQ(tet4_topology.vtk_cell, 10);
  EXPECT_EQ(quad4_topology.nodes, 4);
  EXPECT_EQ(quad4_topology.faces.size(), 1u);
  EXPECT_EQ(quad4_topology.dimension, 2);
  EXPECT_EQ(quad4_topology.xdmf_cell, "Quadrilateral");
  EXPECT_EQ(quad4_topology.vtk_cell, 9);
  EXPECT_EQ(tri3_topology.nodes, 3);
  EXPECT_EQ(tri3_topology.faces.size(), 1u);
  EXPECT_EQ(tri3_topology.dimension, 2);
  EXPECT_EQ(tri3_topology.xdmf_cell, "Triangle");
  EXPECT_EQ(tri3_topology.vtk_cell, 5);
  // Distinct output names, every local node index within the element.
  std::set<std::string_view> names;
  for (const ElementTopology* t : all_topologies) {
    names.insert(t->cell_set);
    for (const LocalFace& f : t->faces)
      for (int k : f) {
        EXPECT_GE(k, 0);
        EXPECT_LT(k, t->nodes);
      }
  }
  EXPECT_EQ(names.size(), all_topologies.size());
}

TEST(ElementTopology, Hex8FacesPointAlongTheNaturalAxes) {
  // zeta-, zeta+, eta-, xi+, eta+, xi- of the unit cube (xi = x, eta = y, zeta = z): the order
  // surfaces list faces in, so it must not change.
  const Vec3Field x = field(kUnitHex);
  const Vec3 expected[6] = {{0, 0, -1}, {0, 0, 1}, {0, -1, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}};
  for (int k = 0; k < 6; ++k) {
    const LocalFace& f = hex8_topology.faces[static_cast<std::size_t>(k)];
    EXPECT_NEAR((face_area_vector(x, f) - expected[k]).norm(), 0.0, 1e-15) << "face " << k;
    // Same node set as the (unoriented) face table of the time step.
    const std::set<int> s1(f.begin(), f.end());
    const std::set<int> s2(hex8::detail::faces[k], hex8::detail::faces[k] + 4);
    EXPECT_EQ(s1, s2) << "face " << k;
  }
  expect_closed_and_outward(hex8_topology, x);
}

TEST(ElementTopology, Hex8FacesPointOutOfADistortedHexahedron) {
  const Vec3Field x = field({{0, 0, 0}, {1.2, 0.1, 0}, {1.1, 0.9, 0.2}, {-0.1, 1, 0},
                             {0.1, 0, 1.1}, {1, -0.1, 0.9}, {1.3, 1.2, 1.2}, {0, 0.9, 1}});
  EXPECT_GT(hex8_topology.measure(x, iota_conn(8).data()), 0.0);
  for (const LocalFace& f : hex8_topology.faces)
    if (f[2] != f[3]) EXPECT_GT(face_area_vector(x, f).norm(), 0.0);
  // Warped faces are not planar; a bilinear face's area vector is still the exact integral of
  // its normal, so the faces close.
  expect_closed_and_outward(hex8_topology, x);
}

TEST(ElementTopology, Tet4FacesAreOutwardTriangles) {
  const Vec3Field x = field(kUnitTet);
  for (const LocalFace& f : tet4_topology.faces) EXPECT_EQ(f[2], f[3]);  // triangles
  expect_closed_and_outward(tet4_topology, x);
  // The four outward normals of the unit tetrahedron: -z, -y, (1,1,1)/sqrt 3, -x.
  const Vec3 n[4] = {{0, 0, -1}, {0, -1, 0}, Vec3(1, 1, 1).normalized(), {-1, 0, 0}};
  for (std::size_t k = 0; k < 4; ++k)
    EXPECT_NEAR((face_area_vector(x, tet4_topology.faces[k]).normalized() - n[k]).norm(), 0.0, 1e-15);
}

TEST(ElementTopology, SolidVolumes) {
  EXPECT_DOUBLE_EQ(hex8_topology.measure(field(kUnitHex), iota_conn(8).data()), 1.0);
  EXPECT_DOUBLE_EQ(tet4_topology.measure(field(kUnitTet), iota_conn(4).data()), 1.0 / 6.0);
  // A box 2 x 3 x 0.5 and a tetrahedron scaled by (2, 3, 0.5): volumes scale by 3.
  std::vector<Vec3> box = kUnitHex, tet = kUnitTet;
  for (Vec3& p : box) p = Vec3(2 * p[0], 3 * p[1], 0.5 * p[2]);
  for (Vec3& p : tet) p = Vec3(2 * p[0], 3 * p[1], 0.5 * p[2]);
  EXPECT_NEAR(hex8_topology.measure(field(box), iota_conn(8).data()), 3.0, 1e-15);
  EXPECT_NEAR(tet4_topology.measure(field(tet), iota_conn(4).data()), 0.5, 1e-15);
  // Mirrored node order: negative volume (the surface builder then reverses the faces).
  const std::vector<Index> hex_mirror{0, 3, 2, 1, 4, 7, 6, 5}, tet_mirror{0, 2, 1, 3};
  EXPECT_DOUBLE_EQ(hex8_topology.measure(field(kUnitHex), hex_mirror.data()), -1.0);
  EXPECT_DOUBLE_EQ(tet4_topology.measure(field(kUnitTet), tet_mirror.data()), -1.0 / 6.0);
}

TEST(ElementTopology, Tet4OrientationIsLsDynasDegenerateHexahedron) {
  // A deck writes a tetrahedron as *ELEMENT_SOLID N1 N2 N3 N4 N4 N4 N4 N4: the same four nodes in
  // tet4 order must be positive exactly when that hexahedron is. Collapsed the other way
  // (N1 N2 N3 N3 N4 N4 N4 N4) the trilinear hexahedron is the tetrahedron itself, so the volumes
  // agree. On a skewed element, and mirrored.
  const Vec3Field x = field({{0.1, 0.2, 0.0}, {1.3, 0.1, 0.2}, {0.4, 1.1, -0.1}, {0.3, 0.5, 0.9}});
  for (const bool mirrored : {false, true}) {
    const std::vector<Index> tet = mirrored ? std::vector<Index>{0, 2, 1, 3} : iota_conn(4);
    const std::vector<Index> deck{tet[0], tet[1], tet[2], tet[3], tet[3], tet[3], tet[3], tet[3]};
    const std::vector<Index> collapsed{tet[0], tet[1], tet[2], tet[2], tet[3], tet[3], tet[3], tet[3]};
    const Real v = tet4_topology.measure(x, tet.data());
    EXPECT_EQ(v > 0.0, !mirrored);
    EXPECT_GT(hex8_topology.measure(x, deck.data()) * v, 0.0);
    EXPECT_NEAR(hex8_topology.measure(x, collapsed.data()), v, 1e-15);
  }
}

TEST(ElementTopology, SurfaceAreasAndTheirOneFace) {
  const Vec3Field square = field({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}});
  EXPECT_DOUBLE_EQ(quad4_topology.measure(square, iota_conn(4).data()), 2.0);
  EXPECT_NEAR((face_area_vector(square, quad4_topology.faces[0]) - Vec3(0, 0, 2)).norm(), 0.0, 1e-15);
  const Vec3Field tri = field({{0, 0, 1}, {2, 0, 1}, {0, 3, 1}});
  EXPECT_DOUBLE_EQ(tri3_topology.measure(tri, iota_conn(3).data()), 3.0);
  EXPECT_NEAR((face_area_vector(tri, tri3_topology.faces[0]) - Vec3(0, 0, 3)).norm(), 0.0, 1e-15);
}

// --- Runs of a block ----------------------------------------------------------------------------

TEST(BlockTopology, RunsOffsetsAndOrder) {
  BlockTopology t(hex8_topology, 2);
  t.add(tet4_topology, 0).add(quad4_topology, 3, 0.1).add(tri3_topology, 1, 0.2);
  ASSERT_EQ(t.runs().size(), 3u);  // an empty run is not kept
  EXPECT_EQ(t.element_count(), 6);
  EXPECT_EQ(t.connectivity_size(), 2u * 8 + 3u * 4 + 3u);
  EXPECT_EQ(t.element(1).node_offset, 8u);
  EXPECT_EQ(&t.element(1).topology(), &hex8_topology);
  EXPECT_EQ(t.element(2).node_offset, 16u);
  EXPECT_EQ(&t.element(4).topology(), &quad4_topology);
  EXPECT_EQ(t.element(4).node_offset, 24u);
  EXPECT_EQ(t.element(4).run.thickness, 0.1);
  EXPECT_EQ(&t.element(5).topology(), &tri3_topology);
  EXPECT_EQ(t.element(5).node_offset, 28u);
  EXPECT_EQ(t.element(5).run.thickness, 0.2);
  EXPECT_THROW(t.element(6), Error);
  std::vector<std::pair<Index, std::size_t>> seen;
  t.for_each_element([&](const TopologyRun&, Index e, std::size_t off) { seen.emplace_back(e, off); });
  const std::vector<std::pair<Index, std::size_t>> expected{{0, 0}, {1, 8}, {2, 16}, {3, 20}, {4, 24}, {5, 28}};
  EXPECT_EQ(seen, expected);
}

TEST(BlockTopology, OneRunPerDeclaredTopologyAtMost) {
  BlockTopology t;
  for (const ElementTopology* k : all_topologies) t.add(*k, 1);
  EXPECT_THROW(t.add(hex8_topology, 1), Error);
}
