// Cards the reader does not read: output and tuning cards warn once per keyword; physics cards are
// errors naming card and line, or, with ReadOptions::ignore_unsupported, dropped and named by the
// checks that meet their ids.
#include <gtest/gtest.h>

#include <string>

#include "slideline/core/error.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/solver/build.hpp"
#include "slideline/solver/validate_model.hpp"

namespace slideline {
namespace {

std::string reader_deck(const std::string& name) {
  return std::string(SLIDELINE_SOURCE_DIR) + "/tests/data/decks/reader/" + name;
}

/// The NotImplementedError message of reading `deck`, or "" when it reads.
std::string refusal(const std::string& deck) {
  try {
    read_keyword_string(deck, "u.k");
  } catch (const NotImplementedError& e) {
    return e.what();
  }
  return "";
}

TEST(KeywordUnsupported, PhysicsPrefixesAreErrorsOutputCardsAreNot) {
  for (const char* kw : {"*MAT_JOHNSON_COOK", "*SECTION_BEAM", "*ELEMENT_BEAM", "*LOAD_SEGMENT_SET",
                         "*BOUNDARY_NON_REFLECTING", "*INITIAL_STRESS_SOLID", "*CONSTRAINED_NODAL_RIGID_BODY",
                         "*RIGIDWALL_PLANAR_MOVING", "*CONTACT_SPOTWELD", "*CONTROL_IMPLICIT_GENERAL",
                         "*EOS_JWL", "*DEFINE_TABLE", "*SET_SHELL_LIST", "*SOMETHING_NEW"}) {
    const std::string what = refusal(std::string("*KEYWORD\n") + kw + "\n         1\n*END\n");
    EXPECT_EQ(what.rfind(std::string("u.k:2: ") + kw + " (", 0), 0u) << kw << ": " << what;
  }
  for (const char* kw : {"*CONTROL_ENERGY", "*CONTROL_OUTPUT", "*CONTROL_CPU", "*DATABASE_MATSUM",
                         "*DATABASE_EXTENT_BINARY", "*DATABASE_BINARY_D3THDT"}) {
    std::vector<Diagnostic> warnings;
    EXPECT_NO_THROW(read_keyword_string(std::string("*KEYWORD\n") + kw + "\n         1\n*END\n", "u.k", &warnings))
        << kw;
    ASSERT_EQ(warnings.size(), 1u) << kw;
    EXPECT_EQ(to_string(warnings[0]).rfind(std::string("u.k:2: ") + kw + " skipped: ", 0), 0u) << to_string(warnings[0]);
  }
}

TEST(KeywordUnsupported, OneLinePerKeywordWithIdsUsersAndLines) {
  std::vector<Diagnostic> warnings;
  std::string what;
  try {
    read_keyword_file(reader_deck("unsupported_cards.k"), &warnings);
  } catch (const NotImplementedError& e) {
    what = e.what();
  }
  const std::string deck = reader_deck("unsupported_cards.k");
  EXPECT_EQ(what.rfind(deck + ":26: *MAT_JOHNSON_COOK (material 3; used by part 1) is not supported\n" +
                           deck + ":28: *LOAD_SEGMENT (load) is not supported\n",
                       0),
            0u)
      << what;
  // The output cards: one warning per keyword, with the count, gathered before the error.
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(warnings[0].line, 4);
  EXPECT_NE(warnings[0].message.find("*CONTROL_ENERGY skipped"), std::string::npos);
  EXPECT_EQ(warnings[1].line, 6);
  EXPECT_NE(warnings[1].message.find("*DATABASE_EXTENT_BINARY skipped: output request that slideline does not use "
                                     "(2 keywords, first here)"),
            std::string::npos)
      << warnings[1].message;
}

TEST(KeywordUnsupported, DroppedCardsAreNamedByTheReferenceCheck) {
  std::vector<Diagnostic> warnings;
  ReadOptions o;
  o.ignore_unsupported = true;
  const auto m = read_keyword_file(reader_deck("unsupported_cards.k"), &warnings, o);
  ASSERT_EQ(m.unsupported.size(), 2u);
  EXPECT_EQ(m.unsupported[0].id, 3);
  EXPECT_EQ(m.unsupported[1].cards, 2);
  const auto problems = check_references(m);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].line, 23);  // the *PART card that names MID 3
  EXPECT_EQ(problems[0].message, "part 1 uses *MAT_JOHNSON_COOK (line 26), not supported");
  // build_simulation (validate_model) says the same when a caller skips check_references.
  try {
    build_simulation(m);
    FAIL() << "no exception";
  } catch (const NotImplementedError& e) {
    EXPECT_EQ(std::string(e.what()), reader_deck("unsupported_cards.k") +
                                         ":23: part 1 uses *MAT_JOHNSON_COOK (line 26), not supported");
  }
  // The point load is referenced by nothing: dropped, listed, and the rest of the deck is clean.
  const auto v = read_keyword_file(reader_deck("dropped_load.k"), nullptr, o);
  EXPECT_TRUE(check_references(v).empty());
  const auto dropped = describe_dropped(v);
  ASSERT_EQ(dropped.size(), 1u);
  EXPECT_EQ(dropped[0].line, 24);
  EXPECT_EQ(dropped[0].message, "*LOAD_SEGMENT (id 5) dropped, 1 card(s)");
}

TEST(KeywordUnsupported, RepeatedElementProblemsAreOneLine) {
  std::string deck = "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n*PART\np\n1,1,1\n*SECTION_SHELL\n1\n0.1\n"
                     "*MAT_ELASTIC\n1,1,1,0.3\n*ELEMENT_SHELL\n";
  for (int e = 1; e <= 500; ++e) deck += std::to_string(e) + ",1,1,2,3,99\n";
  const auto m = read_keyword_string(deck, "many.k");
  const auto problems = check_references(m);
  ASSERT_EQ(problems.size(), 1u);  // one line for 500 dangling nodes, not 500 lines
  EXPECT_EQ(to_string(problems[0]),
            "many.k:15: *ELEMENT_SHELL refers to undefined nodes: 500 references (element -> node) (first: 1 -> 99, "
            "2 -> 99, 3 -> 99, ...)");
}

}  // namespace
}  // namespace slideline
