#pragma once
/// DYNA3D Type 12 (*CONTACT_AUTOMATIC_SINGLE_SURFACE), penalty enforcement: one pass of every
/// surface node of the parts against every segment, without a node's own segments and faces that
/// do not face it (the pass's `automatic` option). DYNA3D's interface force is meaningless here
/// (every node is a slave, spec section 4.3); this class reports the force transmitted between
/// parts instead: "transmitted_force" (the second part on the first), or
/// "transmitted_force/<a>_<b>" per pair for more than two parts. docs/contact.md, "Penalty contact".
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "slideline/contact/contact_algorithm.hpp"
#include "slideline/contact/friction/exponential_coulomb.hpp"
#include "slideline/contact/friction/frictionless.hpp"
#include "slideline/contact/penalty_passes.hpp"

namespace slideline {

/// Friction: Frictionless or ExponentialCoulomb (compile-time policy).
template <class Friction>
class AutomaticContact final : public ContactAlgorithm {
 public:
  /// pass: all surface nodes against all segments (slave_part() set per node); parts: the parts
  /// whose pairwise transmitted force is reported.
  AutomaticContact(std::string title, std::unique_ptr<PenaltyPass> pass, std::vector<Id> parts, Friction friction)
      : core_(std::move(title), one(std::move(pass)), {false}), friction_(friction), parts_(std::move(parts)) {
    for (std::size_t a = 0; a < parts_.size(); ++a)
      for (std::size_t b = a + 1; b < parts_.size(); ++b) pairs_.emplace_back(a, b);
    transmitted_.assign(pairs_.size(), Vec3::Zero());
  }

  const std::string& name() const override { return core_.name(); }
  void initialize(const ContactContext& context) override { core_.initialize(context); }
  void resolve_initial_penetrations(NodalFields& nodes) override { core_.resolve_initial_penetrations(nodes); }
  void apply_forces(const NodalFields& nodes, const StepTimes& times, ContactForceView out) override {
    core_.apply_forces(nodes, times, out, friction_);
    if (!pairs_.empty()) update_transmitted();
  }
  Real stable_dt() const override { return core_.stable_dt(); }
  Vec3 slave_force() const override { return core_.slave_force(); }
  Vec3 master_force() const override { return core_.master_force(); }
  Real friction_work() const override { return core_.friction_work(); }

  void append_output_names(std::vector<std::string>& names) const override {
    if (pairs_.size() == 1) {
      names.emplace_back("transmitted_force");
      return;
    }
    for (auto [a, b] : pairs_)
      names.push_back("transmitted_force/" + std::to_string(parts_[a]) + "_" + std::to_string(parts_[b]));
  }
  /// Per part pair (a, b): the force part b exerts on part a (force), 3 values each.
  void write_output_values(std::span<Real> out) const override {
    for (std::size_t k = 0; k < transmitted_.size(); ++k)
      for (int c = 0; c < 3; ++c) out[3 * k + static_cast<std::size_t>(c)] = transmitted_[k][c];
  }

  /// The passes (state, records, initial penetrations), for tests and diagnostics.
  const PenaltyPasses& passes() const { return core_; }
  /// Force that parts_[b] exerts on parts_[a] for the k-th pair (a < b) at the last cycle.
  const std::vector<Vec3>& transmitted_forces() const { return transmitted_; }

 private:
  static std::vector<std::unique_ptr<PenaltyPass>> one(std::unique_ptr<PenaltyPass> a) {
    std::vector<std::unique_ptr<PenaltyPass>> v;
    v.push_back(std::move(a));
    return v;
  }

  std::size_t pair_index(Id pa, Id pb, bool& flip) const {
    for (std::size_t k = 0; k < pairs_.size(); ++k) {
      const Id a = parts_[pairs_[k].first], b = parts_[pairs_[k].second];
      if (a == pa && b == pb) { flip = false; return k; }
      if (a == pb && b == pa) { flip = true; return k; }
    }
    return pairs_.size();
  }

  void update_transmitted() {
    for (Vec3& t : transmitted_) t.setZero();
    const PenaltyPass& p = core_.pass(0);
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

  PenaltyPasses core_;
  Friction friction_;
  std::vector<Id> parts_;
  std::vector<std::pair<std::size_t, std::size_t>> pairs_;
  std::vector<Vec3> transmitted_;
};

}  // namespace slideline
