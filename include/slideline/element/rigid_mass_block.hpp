#pragma once
/// The elements of a rigid part: they add their lumped mass to the nodes and no internal force.
/// The RigidBody constraint (solver/rigid_body.hpp) then moves those nodes as one body.
///
/// The rigid material's E and nu still set a time step, as in LS-DYNA *MAT_RIGID: the step the
/// same elements would have if they were elastic (constant, since the elements do not deform).
/// A model of rigid parts alone then has a step, and contact stiffness scaled on these elements
/// sees a step that matches them.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "slideline/core/error.hpp"
#include "slideline/element/element_block.hpp"
#include "slideline/element/hex8.hpp"
#include "slideline/element/shell_bt.hpp"

namespace slideline {

class RigidMassBlock final : public ElementBlock {
 public:
  /// `density` mass/length^3; `youngs` (force/length^2) and `poisson` the rigid material's
  /// elastic constants, used for the time step only; `hex_connectivity`: 8 internal node indices
  /// per hexahedron; `quad_connectivity`: 4 per shell of thickness `shell_thickness` (length);
  /// `element_ids`: the hexahedra's ids, then the shells'.
  RigidMassBlock(Id part_id, Real density, Real youngs, Real poisson,
                 std::vector<Index> hex_connectivity, std::vector<Index> quad_connectivity,
                 Real shell_thickness, std::vector<Id> element_ids)
      : part_id_(part_id),
        density_(density),
        youngs_(youngs),
        poisson_(poisson),
        thickness_(shell_thickness),
        n_hex_(static_cast<Index>(hex_connectivity.size() / 8)),
        n_quad_(static_cast<Index>(quad_connectivity.size() / 4)),
        ids_(std::move(element_ids)) {
    if (hex_connectivity.size() % 8 != 0 || quad_connectivity.size() % 4 != 0 ||
        ids_.size() != static_cast<std::size_t>(n_hex_ + n_quad_))
      throw InputError("rigid part " + std::to_string(part_id_) +
                       ": connectivity does not match the element count");
    if (!(density_ > 0.0))
      throw InputError("rigid part " + std::to_string(part_id_) + ": density must be positive");
    if (!(youngs_ > 0.0))
      throw InputError("rigid part " + std::to_string(part_id_) +
                       ": Young's modulus must be positive (it sets the time step)");
    if (!(poisson_ > -1.0 && poisson_ < 0.5))
      throw InputError("rigid part " + std::to_string(part_id_) +
                       ": Poisson's ratio must be in (-1, 0.5)");
    if (n_quad_ > 0 && !(thickness_ > 0.0))
      throw InputError("rigid part " + std::to_string(part_id_) + ": shell thickness must be positive");
    conn_ = std::move(hex_connectivity);
    conn_.insert(conn_.end(), quad_connectivity.begin(), quad_connectivity.end());
  }

  std::string kind() const override { return "rigid"; }
  Id part_id() const override { return part_id_; }
  Index element_count() const override { return n_hex_ + n_quad_; }
  std::span<const Index> connectivity() const override { return conn_; }
  /// The hexahedra, then the shells (with the part's shell thickness).
  BlockTopology topology() const override {
    return BlockTopology(hex8_topology, n_hex_).add(quad4_topology, n_quad_, thickness_);
  }
  Id element_id(Index e) const override { return ids_[e]; }

  /// Adds rho V / 8 per hexahedron corner and rho A t / 4 per shell corner (mass only: the
  /// rigid body's rotary inertia comes from the distribution of these point masses), and finds
  /// the step: hexahedra V / A_max over the dilatational wave speed sqrt(E (1 - nu) /
  /// ((1 + nu)(1 - 2 nu) rho)), shells A / max(side, diagonal) over the plate wave speed
  /// sqrt(E / ((1 - nu^2) rho)), the characteristic lengths of the deformable elements.
  void initialize(NodalFields& nodes) override {
    const Real c_solid = std::sqrt(youngs_ * (1.0 - poisson_) /
                                   ((1.0 + poisson_) * (1.0 - 2.0 * poisson_) * density_));
    const Real c_plate = std::sqrt(youngs_ / ((1.0 - poisson_ * poisson_) * density_));
    dt_ = std::numeric_limits<Real>::max();
    for (Index e = 0; e < n_hex_; ++e) {
      hex8::NodeMat X;
      for (int k = 0; k < 8; ++k) X.row(k) = nodes.x0.get(conn_[8 * e + k]).transpose();
      const Real v = hex8::volume(X, hex8::volume_gradient(X));
      if (!(v > 0.0))
        throw InputError("rigid solid element " + std::to_string(ids_[e]) + " of part " +
                         std::to_string(part_id_) + " has non-positive volume");
      for (int k = 0; k < 8; ++k) nodes.mass[conn_[8 * e + k]] += density_ * v / 8.0;
      dt_ = std::min(dt_, v / hex8::max_face_area(X) / c_solid);
    }
    const Index q0 = 8 * n_hex_;
    for (Index e = 0; e < n_quad_; ++e) {
      shell_bt::NodeMat X;
      for (int k = 0; k < 4; ++k) X.row(k) = nodes.x0.get(conn_[q0 + 4 * e + k]).transpose();
      const Real a = shell_bt::local_geometry(X).area;
      if (!(a > 0.0))
        throw InputError("rigid shell element " + std::to_string(ids_[n_hex_ + e]) + " of part " +
                         std::to_string(part_id_) + " has non-positive area");
      for (int k = 0; k < 4; ++k) nodes.mass[conn_[q0 + 4 * e + k]] += density_ * a * thickness_ / 4.0;
      dt_ = std::min(dt_, shell_bt::characteristic_length(X, a) / c_plate);
    }
  }

  /// Writes zero corner forces (the slots exist so that the gather stays uniform) and returns the
  /// step found at initialisation (time).
  bool bounds_time_step() const override { return false; }

  Real compute_forces(const NodalFields&, Real, CornerBuffer& corners, BlockEnergy&) override {
    const Index b = force_slot_base();
    const Index n = static_cast<Index>(conn_.size());
    for (Index k = 0; k < n; ++k) {
      corners.force.x[b + k] = 0.0;
      corners.force.y[b + k] = 0.0;
      corners.force.z[b + k] = 0.0;
    }
    return dt_;
  }

  /// The stable step of the part's elements (time), valid after initialize().
  Real stable_dt() const { return dt_; }
  /// E / (3 (1 - 2 nu)) of the rigid material: the stiffness contact sees on a rigid surface.
  Real bulk_modulus() const override { return youngs_ / (3.0 * (1.0 - 2.0 * poisson_)); }

 private:
  Id part_id_;
  Real density_;
  Real youngs_;
  Real poisson_;
  Real thickness_;
  Real dt_ = std::numeric_limits<Real>::max();
  Index n_hex_, n_quad_;
  std::vector<Index> conn_;
  std::vector<Id> ids_;
};

}  // namespace slideline
