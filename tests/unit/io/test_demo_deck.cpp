// The demo deck the README's main command runs is the scenario generator's merged two-block model,
// written by the keyword writer: reading it back must give that model again.
#include <gtest/gtest.h>

#include "slideline/io/keyword_reader.hpp"
#include "slideline/scenarios/two_block.hpp"
#include "unit/io/model_equal.hpp"

using namespace slideline;

TEST(DemoDeck, IsTheMergedTwoBlockScenario) {
  const model::Model deck =
      read_keyword_file(std::string(SLIDELINE_SOURCE_DIR) + "/examples/decks/merged_blocks.k");
  scenarios::TwoBlockOptions o;
  o.merged = true;
  model::Model generated = scenarios::make_solid_pair_model(o);
  generated.title = deck.title;
  EXPECT_EQ(test::model_difference(deck, generated), "");
}
