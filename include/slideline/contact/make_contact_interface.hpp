#pragma once
/// The one place that maps a resolved *CONTACT card (InterfaceSpec, interface_spec.hpp) to a
/// ContactAlgorithm class: src/contact/make_contact_interface.cpp dispatches on the DYNA3D type
/// and enforcement; each family of interfaces has its own factory file, which reads only the spec.
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "slideline/contact/contact_algorithm.hpp"
#include "slideline/contact/interface_spec.hpp"

namespace slideline {

class ContactErosion;
struct LagrangeContactSettings;

/// Contact with eroding parts (docs/contact_erosion.md), before make_contact_interface():
/// `eroding_part` holds, per internal node, the deck id of an eroding part that holds it (0:
/// none; empty: no part erodes). When a side of `spec` holds such a node: an interface that
/// updates its surfaces (the automatic penalty cards and *CONTACT_ERODING_...) gets the interior
/// faces of its sides' solids (InterfaceSpec::interior_faces) and spec.eroding; any other is
/// refused (NotImplementedError naming the card, the part and the cards that support it).
void prepare_eroding_contact(InterfaceSpec& spec, const ContactBuildContext& ctx, const std::vector<Id>& eroding_part);

/// A node-set slave side with eroding parts (SSTYP 4; docs/contact_erosion.md): the faces that
/// orient its nodes, the exterior faces of the parts its nodes lie on and every interior face of
/// their erodible solids (each once per owning element, as EROSOP = 1 adds them), so that a node
/// is oriented by the faces of the body as it is now.
Surface eroding_node_set_faces(const std::vector<Index>& nodes, const ContactBuildContext& ctx, const std::string& where);
/// Keeps each slave of a node set active while an element that holds it is live
/// (ContactErosion::set_slave_elements).
void set_node_set_slave_elements(ContactErosion& erosion, std::span<const Index> slaves, const ContactBuildContext& ctx);
/// ENMASS 1, 2 (*CONTROL_CONTACT): keeps each slave freed of all its elements in the contact as a
/// free mass, when one of them was a solid (1) or any (2) (ContactErosion::set_retained_nodes);
/// nothing for ENMASS 0.
void set_retained_slave_nodes(ContactErosion& erosion, std::span<const Index> slaves, const ContactBuildContext& ctx,
                              int enmass);

/// Builds the interface of a resolved card (resolve_interface); takes the spec's sides.
std::unique_ptr<ContactAlgorithm> make_contact_interface(InterfaceSpec& spec, const ContactBuildContext& ctx);

// Factories per family (one source file each, src/contact/make_*.cpp); each takes the spec's sides.
/// Types 3 (surface to surface) and 10 (one way), penalty.
std::unique_ptr<ContactAlgorithm> make_sliding_contact(InterfaceSpec& spec);
/// Types 2 (tied surfaces), 6 (tied nodes), 7 (tied shell edge): kinematic.
std::unique_ptr<ContactAlgorithm> make_tied_contact(InterfaceSpec& spec);
/// Type 1 (sliding only): kinematic.
std::unique_ptr<ContactAlgorithm> make_sliding_only_contact(InterfaceSpec& spec, const ContactBuildContext& ctx);
/// Lagrange-multiplier enforcement of Types 3, 5, 10, 12.
std::unique_ptr<ContactAlgorithm> make_lagrange_contact(InterfaceSpec& spec, const ContactBuildContext& ctx);
/// The dofs the deck holds on rigid bodies, for a Lagrange or Type 1 solve's rigid masters:
/// *MAT_RIGID CMO = 1 CON1 (translations) and CON2 (rotations), *BOUNDARY_PRESCRIBED_MOTION_RIGID
/// (driven dofs, while their drive acts); make_lagrange_contact.cpp.
void set_rigid_master_constraints(LagrangeContactSettings& s, const model::Model& model);
/// Types 5 (nodes to surface) and 12 (automatic): penalty.
std::unique_ptr<ContactAlgorithm> make_node_and_automatic_contact(InterfaceSpec& spec, const ContactBuildContext& ctx);
/// The LS-DYNA automatic cards of type family 12 (model::ContactForm other than dyna3d), penalty:
/// *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE, the automatic pass restricted to the cross pairs of its
/// two sides; *CONTACT_AUTOMATIC_NODES_TO_SURFACE and *CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE,
/// the automatic pass of the slave side's nodes on the master side's segments.
std::unique_ptr<ContactAlgorithm> make_automatic_surface_contact(InterfaceSpec& spec, const ContactBuildContext& ctx);
/// SOFT = 2 (segment-based contact, segment_contact.hpp) on *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE
/// (the cross pairs of its two sides) and *CONTACT_AUTOMATIC_SINGLE_SURFACE (every segment against
/// every other), solid faces and shells (offset by half their contact thickness).
std::unique_ptr<ContactAlgorithm> make_segment_contact(InterfaceSpec& spec);
/// Types 8 (nodes spotwelded: failure per node, NFLF/SFLF forces, NEN/MES exponents) and 9
/// (tied surfaces with failure: failure per slave segment, NFLF/SFLF stresses): penalty factor
/// SLSFAC x SFS; friction FS, FD, DC after failure.
std::unique_ptr<ContactAlgorithm> make_tiebreak_contact(InterfaceSpec& spec);
/// *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK (OPTION 2): Type 9's tie and failure law, then
/// the automatic surface-to-surface pass (automatic_tiebreak_contact.hpp); solid faces only.
std::unique_ptr<ContactAlgorithm> make_automatic_tiebreak_contact(InterfaceSpec& spec, const ContactBuildContext& ctx);

}  // namespace slideline
