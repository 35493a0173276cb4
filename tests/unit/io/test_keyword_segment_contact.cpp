// SOFT = 2 (segment-based contact) in the reader: accepted on *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE,
// *CONTACT_AUTOMATIC_SINGLE_SURFACE and *CONTACT_SURFACE_TO_SURFACE (the build refuses shells
// there) with SBOPT and DEPTH at their defaults (2; 0 and blank mean 2); BSORT >= 0 read (cycles between searches, honoured by SegmentContact); every other SBOPT,
// DEPTH, LCIDAB, a negative BSORT (a load curve), the SOFT = 2 fields of optional cards D-F, and
// SOFT = 2 on another card are refused naming file, line, card, field and value. docs/contact.md,
// "Segment-based contact (SOFT = 2)".
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "slideline/core/error.hpp"
#include "slideline/io/keyword_reader.hpp"

namespace slideline {
namespace {

/// A fixed-format card of 10-character fields.
std::string card(const std::vector<std::string>& fields) {
  std::string out;
  for (const auto& v : fields) out += std::string(10 - std::min<std::size_t>(10, v.size()), ' ') + v;
  return out + "\n";
}

/// A contact deck: card 1 on line 3, cards 2 and 3 blank, optional card A (`card_a`) on line 6,
/// then `extra`.
std::string deck(const std::string& card_a, const std::string& extra = "",
                 const std::string& type = "AUTOMATIC_SURFACE_TO_SURFACE") {
  return "*KEYWORD\n*CONTACT_" + type + "\n" + card({"1", "2", "3", "3"}) + card({}) + card({}) + card_a + extra +
         "*END\n";
}

std::string refusal(const std::string& text) {
  try {
    read_keyword_string(text, "u.k", nullptr);
  } catch (const NotImplementedError& e) {
    return e.what();
  } catch (const InputError& e) {
    return std::string("input error: ") + e.what();
  }
  return "";
}

TEST(KeywordSegmentContact, SoftTwoIsReadWithItsDefaultOptions) {
  for (const std::string& a : {card({"2"}), card({"2", "", "", "", "2", "2"}), card({"2", "", "0", "", "0", "0"})}) {
    const model::Model m = read_keyword_string(deck(a), "u.k", nullptr);
    ASSERT_EQ(m.contacts.size(), 1u);
    EXPECT_EQ(m.contacts[0].soft, 2) << a;
  }
  for (const std::string type : {"AUTOMATIC_SINGLE_SURFACE", "SURFACE_TO_SURFACE"}) {  // Type 3: solid faces
    const model::Model m = read_keyword_string(deck(card({"2"}), "", type), "u.k", nullptr);
    ASSERT_EQ(m.contacts.size(), 1u);
    EXPECT_EQ(m.contacts[0].soft, 2) << type;
  }
}

TEST(KeywordSegmentContact, OtherOptionsAndCardsAreRefusedNamingFileLineFieldAndValue) {
  const std::string blank = card({});
  struct Case {
    std::string deck, expected;
  };
  const std::vector<Case> cases = {
      {deck(card({"2", "", "", "", "1"})), "u.k:6: *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE optional card A: field SBOPT = 1 (pinball edge checking) is not implemented"},
      {deck(card({"2", "", "", "", "3"})), "u.k:6: *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE optional card A: field SBOPT = 3 (warped segment checking)"},
      {deck(card({"2", "", "", "", "4"})), "field SBOPT = 4 (sliding option)"},
      {deck(card({"2", "", "", "", "5"})), "field SBOPT = 5 (warped segment checking and sliding option)"},
      {deck(card({"2", "", "", "", "7"})), "input error: u.k:6: *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE optional card A: field SBOPT = 7"},
      {deck(card({"2", "", "", "", "", "3"})), "u.k:6: *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE optional card A: field DEPTH = 3 (segment-based search depth and edge-to-edge checks) is not implemented"},
      {deck(card({"2", "", "", "", "", "5"})), "field DEPTH = 5"},
      {deck(card({"2", "", "1"})), "u.k:6: *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE optional card A: field LCIDAB = 1"},
      {deck(card({"2", "", "", "", "", "", "-3"})), "u.k:6: *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE optional card A: field BSORT = -3 (load curve of the bucket sort interval) is not implemented"},
      {deck(card({"2"}), blank + blank + card({"1"})), "u.k:9: *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE optional card D: field Q2TRI = 1"},
      {deck(card({"2"}), blank + blank + blank + card({"", "", "", "", "0.5"})), "optional card E: field FRICSF = 0.5"},
      {deck(card({"2"}), "", "ONE_WAY_SURFACE_TO_SURFACE"), "u.k:6: *CONTACT_ONE_WAY_SURFACE_TO_SURFACE optional card A: field SOFT = 2"},
      {deck(card({"2"}), "", "SURFACE_TO_SURFACE_LAGRANGE"), "u.k:6: *CONTACT_SURFACE_TO_SURFACE_LAGRANGE optional card A: field SOFT = 2"},
      {deck(card({"2", "", "", "", "", "3"}), "", "SURFACE_TO_SURFACE"), "u.k:6: *CONTACT_SURFACE_TO_SURFACE optional card A: field DEPTH = 3"},
      {deck(card({"2"}), "", "AUTOMATIC_GENERAL"), "u.k:6: *CONTACT_AUTOMATIC_GENERAL optional card A: field SOFT = 2"},
      {deck(card({"2", "", "", "", "1"}), "", "AUTOMATIC_SINGLE_SURFACE"), "u.k:6: *CONTACT_AUTOMATIC_SINGLE_SURFACE optional card A: field SBOPT = 1"},
  };
  for (const Case& c : cases) {
    const std::string msg = refusal(c.deck);
    EXPECT_NE(msg.find(c.expected), std::string::npos) << "expected '" << c.expected << "', got '" << msg << "'\n"
                                                       << c.deck;
  }
}

TEST(KeywordSegmentContact, BsortIsReadWithSoftTwoWithoutAWarning) {
  for (const int bsort : {0, 1, 25}) {
    std::vector<Diagnostic> warnings;
    const model::Model m = read_keyword_string(
        deck(card({"2", "", "", "", "", "", bsort == 0 ? "" : std::to_string(bsort)})), "u.k", &warnings);
    ASSERT_EQ(m.contacts.size(), 1u);
    EXPECT_EQ(m.contacts[0].bsort, bsort);
    for (const Diagnostic& d : warnings) EXPECT_EQ(d.message.find("BSORT"), std::string::npos) << d.message;
  }
}

TEST(KeywordSegmentContact, SoftTwoOnlyFieldsAreStillWarnedAboutWithSoftZero) {
  std::vector<Diagnostic> warnings;
  read_keyword_string(deck(card({"0", "", "", "", "3"})), "u.k", &warnings);
  bool found = false;
  for (const Diagnostic& d : warnings) found = found || d.message.find("SBOPT = 3") != std::string::npos;
  EXPECT_TRUE(found);
}

}  // namespace
}  // namespace slideline
