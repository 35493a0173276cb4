// The plastic work of the history channel parts/<id>/plastic_work (ElementBlock::plasticity_totals)
// is the work of the stress on the plastic strain at the volume each increment was done in
// (j2_return.hpp: the law sums J sigma : d eps_p per unit reference volume), not the sum of the
// density increments times the volume at output time.
//
// Closed form: perfect plasticity (ETAN = 0), a homogeneous path in three legs on the distorted
// 8-cell patch (its cells' volumes sum to V0 = 1):
//   1. pure compression to J1 = V/V0 = 0.95 (no deviator: elastic);
//   2. at J1, the isochoric stretch diag(lambda, lambda^-1/2, lambda^-1/2) to lambda_end: the
//      deviatoric strain's von Mises measure is ln lambda, the trial stress 3 G ln lambda; yield at
//      ln lambda = sigma_y / (3 G), then sigma_vm = sigma_y and eps_p = ln lambda_end - sigma_y / (3 G)
//      (radial return is exact on this proportional path);
//   3. pure expansion back to J = 1 (the deviator stays put: no flow).
// The plastic work sigma : D_p integrated over the current volume is done entirely in leg 2 at
// V = J1 V0: W_p = sigma_y eps_p J1 V0. The channel as it was (density sum times the volume at
// output, here V0) gave sigma_y eps_p V0, 5 % (1 - J1) above.
#include <gtest/gtest.h>

#include <cmath>

#include "slideline/element/full_hex_block.hpp"
#include "slideline/element/hex_block.hpp"
#include "slideline/material/j2_plasticity.hpp"
#include "test_support/block_eval.hpp"
#include "test_support/patch_mesh.hpp"

using namespace slideline;

namespace {

constexpr Real kE = 2.0e5, kNu = 0.3, kSy = 250.0;
constexpr Real kJ1 = 0.95, kLambdaEnd = 1.02;

/// Drives `block` through the three legs (steps of log strain increments, so that the law's
/// sum of D dt is the log strain exactly) and returns its plastic work total.
Real plastic_work_after_path(ElementBlock& block, NodalFields& nodes, CornerBuffer& corners, Real rotation_angle) {
  const Eigen::Matrix3d rot = Eigen::AngleAxisd(rotation_angle, Vec3(1.0, 2.0, 3.0).normalized()).toRotationMatrix();
  const Real dt = 1e-3;
  // F(J, lambda) = J^(1/3) rot diag(lambda, lambda^-1/2, lambda^-1/2) rot^T.
  auto F = [&](Real j, Real lambda) {
    const Vec3 d(lambda, 1.0 / std::sqrt(lambda), 1.0 / std::sqrt(lambda));
    return Eigen::Matrix3d(std::cbrt(j) * rot * d.asDiagonal() * rot.transpose());
  };
  Real j = 1.0, lambda = 1.0;
  auto step_to = [&](Real j_new, Real lambda_new) {
    // The rate of deformation whose dt step is the log strain increment from (j, lambda).
    const Real vol = std::log(j_new / j) / 3.0, dev = std::log(lambda_new / lambda);
    const Vec3 d(vol + dev, vol - 0.5 * dev, vol - 0.5 * dev);
    const Eigen::Matrix3d D = rot * (d / dt).asDiagonal() * rot.transpose();
    const Eigen::Matrix3d f = F(j_new, lambda_new);
    for (Index i = 0; i < static_cast<Index>(nodes.size()); ++i) {
      const Vec3 x = f * nodes.x0.get(i);
      nodes.x.set(i, x);
      nodes.v.set(i, D * x);
    }
    BlockEnergy e;
    block.compute_forces(nodes, dt, corners, e);
    j = j_new;
    lambda = lambda_new;
  };
  const int n = 40;
  for (int s = 1; s <= n; ++s) step_to(1.0 + (kJ1 - 1.0) * s / n, 1.0);
  for (int s = 1; s <= n; ++s) step_to(kJ1, std::exp(std::log(kLambdaEnd) * s / n));
  for (int s = 1; s <= n; ++s) step_to(kJ1 + (1.0 - kJ1) * s / n, kLambdaEnd);
  return block.plasticity_totals(nodes).plastic_work;
}

Real closed_form() {
  const Real g = kE / (2.0 * (1.0 + kNu));
  const Real eps_p = std::log(kLambdaEnd) - kSy / (3.0 * g);
  return kSy * eps_p * kJ1 * 1.0;  // V0 = 1
}

J2Plasticity perfectly_plastic() { return J2Plasticity({7.8, kE, kNu, kSy, 0.0, 1.0, 0.0, 0.0}); }

}  // namespace

TEST(PlasticWorkVolume, OnePointHexahedraBookEachIncrementAtItsVolume) {
  for (const Real angle : {0.0, 0.7}) {
    const test_support::PatchMesh p = test_support::make_patch_mesh();
    HexBlock<J2Plasticity> block(1, perfectly_plastic(), HexHourglass{}, BulkViscosity{0.0, 0.0}, p.conn, p.ids);
    NodalFields nodes = p.nodes;
    CornerBuffer corners;
    test_support::prepare(block, nodes, corners);
    const Real w = plastic_work_after_path(block, nodes, corners, angle);
    ASSERT_GT(closed_form(), 0.0);
    EXPECT_NEAR(w, closed_form(), 1e-9 * closed_form()) << "rotation " << angle;
  }
}

TEST(PlasticWorkVolume, FullyIntegratedHexahedraBookEachIncrementAtItsVolume) {
  for (const Real angle : {0.0, 0.7}) {
    const test_support::PatchMesh p = test_support::make_patch_mesh();
    FullHexBlock<J2Plasticity> block(1, perfectly_plastic(), BulkViscosity{0.0, 0.0}, p.conn, p.ids);
    NodalFields nodes = p.nodes;
    CornerBuffer corners;
    test_support::prepare(block, nodes, corners);
    const Real w = plastic_work_after_path(block, nodes, corners, angle);
    EXPECT_NEAR(w, closed_form(), 1e-9 * closed_form()) << "rotation " << angle;
  }
}
