#pragma once
/// *CONTACT_FORCE_TRANSDUCER_PENALTY: an output-only interface. It adds no force; after every
/// other interface has put its penalty and friction forces into f_contact, it sums f_contact over
/// the nodes of its slave side (and of its master side, when the card gives one): the contact
/// force that the rest of the model exerts on that surface, written as the interface's
/// slave_force / master_force history channels like any interface's. The builder places it after
/// every other interface (build.cpp) and refuses it in a model whose contact acts through
/// constraints (kinematic ties, Type 1, Lagrange multipliers: their forces are not in f_contact).
/// docs/contact.md, "Force transducer".
#include <string>
#include <utility>
#include <vector>

#include "slideline/contact/contact_algorithm.hpp"

namespace slideline {

class ForceTransducer final : public ContactAlgorithm, public ContactForces {
 public:
  /// slave_nodes, master_nodes: internal node indices (master_nodes may be empty).
  ForceTransducer(std::string title, std::vector<Index> slave_nodes, std::vector<Index> master_nodes)
      : title_(std::move(title)), slave_(std::move(slave_nodes)), master_(std::move(master_nodes)) {}

  const std::string& name() const override { return title_; }
  void initialize(const ContactContext& /*context*/) override {}
  ContactPhases phases() override { return {.forces = this}; }
  /// Reads the contact forces the interfaces before it added into `out` (force); adds nothing.
  void apply_forces(const NodalFields& /*nodes*/, const StepTimes& /*times*/, ContactForceView out) override {
    slave_force_ = sum(out.force, slave_);
    master_force_ = sum(out.force, master_);
  }
  /// Total contact force on the slave side's nodes (force).
  Vec3 slave_force() const override { return slave_force_; }
  /// Total contact force on the master side's nodes (force; zero without a master side).
  Vec3 master_force() const override { return master_force_; }

 private:
  static Vec3 sum(const Vec3Field& f, const std::vector<Index>& nodes) {
    Vec3 s = Vec3::Zero();
    for (Index i : nodes) s += f.get(i);
    return s;
  }

  std::string title_;
  std::vector<Index> slave_, master_;
  Vec3 slave_force_ = Vec3::Zero(), master_force_ = Vec3::Zero();
};

}  // namespace slideline
