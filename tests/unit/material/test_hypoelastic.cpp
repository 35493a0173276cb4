// The toy hypoelastic law added through the registry (issue 19's guide check).
#include <gtest/gtest.h>

#include "slideline/element/block_factory.hpp"
#include "slideline/element/hex_block.hpp"
#include "slideline/solver/material_registry.hpp"
#include "test_support/block_eval.hpp"
#include "test_support/hex_fixtures.hpp"

using namespace slideline;

static_assert(SolidMaterial<Hypoelastic>);

// A unit cube stretched at a constant rate in x (uniaxial strain) for n steps: the stress the
// block's state holds is (lambda + 2 mu) eps in x and lambda eps across, eps = rate n dt.
TEST(Hypoelastic, RegistryMapsItAndTheBlockIntegratesItsState) {
  const Real E = 1000.0, nu = 0.25, rate = 1e-2, dt = 1e-3;
  const MaterialLaws laws = material_laws(model::MatHypoelastic{1, 1.0, E, nu, "", {}});
  ASSERT_TRUE(laws.solid);
  EXPECT_FALSE(laws.shell || laws.rigid);
  auto block = make_hex_block(1, *laws.solid, {}, BulkViscosity{0.0, 0.0}, {0, 1, 2, 3, 4, 5, 6, 7}, {1});
  auto* hex = dynamic_cast<HexBlock<Hypoelastic>*>(block.get());
  ASSERT_NE(hex, nullptr);
  NodalFields nodes;
  nodes.resize(8);
  const hex8::NodeMat X = test_support::unit_hex();
  for (int i = 0; i < 8; ++i) {
    nodes.x0.set(i, X.row(i).transpose());
    nodes.x.set(i, X.row(i).transpose());
    nodes.v.set(i, Vec3(rate * X(i, 0), 0.0, 0.0));
  }
  CornerBuffer corners;
  test_support::prepare(*hex, nodes, corners);
  BlockEnergy energy;
  const int n = 10;
  for (int s = 0; s < n; ++s) hex->compute_forces(nodes, dt, corners, energy);
  const Real mu = E / (2.0 * (1.0 + nu)), lambda = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  const Real eps = rate * n * dt;
  const auto& sigma = hex->states()[0].sigma;
  EXPECT_NEAR(sigma[0][0][0], (lambda + 2.0 * mu) * eps, 1e-12);
  EXPECT_NEAR(sigma[1][1][0], lambda * eps, 1e-12);
  EXPECT_NEAR(sigma[2][2][0], lambda * eps, 1e-12);
  EXPECT_NEAR(sigma[0][1][0], 0.0, 1e-12);
}
