#pragma once
/// Who dictates each node's motion, and which of its components the supports prescribe.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "slideline/contact/contact_manager.hpp"
#include "slideline/core/types.hpp"
#include "slideline/mesh/nodal_fields.hpp"
#include "slideline/solver/boundary.hpp"
#include "slideline/solver/nodal_constraint.hpp"

namespace slideline {

/// Per node: who dictates its motion. kFree: the velocity update; kRigid: a NodalConstraint (work
/// booked to `constraint`); kDictated: a contact tie sets its velocity (a tied slave);
/// kTieMaster: the velocity update moves it with tied slave mass condensed onto it (the tie
/// forces' work is booked to `contact`).
enum NodeKind : std::uint8_t { kFree = 0, kRigid = 1, kDictated = 2, kTieMaster = 3 };

class NodeRoles {
 public:
  /// Once: every node free, then the rigid bodies' nodes kRigid (their lists are known before they
  /// initialise). Throws InputError for a node index out of range.
  void assign_rigid(Index n, const std::vector<std::unique_ptr<NodalConstraint>>& constraints);
  /// Once: checks the supports' nodes and sets the flags of the supports active at `t`.
  void assign_supports(Index n, const std::vector<SupportGroup>& supports, Real t);
  /// kDictated and kTieMaster from the interfaces that act now (t = 0 and at each birth or death;
  /// allocates only then). Rigid nodes keep their kind; a tied slave on a rigid part is refused.
  void classify_contacts(const ContactManager& contacts, const NodalFields& nodes);
  /// The flags of the supports active at `t` (only supports with BIRTH/DEATH change them).
  void refresh_supports(const std::vector<SupportGroup>& supports, Real t);

  std::span<const std::uint8_t> kinds() const { return kind_; }
  /// 1 where kRigid (a view for contact).
  std::span<const std::uint8_t> rigid() const { return rigid_; }
  /// kRigid nodes, in order of first mention.
  std::span<const Index> constrained_nodes() const { return constrained_nodes_; }
  /// kDictated nodes, ascending.
  std::span<const Index> dictated_nodes() const { return dictated_nodes_; }
  /// Per axis: 1 where a support prescribes this component (fixed) or this rotation (fixed_rot).
  std::span<const std::uint8_t> fixed(int c) const { return fixed_[c]; }
  std::span<const std::uint8_t> fixed_rot(int c) const { return fixed_rot_[c]; }
  /// A support has BIRTH/DEATH: the flags are refreshed each cycle.
  bool has_timed_supports() const { return has_timed_supports_; }

 private:
  std::vector<std::uint8_t> kind_;
  std::vector<std::uint8_t> rigid_;
  std::vector<Index> constrained_nodes_;
  std::vector<Index> dictated_nodes_;
  std::vector<std::uint8_t> fixed_[3];
  std::vector<std::uint8_t> fixed_rot_[3];
  bool has_timed_supports_ = false;
};

}  // namespace slideline
