// NodalElementSteps (solver/nodal_element_steps.hpp): per node, 1 / dt_e^2 of the smallest vote of
// the element blocks (that bound the step) it belongs to, through the view the contact votes read
// (contact/element_steps_view.hpp), and the rule 1 / dt^2 = 1 / dt_e^2 + 1 / dt_c^2.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "slideline/contact/element_steps_view.hpp"
#include "slideline/solver/nodal_element_steps.hpp"

namespace slideline {
namespace {

/// A block of nothing but connectivity (two-node "elements"), bounding the step or not.
class ConnectivityBlock final : public ElementBlock {
 public:
  ConnectivityBlock(std::vector<Index> conn, bool bounds) : conn_(std::move(conn)), bounds_(bounds) {}
  std::string kind() const override { return "stub"; }
  Id part_id() const override { return 1; }
  Index element_count() const override { return static_cast<Index>(conn_.size() / 2); }
  std::span<const Index> connectivity() const override { return conn_; }
  Id element_id(Index e) const override { return e + 1; }
  BlockTopology topology() const override { return {}; }
  bool bounds_time_step() const override { return bounds_; }
  void initialize(NodalFields&) override {}
  Real compute_forces(const NodalFields&, Real, CornerBuffer&, BlockEnergy&) override { return 0.0; }

 private:
  std::vector<Index> conn_;
  bool bounds_;
};

TEST(NodalElementSteps, EachNodeTakesTheSmallestVoteOfItsBlocks) {
  // Nodes 0-5: block 0 holds 0-2, block 1 holds 2-4 (node 2 in both), block 2 (rigid: does not
  // bound the step) holds 4-5; node 5 is in no bounding block.
  ElementBlocks blocks;
  blocks.push_back(std::make_unique<ConnectivityBlock>(std::vector<Index>{0, 1, 1, 2}, true));
  blocks.push_back(std::make_unique<ConnectivityBlock>(std::vector<Index>{2, 3, 3, 4, 4, 2}, true));
  blocks.push_back(std::make_unique<ConnectivityBlock>(std::vector<Index>{4, 5}, false));
  NodalElementSteps steps;
  EXPECT_TRUE(steps.view().empty());
  steps.build(blocks, 6);
  ASSERT_TRUE(steps.built());
  EXPECT_EQ(steps.group_count(), 4u);  // none, {0}, {0, 1}, {1}
  const std::vector<Real> votes{0.5, 0.25, 1e-9};
  steps.update(votes);
  const ElementStepsView v = steps.view();
  EXPECT_EQ(v.at(0), 4.0);   // 1 / 0.5^2
  EXPECT_EQ(v.at(1), 4.0);
  EXPECT_EQ(v.at(2), 16.0);  // the smaller vote of blocks 0 and 1
  EXPECT_EQ(v.at(3), 16.0);
  EXPECT_EQ(v.at(4), 16.0);  // the rigid block's vote does not count
  EXPECT_EQ(v.at(5), 0.0);
  // A block that votes nothing (+max: every element deleted) adds nothing.
  steps.update(std::vector<Real>{std::numeric_limits<Real>::max(), 0.25, 1.0});
  EXPECT_EQ(steps.view().at(0), 0.0);
  EXPECT_EQ(steps.view().at(2), 16.0);
  // A pair: its slave and the master nodes with a weight.
  const Index masters[4] = {0, 1, 3, 5};
  const Real weights[4] = {0.5, 0.5, 0.0, 0.0};
  EXPECT_EQ(steps.view().pair(5, masters, weights, 4), 0.0);    // node 3 has no weight
  EXPECT_EQ(steps.view().pair(4, masters, weights, 4), 16.0);   // the slave's own
  EXPECT_EQ(ElementStepsView{}.pair(4, masters, weights, 4), 0.0);
}

TEST(NodalElementSteps, TheRuleAddsTheInverseSquares) {
  // dt_e = 3, dt_c = 4: 1 / dt^2 = 1/9 + 1/16 = 25 / 144, dt = 12 / 5.
  const Real w2 = combined_step_inv2(1.0 / 16.0, 1.0 / 9.0);
  EXPECT_DOUBLE_EQ(1.0 / std::sqrt(w2), 2.4);
  // No element term: the spring's own, bit for bit; no spring: no vote.
  EXPECT_EQ(combined_step_inv2(0.3, 0.0), 0.3);
  EXPECT_EQ(combined_step_inv2(0.0, 5.0), 0.0);
}

}  // namespace
}  // namespace slideline
