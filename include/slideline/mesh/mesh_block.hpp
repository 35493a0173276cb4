#pragma once
/// What the mesh layer knows of an element block: its part, its elements' nodes and their declared
/// topologies. ElementBlock (element/element_block.hpp) implements it; surfaces, segment stiffness
/// and the output mesh read blocks through it, so mesh code never includes element/ and never asks
/// what class a block is.
#include <concepts>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "slideline/core/types.hpp"
#include "slideline/mesh/block_topology.hpp"

namespace slideline {

class MeshBlock {
 public:
  virtual ~MeshBlock() = default;

  /// The formulation's name, for messages ("hex8", "shell_bt", "rigid").
  virtual std::string kind() const = 0;
  virtual Id part_id() const = 0;
  virtual Index element_count() const = 0;
  /// Flat connectivity: each element's nodes (its topology's count) one after the other, in the
  /// element order of topology().
  virtual std::span<const Index> connectivity() const = 0;
  /// Deck id of element e, for messages.
  virtual Id element_id(Index e) const = 0;
  /// The topology of every element, as runs in element order (and section thickness of shells).
  virtual BlockTopology topology() const = 0;
  /// Small-strain bulk modulus of the block's material (force/length^2), for contact penalty
  /// stiffness; 0 for a block without one.
  virtual Real bulk_modulus() const { return 0.0; }
};

/// A range the surface builders take as "the model's blocks": an indexable range of (smart)
/// pointers to MeshBlock or a class derived from it, e.g. Simulation::blocks().
template <class R>
concept MeshBlockRange = requires(const R& r, std::size_t i) {
  { r.size() } -> std::convertible_to<std::size_t>;
  { *r[i] } -> std::convertible_to<const MeshBlock&>;
};

/// Plain pointers to the blocks of `blocks`, in order (allocates: for initialisation).
template <MeshBlockRange R>
std::vector<const MeshBlock*> mesh_blocks(const R& blocks) {
  std::vector<const MeshBlock*> out;
  out.reserve(blocks.size());
  for (std::size_t i = 0; i < blocks.size(); ++i) out.push_back(&static_cast<const MeshBlock&>(*blocks[i]));
  return out;
}

/// The cells of one topology over a whole model, for output.
struct TopologyCells {
  const ElementTopology* topology = nullptr;
  std::vector<Index> connectivity;  ///< topology->nodes internal node indices per cell

  std::size_t count() const { return connectivity.size() / static_cast<std::size_t>(topology->nodes); }
};

/// Every element of `blocks` grouped by topology: one entry per topology of all_topologies, in that
/// order (an empty connectivity where the model has none; a topology outside that list gets an
/// entry after them), cells in block then element order.
std::vector<TopologyCells> cells_by_topology(std::span<const MeshBlock* const> blocks);

}  // namespace slideline
