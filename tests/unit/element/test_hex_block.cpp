#include <gtest/gtest.h>

#include <array>
#include <numbers>

#include <Eigen/Geometry>

#include "slideline/element/hex_block.hpp"
#include "slideline/material/elastic.hpp"
#include "slideline/material/mooney_rivlin.hpp"
#include "test_support/block_eval.hpp"
#include "test_support/hex_fixtures.hpp"
#include "test_support/patch_mesh.hpp"

using namespace slideline;

namespace {

using test_support::make_patch_mesh;
using test_support::PatchMesh;

template <class Mat>
HexBlock<Mat> make_block(const PatchMesh& p, Mat mat, HexHourglass::Kind hk) {
  return HexBlock<Mat>(1, mat, HexHourglass{hk, hk == HexHourglass::Kind::viscous ? 0.1 : 1.0},
                       BulkViscosity{}, p.conn, p.ids);
}

}  // namespace

class HexBlockRigidMotion : public ::testing::TestWithParam<HexHourglass::Kind> {};

TEST_P(HexBlockRigidMotion, GivesZeroInternalForce) {
  PatchMesh p = make_patch_mesh();
  auto block = make_block(p, MooneyRivlin(0.01, 909.091, 0.0, 0.1), GetParam());
  CornerBuffer corners;
  test_support::prepare(block, p.nodes, corners);
  // A large rotation plus translation, applied to positions; velocities of the same rigid motion.
  const Mat3 R = Eigen::AngleAxis<Real>(1.1, Vec3(1, 2, -0.5).normalized()).toRotationMatrix();
  const Vec3 w(0.3, -1.2, 0.7), v0(2.0, -1.0, 0.5);
  for (Index i = 0; i < 27; ++i) {
    const Vec3 x = R * p.nodes.x0.get(i) + Vec3(3.0, -2.0, 1.0);
    p.nodes.x.set(i, x);
    p.nodes.v.set(i, v0 + w.cross(x));
  }
  test_support::evaluate(block, p.nodes, corners);
  Real fmax = 0.0;
  for (Index i = 0; i < 27; ++i) fmax = std::max(fmax, p.nodes.f_int.get(i).norm());
  EXPECT_LT(fmax, 1e-10);
}

INSTANTIATE_TEST_SUITE_P(BothHourglassForms, HexBlockRigidMotion,
                         ::testing::Values(HexHourglass::Kind::viscous,
                                           HexHourglass::Kind::physical_stiffness),
                         [](const auto& info) {
                           return std::string(info.param == HexHourglass::Kind::viscous ? "viscous"
                                                                                        : "physical_stiffness");
                         });

TEST(HexBlockPatch, ConstantStrainOnDistortedMeshGivesUniformStressAndInteriorEquilibrium) {
  PatchMesh p = make_patch_mesh();
  const ElasticSolid mat(1.0, 1000.0, 0.3);
  auto block = make_block(p, mat, HexHourglass::Kind::physical_stiffness);
  CornerBuffer corners;
  test_support::prepare(block, p.nodes, corners);
  Mat3 F;
  F << 1.02, 0.01, -0.005, 0.003, 0.985, 0.01, 0.0, 0.004, 1.01;
  for (Index i = 0; i < 27; ++i) p.nodes.x.set(i, F * p.nodes.x0.get(i));
  test_support::evaluate(block, p.nodes, corners);
  // The interior node is shared by all 8 elements: its force vanishes only if every element has
  // the same stress and the gradient operator is the exact volume average.
  for (int n : p.interior) EXPECT_LT(p.nodes.f_int.get(n).norm(), 1e-10);
  // Total force on the x = max face equals the traction sigma . n times the deformed face area.
  const Mat3 sigma = mat.cauchy_stress(F);
  Vec3 face = Vec3::Zero();
  for (Index i = 0; i < 27; ++i)
    if (std::abs(p.nodes.x0.x[i] - 1.0) < 1e-12) face += p.nodes.f_int.get(i);
  const Vec3 area_vec = F.determinant() * F.inverse().transpose() * Vec3(1, 0, 0);  // Nanson
  const Vec3 expected = -(sigma * area_vec);  // residual form: the element pulls the face inward
  EXPECT_LT((face - expected).norm(), 1e-10 * expected.norm() + 1e-12);
}

TEST(HexBlockUniaxial, OneElementForcesMatchMooneyRivlinClosedForm) {
  // One element stretched to lambda = 1.8 in x with the lateral stretch of uniaxial stress: the
  // x-face force must equal sigma_11 times the current face area, and the lateral faces carry none.
  // (A nearly incompressible rubber: with nu = 0.1 DYNA3D's form has no uniaxial state at 1.8.)
  const MooneyRivlin mat(1.0, 300.0, 120.0, 0.45);
  NodalFields nodes;
  nodes.resize(8);
  const hex8::NodeMat X = test_support::unit_hex();
  // lateral stretch from the material itself (sigma_22 = 0), found by bisection
  const Real l1 = 1.8;
  Real lo = 0.5, hi = 1.0;
  ASSERT_LT(mat.cauchy_stress(Vec3(l1, lo, lo).asDiagonal())(1, 1), 0.0);
  ASSERT_GT(mat.cauchy_stress(Vec3(l1, hi, hi).asDiagonal())(1, 1), 0.0);
  for (int it = 0; it < 200; ++it) {
    const Real mid = 0.5 * (lo + hi);
    (mat.cauchy_stress(Vec3(l1, mid, mid).asDiagonal())(1, 1) > 0 ? hi : lo) = mid;
  }
  const Real l2 = 0.5 * (lo + hi);
  for (int i = 0; i < 8; ++i) {
    nodes.ids[i] = i + 1;
    nodes.x0.set(i, X.row(i).transpose());
    nodes.x.set(i, Vec3(l1 * X(i, 0), l2 * X(i, 1), l2 * X(i, 2)));
  }
  HexBlock<MooneyRivlin> block(1, mat, {HexHourglass::Kind::physical_stiffness, 1.0}, {},
                               {0, 1, 2, 3, 4, 5, 6, 7}, {1});
  CornerBuffer corners;
  test_support::prepare(block, nodes, corners);
  test_support::evaluate(block, nodes, corners);
  const Real s11 = mat.cauchy_stress(Vec3(l1, l2, l2).asDiagonal())(0, 0);
  Real fx = 0.0, fy = 0.0;
  for (int i = 0; i < 8; ++i) {
    if (X(i, 0) == 1.0) fx += nodes.f_int.x[i];
    if (X(i, 1) == 1.0) fy += nodes.f_int.y[i];
  }
  EXPECT_GT(s11, 0.0);
  EXPECT_NEAR(-fx, s11 * l2 * l2, 1e-9 * s11);
  EXPECT_NEAR(fy, 0.0, 1e-6 * s11);
}

TEST(HexBlockTimeStep, EqualsEdgeOverWaveSpeedForCubeAtRest) {
  const ElasticSolid mat(7.8e-3, 2.0e5, 0.3);
  NodalFields nodes;
  nodes.resize(8);
  const hex8::NodeMat X = test_support::unit_hex() * 0.25;
  for (int i = 0; i < 8; ++i) {
    nodes.x0.set(i, X.row(i).transpose());
    nodes.x.set(i, X.row(i).transpose());
  }
  HexBlock<ElasticSolid> block(1, mat, {}, {}, {0, 1, 2, 3, 4, 5, 6, 7}, {1});
  CornerBuffer corners;
  test_support::prepare(block, nodes, corners);
  const Real dt = test_support::evaluate(block, nodes, corners);
  const Real c = std::sqrt(2.0e5 * 0.7 / (1.3 * 0.4) / 7.8e-3);  // sqrt((lambda + 2 mu) / rho)
  EXPECT_NEAR(dt, 0.25 / c, 1e-12);
  Real m = 0;
  for (int i = 0; i < 8; ++i) m += nodes.mass[i];
  EXPECT_NEAR(m, 7.8e-3 * 0.25 * 0.25 * 0.25, 1e-15);
}

namespace {

/// One element [-a, a] x [-b, b] x [-c, c] about `centre`, turned by R, in a block with hourglass
/// `hg`; u(p) (local coordinates p about the centre, local components) is applied as R u(R^T p).
/// Returns the work -sum f . u of the resulting nodal forces (= 2 U for a linear response). The
/// stiffness hourglass forms integrate rates, so u is reached in one step of velocity u / dt.
template <class Field>
Real element_work(HexHourglass hg, const ElasticSolid& mat, Vec3 half, const Mat3& R, Field u_local) {
  NodalFields nodes;
  nodes.resize(8);
  const hex8::NodeMat X = test_support::unit_hex();
  const Vec3 centre(0.3, -0.2, 0.7);
  std::array<Vec3, 8> u;
  for (int i = 0; i < 8; ++i) {
    const Vec3 p((2.0 * X(i, 0) - 1.0) * half[0], (2.0 * X(i, 1) - 1.0) * half[1], (2.0 * X(i, 2) - 1.0) * half[2]);
    u[i] = R * u_local(p);
    nodes.ids[i] = i + 1;
    nodes.x0.set(i, centre + R * p);
    nodes.x.set(i, centre + R * p + u[i]);
  }
  const Real dt = 1e-3;
  if (hg.kind != HexHourglass::Kind::viscous)
    for (int i = 0; i < 8; ++i) nodes.v.set(i, u[i] / dt);
  HexBlock<ElasticSolid> block(1, mat, hg, {}, {0, 1, 2, 3, 4, 5, 6, 7}, {1});
  CornerBuffer corners;
  test_support::prepare(block, nodes, corners);
  BlockEnergy en;
  block.compute_forces(nodes, dt, corners, en);
  corners.gather(nodes.f_int, nodes.m_int);
  Real w = 0.0;
  for (int i = 0; i < 8; ++i) w -= nodes.f_int.get(i).dot(u[i]);
  return w;
}

}  // namespace

// Assumed-strain hourglass (IHQ 6, QM = 1) on a rectangular 2a x 2b x 2c element, straight and
// turned by a large rotation: pure bending u_x = k x y (in the element's axes) stores the
// Euler-Bernoulli energy U = E k^2 I_z (2a) / 2 = E k^2 V b^2 / 6 (uniaxial stress, no parasitic
// shear: the one-point part sees no mean strain), and the plate twist u = k (-y z, -x z, x y)
// stores U = mu k^2 V (2c)^2 / 6 (gamma_xy = -2 k z, every other strain zero). The viscous form
// has no stiffness at all.
TEST(HexBlockAssumedStrain, RectangularElementBendingAndTwistMatchTheClosedFormEnergies) {
  const Real e = 1000.0, nu = 0.3, mu = e / (2.0 * (1.0 + nu)), k = 1e-5;
  const ElasticSolid mat(1.0, e, nu);
  const Vec3 half(1.0, 0.25, 0.5);
  const Real vol = 8.0 * half.prod();
  const auto bend = [&](const Vec3& p) { return Vec3(k * p[0] * p[1], 0.0, 0.0); };
  const auto twist = [&](const Vec3& p) { return Vec3(-k * p[1] * p[2], -k * p[0] * p[2], k * p[0] * p[1]); };
  const Real u_bend = e * k * k * vol * half[1] * half[1] / 6.0;
  const Real u_twist = mu * k * k * vol * 4.0 * half[2] * half[2] / 6.0;
  const HexHourglass as{HexHourglass::Kind::assumed_strain, 1.0};
  for (const Mat3& R : {Mat3(Mat3::Identity()),
                        Mat3(Eigen::AngleAxis<Real>(0.9, Vec3(1, -2, 0.5).normalized()).toRotationMatrix())}) {
    EXPECT_NEAR(element_work(as, mat, half, R, bend), 2.0 * u_bend, 1e-6 * u_bend);
    EXPECT_NEAR(element_work(as, mat, half, R, twist), 2.0 * u_twist, 1e-6 * u_twist);
    EXPECT_NEAR(element_work({HexHourglass::Kind::viscous, 0.1}, mat, half, R, bend), 0.0, 1e-6 * u_bend);
  }
  // QM scales the stiffness: the default 0.1 stores a tenth.
  EXPECT_NEAR(element_work({HexHourglass::Kind::assumed_strain, 0.1}, mat, half, Mat3::Identity(), bend),
              0.2 * u_bend, 1e-6 * u_bend);
}

// Flanagan-Belytschko stiffness (IHQ 4/5): a unit cube given the hourglass velocity v_x = s Gamma_3
// (the xi eta mode) gets generalised force Q = dt k qdot with qdot = 8 s (gamma = Gamma on a
// rectangular element), k = QM (lambda + 2 mu) V |B|^2 / 72, |B|^2 = 3 / (2 h^2); the nodal forces
// are f_I = -Q Gamma_I, and a second step with the same velocity doubles them (the forces are
// integrated, not recomputed from the rate).
TEST(HexBlockFlanaganBelytschkoStiffness, HourglassVelocityIntegratesToTheClosedFormForce) {
  const Real e = 1000.0, nu = 0.3, s = 0.02, dt = 1e-3, qm = 0.1;
  const ElasticSolid mat(1.0, e, nu);
  NodalFields nodes;
  nodes.resize(8);
  const hex8::NodeMat X = test_support::unit_hex();
  for (int i = 0; i < 8; ++i) {
    nodes.ids[i] = i + 1;
    nodes.x0.set(i, X.row(i).transpose());
    nodes.x.set(i, X.row(i).transpose());
    nodes.v.set(i, Vec3(s * hex8::hourglass_signs[2][i], 0.0, 0.0));
  }
  HexBlock<ElasticSolid> block(1, mat, {HexHourglass::Kind::fb_stiffness, qm}, {}, {0, 1, 2, 3, 4, 5, 6, 7}, {1});
  CornerBuffer corners;
  test_support::prepare(block, nodes, corners);
  const Real lambda2mu = e * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));
  const Real q = dt * qm * lambda2mu * 1.5 / 72.0 * 8.0 * s;
  for (int step = 1; step <= 2; ++step) {
    BlockEnergy en;
    block.compute_forces(nodes, dt, corners, en);
    nodes.f_int.fill(0.0);
    corners.gather(nodes.f_int, nodes.m_int);
    for (int i = 0; i < 8; ++i) {
      EXPECT_NEAR(nodes.f_int.x[i], -step * q * hex8::hourglass_signs[2][i], 1e-12 * q);
      EXPECT_NEAR(nodes.f_int.y[i], 0.0, 1e-12 * q);
      EXPECT_NEAR(nodes.f_int.z[i], 0.0, 1e-12 * q);
    }
  }
}

// The stiffness forms on the distorted 2x2x2 patch: a rigid motion (large rotation, spin) and a
// uniform strain with a linear velocity field give no hourglass force, so every interior node is
// in equilibrium and the rigid mesh has no force at all (patch test of the hourglass part).
TEST(HexBlockStiffnessHourglass, RigidMotionAndUniformStrainGiveNoHourglassForce) {
  for (auto kind : {HexHourglass::Kind::fb_stiffness, HexHourglass::Kind::assumed_strain}) {
    PatchMesh p = make_patch_mesh();
    const ElasticSolid mat(1.0, 1000.0, 0.3);
    HexBlock<ElasticSolid> block(1, mat, {kind, 1.0}, {}, p.conn, p.ids);
    CornerBuffer corners;
    test_support::prepare(block, p.nodes, corners);
    const Mat3 R = Eigen::AngleAxis<Real>(1.1, Vec3(1, 2, -0.5).normalized()).toRotationMatrix();
    Mat3 L;
    L << 0.3, -0.1, 0.2, 0.05, -0.2, 0.1, 0.0, 0.15, 0.25;
    for (Index i = 0; i < 27; ++i) {
      const Vec3 x = R * p.nodes.x0.get(i) + Vec3(3.0, -2.0, 1.0);
      p.nodes.x.set(i, x);
      p.nodes.v.set(i, Vec3(2.0, -1.0, 0.5) + Vec3(0.3, -1.2, 0.7).cross(x));
    }
    BlockEnergy en;
    for (int step = 0; step < 3; ++step) block.compute_forces(p.nodes, 1e-3, corners, en);
    p.nodes.f_int.fill(0.0);
    corners.gather(p.nodes.f_int, p.nodes.m_int);
    Real fmax = 0.0;
    for (Index i = 0; i < 27; ++i) fmax = std::max(fmax, p.nodes.f_int.get(i).norm());
    EXPECT_LT(fmax, 1e-10);
    Mat3 F;
    F << 1.02, 0.01, -0.005, 0.003, 0.985, 0.01, 0.0, 0.004, 1.01;
    for (Index i = 0; i < 27; ++i) {
      p.nodes.x.set(i, F * p.nodes.x0.get(i));
      p.nodes.v.set(i, L * p.nodes.x.get(i));
    }
    for (int step = 0; step < 3; ++step) block.compute_forces(p.nodes, 1e-3, corners, en);
    p.nodes.f_int.fill(0.0);
    corners.gather(p.nodes.f_int, p.nodes.m_int);
    for (int n : p.interior) EXPECT_LT(p.nodes.f_int.get(n).norm(), 1e-10);
  }
}

// Objectivity of the stiffness forms (IHQ 4 and 6): a 2 x 0.5 x 1 element is bent through its
// hourglass mode (u_x = k x y, in ten steps of velocity du / dt), then turned rigidly by 90 degrees
// about a skew axis in 200 steps, each step's velocity the chord (x_n+1 - x_n) / dt. The rates
// of a rigid turn have no hourglass part, so the stored forces must turn with the element:
// f_after = R f_before to round-off. Forces kept in global components would stay where they were
// (an error of the order of |f| itself).
TEST(HexBlockStiffnessHourglass, ForcesTurnWithTheElementUnderARigidRotation) {
  for (auto kind : {HexHourglass::Kind::fb_stiffness, HexHourglass::Kind::assumed_strain}) {
    const ElasticSolid mat(1.0, 1000.0, 0.3);
    const hex8::NodeMat X = test_support::unit_hex();
    const Vec3 half(1.0, 0.25, 0.5), centre(0.3, -0.2, 0.7);
    const Real k = 1e-3, dt = 1e-3;
    NodalFields nodes;
    nodes.resize(8);
    std::array<Vec3, 8> p;
    for (int i = 0; i < 8; ++i) {
      p[i] = Vec3((2.0 * X(i, 0) - 1.0) * half[0], (2.0 * X(i, 1) - 1.0) * half[1], (2.0 * X(i, 2) - 1.0) * half[2]);
      nodes.ids[i] = i + 1;
      nodes.x0.set(i, centre + p[i]);
      nodes.x.set(i, centre + p[i]);
    }
    HexBlock<ElasticSolid> block(1, mat, {kind, 1.0}, {}, {0, 1, 2, 3, 4, 5, 6, 7}, {1});
    CornerBuffer corners;
    test_support::prepare(block, nodes, corners);
    BlockEnergy en;
    const auto step_to = [&](auto&& position) {
      for (int i = 0; i < 8; ++i) {
        const Vec3 x = position(i);
        nodes.v.set(i, (x - nodes.x.get(i)) / dt);
        nodes.x.set(i, x);
      }
      block.compute_forces(nodes, dt, corners, en);
    };
    for (int n = 1; n <= 10; ++n)
      step_to([&](int i) -> Vec3 { return centre + p[i] + Vec3(0.1 * n * k * p[i][0] * p[i][1], 0.0, 0.0); });
    nodes.f_int.fill(0.0);
    corners.gather(nodes.f_int, nodes.m_int);
    std::array<Vec3, 8> f0, bent;
    Real fmax = 0.0;
    for (int i = 0; i < 8; ++i) {
      f0[i] = nodes.f_int.get(i);
      bent[i] = nodes.x.get(i) - centre;
      fmax = std::max(fmax, f0[i].norm());
    }
    ASSERT_GT(fmax, 1e-6) << "no hourglass force after the bend";
    const Vec3 axis = Vec3(1.0, -2.0, 0.5).normalized();
    const auto turn = [&](Real angle) { return Mat3(Eigen::AngleAxis<Real>(angle, axis).toRotationMatrix()); };
    for (int n = 1; n <= 200; ++n) {
      const Mat3 R = turn(0.5 * std::numbers::pi * n / 200.0);
      step_to([&](int i) -> Vec3 { return centre + R * bent[i]; });
    }
    nodes.f_int.fill(0.0);
    corners.gather(nodes.f_int, nodes.m_int);
    const Mat3 R = turn(0.5 * std::numbers::pi);
    for (int i = 0; i < 8; ++i) EXPECT_LT((nodes.f_int.get(i) - R * f0[i]).norm(), 1e-9 * fmax) << "node " << i;
  }
}
