#pragma once
/// ContactManager: owns the contact interfaces of a simulation and runs each contact phase over
/// all of them in a fixed order (their order of addition), so that the sums into the shared force
/// buffers do not depend on anything but the deck.
///
/// Birth and death (LS-DYNA BT and DT of a *CONTACT card) are honoured here, once for every
/// interface type: an interface acts in the cycles that start at birth <= t <= death. It is
/// initialised at its birth (at t = 0 for BT = 0), on the geometry of that moment, so a tied or
/// tiebreak interface ties its slaves where they are at birth; after its death no phase calls it
/// (ties release, the nodes move freely) and its forces read zero.
#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "slideline/contact/contact_algorithm.hpp"

namespace slideline {

/// When an interface acts: in the cycles that start at a time t with birth <= t <= death.
struct ContactWindow {
  /// LS-DYNA's "never dies" (DT = 0 or blank on the card).
  static constexpr Real kNever = 1e20;
  Real birth = 0.0;
  Real death = kNever;
  bool contains(Real t) const { return t >= birth && t <= death; }
  /// True when the interface does not act for the whole run.
  bool timed() const { return birth > 0.0 || death < kNever; }
};

class ContactManager {
 public:
  void add(std::unique_ptr<ContactAlgorithm> algorithm, ContactWindow window = {}) {
    phases_.push_back(algorithm->phases());
    algorithms_.push_back(std::move(algorithm));
    windows_.push_back(window);
    state_.push_back(State::waiting);
  }
  std::size_t size() const { return algorithms_.size(); }
  bool empty() const { return algorithms_.empty(); }
  /// True when any active interface condenses tied slaves onto their masters.
  bool condenses() const { return condenses_; }
  auto begin() { return algorithms_.begin(); }
  auto end() { return algorithms_.end(); }
  auto begin() const { return algorithms_.begin(); }
  auto end() const { return algorithms_.end(); }
  ContactAlgorithm& operator[](std::size_t k) { return *algorithms_[k]; }
  const ContactAlgorithm& operator[](std::size_t k) const { return *algorithms_[k]; }
  const ContactWindow& window(std::size_t k) const { return windows_[k]; }
  /// True while interface k acts (born and not dead).
  bool active(std::size_t k) const { return state_[k] == State::active; }

  /// At t = 0: initialises the interfaces born at 0; the others wait for update_activity().
  /// `context` must outlive the manager's use (the simulation's own members).
  void initialize(const ContactContext& context) {
    context_.emplace(context);
    std::fill(state_.begin(), state_.end(), State::waiting);
    update_activity(0.0);
  }

  /// At the start of the cycle from t: initialises the interfaces born by t (on the current
  /// geometry) and retires those whose death time has passed. Returns true when the set of active
  /// interfaces changed (the caller then re-reads dictated_nodes() and tie_master_nodes()).
  bool update_activity(Real t) {
    bool changed = false;
    for (std::size_t k = 0; k < algorithms_.size(); ++k) {
      if (state_[k] == State::waiting && t >= windows_[k].birth) {
        state_[k] = t <= windows_[k].death ? State::active : State::dead;
        if (state_[k] == State::active) algorithms_[k]->initialize(*context_);
        changed = true;
      } else if (state_[k] == State::active && t > windows_[k].death) {
        state_[k] = State::dead;
        changed = true;
      }
    }
    if (changed) {
      condenses_ = false;
      for (std::size_t k = 0; k < algorithms_.size(); ++k)
        condenses_ = condenses_ || (active(k) && phases_[k].tie);
    }
    return changed;
  }

  /// Once after initialize(), before the first step, in the order of addition (interfaces active
  /// at t = 0 only: a later birth takes the geometry as it finds it).
  void resolve_initial_penetrations(NodalFields& nodes) {
    for (std::size_t k = 0; k < algorithms_.size(); ++k)
      if (active(k) && phases_[k].forces) phases_[k].forces->resolve_initial_penetrations(nodes);
  }

  /// Penalty and friction forces into `out`; returns the smallest stable step the active
  /// interfaces allow.
  Real apply_forces(const NodalFields& nodes, const StepTimes& times, ContactForceView out) {
    Real dt = std::numeric_limits<Real>::max();
    for (std::size_t k = 0; k < algorithms_.size(); ++k) {
      if (!active(k)) continue;
      if (phases_[k].forces) phases_[k].forces->apply_forces(nodes, times, out);
      dt = std::min(dt, algorithms_[k]->stable_dt());
    }
    return dt;
  }
  void condense(const NodalFields& nodes, CondenseView view) {
    for (std::size_t k = 0; k < algorithms_.size(); ++k)
      if (active(k) && phases_[k].tie) phases_[k].tie->condense(nodes, view);
  }
  void enforce(ConstraintView view, const StepTimes& times) {
    for (std::size_t k = 0; k < algorithms_.size(); ++k)
      if (active(k) && phases_[k].constraint) phases_[k].constraint->enforce(view, times);
  }
  void follow_velocities(NodalFields& nodes) {
    for (std::size_t k = 0; k < algorithms_.size(); ++k)
      if (active(k) && phases_[k].tie) phases_[k].tie->follow_velocities(nodes);
  }
  void follow_positions(NodalFields& nodes) {
    for (std::size_t k = 0; k < algorithms_.size(); ++k)
      if (active(k) && phases_[k].tie) phases_[k].tie->follow_positions(nodes);
  }
  /// Energy dissipated by friction in all interfaces so far (a dead interface keeps its share).
  Real friction_work() const {
    Real w = 0.0;
    for (std::size_t k = 0; k < algorithms_.size(); ++k)
      if (state_[k] != State::waiting) w += algorithms_[k]->friction_work();
    return w;
  }

 private:
  enum class State : std::uint8_t { waiting, active, dead };
  std::vector<std::unique_ptr<ContactAlgorithm>> algorithms_;
  std::vector<ContactPhases> phases_;  ///< algorithms_[k]->phases(), read once
  std::vector<ContactWindow> windows_;
  std::vector<State> state_;
  std::optional<ContactContext> context_;
  bool condenses_ = false;
};

}  // namespace slideline
