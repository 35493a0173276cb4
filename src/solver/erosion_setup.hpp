#pragma once
// What deletes the elements of a part (element/erosion_criteria.hpp): its material's failure
// strain and TDEL, and the *MAT_ADD_EROSION card of its material (docs/solver.md, "Failure and
// erosion"). Internal to the builder (build.cpp).
#include <string>
#include <unordered_map>

#include "slideline/element/erosion_criteria.hpp"
#include "slideline/model/model.hpp"
#include "slideline/solver/material_registry.hpp"

namespace slideline {

/// The *MAT_ADD_EROSION cards by material id. Refuses (InputError, at the card's file and line)
/// a MID the deck does not define as a material, a second card for the same MID, and a card on
/// *MAT_RIGID (a rigid body has no element stress to fail).
std::unordered_map<Id, const model::MatAddErosion*> add_erosions_by_material(
    const model::Model& m, const std::unordered_map<Id, const model::Material*>& materials);

/// The criteria of a part of material `laws` with `add` (null: none).
ErosionCriteria erosion_criteria(const MaterialLaws& laws, const model::MatAddErosion* add);

/// For messages: what makes the part erode ("FS = 0.02 of *MAT_PLASTIC_KINEMATIC", "*MAT_ADD_EROSION
/// (file:line)", ...).
std::string erosion_description(const MaterialLaws& laws, const model::MatAddErosion* add);

}  // namespace slideline
