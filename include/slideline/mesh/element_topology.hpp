#pragma once
/// Declared element topologies: what mesh code (surfaces, segment stiffness, output) needs to know
/// of an element's shape, so that it never guesses a shape from a node count or a block's class.
/// An element block reports the topology of each of its elements (mesh/block_topology.hpp); a
/// new element shape is a new constant here plus a row of all_topologies.
///
/// Face orientation: the faces of a solid are listed with OUTWARD node order for an element of
/// positive measure, i.e. counter-clockwise seen from outside, so that
/// (x[f[2]] - x[f[0]]) x (x[f[3]] - x[f[1]]) points out (the segment convention of
/// mesh/surface.hpp). A triangle repeats its third node as the fourth (f[2] == f[3]). A surface
/// element (a shell) has one face, itself, in its own node order (its normal).
#include <array>
#include <span>
#include <string_view>

#include "slideline/core/types.hpp"
#include "slideline/mesh/hex8_geometry.hpp"
#include "slideline/mesh/nodal_fields.hpp"

namespace slideline {

/// Local node indices (0-based, into one element's connectivity) of one face.
using LocalFace = std::array<int, 4>;

struct ElementTopology {
  std::string_view name;              ///< "hex8", "quad4", "tet4", "tri3"
  int dimension = 0;                  ///< 3: a solid bounded by its faces; 2: a surface element
  int nodes = 0;                      ///< nodes per element in its connectivity
  std::span<const LocalFace> faces;   ///< see the header comment for the order
  std::string_view cell_set;          ///< output name of its cells (HDF5 /mesh/<cell_set>)
  std::string_view xdmf_cell;         ///< XDMF TopologyType
  int vtk_cell = 0;                   ///< VTK cell type id
  /// Measure of one element whose `nodes` internal node indices start at `c`, at coordinates
  /// `x`: the signed volume of a solid (length^3, positive in the node order the faces assume),
  /// the area of a surface element (length^2, >= 0).
  Real (*measure)(const Vec3Field& x, const Index* c) = nullptr;

  bool is_solid() const { return dimension == 3; }
};

namespace topology_detail {

inline Real hex8_volume(const Vec3Field& x, const Index* c) {
  const hex8::NodeMat X = gather_rows<8>(x, c);
  return hex8::volume(X, hex8::volume_gradient(X));
}

/// Half the cross product of the diagonals, the formula of segment_area (mesh/segment_geometry.hpp):
/// a shell's volume A t over its segment's area is then exactly t.
inline Real quad4_area(const Vec3Field& x, const Index* c) {
  const Vec3 d1 = x.get(c[2]) - x.get(c[0]);
  const Vec3 d2 = x.get(c[3]) - x.get(c[1]);
  return 0.5 * d1.cross(d2).norm();
}

/// A triangle as a segment with its third node repeated: the same diagonal formula.
inline Real tri3_area(const Vec3Field& x, const Index* c) {
  const Vec3 d1 = x.get(c[2]) - x.get(c[0]);
  const Vec3 d2 = x.get(c[2]) - x.get(c[1]);
  return 0.5 * d1.cross(d2).norm();
}

/// (x1 - x0) . ((x2 - x0) x (x3 - x0)) / 6: positive when 0 1 2 run counter-clockwise seen from 3.
inline Real tet4_volume(const Vec3Field& x, const Index* c) {
  const Vec3 x0 = x.get(c[0]);
  return (x.get(c[1]) - x0).dot((x.get(c[2]) - x0).cross(x.get(c[3]) - x0)) / 6.0;
}

/// LS-DYNA's hexahedron node order, with (xi, eta, zeta) the natural coordinates (node 1 at
/// (-1,-1,-1), 2 at (1,-1,-1), 3 at (1,1,-1), 4 at (-1,1,-1), 5-8 the same at zeta = +1):
///   0: zeta = -1 (nodes 1 4 3 2), points along -zeta      1: zeta = +1 (5 6 7 8), +zeta
///   2: eta  = -1 (nodes 1 2 6 5), points along -eta       3: xi   = +1 (2 3 7 6), +xi
///   4: eta  = +1 (nodes 3 4 8 7), points along +eta       5: xi   = -1 (4 1 5 8), -xi
/// Face k has the nodes of hex8::detail::faces[k] (the time step's table); only face 0 runs the
/// other way there. Surfaces list faces in this order, so it must not change.
inline constexpr LocalFace hex8_faces[6] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                            {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
/// Nodes 1-3 the base, counter-clockwise seen from the apex 4: the base face runs the other way.
inline constexpr LocalFace tet4_faces[4] = {{0, 2, 1, 1}, {0, 1, 3, 3}, {1, 2, 3, 3}, {2, 0, 3, 3}};
inline constexpr LocalFace quad4_faces[1] = {{0, 1, 2, 3}};
inline constexpr LocalFace tri3_faces[1] = {{0, 1, 2, 2}};

}  // namespace topology_detail

/// The one-point hexahedron (HexBlock) and a rigid part's solids.
inline constexpr ElementTopology hex8_topology{"hex8", 3, 8, topology_detail::hex8_faces,
                                               "hexahedra", "Hexahedron", 12,
                                               &topology_detail::hex8_volume};
/// The Belytschko-Tsay shell (ShellBlock) and a rigid part's shells.
inline constexpr ElementTopology quad4_topology{"quad4", 2, 4, topology_detail::quad4_faces,
                                                "quadrilaterals", "Quadrilateral", 9,
                                                &topology_detail::quad4_area};
/// The 4-node tetrahedron (TetBlock, *SECTION_SOLID ELFORM 10).
inline constexpr ElementTopology tet4_topology{"tet4", 3, 4, topology_detail::tet4_faces,
                                               "tetrahedra", "Tetrahedron", 10,
                                               &topology_detail::tet4_volume};
/// The 3-node triangular shell: declared (face, area, output) but no element block uses it yet.
inline constexpr ElementTopology tri3_topology{"tri3", 2, 3, topology_detail::tri3_faces,
                                               "triangles", "Triangle", 5,
                                               &topology_detail::tri3_area};

/// Every topology, in the order output lists them (solids first).
inline constexpr std::array<const ElementTopology*, 4> all_topologies{
    &hex8_topology, &tet4_topology, &quad4_topology, &tri3_topology};

}  // namespace slideline
