#pragma once
/// The pass logic every penalty interface class shares (not a base class: each interface type is a
/// final ContactAlgorithm holding one PenaltyPasses). One or two PenaltyPass objects
/// (enforcement/penalty.hpp) run in a fixed order; a `reversed` pass has the interface's master
/// nodes as its slaves and its forces count to the other side's totals. See docs/contact.md,
/// "Penalty contact".
#include <algorithm>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "slideline/contact/contact_algorithm.hpp"
#include "slideline/contact/enforcement/penalty.hpp"
#include "slideline/element/element_block.hpp"

namespace slideline {

class PenaltyPasses {
 public:
  PenaltyPasses(std::string title, std::vector<std::unique_ptr<PenaltyPass>> passes, std::vector<bool> reversed)
      : name_(std::move(title)), passes_(std::move(passes)), reversed_(std::move(reversed)) {}

  const std::string& name() const { return name_; }

  /// Stiffness and search structures of every pass (needs lumped masses); finds the initial
  /// penetrations.
  void initialize(const ContactContext& context) {
    for (auto& p : passes_) p->initialize(context.nodes, context.blocks);
    diagnostics_ = context.diagnostics;
  }

  /// Moves the slaves found below their master surface out to it, pass by pass (a pass after one
  /// that moved nodes re-reads its gaps first: Type 3's reverse pass sees the moved slave
  /// surface), and warns (ContactContext::diagnostics) with the count, the largest move and the
  /// interface title.
  void resolve_initial_penetrations(NodalFields& nodes) {
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
    if (initial_penetration_count() > 0 && passes_.front()->keeps_initial_penetrations()) {
      warn(diagnostics_,
           "contact '%s': %ld initial penetration(s), largest %.6g: kept as the springs' zero (IGNORE)",
           name_.c_str(), static_cast<long>(initial_penetration_count()), largest_initial_penetration());
    } else if (initial_penetration_count() > 0) {
      warn(diagnostics_,
                   "contact '%s': %ld initial penetration(s), largest %.6g: %ld node(s) moved out to the "
                   "surface, largest move %.6g",
                   name_.c_str(), static_cast<long>(initial_penetration_count()), largest_initial_penetration(),
                   static_cast<long>(moved), largest);
    }
  }

  /// Penalty and friction forces at x^n, v^{n-1/2} added into out.force, pass by pass.
  template <class Friction>
  void apply_forces(const NodalFields& nodes, const StepTimes& times, ContactForceView out, const Friction& friction) {
    slave_ = master_ = Vec3::Zero();
    dt_ = std::numeric_limits<Real>::max();
    for (std::size_t k = 0; k < passes_.size(); ++k) {
      PenaltyPass& p = *passes_[k];
      p.compute(nodes, times, friction);
      Vec3 on_slaves = Vec3::Zero(), on_masters = Vec3::Zero();
      p.scatter(out, on_slaves, on_masters, friction_work_);
      if (reversed_[k]) std::swap(on_slaves, on_masters);
      slave_ += on_slaves;
      master_ += on_masters;
      dt_ = std::min(dt_, p.stable_dt());
    }
  }

  /// Largest step the penalty springs allow (time), before the global scale factor.
  Real stable_dt() const { return dt_; }
  Vec3 slave_force() const { return slave_; }
  Vec3 master_force() const { return master_; }
  /// Energy dissipated by friction so far (energy, >= 0).
  Real friction_work() const { return friction_work_; }

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
  const PenaltyPass& pass(std::size_t k) const { return *passes_[k]; }
  std::size_t pass_count() const { return passes_.size(); }

 private:
  std::string name_;
  std::vector<std::unique_ptr<PenaltyPass>> passes_;
  std::vector<bool> reversed_;
  Vec3 slave_ = Vec3::Zero(), master_ = Vec3::Zero();
  Real friction_work_ = 0.0;
  Real dt_ = std::numeric_limits<Real>::max();
  Index moved_ = 0;
  Real largest_move_ = 0.0;
  DiagnosticSink* diagnostics_ = nullptr;
};

}  // namespace slideline
