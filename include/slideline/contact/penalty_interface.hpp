#pragma once
/// PenaltyInterface<Kind, Friction>: a penalty contact interface (DYNA3D Types 3, 5, 10, 12). The
/// pass logic is PenaltyPasses (penalty_passes.hpp); the interface type is a compile-time Kind,
/// one final class per (Kind, Friction), named by an alias in the type's own header:
///  - SurfaceToSurfaceContact (Type 3, surface_to_surface_contact.hpp): two passes;
///  - OneWayContact (Type 10, one_way_contact.hpp): one pass, optionally "sliding only";
///  - NodesToSurfaceContact (Type 5, nodes_to_surface_contact.hpp): one pass of nodes with a radius;
///  - AutomaticContact (Type 12, automatic_contact.hpp): one single-surface pass, and the force
///    transmitted between parts (the Kind carries that state);
///  - AutomaticSurfaceContact (*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE, automatic_surface_contact.hpp):
///    one automatic pass over both sides, cross pairs only; the Kind gives the side forces.
/// A Kind states `pass_count` (1 or 2: the second pass is the reverse one, its forces count to
/// the other side's totals) and may carry state with the optional hooks
/// after_forces(const PenaltyPasses&), append_output_names(names), write_output_values(out),
/// slave_force() and master_force() (replacing the passes' totals).
/// Friction: Frictionless or ExponentialCoulomb. docs/contact.md, "Penalty contact".
#include <concepts>
#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "slideline/contact/contact_algorithm.hpp"
#include "slideline/contact/friction/exponential_coulomb.hpp"
#include "slideline/contact/friction/frictionless.hpp"
#include "slideline/contact/penalty_passes.hpp"

namespace slideline {

template <class Kind, class Friction>
class PenaltyInterface final : public ContactAlgorithm, public ContactForces {
 public:
  /// One pass (Types 5, 10): the card's slave nodes on its master surface.
  PenaltyInterface(std::string title, std::unique_ptr<PenaltyPass> pass, Friction friction)
    requires(Kind::pass_count == 1 && std::default_initializable<Kind>)
      : core_(std::move(title), pass_list(std::move(pass)), {false}), friction_(friction) {}

  /// One pass and the kind's own state made from `kind_arg` (Type 12: the parts whose pairwise
  /// transmitted force is reported).
  template <class KindArg>
    requires(Kind::pass_count == 1 && std::constructible_from<Kind, KindArg &&>)
  PenaltyInterface(std::string title, std::unique_ptr<PenaltyPass> pass, KindArg&& kind_arg, Friction friction)
      : core_(std::move(title), pass_list(std::move(pass)), {false}),
        friction_(friction),
        kind_(std::forward<KindArg>(kind_arg)) {}

  /// Two passes (Type 3): slave_pass, the card's slave nodes on its master surface; master_pass,
  /// the master nodes on the slave surface (its forces count to the other side's totals).
  PenaltyInterface(std::string title, std::unique_ptr<PenaltyPass> slave_pass, std::unique_ptr<PenaltyPass> master_pass,
                   Friction friction)
    requires(Kind::pass_count == 2 && std::default_initializable<Kind>)
      : core_(std::move(title), pass_list(std::move(slave_pass), std::move(master_pass)), {false, true}),
        friction_(friction) {}

  const std::string& name() const override { return core_.name(); }
  void initialize(const ContactContext& context) override { core_.initialize(context); }
  ContactPhases phases() override { return {.forces = this}; }
  void resolve_initial_penetrations(NodalFields& nodes) override { core_.resolve_initial_penetrations(nodes); }
  void apply_forces(const NodalFields& nodes, const StepTimes& times, ContactForceView out) override {
    core_.apply_forces(nodes, times, out, friction_);
    if constexpr (requires { kind_.after_forces(core_); }) kind_.after_forces(core_);
  }
  Real stable_dt() const override { return core_.stable_dt(); }
  /// The interface forces: the passes' slave and master totals, or the kind's own (a two-sided
  /// automatic pass, whose slaves and masters are both sides).
  Vec3 slave_force() const override {
    if constexpr (requires { kind_.slave_force(); }) return kind_.slave_force();
    else return core_.slave_force();
  }
  Vec3 master_force() const override {
    if constexpr (requires { kind_.master_force(); }) return kind_.master_force();
    else return core_.master_force();
  }
  Real friction_work() const override { return core_.friction_work(); }

  void append_output_names(std::vector<std::string>& names) const override {
    if constexpr (requires { kind_.append_output_names(names); }) kind_.append_output_names(names);
  }
  void write_output_values(std::span<Real> out) const override {
    if constexpr (requires { kind_.write_output_values(out); }) kind_.write_output_values(out);
  }

  /// The passes (state, records, initial penetrations), for tests and diagnostics.
  const PenaltyPasses& passes() const { return core_; }
  /// The kind's state (Type 12: the transmitted forces).
  const Kind& kind() const { return kind_; }

 private:
  template <class... P>
  static std::vector<std::unique_ptr<PenaltyPass>> pass_list(P... p) {
    std::vector<std::unique_ptr<PenaltyPass>> v;
    (v.push_back(std::move(p)), ...);
    return v;
  }

  PenaltyPasses core_;
  Friction friction_;
  [[no_unique_address]] Kind kind_{};
};

}  // namespace slideline
