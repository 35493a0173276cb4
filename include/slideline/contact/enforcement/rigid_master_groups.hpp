#pragma once
/// RigidMasterGroups: the rigid parts on a Lagrange interface's master side, each moved by the
/// forward-increment solve as ONE rigid body that translates and (unless switched off) turns about
/// its centre of mass (RigidGroups, enforcement/lagrange.hpp, whose file comment says why). Built
/// once in initialize() (allocates); update() allocates nothing.
///
/// Mass, centre of mass and inertia are formed each cycle from the group's nodes at x^n as the
/// rigid-body module forms them (solver/rigid_body.hpp): M = sum m_i, c = sum m_i x_i / M,
/// I = sum m_i (|s_i|^2 1 - s_i s_i^T) + (sum of the rotary inertias of nodes that carry
/// rotations) 1, s_i = x_i - c. RigidBody resets its nodes exactly from (c, orientation) every
/// cycle, so these equal its centre and current inertia to round-off. It turns with
/// omega = I^-1 L on its free axes (RigidBody::solve_omega: held rows and columns replaced by the
/// identity, the pseudo-inverse below a 1e-12 relative eigenvalue cut), which is the J_g here.
#include <algorithm>
#include <array>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include <Eigen/Eigenvalues>

#include "slideline/contact/contact_algorithm.hpp"
#include "slideline/contact/enforcement/lagrange.hpp"
#include "slideline/mesh/mesh_sets.hpp"
#include "slideline/mesh/surface.hpp"

namespace slideline {

/// A prescribed motion of a rigid master part (*BOUNDARY_PRESCRIBED_MOTION_RIGID): while it acts
/// (birth <= t <= death, as RigidDrive::active) the body's dof is held in the solve.
struct RigidMasterDrive {
  Id part = 0;
  int dof = 0;  ///< 0-2 translation x y z, 3-5 rotation about x y z
  Real birth = 0.0, death = 1e28;
  bool active(Real t) const { return t >= birth && t <= death; }
};

class RigidMasterGroups {
 public:
  /// One group per rigid part with a segment on `master`: its nodes are the part's nodes (from the
  /// context's sets when given, else the part's master-surface nodes). held: the translations a
  /// part's body holds fixed (*MAT_RIGID CMO/CON1), by part id; parts not listed translate freely.
  /// held_rotations: likewise the rotations (CON2). drives: the dofs a prescribed motion holds
  /// while it acts. rotation = false: the groups only translate (the solve before the rotation was
  /// added; for comparisons).
  void setup(const Surface& master, const ContactContext& c,
             std::span<const std::pair<Id, std::array<int, 3>>> held,
             std::span<const std::pair<Id, std::array<int, 3>>> held_rotations = {}, bool rotation = false,
             std::span<const RigidMasterDrive> drives = {}) {
    group_of_.clear();
    group_nodes_.clear();
    group_mass_.clear();
    group_center_.clear();
    group_spin_.clear();
    group_torque_.clear();
    if (c.rigid.empty()) return;
    std::vector<Id> parts;
    for (Index s = 0; s < master.segment_count(); ++s) {
      const Index* n = &master.conn[4 * static_cast<std::size_t>(s)];
      if (!c.rigid[static_cast<std::size_t>(n[0])]) continue;
      const Id pid = master.part[static_cast<std::size_t>(s)];
      if (std::find(parts.begin(), parts.end(), pid) == parts.end()) parts.push_back(pid);
    }
    if (parts.empty()) return;
    group_of_.assign(c.nodes.size(), -1);
    for (std::size_t g = 0; g < parts.size(); ++g) {
      std::vector<Index> nodes = part_nodes(master, c, parts[g]);
      for (Index n : nodes)
        if (c.rigid[static_cast<std::size_t>(n)] && group_of_[static_cast<std::size_t>(n)] < 0)
          group_of_[static_cast<std::size_t>(n)] = static_cast<Index>(g);
      group_nodes_.push_back(std::move(nodes));
    }
    group_held_.assign(parts.size(), {0, 0, 0});
    for (std::size_t g = 0; g < parts.size(); ++g)
      for (const auto& [pid, h] : held)
        if (pid == parts[g]) group_held_[g] = h;
    group_held_rotation_.assign(parts.size(), {0, 0, 0});
    for (std::size_t g = 0; g < parts.size(); ++g)
      for (const auto& [pid, h] : held_rotations)
        if (pid == parts[g]) group_held_rotation_[g] = h;
    group_drives_.clear();
    for (std::size_t g = 0; g < parts.size(); ++g)
      for (const RigidMasterDrive& d : drives)
        if (d.part == parts[g]) group_drives_.emplace_back(g, d);
    group_mass_.assign(parts.size(), 0.0);
    group_compliance_.assign(parts.size(), Vec3::Zero());
    group_force_.assign(parts.size(), Vec3::Zero());
    groups_ = {group_of_, group_compliance_, group_force_};
    if (!rotation) return;
    group_center_.assign(parts.size(), Vec3::Zero());
    group_spin_.assign(parts.size(), Mat3::Zero());
    group_torque_.assign(parts.size(), Vec3::Zero());
    groups_.center = group_center_;
    groups_.spin = group_spin_;
    groups_.torque = group_torque_;
  }

  /// The compliance of each group for this cycle's solve: c_g = dt_next dt_avg / ((1 + h) M_g) per
  /// component, 0 where the body is held or any of its nodes is fixed.
  void update(const ConstraintView& view, const StepTimes& times) {
    for (std::size_t g = 0; g < group_mass_.size(); ++g) {
      Real m = 0.0, h = 0.0;
      std::array<bool, 3> fixed{group_held_[g][0] != 0, group_held_[g][1] != 0, group_held_[g][2] != 0};
      std::array<bool, 3> turn_held{group_held_rotation_[g][0] != 0, group_held_rotation_[g][1] != 0,
                                    group_held_rotation_[g][2] != 0};
      for (const auto& [dg, d] : group_drives_)
        if (dg == g && d.active(times.t)) (d.dof < 3 ? fixed : turn_held)[static_cast<std::size_t>(d.dof % 3)] = true;
      for (Index n : group_nodes_[g]) {
        if (group_of_[static_cast<std::size_t>(n)] != static_cast<Index>(g)) continue;
        m += view.nodes.mass[static_cast<std::size_t>(n)];
        h = 0.5 * view.damping[static_cast<std::size_t>(n)] * times.dt_avg;
        for (int c = 0; c < 3; ++c) fixed[c] = fixed[c] || view.fixed[c][static_cast<std::size_t>(n)];
      }
      const Real cg = m > 0.0 ? times.dt_next * times.dt_avg / ((1.0 + h) * m) : 0.0;
      group_compliance_[g] = {fixed[0] ? 0.0 : cg, fixed[1] ? 0.0 : cg, fixed[2] ? 0.0 : cg};
      group_mass_[g] = m;
      if (!group_spin_.empty()) update_rotation(g, view, times.dt_next * times.dt_avg / (1.0 + h), turn_held);
    }
  }

  /// Centre of mass at x^n of each group (length; rotation only), for tests.
  std::span<const Vec3> centers() const { return group_center_; }
  /// Rotational compliance J_g of each group this cycle (1 / (force length); rotation only).
  std::span<const Mat3> spins() const { return group_spin_; }

  /// The groups for the solve, or nullptr when the master has no rigid part.
  const RigidGroups* groups() const { return group_mass_.empty() ? nullptr : &groups_; }

 private:
  /// Centre and J_g = scale I^-1 of group g (the file comment); J_g = 0 when any node of the group
  /// has a fixed component (a support on a rigid node pins the body somewhere other than its
  /// centre: the solve then leaves the rotation to the update, as before).
  void update_rotation(std::size_t g, const ConstraintView& view, Real scale, const std::array<bool, 3>& held) {
    const NodalFields& nodes = view.nodes;
    Real m = 0.0, rot = 0.0;
    Vec3 first = Vec3::Zero();
    bool pinned = false;
    for (Index n : group_nodes_[g]) {
      const auto i = static_cast<std::size_t>(n);
      if (group_of_[i] != static_cast<Index>(g)) continue;
      m += view.mass[i];
      first += view.mass[i] * nodes.x.get(n);
      pinned = pinned || view.fixed[0][i] || view.fixed[1][i] || view.fixed[2][i];
    }
    group_spin_[g].setZero();
    if (!(m > 0.0)) return;
    const Vec3 center = first / m;
    group_center_[g] = center;
    if (pinned) return;
    Mat3 inertia = Mat3::Zero();
    for (Index n : group_nodes_[g]) {
      const auto i = static_cast<std::size_t>(n);
      if (group_of_[i] != static_cast<Index>(g)) continue;
      const Vec3 s = nodes.x.get(n) - center;
      inertia += view.mass[i] * (s.squaredNorm() * Mat3::Identity() - s * s.transpose());
      if (nodes.has_rotation[i] != 0 && nodes.rot_inertia[i] > 0.0) rot += nodes.rot_inertia[i];
    }
    inertia += rot * Mat3::Identity();
    // RigidBody::solve_omega: held rotations take the identity's row and column, and their
    // component of omega is held; the free block is inverted as solve_psd does.
    for (int c = 0; c < 3; ++c)
      if (held[static_cast<std::size_t>(c)]) {
        inertia.row(c).setZero();
        inertia.col(c).setZero();
        inertia(c, c) = 1.0;
      }
    const Eigen::SelfAdjointEigenSolver<Mat3> es(inertia);
    const Vec3 ev = es.eigenvalues();
    const Real cut = 1e-12 * std::max(ev.cwiseAbs().maxCoeff(), std::numeric_limits<Real>::min());
    Vec3 inv = Vec3::Zero();
    for (int k = 0; k < 3; ++k) inv[k] = ev[k] > cut ? 1.0 / ev[k] : 0.0;
    Mat3 j = es.eigenvectors() * inv.asDiagonal() * es.eigenvectors().transpose();
    for (int c = 0; c < 3; ++c)
      if (held[static_cast<std::size_t>(c)]) {
        j.row(c).setZero();
        j.col(c).setZero();
      }
    group_spin_[g] = scale * j;
  }

  static std::vector<Index> part_nodes(const Surface& master, const ContactContext& c, Id pid) {
    if (c.sets) {
      const auto f = c.sets->part_nodes.find(pid);
      if (f != c.sets->part_nodes.end()) return f->second;
    }
    std::vector<Index> nodes;
    for (Index s = 0; s < master.segment_count(); ++s)
      if (master.part[static_cast<std::size_t>(s)] == pid)
        for (int k = 0; k < 4; ++k) nodes.push_back(master.conn[4 * static_cast<std::size_t>(s) + k]);
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    return nodes;
  }

  std::vector<Index> group_of_;                ///< per node: its group, -1
  std::vector<std::vector<Index>> group_nodes_;
  std::vector<Real> group_mass_;
  std::vector<std::array<int, 3>> group_held_, group_held_rotation_;
  std::vector<std::pair<std::size_t, RigidMasterDrive>> group_drives_;  ///< (group, drive)
  std::vector<Vec3> group_compliance_, group_force_;
  std::vector<Vec3> group_center_, group_torque_;  ///< rotation only
  std::vector<Mat3> group_spin_;                   ///< rotation only
  RigidGroups groups_;
};

}  // namespace slideline
