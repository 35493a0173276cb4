// The shell blocks the builder makes: the one place ShellBlock's kernel is compiled for
// build_simulation.
#include "slideline/element/shell_block.hpp"

#include <memory>

#include "slideline/element/block_factory.hpp"

namespace slideline {

std::unique_ptr<ElementBlock> make_shell_block(Id part_id, const ShellMaterial& material,
                                               const ShellSection& section,
                                               std::vector<Index> connectivity,
                                               std::vector<Id> element_ids, StiffnessDamping damping) {
  return std::make_unique<ShellBlock>(part_id, material, section, std::move(connectivity),
                                      std::move(element_ids), damping);
}

}  // namespace slideline
