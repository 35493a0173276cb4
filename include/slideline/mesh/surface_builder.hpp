#pragma once
/// Builds contact surfaces (mesh/surface.hpp) from the element blocks of a Simulation: from parts
/// (the exterior faces of their solids and their shells) or from a segment set (each segment
/// matched to the solid face or shell with the same nodes). Runs at initialisation; allocates.
/// Blocks are read through MeshBlock and each element through its declared topology
/// (mesh/element_topology.hpp): a solid (hex8, tet4) gives its faces, a surface element (quad4,
/// tri3: shells) gives itself.
///
/// Orientation of solid faces: each face is taken from the topology's face table, which points
/// out of an element of positive volume (LS-DYNA's node order for hex8). Whether an element is
/// positive is decided by the sign of its volume in the reference configuration (nodes.x0), not
/// by testing each face against the element centroid: the volume sign is exact for any element
/// the solver accepts, while a centroid test can fail on strongly distorted elements. A mirrored
/// element (negative volume) gets its faces reversed, so its normals still point out.
///
/// Degenerate hexahedra (wedges written with repeated nodes) are handled: a face whose nodes
/// collapse to 3 becomes a triangle (n3 == n4), one that collapses further is dropped.
#include <span>
#include <string>
#include <vector>

#include "slideline/mesh/mesh_block.hpp"
#include "slideline/mesh/mesh_sets.hpp"
#include "slideline/mesh/nodal_fields.hpp"
#include "slideline/mesh/surface.hpp"

namespace slideline {

using MeshBlocks = std::span<const MeshBlock* const>;

/// The surface of the parts `parts` (deck part ids; rigid parts included): every solid face that
/// no other solid face of these parts shares (same nodes), oriented outward, and one segment per
/// shell element with the shell's own connectivity and the thickness of its section.
/// Segments are ordered by block, element, then face (the topology's face order), so the result
/// is deterministic. Adjacency is built (build_surface_adjacency).
/// Throws InputError "<context>: ..." when a part has no elements, a solid has zero volume, or
/// the parts have no faces at all; NotImplementedError for a topology without faces.
Surface build_surface_from_parts(MeshBlocks blocks, const NodalFields& nodes,
                                 std::span<const Id> parts, const std::string& context);

/// The solid faces of the parts `parts` that build_surface_from_parts leaves out as interior
/// (another solid face of these parts has the same nodes), each once per element that owns it and
/// oriented out of that element, ordered by block, element, face; adjacency not built. Contact
/// with eroding parts (contact/search/contact_erosion.hpp) makes them surface when the element in
/// front of them is deleted.
Surface interior_faces_of_parts(MeshBlocks blocks, const NodalFields& nodes, std::span<const Id> parts,
                                const std::string& context);

/// The surface of a segment set: segments of 4 internal node indices (n3 == n4 for a triangle),
/// in any of the elements' blocks. Each segment is matched to the solid face or shell with
/// the same node set and takes its block, element, part and thickness. Orientation:
/// - solid face: the given order is kept when it points out of the element; when it points in,
///   the nodes are reversed keeping the first (n1 n4 n3 n2); when it is not a cyclic order of
///   the face at all (crossed), the element's outward order is used. A face shared by two
///   solids belongs to the one the given order points out of (so the order picks the side),
///   else to the first in block/element order.
/// - shell: the shell's own connectivity (its normal), whatever the given order; a solid face
///   with the same nodes is preferred to a shell.
/// Segments keep the set's order. Throws InputError "<context>: segment k (nodes ...) ..." for a
/// segment that matches no element (solids of zero volume, which have no outward side, and
/// topologies without faces are not candidates), repeats an earlier segment, has fewer than 3
/// distinct nodes or a node index out of range.
Surface build_surface_from_segments(MeshBlocks blocks, const NodalFields& nodes,
                                    std::span<const SegmentNodes> segments,
                                    const std::string& context);

/// The two builders for any MeshBlockRange (SimulationSetup::blocks, Simulation::blocks()).
template <MeshBlockRange R>
Surface build_surface_from_parts(const R& blocks, const NodalFields& nodes, std::span<const Id> parts,
                                 const std::string& context) {
  const std::vector<const MeshBlock*> b = mesh_blocks(blocks);
  return build_surface_from_parts(MeshBlocks(b), nodes, parts, context);
}
template <MeshBlockRange R>
Surface interior_faces_of_parts(const R& blocks, const NodalFields& nodes, std::span<const Id> parts,
                                const std::string& context) {
  const std::vector<const MeshBlock*> b = mesh_blocks(blocks);
  return interior_faces_of_parts(MeshBlocks(b), nodes, parts, context);
}
template <MeshBlockRange R>
Surface build_surface_from_segments(const R& blocks, const NodalFields& nodes,
                                    std::span<const SegmentNodes> segments, const std::string& context) {
  const std::vector<const MeshBlock*> b = mesh_blocks(blocks);
  return build_surface_from_segments(MeshBlocks(b), nodes, segments, context);
}

/// Fills surf.nodes, surf.node_segments and surf.segment_neighbors from surf.conn (the other
/// fields are not read). Two segments are neighbours when they share an edge (both end nodes);
/// a triangle's collapsed edge n3-n4 is not an edge. Rows are sorted ascending; a segment is not
/// its own neighbour. The builders above call it; call it again after editing conn.
void build_surface_adjacency(Surface& surf);

}  // namespace slideline
