#pragma once
// Internal interface between the sslide problem table (sslide_problems.cpp) and the pairing
// geometry (sslide_pairings.cpp).
#include <string>

#include "block_mesh.hpp"
#include "slideline/scenarios/sslide.hpp"

namespace slideline::scenarios::detail {

/// Ids of the cards every pairing shares (materials, sections, hourglass cards, loaded part set).
struct SslideCommonIds {
  Id solid_material = 0, shell_material = 0, rigid_material = 0;
  Id solid_section = 0, shell_section = 0;
  Id solid_hourglass = 0, shell_hourglass = 0;
  Id loaded_parts = 0;  ///< part set of every upper body (*LOAD_BODY_PARTS)
};

/// What a pairing is made of.
struct SslidePairingRequest {
  std::string name;
  Real x0 = 0.0;           ///< lower block's left face
  Real cells = 1.0;        ///< unit cells in z
  Real gap = 0.0;          ///< upper contact surface height above y = 1
  bool upper_shell = false;  ///< the upper body is the 3 x 3 shell plate (else the solid block)
  bool upper_edge_plate = false;  ///< the upper body is a plate in the y-z plane (type 7)
  bool skin = false;         ///< shells on the lower block's top face form the master surface
  bool rigid_skin = false;   ///< the skin shells are rigid (sslide10lr shell-on-shell)
  Real px = 0.0, py = 0.0;   ///< load magnitudes carried by this pairing
};

/// Sets a contact can refer to.
struct SslidePairingSets {
  Id upper_segments = 0;  ///< segment set: upper block's bottom face (outward normal -y); solid only
  Id lower_segments = 0;  ///< segment set: lower block's top face (outward normal +y)
  Id upper_nodes = 0;     ///< node set: the upper body's contact nodes (plate nodes or plate edge)
  Id contact_parts = 0;   ///< part set: the upper body and the master-surface part (type 12)
};

/// Mesh writer and id counters of a model under construction.
struct SslideIds {
  MeshWriter mesh;
  Id next_part = 1;
  Id next_set = 1;
};

/// Adds one pairing (parts, mesh, supports, sets, monitor and its history nodes) to `m`.
SslidePairing add_sslide_pairing(model::Model& m, const SslideCommonIds& common, SslideIds& ids,
                                 const SslidePairingRequest& request, SslidePairingSets& sets);

}  // namespace slideline::scenarios::detail
