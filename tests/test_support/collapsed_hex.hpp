#pragma once
// Pentahedra and pyramids cut out of a hexahedron, written as LS-DYNA writes them in
// *ELEMENT_SOLID: a pentahedron N1 N2 N3 N4 N5 N5 N6 N6 (N1 N2 N3 N4 a quadrilateral face,
// N5-N6 the opposite edge: triangles N1 N2 N5 and N4 N3 N6), a pyramid N1 N2 N3 N4 N5 N5 N5 N5
// (base N1-N4 counter-clockwise seen from the apex N5). T is anything that names a node (a deck
// id, an internal index).
#include <array>
#include <vector>

#include "slideline/mesh/element_topology.hpp"

namespace test_support {

/// The two pentahedra of hexahedron `c` (LS-DYNA order) cut by the diagonal plane through its
/// edges 1-5 and 3-7, both of positive volume when the hexahedron is. Their collapsed edges are
/// 3-7 (first) and 1-5 (second): each carries a double share of its pentahedron's lumped mass,
/// so the two faces x = const of a cell of a grid (i along N1-N2) carry equal masses.
template <class T>
std::array<std::array<T, 8>, 2> split_into_pentahedra(const std::array<T, 8>& c) {
  // Triangle 2 1 3 (0-based 1 0 2) with the quadrilateral 2 1 5 6 seen counter-clockwise from 3;
  // triangle 4 3 1 with the quadrilateral 4 3 7 8 seen counter-clockwise from 1.
  return {{{c[1], c[0], c[4], c[5], c[2], c[2], c[6], c[6]},
           {c[3], c[2], c[6], c[7], c[0], c[0], c[4], c[4]}}};
}

/// The six pyramids of hexahedron `c` (LS-DYNA order) with the apex `centre` inside it, one per
/// face: the base is the face (element_topology.hpp's hex8 face, outward) reversed, so it runs
/// counter-clockwise seen from the apex.
template <class T>
std::vector<std::array<T, 8>> split_into_pyramids(const std::array<T, 8>& c, T centre) {
  std::vector<std::array<T, 8>> out;
  for (const auto& f : slideline::topology_detail::hex8_faces)
    out.push_back({c[f[0]], c[f[3]], c[f[2]], c[f[1]], centre, centre, centre, centre});
  return out;
}

}  // namespace test_support
