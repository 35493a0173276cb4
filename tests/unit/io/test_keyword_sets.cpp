// *KEYWORD_ID, *SET_NODE_LIST_GENERATE and *SET_NODE_GENERAL (src/io/keyword_sets.cpp).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "slideline/core/error.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/io/keyword_writer.hpp"

namespace slideline {
namespace {

/// A 2 x 1 row of shells (part 1: nodes 1 2 5 4; part 2: nodes 2 3 6 5) in the x-y plane, node
/// ids 1-6 at x = 0, 1, 2 (y = 0, then y = 1), and a node 10 far away. The cards under test come
/// first, so that the sets' nodes, parts and boxes are all defined after them.
std::string deck_with(const std::string& cards) {
  return "*KEYWORD\n" + cards +
         "*NODE\n1,0,0,0\n2,1,0,0\n3,2,0,0\n4,0,1,0\n5,1,1,0\n6,2,1,0\n10,50,0,0\n"
         "*ELEMENT_SHELL\n1,1,1,2,5,4\n2,2,2,3,6,5\n"
         "*PART\na\n1,1,1\nb\n2,1,1\n"
         "*DEFINE_BOX\n7,0.5,2.5,-0.5,0.5,-1,1\n*END\n";
}

std::vector<Id> set_nodes(const std::string& cards) {
  const auto m = read_keyword_string(deck_with(cards), "sets.k");
  EXPECT_EQ(m.node_sets.size(), 1u);
  return m.node_sets.empty() ? std::vector<Id>{} : m.node_sets.front().nodes;
}

std::string error_of(const std::string& cards) {
  try {
    read_keyword_string(deck_with(cards), "sets.k");
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(KeywordSets, KeywordIdIsKeptAsTheTitleUnlessTheDeckHasOne) {
  const std::string id_card = "*KEYWORD_ID\nproject   42        stage 1\n";
  const auto m = read_keyword_string(id_card + "*NODE\n1,0,0,0\n*END\n", "id.k");
  EXPECT_EQ(m.title, "project   42        stage 1");
  EXPECT_EQ(m.nodes.size(), 1u);
  EXPECT_EQ(read_keyword_string(write_keyword_string(m), "back.k").title, m.title);
  EXPECT_EQ(read_keyword_string(id_card + "*TITLE\nthe title\n*END\n", "id.k").title, "the title");
}

TEST(KeywordSets, KeywordIdLineTakesTheFormatOptions) {
  // LONG=Y on the *KEYWORD_ID line widens the rest of the file as on *KEYWORD.
  const auto m = read_keyword_string(
      "*KEYWORD_ID LONG=Y\nid\n*NODE\n                   7                 1.5                 2.5\n*END\n", "id.k");
  ASSERT_EQ(m.nodes.size(), 1u);
  EXPECT_EQ(m.nodes[0].id, 7);
  EXPECT_DOUBLE_EQ(m.nodes[0].x[1], 2.5);
}

TEST(KeywordSets, GenerateTakesTheDefinedNodesOfEachRange) {
  // 2-5 and 10-20: ids 2 3 4 5 and 10 (11-20 are not defined); the nodes come after the set.
  EXPECT_EQ(set_nodes("*SET_NODE_LIST_GENERATE\n3\n2,5,10,20\n"), (std::vector<Id>{2, 3, 4, 5, 10}));
  EXPECT_EQ(set_nodes("*SET_NODE_LIST_GENERATE_TITLE\nends\n3\n1,1\n0,0,6,6\n"), (std::vector<Id>{1, 6}));
}

TEST(KeywordSets, GenerateRefusesAnInvertedRangeNamingTheFields) {
  const std::string e = error_of("*SET_NODE_LIST_GENERATE\n3\n5,2\n");
  EXPECT_NE(e.find("sets.k:4: fields B1BEG, B1END of *SET_NODE_LIST_GENERATE"), std::string::npos) << e;
}

TEST(KeywordSets, GeneralAddsAndRemovesInCardOrder) {
  EXPECT_EQ(set_nodes("*SET_NODE_GENERAL\n4\nALL\n"), (std::vector<Id>{1, 2, 3, 4, 5, 6, 10}));
  EXPECT_EQ(set_nodes("*SET_NODE_GENERAL\n4\nPART,2\n"), (std::vector<Id>{2, 3, 5, 6}));
  EXPECT_EQ(set_nodes("*SET_NODE_GENERAL\n4\nPART,1,2\nDPART,2\nNODE,10\n"), (std::vector<Id>{1, 4, 10}));
  // Box 7: 0.5 <= x <= 2.5, -0.5 <= y <= 0.5 holds nodes 2 and 3.
  EXPECT_EQ(set_nodes("*SET_NODE_GENERAL\n4\nBOX,7\n"), (std::vector<Id>{2, 3}));
  EXPECT_EQ(set_nodes("*SET_NODE_GENERAL\n4\nALL\nDBOX,7\nDNODE,10,1\n"), (std::vector<Id>{4, 5, 6}));
  // Fixed columns: OPTION in 1-10, E1.. in 11-20, ...
  EXPECT_EQ(set_nodes("*SET_NODE_GENERAL_TITLE\nfixed\n         4\nNODE               6         1\n"),
            (std::vector<Id>{1, 6}));
}

TEST(KeywordSets, GeneralRefusesWhatItDoesNotResolve) {
  std::string e = error_of("*SET_NODE_GENERAL\n4\nSET_SHELL,1\n");
  EXPECT_NE(e.find("sets.k:4: field OPTION of *SET_NODE_GENERAL: 'SET_SHELL' is not supported"), std::string::npos) << e;
  EXPECT_THROW(read_keyword_string(deck_with("*SET_NODE_GENERAL\n4\nSHELL,1\n"), "sets.k"), NotImplementedError);
  e = error_of("*SET_NODE_GENERAL\n4\nPART,9\n");
  EXPECT_NE(e.find("sets.k:4: field E of *SET_NODE_GENERAL (PART) refers to part 9"), std::string::npos) << e;
  e = error_of("*SET_NODE_GENERAL\n4\nNODE,1\nBOX,8\n");
  EXPECT_NE(e.find("sets.k:5: field E of *SET_NODE_GENERAL (BOX) refers to box 8"), std::string::npos) << e;
}

TEST(KeywordSets, GeneratedSetIsWrittenAsAListAndReadsBackEqual) {
  const auto m = read_keyword_string(deck_with("*SET_NODE_GENERAL\n4\nPART,1\n"), "sets.k");
  const auto back = read_keyword_string(write_keyword_string(m), "back.k");
  EXPECT_EQ(back.node_sets, m.node_sets);
  EXPECT_EQ(back.node_sets.at(0).nodes, (std::vector<Id>{1, 2, 4, 5}));
}

}  // namespace
}  // namespace slideline
