#pragma once
/// The axes of a local coordinate system (*DEFINE_COORDINATE_SYSTEM, _NODES, _VECTOR;
/// model/coordinate_system.hpp) at t = 0, as the builder and the model validation resolve them.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "slideline/core/types.hpp"
#include "slideline/model/model.hpp"

namespace slideline {

/// A resolved local system: `r`'s columns are the local x, y, z unit vectors in global
/// components (a proper rotation), so a vector given in the system is r * v_local.
struct LocalAxes {
  Mat3 r = Mat3::Identity();
  Vec3 origin = Vec3::Zero();
  const model::CoordinateSystem* system = nullptr;
};

/// The axes of system `cid` from the deck's nodes at t = 0. `user` names the card that refers to
/// it ("deck.k:12: *INITIAL_VELOCITY field ICID"). Throws InputError naming `user` and the
/// system's card when the deck does not define it, when its points, nodes or vectors do not span
/// a plane (coincident, collinear or zero), when a node it names is not defined, or when CIDL
/// chains loop.
LocalAxes local_axes(const model::Model& m, Id cid, const std::string& user);

/// The global components of local axis `a` of system `cid` (0: `a` itself, 1): the nonzero
/// entries of column a of the system's rotation, in axis order, as (global axis, direction
/// cosine). A load along a local axis is built as one load per entry.
std::vector<std::pair<Axis, Real>> global_components(const model::Model& m, Axis a, Id cid, const std::string& user);

/// When `r` maps each local axis onto a global axis (a signed permutation, to 1e-12), the global
/// axis of each local one; empty otherwise.
std::optional<std::array<int, 3>> axis_permutation(const Mat3& r);

}  // namespace slideline
