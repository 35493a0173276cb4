#pragma once
/// The laws the elements can run: one alternative per law. The element factories
/// (element/block_factory.hpp) instantiate their blocks for each alternative, and the material
/// registry (solver/material_registry.hpp) maps a deck's material card to one of them.
#include <variant>

#include "slideline/material/elastic.hpp"
#include "slideline/material/elastic_shell.hpp"
#include "slideline/material/j2_plasticity.hpp"
#include "slideline/material/mooney_rivlin.hpp"
#include "slideline/material/null_shell.hpp"
#include "slideline/material/null_solid.hpp"
#include "slideline/material/piecewise_plasticity.hpp"
#include "slideline/material/shell_material.hpp"
#include "slideline/material/shell_plasticity.hpp"
#include "slideline/material/solid_material.hpp"

namespace slideline {

/// The law of a hexahedron block.
using SolidLaw = std::variant<ElasticSolid, MooneyRivlin, J2Plasticity, PiecewisePlasticity, NullSolid>;

/// The law of a shell block.
using ShellLaw = std::variant<ElasticShell, NullShell, ShellPlasticity<J2Plasticity>, ShellPlasticity<PiecewisePlasticity>>;

namespace detail {
template <class V>
inline constexpr bool all_solid = false;
template <class... L>
inline constexpr bool all_solid<std::variant<L...>> = (SolidMaterial<L> && ...);
template <class V>
inline constexpr bool all_plane_stress = false;
template <class... L>
inline constexpr bool all_plane_stress<std::variant<L...>> = (PlaneStressMaterial<L> && ...);
}  // namespace detail

static_assert(detail::all_solid<SolidLaw>, "every SolidLaw alternative must be a SolidMaterial");
static_assert(detail::all_plane_stress<ShellLaw>,
              "every ShellLaw alternative must be a PlaneStressMaterial");

}  // namespace slideline
