#pragma once
/// A contact surface: segments (faces of hexahedra, or shell elements) as structure-of-arrays,
/// with node -> segment and segment -> neighbour adjacency in CSR form.
///
/// Conventions (every builder and every contact algorithm relies on them):
/// - A segment has 4 internal node indices in `conn[4 s .. 4 s + 3]`; a triangle repeats its
///   third node as the fourth (conn[4s+2] == conn[4s+3]).
/// - Node order is counter-clockwise seen from the side the normal points to, so that
///   n = (x2 - x0) x (x3 - x1) / |...| is the segment's normal. For a hexahedron face that normal
///   points OUT of the element. For a shell it is the shell's own normal (right-hand rule on its
///   connectivity); both sides of a shell are usable, and `thickness[s]` > 0 tells a contact
///   algorithm to offset the surface by half the thickness on the side it is approached from.
/// - `thickness[s]` is 0 for a hexahedron face.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "slideline/core/types.hpp"

namespace slideline {

/// Compressed row storage: the entries of row r are value[offset[r] .. offset[r + 1]).
struct Csr {
  std::vector<Index> offset;  ///< rows + 1 entries, offset[0] = 0
  std::vector<Index> value;

  Index rows() const { return offset.empty() ? 0 : static_cast<Index>(offset.size()) - 1; }
  Index begin(Index r) const { return offset[r]; }
  Index end(Index r) const { return offset[r + 1]; }
};

enum class SegmentKind : std::uint8_t { solid_face = 0, shell = 1 };

struct Surface {
  // Per segment (size = segment_count(), conn is 4x that).
  std::vector<Index> conn;          ///< 4 internal node indices per segment
  std::vector<Index> block;         ///< index of the owning element block in Simulation::blocks
  std::vector<Index> element;       ///< index of the owning element within that block
  std::vector<Id> part;             ///< deck part id of the owning element
  std::vector<SegmentKind> kind;
  std::vector<Real> thickness;      ///< shell thickness (0 for a hexahedron face)

  /// The distinct nodes of the surface, ascending internal indices.
  std::vector<Index> nodes;
  /// Row i (i indexes `nodes`): the segments that contain nodes[i], ascending.
  Csr node_segments;
  /// Row s: the segments that share an edge with segment s, ascending.
  Csr segment_neighbors;

  Index segment_count() const { return static_cast<Index>(block.size()); }
  Index node_count() const { return static_cast<Index>(nodes.size()); }
  bool is_triangle(Index s) const { return conn[4 * s + 2] == conn[4 * s + 3]; }

  /// Appends segment s of `from` (its nodes and owner); the adjacency is the caller's to rebuild
  /// (build_surface_adjacency) once every segment is in.
  void append_segment(const Surface& from, Index s) {
    const auto u = static_cast<std::size_t>(s);
    conn.insert(conn.end(), from.conn.begin() + 4 * static_cast<std::ptrdiff_t>(s),
                from.conn.begin() + 4 * static_cast<std::ptrdiff_t>(s) + 4);
    block.push_back(from.block[u]);
    element.push_back(from.element[u]);
    part.push_back(from.part[u]);
    kind.push_back(from.kind[u]);
    thickness.push_back(from.thickness[u]);
  }
};

}  // namespace slideline
