#pragma once
/// DYNA3D Type 5 (*CONTACT_NODES_TO_SURFACE), nodes impacting a surface, penalty enforcement:
/// one pass of a node set (or a surface's nodes) on the master segments, each node offset by the
/// nodal radius. docs/contact.md, "Penalty contact".
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
class NodesToSurfaceContact final : public ContactAlgorithm {
 public:
  /// pass: the slave nodes (offsets = nodal radius) on the master surface.
  NodesToSurfaceContact(std::string title, std::unique_ptr<PenaltyPass> pass, Friction friction)
      : core_(std::move(title), one(std::move(pass)), {false}), friction_(friction) {}

  const std::string& name() const override { return core_.name(); }
  void initialize(const ContactContext& context) override { core_.initialize(context); }
  void resolve_initial_penetrations(NodalFields& nodes) override { core_.resolve_initial_penetrations(nodes); }
  void apply_forces(const NodalFields& nodes, const StepTimes& times, ContactForceView out) override {
    core_.apply_forces(nodes, times, out, friction_);
  }
  Real stable_dt() const override { return core_.stable_dt(); }
  Vec3 slave_force() const override { return core_.slave_force(); }
  Vec3 master_force() const override { return core_.master_force(); }
  Real friction_work() const override { return core_.friction_work(); }

  /// The passes (state, records, initial penetrations), for tests and diagnostics.
  const PenaltyPasses& passes() const { return core_; }

 private:
  PenaltyPasses core_;
  Friction friction_;

  static std::vector<std::unique_ptr<PenaltyPass>> one(std::unique_ptr<PenaltyPass> a) {
    std::vector<std::unique_ptr<PenaltyPass>> v;
    v.push_back(std::move(a));
    return v;
  }
};

}  // namespace slideline
