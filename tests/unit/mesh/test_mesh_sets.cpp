// MeshSets: the deck's node, part and segment sets kept in the Simulation by build_simulation.
#include <gtest/gtest.h>

#include <string>

#include "slideline/core/error.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/mesh/segment_geometry.hpp"
#include "slideline/mesh/surface_builder.hpp"
#include "slideline/solver/build.hpp"
#include "test_support/mesh_fixtures.hpp"

using namespace slideline;

namespace {

std::string deck_path(const std::string& name) {
  return std::string(SLIDELINE_SOURCE_DIR) + "/tests/data/decks/" + name;
}

std::string build_error(const model::Model& m) {
  try {
    build_simulation(m);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST(MeshSets, FilledFromADeck) {
  model::Model m = read_keyword_file(deck_path("solid_on_solid_type3.k"));
  m.contacts.clear();  // contact is not built yet; the sets are
  auto sim = build_simulation(m);
  const MeshSets& s = sim->sets();
  // Node ids 1-16 are internal 0-15.
  EXPECT_EQ(s.node_sets.at(1), (std::vector<Index>{8, 9, 10, 11}));
  EXPECT_EQ(s.node_sets.at(2), (std::vector<Index>{9, 10, 13, 14}));
  EXPECT_EQ(s.node_set_titles.at(1), "lower bottom");
  EXPECT_EQ(s.node_set_titles.at(2), "");
  EXPECT_EQ(s.part_sets.at(1), (std::vector<Id>{1}));
  EXPECT_EQ(s.part_set_titles.at(1), "upper parts");
  ASSERT_EQ(s.segment_sets.size(), 2u);
  EXPECT_EQ(s.segment_sets.at(1), (std::vector<SegmentNodes>{{0, 1, 2, 3}}));
  EXPECT_EQ(s.segment_sets.at(2), (std::vector<SegmentNodes>{{12, 13, 14, 15}}));
  EXPECT_EQ(s.segment_set_titles.at(1), "upper bottom");
  EXPECT_EQ(s.part_nodes.at(1), (std::vector<Index>{0, 1, 2, 3, 4, 5, 6, 7}));
  EXPECT_EQ(s.part_nodes.at(2), (std::vector<Index>{8, 9, 10, 11, 12, 13, 14, 15}));
  EXPECT_EQ(s.node_set(1, "t").size(), 4u);
  EXPECT_THROW(s.node_set(3, "t"), InputError);
  EXPECT_THROW(s.segment_set(3, "t"), InputError);

  // The deck's segments face each other once oriented: 1-2-3-4 (upper bottom) already points
  // out of the upper block (-y); 13-14-15-16 is written pointing into the lower block, so it
  // is reversed to +y. (Both elements of this deck have 1-4 clockwise seen from 5-8, i.e. a
  // negative volume; the builder orients by the volume sign, so the normals are still outward.)
  const Surface up = build_surface_from_segments(sim->blocks(), sim->nodes(), s.segment_set(1, "t"), "ss1");
  const Surface lo = build_surface_from_segments(sim->blocks(), sim->nodes(), s.segment_set(2, "t"), "ss2");
  EXPECT_NEAR((segment_normal(up, 0, sim->nodes().x0) - Vec3(0, -1, 0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((segment_normal(lo, 0, sim->nodes().x0) - Vec3(0, 1, 0)).norm(), 0.0, 1e-15);
  EXPECT_EQ(lo.conn, (std::vector<Index>{12, 15, 14, 13}));
  EXPECT_EQ(up.part, (std::vector<Id>{1}));
  EXPECT_EQ(lo.part, (std::vector<Id>{2}));
  // The part set gives the whole upper block, whose bottom is the segment set's face.
  const Surface ps = build_surface_from_parts(sim->blocks(), sim->nodes(), s.part_set(1, "t"), "ps1");
  EXPECT_EQ(ps.segment_count(), 6);
}

TEST(MeshSets, SegmentSetWithAnUnknownNodeNamesTheCard) {
  model::Model m = test_support::hex_grid_model(1, 1, 1);
  m.segment_sets.push_back({5, "", {{1, 2, 4, 3}, {1, 2, 999, 5}}, {"deck.k", 40}});
  EXPECT_EQ(build_error(m),
            "deck.k:40: *SET_SEGMENT 5 refers to node 999, which the deck does not define");
}

TEST(MeshSets, BadSetsAreInputErrors) {
  {
    model::Model m = test_support::hex_grid_model(1, 1, 1);
    m.node_sets.push_back({3, "", {1, 77}, {"deck.k", 8}});  // unused, still checked
    EXPECT_EQ(build_error(m),
              "deck.k:8: *SET_NODE_LIST 3 refers to node 77, which the deck does not define");
  }
  {
    model::Model m = test_support::hex_grid_model(1, 1, 1);
    m.node_sets.push_back({1, "", {1, 2}, {"deck.k", 10}});
    m.node_sets.push_back({1, "", {3}, {"deck.k", 12}});
    EXPECT_EQ(build_error(m), "deck.k:12: duplicate *SET_NODE id 1");
  }
  {
    model::Model m = test_support::hex_grid_model(1, 1, 1);
    m.part_sets.push_back({4, "", {1, 8}, {"deck.k", 20}});
    EXPECT_EQ(build_error(m),
              "deck.k:20: *SET_PART 4 refers to part 8, which the deck does not define");
  }
  {
    model::Model m = test_support::hex_grid_model(1, 1, 1);
    m.spcs.push_back({0, "", 6, 0, {1, 1, 1, 0, 0, 0}, {"deck.k", 30}});
    EXPECT_EQ(build_error(m), "deck.k:30: NSID refers to node set 6, which the deck does not define");
  }
}

TEST(MeshSets, ShellDeckSetsResolve) {
  model::Model m = read_keyword_file(deck_path("shells_all_contacts.k"));
  m.contacts.clear();            // not built yet
  auto sim = build_simulation(m);
  const MeshSets& s = sim->sets();
  EXPECT_EQ(s.node_sets.at(1).size(), 9u);
  EXPECT_EQ(s.part_sets.at(2), (std::vector<Id>{2, 3}));
  // Its two prescribed motions on node set 1: "pull" (DOF 2, VAD 2) and a velocity (DOF 1, VAD 0).
  ASSERT_EQ(sim->supports().size(), 2u);
  EXPECT_EQ(sim->supports()[0].name, "pull");
  EXPECT_EQ(sim->supports()[0].supports.at(0).kind, Prescribed::displacement);
  EXPECT_EQ(sim->supports()[1].supports.at(0).kind, Prescribed::velocity);
  EXPECT_EQ(sim->supports()[1].supports.at(0).axis, Axis::x);
  EXPECT_EQ(sim->supports()[1].supports.at(0).nodes.size(), 9u);
  ASSERT_EQ(s.segment_sets.size(), 2u);
  // Segment set 1 (nodes 11 12 13 14) is shell 5 of part 2.
  const Surface ss1 = build_surface_from_segments(sim->blocks(), sim->nodes(), s.segment_set(1, "t"), "ss1");
  EXPECT_EQ(ss1.kind[0], SegmentKind::shell);
  EXPECT_EQ(ss1.part[0], 2);
  EXPECT_EQ(ss1.thickness[0], 0.1);
  // This seed deck's segment set 2 (nodes 1 2 3 4, three of them on one line) is no element's
  // face, and part set 2 names part 3, which has no elements: both are reported, not skipped.
  EXPECT_THROW(build_surface_from_segments(sim->blocks(), sim->nodes(), s.segment_set(2, "t"), "ss2"),
               InputError);
  EXPECT_THROW(build_surface_from_parts(sim->blocks(), sim->nodes(), s.part_set(2, "t"), "ps2"),
               InputError);
}
