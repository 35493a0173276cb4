// *CONTACT_ERODING_SINGLE_SURFACE / _SURFACE_TO_SURFACE / _NODES_TO_SURFACE (docs/contact_erosion.md)
// and the erosion fields of *CONTROL_CONTACT: each card reads as its automatic counterpart with
// the eroding flag and its card 4 (ISYM EROSOP IADJ), is written back under its name with that
// card, and every field it cannot honour is refused naming file, line, card, field and value.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "slideline/core/error.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/io/keyword_writer.hpp"
#include "slideline/model/contact_keywords.hpp"

namespace slideline {
namespace {

using model::ContactForm;

struct Row {
  const char* keyword;
  ContactForm form;
};
constexpr Row kRows[] = {{"*CONTACT_ERODING_SINGLE_SURFACE", ContactForm::dyna3d},
                         {"*CONTACT_ERODING_SURFACE_TO_SURFACE", ContactForm::automatic_surface_to_surface},
                         {"*CONTACT_ERODING_NODES_TO_SURFACE", ContactForm::automatic_nodes_to_surface}};

std::string deck(const std::string& keyword, const std::string& card4) {
  return "*KEYWORD\n" + keyword + "\n1,2,3,3\n0.1\n\n" + card4 + "*END\n";
}

TEST(ErodingContactCards, ReadAsTheAutomaticCardsWithCard4AndRoundTrip) {
  for (const Row& row : kRows) {
    SCOPED_TRACE(row.keyword);
    for (int erosop : {0, 1}) {
      const auto m = read_keyword_string(deck(row.keyword, "0," + std::to_string(erosop) + ",0\n"), "c.k");
      ASSERT_EQ(m.contacts.size(), 1u);
      const model::Contact& c = m.contacts[0];
      EXPECT_EQ(c.type, model::ContactType::automatic);
      EXPECT_EQ(c.form, row.form);
      EXPECT_TRUE(c.eroding);
      EXPECT_EQ(c.erosop, erosop);
      EXPECT_EQ(c.isym, 0);
      EXPECT_EQ(c.iadj, 0);
      EXPECT_EQ(c.fs, 0.1);
      ASSERT_NE(model::contact_keyword(c), nullptr);
      EXPECT_EQ(model::contact_keyword(c)->keyword, row.keyword);
      const std::string written = write_keyword_string(m);
      EXPECT_NE(written.find(std::string("\n") + row.keyword + "\n"), std::string::npos) << written;
      const auto again = read_keyword_string(written, "again.k");
      ASSERT_EQ(again.contacts.size(), 1u);
      EXPECT_TRUE(again.contacts[0].eroding);
      EXPECT_EQ(again.contacts[0].erosop, erosop);
      EXPECT_EQ(again.contacts[0].form, row.form);
      EXPECT_EQ(again.contacts[0].fs, 0.1);
    }
  }
}

// The automatic cards are not eroding cards: the flag is off and nothing is written for card 4.
TEST(ErodingContactCards, AutomaticCardsStayNonEroding) {
  const auto m = read_keyword_string("*KEYWORD\n*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE\n1,2,3,3\n*END\n", "c.k");
  ASSERT_EQ(m.contacts.size(), 1u);
  EXPECT_FALSE(m.contacts[0].eroding);
  EXPECT_EQ(model::contact_keyword(m.contacts[0])->keyword, "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE");
  EXPECT_EQ(write_keyword_string(m).find("EROSOP"), std::string::npos);
}

// Card 4 left out: ISYM = EROSOP = IADJ = 0, the manual's defaults.
TEST(ErodingContactCards, MissingCard4MeansTheDefaults) {
  const auto m = read_keyword_string("*KEYWORD\n*CONTACT_ERODING_SINGLE_SURFACE\n1\n*END\n", "c.k");
  ASSERT_EQ(m.contacts.size(), 1u);
  EXPECT_TRUE(m.contacts[0].eroding);
  EXPECT_EQ(m.contacts[0].erosop, 0);
}

template <class E>
std::string refusal(const std::string& text) {
  try {
    read_keyword_string(text, "c.k");
  } catch (const E& e) {
    return e.what();
  }
  ADD_FAILURE() << "read without an error";
  return {};
}

TEST(ErodingContactCards, Card4FieldsOutsideWhatRunsAreRefusedByName) {
  for (const Row& row : kRows) {
    SCOPED_TRACE(row.keyword);
    const std::string at = std::string("c.k:6: ") + row.keyword + " card 4: field ";
    std::string w = refusal<InputError>(deck(row.keyword, "2,1,0\n"));
    EXPECT_NE(w.find(at + "ISYM must be 0 or 1 (faces on symmetry planes left out of the contact; got 2)"),
              std::string::npos)
        << w;
    EXPECT_EQ(read_keyword_string(deck(row.keyword, "1,1,0\n"), "c.k").contacts.at(0).isym, 1);
    EXPECT_EQ(read_keyword_string(deck(row.keyword, "0,0,1\n"), "c.k").contacts.at(0).iadj, 1);
    w = refusal<InputError>(deck(row.keyword, "0,1,2\n"));
    EXPECT_NE(w.find(at + "IADJ must be 0 (faces on the free boundary) or 1"), std::string::npos) << w;
    w = refusal<InputError>(deck(row.keyword, "0,2,0\n"));
    EXPECT_NE(w.find(at + "EROSOP must be 0 or 1 (got 2)"), std::string::npos) << w;
    w = refusal<InputError>(deck(row.keyword, "0,1,0,7\n"));
    EXPECT_NE(w.find(at + "4 = 7"), std::string::npos) << w;
  }
}

// *CONTROL_CONTACT: ENMASS 0, 1, 2 are read (freed nodes leave the contact, or stay as free masses:
// docs/contact_erosion.md), other values are input errors naming the field and value; NSEROD is
// refused; ECDT only chooses the step and is warned about.
TEST(ErodingContactCards, ControlContactErosionFields) {
  const std::string head = "*KEYWORD\n*CONTROL_CONTACT\n";
  for (int enmass : {0, 1, 2})
    EXPECT_EQ(read_keyword_string(head + "0.1,0,1,0,1,0,1," + std::to_string(enmass) + "\n*END\n", "c.k")
                  .control_contact.enmass,
              enmass);
  std::string w = refusal<InputError>(head + "0.1,0,1,0,1,0,1,3\n*END\n");
  EXPECT_NE(w.find("c.k:3: *CONTROL_CONTACT card 1: field ENMASS must be 0, 1 or 2"), std::string::npos) << w;
  EXPECT_NE(w.find("got 3"), std::string::npos) << w;
  w = refusal<NotImplementedError>(head + "\n\n\n\n0,1\n*END\n");
  EXPECT_NE(w.find("field NSEROD = 1"), std::string::npos) << w;
  std::vector<Diagnostic> warnings;
  read_keyword_string(head + "\n0,0,0,0,4,0,1\n*END\n", "c.k", &warnings);
  bool warned = false;
  for (const auto& d : warnings) warned = warned || d.message.find("ECDT = 1") != std::string::npos;
  EXPECT_TRUE(warned);
}

}  // namespace
}  // namespace slideline
