#include "slideline/mesh/segment_stiffness.hpp"

#include "slideline/element/hex8.hpp"
#include "slideline/mesh/block_topology.hpp"
#include "slideline/mesh/segment_geometry.hpp"

namespace slideline {

Real element_volume(const ElementBlock& block, Index e, const Vec3Field& x) {
  const BlockTopology topo = block_topology(block);
  const Index* c = block.connectivity().data() + topo.node_offset(e);
  if (topo.is_hex(e)) {
    const hex8::NodeMat X = gather_rows<8>(x, c);
    return hex8::volume(X, hex8::volume_gradient(X));
  }
  // Same area formula as segment_area, so a shell's V / A is exactly its thickness.
  const Vec3 d1 = x.get(c[2]) - x.get(c[0]);
  const Vec3 d2 = x.get(c[3]) - x.get(c[1]);
  return 0.5 * d1.cross(d2).norm() * topo.shell_thickness;
}

SegmentStiffnessData segment_stiffness_data(const Surface& surf, Index s, const ElementBlocks& blocks,
                                            const Vec3Field& x) {
  const ElementBlock& block = *blocks[surf.block[s]];
  SegmentStiffnessData d;
  d.bulk_modulus = block.bulk_modulus();
  d.element_volume = element_volume(block, surf.element[s], x);
  d.face_area = segment_area(surf, s, x);
  d.thickness = surf.thickness[s];
  d.max_diagonal = segment_max_diagonal(surf, s, x);
  return d;
}

}  // namespace slideline
