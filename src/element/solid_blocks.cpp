// The tetrahedron (ELFORM 10) and fully integrated hexahedron (ELFORM 2) blocks the builder makes:
// the one place TetBlock<law> and FullHexBlock<law> are instantiated for build_simulation, once
// per alternative of SolidLaw.
#include <memory>
#include <string>
#include <type_traits>
#include <variant>

#include "slideline/core/error.hpp"
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
        using Law = std::decay_t<decltype(law)>;
        // A null solid's step reads its state's sound speed, which only the one-point hexahedron
        // does (validate_parts refuses the other forms first, by name).
        if constexpr (std::is_same_v<Law, NullSolid>)
          throw NotImplementedError("part " + std::to_string(part_id) +
                                    ": *MAT_NULL solids run as one-point hexahedra (ELFORM 1) only");
        else
          return std::make_unique<Block<Law>>(part_id, law, bulk, std::move(connectivity), std::move(element_ids),
                                              damping);
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
