// The owned parts of the step (issue 19, "the lean step"): the one total-force sum, the pure
// central-difference update against its closed form, node roles, and the exchange points a
// distributed run will implement (docs/architecture.md, "The time step").
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "slideline/core/error.hpp"
#include "slideline/core/parallel.hpp"
#include "slideline/element/block_factory.hpp"
#include "slideline/solver/central_difference.hpp"
#include "slideline/solver/simulation.hpp"
#include "slideline/solver/total_force.hpp"

using namespace slideline;

namespace {

NodalFields one_node(Real mass) {
  NodalFields n;
  n.resize(1);
  n.mass[0] = mass;
  return n;
}

}  // namespace

TEST(TotalForce, AddsInternalExternalContactInThatOrder) {
  // (1e16 - 1e16) + 1 = 1, but 1e16 + (-1e16 + 1) = 0: the order of the sum shows.
  NodalFields n = one_node(1.0);
  n.f_int.x[0] = 1e16;
  n.f_ext.x[0] = -1e16;
  n.f_contact.x[0] = 1.0;
  n.m_int.y[0] = 2.0;
  n.m_ext.y[0] = 3.0;
  n.m_contact.y[0] = 4.0;
  EXPECT_EQ(total_force(n, 0, 0), 1.0);
  EXPECT_EQ(total_force<false>(n, 0, 0), 0.0);  // without contact the contact field is not read
  EXPECT_EQ(total_moment(n, 1, 0), 9.0);
  EXPECT_EQ(total_moment<false>(n, 1, 0), 5.0);
}

TEST(CentralDifference, DampedFreeNodeMatchesClosedForm) {
  const Real m = 2.0, f = 3.0, alpha = 4.0, v0 = 0.5, dt_prev = 0.01, dt_next = 0.02;
  NodalFields n = one_node(m);
  n.f_ext.x[0] = f;
  n.v.x[0] = v0;
  NodeRoles roles;
  roles.assign_rigid(1, {});
  roles.assign_supports(1, {}, 0.0);
  form_accelerations(n, false, false);
  EXPECT_EQ(n.a.x[0], f / m);
  const std::vector<Real> damping{alpha};
  std::vector<NodalEnergySums> chunks(static_cast<std::size_t>(chunk_count(1)));
  const Real dt_avg = 0.5 * (dt_prev + dt_next);
  const NodalEnergySums e =
      update_velocities(n, roles, damping, VelocityStep{dt_prev, dt_avg, dt_next, false, false}, chunks);
  const Real h = 0.5 * alpha * dt_avg;
  const Real v1 = ((1.0 - h) * v0 + dt_avg * f / m) / (1.0 + h);
  EXPECT_NEAR(n.v.x[0], v1, 1e-15);
  const Real vbar = 0.5 * (v0 + v1);
  EXPECT_NEAR(e.kinetic, 0.5 * m * vbar * vbar, 1e-15);
  // The external force's work over the half steps either side of t^n.
  EXPECT_NEAR(e.external.before, f * 0.5 * dt_prev * v0, 1e-15);
  EXPECT_NEAR(e.external.after, f * 0.5 * dt_next * v1, 1e-15);
  // Damping dissipates alpha m vbar^2 dt over the two halves.
  EXPECT_NEAR(e.damping.before + e.damping.after, alpha * m * vbar * (0.5 * dt_prev * v0 + 0.5 * dt_next * v1),
              1e-15);
  update_positions(n, dt_next);
  EXPECT_NEAR(n.x.x[0], dt_next * v1, 1e-15);
}

TEST(CentralDifference, SupportedComponentTakesItsAccelerationUndamped) {
  NodalFields n = one_node(1.0);
  n.v.y[0] = 1.0;
  SupportGroup g;
  g.name = "s";
  Support s;
  s.axis = Axis::y;
  s.nodes = {0};
  g.supports.push_back(s);
  NodeRoles roles;
  roles.assign_rigid(1, {});
  roles.assign_supports(1, {g}, 0.0);
  n.a.y[0] = -1.0 / 0.01;  // what prescribe_supports sets to land on v = 0
  const std::vector<Real> damping{100.0};
  std::vector<NodalEnergySums> chunks(static_cast<std::size_t>(chunk_count(1)));
  update_velocities(n, roles, damping, VelocityStep{0.0, 0.01, 0.02, true, false}, chunks);
  // v = 1 + 0.01 (-1 / 0.01) = 0 to round-off (the product may be fused); damped as a free
  // component (h = 0.5) it would be -1/3.
  EXPECT_NEAR(n.v.y[0], 0.0, 1e-15);
}

TEST(NodeRoles, SupportsWithBirthAndDeathActOnlyInTheirWindow) {
  SupportGroup g;
  g.name = "timed";
  Support s;
  s.axis = Axis::z;
  s.nodes = {1};
  s.birth = 0.5;
  s.death = 1.0;
  g.supports.push_back(s);
  const std::vector<SupportGroup> groups{g};
  NodeRoles roles;
  roles.assign_rigid(3, {});
  roles.assign_supports(3, groups, 0.0);
  EXPECT_TRUE(roles.has_timed_supports());
  EXPECT_EQ(roles.fixed(2)[1], 0);
  roles.refresh_supports(groups, 0.75);
  EXPECT_EQ(roles.fixed(2)[1], 1);
  EXPECT_EQ(roles.fixed(2)[0], 0);
  roles.refresh_supports(groups, 1.5);
  EXPECT_EQ(roles.fixed(2)[1], 0);
  EXPECT_THROW(roles.assign_supports(1, groups, 0.0), InputError);  // node 1 of a 1-node model
}

namespace {

/// Counts the exchange calls and halves the stable step, as a process whose neighbour votes for
/// half of this one's step would see it.
class CountingExchange final : public Exchange {
 public:
  struct Counts {
    int forces = 0, dt = 0, energies = 0, block_energies = 0;
  };
  explicit CountingExchange(Counts& c) : c_(c) {}
  void sum_forces(NodalFields&) override { ++c_.forces; }
  StepVotes min_dt(const StepVotes& local) override {
    ++c_.dt;
    StepVotes v = local;
    v.elements = 0.5 * local.elements;
    return v;
  }
  void sum_energies(NodalEnergySums&, Real&) override { ++c_.energies; }
  void sum_block_energies(std::span<BlockEnergy>) override { ++c_.block_energies; }
  Real sum_reset_work(Real local) override { return local; }

 private:
  Counts& c_;
};

/// Two processes holding the same elements and nodes: every sum is twice this process's.
class DoublingExchange final : public Exchange {
 public:
  void sum_forces(NodalFields&) override {}
  StepVotes min_dt(const StepVotes& local) override { return local; }
  void sum_energies(NodalEnergySums&, Real&) override {}
  void sum_block_energies(std::span<BlockEnergy> blocks) override {
    for (auto& b : blocks) {
      b.hourglass_power *= 2.0;
      b.viscous_power *= 2.0;
      b.damping_power *= 2.0;
      b.element_power *= 2.0;
    }
  }
  Real sum_reset_work(Real local) override { return 2.0 * local; }
};

/// One free elastic hexahedron [0,1]^3 moving at unit speed in x, for `cycles` cycles.
SimulationSetup free_hex(long cycles) {
  SimulationSetup setup;
  setup.nodes.resize(8);
  for (Index i = 0; i < 8; ++i) {
    const Vec3 x(Real(i & 1), Real((i >> 1) & 1), Real((i >> 2) & 1));
    setup.nodes.ids[i] = i + 1;
    setup.nodes.x0.set(i, x);
    setup.nodes.x.set(i, x);
    setup.nodes.v.set(i, Vec3(1.0, 0.0, 0.0));
  }
  setup.blocks.push_back(make_hex_block(1, ElasticSolid(1.0, 1000.0, 0.3), HexHourglass{}, BulkViscosity{1.5, 0.06},
                                        {0, 1, 3, 2, 4, 5, 7, 6}, {1}));
  setup.controls.end_time = 1.0;
  setup.controls.max_cycles = cycles;
  return setup;
}

}  // namespace

TEST(Exchange, TheStepCallsItsThreePointsAndTakesTheReducedStep) {
  Simulation plain(free_hex(10));
  plain.initialize();
  CountingExchange::Counts counts;
  Simulation sim(free_hex(10), std::make_unique<CountingExchange>(counts));
  sim.initialize();
  EXPECT_EQ(counts.forces, 1);  // the forces at t = 0
  EXPECT_EQ(counts.dt, 1);
  EXPECT_GT(plain.stable_dt(), 0.0);
  EXPECT_EQ(sim.stable_dt(), 0.5 * plain.stable_dt());
  while (sim.step()) {
  }
  // Ten cycles evaluate the forces at their end; the eleventh records t^10 and stops. Every
  // cycle books its energies.
  EXPECT_EQ(sim.cycle(), 10);
  EXPECT_EQ(counts.forces, 11);
  EXPECT_EQ(counts.dt, 11);
  EXPECT_EQ(counts.energies, 11);
  EXPECT_EQ(counts.block_energies, 11);
  // A rigid translation at unit speed: the centre moved by the time elapsed.
  Real mean_ux = 0.0;
  for (Index i = 0; i < 8; ++i) mean_ux += sim.nodes().displacement(i)[0] / 8.0;
  EXPECT_NEAR(mean_ux, sim.time(), 1e-12);
}

TEST(Exchange, ElementEnergiesPerPartAndInTotalComeFromTheReducedPowers) {
  // A stretch in x with a small hourglass mode on it: hourglass, bulk-viscosity and stored
  // energies all nonzero.
  const auto hourglassing_hex = [] {
    SimulationSetup setup = free_hex(3);  // a few cycles: a free element so set going stops with "inverted" by cycle 10
    for (Index i = 0; i < 8; ++i) {
      const Real hg = (((i & 1) + ((i >> 1) & 1) + ((i >> 2) & 1)) % 2) ? 1e-4 : -1e-4;
      setup.nodes.v.set(i, Vec3((i & 1 ? 1e-3 : -1e-3) + hg, 0.0, 0.0));
    }
    // Doubled element energies against one process's nodal work: not a balance to stop on.
    setup.controls.energy_error_limit = 1e30;
    setup.controls.energy_error_warning = 1e30;
    return setup;
  };
  Simulation plain(hourglassing_hex());
  plain.run({});
  Simulation twice(hourglassing_hex(), std::make_unique<DoublingExchange>());
  twice.run({});
  ASSERT_EQ(twice.cycle(), plain.cycle());
  ASSERT_GT(plain.energy().hourglass, 0.0);
  ASSERT_GT(plain.part_energies().internal_energy(0), 0.0);
  // The motion is this process's own; the energies are the reduced powers', exactly twice.
  EXPECT_EQ(twice.energy().hourglass, 2.0 * plain.energy().hourglass);
  EXPECT_EQ(twice.energy().bulk_viscosity, 2.0 * plain.energy().bulk_viscosity);
  EXPECT_EQ(twice.part_energies().hourglass_energy(0), 2.0 * plain.part_energies().hourglass_energy(0));
  EXPECT_EQ(twice.part_energies().internal_energy(0), 2.0 * plain.part_energies().internal_energy(0));
}
