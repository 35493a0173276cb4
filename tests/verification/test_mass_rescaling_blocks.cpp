// Mass scaling re-evaluated every cycle (DT2MS with MS1ST = 0 of *CONTROL_TIMESTEP) on every
// deformable block besides the one-point hexahedron (test_mass_rescaling.cpp): Belytschko-Tsay
// shells (mass and rotary inertia), fully integrated hexahedra (ELFORM 2) and tetrahedra (ELFORM 10),
// against closed forms. The strips and their element steps: mass_rescaling_strips.hpp.
//
// A pushed strip shortens by ~20 % over ~10 wave transits; with T = |DT2MS| = 0.95 x the element
// step at rest and DT2MS < 0 an element of step dt_e < T gets the factor f_e = (T / dt_e)^2, its
// added mass m_e (f_e - 1) (a shell's rotary inertia grows by the same factor) and its step becomes
// dt_e sqrt(f_e) = T: once any element is scaled the run's stable step is T (to round-off) and
// its step TSSFAC x T.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "mass_rescaling_strips.hpp"
#include "slideline/core/parallel.hpp"
#include "slideline/solver/output_sink.hpp"

using namespace slideline;
using namespace slideline::strips;

namespace {

constexpr Real kTssfac = 0.9;

/// Runs `model` (one strip or more) with DT2MS = `dt2ms` and MS1ST = 0 or 1 for `cycles` cycles;
/// returns the smallest and largest stable step seen after the first element fell below T, and the
/// largest difference, relative to the kinetic energy, between what a cycle booked in
/// energy/mass_scaling and sum_i 1/2 (m_i' - m_i) |v_i|^2 + 1/2 (J_i' - J_i) |omega_i|^2 (the masses
/// and rotary inertias before and after its re-evaluation, at the velocities v^{n+1/2} it happens at).
struct PushResult {
  Real min_stable = 1e30, max_stable = 0.0, worst_booking = 0.0;
};
PushResult push(StripModel& model, Real dt2ms, bool every_cycle, long cycles) {
  model.setup.controls.dt2ms = dt2ms;
  model.setup.controls.dt_scale = kTssfac;
  model.setup.controls.max_cycles = cycles;
  model.setup.controls.mass_scaling_every_cycle = every_cycle;
  model.start();
  PushResult r;
  const Real target = std::abs(dt2ms);
  const NodalFields& nd = model.sim().nodes();
  for (;;) {
    const std::vector<Real> mass = nd.mass, inertia = nd.rot_inertia;
    const Real booked = model.sim().energy().mass_scaling;
    if (!model.sim().step()) break;
    Real dk = 0.0, k = 0.0;
    for (std::size_t i = 0; i < nd.size(); ++i) {
      dk += 0.5 * (nd.mass[i] - mass[i]) * nd.v.get(i).squaredNorm();
      if (nd.has_rotation[i]) dk += 0.5 * (nd.rot_inertia[i] - inertia[i]) * nd.omega.get(i).squaredNorm();
      k += 0.5 * nd.mass[i] * nd.v.get(i).squaredNorm();
    }
    r.worst_booking = std::max(r.worst_booking, std::abs(model.sim().energy().mass_scaling - booked - dk) / k);
    bool below = false;
    for (const Strip& s : model.strips)
      for (std::size_t e = 0; e < s.elements.size(); ++e) below |= element_step(s, model.sim().nodes(), e) < target;
    if (!below) continue;
    r.min_stable = std::min(r.min_stable, model.sim().stable_dt());
    r.max_stable = std::max(r.max_stable, model.sim().stable_dt());
  }
  return r;
}

/// The cycles that push a strip of `kind` about as far as the hexahedron bar of
/// test_mass_rescaling.cpp (120 cycles of 0.9 x 0.95 h / c).
long cycles_for(Kind kind, Real h) {
  return static_cast<long>(std::ceil(120.0 * h / wave_speed() / reference_step(kind, h)));
}

}  // namespace

// MS1ST = 0 on a pushed strip of shells, of ELFORM 2 hexahedra and of tetrahedra, along x and
// along a rotated axis: the stable step stays T from the first element below T on, the added mass
// is the closed form from the deformed nodes, a shell strip's rotary inertia is the closed form
// sum_e f_e m_e A0 / 12, and the energy balance closes with the kinetic energy the mass changes put
// in (energy/mass_scaling).
TEST(MassRescalingBlocks, PushedStripsKeepTheStepWithTheClosedFormAddedMass) {
  for (Kind kind : {Kind::shell, Kind::hex2, Kind::tet})
    for (const Eigen::Matrix3d& rot : {Eigen::Matrix3d(Eigen::Matrix3d::Identity()), rotation()}) {
      SCOPED_TRACE(std::string(name(kind)) + (rot.isIdentity() ? " along x" : " rotated"));
      StripSpec spec;
      spec.kind = kind;
      spec.r = rot;
      StripModel model({spec}), once({spec});
      const Real target = 0.95 * reference_step(kind, spec.h);
      const PushResult r = push(model, -target, true, cycles_for(kind, spec.h));
      push(once, -target, false, cycles_for(kind, spec.h));  // MS1ST = 1: nothing scaled at rest
      const Simulation& sim = model.sim();
      const Strip& s = model.strips[0];
      EXPECT_NEAR(r.min_stable, target, 1e-12 * target);
      EXPECT_NEAR(r.max_stable, target, 1e-12 * target);
      EXPECT_NEAR(sim.dt(), kTssfac * target, 1e-12 * target);
      Real m0 = 0.0, dt_min = 1.0;
      int below = 0;
      for (std::size_t e = 0; e < s.elements.size(); ++e) {
        m0 += s.mass[e];
        const Real dt_e = element_step(s, sim.nodes(), e);
        dt_min = std::min(dt_min, dt_e);
        below += dt_e < target ? 1 : 0;
      }
      const Real expected = closed_form_added(s, sim, -target);
      const PartAddedMass& p = sim.added_mass().at(0);
      EXPECT_GT(below, static_cast<int>(s.elements.size()) / 2);
      EXPECT_EQ(p.scaled, below);
      EXPECT_NEAR(p.mass, m0, 1e-13 * m0);
      EXPECT_GT(expected, 0.1 * m0);
      EXPECT_NEAR(p.added, expected, 1e-12 * expected);
      EXPECT_NEAR(model.total_mass(), m0 + expected, 1e-12 * m0);
      EXPECT_NEAR(p.smallest_step, dt_min, 1e-12 * target);
      Real inertia = 0.0, inertia0 = 0.0;
      if (kind == Kind::shell) {
        inertia = closed_form_inertia(s, sim, -target);
        for (Real m : s.mass) inertia0 += m * spec.h * spec.h / 12.0;
        EXPECT_GT(inertia, 1.1 * inertia0);
        EXPECT_NEAR(model.total_inertia(), inertia, 1e-12 * inertia);
      }
      // Energy: every cycle books exactly the kinetic energy its mass changes put in; with it the
      // balance error is that of the same push with MS1ST = 1 (nothing scaled: the scheme's own
      // O(dt^2) error of the half-step kinetic energy).
      const EnergyReport& en = sim.energy();
      const EnergyReport& en_once = once.sim().energy();
      EXPECT_EQ(once.sim().added_mass().at(0).added, 0.0);
      EXPECT_LT(r.worst_booking, 1e-14);
      EXPECT_GT(en.mass_scaling, 0.0);
      EXPECT_LT(std::abs(en.relative_balance_error()), 1e-4) << en.balance_error() << " of " << en.support;
      EXPECT_LT(std::abs(en.balance_error()), 2.0 * std::abs(en_once.balance_error()));
      std::printf("%s strip (%s): %zu elements, %d below T; added mass %.10g (closed form %.10g, %.3g of the mass)%s; "
                  "stable step / T - 1 in [%.2g, %.2g]; energy: booked - 1/2 dm v^2 <= %.2g K, mass_scaling %.4g, "
                  "balance error %.3g (MS1ST = 1: %.3g) of support work %.4g\n",
                  name(kind), rot.isIdentity() ? "along x" : "rotated", s.elements.size(), below, p.added, expected,
                  p.added / m0,
                  kind == Kind::shell ? (", rotary inertia x" + std::to_string(inertia / inertia0)).c_str() : "",
                  r.min_stable / target - 1.0, r.max_stable / target - 1.0, r.worst_booking, en.mass_scaling,
                  en.balance_error(), en_once.balance_error(), en.support);
    }
}

// MS1ST = 0 where no element falls below |DT2MS| (a short push, T = half the step at rest): bit for
// bit the run without mass scaling, for shells (rotary inertia included), ELFORM 2 and tetrahedra.
TEST(MassRescalingBlocks, NothingBelowTheTargetIsBitwiseNoMassScaling) {
  for (Kind kind : {Kind::shell, Kind::hex2, Kind::tet}) {
    SCOPED_TRACE(name(kind));
    StripSpec spec;
    spec.kind = kind;
    spec.r = rotation();
    StripModel plain({spec}), scaled({spec});
    scaled.setup.controls.dt2ms = -0.5 * reference_step(kind, spec.h);
    scaled.setup.controls.mass_scaling_every_cycle = true;
    for (StripModel* m : {&plain, &scaled}) {
      m->setup.controls.max_cycles = 30;
      m->start();
    }
    while (plain.sim().step()) ASSERT_TRUE(scaled.sim().step());
    EXPECT_FALSE(scaled.sim().step());
    const NodalFields& a = plain.sim().nodes();
    const NodalFields& b = scaled.sim().nodes();
    EXPECT_GT((a.x.get(a.size() - 1) - a.x0.get(a.size() - 1)).norm(), 0.0);
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a.x.get(i), b.x.get(i)) << i;
      EXPECT_EQ(a.v.get(i), b.v.get(i)) << i;
      EXPECT_EQ(a.omega.get(i), b.omega.get(i)) << i;
      EXPECT_EQ(a.mass[i], b.mass[i]) << i;
      EXPECT_EQ(a.rot_inertia[i], b.rot_inertia[i]) << i;
    }
    EXPECT_EQ(plain.sim().stable_dt(), scaled.sim().stable_dt());
    EXPECT_EQ(plain.sim().energy().values(), scaled.sim().energy().values());
    EXPECT_EQ(scaled.sim().added_mass().at(0).added, 0.0);
    EXPECT_EQ(scaled.sim().energy().mass_scaling, 0.0);
  }
}

// A model of a one-point hexahedron strip (part 1, cells h / sqrt 2, so that its step at rest is
// the shells') and a shell strip (part 2), both pushed: the history channels parts/1/added_mass and
// parts/2/added_mass hold each part's closed form, recorded every cycle; the model's step is T.
TEST(MassRescalingBlocks, MixedHexAndShellPartsReportTheirOwnAddedMass) {
  StripSpec hex, shell;
  hex.kind = Kind::hex1;
  hex.h = 0.1 / std::sqrt(2.0);
  hex.part = 1;
  shell.kind = Kind::shell;
  shell.part = 2;
  shell.origin = Vec3(0.0, 0.0, 1.0);
  shell.r = rotation();
  StripModel model({hex, shell});
  const Real target = 0.95 * reference_step(Kind::shell, shell.h);
  ASSERT_NEAR(reference_step(Kind::hex1, hex.h), reference_step(Kind::shell, shell.h), 1e-15);
  model.setup.controls.dt2ms = -target;
  model.setup.controls.dt_scale = kTssfac;
  model.setup.controls.max_cycles = cycles_for(Kind::shell, shell.h);
  model.setup.controls.mass_scaling_every_cycle = true;
  model.start();
  History h;
  model.sim().run({&h});
  const Simulation& sim = model.sim();
  ASSERT_GT(h.records(), 100u);
  const std::size_t last = h.records() - 1;
  for (int k = 0; k < 2; ++k) {
    const Strip& s = model.strips[static_cast<std::size_t>(k)];
    const Real expected = closed_form_added(s, sim, -target);
    const Real m0 = s.mass[0] * static_cast<Real>(s.elements.size());
    EXPECT_GT(expected, 0.1 * m0) << k;
    EXPECT_NEAR(sim.added_mass().at(static_cast<std::size_t>(k)).added, expected, 1e-12 * expected) << k;
    EXPECT_EQ(h.value("parts/" + std::to_string(k + 1) + "/added_mass", last), sim.added_mass()[k].added) << k;
    // Nothing was scaled at the start (every step at rest 0.95 T^-1 above T); mass is added later.
    EXPECT_EQ(h.value("parts/" + std::to_string(k + 1) + "/added_mass", 0), 0.0) << k;
  }
  EXPECT_NEAR(sim.stable_dt(), target, 1e-12 * target);
  EXPECT_LT(std::abs(sim.energy().relative_balance_error()), 1e-4);
}

// Thread independence: a 64 x 64 shell plate (4096 elements, 4225 nodes) and a block of 5400
// tetrahedra (10 x 10 x 9 cubes), each above the parallel threshold, crushed with DT2MS > 0 (every
// element rescaled every cycle): bit for bit the same histories, masses, rotary inertias and
// positions on 1 and 3 threads.
TEST(MassRescalingBlocks, CrushedShellPlateAndTetBlockAreThreadCountIndependent) {
  const auto run = [](int threads) {
    test_support::StagedSimulation s;
    const Real h = 0.05;
    const int m = 64, np = m + 1;
    const int tx = 10, ty = 10, tz = 9;
    const Index shell_nodes = np * np, tet_nodes = (tx + 1) * (ty + 1) * (tz + 1);
    s.setup.nodes.resize(shell_nodes + tet_nodes);
    const auto sid = [np](int i, int j) { return static_cast<Index>(j * np + i); };
    const auto tid = [&](int i, int j, int k) {
      return shell_nodes + static_cast<Index>((k * (ty + 1) + j) * (tx + 1) + i);
    };
    for (int j = 0; j < np; ++j)
      for (int i = 0; i < np; ++i) {
        const Vec3 p(i * h, j * h, 0.0);
        s.setup.nodes.x0.set(sid(i, j), p);
        s.setup.nodes.x.set(sid(i, j), p);
      }
    for (int k = 0; k <= tz; ++k)
      for (int j = 0; j <= ty; ++j)
        for (int i = 0; i <= tx; ++i) {
          const Vec3 p(i * h, j * h, 1.0 + k * h);
          s.setup.nodes.x0.set(tid(i, j, k), p);
          s.setup.nodes.x.set(tid(i, j, k), p);
        }
    for (Index q = 0; q < static_cast<Index>(s.setup.nodes.size()); ++q) s.setup.nodes.ids[q] = q + 1;
    std::vector<Index> sc, tc;
    std::vector<Id> sids, tids;
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) {
        sc.insert(sc.end(), {sid(i, j), sid(i + 1, j), sid(i + 1, j + 1), sid(i, j + 1)});
        sids.push_back(static_cast<Id>(sids.size() + 1));
      }
    constexpr int kuhn[6][2] = {{1, 2}, {2, 3}, {3, 7}, {7, 4}, {4, 5}, {5, 1}};
    for (int k = 0; k < tz; ++k)
      for (int j = 0; j < ty; ++j)
        for (int i = 0; i < tx; ++i) {
          const Index q[8] = {tid(i, j, k),     tid(i + 1, j, k),     tid(i + 1, j + 1, k),     tid(i, j + 1, k),
                              tid(i, j, k + 1), tid(i + 1, j, k + 1), tid(i + 1, j + 1, k + 1), tid(i, j + 1, k + 1)};
          for (const auto& kk : kuhn) {
            Index t[4] = {q[0], q[kk[0]], q[kk[1]], q[6]};
            Eigen::Matrix3d e;
            for (int c = 0; c < 3; ++c) e.col(c) = s.setup.nodes.x0.get(t[c + 1]) - s.setup.nodes.x0.get(t[0]);
            if (e.determinant() < 0.0) std::swap(t[1], t[2]);
            tc.insert(tc.end(), t, t + 4);
            tids.push_back(static_cast<Id>(100000 + tids.size()));
          }
        }
    ShellSection sec;
    sec.thickness = 0.01;
    s.setup.blocks.push_back(std::make_unique<ShellBlock>(1, ElasticShell(kRho, kE, 0.3), sec, sc, sids));
    s.setup.blocks.push_back(
        std::make_unique<TetBlock<ElasticSolid>>(2, ElasticSolid(kRho, kE, 0.3), BulkViscosity{}, tc, tids));
    // The plate: edge x = 0 held, edge x = L pushed in -x; the tet block: bottom held, top pushed in -z.
    std::vector<Index> left, right, bottom, top;
    for (int j = 0; j < np; ++j) {
      left.push_back(sid(0, j));
      right.push_back(sid(m, j));
    }
    for (int j = 0; j <= ty; ++j)
      for (int i = 0; i <= tx; ++i) {
        bottom.push_back(tid(i, j, 0));
        top.push_back(tid(i, j, tz));
      }
    const auto fixed = [](Axis a, std::vector<Index> nodes) {
      Support f;
      f.axis = a;
      f.nodes = std::move(nodes);
      return f;
    };
    const auto pushed = [&](Axis a, std::vector<Index> nodes) {
      Support p = fixed(a, std::move(nodes));
      p.has_curve = true;
      p.kind = Prescribed::velocity;
      p.curve = LoadCurve::constant(1.0);
      p.scale = -5.0;
      return p;
    };
    s.setup.supports = {SupportGroup{"left", {fixed(Axis::x, left), fixed(Axis::z, left)}, Vec3::Zero()},
                        SupportGroup{"right", {pushed(Axis::x, right)}, Vec3::Zero()},
                        SupportGroup{"bottom", {fixed(Axis::z, bottom)}, Vec3::Zero()},
                        SupportGroup{"top", {pushed(Axis::z, top)}, Vec3::Zero()}};
    s.setup.controls.end_time = 0.0;
    s.setup.controls.max_cycles = 12;
    s.setup.controls.dt2ms = 1.2 * h / wave_speed();
    s.setup.controls.mass_scaling_every_cycle = true;
    const int before = max_threads();
    set_threads(threads);
    s.start();
    std::vector<Real> out;
    while (s.sim().step()) {
      for (Real v : s.sim().energy().values()) out.push_back(v);
      out.push_back(s.sim().energy().mass_scaling);
      out.push_back(s.sim().stable_dt());
      for (const PartAddedMass& p : s.sim().added_mass()) out.push_back(p.added);
    }
    const NodalFields& nd = s.sim().nodes();
    out.insert(out.end(), nd.mass.begin(), nd.mass.end());
    out.insert(out.end(), nd.rot_inertia.begin(), nd.rot_inertia.end());
    out.insert(out.end(), nd.x.x.begin(), nd.x.x.end());
    out.insert(out.end(), nd.x.z.begin(), nd.x.z.end());
    out.insert(out.end(), nd.omega.y.begin(), nd.omega.y.end());
    set_threads(before);
    return out;
  };
  const std::vector<Real> one = run(1), three = run(3);
  ASSERT_EQ(one.size(), three.size());
  EXPECT_TRUE(one == three);
}
