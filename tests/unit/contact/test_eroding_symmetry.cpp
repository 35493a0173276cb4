// ISYM = 1 of *CONTACT_ERODING_... (docs/contact_erosion.md): the solid faces on a symmetry plane
// are left out of the contact surface. A block of two hexahedra [0, 2] x [0, 1] x [0, 1] of an
// eroding part, cut by the symmetry planes x = 0 and z = 0 (x held on x = 0, z held on z = 0):
// its exterior has 10 faces; the x = 0 face and the two z = 0 faces lie on symmetry planes, so
// ISYM = 1 keeps 7. The interior face x = 1 (two copies, one per element: EROSOP = 1) has its
// normal along x but nodes not held in x: kept. The y = 0 faces hold nodes held in x and z but not
// in y (their normal): kept. ISYM = 0 keeps every face.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "slideline/contact/interface_spec.hpp"
#include "slideline/contact/make_contact_interface.hpp"
#include "slideline/element/element_block.hpp"
#include "slideline/element/element_erosion.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/solver/build.hpp"
#include "slideline/solver/held_axes.hpp"

namespace slideline {
namespace {

std::string deck(int isym, int erosop) {
  return "*KEYWORD\n*CONTROL_TERMINATION\n1.0\n*SECTION_SOLID\n1,1\n*MAT_ELASTIC\n1,1.0,1000.0,0.3\n"
         "*MAT_ADD_EROSION\n1\n,,1.0e6\n*PART\nblock\n1,1,1\n*NODE\n"
         "1,0,0,0\n2,1,0,0\n3,2,0,0\n4,0,1,0\n5,1,1,0\n6,2,1,0\n7,0,0,1\n8,1,0,1\n9,2,0,1\n10,0,1,1\n11,1,1,1\n"
         "12,2,1,1\n*ELEMENT_SOLID\n1,1,1,2,5,4,7,8,11,10\n2,1,2,3,6,5,8,9,12,11\n"
         "*SET_NODE_LIST\n1\n1,4,7,10\n*SET_NODE_LIST\n2\n1,2,3,4,5,6\n*BOUNDARY_SPC_SET\n1,0,1,0,0\n"
         "*BOUNDARY_SPC_SET\n2,0,0,0,1\n*CONTACT_ERODING_SINGLE_SURFACE\n1,,3\n\n\n" +
         std::to_string(isym) + "," + std::to_string(erosop) + ",0\n*END\n";
}

/// The slave surface's segment count of the deck's contact after prepare_eroding_contact.
Index faces(int isym, int erosop) {
  const model::Model m = read_keyword_string(deck(isym, erosop), "sym.k");
  const SimulationSetup setup = build_setup(m);
  const std::vector<std::uint8_t> held = held_axes(setup.supports, setup.nodes.size());  // as build.cpp
  const ContactBuildContext ctx{m, setup.blocks, setup.nodes, setup.sets, held};
  InterfaceSpec spec = resolve_interface(m.contacts.at(0), 1, ctx);
  std::vector<Id> eroding(setup.nodes.size(), 0);
  for (const auto& b : setup.blocks)
    if (std::as_const(*b).erosion())
      for (Index n : b->connectivity()) eroding[static_cast<std::size_t>(n)] = b->part_id();
  prepare_eroding_contact(spec, ctx, eroding);
  EXPECT_EQ(spec.master.surface.segment_count(), spec.slave.surface.segment_count());  // single surface
  return spec.slave.surface.segment_count();
}

TEST(ErodingContactSymmetry, FacesOnSymmetryPlanesLeaveTheSurface) {
  EXPECT_EQ(faces(0, 0), 10);
  EXPECT_EQ(faces(1, 0), 7);
  EXPECT_EQ(faces(0, 1), 12);
  EXPECT_EQ(faces(1, 1), 9);
}

}  // namespace
}  // namespace slideline
