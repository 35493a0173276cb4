// The strain criteria of *MAT_ADD_EROSION (element/erosion_criteria.hpp; docs/solver.md, "Failure
// and erosion"): the principal logarithmic strains of a deformation gradient against closed forms
// (stretches, simple shear), each threshold's sign rule, and the one-point hexahedron block deleting
// a distorted grid under a homogeneous deformation exactly when the closed-form strain crosses the
// threshold, in the grid's frame and in a rotated copy.
//
// Closed forms. F = R diag(l1, l2, l3) Q^T (R, Q rotations) has F F^T = R diag(l^2) R^T, so the
// principal logarithmic strains are ln l_i. Simple shear F = 1 + g e_x (x) e_y has principal
// stretches g/2 + sqrt(1 + g^2/4) and its inverse (and 1 out of plane): e1 = -e3 = asinh(g/2),
// e2 = 0, so the tensorial shear strain (e1 - e3)/2 = asinh(g/2) (g/2 for small g). For
// diag(L, Lt, Lt) (uniaxial stress, lateral stretch Lt) the effective strain is (2/3)(ln L - ln Lt),
// i.e. (2/3)(1 + nu) ln L where Lt = L^-nu (the small-strain (2/3)(1 + nu) eps_axial), and the
// volumetric strain ln J = ln L + 2 ln Lt.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <functional>

#include "slideline/element/hex_block.hpp"
#include "slideline/material/elastic.hpp"
#include "test_support/block_eval.hpp"

using namespace slideline;

namespace {

Mat3 rotation(Real angle, const Vec3& axis) { return Eigen::AngleAxis<Real>(angle, axis.normalized()).toRotationMatrix(); }

Mat3 stretch(Real a, Real b, Real c) { return Vec3(a, b, c).asDiagonal(); }

Mat3 simple_shear(Real g) {
  Mat3 f = Mat3::Identity();
  f(0, 1) = g;
  return f;
}

}  // namespace

// Principal logarithmic strains of R diag(l) Q^T and of (rotated) simple shear, to round-off.
TEST(ErosionStrain, PrincipalLogStrainsOfStretchesAndShear) {
  const Mat3 R = rotation(0.7, Vec3(1, 2, 3)), Q = rotation(-1.9, Vec3(-2, 0.5, 1));
  for (const auto& l : {std::array<Real, 3>{1.3, 0.8, 1.05}, std::array<Real, 3>{1.2, 1.2, 0.6},
                        std::array<Real, 3>{0.5, 0.5, 0.5}, std::array<Real, 3>{1.0, 1.0, 1.0}}) {
    for (const Mat3& F : {Mat3(stretch(l[0], l[1], l[2])), Mat3(R * stretch(l[0], l[1], l[2]) * Q.transpose())}) {
      const auto e = ErosionCriteria::principal_log_strains(F);
      std::array<Real, 3> x{std::log(l[0]), std::log(l[1]), std::log(l[2])};
      std::sort(x.begin(), x.end(), std::greater<>());
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(e[i], x[i], 1e-14) << l[0] << " " << l[1] << " " << l[2] << " " << i;
    }
  }
  for (Real g : {1e-4, 0.3, 2.0}) {
    const Real a = std::asinh(0.5 * g);
    for (const Mat3& F : {simple_shear(g), Mat3(R * simple_shear(g) * R.transpose()), Mat3(R * simple_shear(g))}) {
      const auto e = ErosionCriteria::principal_log_strains(F);
      EXPECT_NEAR(e[0], a, 1e-13 * (1.0 + a)) << g;
      EXPECT_NEAR(e[1], 0.0, 1e-13) << g;
      EXPECT_NEAR(e[2], -a, 1e-13 * (1.0 + a)) << g;
    }
  }
  // Uniaxial stress with Poisson's ratio nu (Lt = L^-nu): eps_eff = (2/3)(1 + nu) ln L.
  const Real L = 1.25, nu = 0.3, Lt = std::pow(L, -nu);
  const auto e = ErosionCriteria::principal_log_strains(R * stretch(L, Lt, Lt) * Q.transpose());
  EXPECT_NEAR(ErosionCriteria::effective_strain(e), 2.0 / 3.0 * (1.0 + nu) * std::log(L), 1e-14);
  EXPECT_NEAR(e[0] + e[1] + e[2], (1.0 - 2.0 * nu) * std::log(L), 1e-14);
}

// Each strain threshold and its sign rule on the principal strains (e1, e2, e3); a threshold holds
// once passed, strictly (a strain equal to it does not delete).
TEST(ErosionStrain, ThresholdsAndSigns) {
  const std::array<Real, 6> no_stress{};
  const std::array<Real, 3> tension{0.2, -0.05, -0.05}, compression{0.05, 0.05, -0.2};
  ErosionCriteria k;
  k.mxeps = {true, 0.19};
  EXPECT_TRUE(k.needs_strain());
  EXPECT_TRUE(k.point_fails(no_stress, 0.0, tension));
  EXPECT_FALSE(k.point_fails(no_stress, 0.0, compression));
  k.mxeps = {};
  k.mneps = {true, -0.19};
  EXPECT_FALSE(k.point_fails(no_stress, 0.0, tension));
  EXPECT_TRUE(k.point_fails(no_stress, 0.0, compression));
  k.mneps = {};
  k.voleps = {true, 0.099};  // tension: ln J > 0.099
  EXPECT_TRUE(k.point_fails(no_stress, 0.0, {0.1, 0.0, 0.0}));
  EXPECT_FALSE(k.point_fails(no_stress, 0.0, {0.1, 0.0, -0.002}));
  EXPECT_FALSE(k.point_fails(no_stress, 0.0, {0.0, 0.0, -0.5}));
  k.voleps = {true, -0.099};  // compression: ln J < -0.099
  EXPECT_TRUE(k.point_fails(no_stress, 0.0, {0.0, 0.0, -0.1}));
  EXPECT_FALSE(k.point_fails(no_stress, 0.0, {0.0, 0.0, -0.098}));
  EXPECT_FALSE(k.point_fails(no_stress, 0.0, {0.5, 0.0, 0.0}));
  k.voleps = {};
  k.epssh = {true, 0.12};  // (e1 - e3)/2: 0.125 in tension and in compression
  EXPECT_TRUE(k.point_fails(no_stress, 0.0, tension));
  EXPECT_TRUE(k.point_fails(no_stress, 0.0, compression));
  EXPECT_FALSE(k.point_fails(no_stress, 0.0, {0.1, 0.0, -0.1}));
  k.epssh = {};
  k.effeps = {true, 0.25};  // eps_eff of tension: (2/3)(0.25) = 1/6; of (0.3, 0, -0.3): sqrt(2/3 * 0.18)
  EXPECT_FALSE(k.point_fails(no_stress, 0.0, tension));
  EXPECT_TRUE(k.point_fails(no_stress, 0.0, {0.3, 0.0, -0.3}));
  EXPECT_NEAR(ErosionCriteria::effective_strain({0.3, 0.0, -0.3}), std::sqrt(0.12), 1e-15);
  // NCS = 2 with SIGVM: both must hold.
  k.sigvm = {true, 10.0};
  k.ncs = 2;
  EXPECT_FALSE(k.point_fails(no_stress, 0.0, {0.3, 0.0, -0.3}));
  EXPECT_TRUE(k.point_fails({20.0, 0.0, 0.0, 0.0, 0.0, 0.0}, 0.0, {0.3, 0.0, -0.3}));
  EXPECT_FALSE(k.point_fails({20.0, 0.0, 0.0, 0.0, 0.0, 0.0}, 0.0, tension));
}

namespace {

/// A 3 x 2 x 2 grid of distorted unit hexahedra (12 elements: a full batch of 8 lanes and a
/// partial one) deformed homogeneously to x = F X; returns how many elements the one-point block
/// deletes at one evaluation with the criteria `k`.
Index deleted_by(const ErosionCriteria& k, const Mat3& F) {
  const int nx = 3, ny = 2, nz = 2;
  NodalFields nodes;
  std::vector<Index> conn;
  std::vector<Id> ids;
  const auto id = [&](int i, int j, int k3) { return static_cast<Index>(i + (nx + 1) * (j + (ny + 1) * k3)); };
  nodes.resize(static_cast<std::size_t>((nx + 1) * (ny + 1) * (nz + 1)));
  for (int c = 0; c <= nz; ++c)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        const Index n = id(i, j, c);
        const Vec3 X = Vec3(i, j, c) + 0.1 * Vec3(std::sin(3.1 * n), std::cos(1.7 * n), std::sin(0.9 * n + 1.0));
        nodes.ids[n] = n + 1;
        nodes.x0.set(n, X);
        nodes.x.set(n, F * X);
      }
  for (int c = 0; c < nz; ++c)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        conn.insert(conn.end(), {id(i, j, c), id(i + 1, j, c), id(i + 1, j + 1, c), id(i, j + 1, c), id(i, j, c + 1),
                                 id(i + 1, j, c + 1), id(i + 1, j + 1, c + 1), id(i, j + 1, c + 1)});
        ids.push_back(static_cast<Id>(ids.size() + 1));
      }
  HexBlock<ElasticSolid> block(1, ElasticSolid(1.0, 1000.0, 0.3), HexHourglass{HexHourglass::Kind::viscous, 0.1},
                               BulkViscosity{0.0, 0.0}, conn, ids, StiffnessDamping{});
  block.enable_erosion(k);
  CornerBuffer corners;
  test_support::prepare(block, nodes, corners);
  test_support::evaluate(block, nodes, corners);
  return block.erosion()->deleted_count();
}

}  // namespace

// The one-point hexahedron under x = F X (F exact at every element's point for a linear field):
// every element goes when the closed-form strain is 1e-9 (relative) past the threshold, none
// when it is 1e-9 short, for F in the grid's frame and turned by a rotation R (x = R F X).
TEST(ErosionStrain, HexBlockDeletesAtTheClosedFormStrain) {
  const Mat3 R = rotation(2.1, Vec3(0.3, -1, 0.4));
  const auto check = [&](const char* what, ErosionCriteria::Threshold ErosionCriteria::*field, Real value,
                         const std::function<Mat3(Real)>& at) {
    ErosionCriteria k;
    k.*field = {true, value};
    for (const Mat3& turn : {Mat3(Mat3::Identity()), R}) {
      EXPECT_EQ(deleted_by(k, turn * at(1.0 + 1e-9)), 12) << what;
      EXPECT_EQ(deleted_by(k, turn * at(1.0 - 1e-9)), 0) << what;
    }
  };
  const Real nu = 0.3;
  // MXEPS 0.1 at L = exp(0.1) (lateral L^-nu); EFFEPS 0.15 at (2/3)(1 + nu) ln L = 0.15.
  check("MXEPS", &ErosionCriteria::mxeps, 0.1, [&](Real s) {
    const Real L = std::exp(0.1 * s);
    return Mat3(stretch(L, std::pow(L, -nu), std::pow(L, -nu)));
  });
  check("EFFEPS", &ErosionCriteria::effeps, 0.15, [&](Real s) {
    const Real L = std::exp(0.15 * s / (2.0 / 3.0 * (1.0 + nu)));
    return Mat3(stretch(L, std::pow(L, -nu), std::pow(L, -nu)));
  });
  // VOLEPS 0.05 (tension) and -0.05 (compression): ln J = 3 ln l for l = exp(+-0.05/3).
  check("VOLEPS > 0", &ErosionCriteria::voleps, 0.05, [&](Real s) {
    const Real l = std::exp(0.05 * s / 3.0);
    return Mat3(stretch(l, l, l));
  });
  check("VOLEPS < 0", &ErosionCriteria::voleps, -0.05, [&](Real s) {
    const Real l = std::exp(-0.05 * s / 3.0);
    return Mat3(stretch(l, l, l));
  });
  // MNEPS -0.08 in uniaxial compression: e3 = ln L.
  check("MNEPS", &ErosionCriteria::mneps, -0.08, [&](Real s) {
    const Real L = std::exp(-0.08 * s);
    return Mat3(stretch(std::pow(L, -nu), std::pow(L, -nu), L));
  });
  // EPSSH 0.05 in simple shear: asinh(g/2) = 0.05.
  check("EPSSH", &ErosionCriteria::epssh, 0.05, [&](Real s) { return simple_shear(2.0 * std::sinh(0.05 * s)); });
}
