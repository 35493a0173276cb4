// NodeRoles: rigid nodes once, tied nodes at t = 0 and whenever an interface is born or dies (BT,
// DT of its card; contact_manager.hpp), supported components once and at supports' birth/death.
#include "slideline/solver/node_roles.hpp"

#include <algorithm>
#include <string>

#include "slideline/core/error.hpp"

namespace slideline {

void NodeRoles::assign_rigid(Index n, const std::vector<std::unique_ptr<NodalConstraint>>& constraints) {
  kind_.assign(n, kFree);
  rigid_.assign(n, 0);
  constrained_nodes_.clear();
  for (const auto& c : constraints)
    for (Index i : c->constrained_nodes()) {
      if (i < 0 || i >= n) throw InputError("a nodal constraint refers to a node index out of range");
      if (!rigid_[i]) constrained_nodes_.push_back(i);
      rigid_[i] = 1;
      kind_[i] = kRigid;
    }
}

void NodeRoles::assign_supports(Index n, const std::vector<SupportGroup>& supports, Real t) {
  has_timed_supports_ = false;
  for (const auto& g : supports)
    for (const auto& s : g.supports) {
      has_timed_supports_ = has_timed_supports_ || s.timed();
      for (Index i : s.nodes)
        if (i < 0 || i >= n) throw InputError("support " + g.name + " refers to a missing node");
    }
  for (auto& f : fixed_) f.assign(n, 0);
  for (auto& f : fixed_rot_) f.assign(n, 0);
  refresh_supports(supports, t);
}

void NodeRoles::refresh_supports(const std::vector<SupportGroup>& supports, Real t) {
  // The components the active supports prescribe (all supports are active without BIRTH/DEATH).
  if (has_timed_supports_)
    for (const auto& g : supports)
      for (const auto& s : g.supports)
        for (Index i : s.nodes) (s.rotational ? fixed_rot_ : fixed_)[static_cast<int>(s.axis)][i] = 0;
  for (const auto& g : supports)
    for (const auto& s : g.supports)
      if (s.active(t))
        for (Index i : s.nodes) (s.rotational ? fixed_rot_ : fixed_)[static_cast<int>(s.axis)][i] = 1;
}

void NodeRoles::classify_contacts(const ContactManager& contacts, const NodalFields& nodes) {
  // Rigid bodies keep their nodes (kRigid, set once by assign_rigid()); the rest is redone from the
  // interfaces that act now.
  const Index n = static_cast<Index>(nodes.size());
  for (auto& kind : kind_)
    if (kind != kRigid) kind = kFree;
  dictated_nodes_.clear();
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    if (!contacts.active(k)) continue;
    const ContactAlgorithm& c = contacts[k];
    for (Index i : c.dictated_nodes()) {
      if (i < 0 || i >= n) throw InputError("contact " + c.name() + " ties a node index out of range");
      if (kind_[i] == kRigid)
        throw InputError("contact " + c.name() + ": tied slave node " + std::to_string(nodes.ids[i]) +
                         " belongs to a rigid part; tie the rigid part as the master instead");
      if (kind_[i] != kDictated) dictated_nodes_.push_back(i);
      kind_[i] = kDictated;
    }
  }
  for (std::size_t k = 0; k < contacts.size(); ++k)
    if (contacts.active(k))
      for (Index i : contacts[k].tie_master_nodes())
        if (i >= 0 && i < n && kind_[i] == kFree) kind_[i] = kTieMaster;
  std::sort(dictated_nodes_.begin(), dictated_nodes_.end());
}

}  // namespace slideline
