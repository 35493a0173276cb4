// Simulation: who dictates each node's motion among the active contact interfaces (ties), redone
// when an interface is born or dies (BT, DT of its card; contact_manager.hpp).
#include <algorithm>

#include "slideline/core/error.hpp"
#include "slideline/solver/simulation.hpp"

namespace slideline {

void Simulation::classify_contact_nodes() {
  // Rigid bodies keep their nodes (kRigid, set once by initialize()); the rest is redone from the
  // interfaces that act now. Allocates only here, at t = 0 and at a birth or death.
  const Index n = static_cast<Index>(nodes.size());
  for (auto& kind : node_kind_)
    if (kind != kRigid) kind = kFree;
  dictated_nodes_.clear();
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    if (!contacts.active(k)) continue;
    const ContactAlgorithm& c = contacts[k];
    for (Index i : c.dictated_nodes()) {
      if (i < 0 || i >= n) throw InputError("contact " + c.name() + " ties a node index out of range");
      if (node_kind_[i] == kRigid)
        throw InputError("contact " + c.name() + ": tied slave node " + std::to_string(nodes.ids[i]) +
                         " belongs to a rigid part; tie the rigid part as the master instead");
      if (node_kind_[i] != kDictated) dictated_nodes_.push_back(i);
      node_kind_[i] = kDictated;
    }
  }
  for (std::size_t k = 0; k < contacts.size(); ++k)
    if (contacts.active(k))
      for (Index i : contacts[k].tie_master_nodes())
        if (i >= 0 && i < n && node_kind_[i] == kFree) node_kind_[i] = kTieMaster;
  std::sort(dictated_nodes_.begin(), dictated_nodes_.end());
  dictated_v_old_.assign(dictated_nodes_.size(), Vec3::Zero());
  dictated_w_old_.assign(dictated_nodes_.size(), Vec3::Zero());
}

}  // namespace slideline
