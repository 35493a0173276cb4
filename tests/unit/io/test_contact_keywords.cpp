// The contact keyword table (model/contact_keywords.hpp) behind the reader and the writer: every
// row, with each option it takes, reads as the row says and is written back under the same name.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "slideline/core/error.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/io/keyword_table.hpp"
#include "slideline/io/keyword_writer.hpp"
#include "slideline/model/contact_keywords.hpp"

namespace slideline {
namespace {

using model::ContactKeyword;
using model::Enforcement;

struct Spelling {
  std::string keyword;
  bool lagrange, sliding, heading;
  bool mortar = false;
};

std::vector<Spelling> spellings(const ContactKeyword& k) {
  const std::string base(k.keyword);
  std::vector<Spelling> s = {{base, false, false, false},
                             {base + "_LAGRANGE", true, false, false},
                             {base + "_ID", false, false, true},
                             {base + "_LAGRANGE_TITLE", true, false, true}};
  if (k.sliding_option) {
    s.push_back({base + "_SLIDING_ONLY", false, true, false});
    s.push_back({base + "_LAGRANGE_SLIDING_ONLY_ID", true, true, true});
  }
  if (k.mortar_option) {
    s.push_back({base + "_MORTAR", false, false, false, true});
    s.push_back({base + "_MORTAR_ID", false, false, true, true});
    // Read (the model build refuses _MORTAR with _LAGRANGE, by name).
    s.push_back({base + "_LAGRANGE_MORTAR", true, false, false, true});
    if (k.sliding_option) s.push_back({base + "_MORTAR_SLIDING_ONLY_TITLE", false, true, true, true});
  }
  return s;
}

TEST(ContactKeywords, EachRowReadsAsItSaysAndIsWrittenUnderItsName) {
  int checked = 0;
  for (const auto& k : model::kContactKeywords)
    for (const auto& s : spellings(k)) {
      SCOPED_TRACE(s.keyword);
      // The automatic tiebreak card needs its card 4 (OPTION 2, the stress-criterion law).
      const bool card4 = k.type == model::ContactType::tiebreak_surface && k.form != model::ContactForm::dyna3d;
      const std::string deck = "*KEYWORD\n" + s.keyword + "\n" + (s.heading ? "         7a contact\n" : "") +
                               "1,2\n" + (card4 ? "0\n1\n2\n" : "") + "*END\n";
      const auto m = read_keyword_string(deck, "c.k");
      ASSERT_EQ(m.contacts.size(), 1u);
      const auto& c = m.contacts[0];
      EXPECT_EQ(c.type, k.type);
      EXPECT_EQ(c.automatic_general, k.automatic_general);
      EXPECT_EQ(c.enforcement, s.lagrange ? Enforcement::lagrange : k.enforcement);
      EXPECT_EQ(c.sliding_only_option, s.sliding);
      EXPECT_EQ(c.penalty_coupling, s.mortar ? 1 : 0);
      EXPECT_EQ(model::contact_keyword(c), &k);
      const std::string written = write_keyword_string(m);
      EXPECT_NE(written.find("\n" + std::string(k.keyword)), std::string::npos);
      const auto again = read_keyword_string(written, "again.k");
      ASSERT_EQ(again.contacts.size(), 1u);
      EXPECT_EQ(again.contacts[0].type, k.type);
      EXPECT_EQ(again.contacts[0].enforcement, c.enforcement);
      EXPECT_EQ(again.contacts[0].automatic_general, k.automatic_general);
      EXPECT_EQ(again.contacts[0].sliding_only_option, s.sliding);
      EXPECT_EQ(again.contacts[0].penalty_coupling, c.penalty_coupling);
      EXPECT_EQ(again.contacts[0].cid, c.cid);
      EXPECT_EQ(again.contacts[0].title, c.title);
      ++checked;
    }
  EXPECT_GE(checked, 4 * 11 + 3 * 4 + 1);
}

// _MORTAR on a card that does not take it is an input error naming the file, the line and the
// option, not a card read without it.
TEST(ContactKeywords, MortarWhereItIsNotBuiltIsRefusedByName) {
  int refused = 0, without = 0;
  for (const auto& k : model::kContactKeywords) {
    if (k.mortar_option) continue;
    ++without;
    const std::string kw = std::string(k.keyword) + "_MORTAR_ID";
    SCOPED_TRACE(kw);
    try {
      read_keyword_string("*KEYWORD\n" + kw + "\n         7\n1,2\n*END\n", "c.k");
      ADD_FAILURE() << "read";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("c.k:2: " + kw + ": _MORTAR is an option of *CONTACT_SURFACE_TO_SURFACE, "), std::string::npos)
          << what;
      EXPECT_NE(what.find(" and *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE only"), std::string::npos) << what;
      ++refused;
    }
  }
  EXPECT_EQ(refused, without);
  EXPECT_GE(without, 10);  // the table's cards without the option (11 with the force transducer)
}

// The CLI's names (blockcontact check) and the DYNA3D numbers, from the table.
TEST(ContactKeywords, NamesAndTypeNumbers) {
  model::Contact c;
  c.type = model::ContactType::automatic;
  c.automatic_general = true;
  ASSERT_NE(model::contact_keyword(c), nullptr);
  EXPECT_EQ(model::contact_keyword(c)->keyword, "*CONTACT_AUTOMATIC_GENERAL");
  EXPECT_EQ(model::contact_keyword(c)->dyna3d_type, 12);
  c.automatic_general = false;
  EXPECT_EQ(model::contact_keyword(c)->keyword, "*CONTACT_AUTOMATIC_SINGLE_SURFACE");
  c.type = model::ContactType::tied_shell_edge;
  EXPECT_EQ(model::contact_keyword(c)->name, "tied shell edge");
  EXPECT_EQ(model::contact_keyword(c)->enforcement, Enforcement::kinematic);
  EXPECT_EQ(model::enforcement_name(Enforcement::lagrange), "Lagrange");
}

// The reader's table takes a contact's options in its grammar only: _LAGRANGE, _SLIDING_ONLY and
// _MORTAR once each, in any order, then at most one of _ID / _TITLE; other keywords their one option.
TEST(ContactKeywords, TheReadersTableKeepsTheOptionGrammar) {
  for (const char* kw : {"*CONTACT_SURFACE_TO_SURFACE", "*CONTACT_SURFACE_TO_SURFACE_LAGRANGE_ID",
                         "*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_SLIDING_ONLY_LAGRANGE_TITLE",
                         "*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_LAGRANGE_SLIDING_ONLY", "*CONTACT_SLIDING_ONLY",
                         "*CONTACT_SLIDING_ONLY_LAGRANGE", "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_MORTAR_ID",
                         "*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_MORTAR_SLIDING_ONLY",
                         "*SET_NODE_LIST_TITLE", "*PARAMETER_EXPRESSION_LOCAL",
                         "*DAMPING_PART_MASS_SET", "*BOUNDARY_SPC_SET_ID"})
    EXPECT_TRUE(reads_keyword(kw)) << kw;
  for (const char* kw : {"*CONTACT_SURFACE_TO_SURFACE_ID_LAGRANGE", "*CONTACT_SURFACE_TO_SURFACE_LAGRANGE_LAGRANGE",
                         "*CONTACT_SURFACE_TO_SURFACE_ID_TITLE", "*CONTACT_SURFACE", "*CONTACT_",
                         "*SET_NODE_LIST_ID", "*SET_NODE_LIST_TITLE_TITLE", "*NODE_TITLE", "*PARAMETER_DUPLICATION",
                         "*MAT_ELASTIC_LAGRANGE", "*CONTROL_CONTACT_TITLE", "*CONTACT_SURFACE_TO_SURFACE_MORTAR_MORTAR",
                         "*CONTACT_SURFACE_TO_SURFACE_ID_MORTAR", "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_MORTAR_TIED",
                         "*CONTACT_FORMING_SURFACE_TO_SURFACE_MORTAR"})
    EXPECT_FALSE(reads_keyword(kw)) << kw;
}

// *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK card 4: OPTION 2 with NFLS, SFLS is read (stresses,
// kept as the tiebreak failure fields) and written back; OPTION 1 (and blank or 0, its default: a
// permanent tie that also ties nodes arriving later) and 3 (as 1, with failure) are read; the unbuilt
// OPTIONs, a field of card 4 that is not honoured (NFLS, SFLS on OPTION 1) and a curve (NFLS, SFLS <
// 0) are refused naming the file, line, field and value.
TEST(ContactKeywords, AutomaticTiebreakCard4) {
  const auto deck = [](const std::string& card4) {
    return "*KEYWORD\n*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK\n1,2,3,3\n0.2,0.2\n1\n" + card4 + "*END\n";
  };
  const auto m = read_keyword_string(deck("2,2.5,3.5\n"), "c.k");
  ASSERT_EQ(m.contacts.size(), 1u);
  const auto& c = m.contacts[0];
  EXPECT_EQ(c.type, model::ContactType::tiebreak_surface);
  EXPECT_EQ(c.form, model::ContactForm::automatic_surface_to_surface);
  EXPECT_EQ(c.option, 2);
  EXPECT_EQ(c.nflf, 2.5);
  EXPECT_EQ(c.sflf, 3.5);
  const std::string written = write_keyword_string(m);
  EXPECT_NE(written.find("\n*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK\n"), std::string::npos) << written;
  const auto again = read_keyword_string(written, "again.k");
  ASSERT_EQ(again.contacts.size(), 1u);
  EXPECT_EQ(again.contacts[0].option, 2);
  EXPECT_EQ(again.contacts[0].nflf, 2.5);
  EXPECT_EQ(again.contacts[0].sflf, 3.5);
  EXPECT_EQ(again.contacts[0].fs, 0.2);

  const auto refused = [&](const std::string& card4, const std::string& message) {
    SCOPED_TRACE(card4);
    try {
      read_keyword_string(deck(card4), "c.k");
      ADD_FAILURE() << "read";
    } catch (const NotImplementedError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  };
  const std::string at = "c.k:6: *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK card 4: field ";
  refused("10,2.5,3.5,0.1\n", at + "OPTION = 10 is not implemented (OPTION 10 is the offset-shell variant of OPTION 7");
  refused("7,2.5,3.5\n", at + "OPTION = 7 is not implemented (OPTION 7 (Dycoss");
  refused("11,2.5,3.5\n", at + "OPTION = 11 is not implemented (OPTION 11 is the offset-shell variant of OPTION 9");
  refused("-9,2.5,3.5\n", at + "OPTION = -9 is not implemented");
  // OPTION 1 (blank and 0 its default) never fails: NFLS, SFLS refused there, read on OPTION 3.
  refused(",2.5\n", at + "NFLS = 2.5 (OPTION 1 never fails (give OPTION 3 for failure))");
  refused("1,0,3.5\n", at + "SFLS = 3.5 (OPTION 1 never fails (give OPTION 3 for failure))");
  refused("1,0,0,1\n", at + "PARAM = 1");
  refused("3,2.5,3.5,1\n", at + "PARAM = 1");
  refused("5,2.5,3.5\n", at + "OPTION = 5 is not implemented (OPTION 5 is a damage curve");
  for (const auto& [card4, option] : {std::pair<std::string, int>{"\n", 0}, {"0\n", 0}, {"1\n", 1}, {"3,2.5,3.5\n", 3}}) {
    const auto read = read_keyword_string(deck(card4), "c.k");
    ASSERT_EQ(read.contacts.size(), 1u);
    EXPECT_EQ(read.contacts[0].option, option) << card4;
    if (option == 3) EXPECT_EQ(read.contacts[0].nflf, 2.5);
    if (option == 3) EXPECT_EQ(read.contacts[0].sflf, 3.5);
  }
  refused("2,-4,3.5\n", at + "NFLS = -4");
  refused("2,2.5,-7\n", at + "SFLS = -7");
  refused("2,2.5,3.5,0.1\n", at + "PARAM = 0.1");
  refused("2,2.5,3.5,0,5\n", at + "ERATEN = 5");
  refused("2,2.5,3.5,0,0,6\n", at + "ERATES = 6");
  refused("2,2.5,3.5,0,0,0,0.5\n", at + "CT2CN = 0.5");
  refused("2,2.5,3.5,0,0,0,0,1e5\n", at + "CN = 100000");
  EXPECT_THROW(read_keyword_string(deck(""), "c.k"), InputError);  // card 4 missing
}

// OPTION 2 is the stress criterion; OPTION 9 reads the
// whole card (PARAM, ERATEN, ERATES, CT2CN, CN) and writes it back; its peak tractions and energy
// release rates are required (> 0), CT2CN and CN < 0 refused; PARAM..CN on OPTION 2 are refused.
TEST(ContactKeywords, AutomaticTiebreakOptions2And9) {
  const auto deck = [](const std::string& card4) {
    return "*KEYWORD\n*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK\n1,2,3,3\n0.2,0.2\n1\n" + card4 + "*END\n";
  };
  const auto two = read_keyword_string(deck("2,2.5,3.5\n"), "c.k");
  EXPECT_EQ(two.contacts.at(0).option, 2);
  EXPECT_EQ(two.contacts.at(0).nflf, 2.5);
  const auto m = read_keyword_string(deck("9,2.5,3.5,-1.5,0.01,0.02,0.8,1e4\n"), "c.k");
  const auto& c = m.contacts.at(0);
  EXPECT_EQ(c.option, 9);
  EXPECT_EQ(c.nflf, 2.5);
  EXPECT_EQ(c.sflf, 3.5);
  EXPECT_EQ(c.param, -1.5);
  EXPECT_EQ(c.eraten, 0.01);
  EXPECT_EQ(c.erates, 0.02);
  EXPECT_EQ(c.ct2cn, 0.8);
  EXPECT_EQ(c.cn, 1e4);
  const auto again = read_keyword_string(write_keyword_string(m), "again.k");
  const auto& b = again.contacts.at(0);
  EXPECT_EQ(b.option, 9);
  EXPECT_EQ(b.nflf, 2.5);
  EXPECT_EQ(b.sflf, 3.5);
  EXPECT_EQ(b.param, -1.5);
  EXPECT_EQ(b.eraten, 0.01);
  EXPECT_EQ(b.erates, 0.02);
  EXPECT_EQ(b.ct2cn, 0.8);
  EXPECT_EQ(b.cn, 1e4);

  const std::string at = "c.k:6: *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK card 4: field ";
  const auto input_error = [&](const std::string& card4, const std::string& message) {
    SCOPED_TRACE(card4);
    try {
      read_keyword_string(deck(card4), "c.k");
      ADD_FAILURE() << "read";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  };
  input_error("9,0,3.5,1,0.01,0.02\n", at + "NFLS = 0: OPTION 9 needs the peak normal traction > 0");
  input_error("9,2.5,,1,0.01,0.02\n", at + "SFLS = 0: OPTION 9 needs the peak shear traction > 0");
  input_error("9,2.5,3.5,1,,0.02\n", at + "ERATEN = 0: OPTION 9 needs the mode I energy release rate > 0");
  input_error("9,2.5,3.5,1,0.01,-2\n", at + "ERATES = -2: OPTION 9 needs the mode II energy release rate > 0");
  input_error("9,2.5,3.5,1,0.01,0.02,-1\n", at + "CT2CN = -1 < 0");
  input_error("9,2.5,3.5,1,0.01,0.02,1,-5\n", at + "CN = -5 < 0");
  try {
    read_keyword_string(deck("2,2.5,3.5,0,0.01\n"), "c.k");
    ADD_FAILURE() << "read";
  } catch (const NotImplementedError& e) {
    EXPECT_NE(std::string(e.what()).find(at + "ERATEN = 0.01"), std::string::npos) << e.what();
  }
}

// OPTION 6 reads NFLS, SFLS (the criterion that starts the damage) and PARAM (CCRIT, the distance
// at which the damage is complete), all three required (> 0), and writes them back; ERATEN, ERATES,
// CT2CN and CN (fields of other OPTIONs; CN on OPTION 6 with _MORTAR only) are refused. OPTION 4
// reads NFLS (required) and refuses SFLS and PARAM.
TEST(ContactKeywords, AutomaticTiebreakOptions4And6) {
  const auto deck = [](const std::string& card4) {
    return "*KEYWORD\n*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK\n1,2,3,3\n0.2,0.2\n1\n" + card4 + "*END\n";
  };
  const auto m = read_keyword_string(deck("6,2.5,3.5,0.01\n"), "c.k");
  const auto& c = m.contacts.at(0);
  EXPECT_EQ(c.option, 6);
  EXPECT_EQ(c.nflf, 2.5);
  EXPECT_EQ(c.sflf, 3.5);
  EXPECT_EQ(c.param, 0.01);
  const auto again = read_keyword_string(write_keyword_string(m), "again.k");
  EXPECT_EQ(again.contacts.at(0).option, 6);
  EXPECT_EQ(again.contacts.at(0).nflf, 2.5);
  EXPECT_EQ(again.contacts.at(0).sflf, 3.5);
  EXPECT_EQ(again.contacts.at(0).param, 0.01);

  const std::string at = "c.k:6: *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK card 4: field ";
  const auto input_error = [&](const std::string& card4, const std::string& message) {
    SCOPED_TRACE(card4);
    try {
      read_keyword_string(deck(card4), "c.k");
      ADD_FAILURE() << "read";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  };
  input_error("6,,3.5,0.01\n", at + "NFLS = 0: OPTION 6 needs the normal failure stress > 0");
  input_error("6,2.5,0,0.01\n", at + "SFLS = 0: OPTION 6 needs the shear failure stress > 0");
  input_error("6,2.5,3.5\n", at + "PARAM = 0: OPTION 6 needs the critical distance CCRIT > 0");
  input_error("6,2.5,3.5,-1\n", at + "PARAM = -1: OPTION 6 needs the critical distance CCRIT > 0");
  const auto refused = [&](const std::string& card4, const std::string& message) {
    SCOPED_TRACE(card4);
    try {
      read_keyword_string(deck(card4), "c.k");
      ADD_FAILURE() << "read";
    } catch (const NotImplementedError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  };
  refused("6,2.5,3.5,0.01,5\n", at + "ERATEN = 5");
  // OPTION 4: NFLS (required); SFLS and PARAM (= 1: SFLS a friction stress limit) refused.
  EXPECT_EQ(read_keyword_string(deck("4,2.5\n"), "c.k").contacts.at(0).option, 4);
  EXPECT_EQ(read_keyword_string(write_keyword_string(read_keyword_string(deck("4,2.5\n"), "c.k")), "w.k")
                .contacts.at(0).nflf, 2.5);
  input_error("4\n", at + "NFLS = 0: OPTION 4 needs the normal failure stress > 0");
  refused("4,2.5,3.5\n", at + "SFLS = 3.5");
  refused("4,2.5,0,1\n", at + "PARAM = 1");
  refused("4,2.5,0,0,0,0,0,1e5\n", at + "CN = 100000");
  refused("6,2.5,3.5,0.01,0,6\n", at + "ERATES = 6");
  refused("6,2.5,3.5,0.01,0,0,0.5\n", at + "CT2CN = 0.5");
  refused("6,2.5,3.5,0.01,0,0,0,1e5\n", at + "CN = 100000");
}

// OPTION 8 (OPTION 6 on offset shells) reads NFLS, SFLS and PARAM as OPTION 6 does (all three > 0,
// ERATEN..CN refused) and card 3's contact thicknesses SST, MST, SFST, SFMT (its shells' offsets),
// which OPTION 6 (no offsets) refuses.
TEST(ContactKeywords, AutomaticTiebreakOption8) {
  const auto deck = [](const std::string& card3, const std::string& card4) {
    return "*KEYWORD\n*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK\n1,2,3,3\n0.2,0.2\n" + card3 + card4 + "*END\n";
  };
  const auto m = read_keyword_string(deck("1,1,0.3,0.2,1.5,0.5\n", "8,2.5,3.5,0.01\n"), "c.k");
  const auto& c = m.contacts.at(0);
  EXPECT_EQ(c.option, 8);
  EXPECT_EQ(c.nflf, 2.5);
  EXPECT_EQ(c.sflf, 3.5);
  EXPECT_EQ(c.param, 0.01);
  EXPECT_EQ(c.sst, 0.3);
  EXPECT_EQ(c.mst, 0.2);
  EXPECT_EQ(c.sfst, 1.5);
  EXPECT_EQ(c.sfmt, 0.5);
  const auto again = read_keyword_string(write_keyword_string(m), "again.k");
  EXPECT_EQ(again.contacts.at(0).option, 8);
  EXPECT_EQ(again.contacts.at(0).param, 0.01);
  EXPECT_EQ(again.contacts.at(0).sst, 0.3);

  const std::string at = "c.k:6: *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK card 4: field ";
  const auto input_error = [&](const std::string& card4, const std::string& message) {
    SCOPED_TRACE(card4);
    try {
      read_keyword_string(deck("1\n", card4), "c.k");
      ADD_FAILURE() << "read";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  };
  input_error("8,,3.5,0.01\n", at + "NFLS = 0: OPTION 8 needs the normal failure stress > 0");
  input_error("8,2.5,0,0.01\n", at + "SFLS = 0: OPTION 8 needs the shear failure stress > 0");
  input_error("8,2.5,3.5\n", at + "PARAM = 0: OPTION 8 needs the critical distance CCRIT > 0");
  const auto refused = [&](const std::string& card3, const std::string& card4, const std::string& message) {
    SCOPED_TRACE(card3 + card4);
    try {
      read_keyword_string(deck(card3, card4), "c.k");
      ADD_FAILURE() << "read";
    } catch (const NotImplementedError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  };
  refused("1\n", "8,2.5,3.5,0.01,5\n", at + "ERATEN = 5");
  refused("1\n", "8,2.5,3.5,0.01,0,0,0,1e5\n", at + "CN = 100000");
  // OPTION 6 has no offsets: its card 3 thicknesses stay refused.
  refused("1,1,0.3\n", "6,2.5,3.5,0.01\n", "c.k:5: *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK card 3: field SST = 0.3");
}

}  // namespace
}  // namespace slideline
