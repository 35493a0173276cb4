// The fully integrated selective-reduced hexahedron (FullHexBlock, *SECTION_SOLID ELFORM 2):
// rigid motion, the constant-strain patch test on a distorted mesh, no hourglass modes, the
// mean-dilatation pressure, and the same laws as the one-point hexahedron.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "slideline/element/full_hex_block.hpp"
#include "slideline/element/hex_block.hpp"
#include "slideline/material/elastic.hpp"
#include "slideline/material/j2_plasticity.hpp"
#include "slideline/material/mooney_rivlin.hpp"
#include "test_support/block_eval.hpp"
#include "test_support/hex_fixtures.hpp"
#include "test_support/patch_mesh.hpp"

using namespace slideline;

namespace {

template <class Mat>
FullHexBlock<Mat> make_block(const test_support::PatchMesh& p, Mat mat) {
  return FullHexBlock<Mat>(1, mat, BulkViscosity{}, p.conn, p.ids);
}

/// One element's nodal forces (24, residual form) at nodal displacements u from `X`.
Eigen::Matrix<Real, 24, 1> forces(FullHexBlock<ElasticSolid>& block, NodalFields& nodes, CornerBuffer& corners,
                                  const hex8::NodeMat& X, const Eigen::Matrix<Real, 24, 1>& u) {
  for (Index k = 0; k < 8; ++k) nodes.x.set(k, X.row(k).transpose() + u.segment<3>(3 * k));
  test_support::evaluate(block, nodes, corners);
  Eigen::Matrix<Real, 24, 1> f;
  for (Index k = 0; k < 8; ++k) f.segment<3>(3 * k) = nodes.f_int.get(k);
  return f;
}

}  // namespace

TEST(FullHexBlock, RigidMotionGivesZeroInternalForce) {
  test_support::PatchMesh p = test_support::make_patch_mesh();
  auto block = make_block(p, MooneyRivlin(0.01, 909.091, 0.0, 0.1));
  CornerBuffer corners;
  test_support::prepare(block, p.nodes, corners);
  const Mat3 R = Eigen::AngleAxis<Real>(1.1, Vec3(1, 2, -0.5).normalized()).toRotationMatrix();
  const Vec3 w(0.3, -1.2, 0.7), v0(2.0, -1.0, 0.5);
  for (Index i = 0; i < 27; ++i) {
    const Vec3 x = R * p.nodes.x0.get(i) + Vec3(3.0, -2.0, 1.0);
    p.nodes.x.set(i, x);
    p.nodes.v.set(i, v0 + w.cross(x));
  }
  test_support::evaluate(block, p.nodes, corners);
  for (Index i = 0; i < 27; ++i) EXPECT_LT(p.nodes.f_int.get(i).norm(), 1e-10) << "node " << i;
}

TEST(FullHexBlock, ConstantStrainOnDistortedMeshGivesUniformStressAndInteriorEquilibrium) {
  test_support::PatchMesh p = test_support::make_patch_mesh();
  const ElasticSolid mat(1.0, 1000.0, 0.3);
  auto block = make_block(p, mat);
  CornerBuffer corners;
  test_support::prepare(block, p.nodes, corners);
  Mat3 F;
  F << 1.02, 0.01, -0.005, 0.003, 0.985, 0.01, 0.0, 0.004, 1.01;
  for (Index i = 0; i < 27; ++i) p.nodes.x.set(i, F * p.nodes.x0.get(i));
  test_support::evaluate(block, p.nodes, corners);
  for (int n : p.interior) EXPECT_LT(p.nodes.f_int.get(n).norm(), 1e-12);
  const Mat3 sigma = mat.cauchy_stress(F);
  std::vector<CellOutput> out(p.ids.size());
  block.cell_outputs(p.nodes, out);
  for (const CellOutput& c : out) {
    EXPECT_NEAR(c.stress[0], sigma(0, 0), 1e-11 * sigma.norm());
    EXPECT_NEAR(c.stress[5], sigma(0, 2), 1e-11 * sigma.norm());
  }
  Vec3 face = Vec3::Zero();
  for (Index i = 0; i < 27; ++i)
    if (std::abs(p.nodes.x0.x[i] - 1.0) < 1e-12) face += p.nodes.f_int.get(i);
  const Vec3 expected = -(sigma * (F.determinant() * F.inverse().transpose() * Vec3(1, 0, 0)));
  EXPECT_LT((face - expected).norm(), 1e-12 * expected.norm());
}

// The tangent stiffness of one distorted element (central differences of the forces) has exactly
// the six rigid-body zero eigenvalues: no hourglass (zero-energy) mode, so no hourglass control.
// Its volumetric part has rank one (one pressure per element): at nu -> 0.5 the bulk modulus
// grows but only one eigenvalue follows it, the others stay of the order of the shear modulus.
TEST(FullHexBlock, StiffnessHasOnlyRigidZeroModesAndOneVolumetricMode) {
  const hex8::NodeMat X = test_support::distorted_hex();
  for (const Real nu : {0.3, 0.4999}) {
    const ElasticSolid mat(1.0, 1000.0, nu);
    FullHexBlock<ElasticSolid> block(1, mat, BulkViscosity{0.0, 0.0}, {0, 1, 2, 3, 4, 5, 6, 7}, {1});
    NodalFields nodes;
    nodes.resize(8);
    for (Index k = 0; k < 8; ++k) {
      nodes.x0.set(k, X.row(k).transpose());
      nodes.x.set(k, X.row(k).transpose());
    }
    CornerBuffer corners;
    test_support::prepare(block, nodes, corners);
    Eigen::Matrix<Real, 24, 24> K;
    const Real h = 1e-6;
    for (int j = 0; j < 24; ++j) {
      Eigen::Matrix<Real, 24, 1> u = Eigen::Matrix<Real, 24, 1>::Zero();
      u[j] = h;
      const auto fp = forces(block, nodes, corners, X, u);
      u[j] = -h;
      K.col(j) = -(fp - forces(block, nodes, corners, X, u)) / (2.0 * h);
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<Real, 24, 24>> es(0.5 * (K + K.transpose()));
    const auto& ev = es.eigenvalues();  // ascending
    const Real g = mat.shear_modulus();
    for (int i = 0; i < 6; ++i) EXPECT_LT(std::abs(ev[i]), 1e-6 * g) << "nu " << nu << " mode " << i;
    EXPECT_GT(ev[6], 1e-2 * g) << "nu " << nu << ": a seventh zero-energy mode";
    if (nu > 0.49) {
      EXPECT_LT(ev[22], 10.0 * g) << "more than one mode follows the bulk modulus";
    }
    EXPECT_GT(ev[23], 0.5 * mat.bulk_modulus()) << "nu " << nu;
  }
}

// J2 plasticity's history totals (ElementBlock::plasticity_totals) under a homogeneous stretch to 3x
// the yield strain on the distorted patch: every Gauss point carries the one-point hexahedron's
// state, so the largest plastic strain and the plastic work (the Gauss points' detJ sum against the
// one-point elements' volumes) agree.
TEST(FullHexBlock, PlasticityTotalsMatchTheOnePointHexahedron) {
  const test_support::PatchMesh p = test_support::make_patch_mesh();
  const J2Plasticity law({7.8, 2.0e5, 0.3, 250.0, 1.0e3, 1.0, 0.0, 0.0});
  FullHexBlock<J2Plasticity> full(1, law, BulkViscosity{0.0, 0.0}, p.conn, p.ids);
  HexBlock<J2Plasticity> one(2, law, HexHourglass{}, BulkViscosity{0.0, 0.0}, p.conn, p.ids);
  NodalFields a = p.nodes, b = p.nodes;
  CornerBuffer ca, cb;
  test_support::prepare(full, a, ca);
  test_support::prepare(one, b, cb);
  const Real dt = 1e-3, rate = 3.0 * 250.0 / 2.0e5 / (30 * dt);
  for (int s = 1; s <= 30; ++s) {
    const Real l = 1.0 + rate * dt * s, lat = 1.0 - 0.5 * rate * dt * s;
    const Vec3 stretch(l, lat, lat), vel(rate, -0.5 * rate, -0.5 * rate);
    for (NodalFields* n : {&a, &b})
      for (Index i = 0; i < 27; ++i) {
        n->x.set(i, stretch.cwiseProduct(n->x0.get(i)));
        n->v.set(i, vel.cwiseProduct(n->x0.get(i)));
      }
    BlockEnergy e;
    full.compute_forces(a, dt, ca, e);
    one.compute_forces(b, dt, cb, e);
  }
  ASSERT_TRUE(full.has_plasticity());
  ASSERT_FALSE(make_block(p, ElasticSolid(1.0, 1000.0, 0.3)).has_plasticity());
  const PlasticityTotals tf = full.plasticity_totals(a), to = one.plasticity_totals(b);
  EXPECT_GT(to.max_plastic_strain, 1e-3);
  EXPECT_NEAR(tf.max_plastic_strain, to.max_plastic_strain, 1e-12);
  EXPECT_GT(to.plastic_work, 0.0);
  EXPECT_NEAR(tf.plastic_work, to.plastic_work, 1e-9 * to.plastic_work);
}
