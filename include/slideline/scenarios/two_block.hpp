#pragma once
/// The two-block problem of the DYNA3D contact verification report (../shared/spec), generated as a
/// model description. Geometry, materials, loads, curves and supports follow the spec digest;
/// the mesh is 3 elements per unit length in x and z on the upper block, 2 on the lower block,
/// 2 through y. The upper block sits at x in [x_offset, x_offset + 1], z in [0.01, 1.01], so no
/// upper node lies on a lower node or edge and it can slide 0.45 in +x without leaving.
#include <string>

#include "slideline/model/model.hpp"

namespace slideline::scenarios {

struct TwoBlockOptions {
  Real px = 3.1;          ///< applied force on the upper block along +x (spec P_x)
  Real py = 10.0;         ///< applied force on the upper block along -y (spec P_y, compression > 0)
  Real end_time = 0.5;
  Real x_offset = 0.03;   ///< upper block's left face
  Real origin_x = 0.0;    ///< shifts the whole pair (several pairs side by side in one deck)
  bool merged = false;    ///< one body: the lower mesh takes the upper block's grid lines and the
                          ///< interface nodes are shared (no contact needed)
  Real history_interval = 0.0025;
  Real state_interval = 0.05;
  Id first_id = 1;        ///< first node, element, part, set and curve id used
};

/// Node sets, parts and titles of a generated pair, for the caller to attach contacts or outputs.
struct TwoBlockIds {
  Id upper_part = 0, lower_part = 0;
  Id bottom_set = 0, right_set = 0;  ///< support node sets
  Id upper_bottom_nodes = 0;         ///< node set of the upper block's bottom face
  Id lower_top_nodes = 0;            ///< node set of the lower block's top face
  Id monitor_upper = 0, monitor_lower = 0;  ///< node pair near the centre of the contact area
};

/// Adds one solid-on-solid pair to `model` (materials, sections, curves, loads, damping and
/// controls are added once, on the first call) and returns its ids.
TwoBlockIds add_solid_pair(model::Model& model, const TwoBlockOptions& options);

/// A complete model: one solid pair with the spec's controls.
model::Model make_solid_pair_model(const TwoBlockOptions& options);

}  // namespace slideline::scenarios
