// The tie search's shell offsets (TieSearchOptions::master_offset, node_offset; the automatic
// tiebreak's OPTION 8): a slave is tied within normal_tol x the segment diagonal of the two contact
// surfaces, |gap| <= 0.3 sqrt(2) + o_m + o_s on a unit square, on either side of the segment; with
// no offsets the bound is the solid faces' 0.3 sqrt(2) = 0.42426, as before.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "slideline/contact/search/tie_search.hpp"
#include "unit/contact/plate_surface.hpp"

using namespace slideline;

namespace {

constexpr Real kOm = 0.3, kOs = 0.2;  // master segment's and slave node's offsets

/// Ties a node at (0.5, 0.5, z) over the unit square at z = 0; true when tied.
bool tied_at(Real z, bool offsets) {
  Vec3Field x;
  const Surface master = test::make_plate(x, 1, 1, 1.0, Vec3::Zero());
  const Index slave = static_cast<Index>(x.size());
  x.x.push_back(0.5);
  x.y.push_back(0.5);
  x.z.push_back(z);
  const std::vector<Real> segment_table{kOm};
  std::vector<Real> node_table(x.size(), 0.0);
  node_table[static_cast<std::size_t>(slave)] = kOs;
  TieSearchOptions opt;
  if (offsets) {
    opt.master_offset = segment_table;
    opt.node_offset = node_table;
  }
  const std::vector<Index> slaves{slave};
  const TiePoint t = find_tie_points(slaves, master, x, opt).at(0);
  if (t.segment >= 0) EXPECT_NEAR(t.gap, z, 1e-14);  // the stand-off kept as found
  return t.segment >= 0;
}

}  // namespace

TEST(TieSearchOffsets, TiesWithinTheToleranceOfBothContactSurfaces) {
  const Real solid = 0.3 * std::sqrt(2.0);
  const Real shells = solid + kOm + kOs;
  for (Real side : {1.0, -1.0}) {
    EXPECT_TRUE(tied_at(side * (solid - 1e-6), false));
    EXPECT_FALSE(tied_at(side * (solid + 1e-6), false));
    EXPECT_TRUE(tied_at(side * (shells - 1e-6), true));
    EXPECT_FALSE(tied_at(side * (shells + 1e-6), true));
    EXPECT_TRUE(tied_at(side * (kOm + kOs), true));  // the offset gap closed: the surfaces touch
  }
}
