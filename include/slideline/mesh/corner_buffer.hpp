#pragma once
/// Per-element-corner force (and moment) storage, gathered into nodes without atomics.
///
/// Every element writes the forces it applies to its nodes into its own corner slots; a node then
/// sums its slots in a fixed order (a CSR list built once). The sum therefore does not depend on
/// the thread count, and no two threads ever write the same memory.
#include <span>
#include <vector>

#include "slideline/core/parallel.hpp"
#include "slideline/mesh/nodal_fields.hpp"

namespace slideline {

/// Compressed node -> slot lists.
struct NodeSlots {
  std::vector<Index> offset;  ///< size n_nodes + 1
  std::vector<Index> slot;

  /// Builds the lists from a flat connectivity: slot s belongs to node conn[s] (slot base added).
  void build(Index n_nodes, const std::vector<std::pair<Index, Index>>& node_slot_pairs) {
    offset.assign(n_nodes + 1, 0);
    for (const auto& [n, s] : node_slot_pairs) ++offset[n + 1];
    for (Index i = 0; i < n_nodes; ++i) offset[i + 1] += offset[i];
    slot.assign(node_slot_pairs.size(), 0);
    std::vector<Index> fill(offset.begin(), offset.end() - 1);
    for (const auto& [n, s] : node_slot_pairs) slot[fill[n]++] = s;
  }
};

/// Corner slots of all element blocks of a model. A block owns the range
/// [base, base + nodes of its elements' topologies) of `force`, and shells also a range of `moment`.
struct CornerBuffer {
  Vec3Field force;
  Vec3Field moment;
  NodeSlots force_slots;
  NodeSlots moment_slots;

  /// -sum (f . v + m . omega) over a block's corners: the forces (and moments) now in its slots
  /// [fbase, fbase + conn.size()) (moments from mbase when `moments`) at the velocities of `nodes`,
  /// slot fbase + k acting on node conn[k]. Called before the block writes its new forces, it is
  /// the power of the last evaluation's forces at this step's rates: with the new forces' power, the
  /// trapezoidal work of the block's forces (Simulation::compute_internal_forces). `partial` holds
  /// at least chunk_count(conn.size()) entries; summed in chunk order (thread-count independent).
  Real power(std::span<const Index> conn, Index fbase, Index mbase, bool moments, const NodalFields& nodes,
             std::vector<Real>& partial) const {
    const Index n = static_cast<Index>(conn.size());
    parallel_for_chunks(n, [&](Index b, Index end, Index chunk) {
      Real p = 0.0;
      for (Index k = b; k < end; ++k) {
        const Index i = conn[static_cast<std::size_t>(k)], s = fbase + k;
        p -= force.x[s] * nodes.v.x[i] + force.y[s] * nodes.v.y[i] + force.z[s] * nodes.v.z[i];
        if (moments) {
          const Index r = mbase + k;
          p -= moment.x[r] * nodes.omega.x[i] + moment.y[r] * nodes.omega.y[i] + moment.z[r] * nodes.omega.z[i];
        }
      }
      partial[static_cast<std::size_t>(chunk)] = p;
    });
    Real sum = 0.0;
    for (Index c = 0; c < chunk_count(n); ++c) sum += partial[static_cast<std::size_t>(c)];
    return sum;
  }

  /// Sums the corner forces into `f` and the corner moments into `m` (both overwritten).
  void gather(Vec3Field& f, Vec3Field& m) const {
    const Index n = static_cast<Index>(f.size());
    parallel_for(n, [&](Index i) {
      sum_slots(force_slots, force, i, f);
      if (moment_slots.offset.empty()) return;
      sum_slots(moment_slots, moment, i, m);
    });
  }

 private:
  /// out[i] = the sum of node i's slots of `corners`, in slot-list order.
  static void sum_slots(const NodeSlots& slots, const Vec3Field& corners, Index i, Vec3Field& out) {
    Real sx = 0, sy = 0, sz = 0;
    for (Index k = slots.offset[i]; k < slots.offset[i + 1]; ++k) {
      const Index s = slots.slot[k];
      sx += corners.x[s];
      sy += corners.y[s];
      sz += corners.z[s];
    }
    out.x[i] = sx;
    out.y[i] = sy;
    out.z[i] = sz;
  }
};

}  // namespace slideline
