#pragma once
// Evaluates one element block's nodal forces outside a Simulation.
#include <utility>
#include <vector>

#include "slideline/element/element_block.hpp"

namespace test_support {

/// Initializes `block` on `nodes` (masses) and returns nothing; call once.
inline void prepare(slideline::ElementBlock& block, slideline::NodalFields& nodes,
                    slideline::CornerBuffer& corners) {
  using slideline::Index;
  block.set_slot_base(0, 0);
  block.initialize(nodes);
  const auto conn = block.connectivity();
  std::vector<std::pair<Index, Index>> pairs;
  for (std::size_t k = 0; k < conn.size(); ++k) pairs.emplace_back(conn[k], static_cast<Index>(k));
  corners.force.resize(conn.size());
  corners.moment.resize(block.has_moments() ? conn.size() : 0);
  corners.force_slots.build(static_cast<Index>(nodes.size()), pairs);
  if (block.has_moments()) corners.moment_slots.build(static_cast<Index>(nodes.size()), pairs);
}

/// Computes the block's forces into nodes.f_int (and m_int); returns the stable step.
inline slideline::Real evaluate(slideline::ElementBlock& block, slideline::NodalFields& nodes,
                                slideline::CornerBuffer& corners) {
  slideline::BlockEnergy e;
  const slideline::Real dt = block.compute_forces(nodes, 0.0, corners, e);
  corners.gather(nodes.f_int, nodes.m_int);
  return dt;
}

}  // namespace test_support
