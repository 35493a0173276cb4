#pragma once
// Six tetrahedra per hexahedral cell (Kuhn's subdivision along the diagonal from corner 000 to
// 111): the same diagonal in every cell of a structured grid, so the tetrahedra of neighbouring
// cells share their faces (a conforming mesh).
#include <array>
#include <utility>

namespace test_support {

/// The six tetrahedra of one cell, as positions into `corner` (index i + 2 j + 4 k of the cell's
/// corner at offset (i, j, k)), each listed N1 N2 N3 counter-clockwise seen from N4 (positive
/// volume) for a cell with its edges along +x, +y, +z.
inline std::array<std::array<int, 4>, 6> kuhn_tets() {
  static constexpr int perms[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  std::array<std::array<int, 4>, 6> tets{};
  for (int p = 0; p < 6; ++p) {
    const int a = 1 << perms[p][0], b = a | (1 << perms[p][1]);
    tets[p] = {0, a, b, 7};
    if (p >= 3) std::swap(tets[p][1], tets[p][2]);  // odd permutations: turn the base round
  }
  return tets;
}

}  // namespace test_support
