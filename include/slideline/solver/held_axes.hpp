#pragma once
/// Which translational axes the supports hold at each node for the whole run: what the contact
/// builder needs to tell a symmetry plane (ISYM = 1 of the *CONTACT_ERODING_... cards;
/// ContactBuildContext::held_axes, docs/contact_erosion.md).
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "slideline/solver/boundary.hpp"

namespace slideline {

/// Per node (of `node_count`): bit a set when a support without a curve (an SPC or *NODE TC code,
/// not a prescribed motion) holds translational axis a from the start to the end of the run.
inline std::vector<std::uint8_t> held_axes(std::span<const SupportGroup> supports, std::size_t node_count) {
  std::vector<std::uint8_t> held(node_count, 0);
  for (const SupportGroup& g : supports)
    for (const Support& s : g.supports)
      if (!s.rotational && !s.has_curve && s.birth <= 0.0 && s.death == std::numeric_limits<Real>::infinity())
        for (Index n : s.nodes) held[static_cast<std::size_t>(n)] |= std::uint8_t(1u << static_cast<int>(s.axis));
  return held;
}

}  // namespace slideline
