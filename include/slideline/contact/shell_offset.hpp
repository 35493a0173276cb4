#pragma once
/// The one shell offset rule of every contact family: a shell segment's contact surface lies half
/// its thickness off its mid-surface (LS-DYNA's SHLTHK; always for Type 12), the thickness taken
/// from the card (SST for the slave side, MST for the master side) when positive, else from the
/// element, and scaled by SFST / SFMT. A solid face has no offset. Penalty (enforcement/penalty.hpp),
/// Lagrange (lagrange_contact.hpp) and the interface specification (interface_spec.hpp) call these
/// functions; nothing else computes an offset from a thickness.
#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

#include "slideline/core/types.hpp"
#include "slideline/mesh/surface.hpp"

namespace slideline {

/// How one side of an interface offsets its shell segments.
struct ShellOffsetRule {
  bool on = false;        ///< offset shell segments at all (SHLTHK > 0, or Type 12)
  Real thickness = 0.0;   ///< > 0: replaces the shells' thickness (SST or MST, length)
  Real scale = 1.0;       ///< SFST or SFMT (dimensionless)
};

/// Offset of segment `s` of `surface` (length): 0.5 t scale on a shell when the rule is on, else 0.
inline Real segment_offset(const Surface& surface, Index s, const ShellOffsetRule& rule) {
  const auto k = static_cast<std::size_t>(s);
  if (!rule.on || surface.kind[k] != SegmentKind::shell) return 0.0;
  const Real t = rule.thickness > 0.0 ? rule.thickness : surface.thickness[k];
  return 0.5 * t * rule.scale;
}

/// Offset of the node in row `row` of `surface` (length): the largest offset among its segments
/// (0 for a node on solid faces only). Rounding is monotone, so this equals 0.5 x (largest
/// thickness) x scale to the bit.
inline Real node_offset(const Surface& surface, Index row, const ShellOffsetRule& rule) {
  Real off = 0.0;
  for (Index j = surface.node_segments.begin(row); j < surface.node_segments.end(row); ++j)
    off = std::max(off, segment_offset(surface, surface.node_segments.value[static_cast<std::size_t>(j)], rule));
  return off;
}

/// Offset of each of `nodes` (internal indices, length): the largest offset of its segments on
/// `own` under `rule` (node_offset; a node not on `own`, e.g. of a node set, has none), at least
/// `radius` (a nodal radius). Allocates the result.
inline std::vector<Real> node_offsets(std::span<const Index> nodes, const Surface& own, const ShellOffsetRule& rule,
                                      Real radius) {
  std::vector<Real> out(nodes.size(), radius);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const auto it = std::lower_bound(own.nodes.begin(), own.nodes.end(), nodes[i]);  // own.nodes is sorted
    if (it == own.nodes.end() || *it != nodes[i]) continue;
    out[i] = std::max(out[i], node_offset(own, static_cast<Index>(it - own.nodes.begin()), rule));
  }
  return out;
}

}  // namespace slideline
