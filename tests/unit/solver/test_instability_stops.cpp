// Runs that go wrong stop with an InstabilityError that says where (issue "Trustworthy runs"): a
// non-finite state, an energy balance that has blown up, a collapsing time step. And supports with
// BIRTH/DEATH act only inside their window.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "slideline/core/error.hpp"
#include "slideline/element/block_factory.hpp"
#include "slideline/solver/simulation.hpp"

using namespace slideline;

namespace {

/// One elastic hexahedron [0,1]^3 (ids 1-8, element 7 of part 3), bottom face (z = 0) fixed.
void unit_hex(SimulationSetup& setup) {
  setup.nodes.resize(8);
  const Real xs[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (Index i = 0; i < 8; ++i) {
    setup.nodes.ids[i] = i + 1;
    setup.nodes.x0.set(i, Vec3(xs[i][0], xs[i][1], xs[i][2]));
    setup.nodes.x.set(i, Vec3(xs[i][0], xs[i][1], xs[i][2]));
  }
  HexHourglass hg;
  setup.blocks.push_back(make_hex_block(3, ElasticSolid(1.0, 1000.0, 0.3), hg, BulkViscosity{1.5, 0.06},
                                      {0, 1, 2, 3, 4, 5, 6, 7}, {7}));
  SupportGroup g;
  g.name = "bottom";
  for (int c = 0; c < 3; ++c) {
    Support s;
    s.axis = static_cast<Axis>(c);
    s.nodes = {0, 1, 2, 3};
    g.supports.push_back(s);
  }
  setup.supports.push_back(g);
  setup.controls.end_time = 1.0;
  setup.controls.dt_scale = 0.5;
}

std::string run_until_error(Simulation& sim) {
  try {
    while (sim.step()) {
    }
  } catch (const InstabilityError& e) {
    return e.what();
  }
  return "";
}

/// Pushes its nodes with a force the simulation is not told about (it lists no constrained
/// nodes): the work it does is missing from the balance.
class HiddenPush final : public NodalConstraint {
 public:
  void initialize(NodalFields&, std::span<const Real>) override {}
  void constrain_accelerations(const ConstraintLoads& loads, NodalFields& n, Real) override {
    for (Index i = 4; i < 8; ++i) n.a.set(i, loads.force(i) / loads.mass[i] + Vec3(0.0, 0.0, 5.0));
  }
  void after_positions(std::span<const Real>, NodalFields&, Real) override {}
};

/// A contact stand-in whose stable step halves every cycle.
class ShrinkingStep final : public ContactAlgorithm, public ContactForces {
 public:
  ContactPhases phases() override { return {.forces = this}; }
  const std::string& name() const override { return name_; }
  void initialize(const ContactContext&) override {}
  void apply_forces(const NodalFields&, const StepTimes& t, ContactForceView) override {
    dt_ = 1e-3 * std::pow(0.5, static_cast<Real>(t.cycle));
  }
  Real stable_dt() const override { return dt_; }
  Vec3 slave_force() const override { return Vec3::Zero(); }
  Vec3 master_force() const override { return Vec3::Zero(); }

 private:
  std::string name_ = "shrinking";
  Real dt_ = 1e-3;
};

}  // namespace

TEST(InstabilityStops, NonFiniteStateNamesTheNodeAndElement) {
  SimulationSetup setup;
  unit_hex(setup);
  BodyLoad b;
  b.axis = Axis::z;
  b.scale = std::numeric_limits<Real>::quiet_NaN();
  setup.body_loads.push_back(b);
  Simulation sim(std::move(setup));
  const std::string msg = run_until_error(sim);
  EXPECT_NE(msg.find("non-finite"), std::string::npos) << msg;
  EXPECT_NE(msg.find("node 1"), std::string::npos) << msg;  // the first node (body loads act on all)
  EXPECT_NE(msg.find("element 7 of part 3"), std::string::npos) << msg;
  EXPECT_NE(msg.find("cycle 0"), std::string::npos) << msg;
}

TEST(InstabilityStops, EnergyBalanceBeyondTheLimitStopsTheRun) {
  SimulationSetup setup;
  unit_hex(setup);
  setup.constraints.push_back(std::make_unique<HiddenPush>());
  setup.controls.end_time = 10.0;  // several hundred cycles: the check starts at cycle 100
  Simulation sim(std::move(setup));
  const std::string msg = run_until_error(sim);
  EXPECT_NE(msg.find("energy balance error"), std::string::npos) << msg;
  EXPECT_NE(msg.find("exceeds the limit of 5.0"), std::string::npos) << msg;
  EXPECT_NE(msg.find("element 7 of part 3"), std::string::npos) << msg;
  ASSERT_TRUE(sim.energy_warning().has_value());
  EXPECT_GT(sim.energy_warning()->relative_error, 0.01);
  EXPECT_GE(sim.cycle(), kEnergyCheckStart);
}

TEST(InstabilityStops, TheSameRunWithTheCheckOffRunsToTheEnd) {
  SimulationSetup setup;
  unit_hex(setup);
  setup.constraints.push_back(std::make_unique<HiddenPush>());
  setup.controls.energy_error_limit = 0.0;
  setup.controls.end_time = 10.0;
  Simulation sim(std::move(setup));
  EXPECT_EQ(run_until_error(sim), "");
  EXPECT_GT(sim.energy_error_fraction(), 0.05);  // it did blow up: the limit was what stopped it
}

TEST(InstabilityStops, CollapsingStepStopsAndNamesWhatSetsIt) {
  SimulationSetup setup;
  unit_hex(setup);
  setup.contacts.add(std::make_unique<ShrinkingStep>());
  Simulation sim(std::move(setup));
  const std::string msg = run_until_error(sim);
  EXPECT_NE(msg.find("fell below 0.0001"), std::string::npos) << msg;
  EXPECT_NE(msg.find("contact interface '"), std::string::npos) << msg;
  EXPECT_LT(sim.cycle(), 30);
}

TEST(InstabilityStops, CrushedElementStopsTheRunAndIsNamed) {
  SimulationSetup setup;
  unit_hex(setup);
  // The top face driven down through the whole height in unit time: the element's step shrinks
  // geometrically with its height until it falls below DTMIN x the first step.
  SupportGroup g;
  g.name = "crush";
  Support s;
  s.axis = Axis::z;
  s.nodes = {4, 5, 6, 7};
  s.has_curve = true;
  s.curve = LoadCurve({{0.0, 0.0}, {1.0, -1.0}});
  g.supports.push_back(s);
  setup.supports.push_back(g);
  Simulation sim(std::move(setup));
  const std::string msg = run_until_error(sim);
  EXPECT_NE(msg.find("fell below 0.0001"), std::string::npos) << msg;
  EXPECT_NE(msg.find("hex8 element 7 of part 3"), std::string::npos) << msg;
  EXPECT_LT(sim.time(), 1.0);
}

TEST(SupportWindow, PrescribedMotionActsBetweenBirthAndDeath) {
  SimulationSetup setup;
  unit_hex(setup);
  SupportGroup g;
  g.name = "push";
  Support s;
  s.axis = Axis::x;
  s.nodes = {4, 5, 6, 7};
  s.has_curve = true;
  s.curve = LoadCurve::constant(1.0);
  s.scale = 0.01;
  s.birth = 0.1;
  s.death = 0.2;
  g.supports.push_back(s);
  setup.supports.push_back(g);
  setup.controls.end_time = 0.3;
  setup.controls.history_interval = 0.01;
  MassDamping d;
  d.alpha = 20.0;
  setup.damping = {d};
  Simulation sim(std::move(setup));
  sim.initialize();
  Real max_before = 0.0, max_after_reaction = 0.0;
  Real u_inside = 0.0;
  while (sim.step()) {
    const Real t = sim.time();
    const Real u = sim.nodes().displacement(6)[0];
    const Real r = sim.supports()[1].reaction.norm();
    if (t < 0.1 - 1e-9) max_before = std::max(max_before, std::abs(u) + r);
    if (std::abs(t - 0.15) < 1e-9) u_inside = u;
    if (t > 0.2 + 0.01) max_after_reaction = std::max(max_after_reaction, r);
  }
  EXPECT_EQ(max_before, 0.0);               // nothing before birth
  EXPECT_NEAR(u_inside, 0.01, 1e-12);       // the curve inside the window
  EXPECT_EQ(max_after_reaction, 0.0);       // no reaction after death
  EXPECT_LT(std::abs(sim.nodes().displacement(6)[0] - 0.01), 0.01);  // released, springing back
}
