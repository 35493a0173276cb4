// Contact birth and death times (BT, DT of *CONTACT card 2) for every interface type, honoured by
// ContactManager (contact_manager.hpp), on the spec's two-block problems (scenarios/sslide.hpp):
//  - a contact born after the end time runs exactly as the model without it (bitwise);
//  - a contact that dies mid-run releases: from its death on it carries no force and the upper
//    body moves freely under its load;
//  - a tied contact born mid-run ties the bodies where they are at its birth;
//  - DT = 0 on the card is the default (never dies), as a blank field is;
//  - a timed tie runs beside a rigid wall and is refused onto a rigid body.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "slideline/core/error.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/io/keyword_writer.hpp"
#include "slideline/model/model.hpp"
#include "slideline/scenarios/sslide.hpp"
#include "slideline/solver/build.hpp"
#include "slideline/solver/output_sink.hpp"

namespace slideline {
namespace {

using scenarios::SslideProblem;

/// One problem per interface family: type 1, 2, 3 (penalty, Lagrange), 5, 6, 7, 8, 9, 10, 12.
const std::vector<std::string> kProblems = {"sslide1k", "sslide2kt", "sslide3p",   "sslide3l",   "sslide5p",
                                            "sslide6k", "sslide7k",  "sslide8p",   "sslide9pt",  "sslide10pv",
                                            "sslide10lr", "sslide12p", "sslide12l"};

struct Run {
  std::unique_ptr<Simulation> sim;
  History history;
};

/// Runs `m` to `end`. `energy_limit` < 0: the deck's energy-balance stop; else this limit.
std::unique_ptr<Run> run(const model::Model& m, Real end, Real energy_limit = -1.0) {
  BuildOptions o;
  o.end_time = end;
  auto r = std::make_unique<Run>();
  SimulationSetup setup = build_setup(m, o);
  if (energy_limit >= 0.0) setup.controls.energy_error_limit = energy_limit;
  r->sim = std::make_unique<Simulation>(std::move(setup));
  r->sim->run({&r->history});
  return r;
}

/// The y displacement of the pairing's monitored slave node at the last record.
Real slave_uy(const Run& r, const scenarios::SslidePairing& p) {
  const std::string ch = "nodes/" + std::to_string(p.monitor.slave_node) + "/displacement";
  return r.history.value(ch, r.history.records() - 1, 1);
}

class ContactBirthDeath : public ::testing::TestWithParam<std::string> {};

TEST_P(ContactBirthDeath, BornAfterTheEndRunsAsWithoutTheContact) {
  SslideProblem p = scenarios::make_sslide_problem(GetParam());
  model::Model late = p.model, none = p.model;
  for (auto& c : late.contacts) c.bt = 1.0;  // after the end time
  none.contacts.clear();
  const Real end = 0.03;
  const auto a = run(late, end), b = run(none, end);
  ASSERT_EQ(a->sim->cycle(), b->sim->cycle());
  const NodalFields &xa = a->sim->nodes(), &xb = b->sim->nodes();
  ASSERT_EQ(xa.size(), xb.size());
  for (std::size_t i = 0; i < xa.size(); ++i)
    for (int c = 0; c < 3; ++c) ASSERT_EQ(xa.x[c][i], xb.x[c][i]) << "node " << xa.ids[i] << " component " << c;
  for (std::size_t k = 0; k < a->sim->contacts().size(); ++k) EXPECT_FALSE(a->sim->contacts().active(k));
  for (const auto& pair : p.pairings)
    for (Real f : a->history.series("interfaces/" + pair.contact_title + "/slave_force", 1)) ASSERT_EQ(f, 0.0);
}

TEST_P(ContactBirthDeath, DeathMidRunReleases) {
  SslideProblem p = scenarios::make_sslide_problem(GetParam());
  model::Model dying = p.model;
  // End before the tension problems' failure (t = 0.09), so that the held contact still holds.
  const Real death = 0.05, end = 0.08;
  for (auto& c : dying.contacts) c.dt = death;
  // The sudden release is an impulsive load on the upper body: the energy balance, whose kinetic
  // energy is that of the mean of the half-step velocities (docs/solver.md), shows a transient of
  // 5-9% of the little energy in play at the first check after it (measured), which would stop
  // the run; it decays as the body speeds up (<= 0.012% at t = 0.08 for every type, printed).
  const auto held = run(p.model, end), released = run(dying, end, 0.0);
  std::printf("%s: energy balance error after the release %.3g%% at the end\n", GetParam().c_str(),
              100.0 * released->sim->energy_error_fraction());
  EXPECT_LT(released->sim->energy_error_fraction(), 1e-3);
  for (const auto& pair : p.pairings) {
    const std::string ch = "interfaces/" + pair.contact_title + "/slave_force";
    const auto t = released->history.time();
    const auto f = released->history.series(ch, 1), f_held = held->history.series(ch, 1);
    Real before = 0.0, after = 0.0;  // largest |F_y| up to the death and after it
    for (std::size_t r = 0; r < t.size(); ++r) {
      Real& m = t[r] <= death ? before : after;
      m = std::max(m, std::abs(f[r]));
    }
    EXPECT_GT(before, 0.5) << pair.name << ": the interface carried the load before its death";
    EXPECT_EQ(after, 0.0) << pair.name << ": no force after the death";
    EXPECT_GT(std::abs(f_held.back()), 0.5) << pair.name << ": without DT it still carries the load";
    // The load pulls (py < 0) or pushes (py > 0) the released body away along y; the held one stays.
    const Real dir = pair.py > 0.0 ? -1.0 : 1.0;
    EXPECT_GT(dir * slave_uy(*released, pair), 0.05) << pair.name << ": the released body moves with its load";
    EXPECT_LT(std::abs(slave_uy(*held, pair)), 0.02) << pair.name;
  }
}

INSTANTIATE_TEST_SUITE_P(Types, ContactBirthDeath, ::testing::ValuesIn(kProblems),
                         [](const auto& info) { return info.param; });

// A tie born mid-run ties the slaves where they are then: the tension load pulls the upper block
// away until the birth, then the tie holds it there (its distance from the master stays).
TEST(ContactBirthDeath, TieBornMidRunHoldsTheBodiesWhereTheyAre) {
  SslideProblem p = scenarios::make_sslide_problem("sslide2kt");
  // Born at 0.03: the block has been lifted ~0.045 by then, well within the tie search's normal
  // tolerance (0.3 of a master segment's diagonal).
  const Real birth = 0.03;
  for (auto& c : p.model.contacts) c.bt = birth;
  BuildOptions o;
  o.end_time = 0.08;
  auto sim = build_simulation(p.model, o);
  History h;
  sim->run({&h});
  for (const auto& pair : p.pairings) {
    const std::string node = "nodes/" + std::to_string(pair.monitor.slave_node) + "/displacement";
    const auto t = h.time();
    const auto uy = h.series(node, 1);
    Real at_birth = 0.0;
    for (std::size_t r = 0; r < t.size(); ++r)
      if (t[r] <= birth) at_birth = uy[r];
    EXPECT_GT(at_birth, 1e-3) << pair.name << ": free before the birth, the load lifts the block";
    // After the birth the slave follows its master point: its lift changes no more than the lower
    // block's (elastic) stretch.
    EXPECT_NEAR(uy.back(), at_birth, 0.02 + 0.1 * at_birth) << pair.name;
    const auto f = h.series("interfaces/" + pair.contact_title + "/slave_force", 1);
    EXPECT_GT(std::abs(f.back()), 0.5) << pair.name << ": the tie carries the load after its birth";
  }
}

// DT = 0 on the card reads as the default (never dies): a Lagrange interface used to die at t = 0.
TEST(ContactBirthDeath, DeathTimeZeroIsTheDefault) {
  SslideProblem p = scenarios::make_sslide_problem("sslide3l");
  model::Model zero = p.model;
  for (auto& c : zero.contacts) c.dt = 0.0;
  const model::Model read = read_keyword_string(write_keyword_string(zero), "dt_zero.k");
  ASSERT_FALSE(read.contacts.empty());
  for (const auto& c : read.contacts) EXPECT_EQ(c.dt, 1e20);
  const Real end = 0.05;
  const auto a = run(read, end), b = run(p.model, end);
  for (const auto& pair : p.pairings) {
    const std::string ch = "interfaces/" + pair.contact_title + "/slave_force";
    EXPECT_GT(std::abs(a->history.series(ch, 1).back()), 1.0) << pair.name;
    EXPECT_EQ(a->history.series(ch, 1), b->history.series(ch, 1)) << pair.name;
  }
}

// Negative BT/DT (LS-DYNA's dynamic-relaxation forms) are refused naming the card; DT <= BT too.
TEST(ContactBirthDeath, NegativeOrReversedTimesAreRefused) {
  SslideProblem p = scenarios::make_sslide_problem("sslide3p");
  model::Model neg = p.model, rev = p.model;
  neg.contacts.front().bt = -0.1;
  rev.contacts.front().bt = 0.2;
  rev.contacts.front().dt = 0.1;
  try {
    build_simulation(neg);
    FAIL() << "negative BT accepted";
  } catch (const NotImplementedError& e) {
    EXPECT_NE(std::string(e.what()).find("field BT of *CONTACT"), std::string::npos) << e.what();
  }
  try {
    build_simulation(rev);
    FAIL() << "DT before BT accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("field DT of *CONTACT"), std::string::npos) << e.what();
  }
}

// The refusal of a tied interface with BT or DT that a rigid body's mass properties protect (the
// body takes the mass of the slaves tied to it once, at the start) fires for that alone: a model
// whose only nodal constraint is a rigid wall (no body) runs the timed tie, and a tie whose master
// surface is on a rigid body (sslide2kt's shell-on-shell skin made rigid, as sslide10lr's) is
// refused naming the interface, the rigid body and a node of it.
TEST(ContactBirthDeath, TimedTieRunsBesideARigidWallAndIsRefusedOnARigidMaster) {
  SslideProblem p = scenarios::make_sslide_problem("sslide2kt");
  const Real death = 0.05;
  model::Model walled = p.model;
  for (auto& c : walled.contacts) c.dt = death;
  model::RigidWallPlanar wall;
  wall.title = "far_floor";
  // Normal +z (the supports hold x and y, which a wall may not push along), 10 behind the blocks:
  // no node reaches it.
  wall.tail = Vec3(0.0, 0.0, -10.0);
  wall.head = Vec3(0.0, 0.0, -9.0);
  walled.rigid_walls.push_back(wall);
  const auto r = run(walled, 0.08, 0.0);
  for (const auto& pair : p.pairings) {
    const auto t = r->history.time();
    const auto f = r->history.series("interfaces/" + pair.contact_title + "/slave_force", 1);
    for (std::size_t k = 0; k < t.size(); ++k)
      if (t[k] > death) ASSERT_EQ(f[k], 0.0) << pair.name << ": the tie died at DT";
    EXPECT_GT(slave_uy(*r, pair), 0.05) << pair.name << ": released, the tension load lifts the block";
  }
  for (Real f : r->history.series("rigidwalls/far_floor/force", 1)) EXPECT_EQ(f, 0.0);

  model::Model rigid = p.model;
  for (auto& c : rigid.contacts) c.dt = death;
  Id skin = 0;
  for (const auto& pair : p.pairings)
    if (pair.skin_part != 0 && pair.name == "shell_on_shell") skin = pair.skin_part;
  ASSERT_NE(skin, 0);
  rigid.materials.push_back(model::MatRigid{990, 0.1, 1000.0, 0.1, 0.0, 0, 0, "rigid_skin", {}});
  for (auto& part : rigid.parts)
    if (part.pid == skin) part.mid = 990;
  // The supports hold nodes of the skin, which a rigid part refuses (it is held through *MAT_RIGID);
  // the refusal under test comes at initialisation, before any step, so the model needs none.
  rigid.spcs.clear();
  try {
    build_simulation(rigid)->initialize();  // the interfaces find their ties at initialisation
    FAIL() << "a timed tie onto a rigid body was accepted";
  } catch (const NotImplementedError& e) {
    EXPECT_NE(std::string(e.what()).find("master surface is on a rigid body (node "), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("birth or death time (BT, DT)"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace slideline
