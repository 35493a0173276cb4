#pragma once
/// The one place that maps a deck's *CONTACT card to a ContactAlgorithm class
/// (src/contact/make_contact_interface.cpp dispatches on the DYNA3D type; each family of
/// interfaces has its own factory file).
#include <memory>
#include <string>
#include <vector>

#include "slideline/contact/contact_algorithm.hpp"
#include "slideline/mesh/mesh_sets.hpp"
#include "slideline/mesh/surface.hpp"
#include "slideline/model/model.hpp"

namespace slideline {

class ElementBlock;

/// What a factory may use: the card, the deck's contact controls, and the built mesh (element
/// blocks with their masses lumped is NOT guaranteed: factories build geometry only; mass-dependent
/// data belongs in ContactAlgorithm::initialize).
struct ContactBuildContext {
  const model::Model& model;
  const std::vector<std::unique_ptr<ElementBlock>>& blocks;
  const NodalFields& nodes;
  const MeshSets& sets;
};

/// One side of an interface as the card's SSID/SSTYP (or MSID/MSTYP) select it.
struct ContactSide {
  Surface surface;            ///< segments (empty for a node-set side)
  std::vector<Index> nodes;   ///< the side's nodes: the surface's nodes, or the node set
  std::vector<Id> parts;      ///< the parts the side was selected by (empty for sets)
};

/// Resolves SSID/SSTYP (slave = true) or MSID/MSTYP of `card` into a side. Set types (LS-DYNA):
/// 0 segment set, 1 shell element set (not supported), 2 part set, 3 part id, 4 node set
/// (slave side only), 5 all parts. Throws InputError naming the card's file:line and field.
ContactSide resolve_contact_side(const model::Contact& card, bool slave, const ContactBuildContext& ctx);

/// The faces that orient the nodes of a node-set slave side (Type 5; search/slave_orientation.hpp):
/// the exterior faces of every part that holds one of `nodes` (faces shared by two such parts
/// are interior and left out), adjacency built; empty when no part holds them. Allocates.
Surface node_set_faces(const std::vector<Index>& nodes, const ContactBuildContext& ctx, const std::string& context);

/// The interface title: the card's heading, else "contact_<cid>", else "contact_<k>" (k = the
/// card's position among the deck's contacts, from 1).
std::string contact_title(const model::Contact& card, std::size_t position);

/// Builds the interface for a card. Throws NotImplementedError (naming the card and its line) for
/// a type or enforcement this version does not run, InputError for a bad reference or value.
std::unique_ptr<ContactAlgorithm> make_contact_interface(const model::Contact& card, std::size_t position,
                                                         const ContactBuildContext& ctx);

// Factories per family (one source file each, src/contact/make_*.cpp).
/// Types 3 (surface to surface) and 10 (one way), penalty.
std::unique_ptr<ContactAlgorithm> make_sliding_contact(const model::Contact& card, const std::string& title,
                                                       const ContactBuildContext& ctx);
/// Types 2 (tied surfaces), 6 (tied nodes), 7 (tied shell edge): kinematic.
std::unique_ptr<ContactAlgorithm> make_tied_contact(const model::Contact& card, const std::string& title,
                                                    const ContactBuildContext& ctx);
/// Type 1 (sliding only): kinematic.
std::unique_ptr<ContactAlgorithm> make_sliding_only_contact(const model::Contact& card, const std::string& title,
                                                            const ContactBuildContext& ctx);
/// Lagrange-multiplier enforcement of Types 3, 5, 10, 12.
std::unique_ptr<ContactAlgorithm> make_lagrange_contact(const model::Contact& card, const std::string& title,
                                                        const ContactBuildContext& ctx);
/// Types 5 (nodes to surface), 8 (tiebreak nodes), 9 (tiebreak surface), 12 (automatic): penalty.
std::unique_ptr<ContactAlgorithm> make_node_and_automatic_contact(const model::Contact& card,
                                                                  const std::string& title,
                                                                  const ContactBuildContext& ctx);

/// "<file:line>: <keyword> (DYNA3D type N[, enforcement]) is not implemented yet": the
/// NotImplementedError a factory throws for what it does not run.
[[noreturn]] void throw_contact_not_implemented(const model::Contact& card, const std::string& what = {});

}  // namespace slideline
