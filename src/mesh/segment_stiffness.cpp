#include "slideline/mesh/segment_stiffness.hpp"

#include "slideline/mesh/segment_geometry.hpp"

namespace slideline {

Real element_volume(const MeshBlock& block, Index e, const Vec3Field& x) {
  const BlockTopology::Element el = block.topology().element(e);
  const Real measure = el.topology().measure(x, block.connectivity().data() + el.node_offset);
  return el.topology().is_solid() ? measure : measure * el.run.thickness;
}

SegmentStiffnessData segment_stiffness_data(const Surface& surf, Index s, const MeshBlock& block,
                                            const Vec3Field& x) {
  SegmentStiffnessData d;
  d.bulk_modulus = block.bulk_modulus();
  d.element_volume = element_volume(block, surf.element[s], x);
  d.face_area = segment_area(surf, s, x);
  d.thickness = surf.thickness[s];
  d.max_diagonal = segment_max_diagonal(surf, s, x);
  return d;
}

}  // namespace slideline
