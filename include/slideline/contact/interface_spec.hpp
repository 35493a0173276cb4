#pragma once
/// InterfaceSpec: a *CONTACT card resolved once, for every interface family (penalty, Lagrange,
/// tiebreak, kinematic ties). resolve_interface() checks that the (type, enforcement, options)
/// combination runs here, resolves both sides to surfaces and nodes, and turns the card's fields
/// into the values the families consume: one shell offset rule per side (shell_offset.hpp), the
/// nodal radius, one friction law, the stiffness factors, the tiebreak failure data, birth and
/// death, and the outputs. The factories (src/contact/make_*.cpp) read the spec, never the card.
/// docs/architecture.md, "The contact pipeline".
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "slideline/contact/contact_manager.hpp"
#include "slideline/contact/friction/exponential_coulomb.hpp"
#include "slideline/contact/shell_offset.hpp"
#include "slideline/mesh/mesh_sets.hpp"
#include "slideline/mesh/surface.hpp"
#include "slideline/model/model.hpp"

namespace slideline {

class ElementBlock;

/// What resolution may use: the card, the deck's contact controls, and the built mesh (element
/// blocks with their masses lumped is NOT guaranteed: resolution builds geometry only;
/// mass-dependent data belongs in ContactAlgorithm::initialize).
struct ContactBuildContext {
  const model::Model& model;
  const std::vector<std::unique_ptr<ElementBlock>>& blocks;
  const NodalFields& nodes;
  const MeshSets& sets;
  /// Per node, the translational axes (bit a for axis a) a support without a curve holds for the
  /// whole run (the builder's: for ISYM = 1 of the eroding cards, faces on symmetry planes);
  /// empty when the caller has none to give.
  std::span<const std::uint8_t> held_axes = {};
};

/// One side of an interface as the card's SSID/SSTYP (or MSID/MSTYP) select it.
struct ContactSide {
  Surface surface;            ///< segments (empty for a node-set side)
  std::vector<Index> nodes;   ///< the side's nodes: the surface's nodes, or the node set
  std::vector<Id> parts;      ///< the parts the side was selected by (empty for sets)
};

/// Tiebreak failure (Types 8 and 9; unused by the other types).
struct TiebreakFailure {
  Real normal = 0.0;    ///< NFLF: force (Type 8) or stress (Type 9); <= 0: no normal failure
  Real shear = 0.0;     ///< SFLF: likewise
  Real normal_exponent = 2.0;  ///< NEN (Type 8; Type 9 uses 2)
  Real shear_exponent = 2.0;   ///< MES (Type 8; Type 9 uses 2)
};

/// The cohesive law of *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK (card 4 after NFLS, SFLS).
struct TiebreakCohesive {
  int option = 0;      ///< OPTION: 2 the stress criterion; 6 its linear softening to CCRIT; 9 the mixed-mode law
  Real param = 0.0;    ///< OPTION 9: mixing exponent (> 0 power law, < 0 B-K; 0 means 1); OPTION 6: CCRIT
  Real eraten = 0.0;   ///< OPTION 9: mode I energy release rate
  Real erates = 0.0;   ///< OPTION 9: mode II energy release rate
  Real ct2cn = 0.0;    ///< OPTION 9: tangential / normal stiffness (0 means 1)
  Real cn = 0.0;       ///< OPTION 9: normal stiffness per unit area (0: the penalty stiffness)
};

/// A card resolved: everything a family's factory needs.
struct InterfaceSpec {
  std::string title;  ///< output title (contact_title)
  std::string where;  ///< "<file:line>: <keyword>": the start of every message about the card
  model::ContactType type = model::ContactType::surface_to_surface;
  model::Enforcement enforcement = model::Enforcement::penalty;
  /// The LS-DYNA card of the type family (an automatic card without a DYNA3D number).
  model::ContactForm form = model::ContactForm::dyna3d;

  ContactSide slave;
  /// The master side; for Type 12 with MSID = 0 (single surface) a copy of the slave side.
  ContactSide master;
  bool single_surface = false;  ///< Type 12 with MSID = 0: every node against every segment
  bool node_set_slaves = false; ///< SSTYP = 4: the slaves are a node set (no slave surface)

  /// Shell offsets: on for Type 12 or *CONTROL_CONTACT SHLTHK > 0; thickness SST / MST, scale
  /// SFST / SFMT; a single surface takes SST / SFST for both.
  ShellOffsetRule slave_shells, master_shells;
  /// *CONTROL_CONTACT THKCHG = 1 on an automatic card (type family 12, penalty): the shell offsets
  /// follow the shells' current thickness every cycle (FollowedOffsets, shell_offset.hpp); the
  /// other cards keep the thickness of the first cycle, as LS-DYNA's.
  bool follow_thickness = false;
  /// Offset of node-set slaves (Type 5; length): RADIUS, else half SST x SFST (0 for SST = 0).
  Real nodal_radius = 0.0;

  /// FS, FD (FS when FD is 0), DC; mu_s = mu_k = 0 means frictionless.
  ExponentialCoulomb friction;
  bool frictional() const { return friction.mu_s > 0.0 || friction.mu_k > 0.0; }

  Real slave_stiffness = 0.1;   ///< SLSFAC x SFS: the pass whose slaves are the card's slaves
  Real master_stiffness = 0.1;  ///< SLSFAC x SFM: Type 3's reverse pass

  bool sliding_only = false;    ///< Type 10 _SLIDING_ONLY: no separation once in contact
  /// VDC / 100: viscous contact damping, fraction of each penalty pair's critical damping
  /// (Types 3, 5, 10, 12 penalty; the reader refuses VDC elsewhere).
  Real viscous_damping = 0.0;
  /// IGNORE 1 or 2 (the card's optional card C, else *CONTROL_CONTACT card 4): penalty interfaces
  /// keep initial penetrations as their springs' zero instead of moving the nodes out.
  bool keep_initial_penetrations = false;
  bool mortar_coupling = false; ///< _MORTAR (model::Contact::penalty_coupling 1): penalty and Lagrange
  /// SOFT = 1: SOFSCL (the soft-constraint stiffness scale, PenaltyPassOptions::soft_scale); 0 for
  /// SOFT = 0 (penalty Types 3, 5, 10, 12; the reader refuses SOFT elsewhere).
  Real soft_scale = 0.0;
  /// SOFT = 2: segment-based contact (contact/segment_contact.hpp; the two-sided automatic card only).
  bool segment_based = false;
  /// SOFT = 2: BSORT, cycles between broad-phase searches (0: SegmentContact's default).
  int search_interval = 0;
  /// VC (stress): the friction of each slave node capped at VC x its master segment's area
  /// (penalty Types 3, 5, 10, 12 with friction; the reader refuses VC elsewhere).
  Real viscous_friction = 0.0;
  /// PENCHK = 1: XPENE (*CONTROL_CONTACT), PenaltyPassOptions::penetration_check; 0 for PENCHK = 0.
  Real penetration_check = 0.0;
  TiebreakFailure failure;
  TiebreakCohesive cohesive;
  ContactWindow window;         ///< BT, DT (honoured by ContactManager for every type)
  /// Type 12: write interfaces/<title>/transmitted_force (the force between its parts).
  bool transmitted_output = false;
  /// Contact with eroding parts (docs/contact_erosion.md). eroding_card: a *CONTACT_ERODING_...
  /// card; interior_faces: interior faces become surface as the elements in front of them are
  /// deleted (every automatic card, and EROSOP = 1), else only the exterior faces, each dropped
  /// with its element (EROSOP = 0); eroding: set by prepare_eroding_contact() when a side holds an
  /// eroding part (the factories then attach a ContactErosion to the pass).
  bool eroding_card = false;
  bool interior_faces = true;
  /// IADJ = 1 with EROSOP = 0: of the interior faces, only those between two parts (the boundary
  /// of each part's subset of the mesh).
  bool interior_faces_between_parts_only = false;
  /// ISYM = 1 of the eroding cards: the solid faces on a symmetry plane (every node held in the
  /// direction of the face's normal) are left out of both sides (prepare_eroding_contact).
  bool symmetry_faces_out = false;
  bool eroding = false;
  /// ENMASS of *CONTROL_CONTACT: 0 a node freed of all its elements leaves the contact; 1 (its
  /// elements included a solid) and 2 (any) it stays as a free mass (set_retained_slave_nodes).
  int enmass = 0;
  /// SNLOG of optional card B (1: the shooting-node logic off): refused by
  /// prepare_eroding_contact() on a pass with an eroding part, whose sudden-penetration rule is
  /// that logic; nothing to act on elsewhere.
  int snlog = 0;
};

/// Resolves `card` (the `position`-th contact of the deck, from 1). Throws NotImplementedError
/// (naming the card's file:line) for a combination this version does not run, InputError for a
/// bad reference or value.
InterfaceSpec resolve_interface(const model::Contact& card, std::size_t position, const ContactBuildContext& ctx);

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

/// The card's friction law (FS, FD, DC); InputError when one is negative.
ExponentialCoulomb contact_friction(const model::Contact& card);

/// Per slave node of `side` (one per side.nodes entry): its shell offset under `rule`, at least
/// `radius` (length). A node-set side has no surface: every node gets `radius`.
std::vector<Real> slave_node_offsets(const ContactSide& side, const ShellOffsetRule& rule, Real radius);

/// "<file:line>: <keyword> (DYNA3D type N[, enforcement]) is not implemented yet": the
/// NotImplementedError thrown for what this version does not run.
[[noreturn]] void throw_contact_not_implemented(const model::Contact& card, const std::string& what = {});

}  // namespace slideline
