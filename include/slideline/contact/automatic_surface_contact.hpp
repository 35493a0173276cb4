#pragma once
/// *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE, penalty enforcement: the automatic (Type 12) pass over
/// the nodes and segments of both sides, restricted to the cross pairs (a slave-side node on a
/// master-side segment, a master-side node on a slave-side segment; ContactPairs::set_sides).
/// Orientation-free like Type 12: a shell has two sides, found from the geometry, offset by half
/// its thickness (SST/SFST on the slave side, MST/SFMT on the master side); a solid face meets
/// only what it faces. One pass, so a node pair is never pushed twice. Its interface forces are
/// the force on each side: exact equal and opposite totals. The one-way automatic cards
/// (*CONTACT_AUTOMATIC_NODES_TO_SURFACE, *CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE) are the same
/// class over the slave side's nodes and the master side's segments. docs/contact.md, "Automatic
/// cards".
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "slideline/contact/penalty_interface.hpp"

namespace slideline {

/// Kind of PenaltyInterface for the two-sided automatic card: one pass over the union of the
/// sides, and the force on each side from the pass's records.
class AutomaticSurfaceKind {
 public:
  static constexpr std::size_t pass_count = 1;

  /// segment_sides: per segment of the pass's surface, bit 1 the card's slave side, bit 2 its
  /// master side (ContactPairs::set_sides).
  explicit AutomaticSurfaceKind(std::vector<std::uint8_t> segment_sides) : segment_side_(std::move(segment_sides)) {}

  /// After each force evaluation: the force on the slave side. A pair's force f acts on its node
  /// and -f on its segment; only cross pairs exist, so when the segment is on the slave side only
  /// the slave side gets -f, and otherwise the node is on the slave side and gets f.
  void after_forces(const PenaltyPasses& core) {
    slave_.setZero();
    const PenaltyPass& p = core.pass(0);
    const auto records = p.records();
    for (std::size_t i = 0; i < records.size(); ++i) {
      const PenaltyRecord& r = records[i];
      if (r.segment < 0) continue;
      if (segment_side_[static_cast<std::size_t>(r.segment)] == 1)
        slave_ -= r.force;
      else
        slave_ += r.force;
    }
  }

  /// Force on the card's slave side, and on its master side (its opposite), at the last cycle.
  Vec3 slave_force() const { return slave_; }
  Vec3 master_force() const { return -slave_; }

 private:
  std::vector<std::uint8_t> segment_side_;
  Vec3 slave_ = Vec3::Zero();
};

/// Friction: Frictionless or ExponentialCoulomb (compile-time policy).
template <class Friction>
using AutomaticSurfaceContact = PenaltyInterface<AutomaticSurfaceKind, Friction>;

}  // namespace slideline
