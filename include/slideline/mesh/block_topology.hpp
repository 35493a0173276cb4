#pragma once
/// Which elements of an element block are hexahedra and which are shells, and where their nodes
/// are in connectivity(). Deformable blocks hold one kind; a rigid part (RigidMassBlock) may hold
/// both, hexahedra first. Surface builders and the stiffness query go through this so that they
/// treat rigid and deformable parts alike.
#include <string>

#include "slideline/core/error.hpp"
#include "slideline/core/types.hpp"
#include "slideline/element/element_block.hpp"
#include "slideline/element/rigid_mass_block.hpp"
#include "slideline/element/shell_block.hpp"

namespace slideline {

struct BlockTopology {
  Index hex_count = 0;          ///< elements 0 .. hex_count - 1 are hexahedra
  Index shell_count = 0;        ///< elements hex_count .. hex_count + shell_count - 1 are shells
  Real shell_thickness = 0.0;   ///< length; 0 when the block has no shells

  bool is_hex(Index e) const { return e < hex_count; }
  /// Offset of element e's first node in connectivity(): 8 per hexahedron, then 4 per shell.
  std::size_t node_offset(Index e) const {
    return e < hex_count ? 8 * static_cast<std::size_t>(e)
                         : 8 * static_cast<std::size_t>(hex_count) +
                               4 * static_cast<std::size_t>(e - hex_count);
  }
};

/// True when `block` holds hexahedra and/or shells (a kind block_topology knows).
inline bool has_faces(const ElementBlock& block) {
  return dynamic_cast<const RigidMassBlock*>(&block) != nullptr ||
         dynamic_cast<const ShellBlock*>(&block) != nullptr || block.nodes_per_element() == 8;
}

/// The topology of `block`. Throws NotImplementedError for a block kind that is neither
/// hexahedra, shells nor a rigid part (it cannot carry a contact surface yet).
inline BlockTopology block_topology(const ElementBlock& block) {
  BlockTopology t;
  if (const auto* rigid = dynamic_cast<const RigidMassBlock*>(&block)) {
    t.hex_count = rigid->hex_count();
    t.shell_count = rigid->element_count() - rigid->hex_count();
    t.shell_thickness = t.shell_count > 0 ? rigid->shell_thickness() : 0.0;
  } else if (const auto* shell = dynamic_cast<const ShellBlock*>(&block)) {
    t.shell_count = shell->element_count();
    t.shell_thickness = shell->section().thickness;
  } else if (block.nodes_per_element() == 8) {
    t.hex_count = block.element_count();
  } else {
    throw NotImplementedError("element block '" + block.kind() + "' of part " +
                              std::to_string(block.part_id()) +
                              " cannot carry a contact surface (only hexahedra and shells can)");
  }
  return t;
}

}  // namespace slideline
