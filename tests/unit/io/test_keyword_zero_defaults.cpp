// LS-DYNA's rule for fields with a manual default: blank and 0 are the same number and both mean
// the default. A deck with 0 written in every such field reads into the same model as the deck
// with those fields blank; and the contact fields the solver does not act on are refused (naming
// file, line and field) or warned about, never dropped.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "model_equal.hpp"
#include "slideline/contact/penalty_contact.hpp"
#include "slideline/core/error.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/io/keyword_writer.hpp"
#include "slideline/solver/build.hpp"
#include "slideline/solver/simulation.hpp"

namespace slideline {
namespace {

/// A fixed-format card of 10-character fields; "Z" stands for the zero-or-blank field under test.
std::string card(const std::vector<std::string>& fields, const std::string& z) {
  std::string out;
  for (const auto& f : fields) {
    const std::string v = f == "Z" ? z : f;
    out += std::string(10 - std::min<std::size_t>(10, v.size()), ' ') + v;
  }
  return out + "\n";
}

/// Every card we read that has a field whose manual default is not 0, with `z` in those fields.
std::string deck(const std::string& z) {
  const std::vector<std::string> zeros(8, "Z");
  std::string d = "*KEYWORD\n";
  d += "*SECTION_SOLID\n" + card({"1", "Z"}, z);
  d += "*SECTION_SHELL\n" + card({"2", "Z", "Z", "Z", "Z", "Z", "Z", "Z"}, z) +
       card({"0.1", "Z", "Z", "Z", "Z", "Z", "Z", "Z"}, z);
  d += "*HOURGLASS\n" + card({"1", "Z", "Z", "", "Z", "Z", "Z", "Z"}, z);
  d += "*CONTROL_HOURGLASS\n" + card({"Z", "Z"}, z);
  d += "*CONTROL_BULK_VISCOSITY\n" + card({"Z", "Z", "Z"}, z);  // TYPE: default 1
  d += "*CONTROL_TERMINATION\n" + card({"1.0", "", "", "", "Z"}, z);  // ENDMAS: default 1e8
  d += "*CONTROL_TIMESTEP\n" + card({"", "Z"}, z);
  d += "*CONTROL_CONTACT\n" + card(zeros, z);
  for (int k = 2; k <= 6; ++k) d += card(zeros, z);  // cards 2-6 (RWGAPS, RWKSF, XPENE: defaults not 0)
  d += "*BOUNDARY_PRESCRIBED_MOTION_SET\n" + card({"1", "1", "Z", "1", "Z", "Z", "Z", "Z"}, z);
  d += "*LOAD_NODE_POINT\n" + card({"1", "1", "1", "Z"}, z);
  d += "*LOAD_BODY_Z\n" + card({"1", "Z"}, z);
  d += "*DEFINE_CURVE\n" + card({"1", "Z", "Z", "Z", "Z", "Z"}, z) + "0.0,0.0\n1.0,1.0\n";
  d += "*DAMPING_PART_MASS\n" + card({"1", "1", "Z"}, z);
  // A penalty contact: cards 2 and 3 (DT left blank: birth and death are another change's),
  // then the optional cards A-F (SOFSCL, MAXPAR, SBOPT, DEPTH, FRCFRQ, IGAP, FRICSF, FSTOL: defaults not 0).
  d += "*CONTACT_SURFACE_TO_SURFACE\n" + card({"1", "2", "3", "3"}, z);
  d += card({"Z", "Z", "Z", "Z", "Z", "Z", "Z", ""}, z) + card(zeros, z);
  for (int k = 0; k < 6; ++k) d += card(zeros, z);
  d += "*CONTACT_TIEBREAK_NODES_TO_SURFACE\n" + card({"1", "2", "4", "3"}, z) + card({}, z) + card({}, z) +
       card({"1.0", "1.0", "Z", "Z"}, z);
  return d + "*END\n";
}

TEST(KeywordZeroDefaults, ZeroInEveryDefaultedFieldReadsAsBlank) {
  std::vector<Diagnostic> wz, wb;
  const auto zero = read_keyword_string(deck("0"), "zero.k", &wz);
  const auto real_zero = read_keyword_string(deck("0.0"), "zero.k");
  const auto blank = read_keyword_string(deck(""), "blank.k", &wb);
  EXPECT_EQ(test::model_difference(zero, blank), "");
  EXPECT_EQ(test::model_difference(real_zero, blank), "");
  // Neither deck asks for anything the solver does not do: no refusal, no warning.
  EXPECT_TRUE(wz.empty()) << wz.front().message;
  EXPECT_TRUE(wb.empty()) << wb.front().message;
}

TEST(KeywordZeroDefaults, ZeroGivesTheManualDefaults) {
  const auto m = read_keyword_string(deck("0.0"), "zero.k");
  EXPECT_DOUBLE_EQ(m.control_contact.slsfac, 0.1);  // a zero SLSFAC gave a contact of no stiffness
  EXPECT_EQ(m.control_contact.islchk, 1);
  EXPECT_EQ(m.control_contact.penopt, 1);
  EXPECT_EQ(m.control_contact.orien, 1);
  EXPECT_DOUBLE_EQ(m.timestep.tssfac, 0.9);
  EXPECT_EQ(m.solid_sections[0].elform, 1);
  EXPECT_EQ(m.shell_sections[0].elform, 2);
  EXPECT_DOUBLE_EQ(m.shell_sections[0].shrf, 1.0);
  EXPECT_EQ(m.shell_sections[0].nip, 2);
  EXPECT_DOUBLE_EQ(m.shell_sections[0].propt, 1.0);
  EXPECT_EQ(m.hourglasses[0].ihq, 1);
  EXPECT_DOUBLE_EQ(m.hourglasses[0].qm, 0.1);
  EXPECT_DOUBLE_EQ(m.hourglasses[0].q1, 1.5);
  EXPECT_DOUBLE_EQ(m.hourglasses[0].q2, 0.06);
  EXPECT_EQ(m.control_hourglass.ihq, 1);
  EXPECT_DOUBLE_EQ(m.control_hourglass.qh, 0.1);
  EXPECT_DOUBLE_EQ(m.bulk_viscosity.q1, 1.5);
  EXPECT_DOUBLE_EQ(m.bulk_viscosity.q2, 0.06);
  EXPECT_EQ(m.prescribed_motions[0].vad, 0);  // LS-DYNA: blank VAD is velocity
  EXPECT_DOUBLE_EQ(m.prescribed_motions[0].sf, 1.0);
  EXPECT_DOUBLE_EQ(m.prescribed_motions[0].death, 1e28);
  EXPECT_DOUBLE_EQ(m.nodal_loads[0].sf, 1.0);
  EXPECT_DOUBLE_EQ(m.body_loads[0].sf, 1.0);
  EXPECT_DOUBLE_EQ(m.curves[0].sfa, 1.0);
  EXPECT_DOUBLE_EQ(m.curves[0].sfo, 1.0);
  EXPECT_DOUBLE_EQ(m.damping_parts[0].sf, 1.0);
  const auto& c = m.contacts[0];
  for (Real f : {c.sfs, c.sfm, c.sfst, c.sfmt, c.fsf, c.vsf}) EXPECT_DOUBLE_EQ(f, 1.0);
  EXPECT_DOUBLE_EQ(m.contacts[1].nen, 2.0);
  EXPECT_DOUBLE_EQ(m.contacts[1].mes, 2.0);
}

/// Stiffness of master segment 0 of the first pass of the deck's first (penalty) contact.
Real first_segment_stiffness(const std::string& text) {
  auto sim = build_simulation(read_keyword_string(text, "slsfac.k"));
  sim->initialize();
  const PenaltyPasses* passes = penalty_passes_of(sim->contacts()[0]);
  if (!passes) throw std::runtime_error("not a penalty contact");
  return passes->pass(0).segment_stiffness(0);
}

TEST(KeywordZeroDefaults, SlsfacZeroGivesTheDefaultPenaltyStiffnessNotNone) {
  // The ball-on-plate: SLSFAC = 0.0 gave contacts of zero stiffness (bodies passed
  // through each other, exit 0). A Type 3 deck with SLSFAC 0.0 and with 0.1 build the same springs.
  std::ifstream in(std::string(SLIDELINE_SOURCE_DIR) + "/tests/data/decks/solid_on_solid_type3.k");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string with_default = ss.str();
  const std::string line = "*CONTROL_CONTACT\n       0.1";
  ASSERT_NE(with_default.find(line), std::string::npos);
  std::string with_zero = with_default;
  with_zero.replace(with_zero.find(line), line.size(), "*CONTROL_CONTACT\n       0.0");
  const Real k_default = first_segment_stiffness(with_default);
  EXPECT_GT(k_default, 0.0);
  EXPECT_DOUBLE_EQ(first_segment_stiffness(with_zero), k_default);
}

/// A penalty Type 3 contact deck with `card2`, `card3` and `extra` (cards after card 3) written in.
std::string contact_deck(const std::string& card2, const std::string& card3, const std::string& extra = "",
                         const std::string& type = "SURFACE_TO_SURFACE") {
  return "*KEYWORD\n*CONTACT_" + type + "\n" + card({"1", "2", "3", "3"}, "") + card2 + card3 + extra + "*END\n";
}

/// The NotImplementedError message of reading `text`, or "" when it reads.
std::string refusal(const std::string& text, std::vector<Diagnostic>* warnings = nullptr) {
  try {
    read_keyword_string(text, "u.k", warnings);
  } catch (const NotImplementedError& e) {
    return e.what();
  }
  return "";
}

struct Refused {
  std::string deck;
  std::string expected;  // file:line: keyword card: field NAME
};

TEST(KeywordContactFields, PhysicsFieldsNotImplementedAreRefusedNamingFileLineAndField) {
  const std::string c2 = card({}, ""), c3 = card({}, "");
  const std::vector<Refused> cases = {
      {contact_deck(card({"", "", "", "5.0"}, ""), c3, "", "TIEBREAK_SURFACE_TO_SURFACE"),
       "u.k:4: *CONTACT_TIEBREAK_SURFACE_TO_SURFACE card 2: field VC = 5"},
      {contact_deck(card({"-2"}, ""), c3), "u.k:4: *CONTACT_SURFACE_TO_SURFACE card 2: FS, FD or DC < 0 (FS = -2"},
      {contact_deck(card({"", "", "", "", "20"}, ""), c3, "", "TIEBREAK_SURFACE_TO_SURFACE"),
       "u.k:4: *CONTACT_TIEBREAK_SURFACE_TO_SURFACE card 2: field VDC = 20"},
      {contact_deck(card({"", "", "", "", "20"}, ""), c3, "", "SURFACE_TO_SURFACE_LAGRANGE"),
       "u.k:4: *CONTACT_SURFACE_TO_SURFACE_LAGRANGE card 2: field VDC = 20"},
      {contact_deck(card({"", "", "", "", "", "2"}, ""), c3), "u.k:4: *CONTACT_SURFACE_TO_SURFACE card 2: field PENCHK = 2"},
      {contact_deck(card({"", "", "", "", "", "1"}, ""), c3, "", "SURFACE_TO_SURFACE_LAGRANGE"),
       "u.k:4: *CONTACT_SURFACE_TO_SURFACE_LAGRANGE card 2: field PENCHK = 1"},
      {contact_deck(card({"", "", "", "", "", "1"}, ""), c3, "", "TIED_SURFACE_TO_SURFACE"),
       "u.k:4: *CONTACT_TIED_SURFACE_TO_SURFACE card 2: field PENCHK = 1"},
      {contact_deck(card({"-1"}, ""), c3), "u.k:4: *CONTACT_SURFACE_TO_SURFACE card 2: FS, FD or DC < 0"},
      {contact_deck(c2, card({"", "", "", "", "", "", "0.5"}, "")), "u.k:5: *CONTACT_SURFACE_TO_SURFACE card 3: field FSF = 0.5"},
      {contact_deck(c2, card({"", "", "", "", "", "", "", "2"}, "")), "u.k:5: *CONTACT_SURFACE_TO_SURFACE card 3: field VSF = 2"},
      {contact_deck(c2, c3, card({"2"}, ""), "ONE_WAY_SURFACE_TO_SURFACE"),  // Type 3 takes it (solid faces)
       "u.k:6: *CONTACT_ONE_WAY_SURFACE_TO_SURFACE optional card A: field SOFT = 2"},
      {contact_deck(c2, c3, card({}, "") + card({"1"}, ""), "TIEBREAK_SURFACE_TO_SURFACE"),  // after card 4
       "u.k:7: *CONTACT_TIEBREAK_SURFACE_TO_SURFACE optional card A: field SOFT = 1"},
      {contact_deck(c2, c3, card({"1"}, ""), "SURFACE_TO_SURFACE_LAGRANGE"),
       "u.k:6: *CONTACT_SURFACE_TO_SURFACE_LAGRANGE optional card A: field SOFT = 1"},
      {contact_deck(c2, c3, card({"", "", "", "", "", "", "", "3"}, "")), "optional card A: field FRCFRQ = 3"},
      {contact_deck(c2, c3, card({}, "") + card({"0.5"}, "")), "u.k:7: *CONTACT_SURFACE_TO_SURFACE optional card B: field PENMAX = 0.5"},
      {contact_deck(c2, c3, card({}, "") + card({}, "") + card({"", "", "0.5"}, "")), "u.k:8: *CONTACT_SURFACE_TO_SURFACE optional card C: field DPRFAC = 0.5"},
      {contact_deck(c2, c3, std::string(6, '\n') + card({"1"}, "")), "a card after optional card F"},
      {contact_deck(c2, card({"10", "5"}, ""), "", "NODES_TO_SURFACE"), "u.k:5: *CONTACT_NODES_TO_SURFACE card 3: field SFM = 5"},
      {contact_deck(c2, card({"", "", "0.1"}, ""), "", "TIED_SURFACE_TO_SURFACE"), "card 3: field SST = 0.1"},
      {contact_deck(c2, c3, card({"", "1", "1", "0.5"}, ""), "TIEBREAK_SURFACE_TO_SURFACE"), "card 4: field PARAM = 0.5"},
      {contact_deck(c2, c3, card({"2", "1", "1"}, ""), "TIEBREAK_SURFACE_TO_SURFACE"),
       "u.k:6: *CONTACT_TIEBREAK_SURFACE_TO_SURFACE card 4: field OPTION = 2"},
      {"*SECTION_SOLID\n" + card({"1", "1", "3"}, ""), "u.k:2: *SECTION_SOLID card 1: field AET = 3"},
      {"*SECTION_SHELL\n" + card({"1", "2", "", "", "", "", "1"}, ""), "u.k:2: *SECTION_SHELL card 1: field ICOMP = 1"},
      {"*SECTION_SHELL\n" + card({"1", "2", "", "", "", "1"}, ""), "u.k:2: *SECTION_SHELL card 1: field QR/IRID = 1"},
      {"*SECTION_SHELL\n" + card({"1"}, "") + card({"0.1", "", "", "", "", "0.5"}, ""), "u.k:3: *SECTION_SHELL card 2: field MAREA = 0.5"},
      {"*HOURGLASS\n" + card({"1", "1", "", "", "", "", "0.05"}, ""), "u.k:2: *HOURGLASS card 1: field QB = 0.05"},
      {"*HOURGLASS\n" + card({"1", "1", "0.2", "", "", "", "", "0.1"}, ""), "u.k:2: *HOURGLASS card 1: field QW = 0.1"},
      {"*CONTROL_CONTACT\n" + card({"", "", "", "", "3"}, ""), "u.k:2: *CONTROL_CONTACT card 1: field PENOPT = 3"},
      {"*CONTROL_CONTACT\n" + card({"", "", "", "", "", "2"}, ""), "u.k:2: *CONTROL_CONTACT card 1: field THKCHG = 2"},
      {"*CONTROL_CONTACT\n" + card({"", "", "", "", "", "", "2"}, ""), "u.k:2: *CONTROL_CONTACT card 1: field ORIEN = 2"},
      {"*CONTROL_CONTACT\n" + card({}, "") + card({}, "") + card({}, "") + card({}, "") + card({"1"}, ""),
       "u.k:6: *CONTROL_CONTACT card 5: field ISYM = 1"},
      // Fields of the other cards that the model does not store (they were read and dropped).
      {"*PART\n\n" + card({"1", "1", "1", "", "", "", "1"}, ""), "u.k:3: *PART card 2: field ADPOPT = 1"},
      {"*CONTROL_TERMINATION\n" + card({"1", "", "", "", "", "1"}, ""), "u.k:2: *CONTROL_TERMINATION card 1: field NOSOL = 1"},
      {"*CONTROL_TIMESTEP\n" + card({}, "") + card({"", "", "1"}, ""), "u.k:3: *CONTROL_TIMESTEP card 2: field IMSCL = 1"},
      {"*CONTROL_TIMESTEP\n" + card({}, "") + card({"0.5"}, ""), "u.k:3: *CONTROL_TIMESTEP card 2: field DT2MSF = 0.5"},
      {"*CONTROL_BULK_VISCOSITY\n" + card({"", "", "2"}, ""), "u.k:2: *CONTROL_BULK_VISCOSITY card 1: field TYPE = 2"},
  };
  for (const auto& c : cases) {
    const std::string msg = refusal(c.deck);
    EXPECT_NE(msg.find(c.expected), std::string::npos) << "expected '" << c.expected << "', got '" << msg << "'\n" << c.deck;
  }
}

TEST(KeywordContactFields, IgnoreIsReadFromOptionalCardCAndControlCard4) {
  const std::string blank = card({}, "");
  const std::string card_c = blank + blank + card({"", "2"}, "");
  const std::string control = "*CONTROL_CONTACT\n" + blank + blank + blank + card({"1"}, "");
  const auto m = read_keyword_string("*KEYWORD\n" + control + contact_deck(blank, blank, card_c).substr(9), "u.k");
  EXPECT_EQ(m.contacts[0].ignore, 2);
  EXPECT_EQ(m.control_contact.ignore, 1);
  // The writer keeps them (optional card C, *CONTROL_CONTACT card 4).
  const auto back = read_keyword_string(write_keyword_string(m), "w.k");
  EXPECT_EQ(back.contacts[0].ignore, 2);
  EXPECT_EQ(back.control_contact.ignore, 1);
  // Another value is an input error naming file, line and field.
  try {
    read_keyword_string(contact_deck(blank, blank, blank + blank + card({"", "3"}, "")), "u.k");
    ADD_FAILURE() << "IGNORE = 3 was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("u.k:8: *CONTACT_SURFACE_TO_SURFACE optional card C: field IGNORE must be 0, 1 or 2"),
              std::string::npos) << e.what();
  }
  // A tied interface ties its nodes where they are: warned.
  std::vector<Diagnostic> w;
  read_keyword_string(contact_deck(blank, blank, card_c, "TIED_SURFACE_TO_SURFACE"), "u.k", &w);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].message.find("field IGNORE = 2"), std::string::npos) << w[0].message;
}

TEST(KeywordContactFields, PenchkOneAndXpeneAreReadAndWrittenBack) {
  const std::string blank = card({}, "");
  const std::string control = "*CONTROL_CONTACT\n" + blank + card({"", "", "", "", "2.5"}, "");
  const auto m = read_keyword_string(
      "*KEYWORD\n" + control + contact_deck(card({"", "", "", "", "", "1"}, ""), blank).substr(9), "u.k");
  EXPECT_EQ(m.contacts[0].penchk, 1);
  EXPECT_EQ(m.control_contact.xpene, 2.5);
  const auto back = read_keyword_string(write_keyword_string(m), "w.k");
  EXPECT_EQ(back.contacts[0].penchk, 1);
  EXPECT_EQ(back.control_contact.xpene, 2.5);
  EXPECT_EQ(back.control_contact.ignore, 0);
  // Blank and 0 are LS-DYNA's default 4.
  const auto zero = read_keyword_string("*KEYWORD\n*CONTROL_CONTACT\n" + blank + card({"", "", "", "", "0"}, "") +
                                        "*END\n", "u.k");
  EXPECT_EQ(zero.control_contact.xpene, 4.0);
  // A negative XPENE is an input error naming file, line and field.
  try {
    read_keyword_string("*KEYWORD\n*CONTROL_CONTACT\n" + blank + card({"", "", "", "", "-1"}, "") + "*END\n", "u.k");
    ADD_FAILURE() << "XPENE = -1 was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("u.k:4: *CONTROL_CONTACT card 2: field XPENE must not be negative"),
              std::string::npos) << e.what();
  }
}

TEST(KeywordContactFields, SoftSofsclAndVcAreReadWhereTheyAct) {
  const std::string blank = card({}, "");
  const std::string friction = card({"0.3", "", "", "2.5"}, "");  // FS 0.3, VC 2.5
  std::vector<Diagnostic> w;
  const auto m = read_keyword_string(contact_deck(friction, blank, card({"1", "0.2"}, "")), "u.k", &w);
  EXPECT_TRUE(w.empty());
  EXPECT_EQ(m.contacts[0].soft, 1);
  EXPECT_DOUBLE_EQ(m.contacts[0].sofscl, 0.2);
  EXPECT_DOUBLE_EQ(m.contacts[0].vc, 2.5);
  // Blank and 0 SOFSCL mean 0.1; the writer keeps SOFT and SOFSCL (optional card A).
  EXPECT_DOUBLE_EQ(read_keyword_string(contact_deck(blank, blank, card({"1", "0.0"}, "")), "u.k").contacts[0].sofscl,
                   0.1);
  const auto back = read_keyword_string(write_keyword_string(m), "w.k");
  EXPECT_EQ(back.contacts[0].soft, 1);
  EXPECT_DOUBLE_EQ(back.contacts[0].sofscl, 0.2);
  // Warned: SOFSCL without SOFT = 1, SOFT = 1 on a kinematic tie, VC without friction.
  const std::vector<std::pair<std::string, std::string>> warned = {
      {contact_deck(blank, blank, card({"", "0.3"}, "")), "optional card A: field SOFSCL = 0.3"},
      {contact_deck(blank, blank, card({"1"}, ""), "TIED_SURFACE_TO_SURFACE"), "optional card A: field SOFT = 1"},
      {contact_deck(card({"", "", "", "2.5"}, ""), blank), "card 2: field VC = 2.5"},
  };
  for (const auto& [deck, text] : warned) {
    std::vector<Diagnostic> ws;
    read_keyword_string(deck, "u.k", &ws);
    ASSERT_EQ(ws.size(), 1u) << deck;
    EXPECT_NE(ws[0].message.find(text), std::string::npos) << ws[0].message;
  }
  // Input errors naming file, line and field.
  for (const auto& [deck, text] : std::vector<std::pair<std::string, std::string>>{
           {contact_deck(blank, blank, card({"3"}, "")), "u.k:6: *CONTACT_SURFACE_TO_SURFACE optional card A: field SOFT = 3"},
           {contact_deck(blank, blank, card({"1", "-0.1"}, "")), "optional card A: field SOFSCL = -0.1"},
           {contact_deck(card({"0.3", "", "", "-1"}, ""), blank), "u.k:4: *CONTACT_SURFACE_TO_SURFACE card 2: field VC = -1"}}) {
    try {
      read_keyword_string(deck, "u.k");
      ADD_FAILURE() << "accepted: " << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
  }
}

TEST(KeywordSectionFields, HourglassQbQwEqualToQmAreAccepted) {
  // QB and QW default to QM; given equal to QM they change nothing.
  std::vector<Diagnostic> w;
  const auto m = read_keyword_string("*HOURGLASS\n" + card({"1", "1", "0.2", "", "", "", "0.2", "0.2"}, ""), "u.k", &w);
  EXPECT_DOUBLE_EQ(m.hourglasses[0].qm, 0.2);
  EXPECT_TRUE(w.empty());
}

TEST(KeywordContactFields, OutputSpeedAndInertFieldsWarnAndStillRead) {
  const std::string blank = card({}, "");
  struct Warned {
    std::string deck, expected;
  };
  const std::vector<Warned> cases = {
      {contact_deck(blank, blank, card({"", "", "", "", "", "", "100"}, "")), "field BSORT = 100 (cycles between bucket sorts) only tunes speed"},
      {"*KEYWORD\n*CONTACT_SURFACE_TO_SURFACE\n" + card({"1", "2", "3", "3", "", "", "1"}, ""), "field SPR = 1"},
      {contact_deck(card({"0.3"}, ""), blank, "", "TIED_SURFACE_TO_SURFACE"), "field FS = 0.3 (friction of a tied interface"},
      {contact_deck(card({"", "", "", "", "20"}, ""), blank, "", "TIED_SURFACE_TO_SURFACE"),
       "field VDC = 20 (viscous contact damping; this interface is a kinematic constraint"},
      {"*CONTROL_CONTACT\n" + blank + blank + card({"0.2"}, ""), "u.k:4: *CONTROL_CONTACT card 3: field SFRIC = 0.2"},
      {"*CONTROL_CONTACT\n" + card({"", "", "2"}, ""), "field ISLCHK = 2 (report of initial penetrations) only tunes output"},
      {"*SECTION_SHELL\n" + card({"1", "2", "", "", "2"}, ""), "u.k:2: *SECTION_SHELL card 1: field PROPT = 2"},
      {"*MAT_ELASTIC\n" + card({"1", "1", "1", "0.3", "", "", "5"}, ""), "u.k:2: *MAT_ELASTIC card 1: field K = 5"},
      {"*MAT_RIGID\n" + card({"1", "1", "1", "0.3", "1", "", "", "name"}, ""), "u.k:2: *MAT_RIGID card 1: field N = 1"},
      {"*MAT_MOONEY-RIVLIN_RUBBER\n" + card({"1", "1", "0.49", "1", "0", "1"}, ""), "*MAT_MOONEY-RIVLIN_RUBBER card 1: field REF = 1"},
      {"*PART\n\n" + card({"1", "1", "1", "", "", "", "", "3"}, ""), "u.k:3: *PART card 2: field TMID = 3"},
      {"*CONTROL_TIMESTEP\n" + card({}, "") + card({"", "", "", "", "", "", "", "1"}, ""), "field IHDO = 1 (solid element time-step method) only chooses the time step"},
      {"*DEFINE_CURVE\n" + card({"1", "", "", "", "", "", "", "100"}, "") + "0,0\n1,1\n", "u.k:2: *DEFINE_CURVE card 1: field LCINT = 100"},
  };
  for (const auto& c : cases) {
    std::vector<Diagnostic> w;
    EXPECT_EQ(refusal(c.deck, &w), "") << c.deck;
    std::string all;
    for (const auto& d : w) all += d.file + ":" + std::to_string(d.line) + ": " + d.message + "\n";
    EXPECT_NE(all.find(c.expected), std::string::npos) << "expected '" << c.expected << "' in\n" << all;
  }
}

}  // namespace
}  // namespace slideline
