#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cmath>

#include "slideline/element/shell_block.hpp"
#include "test_support/block_eval.hpp"

using namespace slideline;

namespace {

constexpr Real kE = 1000.0, kNu = 0.1, kRho = 0.1, kT = 0.1;

/// A (nx+1) x (ny+1) grid of the plane spanned by e1, e2 through `origin`, interior nodes moved
/// by up to `distort` times the spacing (a distorted mesh), shells counter-clockwise about e1 x e2.
struct ShellMesh {
  NodalFields nodes;
  std::vector<Index> conn;
  std::vector<Id> ids;
  int nx = 0, ny = 0;
  Index node(int i, int j) const { return i + (nx + 1) * j; }
};

ShellMesh make_mesh(int nx, int ny, Real lx, Real ly, Real distort = 0.0,
                    const Mat3& frame = Mat3::Identity()) {
  ShellMesh m;
  m.nx = nx;
  m.ny = ny;
  m.nodes.resize(static_cast<std::size_t>((nx + 1) * (ny + 1)));
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      Real x = lx * i / nx, y = ly * j / ny;
      if (i > 0 && i < nx && j > 0 && j < ny) {
        // Deterministic "random" offsets.
        x += distort * lx / nx * std::sin(3.1 * i + 7.3 * j);
        y += distort * ly / ny * std::cos(5.7 * i - 2.9 * j);
      }
      const Index n = m.node(i, j);
      const Vec3 p = frame * Vec3(x, y, 0.0);
      m.nodes.ids[n] = n + 1;
      m.nodes.x0.set(n, p);
      m.nodes.x.set(n, p);
    }
  Id eid = 1;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      m.conn.insert(m.conn.end(), {m.node(i, j), m.node(i + 1, j), m.node(i + 1, j + 1), m.node(i, j + 1)});
      m.ids.push_back(eid++);
    }
  return m;
}

ShellBlock make_block(const ShellMesh& m, Real qhg = 0.1, int nip = 5,
                      shell_bt::ThicknessRule::Kind rule = shell_bt::ThicknessRule::Kind::gauss) {
  ShellSection sec;
  sec.thickness = kT;
  sec.nip = nip;
  sec.rule = rule;
  sec.hourglass_coefficient = qhg;
  return ShellBlock(7, ElasticShell(kRho, kE, kNu), sec, m.conn, m.ids);
}

Real evaluate(ShellBlock& b, NodalFields& n, CornerBuffer& c, Real dt) {
  BlockEnergy e;
  const Real d = b.compute_forces(n, dt, c, e);
  c.gather(n.f_int, n.m_int);
  return d;
}

Mat3 tilted_frame() {
  return (Eigen::AngleAxis<Real>(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix());
}

}  // namespace

TEST(ShellKernel, ThicknessRulesIntegratePolynomials) {
  using K = shell_bt::ThicknessRule::Kind;
  for (auto [kind, lo, hi] : {std::tuple{K::gauss, 1, 10}, std::tuple{K::lobatto, 2, 10}}) {
    for (int n = lo; n <= hi; ++n) {
      const auto r = shell_bt::ThicknessRule::make(n, kind);
      const int exact = kind == K::gauss ? 2 * n - 1 : 2 * n - 3;
      for (int p = 0; p <= exact; ++p) {
        Real s = 0.0;
        for (int i = 0; i < n; ++i) s += r.w[i] * std::pow(r.xi[i], p);
        const Real ref = p % 2 == 0 ? 2.0 / (p + 1) : 0.0;
        EXPECT_NEAR(s, ref, 2e-14) << "n=" << n << " p=" << p;  // beyond 5 points: computed rules
      }
    }
  }
  EXPECT_THROW(shell_bt::ThicknessRule::make(11, K::gauss), InputError);
  EXPECT_THROW(shell_bt::ThicknessRule::make(1, K::lobatto), InputError);
}

TEST(ShellKernel, BMatrixReproducesLinearFields) {
  shell_bt::NodeMat x;
  x << 0.0, 0.0, 0.1, 1.3, 0.2, 0.0, 1.1, 0.9, -0.05, -0.2, 1.1, 0.0;  // warped, distorted
  const auto g = shell_bt::local_geometry(x);
  ASSERT_GT(g.area, 0.0);
  EXPECT_NEAR((g.e.transpose() * g.e - Mat3::Identity()).norm(), 0.0, 1e-14);
  EXPECT_NEAR(g.b1.dot(g.xl), 1.0, 1e-14);
  EXPECT_NEAR(g.b1.dot(g.yl), 0.0, 1e-14);
  EXPECT_NEAR(g.b2.dot(g.yl), 1.0, 1e-14);
  EXPECT_NEAR(g.b1.sum(), 0.0, 1e-14);
  EXPECT_NEAR(g.gamma.dot(g.xl), 0.0, 1e-14);
  EXPECT_NEAR(g.gamma.dot(g.yl), 0.0, 1e-14);
  EXPECT_NEAR(g.gamma.sum(), 0.0, 1e-14);
}

TEST(ShellBlock, LumpedMassAndRotaryInertia) {
  ShellMesh m = make_mesh(3, 3, 1.0, 1.0, 0.2, tilted_frame());
  ShellBlock b = make_block(m);
  CornerBuffer c;
  test_support::prepare(b, m.nodes, c);
  Real mass = 0.0;
  for (Real v : m.nodes.mass) mass += v;
  EXPECT_NEAR(mass, kRho * 1.0 * kT, 1e-14);
  for (std::size_t i = 0; i < m.nodes.size(); ++i) {
    EXPECT_EQ(m.nodes.has_rotation[i], 1);
    EXPECT_GT(m.nodes.rot_inertia[i], 0.0);
  }
  EXPECT_TRUE(b.has_moments());
}

// Constant membrane strain rate on a distorted, tilted 2x2 mesh: every element gets the same
// stress C eps, the interior node is in equilibrium and the edge forces carry the traction.
TEST(ShellBlock, MembranePatchTest) {
  const Mat3 fr = tilted_frame();
  ShellMesh m = make_mesh(2, 2, 1.0, 0.8, 0.25, fr);
  ShellBlock b = make_block(m);
  CornerBuffer c;
  test_support::prepare(b, m.nodes, c);
  // Local (plane) velocity gradient: stretch in x and y and shear.
  Eigen::Matrix<Real, 2, 2> lg;
  // Small (linear-regime) increment: the frames of the elements turn by O(strain) between the
  // mid-step and the current geometry, a geometric effect of relative size O(strain).
  lg << 2e-8, 1.3e-8, -0.4e-8, 1.1e-8;
  const Real dt = 1.0;
  for (std::size_t i = 0; i < m.nodes.size(); ++i) {
    const Vec3 xl = fr.transpose() * m.nodes.x0.get(i);
    const Eigen::Matrix<Real, 2, 1> vl = lg * xl.head<2>();
    const Vec3 v = fr * Vec3(vl[0], vl[1], 0.0);
    m.nodes.v.set(i, v);
    // x^n such that the mid-step geometry is the reference one.
    m.nodes.x.set(i, m.nodes.x0.get(i) + 0.5 * dt * v);
  }
  evaluate(b, m.nodes, c, dt);
  const Real c11 = kE / (1 - kNu * kNu), g = kE / (2 * (1 + kNu));
  const Real exx = lg(0, 0) * dt, eyy = lg(1, 1) * dt, gxy = (lg(0, 1) + lg(1, 0)) * dt;
  const Real sxx = c11 * (exx + kNu * eyy), syy = c11 * (kNu * exx + eyy), sxy = g * gxy;
  // Each element's frame has e1 along its side 1-2, so compare invariants of the in-plane stress.
  const Real tr = sxx + syy, det = sxx * syy - sxy * sxy;
  for (Index e = 0; e < b.element_count(); ++e)
    for (int ip = 0; ip < 5; ++ip) {
      const auto s = b.stress(e, ip);
      EXPECT_NEAR(s[0] + s[1], tr, 1e-12 * std::abs(tr));
      EXPECT_NEAR(s[0] * s[1] - s[2] * s[2], det, 1e-11 * std::abs(det));
      EXPECT_NEAR(s[3], 0.0, 1e-12);
      EXPECT_NEAR(s[4], 0.0, 1e-12);
    }
  const Index mid = m.node(1, 1);
  const Real fscale = std::abs(sxx) * kT;
  EXPECT_LT(m.nodes.f_int.get(mid).norm(), 1e-6 * fscale);
  EXPECT_LT(m.nodes.m_int.get(mid).norm(), 1e-6 * fscale);
  // Right edge (x = 1): the element pulls its nodes back with the traction times the edge
  // length (0.8) and the thickness.
  Vec3 fr_sum = Vec3::Zero();
  for (int j = 0; j <= 2; ++j) fr_sum += m.nodes.f_int.get(m.node(2, j));
  const Vec3 local = fr.transpose() * fr_sum;
  EXPECT_NEAR(local[0], -sxx * 0.8 * kT, 1e-6 * fscale);
  EXPECT_NEAR(local[1], -sxy * 0.8 * kT, 1e-6 * fscale);
  // Sum of all forces and moments vanishes.
  Vec3 ft = Vec3::Zero();
  for (std::size_t i = 0; i < m.nodes.size(); ++i) ft += m.nodes.f_int.get(i);
  EXPECT_LT(ft.norm(), 1e-13 * fscale);
}

// A rigid rotation, prescribed step by step (chord velocities, consistent nodal angular
// velocity), leaves an unstressed shell unstressed and force free; a prestressed shell keeps its
// co-rotational stress and its forces turn with it.
TEST(ShellBlock, RigidRotationGivesZeroStrainAndRotatesStress) {
  ShellMesh m = make_mesh(2, 2, 1.0, 1.0, 0.2, tilted_frame());
  // Slightly warped.
  m.nodes.x0.z[m.node(1, 1)] += 0.03;
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
  // Scale: the stress of a strain equal to one step's rotation angle.
  EXPECT_LT(smax, 1e-9 * kE * dtheta);
  EXPECT_LT(fmax, 1e-9 * kE * dtheta * kT);
}

TEST(ShellBlock, PrestressTurnsWithTheElement) {
  ShellMesh m = make_mesh(1, 1, 1.0, 1.0);
  ShellBlock b = make_block(m);
  CornerBuffer c;
  test_support::prepare(b, m.nodes, c);
  // One step of uniaxial stretch in x.
  const Real dt = 1.0;
  for (std::size_t i = 0; i < m.nodes.size(); ++i) {
    const Vec3 x0 = m.nodes.x0.get(i);
    m.nodes.v.set(i, Vec3(1e-3 * x0[0], 0.0, 0.0));
    m.nodes.x.set(i, x0 + Vec3(1e-3 * x0[0], 0.0, 0.0));
  }
  evaluate(b, m.nodes, c, dt);
  const auto s0 = b.stress(0, 2);
  std::vector<Vec3> f0(4), prev(4);
  for (Index i = 0; i < 4; ++i) f0[i] = m.nodes.f_int.get(i), prev[i] = m.nodes.x.get(i);
  const Vec3 axis = Vec3(1.0, 1.0, 0.5).normalized();
  const int steps = 200;
  const Real dth = 0.5 * M_PI / steps, h = 1e-3;
  Mat3 r = Mat3::Identity();
  std::vector<Vec3> base(prev);
  for (int s = 1; s <= steps; ++s) {
    r = Eigen::AngleAxis<Real>(s * dth, axis).toRotationMatrix();
    for (Index i = 0; i < 4; ++i) {
      const Vec3 x = r * base[i];
      m.nodes.v.set(i, (x - prev[i]) / h);
      m.nodes.x.set(i, x);
      m.nodes.omega.set(i, 2.0 * std::tan(0.5 * dth) / h * axis);
      prev[i] = x;
    }
    evaluate(b, m.nodes, c, h);
  }
  const auto s1 = b.stress(0, 2);
  EXPECT_NEAR((s1 - s0).norm(), 0.0, 1e-9 * s0.norm());
  for (Index i = 0; i < 4; ++i)
    EXPECT_NEAR((m.nodes.f_int.get(i) - r * f0[i]).norm(), 0.0, 1e-9 * f0[i].norm() + 1e-15);
}

// Stability: the element's highest natural frequency (from its stiffness, built column by column
// from force evaluations, and its lumped masses and rotary inertias) must allow the step the
// element reports: dt_reported <= 2 / omega_max. Checks that the rotary inertia scaling keeps the
// rotational modes from setting the step. At nu = 0 the highest mode is the transverse-shear one
// (mean rotation against the deflection slope, frequency ~ sqrt(kappa G), G = E / 2(1 + nu)): w dt
// = 0.93 x 2 for the 1 x 0.7 element.
TEST(ShellBlock, ReportedStepIsStable) {
  for (Real nu : {0.0, kNu, 0.3})
  for (Real t : {0.1, 0.01, 0.4}) {
    for (Real distort : {0.0, 0.3}) {
      ShellMesh m0 = make_mesh(1, 1, 1.0, 0.7);
      if (distort > 0) {
        m0.nodes.x0.x[2] += distort;
        m0.nodes.x0.y[3] -= 0.5 * distort;
        m0.nodes.x = m0.nodes.x0;
      }
      Eigen::Matrix<Real, 24, 24> k;
      Eigen::Matrix<Real, 24, 1> mass;
      Real dt_el = 0.0;
      for (int col = 0; col < 24; ++col) {
        ShellMesh m = m0;
        ShellSection sec;
        sec.thickness = t;
        sec.hourglass_coefficient = 0.0;
        sec.bulk = BulkViscosity{0.0, 0.0};
        ShellBlock b(1, ElasticShell(kRho, kE, nu), sec, m.conn, m.ids);
        CornerBuffer c;
        test_support::prepare(b, m.nodes, c);
        const Real h = 1e-7;
        const int node = col / 6, dof = col % 6;
        if (dof < 3) m.nodes.v[dof][node] = 1.0;
        else m.nodes.omega[dof - 3][node] = 1.0;
        dt_el = evaluate(b, m.nodes, c, h);
        for (int n = 0; n < 4; ++n)
          for (int d = 0; d < 3; ++d) {
            k(6 * n + d, col) = -m.nodes.f_int[d][n] / h;
            k(6 * n + 3 + d, col) = -m.nodes.m_int[d][n] / h;
            mass[6 * n + d] = m.nodes.mass[n];
            mass[6 * n + 3 + d] = m.nodes.rot_inertia[n];
          }
      }
      const Eigen::Matrix<Real, 24, 1> is = mass.cwiseSqrt().cwiseInverse();
      Eigen::Matrix<Real, 24, 24> a = is.asDiagonal() * k * is.asDiagonal();
      a = 0.5 * (a + a.transpose()).eval();
      const Real w2 = Eigen::SelfAdjointEigenSolver<Eigen::Matrix<Real, 24, 24>>(a).eigenvalues().maxCoeff();
      EXPECT_LE(dt_el, 2.0 / std::sqrt(w2)) << "nu=" << nu << " t=" << t << " distort=" << distort;
      // And not absurdly conservative either.
      EXPECT_GT(dt_el, 0.3 * 2.0 / std::sqrt(w2)) << "nu=" << nu << " t=" << t << " distort=" << distort;
    }
  }
}
