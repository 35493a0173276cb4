#pragma once
/// TiedInterface<Kind>: the kinematic tied interfaces of DYNA3D, one final class per type, the
/// kind a compile-time policy: TiedSurfaceContact (Type 2, tied surfaces: slave surface nodes),
/// TiedNodesContact (Type 6, discrete nodes tied to a surface: a slave node set) and
/// TiedShellEdgeContact (Type 7, shell edge tied to a shell surface: rotations tied too). They
/// differ in how the slave nodes are selected (the factory) and in whether rotations are required
/// (Type 7 requires them; Types 2 and 6 tie them where slave and masters both have rotational degrees of freedom,
/// i.e. shell on shell, because the simulation does not integrate a dictated node's rotation:
/// a shell slave on a solid master keeps its initial (zero) angular velocity).
///
/// Kinematics: x_s = sum N_a x_a + d_s, v_s = sum N_a v_a, omega_s = sum N_a omega_a. d_s, the
/// offset at tie time, turns with the master segment (tie_offset.hpp: its components in
/// segment_frame are kept, d_s = F(x) d_local, reset with the position every cycle), so that a tied
/// pair turning as a rigid body stays rigid; a round-off offset (the slave on the surface) is not
/// carried: d_s stays as found and the tie computes exactly what it did before offsets turned.
/// The slave's velocity stays the master point's: the offset's own rate (omega x d_s) is left out
/// (docs/contact.md, "Tied offsets that turn": a rate one step behind, the only one known when the
/// masters are accelerated, made the pair unstable through the bulk viscosity).
///
/// Interface force on the slave side: the force the tie applies to the slaves, sum (m_s a_s - f_s)
/// with a_s = sum N_a a_a (masters' final accelerations); on the master side: what the condensation
/// actually added to each master node, its force df_a less its mass dm_a times its final
/// acceleration, sum (df_a - dm_a a_a) (equal and opposite to the slave total to round-off when the
/// scatter is right: sum N_a = 1).
#include <algorithm>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "slideline/contact/contact_algorithm.hpp"
#include "slideline/contact/enforcement/kinematic.hpp"
#include "slideline/contact/search/tie_offset.hpp"
#include "slideline/contact/search/tie_search.hpp"
#include "slideline/core/error.hpp"
#include "slideline/mesh/surface.hpp"

namespace slideline {

/// Kinds (compile-time policies) of TiedInterface. require_rotations: every tied slave must have
/// rotational degrees of freedom, as must its masters (Type 7).
struct TiedSurfaceKind {
  static constexpr bool require_rotations = false;
};
struct TiedNodesKind {
  static constexpr bool require_rotations = false;
};
struct TiedShellEdgeKind {
  static constexpr bool require_rotations = true;
};

template <class Kind>
class TiedInterface final : public ContactAlgorithm, public KinematicTie {
 public:
  /// slaves: candidate slave node indices; master: the master surface.
  TiedInterface(std::string name, std::vector<Index> slaves, Surface master, TieSearchOptions options = {})
      : name_(std::move(name)), candidates_(std::move(slaves)), master_(std::move(master)), options_(options) {}

  const std::string& name() const override { return name_; }

  void initialize(const ContactContext& context) override {
    const NodalFields& nodes = context.nodes;
    tie_candidates(name_, candidates_, master_, nodes, options_, links_, untied_nodes_, context.diagnostics);
    rotation_.assign(links_.size(), 0);
    slaves_.clear();
    masters_.clear();
    for (std::size_t k = 0; k < links_.size(); ++k) {
      rotation_[k] = kinematic::ties_rotation(links_[k], nodes) ? 1 : 0;
      if (Kind::require_rotations && !rotation_[k])
        throw InputError("contact " + name_ + " (shell edge tied to a shell surface): slave node " +
                         std::to_string(nodes.ids[links_[k].slave]) +
                         " or its master nodes have no rotational degrees of freedom (shells required)");
      slaves_.push_back(links_[k].slave);
      for (int a = 0; a < 4; ++a) masters_.push_back(links_[k].master[a]);
    }
    // Offsets that turn with the master segment (tie_offset.hpp): their frame components and the
    // global offset at the last position reset.
    carried_.assign(links_.size(), 0);
    offset_local_.assign(links_.size(), Vec3::Zero());
    offset_now_.assign(links_.size(), Vec3::Zero());
    for (std::size_t k = 0; k < links_.size(); ++k) {
      const TiePoint& t = links_[k];
      if (!carry_tie_offset(master_, t, nodes.x, offset_local_[k])) continue;
      carried_[k] = 1;
      offset_now_[k] = t.offset;
    }
    std::sort(masters_.begin(), masters_.end());
    masters_.erase(std::unique(masters_.begin(), masters_.end()), masters_.end());
    force_.assign(links_.size(), Vec3::Zero());
    mass_.assign(links_.size(), 0.0);
    master_df_.assign(masters_.size(), Vec3::Zero());
    master_dm_.assign(masters_.size(), 0.0);
    slave_ = master_total_ = Vec3::Zero();
  }

  ContactPhases phases() override { return {.tie = this}; }

  void condense(const NodalFields& /*nodes*/, CondenseView v) override {
    for (std::size_t m = 0; m < masters_.size(); ++m) {  // before: what follows is this tie's
      master_df_[m] = v.force.get(masters_[m]);
      master_dm_[m] = v.mass[masters_[m]];
    }
    for (std::size_t k = 0; k < links_.size(); ++k) {
      const TiePoint& t = links_[k];
      const Real ms = v.mass[t.slave];
      const Vec3 fs = v.force.get(t.slave);
      mass_[k] = ms;
      force_[k] = fs;
      kinematic::scatter(t, v.mass, ms);
      kinematic::scatter(t, v.force, fs);
      if (rotation_[k]) {
        kinematic::scatter(t, v.rot_inertia, v.rot_inertia[t.slave]);
        kinematic::scatter(t, v.moment, v.moment.get(t.slave));
      }
    }
    for (std::size_t m = 0; m < masters_.size(); ++m) {
      master_df_[m] = v.force.get(masters_[m]) - master_df_[m];
      master_dm_[m] = v.mass[masters_[m]] - master_dm_[m];
    }
  }

  void follow_velocities(NodalFields& nodes) override {
    // The tie force on each slave, from the masters' final accelerations (idempotent: the
    // simulation may call this twice in a cycle when a rigid body resets its nodes).
    Vec3 slave = Vec3::Zero(), master = Vec3::Zero();
    for (std::size_t m = 0; m < masters_.size(); ++m)
      master += master_df_[m] - master_dm_[m] * nodes.a.get(masters_[m]);
    for (std::size_t k = 0; k < links_.size(); ++k) {
      const TiePoint& t = links_[k];
      const Vec3 tie = mass_[k] * tie_point_value(t, nodes.a) - force_[k];
      slave += tie;
      nodes.v.set(t.slave, tie_point_value(t, nodes.v));
      if (rotation_[k]) nodes.omega.set(t.slave, tie_point_value(t, nodes.omega));
    }
    slave_ = slave;
    master_total_ = master;
  }

  void follow_positions(NodalFields& nodes) override {
    for (std::size_t k = 0; k < links_.size(); ++k) {
      const TiePoint& t = links_[k];
      if (!carried_[k]) {
        nodes.x.set(t.slave, tie_point_value(t, nodes.x) + t.offset);
        continue;
      }
      offset_now_[k] = carried_tie_offset(master_, t.segment, nodes.x, offset_local_[k]);
      nodes.x.set(t.slave, tie_point_value(t, nodes.x) + offset_now_[k]);
    }
  }

  std::span<const Index> dictated_nodes() const override { return slaves_; }
  std::span<const Index> tie_master_nodes() const override { return masters_; }
  Vec3 slave_force() const override { return slave_; }
  Vec3 master_force() const override { return master_total_; }

  /// The tied slaves' master points (after initialize).
  const std::vector<TiePoint>& links() const { return links_; }
  /// Slave nodes that projected outside every master segment and were left free.
  const std::vector<Index>& untied_nodes() const { return untied_nodes_; }
  const Surface& master_surface() const { return master_; }
  /// Per link: whether its offset turns with the master segment, and the offset now (length; the
  /// tie-time offset where not carried).
  bool offset_carried(std::size_t k) const { return carried_[k] != 0; }
  Vec3 offset_now(std::size_t k) const { return carried_[k] ? offset_now_[k] : links_[k].offset; }

 private:
  std::string name_;
  std::vector<Index> candidates_;
  Surface master_;
  TieSearchOptions options_;
  std::vector<TiePoint> links_;
  std::vector<Index> untied_nodes_, slaves_, masters_;
  std::vector<std::uint8_t> rotation_;
  std::vector<Vec3> force_;   ///< total force on each slave at the last condensation
  std::vector<Real> mass_;    ///< effective mass of each slave at the last condensation
  std::vector<Vec3> master_df_;  ///< per entry of masters_: force the last condensation added
  std::vector<Real> master_dm_;  ///< per entry of masters_: mass the last condensation added
  Vec3 slave_ = Vec3::Zero(), master_total_ = Vec3::Zero();
  std::vector<std::uint8_t> carried_;  ///< per link: its offset turns with the master segment
  std::vector<Vec3> offset_local_;     ///< per carried link: the offset in segment_frame (length)
  std::vector<Vec3> offset_now_;       ///< per carried link: the offset at the last position reset
};

/// Type 2: tied surfaces.
using TiedSurfaceContact = TiedInterface<TiedSurfaceKind>;
/// Type 6: nodes tied to a surface.
using TiedNodesContact = TiedInterface<TiedNodesKind>;
/// Type 7: shell edge tied to a shell surface (rotations too).
using TiedShellEdgeContact = TiedInterface<TiedShellEdgeKind>;

}  // namespace slideline
