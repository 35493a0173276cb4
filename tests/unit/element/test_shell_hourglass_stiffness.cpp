// The stiffness hourglass form of the Belytschko-Tsay quadrilateral (IHQ 4-6 on shells,
// shell_hourglass.hpp): generalised forces integrated from the mode rates in the element's frame.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <numbers>

#include "slideline/element/shell_block.hpp"
#include "test_support/block_eval.hpp"

using namespace slideline;

namespace {

constexpr Real kE = 1000.0, kNu = 0.3, kRho = 0.1, kT = 0.1;

/// One unit-square quadrilateral at `origin` in the plane z = 0, its block with the stiffness
/// form and coefficient `qm`.
struct OneQuad {
  NodalFields nodes;
  ShellBlock block;
  CornerBuffer corners;

  explicit OneQuad(Real qm) : block(make(qm)) {
    nodes.resize(4);
    const std::array<Vec3, 4> p{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
    for (int i = 0; i < 4; ++i) {
      nodes.ids[i] = i + 1;
      nodes.x0.set(i, p[i]);
      nodes.x.set(i, p[i]);
    }
    test_support::prepare(block, nodes, corners);
  }
  static ShellBlock make(Real qm) {
    ShellSection sec;
    sec.thickness = kT;
    sec.hourglass_coefficient = qm;
    sec.hourglass_stiffness = true;
    return ShellBlock(1, ElasticShell(kRho, kE, kNu), sec, {0, 1, 2, 3}, {1});
  }
  /// One step: forces into nodes.f_int / m_int; returns the hourglass power.
  Real step(Real dt) {
    BlockEnergy en;
    block.compute_forces(nodes, dt, corners, en);
    nodes.f_int.fill(0.0);
    nodes.m_int.fill(0.0);
    corners.gather(nodes.f_int, nodes.m_int);
    return en.hourglass_power;
  }
};

}  // namespace

// The out-of-plane mode of a unit square, v_z = s h_I (h = 1, -1, 1, -1; on a square gamma = h),
// has rate qdot = gamma . v = 4 s and the mode stiffness k_w = kappa G t^3 (|b1|^2 + |b2|^2) / 12
// with |b1|^2 = |b2|^2 = 1: after one step the stored force is QM k_w dt qdot and the nodal forces
// f_z,I = -Q h_I; a second step with the same rate doubles them (integrated, not recomputed from
// the rate, as the viscous form would). The mode has no strain at the element's one point, so
// the rest of the element adds nothing.
TEST(ShellHourglassStiffness, OutOfPlaneModeIntegratesToTheClosedFormForce) {
  const Real qm = 0.1, s = 1e-3, dt = 1e-4;
  OneQuad q(qm);
  const std::array<Real, 4> h{1.0, -1.0, 1.0, -1.0};
  for (int i = 0; i < 4; ++i) q.nodes.v.set(i, Vec3(0.0, 0.0, s * h[i]));
  const Real g = (5.0 / 6.0) * kE / (2.0 * (1.0 + kNu));
  const Real k_w = g * kT * kT * kT * 2.0 / 12.0;
  const Real force = qm * k_w * dt * 4.0 * s;
  for (int n = 1; n <= 2; ++n) {
    const Real power = q.step(dt);
    for (int i = 0; i < 4; ++i) {
      EXPECT_NEAR(q.nodes.f_int.z[i], -n * force * h[i], 1e-6 * force) << "step " << n << " node " << i;
      EXPECT_NEAR(q.nodes.f_int.x[i], 0.0, 1e-6 * force);
      EXPECT_NEAR(q.nodes.f_int.y[i], 0.0, 1e-6 * force);
    }
    // The power into the hourglass control over the step is the trapezoid of Q . qdot, the mean of
    // the last force's (n - 1) and this one's (n): (n - 1/2) Q1 qdot (it stores, it does not
    // dissipate; the work over n steps is n^2 Q1 qdot dt / 2 = Q_n^2 / (2 QM k_w), the stored energy).
    EXPECT_NEAR(power, (n - 0.5) * force * 4.0 * s, 1e-6 * force * s);
  }
}

// Objectivity: the square is bent (out-of-plane mode) and sheared in plane (membrane mode) in ten
// steps, then turned rigidly by 90 degrees about a skew axis in 200 steps, each step's velocity
// the chord (x_n+1 - x_n) / dt and the nodes' angular velocity 2 tan(dtheta / 2) / dt about the
// axis (the rotation whose midpoint map is the chord: the rigid part is then removed exactly). The
// stored forces must turn with the element: f_after = R f_before, m_after = R m_before.
TEST(ShellHourglassStiffness, ForcesTurnWithTheElementUnderARigidRotation) {
  const Real dt = 1e-3;
  OneQuad q(0.1);
  const std::array<Real, 4> h{1.0, -1.0, 1.0, -1.0};
  const auto move_to = [&](const std::array<Vec3, 4>& x, const Vec3& omega) {
    for (int i = 0; i < 4; ++i) {
      q.nodes.v.set(i, (x[i] - q.nodes.x.get(i)) / dt);
      q.nodes.x.set(i, x[i]);
      q.nodes.omega.set(i, omega);
    }
    q.step(dt);
  };
  std::array<Vec3, 4> x;
  for (int n = 1; n <= 10; ++n) {
    for (int i = 0; i < 4; ++i) x[i] = q.nodes.x0.get(i) + 1e-4 * n * h[i] * Vec3(0.5, 0.0, 1.0);
    move_to(x, Vec3::Zero());
  }
  const std::array<Vec3, 4> bent = x;
  std::array<Vec3, 4> f0, m0;
  Real fmax = 0.0, mmax = 0.0;
  for (int i = 0; i < 4; ++i) {
    f0[i] = q.nodes.f_int.get(i);
    m0[i] = q.nodes.m_int.get(i);
    fmax = std::max(fmax, f0[i].norm());
    mmax = std::max(mmax, m0[i].norm());
  }
  ASSERT_GT(fmax, 1e-9) << "no hourglass force after the bend";
  const Vec3 axis = Vec3(1.0, -2.0, 0.5).normalized(), centre(0.5, 0.5, 0.0);
  const int steps = 200;
  const Real dtheta = 0.5 * std::numbers::pi / steps;
  const Vec3 omega = axis * (2.0 * std::tan(0.5 * dtheta) / dt);
  for (int n = 1; n <= steps; ++n) {
    const Mat3 R = Eigen::AngleAxis<Real>(n * dtheta, axis).toRotationMatrix();
    for (int i = 0; i < 4; ++i) x[i] = centre + R * (bent[i] - centre);
    move_to(x, omega);
  }
  const Mat3 R = Eigen::AngleAxis<Real>(0.5 * std::numbers::pi, axis).toRotationMatrix();
  for (int i = 0; i < 4; ++i) {
    EXPECT_LT((q.nodes.f_int.get(i) - R * f0[i]).norm(), 1e-8 * fmax) << "node " << i;
    EXPECT_LT((q.nodes.m_int.get(i) - R * m0[i]).norm(), 1e-8 * std::max(mmax, fmax)) << "node " << i;
  }
}
