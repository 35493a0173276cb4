// Domain limiting (SBOXID / MBOXID, *DEFINE_BOX): a Type 12 interface whose box leaves out one
// block's nodes and segments puts no force on that block.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "slideline/contact/contact_algorithm.hpp"
#include "slideline/core/error.hpp"
#include "slideline/scenarios/sslide.hpp"
#include "slideline/solver/build.hpp"
#include "slideline/solver/simulation.hpp"

using namespace slideline;
using namespace slideline::scenarios;

namespace {

/// sslide12p's solid_on_solid pairing alone, its upper block lifted 0.1 off the lower one (so a
/// box can tell the blocks apart), run to t = 0.25 under the downward load. Returns the largest
/// |slave force| of the interface and the lowest y of the upper block's nodes.
struct BoxRun {
  Real max_force = 0.0;
  Real lowest_upper_y = 1e300;
};

BoxRun run(Id sboxid) {
  SslideProblem p = make_sslide_problem("sslide12p");
  const SslidePairing pr = p.pairings.front();
  model::Model& m = p.model;
  m.contacts.resize(1);
  std::set<Id> upper;
  for (const auto& e : m.solids)
    if (e.pid == pr.upper_part) upper.insert(e.n.begin(), e.n.end());
  for (auto& n : m.nodes)
    if (upper.count(n.id)) n.x[1] += 0.1;
  // Box 1 holds the lower block (y <= 1) and not the lifted upper one (y >= 1.1).
  m.boxes.push_back({1, "lower block", {-1e3, -1.0, -1e3}, {1e3, 1.05, 1e3}, {}});
  m.contacts[0].sboxid = sboxid;
  m.termination.endtim = 0.25;
  auto sim = build_simulation(m);
  sim->initialize();
  BoxRun r;
  while (sim->step())
    for (const auto& c : sim->contacts()) r.max_force = std::max(r.max_force, c->slave_force().norm());
  for (std::size_t i = 0; i < sim->nodes().size(); ++i)
    if (upper.count(sim->nodes().ids[i])) r.lowest_upper_y = std::min(r.lowest_upper_y, sim->nodes().x.get(static_cast<Index>(i))[1]);
  return r;
}

TEST(ContactBox, Type12BoxExcludingABlockPutsNoForceOnIt) {
  const BoxRun with_box = run(1);
  const BoxRun without = run(0);
  std::printf("type 12 box: max |F| %.3e with the box (upper y min %.3f), %.3e without (upper y min %.3f)\n",
              with_box.max_force, with_box.lowest_upper_y, without.max_force, without.lowest_upper_y);
  // Without the box the lower block stops the upper one; with it the upper block is not in the
  // interface at all and falls into the lower one.
  EXPECT_GT(without.max_force, 1.0);
  EXPECT_GT(without.lowest_upper_y, 0.99);
  EXPECT_EQ(with_box.max_force, 0.0);
  EXPECT_LT(with_box.lowest_upper_y, 0.99);
}

TEST(ContactBox, UndefinedBoxIsAnInputErrorNamingTheCard) {
  SslideProblem p = make_sslide_problem("sslide12p");
  p.model.contacts.resize(1);
  p.model.contacts[0].sboxid = 9;
  p.model.contacts[0].src = {"deck.k", 42};
  try {
    build_simulation(p.model);
    ADD_FAILURE() << "no error for an undefined box";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("deck.k:42"), std::string::npos) << what;
    EXPECT_NE(what.find("SBOXID"), std::string::npos) << what;
    EXPECT_NE(what.find("undefined box 9"), std::string::npos) << what;
  }
}

}  // namespace
