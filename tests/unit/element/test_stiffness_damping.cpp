// Stiffness-proportional (Rayleigh) damping in the hexahedron and shell blocks: the dissipated
// power against the closed form beta D : C : D, consistency of that power with the forces the
// damping stress adds, no damping of a rigid rotation, and the damped element step.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "slideline/element/block_factory.hpp"
#include "slideline/element/hex_block.hpp"
#include "slideline/element/shell_block.hpp"
#include "slideline/material/elastic.hpp"
#include "test_support/block_eval.hpp"

using namespace slideline;

namespace {

constexpr Real kRho = 2.0, kE = 1000.0, kNu = 0.3, kBeta = 2.5e-3;

/// An nx x ny x nz grid of hexahedra of side h, every node moved by up to `jitter` h (a distorted
/// mesh). 3 x 2 x 2 = 12 elements: one full batch of 8 lanes and a partial one.
struct HexGrid {
  NodalFields nodes;
  std::vector<Index> conn;
  std::vector<Id> ids;
};

HexGrid hex_grid(int nx, int ny, int nz, Real h, Real jitter) {
  HexGrid g;
  const auto id = [&](int i, int j, int k) {
    return static_cast<Index>(i + (nx + 1) * (j + (ny + 1) * k));
  };
  g.nodes.resize(static_cast<std::size_t>((nx + 1) * (ny + 1) * (nz + 1)));
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        const Index n = id(i, j, k);
        const Vec3 d(std::sin(3.1 * n), std::cos(1.7 * n), std::sin(0.9 * n + 1.0));
        const Vec3 x = h * (Vec3(i, j, k) + jitter * d);
        g.nodes.ids[n] = n + 1;
        g.nodes.x0.set(n, x);
        g.nodes.x.set(n, x);
      }
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        g.conn.insert(g.conn.end(), {id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
                                     id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1),
                                     id(i, j + 1, k + 1)});
        g.ids.push_back(static_cast<Id>(g.ids.size() + 1));
      }
  return g;
}

/// A hexahedron block with no hourglass control and no bulk viscosity, so that the damping stress
/// is the only rate-dependent term.
HexBlock<ElasticSolid> hex_block(const HexGrid& g, Real beta) {
  return HexBlock<ElasticSolid>(1, ElasticSolid(kRho, kE, kNu),
                                HexHourglass{HexHourglass::Kind::viscous, 0.0}, BulkViscosity{0.0, 0.0},
                                g.conn, g.ids, StiffnessDamping{beta});
}

struct Evaluation {
  BlockEnergy energy;
  Real dt = 0.0;
  Real power = 0.0;  ///< sum over nodes of f_int . v (+ m_int . omega)
};

Evaluation evaluate(ElementBlock& b, NodalFields& n, Real dt = 0.0) {
  CornerBuffer c;
  test_support::prepare(b, n, c);
  Evaluation r;
  r.dt = b.compute_forces(n, dt, c, r.energy);
  c.gather(n.f_int, n.m_int);
  for (std::size_t i = 0; i < n.size(); ++i) {
    const Index k = static_cast<Index>(i);
    r.power += n.f_int.get(k).dot(n.v.get(k));
    if (b.has_moments()) r.power += n.m_int.get(k).dot(n.omega.get(k));
  }
  return r;
}

Real hex_volume(const HexGrid& g, Index e) {
  hex8::NodeMat X;
  for (int k = 0; k < 8; ++k) X.row(k) = g.nodes.x.get(g.conn[8 * e + k]).transpose();
  return hex8::volume(X, hex8::volume_gradient(X));
}

}  // namespace

// v = L x: every element sees D = sym(L) exactly, so the power is beta V (lambda tr(D)^2 + 2 mu D:D)
// summed over the elements, and it is the work rate of the forces the damping stress adds.
TEST(HexStiffnessDamping, AffineVelocityDissipatesBetaDCD) {
  HexGrid g = hex_grid(3, 2, 2, 0.5, 0.08);
  Mat3 L;
  L << 0.3, -0.2, 0.05, 0.1, -0.4, 0.25, -0.15, 0.2, 0.6;
  for (std::size_t i = 0; i < g.nodes.size(); ++i)
    g.nodes.v.set(static_cast<Index>(i), L * g.nodes.x.get(static_cast<Index>(i)));
  const Mat3 D = 0.5 * (L + L.transpose());
  const ElasticSolid mat(kRho, kE, kNu);
  const Real density = mat.lame_lambda() * D.trace() * D.trace() +
                       2.0 * mat.shear_modulus() * (D.array() * D.array()).sum();
  Real volume = 0.0;
  for (Index e = 0; e < static_cast<Index>(g.ids.size()); ++e) volume += hex_volume(g, e);

  HexGrid g0 = g;
  auto plain = hex_block(g0, 0.0);
  const Evaluation u = evaluate(plain, g0.nodes);
  auto damped = hex_block(g, kBeta);
  const Evaluation first = evaluate(damped, g.nodes);
  const Evaluation d = evaluate(damped, g.nodes);  // the same rates again: the last force is this one

  const Real expected = kBeta * volume * density;
  EXPECT_EQ(u.energy.damping_power, 0.0);
  // The power over a step is the trapezoid: the mean of the last damping force's power at these
  // rates and the new one's (none before the first evaluation: half).
  EXPECT_NEAR(first.energy.damping_power, 0.5 * expected, 1e-12 * expected);
  EXPECT_NEAR(d.energy.damping_power, expected, 1e-12 * expected);
  // The damping forces' work rate: f_d . v = -(damping power).
  EXPECT_NEAR(d.power - u.power, -expected, 1e-10 * expected);
  // Not stored: the hourglass and bulk-viscosity terms are untouched.
  EXPECT_EQ(d.energy.hourglass_power, u.energy.hourglass_power);
  EXPECT_EQ(d.energy.viscous_power, u.energy.viscous_power);
}

// A rigid rotation has D = 0: no damping stress, no dissipated power.
TEST(HexStiffnessDamping, RigidRotationIsNotDamped) {
  HexGrid g = hex_grid(3, 2, 2, 0.5, 0.08);
  const Vec3 w(0.7, -1.3, 0.4), v0(0.2, 0.1, -0.3);
  for (std::size_t i = 0; i < g.nodes.size(); ++i)
    g.nodes.v.set(static_cast<Index>(i), v0 + w.cross(g.nodes.x.get(static_cast<Index>(i))));
  HexGrid g0 = g;
  auto plain = hex_block(g0, 0.0);
  evaluate(plain, g0.nodes);
  auto damped = hex_block(g, kBeta);
  const Evaluation d = evaluate(damped, g.nodes);
  // The scale of the damping stress a unit rate would give, for the round-off bounds.
  const Real scale = kBeta * kE * w.norm();
  EXPECT_LT(std::abs(d.energy.damping_power), 1e-13 * scale * w.norm());
  for (std::size_t i = 0; i < g.nodes.size(); ++i)
    EXPECT_LT((g.nodes.f_int.get(static_cast<Index>(i)) - g0.nodes.f_int.get(static_cast<Index>(i))).norm(),
              1e-13 * scale)
        << "node " << i;
}

// At rest the undamped step of a cube of side h is h / c; with damping it is
// (h / c)(sqrt(1 + xi^2) - xi), xi = beta omega_max / 2 = beta c / h.
TEST(HexStiffnessDamping, StepShrinksToTheDampedLimit) {
  const Real h = 0.5;
  const ElasticSolid mat(kRho, kE, kNu);
  const Real c = mat.wave_speed();
  for (Real beta : {1e-4, 2.5e-3, 0.05}) {
    HexGrid g = hex_grid(3, 2, 2, h, 0.0);
    auto damped = hex_block(g, beta);
    const Evaluation d = evaluate(damped, g.nodes);
    const Real xi = beta * c / h;
    const Real expected = (h / c) * (std::sqrt(1.0 + xi * xi) - xi);
    EXPECT_NEAR(d.dt, expected, 1e-12 * expected) << "beta " << beta;
  }
  HexGrid g = hex_grid(3, 2, 2, h, 0.0);
  auto plain = hex_block(g, 0.0);
  EXPECT_NEAR(evaluate(plain, g.nodes).dt, h / c, 1e-12 * h / c);
}

TEST(HexStiffnessDamping, FactoryPassesTheCoefficientAndRejectsANegativeOne) {
  HexGrid g = hex_grid(1, 1, 1, 1.0, 0.0);
  auto b = make_hex_block(1, ElasticSolid(kRho, kE, kNu), {}, {}, g.conn, g.ids, {kBeta});
  const auto* hex = dynamic_cast<const HexBlock<ElasticSolid>*>(b.get());
  ASSERT_NE(hex, nullptr);
  EXPECT_EQ(hex->stiffness_damping().beta, kBeta);
  EXPECT_THROW(make_hex_block(1, ElasticSolid(kRho, kE, kNu), {}, {}, g.conn, g.ids, {-1.0}), InputError);
}

namespace {

/// A flat nx x ny grid of shells of side h in the x-y plane.
struct ShellGrid {
  NodalFields nodes;
  std::vector<Index> conn;
  std::vector<Id> ids;
};

ShellGrid shell_grid(int nx, int ny, Real h) {
  ShellGrid g;
  const auto id = [&](int i, int j) { return static_cast<Index>(i + (nx + 1) * j); };
  g.nodes.resize(static_cast<std::size_t>((nx + 1) * (ny + 1)));
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const Vec3 x(h * i, h * j, 0.0);
      g.nodes.ids[id(i, j)] = id(i, j) + 1;
      g.nodes.x0.set(id(i, j), x);
      g.nodes.x.set(id(i, j), x);
    }
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      g.conn.insert(g.conn.end(), {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      g.ids.push_back(static_cast<Id>(g.ids.size() + 1));
    }
  return g;
}

constexpr Real kT = 0.05;

/// A shell block with no hourglass control and no bulk viscosity.
std::unique_ptr<ElementBlock> shell_block(const ShellGrid& g, Real beta) {
  ShellSection sec;
  sec.thickness = kT;
  sec.hourglass_coefficient = 0.0;
  sec.bulk = BulkViscosity{0.0, 0.0};
  return make_shell_block(1, ElasticShell(kRho, kE, kNu), sec, g.conn, g.ids, StiffnessDamping{beta});
}

}  // namespace

// A uniform membrane stretch rate (a, b): power = beta A t (c11 a^2 + 2 c12 a b + c11 b^2).
TEST(ShellStiffnessDamping, MembraneStretchRateDissipatesBetaEpsCEps) {
  ShellGrid g = shell_grid(3, 2, 0.25);
  const Real a = 0.4, b = -0.15;
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    const Vec3 x = g.nodes.x.get(static_cast<Index>(i));
    g.nodes.v.set(static_cast<Index>(i), Vec3(a * x[0], b * x[1], 0.0));
  }
  auto block = shell_block(g, kBeta);
  const Evaluation d = evaluate(*block, g.nodes);  // dt = 0: no elastic stress increment
  const Real c11 = kE / (1.0 - kNu * kNu), c12 = kNu * c11;
  const Real area = 0.75 * 0.5;
  const Real expected = kBeta * area * kT * (c11 * a * a + 2.0 * c12 * a * b + c11 * b * b);
  EXPECT_NEAR(d.energy.damping_power, expected, 1e-12 * expected);
  EXPECT_NEAR(d.power, -expected, 1e-10 * expected);
}

// Bending, twisting and transverse shear rates too: the work rate of the damping forces and
// moments is minus the reported power, for an arbitrary velocity and angular-velocity field.
TEST(ShellStiffnessDamping, PowerIsTheWorkRateOfTheDampingForcesAndMoments) {
  ShellGrid g = shell_grid(3, 3, 0.25);
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    const Real s = static_cast<Real>(i);
    g.nodes.v.set(static_cast<Index>(i), Vec3(0.1 * std::sin(s), 0.2 * std::cos(2 * s), 0.3 * std::sin(1.3 * s)));
    g.nodes.omega.set(static_cast<Index>(i), Vec3(std::cos(0.7 * s), -std::sin(1.1 * s), 0.5 * std::cos(s)));
  }
  auto block = shell_block(g, kBeta);
  const Evaluation d = evaluate(*block, g.nodes);
  ASSERT_GT(d.energy.damping_power, 0.0);
  EXPECT_NEAR(d.power, -d.energy.damping_power, 1e-10 * d.energy.damping_power);
  auto plain = shell_block(g, 0.0);
  ShellGrid g0 = g;
  EXPECT_EQ(evaluate(*plain, g0.nodes).energy.damping_power, 0.0);
}

// Square shells of side h: len = h / sqrt(2) (area over the diagonal), c the plate wave speed.
TEST(ShellStiffnessDamping, StepShrinksToTheDampedLimit) {
  const Real h = 0.25, len = h / std::sqrt(2.0);
  const Real c = ElasticShell(kRho, kE, kNu).wave_speed();
  ShellGrid g = shell_grid(2, 2, h);
  auto plain = shell_block(g, 0.0);
  EXPECT_NEAR(evaluate(*plain, g.nodes).dt, len / c, 1e-12 * len / c);
  ShellGrid gd = shell_grid(2, 2, h);
  auto damped = shell_block(gd, kBeta);
  const Real xi = kBeta * c / len;
  const Real expected = (len / c) * (std::sqrt(1.0 + xi * xi) - xi);
  EXPECT_NEAR(evaluate(*damped, gd.nodes).dt, expected, 1e-12 * expected);
}

// Above 4096 elements the loops run in parallel chunks: the damped kernels' forces, powers and
// steps are bit-identical at 1 and 2 threads.
TEST(BlockStiffnessDamping, ResultsDoNotDependOnTheThreadCount) {
  const auto hex_run = [](int threads) {
    set_threads(threads);
    HexGrid g = hex_grid(20, 16, 16, 0.1, 0.05);  // 5120 elements
    for (std::size_t i = 0; i < g.nodes.size(); ++i) {
      const Real s = static_cast<Real>(i);
      g.nodes.v.set(static_cast<Index>(i), Vec3(std::sin(s), std::cos(0.3 * s), std::sin(0.7 * s)));
    }
    auto b = hex_block(g, kBeta);
    const Evaluation e = evaluate(b, g.nodes);
    set_threads(max_threads());
    return std::make_pair(e, g.nodes.f_int);
  };
  const auto [h1, f1] = hex_run(1);
  const auto [h2, f2] = hex_run(2);
  EXPECT_GT(h1.energy.damping_power, 0.0);
  EXPECT_EQ(h1.energy.damping_power, h2.energy.damping_power);
  EXPECT_EQ(h1.dt, h2.dt);
  EXPECT_TRUE(f1.x == f2.x && f1.y == f2.y && f1.z == f2.z);

  const auto shell_run = [](int threads) {
    set_threads(threads);
    ShellGrid g = shell_grid(80, 64, 0.05);  // 5120 elements
    for (std::size_t i = 0; i < g.nodes.size(); ++i) {
      const Real s = static_cast<Real>(i);
      g.nodes.v.set(static_cast<Index>(i), Vec3(0.1 * std::sin(s), 0.1 * std::cos(s), 0.2 * std::sin(0.4 * s)));
      g.nodes.omega.set(static_cast<Index>(i), Vec3(std::cos(0.6 * s), std::sin(0.2 * s), 0.0));
    }
    auto b = shell_block(g, kBeta);
    const Evaluation e = evaluate(*b, g.nodes);
    set_threads(max_threads());
    return std::make_pair(e, g.nodes.f_int);
  };
  const auto [s1, g1] = shell_run(1);
  const auto [s2, g2] = shell_run(2);
  EXPECT_GT(s1.energy.damping_power, 0.0);
  EXPECT_EQ(s1.energy.damping_power, s2.energy.damping_power);
  EXPECT_EQ(s1.dt, s2.dt);
  EXPECT_TRUE(g1.x == g2.x && g1.y == g2.y && g1.z == g2.z);
}
