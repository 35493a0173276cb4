// The shell blocks the builder makes: the one place BasicShellBlock<law> is instantiated for
// build_simulation, once per alternative of ShellLaw.
#include "slideline/element/shell_block.hpp"

#include <memory>
#include <type_traits>
#include <variant>

#include "slideline/element/block_factory.hpp"

namespace slideline {

std::unique_ptr<ElementBlock> make_shell_block(Id part_id, const ShellLaw& material,
                                               const ShellSection& section,
                                               std::vector<Index> connectivity,
                                               std::vector<Id> element_ids, StiffnessDamping damping) {
  return std::visit(
      [&](const auto& law) -> std::unique_ptr<ElementBlock> {
        return std::make_unique<BasicShellBlock<std::decay_t<decltype(law)>>>(
            part_id, law, section, std::move(connectivity), std::move(element_ids), damping);
      },
      material);
}

}  // namespace slideline
