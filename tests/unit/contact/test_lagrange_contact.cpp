// LagrangeContact (forward-increment Lagrange multipliers) and Type 1 sliding only on the small
// two-block model of two_blocks.hpp: closed-form motion, equilibrium forces, interpenetration,
// the static friction peak, a rigid master, the energy ledger and thread-count independence.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

#include "unit/contact/two_blocks.hpp"
#include "slideline/contact/lagrange_contact.hpp"
#include "slideline/core/parallel.hpp"
#include "slideline/scenarios/sslide.hpp"
#include "slideline/solver/build.hpp"

using namespace slideline;
using test::ramped_body_load;
using test::TwoBlocks;

namespace {

/// Type 1 sliding only (bilateral) or Lagrange contact between the blocks.
/// rigid_held: the translations and rotations the rigid lower block holds (as its RigidBody);
/// rotation: the solve turns the rigid master (LagrangeContactSettings::rigid_master_rotation).
template <class Kind>
LagrangeInterface<Kind>* add_interface(TwoBlocks& m, ExponentialCoulomb friction = {},
                                       std::array<int, 3> rigid_held = {0, 0, 0}, bool rotation = true) {
  LagrangeContactSettings s;
  s.rigid_fixed_translations = {{1, rigid_held}};
  s.rigid_fixed_rotations = {{1, rigid_held}};
  s.rigid_master_rotation = rotation;
  s.title = Kind::bilateral ? "sliding_only" : "lagrange";
  s.friction = friction;
  auto c = std::make_unique<LagrangeInterface<Kind>>(s, m.lower.face(1, true), m.upper.layer(0), m.upper.face(0, false));
  LagrangeInterface<Kind>* p = c.get();
  m.setup.contacts.add(std::move(c));
  return p;
}
SlidingOnlyContact* add_sliding_only(TwoBlocks& m) { return add_interface<SlidingOnlyKind>(m); }
LagrangeContact* add_contact(TwoBlocks& m, ExponentialCoulomb friction = {}, std::array<int, 3> rigid_held = {0, 0, 0},
                             bool rotation = true) {
  return add_interface<LagrangeContactKind>(m, friction, rigid_held, rotation);
}

MassDamping damping(Real alpha) {
  MassDamping d;
  d.alpha = alpha;
  return d;
}

/// Runs to the end; returns the largest |relative balance error| after t_from.
Real run(TwoBlocks& m, Real t_from, const std::function<void()>& each = {}) {
  m.start();
  Real worst = 0.0;
  while (m.sim().step()) {
    if (m.sim().time() > t_from) worst = std::max(worst, std::abs(m.sim().energy().relative_balance_error()));
    if (each) each();
  }
  return worst;
}

}  // namespace

TEST(SlidingOnly, FrictionlessSlideFollowsConstantAcceleration) {
  TwoBlocks m;
  const Real a = 5.0;
  m.setup.body_loads.push_back(ramped_body_load(Axis::x, a, 2, 0.0));
  auto* c = add_sliding_only(m);
  m.setup.controls.end_time = 0.3;
  Real worst_balance = 0.0;
  const Real energy = run(m, 0.05, [&] {
    worst_balance = std::max(worst_balance, (c->slave_force() + c->master_force()).norm());
  });
  const Real t = m.sim().time();
  const Vec3 u = m.upper_displacement();
  std::printf("sliding only: u_x %.9f vs a t^2/2 %.9f, max |gap| %.3e, balance %.3e, energy %.3e, sweeps max %d\n",
              u[0], 0.5 * a * t * t, c->max_penetration(), worst_balance, energy, c->solve_stats().max_sweeps);
  EXPECT_NEAR(u[0], 0.5 * a * t * t, 1e-4 * 0.5 * a * t * t);
  EXPECT_LT(c->max_penetration(), 1e-9);  // the normal gap stays zero
  EXPECT_LT(std::abs(u[1]), 1e-6);
  EXPECT_LT(worst_balance, 1e-12);
  EXPECT_LT(energy, 1e-2);
  EXPECT_EQ(c->solve_stats().unconverged, 0);
}

TEST(SlidingOnly, HoldsTheSlaveInTension) {
  // Centred: frictionless, an off-centre block would drift down the slope of the deformed face.
  TwoBlocks m(nullptr, 0.5);
  const Real g = 20.0;  // pulls the upper block away from the lower one
  m.setup.body_loads.push_back(ramped_body_load(Axis::y, g, 2, 0.05));
  m.setup.damping = {damping(40.0)};
  auto* c = add_sliding_only(m);
  m.setup.controls.end_time = 0.8;
  const Real energy = run(m, 0.05);
  const Real load = m.upper_mass() * g;
  std::printf("sliding only in tension: F_y %.6f (load %.3f), max |gap| %.3e, energy %.3e\n", c->slave_force()[1],
              load, c->max_penetration(), energy);
  EXPECT_NEAR(c->slave_force()[1], -load, 1e-5 * load);
  EXPECT_LT(c->max_penetration(), 1e-6);
  EXPECT_LT(energy, 1e-2);
}

TEST(LagrangeContact, BlockRestsWithoutInterpenetration) {
  // With friction, so that the block does not creep down the slope of the deformed face.
  TwoBlocks m;
  const Real g = 30.0;
  m.setup.body_loads.push_back(ramped_body_load(Axis::y, -g, 2, 0.05));
  m.setup.damping = {damping(40.0)};
  auto* c = add_contact(m, ExponentialCoulomb{0.3, 0.3, 0.0});
  m.setup.controls.end_time = 0.8;
  const Real energy = run(m, 0.05);
  const Real load = m.upper_mass() * g;
  std::printf("Lagrange, resting block: F_y %.8f (load %.3f), R_y %.8f, max penetration %.3e, energy %.3e, "
              "sweeps %.1f per solve (max %d)\n",
              c->slave_force()[1], load, m.sim().supports()[0].reaction[1], c->max_penetration(), energy,
              static_cast<double>(c->solve_stats().sweeps) / static_cast<double>(c->solve_stats().solves),
              c->solve_stats().max_sweeps);
  EXPECT_NEAR(c->slave_force()[1], load, 1e-6 * load);
  EXPECT_NEAR(c->master_force()[1], -load, 1e-6 * load);
  EXPECT_LT(c->max_penetration(), 1e-6);
  EXPECT_LT(energy, 1e-2);
  EXPECT_EQ(c->solve_stats().unconverged, 0);
}

namespace {

struct StickSlip {
  Real peak = 0.0, normal_at_peak = 0.0, final_fx = 0.0, final_fy = 0.0, penetration = 0.0, energy = 0.0,
       friction = 0.0;
  Vec3 u = Vec3::Zero();
  std::vector<Real> x;
};

/// Pressed down by N = m g, then pulled in x by a load ramped to 1.3 mu_s N over [0.1, 0.3].
StickSlip run_stick_slip(const ExponentialCoulomb& f) {
  TwoBlocks m;
  const Real g = 30.0;
  m.setup.body_loads.push_back(ramped_body_load(Axis::y, -g, 2, 0.05));
  m.setup.body_loads.push_back(ramped_body_load(Axis::x, 1.3 * f.mu_s * g, 2, 0.2, 0.1));
  m.setup.damping = {damping(20.0)};
  auto* c = add_contact(m, f);
  m.setup.controls.end_time = 0.45;
  StickSlip r;
  r.energy = run(m, 0.05, [&] {
    if (std::abs(c->slave_force()[0]) > r.peak) {
      r.peak = std::abs(c->slave_force()[0]);
      r.normal_at_peak = c->slave_force()[1];
    }
  });
  r.final_fx = c->slave_force()[0];
  r.final_fy = c->slave_force()[1];
  r.penetration = c->max_penetration();
  r.friction = m.sim().energy().friction;
  r.u = m.upper_displacement();
  r.x = m.sim().nodes().x.x;
  return r;
}

}  // namespace

TEST(LagrangeContact, CoulombStickSlipReachesTheStaticPeak) {
  const ExponentialCoulomb f{0.3, 0.25, 1.3};
  const StickSlip r = run_stick_slip(f);
  std::printf("stick-slip: peak |F_x| %.5f = %.4f mu_s N (N at peak %.5f), final F_x %.5f (mu_k N %.5f), slid %.4f, "
              "friction work %.5f, penetration %.3e, energy %.3e\n",
              r.peak, r.peak / (f.mu_s * r.normal_at_peak), r.normal_at_peak, r.final_fx, f.mu_k * r.final_fy, r.u[0],
              r.friction, r.penetration, r.energy);
  EXPECT_NEAR(r.peak, f.mu_s * r.normal_at_peak, 0.02 * f.mu_s * r.normal_at_peak);
  EXPECT_GT(r.u[0], 0.01);  // it did slip
  EXPECT_LT(r.final_fx, -f.mu_k * r.final_fy * 0.99);
  EXPECT_GT(r.final_fx, -f.mu_s * r.final_fy * 1.01);
  EXPECT_GT(r.friction, 0.0);
  EXPECT_LT(r.penetration, 1e-6);
  EXPECT_LT(r.energy, 1e-2);
}

TEST(LagrangeContact, ResultsDoNotDependOnTheThreadCount) {
  const ExponentialCoulomb f{0.3, 0.25, 1.3};
  const int before = max_threads();
  set_threads(1);
  const StickSlip one = run_stick_slip(f);
  set_threads(4);
  const StickSlip four = run_stick_slip(f);
  set_threads(before);
  ASSERT_EQ(one.x.size(), four.x.size());
  for (std::size_t i = 0; i < one.x.size(); ++i) EXPECT_EQ(one.x[i], four.x[i]) << "node " << i;
  EXPECT_EQ(one.final_fx, four.final_fx);
  EXPECT_EQ(one.friction, four.friction);
}

TEST(LagrangeContact, RigidMasterCarriesTheLoad) {
  const std::array<int, 6> fixed{1, 1, 1, 1, 1, 1};
  TwoBlocks m(&fixed);
  const Real g = 30.0;
  m.setup.body_loads.push_back(ramped_body_load(Axis::y, -g, 2, 0.05));
  m.setup.damping = {damping(40.0)};
  auto* c = add_contact(m, {}, {1, 1, 1});
  m.setup.controls.end_time = 0.4;
  const Real energy = run(m, 0.05);
  const Real load = m.upper_mass() * g;
  std::printf("rigid fixed master: F_y %.8f, rigid reaction %.8f (load %.3f), penetration %.3e, energy %.3e\n",
              c->slave_force()[1], m.rigid->reaction_force()[1], load, c->max_penetration(), energy);
  EXPECT_NEAR(c->slave_force()[1], load, 1e-4 * load);
  EXPECT_NEAR(m.rigid->reaction_force()[1], -load, 2e-3 * load);
  EXPECT_LT(c->max_penetration(), 1e-9);
  EXPECT_LT(energy, 1e-2);
}

TEST(LagrangeContact, FreeRigidMasterIsPushedWithoutLag) {
  // The upper block centred over the rigid body: rotations of a rigid master are left to the
  // simulation's update after the solve (docs/contact.md), so this checks the translation.
  const std::array<int, 6> free{0, 0, 0, 0, 0, 0};
  TwoBlocks m(&free, 0.5);
  const Real g = 30.0;
  m.setup.body_loads.push_back(ramped_body_load(Axis::y, -g, 2, 0.0));
  auto* c = add_contact(m);
  m.setup.controls.end_time = 0.2;
  run(m, 0.0);
  // Only the body load acts on the pair: total momentum = its impulse; no interpenetration
  // although the rigid master moves within every step.
  const Real t = m.sim().time() + 0.5 * m.sim().dt();
  Real p = 0.0;
  for (std::size_t i = 0; i < m.sim().nodes().size(); ++i) p += m.sim().nodes().mass[i] * m.sim().nodes().v.y[i];
  const Real impulse = -m.upper_mass() * g * t;
  std::printf("free rigid master: momentum %.8f vs impulse %.8f, rigid v_y %.5f, penetration %.3e\n", p, impulse,
              m.rigid->velocity()[1], c->max_penetration());
  EXPECT_NEAR(p, impulse, 1e-6 * std::abs(impulse));
  EXPECT_LT(m.rigid->velocity()[1], -0.1);
  EXPECT_LT(c->max_penetration(), 1e-6);
}

TEST(LagrangeContact, RotatingRigidMasterLagIsSecondOrderInTheStep) {
  // The upper block over the left half of a free rigid body: the contact force turns the body
  // (about z) as well as pushing it. With the rotation switched off the solve moves a rigid master
  // as one translating mass and leaves its rotation to the update after the solve
  // (enforcement/lagrange.hpp), so each step's gap is missed by the turn that step's contact
  // torque adds, ~ dt^2 r^2 F / I: an error of one step that the next solve removes, not one that
  // accumulates. Measured here at two steps. With the rotation in the solve (the default):
  // test_lagrange_rigid_rotation.cpp.
  struct Lag {
    Real penetration, omega, dt;
  };
  const auto measure = [](Real dt_max) {
    const std::array<int, 6> free{0, 0, 0, 0, 0, 0};
    TwoBlocks m(&free, 0.0);
    m.setup.controls.dt_max = dt_max;
    m.setup.body_loads.push_back(ramped_body_load(Axis::y, -30.0, 2, 0.0));
    auto* c = add_contact(m, {}, {0, 0, 0}, false);
    m.setup.controls.end_time = 0.2;
    run(m, 0.0);
    return Lag{c->max_penetration(), m.rigid->angular_velocity().norm(), m.sim().dt()};
  };
  const Lag coarse = measure(2e-4), fine = measure(1e-4);
  std::printf("rotating rigid master: dt %.3g: penetration %.3e, |omega| %.4f; dt %.3g: penetration %.3e, |omega| %.4f\n",
              coarse.dt, coarse.penetration, coarse.omega, fine.dt, fine.penetration, fine.omega);
  EXPECT_GT(coarse.omega, 0.1);  // the body does turn
  EXPECT_LT(coarse.penetration, 1e-6);
  // Second order: halving the step divides the lag by ~4 (3 to 5 allows for the dt the run
  // really takes and the load history).
  EXPECT_GT(coarse.penetration, 3.0 * fine.penetration);
  EXPECT_LT(coarse.penetration, 5.0 * fine.penetration);
}

TEST(LagrangeContact, SingleSurfaceKeepsOneConstraintPerMutualPair) {
  // sslide12l solid_on_solid to t = 0.25: every node is a slave and every segment a master, so
  // the two lower top-face nodes under the block project onto the block's face while the block's
  // nodes project onto the lower segments around them. Kept: only the block's 16 nodes (the finer
  // side on the coarser side's segments); the solve then converges in ~13 sweeps per cycle
  // (both kept: ~130, lagrange_contact.hpp).
  auto problem = scenarios::make_sslide_problem("sslide12l");
  problem.model.termination.endtim = 0.25;
  auto sim = build_simulation(problem.model);
  sim->run({});
  const LagrangeContact* c = nullptr;
  for (const auto& a : sim->contacts())
    if (a->name() == "solid_on_solid") c = dynamic_cast<const LagrangeContact*>(a.get());
  ASSERT_NE(c, nullptr);
  const auto cs = c->constraints();
  ASSERT_EQ(cs.size(), 16u);
  const auto holds = [](const LagrangeConstraint& k, Index node) {
    return std::find(k.master.begin(), k.master.end(), node) != k.master.end();
  };
  for (const auto& a : cs)
    for (const auto& b : cs)
      EXPECT_FALSE(&a != &b && holds(a, b.slave) && holds(b, a.slave)) << a.slave << " and " << b.slave;
  const auto& st = c->solve_stats();
  const double per_solve = static_cast<double>(st.sweeps) / static_cast<double>(st.solves);
  std::printf("sslide12l solid_on_solid: %zu constraints, %.1f sweeps per cycle (max %d)\n", cs.size(), per_solve,
              st.max_sweeps);
  EXPECT_EQ(st.unconverged, 0);
  EXPECT_LT(per_solve, 30.0);
}
