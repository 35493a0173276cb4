#pragma once
/// DYNA3D Type 12 (*CONTACT_AUTOMATIC_SINGLE_SURFACE), penalty enforcement: one pass of every
/// surface node of the parts against every segment, without a node's own segments and faces that
/// do not face it (the pass's `automatic` option). DYNA3D's interface force is meaningless here
/// (every node is a slave, spec section 4.3); this interface reports the force transmitted between
/// parts instead: "transmitted_force" (the second part on the first), or
/// "transmitted_force/<a>_<b>" per pair for more than two parts. docs/contact.md, "Penalty contact".
#include <cstddef>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "slideline/contact/penalty_interface.hpp"

namespace slideline {

/// Kind of PenaltyInterface for Type 12: one pass of all surface nodes against all segments
/// (the pass's slave_part() set per node), and the pairwise transmitted force between `parts`.
class AutomaticKind {
 public:
  static constexpr std::size_t pass_count = 1;

  explicit AutomaticKind(std::vector<Id> parts) : parts_(std::move(parts)) {
    for (std::size_t a = 0; a < parts_.size(); ++a)
      for (std::size_t b = a + 1; b < parts_.size(); ++b) pairs_.emplace_back(a, b);
    transmitted_.assign(pairs_.size(), Vec3::Zero());
  }

  /// After each force evaluation: the transmitted forces from the pass's records.
  void after_forces(const PenaltyPasses& core) {
    if (!pairs_.empty()) update_transmitted(core.pass(0));
  }

  void append_output_names(std::vector<std::string>& names) const {
    if (pairs_.size() == 1) {
      names.emplace_back("transmitted_force");
      return;
    }
    for (auto [a, b] : pairs_)
      names.push_back("transmitted_force/" + std::to_string(parts_[a]) + "_" + std::to_string(parts_[b]));
  }
  /// Per part pair (a, b): the force part b exerts on part a (force), 3 values each.
  void write_output_values(std::span<Real> out) const {
    for (std::size_t k = 0; k < transmitted_.size(); ++k)
      for (int c = 0; c < 3; ++c) out[3 * k + static_cast<std::size_t>(c)] = transmitted_[k][c];
  }

  /// Force that parts_[b] exerts on parts_[a] for the k-th pair (a < b) at the last cycle.
  const std::vector<Vec3>& transmitted_forces() const { return transmitted_; }

 private:
  std::size_t pair_index(Id pa, Id pb, bool& flip) const {
    for (std::size_t k = 0; k < pairs_.size(); ++k) {
      const Id a = parts_[pairs_[k].first], b = parts_[pairs_[k].second];
      if (a == pa && b == pb) { flip = false; return k; }
      if (a == pb && b == pa) { flip = true; return k; }
    }
    return pairs_.size();
  }

  void update_transmitted(const PenaltyPass& p) {
    for (Vec3& t : transmitted_) t.setZero();
    const auto records = p.records();
    const Surface& m = p.master();
    for (std::size_t i = 0; i < records.size(); ++i) {
      const PenaltyRecord& r = records[i];
      if (r.segment < 0) continue;
      const Id node_part = p.slave_part()[i];
      const Id seg_part = m.part[static_cast<std::size_t>(r.segment)];
      bool flip = false;
      const std::size_t k = pair_index(node_part, seg_part, flip);
      if (k == pairs_.size()) continue;
      // r.force acts on the node's part; -r.force on the segment's part.
      transmitted_[k] += flip ? Vec3(-r.force) : r.force;
    }
  }

  std::vector<Id> parts_;
  std::vector<std::pair<std::size_t, std::size_t>> pairs_;
  std::vector<Vec3> transmitted_;
};

/// Friction: Frictionless or ExponentialCoulomb (compile-time policy).
template <class Friction>
using AutomaticContact = PenaltyInterface<AutomaticKind, Friction>;

}  // namespace slideline
