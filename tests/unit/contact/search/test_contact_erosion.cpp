// ContactErosion (contact/search/contact_erosion.hpp): which faces are partners, and the flags
// while every element lives: a face with a partner (an interior face) is inactive, an exterior
// face active; a slave node is active while one of its own faces is, or when it has none (a node
// set's: while an element holding it lives). The
// flags after deletions are checked end to end by tests/verification/test_eroding_contact.cpp.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "slideline/contact/search/contact_erosion.hpp"
#include "slideline/mesh/surface_builder.hpp"

namespace slideline {
namespace {

/// Two hexahedra stacked (block 0, elements 0 and 1): the bottom face of element 0, the face
/// between them once per element (each oriented out of its own element), the top of element 1.
Surface stacked_faces() {
  Surface s;
  s.conn = {0, 3, 2, 1, 4, 5, 6, 7, 4, 7, 6, 5, 8, 9, 10, 11};
  s.block = {0, 0, 0, 0};
  s.element = {0, 0, 1, 1};
  s.part = {1, 1, 1, 1};
  s.kind.assign(4, SegmentKind::solid_face);
  s.thickness.assign(4, 0.0);
  build_surface_adjacency(s);
  return s;
}

TEST(ContactErosion, InteriorFacesArePartnersAndInactiveWhileBothElementsLive) {
  const Surface s = stacked_faces();
  SurfaceErosion e(s);
  EXPECT_EQ(e.partner(0), -1);
  EXPECT_EQ(e.partner(1), 2);
  EXPECT_EQ(e.partner(2), 1);
  EXPECT_EQ(e.partner(3), -1);
  e.bind({});  // no block erodes: every element lives
  EXPECT_FALSE(e.tracked());
  const std::vector<std::uint8_t> want = {1, 0, 0, 1};
  EXPECT_EQ(std::vector<std::uint8_t>(e.active().begin(), e.active().end()), want);
  EXPECT_FALSE(e.update());  // nothing changed
}

TEST(ContactErosion, SlaveNodesFollowTheirOwnFaces) {
  const Surface s = stacked_faces();
  const std::vector<Index> slaves = {0, 4, 8, 99};  // bottom, middle (interior only), top, off the surface
  ContactErosion e(s, nullptr, slaves);
  e.bind({});
  const std::vector<std::uint8_t> want = {1, 0, 1, 1};
  EXPECT_EQ(std::vector<std::uint8_t>(e.slave_active().begin(), e.slave_active().end()), want);
  // A separate own surface: the slaves read their flags from it, the segments from the master.
  Surface own = stacked_faces();
  ContactErosion two(s, &own, slaves);
  two.bind({});
  EXPECT_EQ(std::vector<std::uint8_t>(two.slave_active().begin(), two.slave_active().end()), want);
  EXPECT_EQ(two.own_active().size(), 4u);
}

// A node set's slaves (set_slave_elements) follow the elements that hold them, not their faces:
// the middle node, whose faces are all interior (inactive by the face rule above), is a slave while
// its elements live; so is a node held by no erodible element (99).
TEST(ContactErosion, NodeSetSlavesFollowTheirElements) {
  const Surface s = stacked_faces();
  Surface own = stacked_faces();
  const std::vector<Index> slaves = {0, 4, 8, 99};
  ContactErosion e(s, &own, slaves);
  e.set_slave_elements({0, 1, 3, 4, 4}, {{0, 0}, {0, 0}, {0, 1}, {0, 1}});
  e.bind({});  // no block erodes: every element lives
  const std::vector<std::uint8_t> want = {1, 1, 1, 1};
  EXPECT_EQ(std::vector<std::uint8_t>(e.slave_active().begin(), e.slave_active().end()), want);
  EXPECT_FALSE(e.update());
}

}  // namespace
}  // namespace slideline
