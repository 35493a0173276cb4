#pragma once
/// What a penalty contact needs to know about the element behind a surface segment, to scale its
/// stiffness the way LS-DYNA does (SOFT = 0):
///   solid face  k = SLSFAC * SFM * K A^2 / V
///   shell       k = SLSFAC * SFM * K A / max(diagonal)
/// with K the bulk modulus of the element's material, A the segment area and V the element
/// volume. The formulas stay with the contact code; this query only supplies the inputs.
#include "slideline/core/types.hpp"
#include "slideline/mesh/mesh_block.hpp"
#include "slideline/mesh/nodal_fields.hpp"
#include "slideline/mesh/surface.hpp"

namespace slideline {

/// Inputs of the penalty stiffness of one segment, all at the coordinates passed to the query.
struct SegmentStiffnessData {
  Real bulk_modulus = 0.0;    ///< K of the owning element's material (force/length^2)
  Real element_volume = 0.0;  ///< solid: its volume; shell: A t (length^3)
  Real face_area = 0.0;       ///< segment area A (length^2), segment_area()
  Real thickness = 0.0;       ///< shell thickness (length), 0 for a solid face
  Real max_diagonal = 0.0;    ///< segment_max_diagonal() (length)
};

/// Volume (length^3) of element e of `block` at coordinates `x`, from its declared topology: the
/// volume of a solid (signed, positive in the node order its faces assume), area times section
/// thickness for a surface element (shell).
Real element_volume(const MeshBlock& block, Index e, const Vec3Field& x);

/// The stiffness inputs of segment s of `surf`, whose owning block (surf.block[s]) is `block`, at
/// coordinates `x`: pass nodes.x for the current configuration (what the contact code should use,
/// so that a compressed element stiffens as LS-DYNA's does), nodes.x0 for the reference one.
SegmentStiffnessData segment_stiffness_data(const Surface& surf, Index s, const MeshBlock& block,
                                            const Vec3Field& x);

/// The same, with the block looked up in the model's blocks (any MeshBlockRange, the one the
/// surface was built from).
template <MeshBlockRange R>
SegmentStiffnessData segment_stiffness_data(const Surface& surf, Index s, const R& blocks, const Vec3Field& x) {
  return segment_stiffness_data(surf, s, static_cast<const MeshBlock&>(*blocks[surf.block[s]]), x);
}

}  // namespace slideline
