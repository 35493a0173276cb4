#pragma once
/// The model description: what a keyword deck says, card by card, with LS-DYNA's field names and
/// semantics (ids, not indices; LS-DYNA sign conventions). The keyword reader fills it, the writer
/// writes it back out, the scenarios generate it, and `build_simulation` turns it into the runtime
/// state (dense arrays, internal indices, physical sign conventions).
/// Units are whatever consistent set the deck uses (the spec's problems are unitless).
/// A field left blank in a deck keeps the default given here, which is LS-DYNA's default.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "slideline/core/types.hpp"
#include "slideline/model/coordinate_system.hpp"
#include "slideline/model/initial_velocity.hpp"
#include "slideline/model/materials.hpp"
#include "slideline/model/source.hpp"

namespace slideline::model {

struct Node {
  Id id = 0;
  Vec3 x = Vec3::Zero();
  int tc = 0;  ///< translational constraint code (0 = free)
  int rc = 0;  ///< rotational constraint code (0 = free)
  bool operator==(const Node&) const = default;
};

/// *ELEMENT_SOLID: 8-node hexahedron, LS-DYNA node ordering (bottom face 1-4, top face 5-8).
struct SolidElement {
  Id id = 0;
  Id pid = 0;
  std::array<Id, 8> n{};
  CardLine at;  ///< where the card is, for messages (model::element_source)
  bool operator==(const SolidElement&) const = default;
};

/// *ELEMENT_SHELL: 4-node quadrilateral, or a 3-node triangle written with n3 == n4.
struct ShellElement {
  Id id = 0;
  Id pid = 0;
  std::array<Id, 4> n{};
  CardLine at;  ///< where the card is, for messages (model::element_source)
  bool operator==(const ShellElement&) const = default;
};

/// *PART
struct Part {
  Id pid = 0;
  std::string title;
  Id secid = 0;
  Id mid = 0;
  Id eosid = 0;
  Id hgid = 0;  ///< 0 = use *CONTROL_HOURGLASS
  Source src;
  bool operator==(const Part&) const = default;
};

/// *SECTION_SOLID
struct SectionSolid {
  Id secid = 0;
  int elform = 1;  ///< 1 (0) one-point hexahedron, 2 selective-reduced hexahedron, 10 tetrahedron
  Source src;
  bool operator==(const SectionSolid&) const = default;
};

/// *SECTION_SHELL
struct SectionShell {
  Id secid = 0;
  int elform = 2;      ///< 2 (0) Belytschko-Tsay (C0 triangles where n3 == n4), 4 C0 triangles
  Real shrf = 1.0;     ///< transverse shear factor (LS-DYNA default 1.0; 5/6 is usual)
  int nip = 2;         ///< through-thickness integration points
  Real propt = 1.0;
  std::array<Real, 4> t{0.0, 0.0, 0.0, 0.0};  ///< nodal thicknesses (t2..t4 default to t1)
  Source src;
  bool operator==(const SectionShell&) const = default;
};

/// *HOURGLASS
struct Hourglass {
  Id hgid = 0;
  int ihq = 1;     ///< 1,2 = Flanagan-Belytschko viscous; 10 = total-displacement physical stiffness
  Real qm = 0.1;   ///< hourglass coefficient
  Real q1 = 1.5;   ///< quadratic bulk viscosity (per part)
  Real q2 = 0.06;  ///< linear bulk viscosity (per part)
  Source src;
  bool operator==(const Hourglass&) const = default;
};

/// *CONTROL_HOURGLASS
struct ControlHourglass {
  int ihq = 1;
  Real qh = 0.1;
  bool operator==(const ControlHourglass&) const = default;
};

/// *CONTROL_BULK_VISCOSITY
struct ControlBulkViscosity {
  Real q1 = 1.5;   ///< quadratic coefficient
  Real q2 = 0.06;  ///< linear coefficient
  bool operator==(const ControlBulkViscosity&) const = default;
};

/// *SET_NODE_LIST
struct NodeSet {
  Id sid = 0;
  std::string title;
  std::vector<Id> nodes;
  Source src;
  bool operator==(const NodeSet&) const = default;
};

/// *SET_SEGMENT: each segment lists 4 node ids (n3 == n4 for a triangle).
struct SegmentSet {
  Id sid = 0;
  std::string title;
  std::vector<std::array<Id, 4>> segments;
  Source src;
  bool operator==(const SegmentSet&) const = default;
};

/// *SET_PART_LIST
struct PartSet {
  Id sid = 0;
  std::string title;
  std::vector<Id> parts;
  Source src;
  bool operator==(const PartSet&) const = default;
};

/// *LOAD_NODE_POINT (one node) / *LOAD_NODE_SET (`set`: every node of a node set): a
/// concentrated force (DOF 1-3) or moment (DOF 5-7) of SF x curve LCID on each node.
struct LoadNode {
  bool set = false;
  Id id = 0;  ///< NID, or NSID when `set`
  int dof = 0;
  Id lcid = 0;
  Real sf = 1.0;
  Id cid = 0;
  std::array<Id, 3> m{0, 0, 0};  ///< M1 M2 M3 (follower loads, DOF 4 and 8)
  Source src;
  bool operator==(const LoadNode&) const = default;
};

/// *BOUNDARY_SPC_SET: fixed degrees of freedom (1 = fixed) of every node of a node set;
/// *BOUNDARY_SPC_NODE (`node`): of one node.
struct BoundarySpc {
  Id id = 0;           ///< from the _ID option; 0 if absent
  std::string title;   ///< heading from the _ID option
  Id nsid = 0;         ///< node set id, or the node id when `node`
  Id cid = 0;
  std::array<int, 6> dof{0, 0, 0, 0, 0, 0};  ///< DOFX DOFY DOFZ DOFRX DOFRY DOFRZ
  Source src;
  bool node = false;   ///< *BOUNDARY_SPC_NODE (last, so that {id, title, nsid, ...} still reads)
  bool operator==(const BoundarySpc&) const = default;
};

/// *BOUNDARY_PRESCRIBED_MOTION_SET / _NODE / _RIGID: prescribed motion of a node set, a node or a
/// rigid part in one direction.
struct PrescribedMotion {
  /// The card's option: what the first field names.
  enum class Target : std::uint8_t { set, node, rigid };
  Id id = 0;
  std::string title;
  Id nsid = 0;     ///< the first field: NSID (_SET), NID (_NODE) or PID (_RIGID), see `target`
  int dof = 1;     ///< 1 x, 2 y, 3 z; 5-7 rotations about x, y, z (rigid parts only)
  int vad = 0;     ///< 0 velocity (LS-DYNA's default), 1 acceleration, 2 displacement
  Id lcid = 0;     ///< curve of the prescribed quantity against time
  Real sf = 1.0;   ///< curve scale factor
  Id vid = 0;
  Real death = 1e28;
  Real birth = 0.0;
  Source src;
  Target target = Target::set;
  /// The keyword without _ID, for messages.
  const char* keyword() const {
    return target == Target::set    ? "*BOUNDARY_PRESCRIBED_MOTION_SET"
           : target == Target::node ? "*BOUNDARY_PRESCRIBED_MOTION_NODE"
                                    : "*BOUNDARY_PRESCRIBED_MOTION_RIGID";
  }
  bool operator==(const PrescribedMotion&) const = default;
};

/// *LOAD_BODY_X / _Y / _Z: base acceleration. LS-DYNA semantics: a positive value gives inertial
/// forces in the negative direction (force on a node = -m * sf * curve(t) along the axis).
struct LoadBody {
  Axis axis = Axis::x;
  Id lcid = 0;
  Real sf = 1.0;
  Id lciddr = 0;
  Real xc = 0.0, yc = 0.0, zc = 0.0;
  Id cid = 0;
  Source src;
  bool operator==(const LoadBody&) const = default;
};

/// *LOAD_BODY_PARTS: the part set that *LOAD_BODY_X/Y/Z act on (all parts when absent).
struct LoadBodyParts {
  Id psid = 0;
  Source src;
  bool operator==(const LoadBodyParts&) const = default;
};

/// *DEFINE_BOX: an axis-aligned box [XMN, XMX] x [YMN, YMX] x [ZMN, ZMX] (contact SBOXID / MBOXID).
struct Box {
  Id boxid = 0;
  std::string title;
  std::array<Real, 3> min{0.0, 0.0, 0.0};
  std::array<Real, 3> max{0.0, 0.0, 0.0};
  Source src;
  bool operator==(const Box&) const = default;
};

/// *DEFINE_CURVE: y = SFO * f((t - OFFA) / SFA) + OFFO, piecewise linear, constant outside.
struct Curve {
  Id lcid = 0;
  std::string title;
  int sidr = 0;
  Real sfa = 1.0;
  Real sfo = 1.0;
  Real offa = 0.0;
  Real offo = 0.0;
  int dattyp = 0;
  std::vector<std::pair<Real, Real>> points;
  Source src;
  bool operator==(const Curve&) const = default;
};

/// *DAMPING_GLOBAL: mass-proportional damping, force = -VALDMP * m * v (VALDMP in 1/time).
struct DampingGlobal {
  Id lcid = 0;       ///< curve of the damping constant against time (0 = constant VALDMP)
  Real valdmp = 0.0;
  std::array<Real, 6> stf{0, 0, 0, 0, 0, 0};  ///< STX..SRZ scale factors (0 = 1)
  Source src;
  bool operator==(const DampingGlobal&) const = default;
};

/// *DAMPING_PART_MASS[_SET]: mass-proportional damping of one part (or of the parts of a part set
/// with _SET). FLAG = 1 adds a card of per-direction scale factors STX..SRZ.
struct DampingPartMass {
  Id pid = 0;  ///< part id, or part set id when `set`
  Id lcid = 0;
  Real sf = 1.0;
  int flag = 0;
  bool set = false;
  std::array<Real, 6> stf{0, 0, 0, 0, 0, 0};  ///< STX..SRZ (read when FLAG = 1)
  Source src;
  bool operator==(const DampingPartMass&) const = default;
};

/// *DAMPING_PART_STIFFNESS[_SET]: stiffness-proportional (Rayleigh) damping of one part (or of
/// each part of a part set with _SET). COEF < 0: beta = -COEF (time), the classical coefficient
/// of LS-DYNA 950 (damping stress beta C : D); COEF > 0: LS-DYNA's approximate fraction of
/// critical damping at high frequencies (not implemented); 0: off.
struct DampingPartStiffness {
  Id pid = 0;         ///< PID, or PSID with _SET
  Real coef = 0.0;
  bool set = false;   ///< the _SET option: pid is a part set id
  Source src;
  bool operator==(const DampingPartStiffness&) const = default;
};

/// *CONTROL_TERMINATION
struct ControlTermination {
  Real endtim = 0.0;
  int endcyc = 0;
  /// Stop when the step falls below DTMIN x the first step. LS-DYNA's blank/0 means no limit;
  /// slideline then uses 1e-4 (a collapsing step is an instability, not a reason to run forever).
  Real dtmin = 0.0;
  /// ENDENG: stop (instability, exit 4) when the energy balance error passes ENDENG percent of
  /// the largest energy in play. LS-DYNA's field is a change of the energy ratio in percent; blank
  /// or 0 keeps slideline's default of 5%.
  Real endeng = 0.0;
  /// ENDMAS: mass scaling (DT2MS) may add at most ENDMAS percent of the model's mass: more at the
  /// start refuses the run; more later (MS1ST = 0, mass re-scaled every cycle) stops it as DTMIN
  /// does. 0 or blank: LS-DYNA's default 1e8, no limit.
  Real endmas = 1e8;
  Source src;
  bool operator==(const ControlTermination&) const = default;
};

/// *CONTROL_TIMESTEP
struct ControlTimestep {
  Real dtinit = 0.0;
  Real tssfac = 0.9;  ///< time-step scale factor
  int isdo = 0;
  Real tslimt = 0.0;  ///< TSLIMT (shell moduli lowered below this step): refused when not 0
  /// Mass scaling (docs/solver.md, "Mass scaling"): < 0 the elements whose stable step is below
  /// |DT2MS| get the mass that makes it |DT2MS|; > 0 every deformable element's mass is scaled so
  /// that its step is DT2MS (mass added or removed). The run's step is then TSSFAC x |DT2MS|.
  Real dt2ms = 0.0;
  Id lctm = 0;
  /// MS1ST: 1 mass scaling at the first step only; 0 (LS-DYNA's default, blank) re-evaluates it
  /// every cycle from the elements' current steps (solver/mass_rescaling.hpp; docs/solver.md).
  int ms1st = 0;
  /// ERODE: 1 deletes the solids whose step falls below TSMIN = DTMIN (of *CONTROL_TERMINATION)
  /// x the first step instead of stopping the run (docs/solver.md, "Failure and erosion").
  int erode = 0;
  Source src;
  bool operator==(const ControlTimestep&) const = default;
};

/// *CONTROL_CONTACT (card 1 fields used here)
struct ControlContact {
  Real slsfac = 0.1;  ///< default penalty scale factor
  Real rwpnal = 0.0;
  int islchk = 1;
  int shlthk = 0;     ///< 0 = ignore shell thickness in non-automatic contacts; 1,2 = include
  int penopt = 1;
  int thkchg = 0;
  int orien = 1;
  int enmass = 0;
  int ignore = 0;     ///< card 4: initial penetrations 0 moved out, 1 and 2 kept as the springs' zero
  Real xpene = 4.0;   ///< card 2: PENCHK = 1 releases nodes deeper than XPENE x segment thickness
  bool operator==(const ControlContact&) const = default;
};

/// Output cadences (*DATABASE_...). 0 = not written.
struct DatabaseControl {
  Real rcforc = 0.0;   ///< interface forces
  Real spcforc = 0.0;  ///< support reactions
  Real nodout = 0.0;   ///< node histories
  Real glstat = 0.0;   ///< energies
  Real d3plot = 0.0;   ///< nodal states (deformed mesh)
  std::vector<Id> history_nodes;  ///< *DATABASE_HISTORY_NODE
  bool operator==(const DatabaseControl&) const = default;
};

/// The DYNA3D interface types of the verification report, mapped to LS-DYNA contact cards.
enum class ContactType : std::uint8_t {
  sliding_only = 1,            ///< *CONTACT_SLIDING_ONLY
  tied_surface = 2,            ///< *CONTACT_TIED_SURFACE_TO_SURFACE
  surface_to_surface = 3,      ///< *CONTACT_SURFACE_TO_SURFACE
  nodes_to_surface = 5,        ///< *CONTACT_NODES_TO_SURFACE
  tied_nodes = 6,              ///< *CONTACT_TIED_NODES_TO_SURFACE
  tied_shell_edge = 7,         ///< *CONTACT_TIED_SHELL_EDGE_TO_SURFACE
  tiebreak_nodes = 8,          ///< *CONTACT_TIEBREAK_NODES_TO_SURFACE
  tiebreak_surface = 9,        ///< *CONTACT_TIEBREAK_SURFACE_TO_SURFACE
  one_way = 10,                ///< *CONTACT_ONE_WAY_SURFACE_TO_SURFACE
  automatic = 12,              ///< *CONTACT_AUTOMATIC_SINGLE_SURFACE / _GENERAL
};

enum class Enforcement : std::uint8_t { kinematic, penalty, lagrange };

/// Which LS-DYNA card of a DYNA3D type family a contact is (LS-DYNA's automatic cards have no
/// DYNA3D number: they run as the family whose pass they reuse, docs/contact.md, "Automatic
/// cards"). `dyna3d`: the card of the type itself.
enum class ContactForm : std::uint8_t {
  dyna3d,
  /// *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE (type family 12): the automatic pass over both sides'
  /// nodes and segments, restricted to the cross pairs (a slave-side node on a master-side
  /// segment, or the reverse).
  automatic_surface_to_surface,
  /// *CONTACT_AUTOMATIC_NODES_TO_SURFACE (type family 12): one way, the slave side's nodes against
  /// the master side's segments with the automatic pass's filters (shells two-sided).
  automatic_nodes_to_surface,
  /// *CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE (type family 12): as automatic_nodes_to_surface
  /// (a forming tool's master surface needs no consistent orientation).
  forming_one_way,
  /// *CONTACT_FORCE_TRANSDUCER_PENALTY: adds no force; measures the forces that the other
  /// interfaces put on its slave (and optional master) side (docs/contact.md, "Force transducer").
  force_transducer,
};

/// A *CONTACT_... card with its cards 1-3 and the optional tiebreak card 4.
struct Contact {
  Id cid = 0;             ///< from _ID; 0 if absent
  std::string title;      ///< heading from _ID / _TITLE
  std::string keyword;    ///< the keyword as written, e.g. "*CONTACT_SURFACE_TO_SURFACE_ID"
  ContactType type = ContactType::surface_to_surface;
  Enforcement enforcement = Enforcement::penalty;
  bool sliding_only_option = false;  ///< Type 10's sliding-only (no separation) option
  bool automatic_general = false;    ///< _GENERAL rather than _SINGLE_SURFACE for type 12
  ContactForm form = ContactForm::dyna3d;  ///< the LS-DYNA card of the type family
  // Card 1
  Id ssid = 0, msid = 0;
  int sstyp = 0, mstyp = 0;  ///< 0 segment set, 2 part set, 3 part id, 4 node set, 5 all
  Id sboxid = 0, mboxid = 0;
  int spr = 0, mpr = 0;
  // Card 2
  Real fs = 0.0;    ///< static friction coefficient
  Real fd = 0.0;    ///< dynamic friction coefficient
  Real dc = 0.0;    ///< exponential decay coefficient
  Real vc = 0.0;    ///< viscous friction coefficient
  Real vdc = 0.0;   ///< viscous damping coefficient (% of critical)
  int penchk = 0;
  Real bt = 0.0;    ///< birth time (0: from the start)
  Real dt = 1e20;   ///< death time (0 or blank on the card: 1e20, never)
  // Card 3
  Real sfs = 1.0, sfm = 1.0;    ///< penalty scale factors (slave, master)
  Real sst = 0.0, mst = 0.0;    ///< optional thickness (0 = from the elements)
  Real sfst = 1.0, sfmt = 1.0;  ///< thickness scale factors
  Real fsf = 1.0, vsf = 1.0;
  // Optional card A
  int soft = 0;        ///< SOFT: 0 the segment stiffness rule; 1 also SOFSCL x the nodal-mass stiffness
  Real sofscl = 0.1;   ///< SOFSCL (0 or blank: 0.1)
  int bsort = 0;       ///< BSORT, read with SOFT = 2 only: cycles between searches (0: chosen here)
  // Optional card B
  int snlog = 0;   ///< SNLOG: 0 shooting-node logic on (the eroding passes have it), 1 off (refused there)
  // Optional card C
  int ignore = 0;  ///< IGNORE: 0 *CONTROL_CONTACT's; 1, 2 initial penetrations kept as the springs' zero
  // Card 4 (tiebreak)
  Real nflf = 0.0;  ///< normal failure force (type 8) / stress (type 9)
  Real sflf = 0.0;  ///< shear failure force (type 8) / stress (type 9)
  Real nen = 2.0;   ///< normal exponent
  Real mes = 2.0;   ///< shear exponent
  int option = 0;   ///< tiebreak OPTION
  Real nfls = 0.0, sfls = 0.0, param = 0.0, eraten = 0.0, erates = 0.0, ct2cn = 0.0, cn = 0.0;  ///< card 4
  Real radius = 0.0;  ///< nodal contact radius for discrete nodes (type 5)
  /// *CONTACT_ERODING_... (the automatic counterpart, its surfaces updated as elements are
  /// deleted; docs/contact_erosion.md) and its card 4: ISYM (symmetry-plane faces left out: 0 only
  /// here), EROSOP (1: interior faces become surface when the element in front of them is deleted;
  /// 0: only the exterior faces, each dropped with its element), IADJ (0 only here).
  bool eroding = false;
  int isym = 0, erosop = 0, iadj = 0;
  /// Slave-master coupling (Types 3, 5, 10, 12 with surface slaves; the keyword's _MORTAR option
  /// sets 1, docs/keywords.md): 0 DYNA3D's rule (each slave node on its master segment's closest
  /// point; penalty spring f K A^2 / V), 1 mortar (penalty: the same stiffness per unit area times
  /// the node's tributary area over the master; gap, forces and Lagrange constraints on mortar
  /// weights); docs/contact.md, "The contact patch test".
  int penalty_coupling = 0;
  Source src;
  bool operator==(const Contact&) const = default;
};

/// *RIGIDWALL_PLANAR[_FINITE][_ID]: a stationary plane through the tail point that the slave nodes
/// may not pass, enforced kinematically (docs/solver.md, "Rigid walls"). The normal points from
/// the tail to the head, towards the side the nodes stay on.
struct RigidWallPlanar {
  Id id = 0;            ///< RWID of the _ID option (0 if absent)
  std::string title;    ///< HEADING of the _ID option
  Id nsid = 0;          ///< slave node set (0: every node)
  Id nsidex = 0;        ///< node set excluded from the slaves (0: none)
  Id boxid = 0;         ///< only slaves in this box (0: no box)
  Real offset = 0.0;    ///< slaves within this normal distance (0: the set's nodes)
  Real birth = 0.0;     ///< the wall acts from BIRTH
  Real death = 1e20;    ///< to DEATH (0 or blank: never dies)
  Real rwksf = 1.0;     ///< penalty scale (penalty walls only, RWPNAL > 0)
  Vec3 tail = Vec3::Zero();  ///< XT YT ZT
  Vec3 head = Vec3::Zero();  ///< XH YH ZH
  Real fric = 0.0;      ///< 0 frictionless, 1 no sliding, between: Coulomb coefficient
  Real wvel = 0.0;      ///< critical normal velocity for welding (0: none)
  bool finite = false;  ///< _FINITE: the wall is the rectangle below
  Vec3 edge_head = Vec3::Zero();  ///< XHEV YHEV ZHEV: head of the l edge, from the tail
  Real lenl = 0.0;      ///< length of the l edge
  Real lenm = 0.0;      ///< length of the m edge (m = n x l)
  Source src;
  bool operator==(const RigidWallPlanar&) const = default;
};

/// A card the reader saw and did not use because this version does not support it, kept so that
/// messages can name the real cause ("part 1 uses *MAT_PIECEWISE_LINEAR_PLASTICITY (deck.k:72),
/// not supported") and a run can list what it dropped.
struct UnsupportedCard {
  std::string keyword;  ///< upper-case, e.g. "*MAT_PIECEWISE_LINEAR_PLASTICITY"
  Id id = 0;            ///< first field of its first data card when an integer (MID, SECID, SID...), else 0
  int cards = 0;        ///< data cards under the keyword
  Source src;
  bool operator==(const UnsupportedCard&) const = default;
};

/// Everything a deck says.
struct Model {
  std::string title;
  std::vector<Node> nodes;
  std::vector<SolidElement> solids;
  std::vector<ShellElement> shells;
  std::vector<Part> parts;
  std::vector<SectionSolid> solid_sections;
  std::vector<SectionShell> shell_sections;
  std::vector<Material> materials;
  std::vector<MatAddErosion> add_erosions;
  std::vector<Eos> eos;  ///< *EOS_... cards (the parts' EOSID)
  std::vector<Hourglass> hourglasses;
  ControlHourglass control_hourglass;
  ControlBulkViscosity bulk_viscosity;
  std::vector<NodeSet> node_sets;
  std::vector<SegmentSet> segment_sets;
  std::vector<PartSet> part_sets;
  std::vector<BoundarySpc> spcs;
  std::vector<PrescribedMotion> prescribed_motions;
  std::vector<LoadBody> body_loads;
  std::vector<LoadNode> nodal_loads;
  std::optional<LoadBodyParts> body_load_parts;
  std::vector<Curve> curves;
  std::vector<Box> boxes;
  std::vector<CoordinateSystem> coordinate_systems;
  std::optional<DampingGlobal> damping_global;
  std::vector<DampingPartMass> damping_parts;
  std::vector<DampingPartStiffness> damping_stiffness;
  ControlTermination termination;
  /// *CONTROL_SHELL ESORT: 0 (blank) and 1 run triangular shells (N3 = N4) as C0 triangles (what
  /// ESORT 1 asks for; LS-DYNA's ESORT 0 runs them as degenerate quadrilaterals: docs/keywords.md);
  /// 2 (DKT triangles) is refused where a deformable shell part has triangles. `shell_esort_src`:
  /// where it was given.
  int shell_esort = 0;
  Source shell_esort_src;
  /// *CONTROL_SHELL INTGRD (card 2): the through-thickness rule of every shell section, 0 (blank)
  /// Gauss-Legendre, 1 Gauss-Lobatto (the two surfaces are integration points); other values are
  /// refused by the reader.
  int shell_intgrd = 0;
  /// *CONTROL_SHELL ISTUPD (card 1): 0 (blank) the shells keep their thickness; 1 membrane
  /// straining changes it (the whole normal strain of plane stress), 4 its plastic part alone
  /// (docs/solver.md, "Shell thickness change"); 2 and 3 (thick shells) are refused by the
  /// reader. `shell_istupd_src`: where it was given.
  int shell_istupd = 0;
  Source shell_istupd_src;
  /// *CONTROL_ACCURACY INN, invariant node numbering: 1 (blank, 0) off; 2 and -2 shells (the
  /// quadrilaterals' co-rotational frame from the lines joining opposite mid-sides, invariant under
  /// a renumbering of the nodes; 2 would also ask it of triangles, refused where triangles run);
  /// 3 solids (nothing to do: every solid law here is isotropic and the solid kernels have no
  /// element frame); 4 and -4 both. `accuracy_inn_src`: where it was given.
  int accuracy_inn = 1;
  Source accuracy_inn_src;
  /// *CONTROL_SOLID ESORT: 0 (blank) runs degenerate solids of ELFORM 1 / 2 sections as collapsed
  /// hexahedra; 1 would sort them into ELFORM 10 tetrahedra and 15 pentahedra: accepted where no
  /// such section holds a degenerate solid (nothing to sort), refused where one does.
  int solid_esort = 0;
  Source solid_esort_src;
  ControlTimestep timestep;
  ControlContact control_contact;
  DatabaseControl database;
  std::vector<Contact> contacts;
  std::vector<InitialVelocity> initial_velocities;
  std::vector<InitialVelocityGeneration> initial_velocity_generations;
  std::vector<InitialVelocityNode> initial_velocity_nodes;
  std::vector<RigidWallPlanar> rigid_walls;
  /// Physics cards the reader dropped (only with ReadOptions::ignore_unsupported; otherwise the
  /// reader refuses the deck).
  std::vector<UnsupportedCard> unsupported;
  /// The files the deck was read from (main file first, then *INCLUDEs), for element locations.
  std::vector<std::string> files;
  bool operator==(const Model&) const = default;
};

/// Where an element card came from ("" file and line 0 when generated).
template <class Element>
Source element_source(const Model& m, const Element& e) {
  const CardLine& at = e.at;
  if (at.line <= 0 || at.file < 0 || static_cast<std::size_t>(at.file) >= m.files.size()) return {};
  return {m.files[static_cast<std::size_t>(at.file)], at.line};
}

/// The material id of any material alternative.
inline Id material_id(const Material& m) {
  return std::visit([](const auto& mm) { return mm.mid; }, m);
}

}  // namespace slideline::model
