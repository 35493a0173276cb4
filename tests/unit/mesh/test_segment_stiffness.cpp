// The per-segment penalty-stiffness inputs against closed forms, and ElementBlock::bulk_modulus.
#include <gtest/gtest.h>

#include <cmath>

#include "slideline/mesh/segment_geometry.hpp"
#include "slideline/mesh/segment_stiffness.hpp"
#include "slideline/mesh/surface_builder.hpp"
#include "slideline/solver/build.hpp"
#include "test_support/mesh_fixtures.hpp"

using namespace slideline;

namespace {
const std::vector<Id> kPart1{1};
}

TEST(SegmentStiffness, UnitCubeOfElasticMaterial) {
  auto sim = build_simulation(test_support::hex_grid_model(1, 1, 1));  // E 1000, nu 0.3
  const Surface surf = build_surface_from_parts(sim->blocks(), sim->nodes(), kPart1, "test");
  const Real k = 1000.0 / (3.0 * (1.0 - 2.0 * 0.3));
  for (Index s = 0; s < surf.segment_count(); ++s) {
    const SegmentStiffnessData d = segment_stiffness_data(surf, s, sim->blocks(), sim->nodes().x);
    EXPECT_NEAR(d.bulk_modulus, k, 1e-12 * k);
    EXPECT_NEAR(d.element_volume, 1.0, 1e-15);
    EXPECT_NEAR(d.face_area, 1.0, 1e-15);
    EXPECT_EQ(d.thickness, 0.0);
    EXPECT_NEAR(d.max_diagonal, std::sqrt(2.0), 1e-15);
  }
}

TEST(SegmentStiffness, UsesTheCoordinatesItIsGiven) {
  SimulationSetup setup = build_setup(test_support::hex_grid_model(1, 1, 1));
  const Surface surf = build_surface_from_parts(setup.blocks, setup.nodes, kPart1, "test");
  for (Real& x : setup.nodes.x.x) x *= 1.2;  // stretch along x
  // Face 0 is z = 0 (1.2 x 1), face 3 is x = 1 (1 x 1).
  const SegmentStiffnessData bottom = segment_stiffness_data(surf, 0, setup.blocks, setup.nodes.x);
  const SegmentStiffnessData side = segment_stiffness_data(surf, 3, setup.blocks, setup.nodes.x);
  EXPECT_NEAR(bottom.element_volume, 1.2, 1e-14);
  EXPECT_NEAR(bottom.face_area, 1.2, 1e-14);
  EXPECT_NEAR(bottom.max_diagonal, std::sqrt(1.0 + 1.44), 1e-14);
  EXPECT_NEAR(side.face_area, 1.0, 1e-14);
  const SegmentStiffnessData ref = segment_stiffness_data(surf, 0, setup.blocks, setup.nodes.x0);
  EXPECT_NEAR(ref.element_volume, 1.0, 1e-15);
}

TEST(SegmentStiffness, MooneyRivlinBulkModulusFromSmallStrainModuli) {
  model::Model m = test_support::hex_grid_model(1, 1, 1);
  m.materials[0] = model::MatMooneyRivlin{1, 0.01, 0.1, 909.091, 0.0, "rubber", {}};  // the spec's
  auto sim = build_simulation(m);
  const Real g = 2.0 * 909.091;
  const Real k = 2.0 * g * (1.0 + 0.1) / (3.0 * (1.0 - 2.0 * 0.1));  // = lambda + 2 G / 3
  EXPECT_NEAR(sim->blocks()[0]->bulk_modulus(), k, 1e-12 * k);
  const Surface surf = build_surface_from_parts(sim->blocks(), sim->nodes(), kPart1, "test");
  EXPECT_NEAR(segment_stiffness_data(surf, 2, sim->blocks(), sim->nodes().x).bulk_modulus, k, 1e-12 * k);
}

TEST(SegmentStiffness, ShellSegment) {
  auto sim = build_simulation(test_support::shell_plate_model());  // t 0.1, E 1000, nu 0.1
  const Surface surf = build_surface_from_parts(sim->blocks(), sim->nodes(), kPart1, "test");
  const SegmentStiffnessData d = segment_stiffness_data(surf, 4, sim->blocks(), sim->nodes().x);
  EXPECT_NEAR(d.bulk_modulus, 1000.0 / (3.0 * 0.8), 1e-12);
  EXPECT_NEAR(d.face_area, 1.0 / 9.0, 1e-15);
  EXPECT_NEAR(d.thickness, 0.1, 1e-15);
  EXPECT_NEAR(d.element_volume, 0.1 / 9.0, 1e-16);
  EXPECT_NEAR(d.max_diagonal, std::sqrt(2.0) / 3.0, 1e-15);
}

TEST(SegmentStiffness, RigidPartUsesItsElasticConstants) {
  model::Model m = test_support::hex_grid_model(1, 1, 1);
  m.materials[0] = model::MatRigid{1, 1.0, 2000.0, 0.25, 0.0, 0, 0, "", {}};
  auto sim = build_simulation(m);
  const Surface surf = build_surface_from_parts(sim->blocks(), sim->nodes(), kPart1, "test");
  const SegmentStiffnessData d = segment_stiffness_data(surf, 0, sim->blocks(), sim->nodes().x);
  EXPECT_NEAR(d.bulk_modulus, 2000.0 / (3.0 * 0.5), 1e-12);
  EXPECT_NEAR(d.element_volume, 1.0, 1e-15);
}
