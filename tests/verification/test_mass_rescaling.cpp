// Mass scaling re-evaluated every cycle (DT2MS with MS1ST = 0 of *CONTROL_TIMESTEP,
// solver/mass_rescaling.hpp) against closed forms.
//
// The bar: n cubes of side h along the axis a (x, or a rotated axis), elastic with nu = 0 (wave
// speed c = sqrt(E / rho), no lateral stress, so the cross-section stays h x h), no bulk viscosity,
// one end held, the other pushed along -a at v_p. An element of current length l <= h along a is a
// box of volume l h^2 whose largest face is h^2, so its stable step is dt_e = (l h^2 / h^2) / c =
// l / c. With T = |DT2MS| and DT2MS < 0 it gets the factor f_e = (T / dt_e)^2 when dt_e < T (else
// 1), its added mass is m_e (f_e - 1), m_e = rho h^3, and its step becomes dt_e sqrt(f_e) = T: once
// any element is scaled the run's stable step is T exactly (to round-off), and the step TSSFAC x T.
// With MS1ST = 1 (scaled once, at the start, where every dt_e = h / c > T) nothing is scaled and
// the stable step follows the shortest element, min l_e / c < T.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "slideline/core/error.hpp"
#include "slideline/core/parallel.hpp"
#include "slideline/element/hex_block.hpp"
#include "slideline/material/elastic.hpp"
#include "slideline/solver/simulation.hpp"
#include "test_support/staged_simulation.hpp"

using namespace slideline;

namespace {

constexpr Real kH = 0.1, kRho = 1.0, kE = 1.0e4;

/// The bar along R e_x (R a rotation), node k of plane i at 4 i + k.
struct PushedBar : test_support::StagedSimulation {
  int n;
  Eigen::Matrix3d r;
  PushedBar(int elements, const Eigen::Matrix3d& rotation, Real push_speed, Real nu = 0.0)
      : n(elements), r(rotation) {
    setup.nodes.resize(4 * (n + 1));
    for (int i = 0; i <= n; ++i)
      for (int c = 0; c < 4; ++c) {
        const Index k = 4 * i + c;
        const Vec3 p = r * Vec3(i * kH, (c == 1 || c == 2) ? kH : 0.0, c >= 2 ? kH : 0.0);
        setup.nodes.ids[k] = k + 1;
        setup.nodes.x0.set(k, p);
        setup.nodes.x.set(k, p);
      }
    std::vector<Index> conn;
    std::vector<Id> ids;
    for (int i = 0; i < n; ++i) {
      const Index a = 4 * i, b = 4 * (i + 1);
      conn.insert(conn.end(), {a + 0, b + 0, b + 1, a + 1, a + 3, b + 3, b + 2, a + 2});
      ids.push_back(i + 1);
    }
    setup.blocks.push_back(std::make_unique<HexBlock<ElasticSolid>>(
        1, ElasticSolid(kRho, kE, nu), HexHourglass{}, BulkViscosity{0.0, 0.0}, conn, ids));
    // End 0 held in every direction; end n pushed at v_p along -R e_x.
    SupportGroup held{"held", {}, Vec3::Zero()}, pushed{"pushed", {}, Vec3::Zero()};
    const Vec3 dir = r.col(0);
    for (int c = 0; c < 3; ++c) {
      Support fix;
      fix.axis = static_cast<Axis>(c);
      fix.nodes = {0, 1, 2, 3};
      held.supports.push_back(fix);
      Support push = fix;
      push.nodes = {4 * n, 4 * n + 1, 4 * n + 2, 4 * n + 3};
      push.has_curve = true;
      push.kind = Prescribed::velocity;
      push.curve = LoadCurve::constant(1.0);
      push.scale = -push_speed * dir[c];
      pushed.supports.push_back(push);
    }
    setup.supports = {held, pushed};
    for (int c = 0; c < 4; ++c) setup.nodes.v.set(4 * n + c, -push_speed * dir);  // no jump at t = 0
    setup.controls.end_time = 0.0;
  }
  static Real wave_speed() { return std::sqrt(kE / kRho); }
  /// Current length of element e along the bar's axis (its planes stay planes normal to it).
  Real length(int e) const {
    const auto& x = sim().nodes().x;
    return (x.get(4 * (e + 1)) - x.get(4 * e)).dot(r.col(0));
  }
  /// Element e's stable step from its deformed geometry: V / A_max / c, V the volume of the
  /// trilinear hexahedron (2 x 2 x 2 Gauss points integrate its det J, a polynomial of degree <= 2
  /// in each coordinate, exactly), A_max the largest face area 1/2 |d1 x d2| (d1, d2 the face's
  /// diagonals; exact for a plane face). For the ideal box this is l / c; the pushed bar is a box
  /// to ~1e-9 only: compressed far past Euler's load (stress ~0.2 E against pi^2 E h^2 / (12 L^2)
  /// ~ 0.008 E) it amplifies round-off into a bending of that size, so the closed form is
  /// evaluated on the actual nodes.
  Real element_step(int e) const {
    const auto& x = sim().nodes().x;
    const Index a = 4 * e, b = 4 * (e + 1);
    const std::array<Index, 8> q{a + 0, b + 0, b + 1, a + 1, a + 3, b + 3, b + 2, a + 2};
    constexpr int sx[8] = {-1, 1, 1, -1, -1, 1, 1, -1}, sy[8] = {-1, -1, 1, 1, -1, -1, 1, 1},
                  sz[8] = {-1, -1, -1, -1, 1, 1, 1, 1};
    const Real g = 1.0 / std::sqrt(3.0);
    Real volume = 0.0;
    for (int p = 0; p < 8; ++p) {
      const Real xi = g * sx[p], eta = g * sy[p], zeta = g * sz[p];
      Eigen::Matrix3d jac = Eigen::Matrix3d::Zero();
      for (int k = 0; k < 8; ++k) {
        const Vec3 d(sx[k] * (1 + sy[k] * eta) * (1 + sz[k] * zeta), sy[k] * (1 + sx[k] * xi) * (1 + sz[k] * zeta),
                     sz[k] * (1 + sx[k] * xi) * (1 + sy[k] * eta));
        jac += x.get(q[static_cast<std::size_t>(k)]) * (d / 8.0).transpose();
      }
      volume += jac.determinant();
    }
    constexpr int faces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    Real area = 0.0;
    for (const auto& f : faces) {
      const Vec3 d1 = x.get(q[f[2]]) - x.get(q[f[0]]), d2 = x.get(q[f[3]]) - x.get(q[f[1]]);
      area = std::max(area, 0.5 * d1.cross(d2).norm());
    }
    return volume / area / wave_speed();
  }
  /// The closed-form added mass sum_e m_e ((T / dt_e)^2 - 1) over the elements with dt_e < T.
  Real closed_form_added(Real target) const {
    Real added = 0.0;
    for (int e = 0; e < n; ++e) {
      const Real dt_e = element_step(e);
      if (dt_e < target) added += kRho * kH * kH * kH * ((target / dt_e) * (target / dt_e) - 1.0);
    }
    return added;
  }
  Real total_mass() const {
    Real m = 0.0;
    for (Real v : sim().nodes().mass) m += v;
    return m;
  }
};

Eigen::Matrix3d rotation() {
  return (Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, -0.5).normalized()) * Eigen::AngleAxisd(-0.3, Vec3::UnitZ()))
      .toRotationMatrix();
}

bool has_channel(const Simulation& s, const std::string& name) {
  const auto& c = s.channels();
  return std::any_of(c.begin(), c.end(), [&](const HistoryChannel& h) { return h.path == name; });
}

/// Pushes a 10-element bar at v_p = 2 (c = 100) for `cycles` cycles with DT2MS = -0.95 h/c and
/// TSSFAC 0.9: about 20% shorter at the end, every element below T. `every_cycle`: MS1ST = 0.
/// Checks the step at every cycle; returns the smallest stable step seen after the first element
/// fell below T.
struct PushResult {
  Real min_stable = 0.0, max_stable = 0.0;
};
PushResult push(PushedBar& bar, bool every_cycle, long cycles) {
  const Real target = 0.95 * kH / PushedBar::wave_speed();
  bar.setup.controls.dt2ms = -target;
  bar.setup.controls.dt_scale = 0.9;
  bar.setup.controls.max_cycles = cycles;
  bar.setup.controls.mass_scaling_every_cycle = every_cycle;
  bar.start();
  PushResult r{1e30, 0.0};
  while (bar.sim().step()) {
    bool any_below = false;
    for (int e = 0; e < bar.n; ++e) any_below |= bar.length(e) / PushedBar::wave_speed() < target;
    if (!any_below) continue;
    r.min_stable = std::min(r.min_stable, bar.sim().stable_dt());
    r.max_stable = std::max(r.max_stable, bar.sim().stable_dt());
  }
  return r;
}

}  // namespace

// MS1ST = 0: once elements shrink below T the stable step stays T (to round-off; the run's step
// TSSFAC x T) and the added mass is the closed form from the deformed lengths, in the bar along x
// and in a rotated copy; the kinetic energy the mass changes put in (energy/mass_scaling) closes
// the energy balance. MS1ST = 1 on the same push lets the step fall below T.
TEST(MassRescaling, PushedBarKeepsTheStepWithTheClosedFormAddedMass) {
  const Real target = 0.95 * kH / PushedBar::wave_speed();
  const long cycles = 120;
  PushedBar once(10, Eigen::Matrix3d::Identity(), 2.0);
  const PushResult r1 = push(once, false, cycles);
  // l ~ 0.8 h at the end: the step follows the shortest element, min dt_e (= min l_e / c to the
  // bending's 1e-9), well below T.
  Real dt_once = 1.0, lmin_once = kH;
  for (int e = 0; e < once.n; ++e) {
    dt_once = std::min(dt_once, once.element_step(e));
    lmin_once = std::min(lmin_once, once.length(e));
  }
  EXPECT_NEAR(once.sim().stable_dt(), dt_once, 1e-12 * target);
  EXPECT_NEAR(once.sim().stable_dt(), lmin_once / PushedBar::wave_speed(), 1e-7 * target);
  EXPECT_LT(r1.min_stable, 0.9 * target);
  EXPECT_EQ(once.sim().added_mass().at(0).added, 0.0);
  for (const Eigen::Matrix3d& rot : {Eigen::Matrix3d(Eigen::Matrix3d::Identity()), rotation()}) {
    PushedBar bar(10, rot, 2.0);
    const PushResult r = push(bar, true, cycles);
    EXPECT_NEAR(r.min_stable, target, 1e-12 * target);
    EXPECT_NEAR(r.max_stable, target, 1e-12 * target);
    EXPECT_NEAR(bar.sim().dt(), 0.9 * target, 1e-12 * target);
    // Every element is below T at the end (the closed form then adds mass for all ten).
    for (int e = 0; e < bar.n; ++e) EXPECT_LT(bar.length(e), 0.9 * kH) << e;
    const Real m0 = kRho * kH * kH * kH * bar.n;
    const Real expected = bar.closed_form_added(target);
    const PartAddedMass& p = bar.sim().added_mass().at(0);
    EXPECT_EQ(p.scaled, 10);
    EXPECT_NEAR(p.mass, m0, 1e-13 * m0);
    EXPECT_NEAR(p.added, expected, 1e-12 * expected);
    EXPECT_GT(expected, 0.3 * m0);  // (0.95 / 0.8)^2 - 1 ~ 0.4 per element
    EXPECT_NEAR(bar.total_mass(), m0 + expected, 1e-10 * m0);
    // The smallest element step before the factors, from the shortest element.
    Real dt_min = 1.0;
    for (int e = 0; e < bar.n; ++e) dt_min = std::min(dt_min, bar.element_step(e));
    EXPECT_NEAR(p.smallest_step, dt_min, 1e-12 * target);
    // Energy: the mass changes put kinetic energy in (energy/mass_scaling, 3.1e-3 here); booked,
    // the balance error is that of the same push without mass scaling (measured 5.7e-5 and
    // 7.9e-5 of the support's work 1.7: the O(dt^2) of the half-step kinetic energy), 50 times
    // smaller than the term; unbooked it would be 3.1e-3.
    const EnergyReport& en = bar.sim().energy();
    const EnergyReport& en_once = once.sim().energy();
    EXPECT_GT(en.mass_scaling, 0.0);
    EXPECT_LT(std::abs(en.relative_balance_error()), 1e-4) << en.balance_error() << " of " << en.support;
    EXPECT_LT(std::abs(en.balance_error()), 2.0 * std::abs(en_once.balance_error()));
    EXPECT_GT(std::abs(en.mass_scaling), 20.0 * std::abs(en.balance_error()));
    std::printf("pushed bar (%s): added mass %.10g (closed form %.10g, %.3g of the mass), stable step / T - 1 in "
                "[%.2g, %.2g]; energy: mass_scaling %.4g, balance error %.3g (MS1ST = 1: %.3g) of support work %.4g\n",
                rot.isIdentity() ? "along x" : "rotated", p.added, expected, p.added / m0, r.min_stable / target - 1.0,
                r.max_stable / target - 1.0, en.mass_scaling, en.balance_error(), en_once.balance_error(), en.support);
    EXPECT_TRUE(has_channel(bar.sim(), "energy/mass_scaling"));
    EXPECT_TRUE(has_channel(bar.sim(), "parts/1/added_mass"));
  }
  EXPECT_FALSE(has_channel(once.sim(), "parts/1/added_mass"));
}

// MS1ST = 0 where no element falls below |DT2MS| (a 5% push, T = h / 2c): the run is bit for bit
// the run without mass scaling (factors exactly 1, masses the physical ones).
TEST(MassRescaling, NothingBelowTheTargetIsBitwiseNoMassScaling) {
  PushedBar plain(10, rotation(), 2.0), scaled(10, rotation(), 2.0);
  scaled.setup.controls.dt2ms = -0.5 * kH / PushedBar::wave_speed();
  scaled.setup.controls.mass_scaling_every_cycle = true;
  for (PushedBar* b : {&plain, &scaled}) {
    b->setup.controls.max_cycles = 30;
    b->start();
  }
  while (plain.sim().step()) ASSERT_TRUE(scaled.sim().step());
  EXPECT_FALSE(scaled.sim().step());
  const NodalFields& a = plain.sim().nodes();
  const NodalFields& b = scaled.sim().nodes();
  EXPECT_GT(std::abs(a.x.x[4 * 10] - a.x0.x[4 * 10]), 0.0);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a.x.get(i), b.x.get(i)) << i;
    EXPECT_EQ(a.v.get(i), b.v.get(i)) << i;
    EXPECT_EQ(a.mass[i], b.mass[i]) << i;
  }
  EXPECT_EQ(plain.sim().stable_dt(), scaled.sim().stable_dt());
  EXPECT_EQ(plain.sim().energy().values(), scaled.sim().energy().values());
  EXPECT_EQ(scaled.sim().added_mass().at(0).added, 0.0);
  EXPECT_EQ(scaled.sim().energy().mass_scaling, 0.0);
}

// ENDMAS during the run: nothing is added at the start, so initialize() passes; once the pushed
// bar's added mass passes 5% of its mass the run stops as a DTMIN stop does (InstabilityError,
// exit 4 in the CLI), naming ENDMAS, at that cycle.
TEST(MassRescaling, EndmasStopsTheRunWhenTheAddedMassPassesIt) {
  PushedBar bar(10, Eigen::Matrix3d::Identity(), 2.0);
  bar.setup.controls.added_mass_limit_percent = 5.0;
  const Real target = 0.95 * kH / PushedBar::wave_speed();
  bar.setup.controls.dt2ms = -target;
  bar.setup.controls.max_cycles = 200;
  bar.setup.controls.mass_scaling_every_cycle = true;
  bar.start();
  try {
    while (bar.sim().step()) {
    }
    FAIL() << "expected the ENDMAS stop";
  } catch (const InstabilityError& e) {
    EXPECT_NE(std::string(e.what()).find("ENDMAS"), std::string::npos) << e.what();
    EXPECT_GT(e.cycle(), 10);
    const Real m0 = kRho * kH * kH * kH * bar.n;
    EXPECT_GT(bar.sim().added_mass().at(0).added, 0.05 * m0);
    EXPECT_NEAR(bar.sim().added_mass().at(0).added, bar.closed_form_added(target), 1e-10 * m0);
  }
}

// Thread independence: a 16^3 hex block (4096 elements, 4913 nodes: every loop above the parallel
// threshold) crushed with DT2MS > 0 (every element rescaled every cycle) runs bit for bit on 1 and
// 3 threads.
TEST(MassRescaling, CrushedBlockIsThreadCountIndependent) {
  const int m = 16;
  const auto run = [&](int threads) {
    test_support::StagedSimulation s;
    const int np = m + 1;
    s.setup.nodes.resize(np * np * np);
    const auto id = [np](int i, int j, int k) { return static_cast<Index>((k * np + j) * np + i); };
    for (int k = 0; k < np; ++k)
      for (int j = 0; j < np; ++j)
        for (int i = 0; i < np; ++i) {
          const Index q = id(i, j, k);
          const Vec3 p(i * kH, j * kH, k * kH);
          s.setup.nodes.ids[q] = q + 1;
          s.setup.nodes.x0.set(q, p);
          s.setup.nodes.x.set(q, p);
        }
    std::vector<Index> conn;
    std::vector<Id> ids;
    std::vector<Index> bottom, top;
    for (int k = 0; k < m; ++k)
      for (int j = 0; j < m; ++j)
        for (int i = 0; i < m; ++i) {
          conn.insert(conn.end(), {id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
                                   id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
          ids.push_back(static_cast<Id>(ids.size() + 1));
        }
    for (int j = 0; j < np; ++j)
      for (int i = 0; i < np; ++i) {
        bottom.push_back(id(i, j, 0));
        top.push_back(id(i, j, m));
      }
    s.setup.blocks.push_back(std::make_unique<HexBlock<ElasticSolid>>(1, ElasticSolid(kRho, kE, 0.3), HexHourglass{},
                                                                      BulkViscosity{}, conn, ids));
    Support fix;
    fix.axis = Axis::z;
    fix.nodes = bottom;
    Support crush = fix;
    crush.nodes = top;
    crush.has_curve = true;
    crush.kind = Prescribed::velocity;
    crush.curve = LoadCurve::constant(1.0);
    crush.scale = -5.0;
    s.setup.supports = {SupportGroup{"bottom", {fix}, Vec3::Zero()}, SupportGroup{"top", {crush}, Vec3::Zero()}};
    s.setup.controls.end_time = 0.0;
    s.setup.controls.max_cycles = 20;
    s.setup.controls.dt2ms = 1.2 * kH / PushedBar::wave_speed();
    s.setup.controls.mass_scaling_every_cycle = true;
    const int before = max_threads();
    set_threads(threads);
    s.start();
    std::vector<Real> out;
    while (s.sim().step()) {
      for (Real v : s.sim().energy().values()) out.push_back(v);
      out.push_back(s.sim().energy().mass_scaling);
      out.push_back(s.sim().stable_dt());
      out.push_back(s.sim().added_mass().at(0).added);
    }
    const NodalFields& nd = s.sim().nodes();
    out.insert(out.end(), nd.mass.begin(), nd.mass.end());
    out.insert(out.end(), nd.x.z.begin(), nd.x.z.end());
    out.insert(out.end(), nd.v.x.begin(), nd.v.x.end());
    set_threads(before);
    return out;
  };
  const std::vector<Real> one = run(1), three = run(3);
  ASSERT_EQ(one.size(), three.size());
  EXPECT_TRUE(one == three);
  // The masses are the scaled ones (DT2MS > 0 with T = 1.2 h / sqrt(E / rho), above the elements'
  // steps ~ h / c_dilatational: f ~ 2): an interior node, physical mass rho h^3, has gained.
  const Real interior = one[one.size() - 3 * 4913 + (8 * 17 + 8) * 17 + 8];
  EXPECT_GT(interior, 1.5 * kRho * kH * kH * kH);
}
