// The tetrahedron (ELFORM 10) and fully integrated hexahedron (ELFORM 2) blocks the builder makes:
// the one place TetBlock<law> and FullHexBlock<law> are instantiated for build_simulation, once
// per alternative of SolidLaw.
#include <memory>
#include <type_traits>
#include <variant>

#include "slideline/element/block_factory.hpp"
#include "slideline/element/full_hex_block.hpp"
#include "slideline/element/tet_block.hpp"

namespace slideline {
namespace {

/// Block<law> for the law `material` holds.
template <template <class> class Block>
std::unique_ptr<ElementBlock> make_for_law(Id part_id, const SolidLaw& material, BulkViscosity bulk,
                                           std::vector<Index> connectivity, std::vector<Id> element_ids,
                                           StiffnessDamping damping) {
  return std::visit(
      [&](const auto& law) -> std::unique_ptr<ElementBlock> {
        return std::make_unique<Block<std::decay_t<decltype(law)>>>(part_id, law, bulk, std::move(connectivity),
                                                                    std::move(element_ids), damping);
      },
      material);
}

}  // namespace

std::unique_ptr<ElementBlock> make_tet_block(Id part_id, const SolidLaw& material, BulkViscosity bulk,
                                             std::vector<Index> connectivity, std::vector<Id> element_ids,
                                             StiffnessDamping damping) {
  return make_for_law<TetBlock>(part_id, material, bulk, std::move(connectivity), std::move(element_ids), damping);
}

std::unique_ptr<ElementBlock> make_full_hex_block(Id part_id, const SolidLaw& material, BulkViscosity bulk,
                                                  std::vector<Index> connectivity, std::vector<Id> element_ids,
                                                  StiffnessDamping damping) {
  return make_for_law<FullHexBlock>(part_id, material, bulk, std::move(connectivity), std::move(element_ids),
                                    damping);
}

}  // namespace slideline
