#pragma once
/// The topologies of the elements of one block, as runs of consecutive elements (a deformable
/// block holds one run; a rigid part may hold hexahedra then shells), and where each element's
/// nodes are in the block's flat connectivity. A block reports it (MeshBlock::topology()); mesh
/// code reads it instead of asking what class a block is.
#include <array>
#include <cstddef>
#include <span>

#include "slideline/core/error.hpp"
#include "slideline/core/types.hpp"
#include "slideline/mesh/element_topology.hpp"

namespace slideline {

/// Consecutive elements of one topology.
struct TopologyRun {
  const ElementTopology* topology = nullptr;
  Index count = 0;       ///< elements in the run
  Real thickness = 0.0;  ///< section thickness (length) of a surface element (shell); 0 for a solid
};

/// At most one run per topology, so a fixed capacity: a value, no allocation (cheap to return).
class BlockTopology {
 public:
  BlockTopology() = default;
  /// One run: every element of the block has topology `t`.
  BlockTopology(const ElementTopology& t, Index count, Real thickness = 0.0) { add(t, count, thickness); }

  /// Appends a run of `count` elements after the existing ones (nothing for count 0).
  /// Throws Error when the capacity (one run per declared topology) is exceeded.
  BlockTopology& add(const ElementTopology& t, Index count, Real thickness = 0.0) {
    if (count == 0) return *this;
    if (size_ == runs_.size()) throw Error("BlockTopology: more runs than declared topologies");
    runs_[size_++] = {&t, count, thickness};
    return *this;
  }

  std::span<const TopologyRun> runs() const { return {runs_.data(), size_}; }
  Index element_count() const {
    Index n = 0;
    for (const TopologyRun& r : runs()) n += r.count;
    return n;
  }
  /// Length of the flat connectivity: the sum of nodes over the elements.
  std::size_t connectivity_size() const {
    std::size_t n = 0;
    for (const TopologyRun& r : runs()) n += static_cast<std::size_t>(r.count) * r.topology->nodes;
    return n;
  }

  /// Element e (0 <= e < element_count()): its run (a copy, valid after this value is gone) and
  /// the offset of its first node in the block's connectivity.
  struct Element {
    TopologyRun run;
    std::size_t node_offset;
    const ElementTopology& topology() const { return *run.topology; }
  };
  Element element(Index e) const {
    std::size_t offset = 0;
    for (const TopologyRun& r : runs()) {
      if (e < r.count) return {r, offset + static_cast<std::size_t>(e) * r.topology->nodes};
      e -= r.count;
      offset += static_cast<std::size_t>(r.count) * r.topology->nodes;
    }
    throw Error("BlockTopology: element index out of range");
  }

  /// Calls f(run, e, node_offset) for every element e of the block in order.
  template <class F>
  void for_each_element(F&& f) const {
    Index e = 0;
    std::size_t offset = 0;
    for (const TopologyRun& r : runs())
      for (Index k = 0; k < r.count; ++k, ++e, offset += static_cast<std::size_t>(r.topology->nodes))
        f(r, e, offset);
  }

 private:
  std::array<TopologyRun, all_topologies.size()> runs_{};
  std::size_t size_ = 0;
};

}  // namespace slideline
