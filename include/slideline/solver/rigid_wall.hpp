#pragma once
/// A stationary planar rigid wall (*RIGIDWALL_PLANAR[_FINITE]) that its slave nodes may not pass,
/// enforced kinematically as LS-DYNA does: in the constraint phase, a node whose predicted
/// position x^{n+1} would be behind the plane gets the normal velocity that lands it on the plane,
/// and (FRIC) a tangential velocity change; the momentum change is the wall force. See
/// docs/solver.md, "Rigid walls".
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "slideline/core/types.hpp"
#include "slideline/solver/nodal_constraint.hpp"

namespace slideline {

/// What the builder resolves a *RIGIDWALL_PLANAR card into.
struct RigidWallSpec {
  std::string name;             ///< channels "rigidwalls/<name>/force" and ".../normal_force"
  Vec3 point = Vec3::Zero();    ///< a point of the plane (the tail, L)
  Vec3 normal = Vec3::UnitZ();  ///< unit normal, towards the side the nodes stay on
  /// _FINITE: the wall is the rectangle point + s l + r m, 0 <= s <= lenl, 0 <= r <= lenm.
  bool finite = false;
  Vec3 l_axis = Vec3::UnitX(), m_axis = Vec3::UnitY();  ///< unit, in the plane
  Real lenl = 0.0, lenm = 0.0;
  /// 0 frictionless, >= 1 no sliding, between: Coulomb coefficient on the normal impulse.
  Real friction = 0.0;
  Real birth = 0.0, death = 1e20;
  std::vector<Index> nodes;  ///< slave nodes (internal indices)
  /// Per slave node, bit c set when a support prescribes component c (the wall leaves it alone;
  /// the builder refuses a wall whose normal has a component along a fixed axis).
  std::vector<std::uint8_t> fixed;
};

class RigidWall final : public NodalConstraint {
 public:
  explicit RigidWall(RigidWallSpec spec);

  /// Refuses (InputError) a slave node that starts behind the wall.
  void initialize(NodalFields& nodes, std::span<const Real> mass) override;
  /// Corrects the accelerations of the nodes that would pass the plane over the coming step and
  /// adds the wall's force on them to f_ext (so the energy audit books its work as external work).
  /// A second call in the same cycle adds only what is still needed.
  void constrain_accelerations(const ConstraintLoads& loads, NodalFields& nodes, Real t) override;
  void after_positions(std::span<const Real>, NodalFields&, Real) override {}
  void append_output_names(std::vector<std::string>& names) const override;
  /// force: the force the nodes exert on the wall (global); normal_force: its normal component
  /// (>= 0 pushing the wall), the magnitude of its tangential part, the nodes in contact.
  void write_output_values(std::span<Real> out) const override;

  const RigidWallSpec& spec() const { return spec_; }
  /// The force the nodes exert on the wall at the last constraint phase (M L / T^2).
  const Vec3& force() const { return force_; }
  Index nodes_in_contact() const { return in_contact_; }

 private:
  /// The velocity change that keeps node k on the wall's side over the step (zero if none).
  Vec3 velocity_change(std::size_t k, const NodalFields& nodes, Real dt_avg, Real dt_next) const;
  bool covers(const Vec3& x) const;

  RigidWallSpec spec_;
  Vec3 force_ = Vec3::Zero();
  Index in_contact_ = 0;
  Real cycle_time_ = -1.0;  ///< the t of the sums above (a second call in the cycle adds to them)
};

}  // namespace slideline
