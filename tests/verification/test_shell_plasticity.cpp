// J2 plasticity on Belytschko-Tsay shells in whole runs. (1) A deck's *MAT_PLASTIC_KINEMATIC
// reaches the shells through the registry and the builder: with a yield stress never reached, the
// spec's problem sslide3p runs bit for bit as with *MAT_ELASTIC. (2) The plastic collapse moment
// of a shell cantilever (issue 21): a clamped strip of
// Belytschko-Tsay shells of elastic-perfectly plastic *MAT_PLASTIC_KINEMATIC (ETAN = 0, nu = 0)
// under an end moment ramped quasi-statically with mass damping. The moment is uniform along the
// strip, so the strip bends into a circular arc of curvature kappa = M / (E I) while elastic; the
// moment at which the curvature runs away is the plastic collapse moment. With n_ip through-thickness
// points (abscissae xi_i, weights w_i) the shell's fully plastic moment is
//     M_p,h = sigma_y b t^2 / 4 * sum_i w_i |xi_i|,
// which tends to the beam's sigma_y b t^2 / 4 as n_ip grows (docs/solver.md, "Plasticity").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "slideline/element/block_factory.hpp"
#include "slideline/element/shell_block.hpp"
#include "slideline/material/shell_plasticity.hpp"
#include "slideline/scenarios/sslide.hpp"
#include "slideline/solver/build.hpp"
#include "slideline/solver/output_sink.hpp"
#include "slideline/solver/simulation.hpp"

using namespace slideline;

namespace {

constexpr Real kL = 1.0, kB = 0.25, kT = 0.02, kE = 1.0e4, kSy = 10.0, kRho = 1.0;
constexpr int kNx = 4;

/// The section of a through-thickness rule, in closed form.
struct Section {
  shell_bt::ThicknessRule rule;
  /// The rule's fully plastic moment sigma_y b t^2 / 4 sum w_i |xi_i|.
  Real collapse_moment() const {
    Real s = 0.0;
    for (int i = 0; i < rule.n; ++i) s += rule.w[i] * std::abs(rule.xi[i]);
    return kSy * kB * kT * kT / 4.0 * s;
  }
  /// The moment of the rule's section at the curvature kappa along a monotonic path, each point in
  /// uniaxial stress: b t/2 sum w_i z_i clamp(E z_i kappa, +-sigma_y).
  Real section_moment(Real kappa) const {
    Real m = 0.0;
    for (int i = 0; i < rule.n; ++i) {
      const Real z = 0.5 * kT * rule.xi[i];
      m += rule.w[i] * z * std::clamp(kE * z * kappa, -kSy, kSy);
    }
    return 0.5 * kT * kB * m;
  }
  /// The curvature at which section_moment reaches M (bisection; M below the collapse moment).
  Real section_curvature(Real M) const {
    Real lo = 0.0, hi = 1.0;
    for (int it = 0; it < 200; ++it) (section_moment(0.5 * (lo + hi)) < M ? lo : hi) = 0.5 * (lo + hi);
    return 0.5 * (lo + hi);
  }
};

/// The strip: (kNx + 1) x 2 nodes in the x-y plane, clamped at x = 0, the end moment about y on the
/// two tip nodes given by `moment(t)` (total, force x length).
struct Strip {
  Simulation sim;

  static SimulationSetup make(int nip, shell_bt::ThicknessRuleKind kind, const LoadCurve& moment, Real alpha) {
    SimulationSetup setup;
    setup.nodes.resize(2 * (kNx + 1));
    for (int j = 0; j <= 1; ++j)
      for (int i = 0; i <= kNx; ++i) {
        const Index n = i + (kNx + 1) * j;
        const Vec3 x(kL * i / kNx, kB * j, 0.0);
        setup.nodes.ids[n] = n + 1;
        setup.nodes.x0.set(n, x);
        setup.nodes.x.set(n, x);
      }
    std::vector<Index> conn;
    std::vector<Id> ids;
    for (int i = 0; i < kNx; ++i) {
      conn.insert(conn.end(), {i, i + 1, i + 1 + kNx + 1, i + kNx + 1});
      ids.push_back(i + 1);
    }
    ShellSection sec;
    sec.thickness = kT;
    sec.nip = nip;
    sec.rule = kind;
    const J2Plasticity law({kRho, kE, 0.0, kSy, 0.0, 1.0, 0.0, 0.0});
    setup.blocks.push_back(make_shell_block(1, ShellPlasticity<J2Plasticity>(law), sec, conn, ids, {}));
    SupportGroup clamp;
    clamp.name = "root";
    for (bool rot : {false, true})
      for (Axis a : {Axis::x, Axis::y, Axis::z}) {
        Support s;
        s.name = "root";
        s.axis = a;
        s.rotational = rot;
        s.nodes = {0, kNx + 1};
        clamp.supports.push_back(s);
      }
    setup.supports.push_back(clamp);
    NodalLoad m;
    m.axis = Axis::y;
    m.moment = true;
    m.scale = 0.5;  // each tip node carries half
    m.curve = moment;
    m.nodes = {kNx, 2 * kNx + 1};
    setup.nodal_loads.push_back(m);
    MassDamping d;
    d.alpha = alpha;
    setup.damping.push_back(d);
    setup.controls.end_time = 1e30;
    setup.controls.history_interval = 1e30;
    return setup;
  }

  Strip(int nip, shell_bt::ThicknessRuleKind kind, const LoadCurve& moment, Real alpha)
      : sim(make(nip, kind, moment, alpha)) {
    sim.initialize();
  }

  void run_to(Real t) {
    while (sim.time() < t) sim.step();
  }
  /// The curvature from the slopes of the first and last chords of the edge y = 0 (exact for a
  /// circular arc: a chord's slope is the arc's at the chord's middle).
  Real curvature() const {
    const NodalFields& n = sim.nodes();
    auto slope = [&](Index a) {
      const Vec3 d = n.x.get(a + 1) - n.x.get(a);
      return std::atan2(-d[2], d[0]);
    };
    return (slope(kNx - 1) - slope(0)) / (kL - kL / kNx);
  }
};

/// The first bending frequency of the clamped strip (beam theory), rad/time.
Real omega1() {
  const Real ei = kE * kB * kT * kT * kT / 12.0;
  return 3.516 * std::sqrt(ei / (kRho * kB * kT * kL * kL * kL * kL));
}

struct CollapseRun {
  Real elastic_kappa, elastic_theory, plastic_kappa_mid, plastic_kappa, plastic_theory, kappa_full, runaway_kappa,
      runaway_later;
  Real mp_h, energy_error;
};

/// Ramps the end moment to 0.5 M_e, holds; to `below` M_p,h, holds; to `above` M_p,h, holds.
CollapseRun run_collapse(int nip, shell_bt::ThicknessRuleKind kind, Real below, Real above) {
  // Ramp and hold durations; the damping is half the elastic mode's critical value, about critical
  // for the yielded strip's (lower) tangent stiffness, so it settles near M_p,h too.
  const Real w = omega1(), tr = 8.0 / w, th = 12.0 / w, alpha = 1.4 * w, th2 = 30.0 / w;
  const Real me = kSy * kB * kT * kT / 6.0;
  const Section sec{shell_bt::ThicknessRule::make(nip, kind)};
  const Real mp = sec.collapse_moment();
  const Real m1 = 0.5 * me, m2 = below * mp, m3 = above * mp;
  const Real t1 = tr + th, t2 = t1 + tr + th2, t3 = t2 + tr + 2.0 * th;
  LoadCurve curve({{0.0, 0.0}, {tr, m1}, {t1, m1}, {t1 + tr, m2}, {t2, m2}, {t2 + tr, m3}, {t3 + 1.0, m3}}, "moment");
  Strip s(nip, kind, curve, alpha);
  CollapseRun r{};
  r.mp_h = mp;
  s.run_to(t1);
  r.elastic_kappa = s.curvature();
  r.elastic_theory = m1 / (kE * kB * kT * kT * kT / 12.0);
  s.run_to(t2 - 0.5 * th2);
  r.plastic_kappa_mid = s.curvature();
  s.run_to(t2);
  r.plastic_kappa = s.curvature();
  r.plastic_theory = sec.section_curvature(m2);
  Real zmin = 1.0;  // the innermost point off the mid surface yields last
  for (int i = 0; i < sec.rule.n; ++i)
    if (sec.rule.xi[i] != 0.0) zmin = std::min(zmin, std::abs(sec.rule.xi[i]) * 0.5 * kT);
  r.kappa_full = kSy / (kE * zmin);
  s.run_to(t3 - th);
  r.runaway_kappa = s.curvature();
  s.run_to(t3);
  r.runaway_later = s.curvature();
  r.energy_error = s.sim.energy_error_fraction();
  return r;
}

void report(const char* name, const CollapseRun& r) {
  std::printf("%s: M_p,h / (sigma_y b t^2/4) = %.5f; elastic kappa %.6e vs M/EI %.6e (%+.3f%%); "
              "just below M_p,h kappa %.5e -> %.5e vs section %.5e (%+.2f%%); above M_p,h kappa %.4f -> %.4f "
              "(all points yield at %.4f); energy error %.2e\n",
              name, r.mp_h / (kSy * kB * kT * kT / 4.0), r.elastic_kappa, r.elastic_theory,
              100.0 * (r.elastic_kappa / r.elastic_theory - 1.0), r.plastic_kappa_mid, r.plastic_kappa, r.plastic_theory,
              100.0 * (r.plastic_kappa / r.plastic_theory - 1.0), r.runaway_kappa, r.runaway_later,
              r.kappa_full, r.energy_error);
}

/// The elastic curvature within 0.5% of M / (E I). Just below M_p,h the strip stands: its
/// curvature is at or past the elastic line's and no longer moves over the second half of the hold.
/// Just above M_p,h it folds: over the last half of the hold the curvature grows by a fifth.
/// The uniaxial section curve (plastic_theory) is printed, not asserted: in a plate strip the
/// thickness strain eps_yy = eps_0 + z kappa_yy is linear in z while its plastic part is not, so
/// the yielded points carry a small sigma_yy (0.09 sigma_y at the outer points of 5 Gauss points
/// at 0.99 M_p,h) and the strip is stiffer than a beam's section between first yield and collapse.
/// With 3 points, where the section goes from elastic to fully plastic at once, the two agree.
/// `stands`: whether to assert that the strip settled below M_p,h (with 7 or more points the
/// section's tangent near M_p,h is small and it had not settled within the hold: a finding).
void expect_collapse(const CollapseRun& r, Real below, bool stands = true) {
  EXPECT_NEAR(r.elastic_kappa / r.elastic_theory, 1.0, 0.005);
  EXPECT_GT(r.plastic_kappa, 0.995 * below * r.mp_h / (kE * kB * kT * kT * kT / 12.0));
  if (stands) EXPECT_LT(std::abs(r.plastic_kappa / r.plastic_kappa_mid - 1.0), 0.005);
  EXPECT_GT(r.runaway_kappa, 1.5 * r.plastic_kappa);
  EXPECT_GT(r.runaway_later, 1.2 * r.runaway_kappa);
}

}  // namespace

TEST(ShellPlasticCollapse, EndMomentCollapsesAtTheFullyPlasticMomentGauss5) {
  const CollapseRun r = run_collapse(5, shell_bt::ThicknessRuleKind::gauss, 0.99, 1.01);
  report("5-point Gauss", r);
  expect_collapse(r, 0.99);
  // The rule's fully plastic moment against the beam's sigma_y b t^2 / 4: 0.9449 for 5 Gauss points.
  EXPECT_NEAR(r.mp_h / (kSy * kB * kT * kT / 4.0), 0.94485, 1e-4);
}

TEST(ShellPlasticityDeck, UnreachedYieldRunsAsElastic) {
  // Every *MAT_ELASTIC of sslide3p (its shells; the solids are Mooney-Rivlin) becomes
  // *MAT_PLASTIC_KINEMATIC with the same constants and SIGY = 1e30: the plane-stress law's
  // predictor is the elastic update, so the histories agree bit for bit.
  auto run = [](bool plastic) {
    scenarios::SslideProblem pr = scenarios::make_sslide_problem("sslide3p");
    pr.model.termination.endtim = 0.35;
    int changed = 0;
    if (plastic)
      for (auto& m : pr.model.materials)
        if (const auto* e = std::get_if<model::MatElastic>(&m)) {
          model::MatPlasticKinematic pk;
          pk.mid = e->mid;
          pk.ro = e->ro;
          pk.e = e->e;
          pk.pr = e->pr;
          pk.sigy = 1e30;
          pk.beta = 1.0;
          m = pk;
          ++changed;
        }
    EXPECT_TRUE(!plastic || changed > 0);
    auto sim = build_simulation(pr.model);
    History h;
    sim->run({&h});
    return h;
  };
  const History a = run(false), b = run(true);
  ASSERT_EQ(a.records(), b.records());
  // The plastic run has the plasticity channels of its shell parts besides the elastic run's
  // (docs/output.md), and with the yield never reached they stay 0.
  std::size_t plastic_channels = 0;
  for (const auto& c : b.channels()) {
    if (c.path.rfind("parts/", 0) != 0) continue;
    ++plastic_channels;
    for (std::size_t r = 0; r < b.records(); ++r) ASSERT_EQ(b.value(c.path, r), 0.0) << c.path;
  }
  EXPECT_GT(plastic_channels, 0u);
  ASSERT_EQ(a.channels().size() + plastic_channels, b.channels().size());
  // Bit for bit where the code generation is portable (the sanitized build, -DSLIDELINE_NATIVE=OFF).
  // Under -march=native GCC contracts a*b+c into fused multiply-adds differently in the two inlined
  // updates (tests/CMakeLists.txt), and the contact run amplifies that round-off (7.7e-10 of the
  // channel's largest value by t = 0.35 on this machine's native build; another processor contracts
  // other sums): there each channel must agree to 1e-6 of its largest value, far below what a
  // plastic step would change (order 1).
  std::size_t differ = 0;
  double worst = 0.0;
  for (const auto& c : a.channels()) {
    double scale = 0.0;
    for (std::size_t r = 0; r < a.records(); ++r)
      for (int k = 0; k < c.components; ++k) scale = std::max(scale, std::abs(a.value(c.path, r, k)));
    for (std::size_t r = 0; r < a.records(); ++r)
      for (int k = 0; k < c.components; ++k) {
        const double x = a.value(c.path, r, k), y = b.value(c.path, r, k);
        differ += x != y;
        if (scale > 0.0) worst = std::max(worst, std::abs(x - y) / scale);
      }
  }
#ifdef SLIDELINE_PORTABLE_CODEGEN
  EXPECT_EQ(differ, 0u);
#else
  EXPECT_LE(worst, 1e-6) << differ << " values differ";
  std::printf("native code generation: %zu values differ, worst %.3g of the channel's largest\n", differ, worst);
#endif
}

// How the collapse moment converges with the number of through-thickness points: each rule's
// strip folds at 1.01 M_p,h, and M_p,h / (sigma_y b t^2 / 4) -> 1 (docs/solver.md: the table).
// Below (0.97 M_p,h) the 3- and 5-point strips stand; with 7 or more points the strip was still
// creeping at the end of the hold (2% to 11% over its second half), so that is not asserted.
TEST(ShellPlasticCollapse, SlowCollapseMomentConvergesWithThePointCount) {
  using K = shell_bt::ThicknessRuleKind;
  for (auto [kind, nip] : {std::pair{K::gauss, 3}, std::pair{K::gauss, 7}, std::pair{K::gauss, 9},
                           std::pair{K::gauss, 10}, std::pair{K::lobatto, 5}, std::pair{K::lobatto, 9}}) {
    const CollapseRun r = run_collapse(nip, kind, 0.97, 1.01);
    char name[32];
    std::snprintf(name, sizeof name, "%d-point %s", nip, kind == K::gauss ? "Gauss" : "Lobatto");
    report(name, r);
    expect_collapse(r, 0.97, nip <= 5);
  }
}
