// The control cards whose fields change the physics (*CONTROL_SHELL, *CONTROL_ACCURACY,
// *CONTROL_SOLID, *CONTROL_BULK_VISCOSITY): each field at its default passes silently, one that
// would change the answer is refused naming file, line and field, never warned about as tuning.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "slideline/core/error.hpp"
#include "slideline/element/shell_block.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/solver/build.hpp"

namespace slideline {
namespace {

std::string refusal(const std::string& cards) {
  try {
    read_keyword_string("*KEYWORD\n" + cards + "*END\n", "c.k");
  } catch (const NotImplementedError& e) {
    return e.what();
  }
  return "(not refused)";
}

TEST(KeywordControls, DefaultsAndZerosReadSilently) {
  const std::string zeros = "0,0,0,0,0,0,0,0\n";
  const std::vector<std::string> decks = {
      "*CONTROL_SHELL\n" + zeros + zeros + zeros + zeros, "*CONTROL_SHELL\n20,0,-1,0,2,2,1,0\n1,0,0,1,0\n",
      "*CONTROL_ACCURACY\n0,1,0,0,0\n", "*CONTROL_ACCURACY\n\n", "*CONTROL_SOLID\n" + zeros + zeros,
      "*CONTROL_SOLID\n0,0,4,1\n", "*CONTROL_BULK_VISCOSITY\n1.5,0.06,1,0\n", "*CONTROL_BULK_VISCOSITY\n1.5,0.06,-1\n",
      "*CONTROL_BULK_VISCOSITY\n1.5,0.06,-2\n", "*CONTROL_SHELL\n",
      // OSU = 1 (objective updates, PIDOSU its part set): every update here is objective already
      // (test_j2_plasticity.cpp: a rigid rotation turns the stress exactly).
      "*CONTROL_ACCURACY\n1,1,7\n"};
  for (const std::string& cards : decks) {
    std::vector<Diagnostic> warnings;
    EXPECT_NO_THROW(read_keyword_string("*KEYWORD\n" + cards + "*END\n", "c.k", &warnings)) << cards;
    EXPECT_TRUE(warnings.empty()) << cards << (warnings.empty() ? "" : to_string(warnings[0]));
  }
  const auto m = read_keyword_string("*KEYWORD\n*CONTROL_BULK_VISCOSITY\n1.2,0.05,1\n*END\n", "c.k");
  EXPECT_EQ(m.bulk_viscosity.q1, 1.2);
  EXPECT_EQ(m.bulk_viscosity.q2, 0.05);
}

TEST(KeywordControls, PhysicsFieldsAreRefusedNamingLineAndField) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"*CONTROL_SHELL\n0,0,0,2\n", "c.k:3: *CONTROL_SHELL card 1: field ISTUPD = 2 (shell thickness change)"},
      {"*CONTROL_SHELL\n0,0,0,3\n", "c.k:3: *CONTROL_SHELL card 1: field ISTUPD = 3 (shell thickness change)"},
      {"*CONTROL_SHELL\n0,0,0,-1\n", "c.k:3: *CONTROL_SHELL card 1: field ISTUPD = -1 (shell thickness change)"},
      {"*CONTROL_SHELL\n0,0,0,0,16\n", "c.k:3: *CONTROL_SHELL card 1: field THEORY = 16"},
      {"*CONTROL_SHELL\n\n0,0,1\n", "c.k:4: *CONTROL_SHELL card 2: field LAMSHT = 1"},
      {"*CONTROL_ACCURACY\n0,1,0,1\n", "c.k:3: *CONTROL_ACCURACY card 1: field IACC = 1"},
      {"*CONTROL_SOLID\n0,1\n", "c.k:3: *CONTROL_SOLID card 1: field FMATRX = 1"},
      {"*CONTROL_SOLID\n2\n", "c.k:3: *CONTROL_SOLID card 1: field ESORT = 2 is not implemented"},
      {"*CONTROL_BULK_VISCOSITY\n1.5,0.06,2\n", "c.k:3: *CONTROL_BULK_VISCOSITY card 1: field TYPE = 2"},
      {"*CONTROL_ACCURACY\n0\n1\n", "c.k:4: *CONTROL_ACCURACY: a card after card 1 is not read"},
  };
  for (const auto& [cards, expected] : cases) {
    const std::string what = refusal(cards);
    EXPECT_EQ(what.rfind(expected, 0), 0u) << cards << "\n" << what;
  }
}

TEST(KeywordControls, TuningFieldsWarnNamingTheField) {
  std::vector<Diagnostic> warnings;
  read_keyword_string("*KEYWORD\n*CONTROL_SHELL\n15\n*CONTROL_SOLID\n0,0,0,2\n*END\n", "c.k", &warnings);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(to_string(warnings[0]).find("c.k:3: *CONTROL_SHELL card 1: field WRPANG = 15"), std::string::npos);
  EXPECT_NE(to_string(warnings[1]).find("c.k:5: *CONTROL_SOLID card 1: field SWLOCL = 2"), std::string::npos);
}

// Mass scaling: DT2MS, MS1ST and ENDMAS are read; MS1ST = 0 (mass scaling every cycle, LS-DYNA's
// default) and blank are honoured without a warning; MS1ST outside 0, 1 is refused naming line
// and field.
TEST(KeywordControls, MassScalingFieldsAreReadAndMs1stZeroIsHonoured) {
  std::vector<Diagnostic> warnings;
  auto m = read_keyword_string("*KEYWORD\n*CONTROL_TIMESTEP\n0,0.8,0,0,-1e-4,0,0,1\n*CONTROL_TERMINATION\n1,0,0,0,5\n*END\n",
                               "c.k", &warnings);
  EXPECT_EQ(m.timestep.dt2ms, -1e-4);
  EXPECT_EQ(m.timestep.ms1st, 1);
  EXPECT_EQ(m.termination.endmas, 5.0);
  EXPECT_TRUE(warnings.empty()) << (warnings.empty() ? "" : to_string(warnings[0]));
  for (const char* card : {"0,0.8,0,0,-1e-4\n", "0,0.8,0,0,-1e-4,0,0,0\n", "0,0.8,0,0,-1e-4,0,0,\n"}) {
    warnings.clear();
    m = read_keyword_string(std::string("*KEYWORD\n*CONTROL_TIMESTEP\n") + card + "*END\n", "c.k", &warnings);
    EXPECT_EQ(m.timestep.dt2ms, -1e-4) << card;
    EXPECT_EQ(m.timestep.ms1st, 0) << card;
    EXPECT_TRUE(warnings.empty()) << card << (warnings.empty() ? "" : to_string(warnings[0]));
  }
  EXPECT_EQ(m.termination.endmas, 1e8);
  try {
    read_keyword_string("*KEYWORD\n*CONTROL_TIMESTEP\n0,0.8,0,0,-1e-4,0,0,2\n*END\n", "c.k");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("c.k:3: *CONTROL_TIMESTEP card 1: field MS1ST = 2"), std::string::npos)
        << e.what();
  }
}

// *CONTROL_SHELL ESORT is stored: 0 and 1 run triangles (N3 = N4) as C0 triangles, which is
// ESORT 1; 2 (DKT triangles) is refused by the part checks when a deformable part has triangles
// (naming the card's line, the part and a triangle), and passes where there are none; 3 is refused
// by the reader.
TEST(KeywordControls, ShellEsortTwoIsRefusedWhereTrianglesRun) {
  const auto deck = [](const std::string& esort, bool triangle) {
    return std::string("*KEYWORD\n*CONTROL_TERMINATION\n1.0\n*CONTROL_SHELL\n20,") + esort +
           "\n*SECTION_SHELL\n1,2\n0.1\n*MAT_ELASTIC\n1,1.0,1000.0,0.3\n*PART\nplate\n1,1,1\n*NODE\n1,0,0,0\n2,1,0,0\n"
           "3,1,1,0\n4,0,1,0\n*ELEMENT_SHELL\n" +
           (triangle ? "7,1,1,2,3,3\n" : "7,1,1,2,3,4\n") + "*END\n";
  };
  EXPECT_EQ(read_keyword_string(deck("1", true), "c.k").shell_esort, 1);
  EXPECT_NO_THROW(build_simulation(read_keyword_string(deck("1", true), "c.k")));
  EXPECT_NO_THROW(build_simulation(read_keyword_string(deck("2", false), "c.k")));
  try {
    build_simulation(read_keyword_string(deck("2", true), "c.k"));
    FAIL() << "ESORT 2 with a triangle ran";
  } catch (const std::exception& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("c.k:5: field ESORT of *CONTROL_SHELL: 2 (DKT triangular shells) is not implemented, and part 1 "
                        "has triangles (*ELEMENT_SHELL 7"),
              std::string::npos)
        << what;
  }
  try {
    read_keyword_string(deck("3", true), "c.k");
    FAIL() << "ESORT 3 read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("c.k:5: *CONTROL_SHELL card 1: field ESORT = 3 must be 0, 1 or 2"),
              std::string::npos)
        << e.what();
  }
}

// *CONTROL_SHELL INTGRD (card 2, field 2) picks every shell section's through-thickness rule:
// blank and 0 Gauss-Legendre, 1 Gauss-Lobatto (with NIP = 3 the points are the two surfaces and the
// mid surface, weights 1/3, 4/3, 1/3; NIP = 1 is the mid surface in either rule); 2 is refused.
// (The Lobatto rule's collapse moments: tests/verification/test_shell_plasticity.cpp.)
TEST(KeywordControls, ShellIntgrdPicksTheThroughThicknessRule) {
  const auto deck = [](const std::string& intgrd, int nip) {
    return std::string("*KEYWORD\n*CONTROL_TERMINATION\n1.0\n*CONTROL_SHELL\n\n0,") + intgrd +
           "\n*SECTION_SHELL\n1,2,," + std::to_string(nip) +
           "\n0.1\n*MAT_ELASTIC\n1,1.0,1000.0,0.3\n*PART\nplate\n1,1,1\n*NODE\n1,0,0,0\n2,1,0,0\n"
           "3,1,1,0\n4,0,1,0\n*ELEMENT_SHELL\n7,1,1,2,3,4\n*END\n";
  };
  const auto rule_of = [&](const std::string& intgrd, int nip) {
    const auto m = read_keyword_string(deck(intgrd, nip), "c.k");
    auto sim = build_simulation(m);
    const auto* shells = dynamic_cast<const ShellBlock*>(sim->blocks().at(0).get());
    EXPECT_NE(shells, nullptr);
    return std::pair{m.shell_intgrd, shells != nullptr ? shells->thickness_rule() : shell_bt::ThicknessRule{}};
  };
  const auto [g, gauss] = rule_of("", 3);
  EXPECT_EQ(g, 0);
  EXPECT_NEAR(gauss.xi[2], std::sqrt(0.6), 1e-15);
  const auto [l, lobatto] = rule_of("1", 3);
  EXPECT_EQ(l, 1);
  ASSERT_EQ(lobatto.n, 3);
  EXPECT_EQ(lobatto.xi[0], -1.0);
  EXPECT_EQ(lobatto.xi[1], 0.0);
  EXPECT_EQ(lobatto.xi[2], 1.0);
  EXPECT_NEAR(lobatto.w[0], 1.0 / 3, 1e-15);
  EXPECT_NEAR(lobatto.w[1], 4.0 / 3, 1e-15);
  const auto [l1, one] = rule_of("1", 1);
  EXPECT_EQ(l1, 1);
  ASSERT_EQ(one.n, 1);
  EXPECT_EQ(one.xi[0], 0.0);
  EXPECT_EQ(one.w[0], 2.0);
  try {
    read_keyword_string(deck("2", 3), "c.k");
    FAIL() << "INTGRD 2 read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("c.k:6: *CONTROL_SHELL card 2: field INTGRD = 2 must be 0 (Gauss) or 1 (Lobatto)"),
              std::string::npos)
        << e.what();
  }
}

// *CONTROL_SHELL ISTUPD (card 1, field 4): 1 and 4 are stored and turn the shell blocks' thickness
// update on (docs/solver.md, "Shell thickness change"); 4 on an elastic part and either on a
// *MAT_NULL shell are refused when the model is built, naming the card's line and the part.
TEST(KeywordControls, ShellIstupdTurnsTheThicknessUpdateOn) {
  const auto deck = [](const std::string& istupd, const std::string& mat) {
    return std::string("*KEYWORD\n*CONTROL_TERMINATION\n1.0\n*CONTROL_SHELL\n0,0,0,") + istupd +
           "\n*SECTION_SHELL\n1,2,,3\n0.1\n" + mat + "*PART\nplate\n1,1,1\n*NODE\n1,0,0,0\n2,1,0,0\n"
           "3,1,1,0\n4,0,1,0\n*ELEMENT_SHELL\n7,1,1,2,3,4\n*END\n";
  };
  const std::string elastic = "*MAT_ELASTIC\n1,1.0,1000.0,0.3\n";
  const std::string plastic = "*MAT_PLASTIC_KINEMATIC\n1,1.0,1000.0,0.3,1.0,10.0,1.0\n";
  for (const auto& [istupd, mat, follows] :
       {std::tuple{"", elastic, false}, std::tuple{"1", elastic, true}, std::tuple{"1", plastic, true},
        std::tuple{"4", plastic, true}}) {
    const auto m = read_keyword_string(deck(istupd, mat), "c.k");
    EXPECT_EQ(m.shell_istupd, std::string(istupd).empty() ? 0 : std::stoi(istupd));
    auto sim = build_simulation(m);
    EXPECT_EQ(sim->blocks().at(0)->current_thickness().size(), follows ? 1u : 0u) << istupd;
    if (follows) EXPECT_EQ(sim->blocks().at(0)->current_thickness()[0], 0.1);
  }
  for (const auto& [istupd, mat, expected] :
       {std::tuple{"4", elastic, "c.k:5: field ISTUPD of *CONTROL_SHELL: part 1: *CONTROL_SHELL ISTUPD = 4 (elastic "
                                 "strains left out) acts on elastic-plastic materials"},
        std::tuple{"1", std::string("*MAT_NULL\n1,1.0,0,0,0,0,1000.0,0.3\n"),
                   "c.k:5: field ISTUPD of *CONTROL_SHELL: part 1: its material carries no stress"}}) {
    try {
      build_simulation(read_keyword_string(deck(istupd, mat), "c.k"));
      FAIL() << "ISTUPD " << istupd << " built";
    } catch (const NotImplementedError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  }
}

// *CONTROL_SOLID ESORT = 1 sorts degenerate solids of ELFORM 1 / 2 sections into ELFORM 10
// tetrahedra and 15 pentahedra: with no degenerate solid there is nothing to sort and the deck
// runs; a tetrahedron (N4 repeated) in an ELFORM 1 section is refused naming the card's line, the
// part and the element; in an ELFORM 10 section it is a tetrahedron already and runs.
TEST(KeywordControls, SolidEsortOneRunsWhereThereIsNothingToSort) {
  const auto deck = [](int elform, bool tet) {
    return std::string("*KEYWORD\n*CONTROL_TERMINATION\n1.0\n*CONTROL_SOLID\n1\n*SECTION_SOLID\n1,") +
           std::to_string(elform) + "\n*MAT_ELASTIC\n1,1.0,1000.0,0.3\n*PART\nblock\n1,1,1\n*NODE\n1,0,0,0\n2,1,0,0\n"
           "3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n*ELEMENT_SOLID\n" +
           (tet ? "9,1,1,2,4,5,5,5,5,5\n" : "9,1,1,2,3,4,5,6,7,8\n") + "*END\n";
  };
  EXPECT_EQ(read_keyword_string(deck(1, false), "c.k").solid_esort, 1);
  EXPECT_NO_THROW(build_simulation(read_keyword_string(deck(1, false), "c.k")));
  EXPECT_NO_THROW(build_simulation(read_keyword_string(deck(10, true), "c.k")));
  try {
    build_simulation(read_keyword_string(deck(1, true), "c.k"));
    FAIL() << "ESORT 1 with a tetrahedron in an ELFORM 1 section ran";
  } catch (const std::exception& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("c.k:5: field ESORT of *CONTROL_SOLID: 1 sorts degenerate solids into ELFORM 10 tetrahedra and "
                        "ELFORM 15 pentahedra, which is not implemented for the solids of an ELFORM 1 section, and "
                        "part 1 has one (*ELEMENT_SOLID 9, repeated nodes)"),
              std::string::npos)
        << what;
  }
}

// TSLIMT (field 4) changes the moduli of shells whose step falls below it: refused when not 0 as
// every unimplemented physics field is (NotImplementedError, exit 3), naming file, line, field and
// value; blank and 0 are accepted.
TEST(KeywordControls, TslimtIsRefusedUnlessZero) {
  std::vector<Diagnostic> warnings;
  const auto m = read_keyword_string("*KEYWORD\n*CONTROL_TIMESTEP\n0,0.8,0,0.0\n*END\n", "c.k", &warnings);
  EXPECT_EQ(m.timestep.tslimt, 0.0);
  EXPECT_TRUE(warnings.empty()) << (warnings.empty() ? "" : to_string(warnings[0]));
  try {
    read_keyword_string("*KEYWORD\n*CONTROL_TIMESTEP\n0,0.8,0,2.5e-7\n*END\n", "c.k");
    FAIL() << "expected NotImplementedError";
  } catch (const NotImplementedError& e) {
    EXPECT_NE(std::string(e.what()).find("c.k:3: *CONTROL_TIMESTEP card 1: field TSLIMT = 2.5e-7"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace slideline
