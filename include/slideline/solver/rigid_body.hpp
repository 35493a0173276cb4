#pragma once
/// A rigid part: its nodes move as one body (LS-DYNA *MAT_RIGID).
///
/// Mass, centre of mass and inertia tensor come from the lumped nodal masses (and the rotary
/// inertia of nodes that carry rotations) after every element block has initialised, so a rigid
/// part's elements are represented by a RigidMassBlock that only adds mass.
///
/// Each cycle, the body works through the simulation's own velocity update rather than around it:
///  1. constrain_accelerations (t^n): sums F and the torque about the centre of mass, and gives
///     node i the acceleration A + beta x r_i with A = F/M and I_p beta = sum r_i x f_i (I_p: the
///     point-mass inertia). The translational momentum and the angular momentum of the nodes then
///     change by exactly F dt and torque dt in the simulation's update, whatever damping it applies.
///  2. after_positions (t^{n+1}): projects the updated nodal velocities onto the body's linear
///     momentum P and angular momentum L about the centre of mass, applies the supports of the
///     body (fixed dofs, and prescribed motions: RigidDrive, add_drive), solves I omega = L at the
///     mid-step orientation, advances the orientation with the exponential map (a unit
///     quaternion), and resets every node's position and velocity
///     exactly from the body state (so the body stays rigid to round-off and P, L are conserved
///     to round-off in free flight).
#include <array>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "slideline/core/types.hpp"
#include "slideline/element/element_block.hpp"
#include "slideline/solver/nodal_constraint.hpp"
#include "slideline/solver/rigid_drive.hpp"

namespace slideline {

/// Pseudo-inverse of a symmetric positive semi-definite 3x3 matrix times b (the inertia solves of
/// rigid bodies: nodes on one line have no inertia about it, and are left at rest about it
/// instead of dividing by zero).
Vec3 solve_psd(const Mat3& a, const Vec3& b);

class RigidBody final : public NodalConstraint {
 public:
  /// `nodes`: unique internal node indices of the part; `fixed_dofs`: 1 = fixed, in the order
  /// x y z rx ry rz of the global axes (CMO = +1 CON1 / CON2).
  RigidBody(Id part_id, std::vector<Index> nodes, std::array<int, 6> fixed_dofs);

  /// Prescribes the motion of the centre of mass along one axis, or the angular velocity about
  /// one axis (before initialize). Throws InputError if that dof is fixed (CMO/CON1/CON2) or
  /// already driven; `where` names the card.
  void add_drive(RigidDrive drive, const std::string& where);

  void initialize(NodalFields& nodes, std::span<const Real> mass) override;
  void constrain_accelerations(const ConstraintLoads& loads, NodalFields& nodes, Real t) override;
  void after_positions(std::span<const Real> mass, NodalFields& nodes, Real t) override;
  std::span<const Index> constrained_nodes() const override { return nodes_; }
  /// With any fixed or driven dof: supports/rigid_<part id>/reaction (force) and
  /// supports/rigid_<part id>/reaction_moment (moment about the centre of mass); see
  /// reaction_force(). A free body reports nothing.
  void append_output_names(std::vector<std::string>& names) const override;
  void write_output_values(std::span<Real> out) const override;

  Id part_id() const { return part_id_; }
  const std::vector<Index>& nodes() const { return nodes_; }
  Real mass() const { return mass_; }                     ///< mass
  const Vec3& center_of_mass() const { return com_; }     ///< length, at the last reset
  Vec3 velocity() const { return vel_; }                  ///< length/time, at the last half step
  Vec3 angular_velocity() const { return omega_; }        ///< 1/time, global frame
  Vec3 linear_momentum() const { return mass_ * vel_; }   ///< mass length/time
  const Vec3& angular_momentum() const { return ang_mom_; }  ///< about the centre of mass
  /// Inertia tensor about the centre of mass in the current orientation (mass length^2).
  Mat3 inertia() const;
  const Eigen::Quaternion<Real>& orientation() const { return q_; }
  /// Force (x, y, z) and moment (rx, ry, rz, about the centre of mass) the body exerts on its
  /// supports at the last step; zero in the free directions. Along a driven axis: the load on the
  /// body less its mass times the acceleration the drive imposes, F - M A.
  const Vec3& reaction_force() const { return reaction_f_; }
  const Vec3& reaction_moment() const { return reaction_m_; }

 private:
  Vec3 solve_omega(const Mat3& inertia, const Vec3& l) const;
  bool held_rotation(int c) const { return fixed_[3 + c] != 0 || driving_[3 + c]; }
  void reset_nodes(NodalFields& nodes) const;

  Id part_id_;
  std::vector<Index> nodes_;
  std::array<int, 6> fixed_;
  std::vector<Vec3> offset0_;  // x_i - c in the reference orientation
  Mat3 inertia0_ = Mat3::Zero();  // about the centre of mass, reference orientation
  Mat3 point_inertia0_ = Mat3::Zero();  // the translational (point-mass) part of inertia0_
  Real mass_ = 0.0;
  Vec3 com_ = Vec3::Zero();
  Vec3 vel_ = Vec3::Zero();
  Vec3 omega_ = Vec3::Zero();
  Vec3 ang_mom_ = Vec3::Zero();
  Vec3 torque_ = Vec3::Zero();
  Eigen::Quaternion<Real> q_ = Eigen::Quaternion<Real>::Identity();
  Vec3 reaction_f_ = Vec3::Zero();
  Vec3 reaction_m_ = Vec3::Zero();
  std::vector<RigidDrive> drives_;  // at most one per dof
  std::array<bool, 6> driving_{};   // per dof (x y z rx ry rz): a drive acts over the current step
  Vec3 v_drive_ = Vec3::Zero();     // the velocity it imposes over the current step
  Vec3 w_drive_ = Vec3::Zero();     // the angular velocity it imposes (global components)
  Vec3 angle_ = Vec3::Zero();       // sum of dt omega^{n+1/2} (rotation-angle drives)
  Vec3 com0_ = Vec3::Zero();        // centre of mass at t = 0 (displacement drives)
  Real t_n_ = 0.0;       // time of the last constrain_accelerations
  Real dt_last_ = 0.0;   // the step that led to t^n
};

/// Builder entry point: a rigid body over `nodes` (unique internal indices), with fixed_dofs
/// 1 = fixed in the order x y z rx ry rz. Its mass is gathered from nodes.mass at initialisation.
std::unique_ptr<NodalConstraint> make_rigid_body(Id part_id, std::vector<Index> nodes,
                                                 std::array<int, 6> fixed_dofs);

/// Builder entry point: the mass-only block of a rigid part's elements (hexahedra: 8 indices each;
/// shells: 4 each, thickness `shell_thickness`; ids hexahedra first). `youngs` and `poisson` (the
/// *MAT_RIGID E and PR) set its time step only. See RigidMassBlock.
std::unique_ptr<ElementBlock> make_rigid_mass_block(Id part_id, Real density, Real youngs,
                                                    Real poisson,
                                                    std::vector<Index> hex_connectivity,
                                                    std::vector<Index> quad_connectivity,
                                                    Real shell_thickness,
                                                    std::vector<Id> element_ids);

}  // namespace slideline
