#pragma once
/// DYNA3D Type 3 (*CONTACT_SURFACE_TO_SURFACE), sliding with voids and friction, penalty
/// enforcement: two passes, the slave nodes on the master segments and the master nodes on the
/// slave segments (symmetric treatment), each at the full penalty stiffness of the segment it
/// meets (its springs are distinct node/segment pairs: nothing acts twice). docs/contact.md,
/// "Penalty contact".
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
class SurfaceToSurfaceContact final : public ContactAlgorithm {
 public:
  /// slave_pass: the card's slave nodes on its master surface; master_pass: the master nodes on
  /// the slave surface (its forces count to the other side's totals).
  SurfaceToSurfaceContact(std::string title, std::unique_ptr<PenaltyPass> slave_pass,
                          std::unique_ptr<PenaltyPass> master_pass, Friction friction)
      : core_(std::move(title), two(std::move(slave_pass), std::move(master_pass)), {false, true}),
        friction_(friction) {}

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

  static std::vector<std::unique_ptr<PenaltyPass>> two(std::unique_ptr<PenaltyPass> a, std::unique_ptr<PenaltyPass> b) {
    std::vector<std::unique_ptr<PenaltyPass>> v;
    v.push_back(std::move(a));
    v.push_back(std::move(b));
    return v;
  }
};

}  // namespace slideline
