#pragma once
/// ContactManager: owns the contact interfaces of a simulation and runs each contact phase over
/// all of them in a fixed order (their order of addition), so that the sums into the shared force
/// buffers do not depend on anything but the deck.
#include <algorithm>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "slideline/contact/contact_algorithm.hpp"

namespace slideline {

class ContactManager {
 public:
  void add(std::unique_ptr<ContactAlgorithm> algorithm) {
    algorithms_.push_back(std::move(algorithm));
    condenses_ = condenses_ || algorithms_.back()->condenses();
  }
  std::size_t size() const { return algorithms_.size(); }
  bool empty() const { return algorithms_.empty(); }
  /// True when any interface condenses tied slaves onto their masters.
  bool condenses() const { return condenses_; }
  auto begin() { return algorithms_.begin(); }
  auto end() { return algorithms_.end(); }
  auto begin() const { return algorithms_.begin(); }
  auto end() const { return algorithms_.end(); }
  ContactAlgorithm& operator[](std::size_t k) { return *algorithms_[k]; }
  const ContactAlgorithm& operator[](std::size_t k) const { return *algorithms_[k]; }

  void initialize(const ContactContext& context) {
    condenses_ = false;
    for (auto& a : algorithms_) {
      a->initialize(context);
      condenses_ = condenses_ || a->condenses();
    }
  }

  /// Once after initialize(), before the first step, in the order of addition.
  void resolve_initial_penetrations(NodalFields& nodes) {
    for (auto& a : algorithms_) a->resolve_initial_penetrations(nodes);
  }

  /// Penalty and friction forces into `out`; returns the smallest stable step the interfaces allow.
  Real apply_forces(const NodalFields& nodes, const StepTimes& times, ContactForceView out) {
    Real dt = std::numeric_limits<Real>::max();
    for (auto& a : algorithms_) {
      a->apply_forces(nodes, times, out);
      dt = std::min(dt, a->stable_dt());
    }
    return dt;
  }
  void condense(const NodalFields& nodes, CondenseView view) {
    for (auto& a : algorithms_) a->condense(nodes, view);
  }
  void enforce(ConstraintView view, const StepTimes& times) {
    for (auto& a : algorithms_) a->enforce(view, times);
  }
  void follow_velocities(NodalFields& nodes) {
    for (auto& a : algorithms_) a->follow_velocities(nodes);
  }
  void follow_positions(NodalFields& nodes) {
    for (auto& a : algorithms_) a->follow_positions(nodes);
  }
  /// Energy dissipated by friction in all interfaces so far.
  Real friction_work() const {
    Real w = 0.0;
    for (const auto& a : algorithms_) w += a->friction_work();
    return w;
  }

 private:
  std::vector<std::unique_ptr<ContactAlgorithm>> algorithms_;
  bool condenses_ = false;
};

}  // namespace slideline
