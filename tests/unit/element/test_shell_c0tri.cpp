// The C0 triangle (element/shell_c0tri.hpp) alone and in mixed quad/triangle shell blocks: linear
// fields, the assumed shear of Kirchhoff modes, no spurious modes, membrane patch test on a
// distorted mixed mesh, rigid rotation, lumped mass and a stable reported step.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cmath>

#include "slideline/element/shell_block.hpp"
#include "test_support/block_eval.hpp"
#include "test_support/shell_mesh.hpp"

using namespace slideline;

namespace {

constexpr Real kE = 1000.0, kNu = 0.3, kRho = 0.1, kT = 0.1;

using test_support::all_split;
using test_support::checkerboard;
using Mesh = test_support::ShellMesh;

template <class Split>
Mesh make_mesh(int nx, int ny, Real lx, Real ly, Real distort, const Mat3& frame, Split split) {
  return test_support::shell_mesh(nx, ny, lx, ly, distort, frame, split);
}

ShellBlock make_block(const Mesh& m, Real nu = kNu, Real t = kT) {
  ShellSection sec;
  sec.thickness = t;
  sec.nip = 5;
  sec.hourglass_coefficient = 0.0;
  sec.bulk = BulkViscosity{0.0, 0.0};
  return ShellBlock(7, ElasticShell(kRho, kE, nu), sec, m.conn, m.ids);
}

Real evaluate(ShellBlock& b, NodalFields& n, CornerBuffer& c, Real dt) {
  BlockEnergy e;
  const Real d = b.compute_forces(n, dt, c, e);
  c.gather(n.f_int, n.m_int);
  return d;
}

Mat3 tilted_frame() { return Eigen::AngleAxis<Real>(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix(); }


/// Stiffness (force evaluations of one step h with unit velocities) and lumped masses of the
/// elements of `m0` (one element: 18 or 24 degrees of freedom); returns the stable step it reports.
template <int N>
Real element_stiffness(const Mesh& m0, Real nu, Real t, Eigen::Matrix<Real, N, N>& k,
                       Eigen::Matrix<Real, N, 1>& mass) {
  Real dt_el = 0.0;
  const int nodes = N / 6;
  for (int col = 0; col < N; ++col) {
    Mesh m = m0;
    ShellBlock b = make_block(m, nu, t);
    CornerBuffer c;
    test_support::prepare(b, m.nodes, c);
    const Real h = 1e-7;
    const int node = col / 6, dof = col % 6;
    if (dof < 3) m.nodes.v[dof][node] = 1.0;
    else m.nodes.omega[dof - 3][node] = 1.0;
    dt_el = evaluate(b, m.nodes, c, h);
    for (int n = 0; n < nodes; ++n)
      for (int d = 0; d < 3; ++d) {
        k(6 * n + d, col) = -m.nodes.f_int[d][n] / h;
        k(6 * n + 3 + d, col) = -m.nodes.m_int[d][n] / h;
        mass[6 * n + d] = m.nodes.mass[n];
        mass[6 * n + 3 + d] = m.nodes.rot_inertia[n];
      }
  }
  return dt_el;
}

/// One triangle (nodes 0 1 2) with the given in-plane coordinates.
Mesh one_triangle(const Eigen::Matrix<Real, 3, 2>& xy) {
  Mesh m;
  m.nodes.resize(3);
  for (Index n = 0; n < 3; ++n) {
    const Vec3 p(xy(n, 0), xy(n, 1), 0.0);
    m.nodes.ids[n] = n + 1;
    m.nodes.x0.set(n, p);
    m.nodes.x.set(n, p);
  }
  m.conn = {0, 1, 2, 2};
  m.ids = {1};
  return m;
}

}  // namespace

TEST(ShellC0Triangle, BMatrixReproducesLinearFields) {
  shell_c0tri::NodeMat x;
  x << 0.1, 0.0, 0.2, 1.3, 0.2, -0.1, 0.4, 0.9, 0.3;
  const auto g = shell_c0tri::local_geometry(x);
  ASSERT_GT(g.area, 0.0);
  EXPECT_NEAR((g.e.transpose() * g.e - Mat3::Identity()).norm(), 0.0, 1e-14);
  EXPECT_NEAR(g.area, 0.5 * (x.row(1) - x.row(0)).cross(x.row(2) - x.row(0)).norm(), 1e-14);
  EXPECT_NEAR(g.b1.dot(g.xl), 1.0, 1e-14);
  EXPECT_NEAR(g.b1.dot(g.yl), 0.0, 1e-14);
  EXPECT_NEAR(g.b2.dot(g.yl), 1.0, 1e-14);
  EXPECT_NEAR(g.b2.dot(g.xl), 0.0, 1e-14);
  EXPECT_NEAR(g.b1.sum(), 0.0, 1e-14);
  EXPECT_NEAR(g.b2.sum(), 0.0, 1e-14);
  EXPECT_LT(shell_c0tri::characteristic_length(g, 1.0, 0.5), 2.0 * g.area / g.len.maxCoeff());
}

// The assumed shear: zero for every constant-curvature Kirchhoff mode (w quadratic, the nodal
// rotations its slopes), so a thin plate does not lock in pure bending; a constant shear field
// (w linear, rotations zero) and a constant rotation are reproduced exactly.
TEST(ShellC0Triangle, AssumedShearVanishesForKirchhoffModes) {
  shell_c0tri::NodeMat x;
  x << 0.0, 0.0, 0.0, 1.1, 0.2, 0.0, 0.3, 0.8, 0.0;
  const auto g = shell_c0tri::local_geometry(x);
  const Real p = 0.7, q = -0.4, r = 1.3;  // w = p x^2 / 2 + q y^2 / 2 + r x y
  shell_c0tri::NodeMat vl = shell_c0tri::NodeMat::Zero(), wl = shell_c0tri::NodeMat::Zero();
  for (int k = 0; k < 3; ++k) {
    const Real X = g.xl[k], Y = g.yl[k];
    vl(k, 2) = 0.5 * p * X * X + 0.5 * q * Y * Y + r * X * Y;
    wl(k, 0) = q * Y + r * X;   // theta_x = dw/dy
    wl(k, 1) = -(p * X + r * Y);  // theta_y = -dw/dx
  }
  const auto s = shell_c0tri::strain_rates(g, vl, wl);
  EXPECT_NEAR(s.s.shear[0], 0.0, 1e-14);
  EXPECT_NEAR(s.s.shear[1], 0.0, 1e-14);
  EXPECT_NEAR(s.shear_c, 0.0, 1e-14);
  // Strain z kappa with v_x(z) = -z dw/dx: kappa = -(w_xx, w_yy, 2 w_xy).
  EXPECT_NEAR(s.s.curvature[0], -p, 1e-13);
  EXPECT_NEAR(s.s.curvature[1], -q, 1e-13);
  EXPECT_NEAR(s.s.curvature[2], -2.0 * r, 1e-13);
  // Constant shear: w = 0.3 x - 0.2 y, no rotation: 2 d_xz = 0.3, 2 d_yz = -0.2.
  for (int k = 0; k < 3; ++k) vl(k, 2) = 0.3 * g.xl[k] - 0.2 * g.yl[k];
  wl.setZero();
  const auto c = shell_c0tri::strain_rates(g, vl, wl);
  EXPECT_NEAR(c.s.shear[1], 0.3, 1e-14);
  EXPECT_NEAR(c.s.shear[0], -0.2, 1e-14);
  EXPECT_NEAR(c.shear_c, 0.0, 1e-14);
}

// The free triangle's stiffness has exactly the six rigid-body modes as null space (and, without
// drilling stiffness, the three nodal drilling rotations): no spurious mode, hence no hourglass
// control. The same element in a rotated frame gives the same spectrum.
TEST(ShellC0Triangle, NoSpuriousModes) {
  Eigen::Matrix<Real, 3, 2> xy;
  xy << 0.0, 0.0, 1.0, 0.1, 0.35, 0.8;
  const Mesh m = one_triangle(xy);
  Eigen::Matrix<Real, 18, 18> k;
  Eigen::Matrix<Real, 18, 1> mass;
  element_stiffness<18>(m, kNu, kT, k, mass);
  const Eigen::Matrix<Real, 18, 18> ks = 0.5 * (k + k.transpose());
  EXPECT_LT((k - k.transpose()).norm(), 1e-6 * k.norm());
  const Eigen::Matrix<Real, 18, 1> ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix<Real, 18, 18>>(ks).eigenvalues();
  const Real top = ev.maxCoeff();
  int zero = 0;
  for (int i = 0; i < 18; ++i) {
    EXPECT_GT(ev[i], -1e-7 * top);
    if (ev[i] < 1e-7 * top) ++zero;
  }
  EXPECT_EQ(zero, 6 + 3) << ev.transpose();  // rigid modes + the three drilling rotations
  EXPECT_GT(ev[9], 1e-5 * top);  // the smallest deformation mode is far from zero
}

// Constant membrane strain rate on a distorted, tilted mixed mesh (quads and triangles): every
// element gets the stress C eps to round-off, interior nodes are in equilibrium and the right edge
// carries the traction.
TEST(ShellC0Triangle, MembranePatchTestOnDistortedMixedMesh) {
  for (bool all : {false, true}) {
    const Mat3 fr = tilted_frame();
    Mesh m = all ? make_mesh(3, 3, 1.0, 0.8, 0.25, fr, all_split) : make_mesh(3, 3, 1.0, 0.8, 0.25, fr, checkerboard);
    ShellBlock b = make_block(m);
    CornerBuffer c;
    test_support::prepare(b, m.nodes, c);
    EXPECT_EQ(b.quad_count(), all ? 0 : 4);
    EXPECT_EQ(b.element_count(), all ? 18 : 14);
    Eigen::Matrix<Real, 2, 2> lg;
    lg << 2e-8, 1.3e-8, -0.4e-8, 1.1e-8;
    const Real dt = 1.0;
    for (std::size_t i = 0; i < m.nodes.size(); ++i) {
      const Vec3 xl = fr.transpose() * m.nodes.x0.get(i);
      const Eigen::Matrix<Real, 2, 1> vl = lg * xl.head<2>();
      const Vec3 v = fr * Vec3(vl[0], vl[1], 0.0);
      m.nodes.v.set(i, v);
      m.nodes.x.set(i, m.nodes.x0.get(i) + 0.5 * dt * v);
    }
    evaluate(b, m.nodes, c, dt);
    const Real c11 = kE / (1 - kNu * kNu), g = kE / (2 * (1 + kNu));
    const Real exx = lg(0, 0), eyy = lg(1, 1), gxy = lg(0, 1) + lg(1, 0);
    const Real sxx = c11 * (exx + kNu * eyy), syy = c11 * (kNu * exx + eyy), sxy = g * gxy;
    const Real tr = sxx + syy, det = sxx * syy - sxy * sxy;
    for (Index e = 0; e < b.element_count(); ++e)
      for (int ip = 0; ip < 5; ++ip) {
        const auto s = b.stress(e, ip);
        EXPECT_NEAR(s[0] + s[1], tr, 1e-12 * std::abs(tr)) << "element " << b.element_id(e);
        EXPECT_NEAR(s[0] * s[1] - s[2] * s[2], det, 1e-11 * std::abs(det));
        EXPECT_NEAR(s[3], 0.0, 1e-12 * std::abs(tr));
        EXPECT_NEAR(s[4], 0.0, 1e-12 * std::abs(tr));
      }
    const Real fscale = std::abs(sxx) * kT;
    for (int j = 1; j < 3; ++j)
      for (int i = 1; i < 3; ++i) {
        EXPECT_LT(m.nodes.f_int.get(m.node(i, j)).norm(), 1e-6 * fscale);
        EXPECT_LT(m.nodes.m_int.get(m.node(i, j)).norm(), 1e-6 * fscale);
      }
    Vec3 right = Vec3::Zero();
    for (int j = 0; j <= 3; ++j) right += m.nodes.f_int.get(m.node(3, j));
    const Vec3 local = fr.transpose() * right;
    EXPECT_NEAR(local[0], -sxx * 0.8 * kT, 1e-6 * fscale);
    EXPECT_NEAR(local[1], -sxy * 0.8 * kT, 1e-6 * fscale);
  }
}

// A rigid rotation of a mixed mesh, prescribed step by step, leaves it unstressed and force free.
TEST(ShellC0Triangle, RigidRotationGivesNoStress) {
  Mesh m = make_mesh(2, 2, 1.0, 1.0, 0.2, tilted_frame(), checkerboard);
  m.nodes.x0.z[m.node(1, 1)] += 0.03;  // slightly warped quads
  m.nodes.x.z[m.node(1, 1)] += 0.03;
  ShellBlock b = make_block(m);
  CornerBuffer c;
  test_support::prepare(b, m.nodes, c);
  const Vec3 axis = Vec3(0.3, -0.5, 0.8).normalized();
  const Vec3 center(0.4, 0.2, -0.1);
  const int steps = 400;
  const Real dtheta = 0.5 * M_PI / steps, dt = 1e-3;
  std::vector<Vec3> prev(m.nodes.size());
  for (std::size_t i = 0; i < m.nodes.size(); ++i) prev[i] = m.nodes.x0.get(i);
  for (int s = 1; s <= steps; ++s) {
    const Mat3 r = Eigen::AngleAxis<Real>(s * dtheta, axis).toRotationMatrix();
    for (std::size_t i = 0; i < m.nodes.size(); ++i) {
      const Vec3 x = center + r * (m.nodes.x0.get(i) - center);
      m.nodes.v.set(i, (x - prev[i]) / dt);
      m.nodes.x.set(i, x);
      m.nodes.omega.set(i, 2.0 * std::tan(0.5 * dtheta) / dt * axis);
      prev[i] = x;
    }
    evaluate(b, m.nodes, c, dt);
  }
  Real smax = 0.0, fmax = 0.0;
  for (Index e = 0; e < b.element_count(); ++e)
    for (int ip = 0; ip < 5; ++ip) smax = std::max(smax, b.stress(e, ip).cwiseAbs().maxCoeff());
  for (std::size_t i = 0; i < m.nodes.size(); ++i)
    fmax = std::max({fmax, m.nodes.f_int.get(i).norm(), m.nodes.m_int.get(i).norm()});
  EXPECT_LT(smax, 1e-9 * kE * dtheta);
  EXPECT_LT(fmax, 1e-9 * kE * dtheta * kT);
}

TEST(ShellC0Triangle, LumpedMassIsOneThirdPerNode) {
  Mesh m = make_mesh(3, 2, 1.0, 1.0, 0.2, tilted_frame(), checkerboard);
  ShellBlock b = make_block(m);
  CornerBuffer c;
  test_support::prepare(b, m.nodes, c);
  Real mass = 0.0;
  for (Real v : m.nodes.mass) mass += v;
  EXPECT_NEAR(mass, kRho * 1.0 * kT, 1e-14);
  Eigen::Matrix<Real, 3, 2> xy;
  xy << 0.0, 0.0, 1.0, 0.1, 0.35, 0.8;
  Mesh t = one_triangle(xy);
  ShellBlock bt = make_block(t);
  test_support::prepare(bt, t.nodes, c);
  const Real area = 0.5 * (1.0 * 0.8 - 0.35 * 0.1);
  for (Index n = 0; n < 3; ++n) EXPECT_NEAR(t.nodes.mass[n], kRho * area * kT / 3.0, 1e-15);
  EXPECT_EQ(bt.topology().runs().size(), 1u);
  EXPECT_EQ(bt.topology().runs()[0].topology, &tri3_topology);
  EXPECT_EQ(bt.connectivity().size(), 3u);
}

// The step the triangle reports (shell_c0tri::characteristic_length / c) is below 2 / omega_max of its
// stiffness and lumped masses (rotary inertias included) for thin and thick shells and a
// sliver, and not absurdly conservative.
TEST(ShellC0Triangle, ReportedStepIsStable) {
  for (Real nu : {0.0, 0.3})
    for (Real t : {0.1, 0.01, 0.4})
      for (Real apex : {0.5, 0.1, 1.4}) {
        Eigen::Matrix<Real, 3, 2> xy;
        xy << 0.0, 0.0, 1.0, 0.0, apex, 0.7 * (apex == 0.1 ? 0.3 : 1.0);
        Eigen::Matrix<Real, 18, 18> k;
        Eigen::Matrix<Real, 18, 1> mass;
        const Real dt_el = element_stiffness<18>(one_triangle(xy), nu, t, k, mass);
        const Eigen::Matrix<Real, 18, 1> is = mass.cwiseSqrt().cwiseInverse();
        Eigen::Matrix<Real, 18, 18> a = is.asDiagonal() * k * is.asDiagonal();
        a = 0.5 * (a + a.transpose()).eval();
        const Real w2 = Eigen::SelfAdjointEigenSolver<Eigen::Matrix<Real, 18, 18>>(a).eigenvalues().maxCoeff();
        const Real ratio = dt_el / (2.0 / std::sqrt(w2));
        std::printf("nu %.1f t %.2f apex %.1f: dt / (2 / omega_max) = %.3f\n", nu, t, apex, ratio);
        EXPECT_LE(ratio, 1.0) << "nu=" << nu << " t=" << t << " apex=" << apex;
        EXPECT_GT(ratio, 0.3) << "nu=" << nu << " t=" << t << " apex=" << apex;
      }
}
