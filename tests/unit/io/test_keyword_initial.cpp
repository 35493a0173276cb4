// Reading the *INITIAL_VELOCITY family: fixed columns, the exempted card, located errors and the
// reference check. (Every field also goes through the round trip, test_keyword_roundtrip.cpp.)
#include <gtest/gtest.h>

#include <string>

#include "slideline/core/error.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/solver/validate_model.hpp"

namespace slideline {
namespace {

const std::string kMesh =
    "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n"
    "*ELEMENT_SOLID\n1,1,1,2,3,4,5,6,7,8\n*PART\ncube\n1,1,1\n*SECTION_SOLID\n1,1\n*MAT_ELASTIC\n1,1,1000,0.3\n";

TEST(KeywordInitialVelocity, FixedColumnsAndTheExemptedCard) {
  const auto m = read_keyword_string(
      "*KEYWORD\n"
      "*INITIAL_VELOCITY\n"
      "$#    NSID    NSIDEX     BOXID    IRIGID      ICID\n"
      "         3         4         0        -1\n"
      "      10.0      -2.0       0.5       0.0       0.0       1.0\n"
      "      -1.0       0.0       0.0       0.0       2.0       0.0\n"
      "         0\n"
      "       1.0\n"
      "*INITIAL_VELOCITY_NODE\n"
      "         5       0.0       0.0      -1.0\n"
      "         6                          -2.0       0.5\n"
      "*INITIAL_VELOCITY_GENERATION\n"
      "         7         2      50.0       1.0       2.0       3.0\n"
      "       0.5      0.25       0.0       0.0       0.0       1.0\n"
      "*END\n",
      "iv.k");
  ASSERT_EQ(m.initial_velocities.size(), 2u);
  const auto& a = m.initial_velocities[0];
  EXPECT_EQ(a.nsid, 3);
  EXPECT_EQ(a.nsidex, 4);
  EXPECT_EQ(a.irigid, -1);
  EXPECT_EQ(a.v, Vec3(10.0, -2.0, 0.5));
  EXPECT_EQ(a.vr, Vec3(0.0, 0.0, 1.0));
  EXPECT_EQ(a.ve, Vec3(-1.0, 0.0, 0.0));
  EXPECT_EQ(a.vre, Vec3(0.0, 2.0, 0.0));
  EXPECT_EQ(a.at.line, 4);
  // NSIDEX = 0: no exempted card; the next record starts right after card 2.
  EXPECT_EQ(m.initial_velocities[1].nsid, 0);
  EXPECT_EQ(m.initial_velocities[1].v, Vec3(1.0, 0.0, 0.0));
  ASSERT_EQ(m.initial_velocity_nodes.size(), 2u);
  EXPECT_EQ(m.initial_velocity_nodes[1].nid, 6);
  EXPECT_EQ(m.initial_velocity_nodes[1].v, Vec3(0.0, 0.0, -2.0));
  EXPECT_EQ(m.initial_velocity_nodes[1].vr, Vec3(0.5, 0.0, 0.0));
  EXPECT_EQ(m.initial_velocity_nodes[1].at.line, 11);
  ASSERT_EQ(m.initial_velocity_generations.size(), 1u);
  const auto& g = m.initial_velocity_generations[0];
  EXPECT_EQ(g.id, 7);
  EXPECT_EQ(g.styp, 2);
  EXPECT_EQ(g.omega, 50.0);
  EXPECT_EQ(g.v, Vec3(1.0, 2.0, 3.0));
  EXPECT_EQ(g.xc, Vec3(0.5, 0.25, 0.0));
  EXPECT_EQ(g.n, Vec3(0.0, 0.0, 1.0));
  EXPECT_EQ(g.phase, 0);
  EXPECT_EQ(g.irigid, 0);
}

TEST(KeywordInitialVelocity, MissingCardsAreLocatedErrors) {
  const auto what = [](const std::string& deck) {
    try {
      read_keyword_string(deck, "iv.k");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(what("*INITIAL_VELOCITY\n0,2\n1,0,0\n*END\n"),
            "iv.k:2: *INITIAL_VELOCITY: missing exempted-node velocity (NSIDEX > 0) card");
  EXPECT_EQ(what("*INITIAL_VELOCITY_GENERATION\n1,2,3.0\n*END\n"),
            "iv.k:2: *INITIAL_VELOCITY_GENERATION: missing XC YC ZC NX NY NZ PHASE IRIGID card");
  EXPECT_NE(what("*INITIAL_VELOCITY_NODE\n1,fast\n*END\n").find("field VX of *INITIAL_VELOCITY_NODE"), std::string::npos);
}

TEST(KeywordInitialVelocity, DanglingReferencesAreNamed) {
  const auto m = read_keyword_string("*KEYWORD\n" + kMesh +
                                         "*INITIAL_VELOCITY\n8,9,3\n1\n0\n*INITIAL_VELOCITY_GENERATION\n"
                                         "4,2\n\n*INITIAL_VELOCITY_NODE\n99,1\n*END\n",
                                     "iv.k");
  const auto problems = check_references(m);
  ASSERT_EQ(problems.size(), 5u);
  EXPECT_EQ(to_string(problems[0]), "iv.k:21: *INITIAL_VELOCITY NSID refers to undefined node set 8");
  EXPECT_EQ(to_string(problems[1]), "iv.k:21: *INITIAL_VELOCITY NSIDEX refers to undefined node set 9");
  EXPECT_EQ(to_string(problems[2]), "iv.k:21: *INITIAL_VELOCITY BOXID refers to undefined box 3");
  EXPECT_EQ(to_string(problems[3]), "iv.k:25: *INITIAL_VELOCITY_GENERATION ID refers to undefined part 4");
  EXPECT_EQ(to_string(problems[4]), "iv.k:28: *INITIAL_VELOCITY_NODE refers to undefined node 99");
}

}  // namespace
}  // namespace slideline
