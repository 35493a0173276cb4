// Contact surfaces built from parts and segment sets: outward orientation, exterior-face counts,
// adjacency, and the two-block scenario's contact faces.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "slideline/core/error.hpp"
#include "slideline/element/hex8.hpp"
#include "slideline/element/hex_block.hpp"
#include "slideline/material/elastic.hpp"
#include "slideline/mesh/block_topology.hpp"
#include "slideline/mesh/segment_geometry.hpp"
#include "slideline/mesh/surface_builder.hpp"
#include "slideline/scenarios/two_block.hpp"
#include "slideline/solver/build.hpp"
#include "test_support/hex_fixtures.hpp"
#include "test_support/mesh_fixtures.hpp"

using namespace slideline;

namespace {

/// Centroid of the element behind segment s, at the reference coordinates.
Vec3 element_centroid(const Simulation& sim, const Surface& surf, Index s) {
  const ElementBlock& b = *sim.blocks()[surf.block[s]];
  const BlockTopology t = b.topology();
  const BlockTopology::Element el = t.element(surf.element[s]);
  const int n = el.topology().nodes;
  const Index* c = b.connectivity().data() + el.node_offset;
  Vec3 sum = Vec3::Zero();
  for (int k = 0; k < n; ++k) sum += sim.nodes().x0.get(c[k]);
  return sum / n;
}

/// Every segment's normal points away from its element's centroid; returns how many do.
int count_outward(const Simulation& sim, const Surface& surf) {
  int n = 0;
  for (Index s = 0; s < surf.segment_count(); ++s) {
    const Vec3 d = segment_centroid(surf, s, sim.nodes().x0) - element_centroid(sim, surf, s);
    const Real dot = segment_normal(surf, s, sim.nodes().x0).dot(d);
    EXPECT_GT(dot, 0.0) << "segment " << s << " of element " << surf.element[s] << " points in";
    n += dot > 0.0;
  }
  return n;
}

/// Sum of the area vectors: zero for a closed surface (each bilinear patch's area vector is the
/// exact integral of its normal), so a single inward face shows up.
Vec3 total_area_vector(const Surface& surf, const Vec3Field& x) {
  Vec3 a = Vec3::Zero();
  for (Index s = 0; s < surf.segment_count(); ++s) a += segment_area_vector(surf, s, x);
  return a;
}

std::vector<Index> row(const Csr& c, Index r) {
  return {c.value.begin() + c.begin(r), c.value.begin() + c.end(r)};
}

const std::vector<Id> kPart1{1};

}  // namespace

// --- Surfaces from parts ------------------------------------------------------------------------

TEST(SurfaceFromParts, SingleCubeHasSixOutwardFaces) {
  auto sim = build_simulation(test_support::hex_grid_model(1, 1, 1));
  const Surface surf = build_surface_from_parts(sim->blocks(), sim->nodes(), kPart1, "test");
  ASSERT_EQ(surf.segment_count(), 6);
  EXPECT_EQ(count_outward(*sim, surf), 6);
  for (Index s = 0; s < 6; ++s) {
    EXPECT_EQ(surf.kind[s], SegmentKind::solid_face);
    EXPECT_EQ(surf.thickness[s], 0.0);
    EXPECT_EQ(surf.part[s], 1);
    EXPECT_EQ(surf.element[s], 0);
    EXPECT_NEAR(segment_area(surf, s, sim->nodes().x0), 1.0, 1e-15);
    EXPECT_EQ(row(surf.segment_neighbors, s).size(), 4u);  // a cube face touches the other 4
  }
  ASSERT_EQ(surf.node_count(), 8);
  for (Index i = 0; i < 8; ++i) EXPECT_EQ(surf.node_segments.end(i) - surf.node_segments.begin(i), 3);
  // Face 0 is the bottom (z = 0), normal -z; face 1 the top.
  EXPECT_NEAR((segment_normal(surf, 0, sim->nodes().x0) - Vec3(0, 0, -1)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((segment_normal(surf, 1, sim->nodes().x0) - Vec3(0, 0, 1)).norm(), 0.0, 1e-15);
}

TEST(SurfaceFromParts, TwoByTwoByTwoBlockHas24ExteriorFaces) {
  auto sim = build_simulation(test_support::hex_grid_model(2, 2, 2));
  const Surface surf = build_surface_from_parts(sim->blocks(), sim->nodes(), kPart1, "test");
  EXPECT_EQ(surf.segment_count(), 24);
  EXPECT_EQ(count_outward(*sim, surf), 24);
  EXPECT_EQ(surf.node_count(), 26);  // 27 grid points, less the centre
  EXPECT_NEAR(total_area_vector(surf, sim->nodes().x0).norm(), 0.0, 1e-14);
  for (Index s = 0; s < surf.segment_count(); ++s)
    EXPECT_EQ(row(surf.segment_neighbors, s).size(), 4u);  // closed quad surface
  // The face centre (1, 1, 0) of the bottom is in 4 segments, a corner in 3, an edge midpoint in 4.
  const Index centre = test_support::grid_node(1, 1, 0, 2, 2) - 1;
  const auto it = std::lower_bound(surf.nodes.begin(), surf.nodes.end(), centre);
  ASSERT_NE(it, surf.nodes.end());
  EXPECT_EQ(row(surf.node_segments, static_cast<Index>(it - surf.nodes.begin())).size(), 4u);
  EXPECT_EQ(row(surf.node_segments, 0).size(), 3u);  // node 1 at the origin
}

TEST(SurfaceFromParts, DistortedMeshFacesPointOutward) {
  // 3 x 3 x 3 hexahedra, every grid point moved by a smooth but strong, non-affine field.
  auto warp = [](Vec3 x) {
    return Vec3(x[0] + 0.25 * std::sin(1.3 * x[1] + 0.7 * x[2]),
                x[1] + 0.2 * std::cos(0.9 * x[0]) * x[2] / 3.0,
                x[2] + 0.15 * x[0] * x[1] / 3.0 - 0.1 * std::sin(2.0 * x[0]));
  };
  auto sim = build_simulation(test_support::hex_grid_model(3, 3, 3, 1, warp));
  sim->initialize();  // every element has a positive volume
  const Surface surf = build_surface_from_parts(sim->blocks(), sim->nodes(), kPart1, "test");
  EXPECT_EQ(surf.segment_count(), 54);
  EXPECT_EQ(count_outward(*sim, surf), 54);
  EXPECT_NEAR(total_area_vector(surf, sim->nodes().x0).norm(), 0.0, 1e-13);
}

TEST(SurfaceFromParts, MirroredHexahedronStillPointsOutward) {
  // Nodes 1-4 clockwise seen from the top: negative volume, so the table would point in.
  NodalFields nodes;
  nodes.resize(8);
  const hex8::NodeMat X = test_support::unit_hex();
  for (Index i = 0; i < 8; ++i) {
    nodes.ids[i] = i + 1;
    nodes.x0.set(i, X.row(i).transpose());
  }
  nodes.x = nodes.x0;
  ElementBlocks blocks;
  blocks.push_back(std::make_unique<HexBlock<ElasticSolid>>(
      7, ElasticSolid(1.0, 100.0, 0.3), HexHourglass{}, BulkViscosity{},
      std::vector<Index>{0, 3, 2, 1, 4, 7, 6, 5}, std::vector<Id>{1}));
  const std::vector<Id> parts{7};
  const Surface surf = build_surface_from_parts(blocks, nodes, parts, "test");
  ASSERT_EQ(surf.segment_count(), 6);
  const Vec3 c(0.5, 0.5, 0.5);
  for (Index s = 0; s < 6; ++s)
    EXPECT_GT(segment_normal(surf, s, nodes.x0).dot(segment_centroid(surf, s, nodes.x0) - c), 0.0);
}

TEST(SurfaceFromParts, WedgeGivesTwoTriangles) {
  // A triangular prism written as a hexahedron: 5 = 6 and 7 = 8 on a ridge at x = 0.5, z = 1.
  // The deck builder refuses degenerate solids (the one-point hexahedron cannot run them), so the
  // block is made directly: the surface builder must still handle a block that holds one.
  model::Model m = test_support::hex_grid_model(1, 1, 1);
  SimulationSetup setup;
  setup.nodes.resize(6);
  const Vec3 xs[6] = {m.nodes[0].x, m.nodes[1].x, m.nodes[2].x, m.nodes[3].x, Vec3(0.5, 0, 1), Vec3(0.5, 1, 1)};
  for (Index i = 0; i < 6; ++i) {
    setup.nodes.ids[i] = i + 1;
    setup.nodes.x0.set(i, xs[i]);
    setup.nodes.x.set(i, xs[i]);
  }
  // Node ids 1 2 4 3 5 5 7 7 of the grid model's numbering, as internal indices.
  std::vector<Index> conn{0, 1, 3, 2, 4, 4, 5, 5};
  HexHourglass hg;
  setup.blocks.push_back(std::make_unique<HexBlock<ElasticSolid>>(kPart1[0], ElasticSolid(1.0, 1000.0, 0.3), hg,
                                                                 BulkViscosity{1.5, 0.06}, conn, std::vector<Id>{1}));
  const Surface surf = build_surface_from_parts(setup.blocks, setup.nodes, kPart1, "test");
  ASSERT_EQ(surf.segment_count(), 5);  // the collapsed top face is dropped
  int triangles = 0;
  for (Index s = 0; s < 5; ++s) triangles += surf.is_triangle(s);
  EXPECT_EQ(triangles, 2);
  auto sim = std::make_unique<Simulation>(std::move(setup));
  EXPECT_EQ(count_outward(*sim, surf), 5);
  EXPECT_NEAR(total_area_vector(surf, sim->nodes().x0).norm(), 0.0, 1e-15);
  for (Index s = 0; s < 5; ++s)  // every face borders every other but the opposite triangle
    EXPECT_EQ(row(surf.segment_neighbors, s).size(), surf.is_triangle(s) ? 3u : 4u);
}

TEST(SurfaceFromParts, ShellPlateAdjacency) {
  auto sim = build_simulation(test_support::shell_plate_model());
  const Surface surf = build_surface_from_parts(sim->blocks(), sim->nodes(), kPart1, "test");
  ASSERT_EQ(surf.segment_count(), 9);
  for (Index s = 0; s < 9; ++s) {
    EXPECT_EQ(surf.kind[s], SegmentKind::shell);
    EXPECT_EQ(surf.thickness[s], 0.1);
    EXPECT_EQ(surf.element[s], s);
    // The shell's own normal: (x-edge) x (z-edge) = -y for this connectivity.
    EXPECT_NEAR((segment_normal(surf, s, sim->nodes().x0) - Vec3(0, -1, 0)).norm(), 0.0, 1e-15);
  }
  // Segments 0..8 row by row (x fastest): corners 2 neighbours, edges 3, the centre 4.
  EXPECT_EQ(row(surf.segment_neighbors, 0), (std::vector<Index>{1, 3}));
  EXPECT_EQ(row(surf.segment_neighbors, 2), (std::vector<Index>{1, 5}));
  EXPECT_EQ(row(surf.segment_neighbors, 6), (std::vector<Index>{3, 7}));
  EXPECT_EQ(row(surf.segment_neighbors, 8), (std::vector<Index>{5, 7}));
  EXPECT_EQ(row(surf.segment_neighbors, 1), (std::vector<Index>{0, 2, 4}));
  EXPECT_EQ(row(surf.segment_neighbors, 3), (std::vector<Index>{0, 4, 6}));
  EXPECT_EQ(row(surf.segment_neighbors, 5), (std::vector<Index>{2, 4, 8}));
  EXPECT_EQ(row(surf.segment_neighbors, 7), (std::vector<Index>{4, 6, 8}));
  EXPECT_EQ(row(surf.segment_neighbors, 4), (std::vector<Index>{1, 3, 5, 7}));
  // Node -> segments: nodes 1-16 are internal 0-15, all on the surface.
  ASSERT_EQ(surf.node_count(), 16);
  EXPECT_EQ(row(surf.node_segments, 0), (std::vector<Index>{0}));           // corner
  EXPECT_EQ(row(surf.node_segments, 1), (std::vector<Index>{0, 1}));        // edge
  EXPECT_EQ(row(surf.node_segments, 5), (std::vector<Index>{0, 1, 3, 4}));  // interior
  EXPECT_EQ(row(surf.node_segments, 15), (std::vector<Index>{8}));
  EXPECT_EQ(surf.node_segments.value.size(), 36u);
}

TEST(SurfaceFromParts, RigidPartCarriesItsFaces) {
  model::Model m = test_support::hex_grid_model(2, 1, 1);
  m.materials[0] = model::MatRigid{1, 1.0, 1000.0, 0.3, 0.0, 0, 0, "", {}};
  auto sim = build_simulation(m);
  const Surface surf = build_surface_from_parts(sim->blocks(), sim->nodes(), kPart1, "test");
  EXPECT_EQ(sim->blocks()[0]->kind(), "rigid");
  EXPECT_EQ(surf.segment_count(), 10);
  EXPECT_EQ(count_outward(*sim, surf), 10);
}

TEST(SurfaceFromParts, ErrorsNameTheContext) {
  auto sim = build_simulation(test_support::hex_grid_model(1, 1, 1));
  const std::vector<Id> missing{1, 42};
  try {
    build_surface_from_parts(sim->blocks(), sim->nodes(), missing, "deck.k:7: *CONTACT 3 SSID");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("deck.k:7: *CONTACT 3 SSID: part 42"), std::string::npos)
        << e.what();
  }
}

// --- Surfaces from segment sets -----------------------------------------------------------------

TEST(SurfaceFromSegments, MatchesThePartSurfaceInAnyOrientation) {
  auto sim = build_simulation(test_support::hex_grid_model(2, 2, 2));
  const Surface ref = build_surface_from_parts(sim->blocks(), sim->nodes(), kPart1, "test");
  // The same faces, each rotated by s % 4 and every third one reversed (pointing inward).
  std::vector<SegmentNodes> set;
  for (Index s = 0; s < ref.segment_count(); ++s) {
    SegmentNodes c;
    for (int k = 0; k < 4; ++k) c[k] = ref.conn[4 * s + (k + s) % 4];
    if (s % 3 == 0) std::swap(c[1], c[3]);
    set.push_back(c);
  }
  const Surface surf = build_surface_from_segments(sim->blocks(), sim->nodes(), set, "test");
  ASSERT_EQ(surf.segment_count(), ref.segment_count());
  EXPECT_EQ(surf.block, ref.block);
  EXPECT_EQ(surf.element, ref.element);
  EXPECT_EQ(surf.part, ref.part);
  EXPECT_EQ(surf.nodes, ref.nodes);
  EXPECT_EQ(surf.node_segments.value, ref.node_segments.value);
  EXPECT_EQ(surf.segment_neighbors.offset, ref.segment_neighbors.offset);
  EXPECT_EQ(surf.segment_neighbors.value, ref.segment_neighbors.value);
  for (Index s = 0; s < surf.segment_count(); ++s) {
    const Vec3 n = segment_normal(surf, s, sim->nodes().x0);
    EXPECT_NEAR((n - segment_normal(ref, s, sim->nodes().x0)).norm(), 0.0, 1e-15) << s;
    EXPECT_EQ(surf.conn[4 * s], set[s][0]);  // reordering keeps the first node
  }
}

TEST(SurfaceFromSegments, SharedFaceBelongsToTheSideTheOrderPicks) {
  auto sim = build_simulation(test_support::hex_grid_model(2, 1, 1));
  // The face x = 1 between elements 0 and 1: nodes (1,0,0) (1,1,0) (1,1,1) (1,0,1).
  // Deck ids are Id (64-bit), segment nodes internal Index: convert once, here.
  auto n = [](int i, int j, int k) { return static_cast<Index>(test_support::grid_node(i, j, k, 2, 1) - 1); };
  const std::vector<SegmentNodes> plus{{n(1, 0, 0), n(1, 1, 0), n(1, 1, 1), n(1, 0, 1)}};
  const std::vector<SegmentNodes> minus{{n(1, 0, 0), n(1, 0, 1), n(1, 1, 1), n(1, 1, 0)}};
  const Surface a = build_surface_from_segments(sim->blocks(), sim->nodes(), plus, "test");
  const Surface b = build_surface_from_segments(sim->blocks(), sim->nodes(), minus, "test");
  EXPECT_EQ(a.element[0], 0);  // +x points out of the left element
  EXPECT_EQ(b.element[0], 1);
  EXPECT_NEAR(segment_normal(a, 0, sim->nodes().x0)[0], 1.0, 1e-15);
  EXPECT_NEAR(segment_normal(b, 0, sim->nodes().x0)[0], -1.0, 1e-15);
}

TEST(SurfaceFromSegments, ShellSegmentTakesTheShellNormal) {
  auto sim = build_simulation(test_support::shell_plate_model());
  const std::vector<SegmentNodes> set{{0, 4, 5, 1}, {5, 6, 2, 1}};  // elements 1 and 2, reversed
  const Surface surf = build_surface_from_segments(sim->blocks(), sim->nodes(), set, "test");
  ASSERT_EQ(surf.segment_count(), 2);
  EXPECT_EQ(surf.element, (std::vector<Index>{0, 1}));
  EXPECT_EQ(surf.thickness[1], 0.1);
  EXPECT_NEAR(segment_normal(surf, 1, sim->nodes().x0)[1], -1.0, 1e-15);
  EXPECT_EQ(row(surf.segment_neighbors, 0), (std::vector<Index>{1}));
}

TEST(SurfaceFromSegments, BadSegmentsAreInputErrors) {
  auto sim = build_simulation(test_support::hex_grid_model(1, 1, 1));
  auto message = [&](std::vector<SegmentNodes> set) {
    try {
      build_surface_from_segments(sim->blocks(), sim->nodes(), set, "deck.k:3: *SET_SEGMENT 9");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  // Nodes 1 2 7 8 (internal 0 1 6 7): a diagonal plane, no face.
  const std::string none = message({{0, 1, 6, 7}});
  EXPECT_NE(none.find("deck.k:3: *SET_SEGMENT 9: segment 1 (nodes 1 2 7 8) matches no"),
            std::string::npos) << none;
  EXPECT_NE(message({{0, 1, 2, 3}, {1, 2, 3, 0}}).find("segment 2 (nodes 2 3 4 1) repeats segment 1"),
            std::string::npos);
  EXPECT_NE(message({{0, 1, 1, 1}}).find("fewer than 3 distinct nodes"), std::string::npos);
  EXPECT_NE(message({{0, 1, 2, 99}}).find("out of range"), std::string::npos);
}

// --- The spec's two-block problem ---------------------------------------------------------------

TEST(SurfaceTwoBlock, ContactFacesPointAtEachOther) {
  model::Model m;
  const scenarios::TwoBlockIds ids = scenarios::add_solid_pair(m, {});
  auto sim = build_simulation(m);
  const std::vector<Id> lower{ids.lower_part}, upper{ids.upper_part};
  const Surface ls = build_surface_from_parts(sim->blocks(), sim->nodes(), lower, "lower");
  const Surface us = build_surface_from_parts(sim->blocks(), sim->nodes(), upper, "upper");
  // Lower block: 3 x 2 x 2 elements; upper: 3 x 2 x 3.
  EXPECT_EQ(ls.segment_count(), 2 * (3 * 2 + 2 * 2 + 3 * 2));
  EXPECT_EQ(us.segment_count(), 2 * (3 * 2 + 2 * 3 + 3 * 3));
  EXPECT_EQ(count_outward(*sim, ls), ls.segment_count());
  EXPECT_EQ(count_outward(*sim, us), us.segment_count());
  int lower_top = 0, upper_bottom = 0;
  for (Index s = 0; s < ls.segment_count(); ++s)
    if (std::abs(segment_centroid(ls, s, sim->nodes().x0)[1] - 1.0) < 1e-12) {
      ++lower_top;
      EXPECT_NEAR((segment_normal(ls, s, sim->nodes().x0) - Vec3(0, 1, 0)).norm(), 0.0, 1e-14);
    }
  for (Index s = 0; s < us.segment_count(); ++s)
    if (std::abs(segment_centroid(us, s, sim->nodes().x0)[1] - 1.0) < 1e-12) {
      ++upper_bottom;
      EXPECT_NEAR((segment_normal(us, s, sim->nodes().x0) - Vec3(0, -1, 0)).norm(), 0.0, 1e-14);
    }
  EXPECT_EQ(lower_top, 3 * 2);
  EXPECT_EQ(upper_bottom, 3 * 3);
}
