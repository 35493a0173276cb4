#pragma once
// The fields of the state output (one table for the HDF5 writer and its XDMF companion) and the
// XDMF document that describes them (docs/output.md, "Nodal states and mesh", "ParaView").
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "slideline/core/types.hpp"
#include "slideline/mesh/element_topology.hpp"

namespace slideline::xdmf {

enum class Center { node, cell };

/// One output field: its name (HDF5 dataset and XDMF attribute), where it lives, its components
/// (3: a vector, 6: a symmetric tensor xx yy zz xy yz xz), its units, whether only surface cells
/// (shells) have it, and whether it is fixed for the run (written once under /mesh).
struct Field {
  std::string_view name;
  Center center;
  int components;
  std::string_view units;
  bool surface_only = false;
  bool fixed = false;
  bool integer = false;
};

inline constexpr Field kFields[] = {
    {"displacement", Center::node, 3, "length"},
    {"velocity", Center::node, 3, "length/time"},
    {"acceleration", Center::node, 3, "length/time^2"},
    {"contact_force", Center::node, 3, "force (mass length/time^2)"},
    {"stress", Center::cell, 6, "force/length^2"},
    {"stress_bottom", Center::cell, 6, "force/length^2", true},
    {"stress_top", Center::cell, 6, "force/length^2", true},
    {"von_mises", Center::cell, 1, "force/length^2"},
    {"plastic_strain", Center::cell, 1, "dimensionless"},
    {"energy_density", Center::cell, 1, "energy/length^3 of reference volume"},
    {"part_id", Center::cell, 1, "deck *PART id", false, true, true},
    {"material_id", Center::cell, 1, "deck material id (*PART MID)", false, true, true},
    {"thickness", Center::cell, 1, "length", true, true},
    {"deleted", Center::cell, 1, "1: deleted by erosion, 0: not"},
    {"current_thickness", Center::cell, 1, "length (shells whose thickness changes: *CONTROL_SHELL ISTUPD)", true},
};
inline constexpr std::size_t kFieldCount = sizeof(kFields) / sizeof(kFields[0]);

/// The HDF5 group of state s's own datasets: /states/state_<s>.
std::string state_group(std::size_t s);

/// HDF5 path of field f: /states/state_<s>/<name> (nodal), /states/state_<s>/<cell_set>/<name>
/// (cells, per state) or /mesh/<cell_set>_<name> (cells, fixed).
std::string field_path(const Field& f, std::size_t state, std::string_view cell_set);

/// The cell grid of one topology.
struct Grid {
  const ElementTopology* topology;
  std::size_t count;
};

/// What the document describes: the HDF5 file name (relative to the XDMF file), node count, the
/// grids, and per state its time and which fields it holds (bit i: kFields[i]).
struct Layout {
  std::string h5;
  std::size_t nodes = 0;
  std::vector<Grid> grids;
  std::vector<Real> times;
  std::vector<std::uint32_t> fields;
};

/// The XDMF 3 document: a temporal collection of states, each a grid per topology (a spatial
/// collection when there are several) with the deformed geometry and every field it holds.
std::string document(const Layout& layout);

}  // namespace slideline::xdmf
