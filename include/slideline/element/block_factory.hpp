#pragma once
/// Factories of the deformable element blocks, defined in src/element/. The builder
/// (src/solver/build.cpp) makes its blocks through them, so that it does not instantiate the
/// element kernels itself (they compile once, in src/element/*.cpp).
#include <memory>
#include <vector>

#include "slideline/core/types.hpp"
#include "slideline/element/block_options.hpp"
#include "slideline/element/element_block.hpp"
#include "slideline/material/laws.hpp"

namespace slideline {

/// A block of one-point hexahedra (HexBlock<law>) of part `part_id`. `connectivity`: 8
/// internal node indices per element (LS-DYNA order), `element_ids` the deck ids, one per
/// element; `damping.beta` > 0 adds stiffness-proportional damping.
std::unique_ptr<ElementBlock> make_hex_block(Id part_id, const SolidLaw& material,
                                             HexHourglass hourglass, BulkViscosity bulk,
                                             std::vector<Index> connectivity,
                                             std::vector<Id> element_ids,
                                             StiffnessDamping damping = {});

/// A block of one-point tetrahedra (TetBlock<law>, *SECTION_SOLID ELFORM 10) of part `part_id`.
/// `connectivity`: 4 internal node indices per element, N1-N3 counter-clockwise seen from N4.
std::unique_ptr<ElementBlock> make_tet_block(Id part_id, const SolidLaw& material, BulkViscosity bulk,
                                             std::vector<Index> connectivity, std::vector<Id> element_ids,
                                             StiffnessDamping damping = {});

/// A block of fully integrated selective-reduced hexahedra (FullHexBlock<law>, *SECTION_SOLID
/// ELFORM 2) of part `part_id`: connectivity as make_hex_block's; no hourglass control.
std::unique_ptr<ElementBlock> make_full_hex_block(Id part_id, const SolidLaw& material, BulkViscosity bulk,
                                                  std::vector<Index> connectivity, std::vector<Id> element_ids,
                                                  StiffnessDamping damping = {});

/// A block of Belytschko-Tsay shells (BasicShellBlock<law>) of part `part_id`. `connectivity`: 4 internal
/// node indices per element (counter-clockwise seen from the side the normal points to).
/// Throws InputError on a bad value (non-positive density, modulus, thickness or shear factor,
/// Poisson's ratio outside (-1, 0.5), an unsupported number of thickness points).
std::unique_ptr<ElementBlock> make_shell_block(Id part_id, const ShellLaw& material,
                                               const ShellSection& section,
                                               std::vector<Index> connectivity,
                                               std::vector<Id> element_ids,
                                               StiffnessDamping damping = {});

}  // namespace slideline
