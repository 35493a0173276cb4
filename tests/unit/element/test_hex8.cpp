#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "slideline/element/hex8.hpp"
#include "test_support/hex_fixtures.hpp"

using namespace slideline;

namespace {
// Exact volume of a trilinear hexahedron by 2x2x2 Gauss quadrature of det J (det J is a polynomial
// of degree <= 2 in each reference coordinate, so the rule is exact).
Real gauss_volume(const hex8::NodeMat& X) {
  static const int s[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                              {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  const Real g = 1.0 / std::sqrt(3.0);
  Real v = 0.0;
  for (int a = -1; a <= 1; a += 2)
    for (int b = -1; b <= 1; b += 2)
      for (int c = -1; c <= 1; c += 2) {
        const Real xi = a * g, eta = b * g, zeta = c * g;
        Mat3 J = Mat3::Zero();
        for (int I = 0; I < 8; ++I) {
          const Vec3 dN(0.125 * s[I][0] * (1 + s[I][1] * eta) * (1 + s[I][2] * zeta),
                        0.125 * s[I][1] * (1 + s[I][0] * xi) * (1 + s[I][2] * zeta),
                        0.125 * s[I][2] * (1 + s[I][0] * xi) * (1 + s[I][1] * eta));
          J += X.row(I).transpose() * dN.transpose();
        }
        v += J.determinant();
      }
  return v;
}
}  // namespace

TEST(Hex8, VolumeMatchesGaussQuadratureOnDistortedElement) {
  const hex8::NodeMat X = test_support::distorted_hex();
  const hex8::NodeMat g = hex8::volume_gradient(X);
  EXPECT_NEAR(hex8::volume(X, g), gauss_volume(X), 1e-13);
  EXPECT_NEAR(hex8::volume(test_support::unit_hex(), hex8::volume_gradient(test_support::unit_hex())), 1.0,
              1e-14);
}

TEST(Hex8, VolumeGradientMatchesFiniteDifferences) {
  const hex8::NodeMat X = test_support::distorted_hex();
  const hex8::NodeMat g = hex8::volume_gradient(X);
  const Real h = 1e-6;
  for (int I = 0; I < 8; ++I)
    for (int c = 0; c < 3; ++c) {
      hex8::NodeMat Xp = X, Xm = X;
      Xp(I, c) += h;
      Xm(I, c) -= h;
      const Real fd = (gauss_volume(Xp) - gauss_volume(Xm)) / (2 * h);
      EXPECT_NEAR(g(I, c), fd, 1e-8) << "node " << I << " component " << c;
    }
}

TEST(Hex8, GradientOperatorReproducesLinearFieldsExactly) {
  const hex8::NodeMat X = test_support::distorted_hex();
  const hex8::NodeMat dv = hex8::volume_gradient(X);
  const hex8::NodeMat B = dv / hex8::volume(X, dv);
  Mat3 A;
  A << 0.3, -0.2, 0.1, 0.05, 0.4, -0.3, 0.2, 0.1, -0.15;
  const hex8::NodeMat U = X * A.transpose();  // u = A x
  const Mat3 grad = U.transpose() * B;
  EXPECT_LT((grad - A).norm(), 1e-13);
}

TEST(Hex8, HourglassShapeVectorsAreOrthogonalToLinearFields) {
  const hex8::NodeMat X = test_support::distorted_hex();
  const hex8::NodeMat dv = hex8::volume_gradient(X);
  const hex8::NodeMat B = dv / hex8::volume(X, dv);
  const hex8::HgMat gam = hex8::hourglass_shape(X, B);
  EXPECT_LT((gam * X).norm(), 1e-13);
  EXPECT_LT((gam * Eigen::Matrix<Real, 8, 1>::Ones()).norm(), 1e-13);
}
