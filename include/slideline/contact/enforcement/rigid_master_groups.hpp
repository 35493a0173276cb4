#pragma once
/// RigidMasterGroups: the rigid parts on a Lagrange interface's master side, each moved by the
/// forward-increment solve as ONE translating mass (RigidGroups, enforcement/lagrange.hpp, whose
/// file comment says why). Built once in initialize() (allocates); update() allocates nothing.
#include <algorithm>
#include <array>
#include <span>
#include <utility>
#include <vector>

#include "slideline/contact/contact_algorithm.hpp"
#include "slideline/contact/enforcement/lagrange.hpp"
#include "slideline/mesh/mesh_sets.hpp"
#include "slideline/mesh/surface.hpp"

namespace slideline {

class RigidMasterGroups {
 public:
  /// One group per rigid part with a segment on `master`: its nodes are the part's nodes (from the
  /// context's sets when given, else the part's master-surface nodes). held: the translations a
  /// part's body holds fixed (*MAT_RIGID CMO/CON1), by part id; parts not listed translate freely.
  void setup(const Surface& master, const ContactContext& c,
             std::span<const std::pair<Id, std::array<int, 3>>> held) {
    group_of_.clear();
    group_nodes_.clear();
    group_mass_.clear();
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
    group_mass_.assign(parts.size(), 0.0);
    group_compliance_.assign(parts.size(), Vec3::Zero());
    group_force_.assign(parts.size(), Vec3::Zero());
    groups_ = {group_of_, group_compliance_, group_force_};
  }

  /// The compliance of each group for this cycle's solve: c_g = dt_next dt_avg / ((1 + h) M_g) per
  /// component, 0 where the body is held or any of its nodes is fixed.
  void update(const ConstraintView& view, const StepTimes& times) {
    for (std::size_t g = 0; g < group_mass_.size(); ++g) {
      Real m = 0.0, h = 0.0;
      std::array<bool, 3> fixed{group_held_[g][0] != 0, group_held_[g][1] != 0, group_held_[g][2] != 0};
      for (Index n : group_nodes_[g]) {
        if (group_of_[static_cast<std::size_t>(n)] != static_cast<Index>(g)) continue;
        m += view.nodes.mass[static_cast<std::size_t>(n)];
        h = 0.5 * view.damping[static_cast<std::size_t>(n)] * times.dt_avg;
        for (int c = 0; c < 3; ++c) fixed[c] = fixed[c] || view.fixed[c][static_cast<std::size_t>(n)];
      }
      const Real cg = m > 0.0 ? times.dt_next * times.dt_avg / ((1.0 + h) * m) : 0.0;
      group_compliance_[g] = {fixed[0] ? 0.0 : cg, fixed[1] ? 0.0 : cg, fixed[2] ? 0.0 : cg};
    }
  }

  /// The groups for the solve, or nullptr when the master has no rigid part.
  const RigidGroups* groups() const { return group_mass_.empty() ? nullptr : &groups_; }

 private:
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
  std::vector<std::array<int, 3>> group_held_;
  std::vector<Vec3> group_compliance_, group_force_;
  RigidGroups groups_;
};

}  // namespace slideline
