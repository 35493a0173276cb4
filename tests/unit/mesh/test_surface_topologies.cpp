// The surface builder, segment stiffness and output cells on a block that holds every declared
// topology (hex8, tet4, quad4, tri3) and one without faces, read only through MeshBlock and the
// topology runs: no element block class is involved, so nothing can be guessed from a class or a
// node count.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

#include "slideline/core/error.hpp"
#include "slideline/mesh/element_topology.hpp"
#include "slideline/mesh/mesh_block.hpp"
#include "slideline/mesh/segment_geometry.hpp"
#include "slideline/mesh/segment_stiffness.hpp"
#include "slideline/mesh/surface_builder.hpp"

using namespace slideline;

namespace {

/// A block of any topologies, as a rigid part or a future mixed block would report them.
class TopologyTestBlock final : public MeshBlock {
 public:
  TopologyTestBlock(Id part, std::vector<Index> conn, BlockTopology topology)
      : part_(part), conn_(std::move(conn)), topology_(topology) {}
  std::string kind() const override { return "test"; }
  Id part_id() const override { return part_; }
  Index element_count() const override { return topology_.element_count(); }
  std::span<const Index> connectivity() const override { return conn_; }
  Id element_id(Index e) const override { return 100 + e; }
  BlockTopology topology() const override { return topology_; }
  Real bulk_modulus() const override { return 7.0; }

 private:
  Id part_;
  std::vector<Index> conn_;
  BlockTopology topology_;
};

/// A unit hexahedron (nodes 0-7); two tetrahedra sharing the face 9 10 11 (nodes 8-12); a
/// tetrahedron listed mirrored (13-16, negative volume); a unit quadrilateral shell at z = 5
/// (17-20, normal +z) and a triangular shell beside it (21-23, normal +z).
NodalFields mixed_nodes() {
  const std::vector<Vec3> p{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1},
                            {1, 1, 1}, {0, 1, 1}, {2, 0, 0}, {3, 0, 0}, {2, 1, 0}, {2, 0, 1},
                            {3, 1, 1}, {5, 0, 0}, {6, 0, 0}, {5, 1, 0}, {5, 0, 1}, {0, 0, 5},
                            {1, 0, 5}, {1, 1, 5}, {0, 1, 5}, {2, 0, 5}, {3, 0, 5}, {2, 1, 5}};
  NodalFields nodes;
  nodes.resize(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    nodes.ids[i] = static_cast<Id>(i + 1);
    nodes.x0.set(static_cast<Index>(i), p[i]);
  }
  nodes.x = nodes.x0;
  return nodes;
}

/// Elements: 0 the hexahedron, 1-3 the tetrahedra, 4 the quadrilateral, 5 the triangle.
std::vector<const MeshBlock*> one_mixed_block(std::vector<TopologyTestBlock>& storage) {
  std::vector<Index> conn{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 9, 10, 11, 12, 13, 15, 14, 16,
                          17, 18, 19, 20, 21, 22, 23};
  BlockTopology t(hex8_topology, 1);
  t.add(tet4_topology, 3).add(quad4_topology, 1, 0.1).add(tri3_topology, 1, 0.2);
  storage.emplace_back(1, std::move(conn), t);
  return {&storage.back()};
}

/// Centroid of element e's nodes, through its declared topology.
Vec3 element_centroid(const MeshBlock& b, Index e, const Vec3Field& x) {
  const BlockTopology topo = b.topology();
  const BlockTopology::Element el = topo.element(e);
  Vec3 s = Vec3::Zero();
  for (int k = 0; k < el.topology().nodes; ++k) s += x.get(b.connectivity()[el.node_offset + k]);
  return s / el.topology().nodes;
}

SegmentNodes segment(const Surface& s, Index k) {
  return {s.conn[4 * k], s.conn[4 * k + 1], s.conn[4 * k + 2], s.conn[4 * k + 3]};
}

/// A 2-node line: a topology without faces (a beam, say), which cannot carry a surface.
constexpr ElementTopology kLine2{"line2", 1, 2, {}, "lines", "Polyline", 3, nullptr};

}  // namespace

TEST(SurfaceTopologies, PartsOfEveryTopology) {
  std::vector<TopologyTestBlock> storage;
  const auto blocks = one_mixed_block(storage);
  const NodalFields nodes = mixed_nodes();
  const std::vector<Id> parts{1};
  const Surface surf = build_surface_from_parts(blocks, nodes, parts, "test");

  // 6 hexahedron faces, 4 + 4 - 2 of the two tetrahedra (the shared face is interior), 4 of the
  // mirrored one, then the two shells: in block, element, face order.
  ASSERT_EQ(surf.segment_count(), 18);
  const std::vector<Index> element{0, 0, 0, 0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3, 3, 4, 5};
  EXPECT_EQ(surf.element, element);
  Vec3 closed = Vec3::Zero();
  for (Index s = 0; s < 16; ++s) {
    EXPECT_EQ(surf.kind[s], SegmentKind::solid_face);
    EXPECT_EQ(surf.thickness[s], 0.0);
    EXPECT_EQ(surf.is_triangle(s), s >= 6) << s;
    const Vec3 out = segment_centroid(surf, s, nodes.x0) - element_centroid(*blocks[0], surf.element[s], nodes.x0);
    EXPECT_GT(segment_normal(surf, s, nodes.x0).dot(out), 0.0) << "segment " << s << " points in";
    closed += segment_area_vector(surf, s, nodes.x0);
    SegmentNodes c = segment(surf, s);
    std::sort(c.begin(), c.begin() + 3);
    EXPECT_FALSE(c[0] == 9 && c[1] == 10 && c[2] == 11) << "the shared face is interior";
  }
  EXPECT_NEAR(closed.norm(), 0.0, 1e-14);  // three closed solids
  EXPECT_EQ(surf.kind[16], SegmentKind::shell);
  EXPECT_EQ(surf.thickness[16], 0.1);
  EXPECT_EQ(segment(surf, 16), (SegmentNodes{17, 18, 19, 20}));
  EXPECT_EQ(surf.kind[17], SegmentKind::shell);
  EXPECT_EQ(surf.thickness[17], 0.2);
  EXPECT_EQ(segment(surf, 17), (SegmentNodes{21, 22, 23, 23}));
  EXPECT_NEAR((segment_normal(surf, 17, nodes.x0) - Vec3(0, 0, 1)).norm(), 0.0, 1e-15);
}

TEST(SurfaceTopologies, SegmentSetOnTetrahedraAndTriangles) {
  std::vector<TopologyTestBlock> storage;
  const auto blocks = one_mixed_block(storage);
  const NodalFields nodes = mixed_nodes();
  // 1: the first tetrahedron's base given pointing in (+z): reversed, keeping the first node.
  // 2: the shared face, pointing out of the first tetrahedron: it belongs to that one.
  // 3: the triangular shell given reversed: a shell keeps its own order.
  const std::vector<SegmentNodes> set{{8, 9, 10, 10}, {9, 10, 11, 11}, {21, 23, 22, 22}};
  const Surface surf = build_surface_from_segments(blocks, nodes, set, "test");
  ASSERT_EQ(surf.segment_count(), 3);
  EXPECT_EQ(segment(surf, 0), (SegmentNodes{8, 10, 9, 9}));
  EXPECT_EQ(surf.element[0], 1);
  EXPECT_EQ(segment(surf, 1), (SegmentNodes{9, 10, 11, 11}));
  EXPECT_EQ(surf.element[1], 1);
  EXPECT_EQ(segment(surf, 2), (SegmentNodes{21, 22, 23, 23}));
  EXPECT_EQ(surf.kind[2], SegmentKind::shell);
  EXPECT_EQ(surf.thickness[2], 0.2);
  EXPECT_EQ(surf.element[2], 5);
  // The shared face the other way round points out of the second tetrahedron.
  const std::vector<SegmentNodes> other{{9, 11, 10, 10}};
  const Surface back = build_surface_from_segments(blocks, nodes, other, "test");
  EXPECT_EQ(segment(back, 0), (SegmentNodes{9, 11, 10, 10}));
  EXPECT_EQ(back.element[0], 2);
}

TEST(SurfaceTopologies, ElementVolumesThroughTheTopology) {
  std::vector<TopologyTestBlock> storage;
  const auto blocks = one_mixed_block(storage);
  const NodalFields nodes = mixed_nodes();
  const MeshBlock& b = *blocks[0];
  EXPECT_DOUBLE_EQ(element_volume(b, 0, nodes.x0), 1.0);
  EXPECT_DOUBLE_EQ(element_volume(b, 1, nodes.x0), 1.0 / 6.0);
  EXPECT_DOUBLE_EQ(element_volume(b, 2, nodes.x0), 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(element_volume(b, 3, nodes.x0), -1.0 / 6.0);  // listed mirrored
  EXPECT_DOUBLE_EQ(element_volume(b, 4, nodes.x0), 1.0 * 0.1);    // area x thickness
  EXPECT_DOUBLE_EQ(element_volume(b, 5, nodes.x0), 0.5 * 0.2);
  // A shell's V / A is its thickness, a tetrahedron face's data its own element's.
  const std::vector<Id> parts{1};
  const Surface surf = build_surface_from_parts(blocks, nodes, parts, "test");
  const SegmentStiffnessData tri = segment_stiffness_data(surf, 17, blocks, nodes.x0);
  EXPECT_EQ(tri.bulk_modulus, 7.0);
  EXPECT_DOUBLE_EQ(tri.element_volume / tri.face_area, 0.2);
  const SegmentStiffnessData tet = segment_stiffness_data(surf, 6, blocks, nodes.x0);
  EXPECT_DOUBLE_EQ(tet.element_volume, 1.0 / 6.0);
  EXPECT_DOUBLE_EQ(tet.face_area, 0.5);
}

TEST(SurfaceTopologies, CellsGroupedByTopology) {
  std::vector<TopologyTestBlock> storage;
  const auto blocks = one_mixed_block(storage);
  const std::vector<TopologyCells> cells = cells_by_topology(blocks);
  ASSERT_EQ(cells.size(), all_topologies.size());
  for (std::size_t k = 0; k < cells.size(); ++k) EXPECT_EQ(cells[k].topology, all_topologies[k]);
  EXPECT_EQ(cells[0].connectivity, (std::vector<Index>{0, 1, 2, 3, 4, 5, 6, 7}));
  EXPECT_EQ(cells[1].topology, &tet4_topology);
  EXPECT_EQ(cells[1].connectivity, (std::vector<Index>{8, 9, 10, 11, 9, 10, 11, 12, 13, 15, 14, 16}));
  EXPECT_EQ(cells[1].count(), 3u);
  EXPECT_EQ(cells[2].connectivity, (std::vector<Index>{17, 18, 19, 20}));
  EXPECT_EQ(cells[3].connectivity, (std::vector<Index>{21, 22, 23}));
}

TEST(SurfaceTopologies, TopologyWithoutFaces) {
  std::vector<TopologyTestBlock> storage;
  storage.reserve(2);
  auto blocks = one_mixed_block(storage);
  storage.emplace_back(2, std::vector<Index>{0, 6}, BlockTopology(kLine2, 1));
  blocks.push_back(&storage.back());
  const NodalFields nodes = mixed_nodes();
  // A part of lines has no surface; a segment set ignores the lines (the shell still matches).
  const std::vector<Id> lines{2};
  EXPECT_THROW(build_surface_from_parts(blocks, nodes, lines, "test"), NotImplementedError);
  const std::vector<SegmentNodes> set{{17, 18, 19, 20}};
  EXPECT_EQ(build_surface_from_segments(blocks, nodes, set, "test").segment_count(), 1);
  // Output keeps its cells, after the declared topologies.
  const std::vector<TopologyCells> cells = cells_by_topology(blocks);
  ASSERT_EQ(cells.size(), all_topologies.size() + 1);
  EXPECT_EQ(cells.back().topology, &kLine2);
  EXPECT_EQ(cells.back().connectivity, (std::vector<Index>{0, 6}));
}
