#pragma once
/// *DEFINE_COORDINATE_SYSTEM, *DEFINE_COORDINATE_NODES and *DEFINE_COORDINATE_VECTOR: a local
/// Cartesian system, as the deck gives it (points, nodes or vectors). The builder resolves it to
/// its axes (solver/coordinate_axes.hpp) where a card names it: the velocities of *INITIAL_VELOCITY
/// (ICID), *INITIAL_VELOCITY_GENERATION (ICID) and *INITIAL_VELOCITY_NODE (ICID), the direction of
/// *LOAD_NODE (CID) and *LOAD_BODY (CID), the constrained directions of *BOUNDARY_SPC (CID).
/// docs/keywords.md, "Local coordinate systems".
#include <array>
#include <string>

#include "slideline/core/types.hpp"
#include "slideline/model/source.hpp"

namespace slideline::model {

struct CoordinateSystem {
  /// Which card: SYSTEM (three points), NODES (three nodes), VECTOR (two vectors).
  enum class Kind : std::uint8_t { points, nodes, vectors };
  Id cid = 0;
  std::string title;
  Kind kind = Kind::points;
  /// points: X0 Y0 Z0 (origin), XL YL ZL (a point on the local x axis), XP YP ZP (a point in the
  /// local x-y plane), in system CIDL (0: global). vectors: `axis` = XX YX ZX (the local x axis),
  /// `plane` = XV YV ZV (a vector in the local x-y plane).
  Vec3 origin = Vec3::Zero();
  Vec3 axis = Vec3::Zero();
  Vec3 plane = Vec3::Zero();
  Id cidl = 0;
  /// nodes: N1 (origin), N2 (on the axis DIR), N3 (in the plane of DIR and the next axis);
  /// vectors: nodes[0] = NID, a node the system would rotate with (0: fixed).
  std::array<Id, 3> nodes{};
  /// nodes: FLAG = 1 moves the system with its nodes each step; 0 fixed at t = 0.
  int flag = 0;
  /// nodes: DIR, the axis along N1 -> N2: 0 x (blank, X), 1 y, 2 z. N3 then lies in the plane of
  /// that axis and the next one (x-y, y-z, z-x).
  int dir = 0;
  Source src;
  /// Whether the system moves with nodes during the run (NODES FLAG = 1, VECTOR NID != 0).
  bool moves() const {
    return (kind == Kind::nodes && flag != 0) || (kind == Kind::vectors && nodes[0] != 0);
  }
  bool operator==(const CoordinateSystem&) const = default;
};

}  // namespace slideline::model
