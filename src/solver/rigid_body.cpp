#include "slideline/solver/rigid_body.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "slideline/core/error.hpp"
#include "slideline/element/rigid_mass_block.hpp"

namespace slideline {

namespace {

bool carries_rotation(const NodalFields& nodes, Index i) {
  return nodes.has_rotation[i] != 0 && nodes.rot_inertia[i] > 0.0;
}

/// exp of the rotation vector `phi` as a unit quaternion.
Eigen::Quaternion<Real> quaternion_exp(const Vec3& phi) {
  const Real angle = phi.norm();
  if (!(angle > 0.0)) return Eigen::Quaternion<Real>::Identity();
  return Eigen::Quaternion<Real>(Eigen::AngleAxis<Real>(angle, phi / angle));
}

Mat3 rotate_tensor(const Eigen::Quaternion<Real>& q, const Mat3& a) {
  const Mat3 r = q.toRotationMatrix();
  return r * a * r.transpose();
}

}  // namespace

/// Pseudo-inverse of a symmetric positive semi-definite 3x3 matrix times b. A rigid body whose
/// nodes are collinear has no inertia about that line; the pseudo-inverse leaves it at rest there
/// instead of dividing by zero.
Vec3 solve_psd(const Mat3& a, const Vec3& b) {
  Eigen::SelfAdjointEigenSolver<Mat3> es(a);
  const Vec3 ev = es.eigenvalues();
  const Real cut = 1e-12 * std::max(ev.cwiseAbs().maxCoeff(), std::numeric_limits<Real>::min());
  Vec3 y = es.eigenvectors().transpose() * b;
  for (int k = 0; k < 3; ++k) y[k] = ev[k] > cut ? y[k] / ev[k] : 0.0;
  return es.eigenvectors() * y;
}

RigidBody::RigidBody(Id part_id, std::vector<Index> nodes, std::array<int, 6> fixed_dofs)
    : part_id_(part_id), nodes_(std::move(nodes)), fixed_(fixed_dofs) {
  if (nodes_.empty())
    throw InputError("rigid part " + std::to_string(part_id_) + " has no nodes");
}

void RigidBody::add_drive(RigidDrive drive, const std::string& where) {
  const int c = static_cast<int>(drive.axis);
  const std::string dof = std::string(drive.rotation ? "about " : "along ") + (c == 0 ? "x" : c == 1 ? "y" : "z");
  if (fixed_[(drive.rotation ? 3 : 0) + c])
    throw InputError(where + ": rigid part " + std::to_string(part_id_) + " is fixed " + dof + " by its *MAT_RIGID (CMO = 1, " +
                     (drive.rotation ? "CON2" : "CON1") + ") and cannot also be driven " + dof);
  for (const auto& d : drives_)
    if (d.axis == drive.axis && d.rotation == drive.rotation)
      throw InputError(where + ": rigid part " + std::to_string(part_id_) + " already has a prescribed motion " + dof);
  drives_.push_back(std::move(drive));
}

Mat3 RigidBody::inertia() const { return rotate_tensor(q_, inertia0_); }

Vec3 RigidBody::solve_omega(const Mat3& inertia, const Vec3& l) const {
  // Held rotations (fixed: 0; driven: w_drive_) take their value w_p; only the free components of
  // I omega = L hold (the support or the drive supplies the rest): with S selecting the free axes,
  // solve (S I S + (1 - S)) w_f = S (L - I w_p) and omega = w_f + w_p.
  Vec3 wp = Vec3::Zero();
  for (int c = 0; c < 3; ++c)
    if (driving_[3 + c]) wp[c] = w_drive_[c];
  Mat3 a = inertia;
  Vec3 b = l - inertia * wp;
  for (int c = 0; c < 3; ++c)
    if (held_rotation(c)) {
      a.row(c).setZero();
      a.col(c).setZero();
      a(c, c) = 1.0;
      b[c] = 0.0;
    }
  Vec3 w = solve_psd(a, b);
  for (int c = 0; c < 3; ++c)
    if (held_rotation(c)) w[c] = wp[c];
  return w;
}

void RigidBody::initialize(NodalFields& nodes, std::span<const Real> mass) {
  const Index n = static_cast<Index>(nodes.size());
  mass_ = 0.0;
  Vec3 first = Vec3::Zero();
  for (Index i : nodes_) {
    if (i < 0 || i >= n)
      throw InputError("rigid part " + std::to_string(part_id_) + " refers to a node index out of range");
    mass_ += mass[i];
    first += mass[i] * nodes.x.get(i);
  }
  if (!(mass_ > 0.0))
    throw InputError("rigid part " + std::to_string(part_id_) +
                     " has no mass (its elements must add mass before the body initialises)");
  com_ = first / mass_;
  com0_ = com_;
  driving_.fill(false);
  v_drive_.setZero();
  w_drive_.setZero();
  angle_.setZero();
  offset0_.resize(nodes_.size());
  point_inertia0_.setZero();
  Real rot = 0.0;
  Vec3 p = Vec3::Zero(), l = Vec3::Zero();
  for (std::size_t k = 0; k < nodes_.size(); ++k) {
    const Index i = nodes_[k];
    const Vec3 s = nodes.x.get(i) - com_;
    offset0_[k] = s;
    const Real m = mass[i];
    point_inertia0_ += m * (s.squaredNorm() * Mat3::Identity() - s * s.transpose());
    p += m * nodes.v.get(i);
    l += m * s.cross(nodes.v.get(i));
    if (carries_rotation(nodes, i)) {
      rot += nodes.rot_inertia[i];
      l += nodes.rot_inertia[i] * nodes.omega.get(i);
    }
  }
  inertia0_ = point_inertia0_ + rot * Mat3::Identity();
  q_ = Eigen::Quaternion<Real>::Identity();
  vel_ = p / mass_;
  for (int c = 0; c < 3; ++c)
    if (fixed_[c]) vel_[c] = 0.0;
  omega_ = solve_omega(inertia0_, l);
  ang_mom_ = inertia0_ * omega_;
  torque_.setZero();
  reaction_f_.setZero();
  reaction_m_.setZero();
  t_n_ = 0.0;
  dt_last_ = 0.0;
  reset_nodes(nodes);
}

void RigidBody::constrain_accelerations(const ConstraintLoads& loads, NodalFields& nodes, Real t) {
  t_n_ = t;
  const Mat3 r = q_.toRotationMatrix();
  Vec3 f = Vec3::Zero(), tau_p = Vec3::Zero(), tau_r = Vec3::Zero();
  for (std::size_t k = 0; k < nodes_.size(); ++k) {
    const Index i = nodes_[k];
    const Vec3 fi = loads.force(i);
    f += fi;
    tau_p += (r * offset0_[k]).cross(fi);
    if (carries_rotation(nodes, i)) tau_r += loads.moment(i);
  }
  torque_ = tau_p + tau_r;
  // With the constrained velocity held at zero, the support carries the applied load.
  for (int c = 0; c < 3; ++c) {
    reaction_f_[c] = fixed_[c] ? f[c] : 0.0;
    reaction_m_[c] = fixed_[3 + c] ? torque_[c] : 0.0;
  }
  Vec3 acc = f / mass_;
  for (int c = 0; c < 3; ++c)
    if (fixed_[c]) acc[c] = 0.0;
  // A driven axis: the acceleration that lands the centre of mass on the drive's velocity over
  // the coming step (the same rules as a nodal prescribed motion, Simulation::prescribe_supports);
  // the body exerts F - M A on the drive.
  driving_.fill(false);
  for (const RigidDrive& d : drives_) {
    const int c = static_cast<int>(d.axis);
    const bool on = d.active(t) && loads.dt_avg > 0.0 && loads.dt_next > 0.0;
    driving_[(d.rotation ? 3 : 0) + c] = on;
    if (!on) continue;
    if (d.rotation) {
      // The angular velocity over the coming step, by the same rules; the moment the body exerts
      // on the drive is the torque of its loads less the rate of change of its angular momentum,
      // estimated with the current inertia: torque - (I omega_target - L^{n-1/2}) / dt_avg.
      switch (d.kind) {
        case Prescribed::displacement:
          w_drive_[c] = (d.scale * d.curve(t + loads.dt_next) - angle_[c]) / loads.dt_next;
          break;
        case Prescribed::velocity: w_drive_[c] = d.scale * d.curve(t + 0.5 * loads.dt_next); break;
        case Prescribed::acceleration: w_drive_[c] = omega_[c] + d.scale * d.curve(t) * loads.dt_avg; break;
      }
      Vec3 w_target = omega_;
      w_target[c] = w_drive_[c];
      reaction_m_[c] = torque_[c] - (inertia() * w_target - ang_mom_)[c] / loads.dt_avg;
      continue;
    }
    switch (d.kind) {
      case Prescribed::displacement:
        v_drive_[c] = (d.scale * d.curve(t + loads.dt_next) - (com_[c] - com0_[c])) / loads.dt_next;
        break;
      case Prescribed::velocity: v_drive_[c] = d.scale * d.curve(t + 0.5 * loads.dt_next); break;
      case Prescribed::acceleration: v_drive_[c] = vel_[c] + d.scale * d.curve(t) * loads.dt_avg; break;
    }
    acc[c] = (v_drive_[c] - vel_[c]) / loads.dt_avg;
    reaction_f_[c] = f[c] - mass_ * acc[c];
  }
  // The nodes' own moments change their own angular velocities in the simulation's update; the
  // point masses carry the torque of the forces.
  const Vec3 beta = solve_psd(rotate_tensor(q_, point_inertia0_), tau_p);
  for (std::size_t k = 0; k < nodes_.size(); ++k)
    nodes.a.set(nodes_[k], acc + beta.cross(r * offset0_[k]));
}

void RigidBody::after_positions(std::span<const Real> mass, NodalFields& nodes, Real t) {
  const Real dt = t - t_n_;
  if (!(dt > 0.0)) return;
  const Mat3 r = q_.toRotationMatrix();
  // Momenta of the nodal velocities the simulation just updated (damping included).
  Vec3 p = Vec3::Zero(), l = Vec3::Zero();
  for (std::size_t k = 0; k < nodes_.size(); ++k) {
    const Index i = nodes_[k];
    const Real m = mass[i];
    const Vec3 v = nodes.v.get(i);
    p += m * v;
    l += m * (r * offset0_[k]).cross(v);
    if (carries_rotation(nodes, i)) l += nodes.rot_inertia[i] * nodes.omega.get(i);
  }
  vel_ = p / mass_;
  for (int c = 0; c < 3; ++c) {
    if (fixed_[c]) vel_[c] = 0.0;
    if (driving_[c]) vel_[c] = v_drive_[c];  // exactly, whatever damping the update applied
  }
  com_ += dt * vel_;

  // omega^{n+1/2} = I(t^{n+1/2})^{-1} L^{n+1/2}: the mid-step orientation depends on omega, so
  // iterate (a contraction for |omega| dt << 1; three passes reach round-off in practice).
  Vec3 w = solve_omega(rotate_tensor(q_, inertia0_), l);
  for (int it = 0; it < 3; ++it) {
    const Eigen::Quaternion<Real> q_mid = (quaternion_exp(0.5 * dt * w) * q_).normalized();
    w = solve_omega(rotate_tensor(q_mid, inertia0_), l);
  }
  q_ = (quaternion_exp(dt * w) * q_).normalized();
  // The nodal velocity field at x^{n+1} must carry L exactly: omega from the new inertia.
  const Mat3 inertia_new = rotate_tensor(q_, inertia0_);
  omega_ = solve_omega(inertia_new, l);
  angle_ += dt * w;
  bool any_fixed_rotation = false;
  for (int c = 0; c < 3; ++c) any_fixed_rotation = any_fixed_rotation || held_rotation(c);
  ang_mom_ = any_fixed_rotation ? Vec3(inertia_new * omega_) : l;
  dt_last_ = dt;
  reset_nodes(nodes);
}

void RigidBody::append_output_names(std::vector<std::string>& names) const {
  if (std::none_of(fixed_.begin(), fixed_.end(), [](int f) { return f != 0; }) && drives_.empty()) return;
  const std::string base = "supports/rigid_" + std::to_string(part_id_);
  names.push_back(base + "/reaction");
  names.push_back(base + "/reaction_moment");
}

void RigidBody::write_output_values(std::span<Real> out) const {
  if (out.size() < 6) return;  // a free body has no channels
  for (int c = 0; c < 3; ++c) {
    out[c] = reaction_f_[c];
    out[3 + c] = reaction_m_[c];
  }
}

void RigidBody::reset_nodes(NodalFields& nodes) const {
  const Mat3 r = q_.toRotationMatrix();
  for (std::size_t k = 0; k < nodes_.size(); ++k) {
    const Index i = nodes_[k];
    const Vec3 s = r * offset0_[k];
    nodes.x.set(i, com_ + s);
    nodes.v.set(i, vel_ + omega_.cross(s));
    if (nodes.has_rotation[i]) nodes.omega.set(i, omega_);
  }
}

std::unique_ptr<NodalConstraint> make_rigid_body(Id part_id, std::vector<Index> nodes,
                                                 std::array<int, 6> fixed_dofs) {
  return std::make_unique<RigidBody>(part_id, std::move(nodes), fixed_dofs);
}

std::unique_ptr<ElementBlock> make_rigid_mass_block(Id part_id, Real density, Real youngs,
                                                    Real poisson,
                                                    std::vector<Index> hex_connectivity,
                                                    std::vector<Index> quad_connectivity,
                                                    Real shell_thickness,
                                                    std::vector<Id> element_ids) {
  return std::make_unique<RigidMassBlock>(part_id, density, youngs, poisson,
                                          std::move(hex_connectivity),
                                          std::move(quad_connectivity), shell_thickness,
                                          std::move(element_ids));
}

}  // namespace slideline
