// The hexahedron blocks the builder makes: the one place HexBlock<law> is instantiated for
// build_simulation, once per alternative of SolidLaw.
#include "slideline/element/hex_block.hpp"

#include <memory>
#include <type_traits>
#include <variant>

#include "slideline/element/block_factory.hpp"

namespace slideline {

std::unique_ptr<ElementBlock> make_hex_block(Id part_id, const SolidLaw& material,
                                             HexHourglass hourglass, BulkViscosity bulk,
                                             std::vector<Index> connectivity,
                                             std::vector<Id> element_ids, StiffnessDamping damping) {
  return std::visit(
      [&](const auto& law) -> std::unique_ptr<ElementBlock> {
        return std::make_unique<HexBlock<std::decay_t<decltype(law)>>>(
            part_id, law, hourglass, bulk, std::move(connectivity), std::move(element_ids), damping);
      },
      material);
}

}  // namespace slideline
