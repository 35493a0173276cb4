#pragma once
/// The penalty interfaces (DYNA3D Types 3, 5, 10, 12) as one final class composed of
/// PenaltyPass objects (enforcement/penalty.hpp). The types differ only in how the factory
/// composes the passes (docs/contact.md, "Penalty contact"):
/// - Type 3 (surface to surface): two passes, slave nodes on master segments and master nodes on
///   slave segments, each pair a spring of its own (symmetric treatment).
/// - Type 10 (one way): one pass; "sliding only" keeps a touched node from separating.
/// - Type 5 (nodes to surface): one pass, a node set with the nodal radius as its offset.
/// - Type 12 (automatic single surface): one pass of every surface node against every segment,
///   without a node's own segments and faces that do not face it; reports the force transmitted
///   between parts ("transmitted_force", or "transmitted_force/<a>_<b>" for more than two parts).
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "slideline/contact/contact_algorithm.hpp"
#include "slideline/contact/enforcement/penalty.hpp"
#include "slideline/element/element_block.hpp"

namespace slideline {

class PenaltyContact final : public ContactAlgorithm {
 public:
  /// title: output name; passes: one or two PenaltyPass (slave side first: a pass whose
  /// `reversed` flag is set has the interface's master nodes as its slaves, and its forces count
  /// to the other side's totals); parts: for Type 12, the parts whose pairwise transmitted force
  /// is reported (empty: none).
  PenaltyContact(std::string title, std::vector<std::unique_ptr<PenaltyPass>> passes,
                 std::vector<bool> reversed, std::vector<Id> parts = {})
      : name_(std::move(title)), passes_(std::move(passes)), reversed_(std::move(reversed)),
        parts_(std::move(parts)) {
    for (std::size_t a = 0; a < parts_.size(); ++a)
      for (std::size_t b = a + 1; b < parts_.size(); ++b) pairs_.emplace_back(a, b);
    transmitted_.assign(pairs_.size(), Vec3::Zero());
  }

  const std::string& name() const override { return name_; }

  /// Builds the passes' stiffness and search structures (needs lumped masses) and finds the
  /// initial penetrations (initial_penetration_count()).
  void initialize(const ContactContext& context) override {
    for (auto& p : passes_) p->initialize(context.nodes, context.blocks);
  }

  /// Moves the slaves found below their master surface out to it, pass by pass (a pass after one
  /// that moved nodes re-reads its gaps first: Type 3's reverse pass sees the moved slave
  /// surface), and logs the count and the largest move to stderr with the interface title.
  void resolve_initial_penetrations(NodalFields& nodes) override {
    Index moved = 0;
    Real largest = 0.0;
    for (auto& p : passes_) {
      if (moved > 0) p->redetect_initial_penetrations(nodes);
      Real l = 0.0;
      moved += p->resolve_initial_penetrations(nodes, l);
      largest = std::max(largest, l);
    }
    moved_ = moved;
    largest_move_ = largest;
    if (initial_penetration_count() > 0) {
      std::fprintf(stderr,
                   "contact '%s': %ld initial penetration(s), largest %.6g: %ld node(s) moved out to the "
                   "surface, largest move %.6g\n",
                   name_.c_str(), static_cast<long>(initial_penetration_count()), largest_initial_penetration(),
                   static_cast<long>(moved), largest);
    }
  }

  /// Penalty and friction forces at x^n, v^{n-1/2} added into out.force (force, per node).
  void apply_forces(const NodalFields& nodes, const StepTimes& times, ContactForceView out) override {
    slave_ = master_ = Vec3::Zero();
    dt_ = std::numeric_limits<Real>::max();
    for (std::size_t k = 0; k < passes_.size(); ++k) {
      PenaltyPass& p = *passes_[k];
      p.compute(nodes, times);
      Vec3 on_slaves = Vec3::Zero(), on_masters = Vec3::Zero();
      p.scatter(out, on_slaves, on_masters, friction_work_);
      if (reversed_[k]) std::swap(on_slaves, on_masters);
      slave_ += on_slaves;
      master_ += on_masters;
      dt_ = std::min(dt_, p.stable_dt());
    }
    if (!pairs_.empty()) update_transmitted();
  }

  /// Largest step the penalty springs allow (time), before the global scale factor.
  Real stable_dt() const override { return dt_; }
  Vec3 slave_force() const override { return slave_; }
  Vec3 master_force() const override { return master_; }
  /// Energy dissipated by friction so far (energy, >= 0).
  Real friction_work() const override { return friction_work_; }

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

  /// Initial penetrations over all passes: count and largest depth (length).
  Index initial_penetration_count() const {
    Index n = 0;
    for (const auto& p : passes_) n += p->initial_penetration_count();
    return n;
  }
  Real largest_initial_penetration() const {
    Real m = 0.0;
    for (const auto& p : passes_) m = std::max(m, p->largest_initial_penetration());
    return m;
  }
  /// Nodes moved out by resolve_initial_penetrations() and the largest move (length).
  Index moved_node_count() const { return moved_; }
  Real largest_move() const { return largest_move_; }
  /// Force that parts_[b] exerts on parts_[a] for the k-th pair (a < b) at the last cycle.
  const std::vector<Vec3>& transmitted_forces() const { return transmitted_; }
  const PenaltyPass& pass(std::size_t k) const { return *passes_[k]; }
  std::size_t pass_count() const { return passes_.size(); }

 private:
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
    for (const auto& p : passes_) {
      const auto records = p->records();
      const Surface& m = p->master();
      for (std::size_t i = 0; i < records.size(); ++i) {
        const PenaltyRecord& r = records[i];
        if (r.segment < 0) continue;
        const Id node_part = p->slave_part()[i];
        const Id seg_part = m.part[static_cast<std::size_t>(r.segment)];
        bool flip = false;
        const std::size_t k = pair_index(node_part, seg_part, flip);
        if (k == pairs_.size()) continue;
        // r.force acts on the node's part; -r.force on the segment's part.
        transmitted_[k] += flip ? Vec3(-r.force) : r.force;
      }
    }
  }

  std::string name_;
  std::vector<std::unique_ptr<PenaltyPass>> passes_;
  std::vector<bool> reversed_;
  std::vector<Id> parts_;
  std::vector<std::pair<std::size_t, std::size_t>> pairs_;
  std::vector<Vec3> transmitted_;
  Vec3 slave_ = Vec3::Zero(), master_ = Vec3::Zero();
  Real friction_work_ = 0.0;
  Real dt_ = std::numeric_limits<Real>::max();
  Index moved_ = 0;
  Real largest_move_ = 0.0;
};

}  // namespace slideline
