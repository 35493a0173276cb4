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

/// *CONTROL_CONTACT THKCHG = 1 on the automatic cards (docs/contact.md, "Shell thickness change"):
/// offsets that follow the shells' current thickness (ElementBlock::current_thickness, under
/// *CONTROL_SHELL ISTUPD). Per target (a slave node or a master segment): a floor that does not
/// follow (a nodal radius, a thickness the card gives: SST, MST) and terms half x scale x t of the
/// shell elements whose thickness sets it; its offset is the largest of them, the rule of
/// node_offset and segment_offset re-read at the current thickness.
struct ThicknessTerm {
  Index block = 0, element = 0;  ///< the shell element (block index, element index in it)
  Real half_scale = 0.5;         ///< 0.5 x SFST or SFMT
  Real section = 0.0;            ///< its section thickness (length): the thickness of a block that keeps it
};
struct FollowedOffsets {
  std::vector<Real> floor;           ///< per target (length)
  std::vector<Index> begin{0};       ///< per target + 1: its terms are [begin[i], begin[i + 1])
  std::vector<ThicknessTerm> terms;

  Index size() const { return static_cast<Index>(floor.size()); }
  /// Adds the terms of segment s of `surface` under `rule` to the target being built.
  void add_segment(const Surface& surface, Index s, const ShellOffsetRule& rule, Real& target_floor) {
    const auto k = static_cast<std::size_t>(s);
    if (!rule.on || surface.kind[k] != SegmentKind::shell) return;
    if (rule.thickness > 0.0) {
      target_floor = std::max(target_floor, segment_offset(surface, s, rule));
      return;
    }
    terms.push_back({surface.block[k], surface.element[k], 0.5 * rule.scale, surface.thickness[k]});
  }
  /// Adds the terms of every segment of node row `row` of `surface` (node_offset's segments).
  void add_node(const Surface& surface, Index row, const ShellOffsetRule& rule, Real& target_floor) {
    for (Index j = surface.node_segments.begin(row); j < surface.node_segments.end(row); ++j)
      add_segment(surface, surface.node_segments.value[static_cast<std::size_t>(j)], rule, target_floor);
  }
  /// Adds the terms of `node` (an internal index) on `own` under `rule`, if it is on `own`.
  void add_node_of(const Surface& own, Index node, const ShellOffsetRule& rule, Real& target_floor) {
    const auto it = std::lower_bound(own.nodes.begin(), own.nodes.end(), node);
    if (it != own.nodes.end() && *it == node)
      add_node(own, static_cast<Index>(it - own.nodes.begin()), rule, target_floor);
  }
  /// Closes the target being built with its floor.
  void close(Real target_floor) {
    floor.push_back(target_floor);
    begin.push_back(static_cast<Index>(terms.size()));
  }
  /// The offset of target i at the thicknesses `thickness` (per block; empty: the section's).
  Real value(Index i, std::span<const std::span<const Real>> thickness) const {
    Real v = floor[static_cast<std::size_t>(i)];
    for (Index k = begin[static_cast<std::size_t>(i)]; k < begin[static_cast<std::size_t>(i) + 1]; ++k) {
      const ThicknessTerm& t = terms[static_cast<std::size_t>(k)];
      const std::span<const Real> b = thickness[static_cast<std::size_t>(t.block)];
      v = std::max(v, t.half_scale * (b.empty() ? t.section : b[static_cast<std::size_t>(t.element)]));
    }
    return v;
  }
};

/// The followed offsets of `nodes` on `own` under `rule`, at least `radius` (node_offsets' rule).
inline FollowedOffsets followed_node_offsets(std::span<const Index> nodes, const Surface& own,
                                             const ShellOffsetRule& rule, Real radius) {
  FollowedOffsets f;
  for (const Index n : nodes) {
    Real floor = radius;
    f.add_node_of(own, n, rule, floor);
    f.close(floor);
  }
  return f;
}

}  // namespace slideline
