#include "slideline/mesh/mesh_block.hpp"

#include <algorithm>

namespace slideline {

std::vector<TopologyCells> cells_by_topology(std::span<const MeshBlock* const> blocks) {
  std::vector<TopologyCells> cells;
  for (const ElementTopology* t : all_topologies) cells.push_back({t, {}});
  auto cells_of = [&](const ElementTopology* t) -> std::vector<Index>& {
    auto it = std::find_if(cells.begin(), cells.end(), [&](const TopologyCells& c) { return c.topology == t; });
    if (it == cells.end()) it = cells.insert(cells.end(), {t, {}});  // a topology not in the list
    return it->connectivity;
  };
  for (const MeshBlock* block : blocks) {
    const std::span<const Index> conn = block->connectivity();
    block->topology().for_each_element([&](const TopologyRun& run, Index, std::size_t offset) {
      std::vector<Index>& dst = cells_of(run.topology);
      dst.insert(dst.end(), conn.begin() + static_cast<std::ptrdiff_t>(offset),
                 conn.begin() + static_cast<std::ptrdiff_t>(offset) + run.topology->nodes);
    });
  }
  return cells;
}

}  // namespace slideline
