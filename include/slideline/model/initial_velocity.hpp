#pragma once
/// The *INITIAL_VELOCITY family of keyword cards, as the deck gives them (ids, LS-DYNA field
/// names and defaults). The three cards are one family: build_simulation turns all of them into
/// the nodal velocities at t = 0 (see docs/keywords.md for the semantics and what is refused).
/// Like elements, they locate themselves by line and file index (model::element_source): a deck
/// can give thousands of *INITIAL_VELOCITY_NODE cards.
#include "slideline/core/types.hpp"
#include "slideline/model/source.hpp"

namespace slideline::model {

/// *INITIAL_VELOCITY_NODE: one node's translational (VX VY VZ) and rotational (VXR VYR VZR)
/// velocity. Rotational components act on nodes that carry rotations (shell nodes) only.
struct InitialVelocityNode {
  Id nid = 0;
  Vec3 v = Vec3::Zero();   ///< length/time
  Vec3 vr = Vec3::Zero();  ///< rad/time
  Id icid = 0;             ///< local coordinate system of the velocities (0: global)
  CardLine at;             ///< where the card is, for messages (model::element_source)
  bool operator==(const InitialVelocityNode&) const = default;
};

/// *INITIAL_VELOCITY: the velocity of every node of node set NSID (0 = all nodes), restricted to
/// box BOXID when given; the nodes of NSIDEX take the exempted velocities VXE..VZRE instead.
struct InitialVelocity {
  Id nsid = 0;
  Id nsidex = 0;
  Id boxid = 0;
  int irigid = 0;  ///< overwrite *PART_INERTIA velocities: no effect here (see docs/keywords.md)
  Id icid = 0;     ///< local coordinate system of the velocities, translational and rotational (0: global)
  Vec3 v = Vec3::Zero();
  Vec3 vr = Vec3::Zero();
  Vec3 ve = Vec3::Zero();   ///< exempted nodes (card 3, with NSIDEX > 0)
  Vec3 vre = Vec3::Zero();
  CardLine at;
  bool operator==(const InitialVelocity&) const = default;
};

/// *INITIAL_VELOCITY_GENERATION: a rigid motion v = V + OMEGA n x (x - xc) (and rotational
/// velocity OMEGA n on nodes that carry rotations) of a part set (STYP 1), a part (2) or a node
/// set (3); ID = 0 gives it to every node.
struct InitialVelocityGeneration {
  Id id = 0;
  int styp = 0;
  Real omega = 0.0;  ///< angular velocity about the axis, rad/time
  Vec3 v = Vec3::Zero();
  int ivatn = 0;     ///< slave parts/nodes of constrained rigid bodies (not implemented)
  Id icid = 0;       ///< local coordinate system of VX VY VZ (0: global; not with OMEGA)
  Vec3 xc = Vec3::Zero();  ///< a point on the rotation axis
  Vec3 n = Vec3::Zero();   ///< axis direction (normalised by the builder)
  int phase = 0;     ///< 1 = after dynamic relaxation (not implemented)
  int irigid = 0;    ///< overwrite *PART_INERTIA velocities: no effect here
  CardLine at;
  bool operator==(const InitialVelocityGeneration&) const = default;
};

}  // namespace slideline::model
