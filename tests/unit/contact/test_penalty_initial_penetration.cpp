// Initial penetrations of a penalty interface (LS-DYNA IGNORE = 0): a slave block started 0.01
// inside its master block is moved out to the surface before the first step (x and x0, so no
// element starts strained), the count and largest move are reported, and the run then carries its
// load stably with a closed energy balance. Two-pass (Type 3) interface on two_blocks.hpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "unit/contact/two_blocks.hpp"
#include "slideline/contact/surface_to_surface_contact.hpp"
#include "slideline/contact/search/fcl_broad_phase.hpp"

using namespace slideline;
using test::ramped_body_load;
using test::TwoBlocks;

namespace {

using Type3 = SurfaceToSurfaceContact<ExponentialCoulomb>;

/// Type 3 between the upper block's bottom (slaves, block 1) and the lower block's top (block 0).
const PenaltyPasses* add_type3(TwoBlocks& m, bool keep_initial_penetrations = false, Real xpene = 0.0) {
  Surface lower_top = m.lower.face(1, true);
  Surface upper_bottom = m.upper.face(0, false);
  upper_bottom.block.assign(upper_bottom.block.size(), 1);  // the upper block's elements
  upper_bottom.part.assign(upper_bottom.part.size(), 2);
  std::vector<Index> slaves = m.upper.layer(0), masters = m.lower.layer(1);
  std::sort(slaves.begin(), slaves.end());
  std::sort(masters.begin(), masters.end());
  PenaltyPassOptions o;
  o.stiffness_scale = 1.0;
  o.keep_initial_penetrations = keep_initial_penetrations;
  o.penetration_check = xpene;
  auto c = std::make_unique<Type3>(
      "type3",
      std::make_unique<PenaltyPass>(slaves, std::vector<Real>(slaves.size(), 0.0), lower_top,
                                    std::make_unique<FclBroadPhase>(), o),
      std::make_unique<PenaltyPass>(masters, std::vector<Real>(masters.size(), 0.0), upper_bottom,
                                    std::make_unique<FclBroadPhase>(), o),
      ExponentialCoulomb{0.3, 0.3, 0.0});
  const PenaltyPasses* p = &c->passes();
  m.setup.contacts.add(std::move(c));
  return p;
}

MassDamping damping(Real alpha) {
  MassDamping d;
  d.alpha = alpha;
  return d;
}

}  // namespace

TEST(PenaltyInitialPenetration, SlaveBlockMovedOutThenRunsStable) {
  TwoBlocks m;
  // Start the upper block 0.01 inside the lower one (both configurations: an unstrained mesh).
  const Real depth = 0.01;
  for (Index n : m.upper.all()) {
    m.setup.nodes.x.y[n] -= depth;
    m.setup.nodes.x0.y[n] -= depth;
  }
  const Real g = 30.0;
  m.setup.body_loads.push_back(ramped_body_load(Axis::y, -g, 2, 0.05));
  m.setup.damping = {damping(40.0)};
  m.setup.controls.end_time = 0.4;
  const PenaltyPasses* c = add_type3(m);
  m.start();

  // Found: the 16 bottom nodes of the upper block below the lower top face (pass 1) and the 2
  // lower top nodes under the upper block above its bottom face (pass 2), 0.01 deep. Moving the
  // 16 out seats the 2 (pass 2 re-reads its gaps after pass 1 moved nodes): 16 moves of 0.01.
  EXPECT_EQ(c->initial_penetration_count(), 18);
  EXPECT_NEAR(c->largest_initial_penetration(), depth, 1e-12);
  EXPECT_EQ(c->moved_node_count(), 16);
  EXPECT_NEAR(c->largest_move(), depth, 1e-12);
  // After the move no slave of either pass is below the other surface, and no displacement or
  // strain was introduced (x = x0 everywhere).
  Real lowest = 0.0;
  for (std::size_t k = 0; k < c->pass_count(); ++k) {
    const PenaltyPass& p = c->pass(k);
    for (std::size_t i = 0; i < p.slaves().size(); ++i)
      if (std::isfinite(p.gap(i))) lowest = std::min(lowest, p.gap(i));
  }
  EXPECT_GE(lowest, -1e-12);
  for (Index n : m.upper.layer(0)) {
    EXPECT_NEAR(m.sim().nodes().x.y[n], 0.5, 1e-12);
    EXPECT_EQ((m.sim().nodes().x.get(n) - m.sim().nodes().x0.get(n)).norm(), 0.0);
  }

  // Runs: no force on the first step, the load carried at the end, energy balance within 1 %.
  ASSERT_TRUE(m.sim().step());
  const ContactAlgorithm& contact = m.sim().contacts()[0];
  const Real first = contact.slave_force().norm();
  Real worst = 0.0, fmax = 0.0;
  while (m.sim().step()) {
    fmax = std::max(fmax, contact.slave_force().norm());
    if (m.sim().time() > 0.05) worst = std::max(worst, std::abs(m.sim().energy().relative_balance_error()));
  }
  const Real load = m.upper_mass() * g;
  std::printf("moved %ld node(s), largest move %.3e; first-step |F| %.3e, max |F| %.4f (load %.3f), "
              "final F_y %.6f, energy balance error max %.3e\n",
              static_cast<long>(c->moved_node_count()), c->largest_move(), first, fmax, load, contact.slave_force()[1],
              worst);
  EXPECT_LT(first, 1e-9 * load);
  EXPECT_LT(fmax, 2.0 * load);
  EXPECT_NEAR(contact.slave_force()[1], load, 0.01 * load);
  EXPECT_LT(worst, 0.01);
}

namespace {

struct Settled {
  std::vector<Real> bottom_y;  ///< y of the upper block's bottom nodes at the end
  Real force_y = 0.0, first = 0.0, load = 0.0;
  Index moved = 0, found = 0;
};

/// The upper block started `depth` inside the lower one, pressed by a ramped body load, damped to
/// rest; IGNORE = 0 (moved out) or 1 (kept).
Settled press(Real depth, bool keep) {
  TwoBlocks m;
  for (Index n : m.upper.all()) {
    m.setup.nodes.x.y[n] -= depth;
    m.setup.nodes.x0.y[n] -= depth;
  }
  const Real g = 30.0;
  m.setup.body_loads.push_back(ramped_body_load(Axis::y, -g, 2, 0.05));
  m.setup.damping = {damping(40.0)};
  m.setup.controls.end_time = 0.4;
  const PenaltyPasses* c = add_type3(m, keep);
  m.start();
  Settled r;
  r.found = c->initial_penetration_count();
  r.moved = c->moved_node_count();
  EXPECT_TRUE(m.sim().step());
  r.first = m.sim().contacts()[0].slave_force().norm();
  while (m.sim().step()) {
  }
  r.force_y = m.sim().contacts()[0].slave_force()[1];
  r.load = m.upper_mass() * g;
  for (Index n : m.upper.layer(0)) r.bottom_y.push_back(m.sim().nodes().x.y[n]);
  return r;
}

}  // namespace

// IGNORE = 1 (LS-DYNA): the penetration found at t = 0 stays as the springs' zero. Nothing moves
// before the first step, no force acts on it, and the block settles under its load exactly
// `depth` lower than the same block started seated (the same springs and elements, the same
// load, measured from another zero). (Not lower than the IGNORE = 0 run of the same start: that
// one moves only the bottom nodes, x and x0, so its bottom elements are `depth` taller and
// compress differently: 1.4e-5 here, against 8e-7 from the seated run.)
TEST(PenaltyInitialPenetration, IgnoreKeepsThePenetrationAsTheSpringsZero) {
  const Real depth = 0.01;
  const Settled seated = press(0.0, false), kept = press(depth, true);
  EXPECT_EQ(kept.found, 18);
  EXPECT_EQ(kept.moved, 0);
  EXPECT_EQ(seated.found, 0);
  EXPECT_LT(kept.first, 1e-9 * kept.load);
  EXPECT_NEAR(kept.force_y, kept.load, 0.01 * kept.load);
  ASSERT_EQ(kept.bottom_y.size(), seated.bottom_y.size());
  Real worst = 0.0;
  for (std::size_t i = 0; i < kept.bottom_y.size(); ++i)
    worst = std::max(worst, std::abs((seated.bottom_y[i] - kept.bottom_y[i]) - depth));
  const Settled moved = press(depth, false);  // IGNORE = 0, for the record
  Real worst_moved = 0.0;
  for (std::size_t i = 0; i < kept.bottom_y.size(); ++i)
    worst_moved = std::max(worst_moved, std::abs((moved.bottom_y[i] - kept.bottom_y[i]) - depth));
  std::printf("IGNORE 1: found %ld, moved %ld; settled %.3e below the seated run's nodes (depth %.3e), "
              "worst deviation %.3e (from the IGNORE 0 run: %.3e)\n",
              static_cast<long>(kept.found), static_cast<long>(kept.moved), seated.bottom_y[0] - kept.bottom_y[0],
              depth, worst, worst_moved);
  EXPECT_LT(worst, 1e-3 * depth);
}

// PENCHK = 1 (LS-DYNA): a node deeper than XPENE x its master segment's thickness (1/20 of a solid
// face's shorter diagonal) is released, on top of the geometric limit every pass applies (half
// the face's diagonal, half its element's thickness). Upper block started 0.2 inside the lower one:
// the lower block's top faces are 0.5 x 0.5 with elements 0.5 thick, so the geometric limit is
// 0.25 and XPENE = 4 gives 4 x 0.7071 / 20 = 0.1414. Without PENCHK the 16 bottom nodes of the
// upper block are found 0.2 deep and moved out before the first step; with XPENE = 4 they are
// released (none found, none moved, and the first step carries no contact force); with XPENE = 8
// (0.2828, above the geometric limit) the geometric limit governs and the 16 are moved out again.
// (The reverse pass finds nothing in all three: the upper block's faces, 0.333 x 0.2, give a
// geometric limit of 0.194 < 0.2.)
TEST(PenaltyInitialPenetration, PenchkReleasesNodesDeeperThanXpeneTimesTheSegmentThickness) {
  const Real depth = 0.2;
  struct Found {
    Index found = 0, moved = 0;
    Real largest = 0.0, first = 0.0;
  };
  const auto start = [&](Real xpene) {
    TwoBlocks m;
    for (Index n : m.upper.all()) {
      m.setup.nodes.x.y[n] -= depth;
      m.setup.nodes.x0.y[n] -= depth;
    }
    m.setup.controls.end_time = 1e-3;
    const PenaltyPasses* c = add_type3(m, false, xpene);
    m.start();
    Found f{c->initial_penetration_count(), c->moved_node_count(), c->largest_initial_penetration(), 0.0};
    EXPECT_TRUE(m.sim().step());
    f.first = m.sim().contacts()[0].slave_force().norm();
    return f;
  };
  const Found off = start(0.0), on = start(4.0), loose = start(8.0);
  std::printf("PENCHK 0: found %ld, moved %ld, deepest %.4f; XPENE 4: found %ld, moved %ld, first-step |F| %.3e; "
              "XPENE 8: found %ld, moved %ld\n",
              static_cast<long>(off.found), static_cast<long>(off.moved), off.largest, static_cast<long>(on.found),
              static_cast<long>(on.moved), on.first, static_cast<long>(loose.found), static_cast<long>(loose.moved));
  EXPECT_EQ(off.found, 16);
  EXPECT_EQ(off.moved, 16);
  EXPECT_NEAR(off.largest, depth, 1e-12);
  EXPECT_EQ(on.found, 0);
  EXPECT_EQ(on.moved, 0);
  EXPECT_EQ(on.first, 0.0);
  EXPECT_EQ(loose.found, 16);
  EXPECT_EQ(loose.moved, 16);
}
