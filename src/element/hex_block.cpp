// The hexahedron blocks the builder makes: the one place HexBlock<material> is instantiated for
// build_simulation.
#include "slideline/element/hex_block.hpp"

#include <memory>
#include <variant>

#include "slideline/element/block_factory.hpp"
#include "slideline/material/elastic.hpp"
#include "slideline/material/mooney_rivlin.hpp"

namespace slideline {

std::unique_ptr<ElementBlock> make_hex_block(Id part_id, const HexMaterialSpec& material,
                                             HexHourglass hourglass, BulkViscosity bulk,
                                             std::vector<Index> connectivity,
                                             std::vector<Id> element_ids, StiffnessDamping damping) {
  return std::visit(
      [&](const auto& m) -> std::unique_ptr<ElementBlock> {
        using T = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<T, ElasticSolidSpec>) {
          return std::make_unique<HexBlock<ElasticSolid>>(
              part_id, ElasticSolid(m.density, m.youngs, m.poisson), hourglass, bulk,
              std::move(connectivity), std::move(element_ids), damping);
        } else {
          static_assert(std::is_same_v<T, MooneyRivlinSpec>);
          return std::make_unique<HexBlock<MooneyRivlin>>(
              part_id, MooneyRivlin(m.density, m.a, m.b, m.poisson), hourglass, bulk,
              std::move(connectivity), std::move(element_ids), damping);
        }
      },
      material);
}

}  // namespace slideline
