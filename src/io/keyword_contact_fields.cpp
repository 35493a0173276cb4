// The fields of *CONTACT_... and *CONTROL_CONTACT that the solver does not act on: each one, when
// not at its manual default (blank and 0 both mean the default), is refused (exit 3, naming file,
// line and field) or, when it only tunes output or speed or has nothing to act on here, warned
// about. Nothing is read and dropped. docs/contact.md, "Contact card fields", is the table.
#include <cstdint>
#include <cstdio>
#include <span>
#include <string>

#include "field_rules.hpp"
#include "keyword_card.hpp"
#include "slideline/core/error.hpp"

namespace slideline::keyword {
namespace {

using model::ContactType;
using model::Enforcement;
using detail::check_card;
using detail::check_remaining;
using detail::OptionalCard;
using detail::Rule;
using detail::Use;

std::string num(Real v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

/// Refuses or warns about field `r` holding `v` (not its default) on the card at `line`.
void act(const Context& ctx, int line, std::string_view keyword, std::string_view card, const Rule& r, Real v) {
  const std::string field = std::string(keyword) + " " + std::string(card) + ": field " + r.name + " = " + num(v) +
                            " (" + r.what + ")";
  switch (r.use) {
    case Use::refuse:
      throw NotImplementedError(ctx.where(line) + field + " is not implemented; running without it would be "
                                "a different model (leave it blank or give its default " + num(r.dflt) + ")");
    case Use::output:
      ctx.warn(line, field + " only tunes output that is not written here; ignored");
      return;
    case Use::speed:
      ctx.warn(line, field + " only tunes speed; ignored (the contact search here finds every pair)");
      return;
    case Use::inert:
      ctx.warn(line, field + " has nothing to act on here; ignored");
      return;
    case Use::step:
      ctx.warn(line, field + " only chooses the time step; ignored (the stable step here is the standard one)");
      return;
    case Use::honoured:
    case Use::unused:
      return;
  }
}

// Optional cards A-F of *CONTACT_... (LS-DYNA keyword manual, *CONTACT, "Optional Card A" to "F").
constexpr Rule kCardA[] = {
    {"SOFT", 0, Use::honoured, ""},    // read by read_contact_card_a (keyword_contact_options.cpp)
    {"SOFSCL", 0.1, Use::honoured, ""},  // likewise
    {"LCIDAB", 0, Use::inert, "airbag thickness curve of SOFT = 2; acts only with SOFT = 2"},
    {"MAXPAR", 1.025, Use::refuse, "maximum parametric coordinate of the segment search"},
    {"SBOPT", 2, Use::inert, "segment-based (SOFT = 2) options; acts only with SOFT = 2"},
    {"DEPTH", 2, Use::speed, "search depth"},
    {"BSORT", 0, Use::speed, "cycles between bucket sorts"},
    {"FRCFRQ", 1, Use::refuse, "cycles between contact force updates"},
};
constexpr Rule kCardB[] = {
    {"PENMAX", 0, Use::refuse, "maximum penetration before a node is released"},
    {"THKOPT", 0, Use::refuse, "per-contact thickness option"},
    {"SHLTHK", 0, Use::refuse, "per-contact shell thickness option"},
    {"SNLOG", 0, Use::honoured, ""},  // read by read_contact_optional_cards; refused where a part erodes
    {"ISYM", 0, Use::refuse, "symmetry plane option"},
    {"I2D3D", 0, Use::refuse, "segment search preference of shells over solids"},
    {"SLDTHK", 0, Use::refuse, "solid element contact thickness"},
    {"SLDSTF", 0, Use::refuse, "solid element contact stiffness"},
};
constexpr Rule kCardC[] = {
    {"IGAP", 1, Use::inert, "implicit convergence option; the run is explicit"},
    {"IGNORE", 0, Use::honoured, ""},  // read by read_contact_optional_cards
    {"DPRFAC", 0, Use::refuse, "penetration depth reduction factor (SOFT = 2, Mortar)"},
    {"DTSTIF", 0, Use::refuse, "time step of the SOFT = 1/2 stiffness (Mortar parameter)"},
    {"EDGEK", 0, Use::refuse, "edge-to-edge penalty scale"},
    {"UNUSED", 0, Use::unused, ""},
    {"FLANGL", 0, Use::inert, "feature-line angle of _SMOOTH contact, which is refused"},
    {"CID_RCF", 0, Use::output, "coordinate system of the rcforc output"},
};
constexpr Rule kCardD[] = {
    {"Q2TRI", 0, Use::inert, "split quadrilaterals (SOFT = 2 only)"},
    {"DTPCHK", 0, Use::output, "interval of shell penetration reports"},
    {"SFNBR", 0, Use::inert, "neighbour segment scale (SOFT = 2 only)"},
    {"FNLSCL", 0, Use::refuse, "nonlinear force scaling"},
    {"DNLSCL", 0, Use::refuse, "nonlinear force scaling distance"},
    {"TCSO", 0, Use::refuse, "contact thickness from contact segments only"},
    {"TIEDID", 0, Use::refuse, "incremental displacement update of tied contact"},
    {"SHLEDG", 0, Use::refuse, "shell edge shape"},
};
constexpr Rule kCardE[] = {
    {"SHAREC", 0, Use::inert, "shared constraints (SOFT = 2 only)"},
    {"CPARM8", 0, Use::refuse, "beam contact flags"},
    {"IPBACK", 0, Use::refuse, "backup penalty tied contact"},
    {"SRNDE", 0, Use::refuse, "non-extended exterior shell edges"},
    {"FRICSF", 1, Use::inert, "frictional stiffness scale (SOFT = 2 only)"},
    {"ICOR", 0, Use::refuse, "VDC read as a coefficient of restitution"},
    {"FTORQ", 0, Use::refuse, "transmission of moments across the interface"},
    {"REGION", 0, Use::refuse, "*DEFINE_REGION limiting the contact"},
};
constexpr Rule kCardF[] = {
    {"PSTIFF", 0, Use::refuse, "penalty stiffness method"},
    {"IGNROFF", 0, Use::refuse, "ignore the shell thickness offset"},
    {"UNUSED", 0, Use::unused, ""},
    {"FSTOL", 2, Use::inert, "flat-segment tolerance of _SMOOTH contact, which is refused"},
    {"2DBINR", 0, Use::inert, "2D seat belts in retractors (no belts here)"},
    {"SSFTYP", 0, Use::refuse, "which shell thickness scale factor is used"},
    {"SWTPR", 0, Use::refuse, "constant thickness of tied weld segments"},
    {"TETFAC", 0, Use::inert, "tetrahedron volume factor (SOFT = 2 only)"},
};

// With SOFT = 2 (segment-based contact): SBOPT, DEPTH, LCIDAB and BSORT are read by
// read_contact_card_a; the SOFT = 2 fields of cards D-F act on it, so they are refused.
constexpr Rule kCardA2[] = {
    {"SOFT", 0, Use::honoured, ""},   {"SOFSCL", 0.1, Use::honoured, ""}, {"LCIDAB", 0, Use::honoured, ""},
    {"MAXPAR", 1.025, Use::refuse, "maximum parametric coordinate of the segment search"},
    {"SBOPT", 2, Use::honoured, ""},  {"DEPTH", 2, Use::honoured, ""},
    {"BSORT", 0, Use::honoured, ""},
    {"FRCFRQ", 1, Use::refuse, "cycles between contact force updates"},
};
constexpr Rule kCardD2[] = {
    {"Q2TRI", 0, Use::refuse, "split quadrilaterals of SOFT = 2"},
    {"DTPCHK", 0, Use::output, "interval of shell penetration reports"},
    {"SFNBR", 0, Use::refuse, "neighbour segment scale of SOFT = 2"},
    {"FNLSCL", 0, Use::refuse, "nonlinear force scaling"},
    {"DNLSCL", 0, Use::refuse, "nonlinear force scaling distance"},
    {"TCSO", 0, Use::refuse, "contact thickness from contact segments only"},
    {"TIEDID", 0, Use::refuse, "incremental displacement update of tied contact"},
    {"SHLEDG", 0, Use::refuse, "shell edge shape"},
};
constexpr Rule kCardE2[] = {
    {"SHAREC", 0, Use::refuse, "shared constraints of SOFT = 2"},
    {"CPARM8", 0, Use::refuse, "beam contact flags"},
    {"IPBACK", 0, Use::refuse, "backup penalty tied contact"},
    {"SRNDE", 0, Use::refuse, "non-extended exterior shell edges"},
    {"FRICSF", 1, Use::refuse, "frictional stiffness scale of SOFT = 2"},
    {"ICOR", 0, Use::refuse, "VDC read as a coefficient of restitution"},
    {"FTORQ", 0, Use::refuse, "transmission of moments across the interface"},
    {"REGION", 0, Use::refuse, "*DEFINE_REGION limiting the contact"},
};
constexpr Rule kCardF2[] = {
    {"PSTIFF", 0, Use::refuse, "penalty stiffness method"},
    {"IGNROFF", 0, Use::refuse, "ignore the shell thickness offset"},
    {"UNUSED", 0, Use::unused, ""},
    {"FSTOL", 2, Use::inert, "flat-segment tolerance of _SMOOTH contact, which is refused"},
    {"2DBINR", 0, Use::inert, "2D seat belts in retractors (no belts here)"},
    {"SSFTYP", 0, Use::refuse, "which shell thickness scale factor is used"},
    {"SWTPR", 0, Use::refuse, "constant thickness of tied weld segments"},
    {"TETFAC", 0, Use::refuse, "tetrahedron volume factor of SOFT = 2"},
};
constexpr OptionalCard kOptionalSoft2[] = {{"optional card A", kCardA2}, {"optional card B", kCardB},
                                           {"optional card C", kCardC}, {"optional card D", kCardD2},
                                           {"optional card E", kCardE2}, {"optional card F", kCardF2}};

constexpr OptionalCard kOptional[] = {{"optional card A", kCardA}, {"optional card B", kCardB},
                                      {"optional card C", kCardC}, {"optional card D", kCardD},
                                      {"optional card E", kCardE}, {"optional card F", kCardF}};

// *CONTROL_CONTACT cards 2-6 (LS-DYNA keyword manual, *CONTROL_CONTACT).
constexpr Rule kControl2[] = {
    {"USRSTR", 0, Use::inert, "storage for user contact subroutines (none here)"},
    {"USRFRC", 0, Use::inert, "storage for user friction subroutines (none here)"},
    {"NSBCS", 0, Use::speed, "cycles between contact searches"},
    {"INTERM", 0, Use::refuse, "intermittent searching"},
    {"XPENE", 4, Use::honoured, ""},  // read by read_control_contact_cards (PENCHK = 1)
    {"SSTHK", 0, Use::refuse, "true shell thickness in single-surface contact"},
    {"ECDT", 0, Use::step, "eroding contact left out of the time step"},
    {"TIEDPRJ", 0, Use::refuse, "bypass of the projection of tied nodes"},
};
constexpr Rule kControl3[] = {
    {"SFRIC", 0, Use::inert, "default static friction of *PART_CONTACT, which is refused"},
    {"DFRIC", 0, Use::inert, "default dynamic friction of *PART_CONTACT, which is refused"},
    {"EDC", 0, Use::inert, "default decay coefficient of *PART_CONTACT, which is refused"},
    {"VFC", 0, Use::inert, "default viscous friction of *PART_CONTACT, which is refused"},
    {"TH", 0, Use::inert, "default contact thickness of *PART_CONTACT, which is refused"},
    {"TH_SF", 0, Use::inert, "default thickness scale of *PART_CONTACT, which is refused"},
    {"PEN_SF", 0, Use::inert, "default penalty scale of *PART_CONTACT, which is refused"},
    {"PTSCL", 0, Use::refuse, "penalty scale of node-to-segment contact"},
};
constexpr Rule kControl4[] = {
    {"IGNORE", 0, Use::honoured, ""},  // read by read_control_contact_cards
    {"FRCENG", 0, Use::output, "frictional energy output"},
    {"SKIPRWG", 0, Use::output, "rigid-wall display"},
    {"OUTSEG", 0, Use::output, "spot weld segment output"},
    {"SPOTSTP", 0, Use::inert, "spot weld option (no spot welds here)"},
    {"SPOTDEL", 0, Use::inert, "spot weld deletion (no spot welds here)"},
    {"SPOTHIN", 0, Use::inert, "spot weld thinning (no spot welds here)"},
    {"UNUSED", 0, Use::unused, ""},
};
constexpr Rule kControl5[] = {
    {"ISYM", 0, Use::refuse, "symmetry planes of automatic contact"},
    {"NSEROD", 0, Use::refuse, "one-way node-to-surface algorithm of eroding contact"},
    {"RWGAPS", 1, Use::inert, "rigid-wall gap stiffness (penalty walls only; refused)"},
    {"RWGDTH", 0, Use::inert, "rigid-wall gap death (penalty walls only; refused)"},
    {"RWKSF", 1, Use::inert, "rigid-wall penalty scale (penalty walls only; refused)"},
    {"ICOV", 0, Use::refuse, "invariant node numbering of shell contact"},
    {"SWRADF", 0, Use::inert, "spot weld radius scale (no spot welds here)"},
    {"ITHOFF", 0, Use::inert, "thermal contact offset (no thermal analysis here)"},
};
constexpr Rule kControl6[] = {
    {"SHLEDG", 0, Use::refuse, "shell edge shape"},
    {"PSTIFF", 0, Use::refuse, "penalty stiffness method"},
    {"ITHCNT", 0, Use::inert, "thermal contact option (no thermal analysis here)"},
    {"TDCNOF", 0, Use::refuse, "tied contact node check"},
    {"FTALL", 0, Use::refuse, "force transducers of all contacts"},
    {"UNUSED", 0, Use::unused, ""},
    {"SHLTRW", 0, Use::refuse, "shell thickness in rigid walls"},
    {"IGACTC", 0, Use::inert, "isogeometric contact (no IGA here)"},
};
constexpr OptionalCard kControl[] = {{"card 2", kControl2}, {"card 3", kControl3}, {"card 4", kControl4},
                                     {"card 5", kControl5}, {"card 6", kControl6}};

/// Applies the rules of `cards` to the cards left in `b`, one rule set per card; a non-blank card
/// beyond them is refused.

/// Refuses (or warns about) `name` = v on card `l` when v differs from `dflt`.
void field(const Context& ctx, const Line* l, std::string_view kw, const char* card, Real v, const Rule& r) {
  if (l && v != r.dflt) act(ctx, l->number, kw, card, r, v);
}

bool is_tied(ContactType t) {
  return t == ContactType::tied_surface || t == ContactType::tied_nodes || t == ContactType::tied_shell_edge;
}
bool is_tiebreak(ContactType t) {
  return t == ContactType::tiebreak_nodes || t == ContactType::tiebreak_surface;
}

/// Card 2: FS, FD, DC are honoured where the interface slides with friction; VC, VDC and PENCHK = 1
/// on the penalty sliding interfaces. BT and DT are the contact's birth and death (read and honoured by the builder).
void check_card2(const Context& ctx, const model::Contact& c, const Line* l) {
  const std::string_view kw = c.keyword;
  if (l && (c.fs < 0.0 || c.fd < 0.0 || c.dc < 0.0))
    throw NotImplementedError(ctx.where(l->number) + c.keyword + " card 2: FS, FD or DC < 0 (FS = -2: friction "
                              "tables of *DEFINE_FRICTION; FS = -1: part-based friction) is not implemented; "
                              "give FS, FD, DC >= 0");
  if (is_tied(c.type) || c.type == ContactType::sliding_only) {
    // FS and FD of a sliding-only interface are refused by the builder (it is frictionless).
    const char* why = is_tied(c.type) ? "friction of a tied interface, which does not slide"
                                      : "friction decay of a sliding-only interface, which is frictionless";
    if (is_tied(c.type)) {
      field(ctx, l, kw, "card 2", c.fs, {"FS", 0, Use::inert, why});
      field(ctx, l, kw, "card 2", c.fd, {"FD", 0, Use::inert, why});
    }
    field(ctx, l, kw, "card 2", c.dc, {"DC", 0, Use::inert, why});
  }
  check_viscous_friction(ctx, c, l);
  // VDC: the penalty sliding interfaces (3, 5, 10, 12) damp their springs; kinematic ties and
  // Type 1 have no spring to damp; tiebreak and Lagrange interfaces refuse it.
  const bool penalty_sliding = c.enforcement == Enforcement::penalty && !is_tied(c.type) && !is_tiebreak(c.type) &&
                               c.type != ContactType::sliding_only;
  if (!penalty_sliding) {
    const bool constraint = is_tied(c.type) || c.type == ContactType::sliding_only;
    field(ctx, l, kw, "card 2", c.vdc,
          {"VDC", 0, constraint ? Use::inert : Use::refuse,
           constraint ? "viscous contact damping; this interface is a kinematic constraint, without a spring"
                      : "viscous contact damping of a tiebreak or Lagrange interface"});
  }
  // PENCHK = 1: nodes deeper than XPENE (*CONTROL_CONTACT card 2) x the master segment's thickness
  // are released (penalty sliding interfaces; contact.md "Release of deep penetrations").
  if (c.penchk == 1 && penalty_sliding) return;
  field(ctx, l, kw, "card 2", c.penchk,
        {"PENCHK", 0, Use::refuse,
         c.penchk == 1 ? "release of deep penetrations on a tied, tiebreak, sliding-only or Lagrange interface"
                       : "release of deep penetrations: only PENCHK = 1 is built (2 uses another thickness rule)"});
}

/// Card 3: what each family of interfaces does with the stiffness and thickness fields.
void check_card3(const Context& ctx, const model::Contact& c, const Line* l) {
  const std::string_view kw = c.keyword;
  const bool penalty = c.enforcement == Enforcement::penalty && !is_tied(c.type);
  const bool stiffness = penalty || is_tiebreak(c.type);
  // Thickness offsets: penalty and Lagrange sliding interfaces (Types 3, 5, 10, 12), and the automatic tiebreak's OPTION 8.
  const bool offsets = (c.form == model::ContactForm::automatic_surface_to_surface && c.option == 8) ||
                       (!is_tied(c.type) && !is_tiebreak(c.type) && c.type != ContactType::sliding_only);
  const bool two_way = c.type == ContactType::surface_to_surface || c.type == ContactType::one_way;
  if (!stiffness) {
    const char* why = "penalty scale; this interface is enforced by constraints";
    field(ctx, l, kw, "card 3", c.sfs, {"SFS", 1, Use::inert, why});
    field(ctx, l, kw, "card 3", c.sfm, {"SFM", 1, Use::inert, why});
  } else if (!two_way && c.sfm != c.sfs) {
    // A one-pass interface scales the master segments' stiffness by SFS (docs/contact.md); with
    // SFM = SFS (or the default 1) which factor is applied makes no difference.
    field(ctx, l, kw, "card 3", c.sfm,
          {"SFM", 1, Use::refuse, "master penalty scale different from SFS; this one-pass interface scales by SFS"});
  }
  const char* no_thickness = "contact thickness; this interface has no thickness offsets";
  field(ctx, l, kw, "card 3", offsets ? 0.0 : c.sst, {"SST", 0, Use::refuse, no_thickness});
  field(ctx, l, kw, "card 3", offsets ? 0.0 : c.mst, {"MST", 0, Use::refuse, no_thickness});
  field(ctx, l, kw, "card 3", offsets ? 1.0 : c.sfst, {"SFST", 1, Use::refuse, no_thickness});
  field(ctx, l, kw, "card 3", offsets ? 1.0 : c.sfmt, {"SFMT", 1, Use::refuse, no_thickness});
  if (c.type == ContactType::automatic && c.form == model::ContactForm::dyna3d) {
    // Single surface: SST/SFST apply to every segment; MST/SFMT have no side of their own.
    const char* single = "master thickness; a single-surface contact uses SST and SFST for every segment";
    field(ctx, l, kw, "card 3", c.mst, {"MST", 0, Use::refuse, single});
    field(ctx, l, kw, "card 3", c.sfmt, {"SFMT", 1, Use::refuse, single});
  }
  field(ctx, l, kw, "card 3", c.fsf, {"FSF", 1, Use::refuse, "Coulomb friction scale factor; scale FS and FD"});
  field(ctx, l, kw, "card 3", c.vsf, {"VSF", 1, Use::refuse, "viscous friction scale factor"});
}

// *SECTION_SOLID, *SECTION_SHELL and *HOURGLASS fields the reader does not store (keyword manual).
constexpr Rule kSectionSolid[] = {
    {"SECID", 0, Use::honoured, ""}, {"ELFORM", 1, Use::honoured, ""},
    {"AET", 0, Use::refuse, "ambient element type"},
};
constexpr Rule kSectionShell1[] = {
    {"SECID", 0, Use::honoured, ""},  {"ELFORM", 2, Use::honoured, ""},
    {"SHRF", 1, Use::honoured, ""},   {"NIP", 2, Use::honoured, ""},
    {"PROPT", 1, Use::output, "printout option"},
    {"QR/IRID", 0, Use::refuse, "through-thickness integration rule (0: Gauss)"},
    {"ICOMP", 0, Use::refuse, "composite layer angles"},
    {"SETYP", 1, Use::refuse, "2D solid element type"},
};
constexpr Rule kSectionShell2[] = {
    {"T1", 0, Use::honoured, ""},     {"T2", 0, Use::honoured, ""}, {"T3", 0, Use::honoured, ""},
    {"T4", 0, Use::honoured, ""},     {"NLOC", 0, Use::refuse, "reference surface location"},
    {"MAREA", 0, Use::refuse, "non-structural mass per area"},
    {"IDOF", 0, Use::refuse, "thickness field option"},
    {"EDGSET", 0, Use::refuse, "edge node set of shell elements"},
};

// Fields of other cards that the reader does not store (keyword manual; the stored fields come first).
constexpr Rule kPart[] = {
    {"PID", 0, Use::honoured, ""},   {"SECID", 0, Use::honoured, ""}, {"MID", 0, Use::honoured, ""},
    {"EOSID", 0, Use::honoured, ""}, {"HGID", 0, Use::honoured, ""},
    {"GRAV", 0, Use::inert, "gravity initialisation of *LOAD_DENSITY_DEPTH, which is not read"},
    {"ADPOPT", 0, Use::refuse, "adaptive remeshing of the part"},
    {"TMID", 0, Use::inert, "thermal material (no thermal analysis here)"},
};
constexpr Rule kMatElastic[] = {
    {"MID", 0, Use::honoured, ""}, {"RO", 0, Use::honoured, ""}, {"E", 0, Use::honoured, ""},
    {"PR", 0, Use::honoured, ""},
    {"DA", 0, Use::inert, "axial damping of Belytschko-Schwer beams (no beams here)"},
    {"DB", 0, Use::inert, "bending damping of Belytschko-Schwer beams (no beams here)"},
    {"K", 0, Use::inert, "bulk modulus of *MAT_ELASTIC_FLUID, which is not read"},
};
constexpr Rule kMatMooneyRivlin[] = {
    {"MID", 0, Use::honoured, ""}, {"RO", 0, Use::honoured, ""}, {"PR", 0, Use::honoured, ""},
    {"A", 0, Use::honoured, ""},   {"B", 0, Use::honoured, ""},
    {"REF", 0, Use::inert, "reference geometry of *INITIAL_FOAM_REFERENCE_GEOMETRY, which is not read"},
};
constexpr Rule kMatRigid[] = {
    {"MID", 0, Use::honoured, ""}, {"RO", 0, Use::honoured, ""}, {"E", 0, Use::honoured, ""},
    {"PR", 0, Use::honoured, ""},
    {"N", 0, Use::inert, "MADYMO / CAL3D coupling (none here)"},
    {"COUPLE", 0, Use::inert, "MADYMO / CAL3D coupling option (none here)"},
    {"M", 0, Use::inert, "MADYMO / CAL3D coupling (none here)"},
    {"ALIAS", 0, Use::unused, ""},  // a name for the VDA interface, text
};
constexpr Rule kControlBulkViscosity[] = {
    {"Q1", 1.5, Use::honoured, ""}, {"Q2", 0.06, Use::honoured, ""},
    {"TYPE", 1, Use::honoured, ""},  // checked by the reader (1, -1, -2)
    {"BTYPE", 0, Use::inert, "beam bulk viscosity (no beams here)"},
    {"TSTYPE", 0, Use::inert, "thick-shell bulk viscosity (no thick shells here)"},
};
constexpr Rule kControlTermination[] = {
    {"ENDTIM", 0, Use::honoured, ""}, {"ENDCYC", 0, Use::honoured, ""}, {"DTMIN", 0, Use::honoured, ""},
    {"ENDENG", 0, Use::honoured, ""},
    {"ENDMAS", 1e8, Use::honoured, ""},
    {"NOSOL", 0, Use::refuse, "a run without solution (input check only)"},
};
constexpr Rule kControlTimestep1[] = {
    {"DTINIT", 0, Use::honoured, ""}, {"TSSFAC", 0.9, Use::honoured, ""}, {"ISDO", 0, Use::honoured, ""},
    {"TSLIMT", 0, Use::honoured, ""}, {"DT2MS", 0, Use::honoured, ""},   {"LCTM", 0, Use::honoured, ""},
    {"ERODE", 0, Use::honoured, ""},  // read_control_timestep: 0 or 1
    {"MS1ST", 0, Use::honoured, ""},
};
constexpr Rule kControlTimestep2[] = {
    {"DT2MSF", 0, Use::refuse, "mass scaling to a fraction of the initial step"},
    {"DT2MSLC", 0, Use::refuse, "curve of the mass-scaled step"},
    {"IMSCL", 0, Use::refuse, "selective mass scaling"},
    {"UNUSED", 0, Use::unused, ""},
    {"UNUSED", 0, Use::unused, ""},
    {"RMSCL", 0, Use::refuse, "selective mass scaling of rotational inertia"},
    {"EMSCL", 0, Use::refuse, "added-mass fraction of mass scaling"},
    {"IHDO", 0, Use::step, "solid element time-step method"},
};
constexpr Rule kDefineCurve[] = {
    {"LCID", 0, Use::honoured, ""}, {"SIDR", 0, Use::honoured, ""}, {"SFA", 1, Use::honoured, ""},
    {"SFO", 1, Use::honoured, ""},  {"OFFA", 0, Use::honoured, ""}, {"OFFO", 0, Use::honoured, ""},
    {"DATTYP", 0, Use::honoured, ""},
    {"LCINT", 0, Use::inert, "points of a curve's discretisation (curves are evaluated exactly here)"},
};

struct StoredCardRules {
  const char* card;
  std::span<const Rule> rules;
};
constexpr StoredCardRules kStoredCards[] = {
    {"card 2", kPart},          {"card 1", kMatElastic},          {"card 1", kMatMooneyRivlin},
    {"card 1", kMatRigid},      {"card 1", kControlBulkViscosity}, {"card 1", kControlTermination},
    {"card 1", kControlTimestep1}, {"card 2", kControlTimestep2},  {"card 1", kDefineCurve},
};

}  // namespace

void check_unread_fields(const Context& ctx, const Line& card, std::string_view keyword, StoredCard which) {
  if (which == StoredCard::none) return;
  const StoredCardRules& r = kStoredCards[static_cast<std::size_t>(which)];
  check_card(ctx, card, keyword, r.card, r.rules);
}

void check_section_fields(const Context& ctx, const Line& card1, const Line* card2, std::string_view keyword,
                          bool shell) {
  if (!shell) return check_card(ctx, card1, keyword, "card 1", kSectionSolid);
  check_card(ctx, card1, keyword, "card 1", kSectionShell1);
  if (card2) check_card(ctx, *card2, keyword, "card 2", kSectionShell2);
}

void check_hourglass_fields(const Context& ctx, const Line& card, std::string_view keyword, Real qm) {
  // QB and QW (shell bending and warping coefficients) default to QM; IBQ is unused.
  const Rule rules[] = {{"HGID", 0, Use::honoured, ""}, {"IHQ", 1, Use::honoured, ""},
                        {"QM", 0.1, Use::honoured, ""}, {"IBQ", 0, Use::unused, ""},
                        {"Q1", 1.5, Use::honoured, ""}, {"Q2", 0.06, Use::honoured, ""},
                        {"QB", qm, Use::refuse, "shell bending hourglass coefficient other than QM"},
                        {"QW", qm, Use::refuse, "shell warping hourglass coefficient other than QM"}};
  // 0 (blank) means QM itself.
  const Card k(ctx, card, keyword, kStandard);
  for (int i : {6, 7}) {
    Real v = 0.0;
    k.get(i, rules[i].name, v);
    if (v != 0.0 && v != qm) act(ctx, card.number, keyword, "card 1", rules[i], v);
  }
}

void check_contact_fields(const Context& ctx, const model::Contact& c, const Line* card1, const Line* card2,
                          const Line* card3, const Line* card4) {
  const std::string_view kw = c.keyword;
  field(ctx, card1, kw, "card 1", c.spr, {"SPR", 0, Use::output, "slave side in the interface force file"});
  field(ctx, card1, kw, "card 1", c.mpr, {"MPR", 0, Use::output, "master side in the interface force file"});
  check_card2(ctx, c, card2);
  check_card3(ctx, c, card3);
  if (!card4) return;
  // Tiebreak card 4: the fields after those read (type 8: NFLF SFLF NEN MES; type 9: OPTION NFLS
  // SFLS) are not implemented.
  static constexpr Rule kType8[] = {{"NFLF", 0, Use::honoured, ""}, {"SFLF", 0, Use::honoured, ""},
                                    {"NEN", 2, Use::honoured, ""},  {"MES", 2, Use::honoured, ""},
                                    {"(field 5)", 0, Use::refuse, "not a field of this card"},
                                    {"(field 6)", 0, Use::refuse, "not a field of this card"},
                                    {"(field 7)", 0, Use::refuse, "not a field of this card"},
                                    {"(field 8)", 0, Use::refuse, "not a field of this card"}};
  static constexpr Rule kType9[] = {{"OPTION", 0, Use::honoured, ""}, {"NFLS", 0, Use::honoured, ""},
                                    {"SFLS", 0, Use::honoured, ""},   {"PARAM", 0, Use::refuse, "failure law parameter"},
                                    {"ERATEN", 0, Use::refuse, "normal energy release rate"},
                                    {"ERATES", 0, Use::refuse, "shear energy release rate"},
                                    {"CT2CN", 0, Use::refuse, "tangential to normal stiffness ratio"},
                                    {"CN", 0, Use::refuse, "normal stiffness"}};
  // OPTION 6 (8) of the automatic card: PARAM is CCRIT; ERATEN..CN are other OPTIONs' (CN: _MORTAR).
  static constexpr Rule kAuto6[] = {{"OPTION", 0, Use::honoured, ""}, {"NFLS", 0, Use::honoured, ""},
                                    {"SFLS", 0, Use::honoured, ""},   {"PARAM", 0, Use::honoured, ""},
                                    {"ERATEN", 0, Use::refuse, "energy release rate (OPTION 7, 9-11)"},
                                    {"ERATES", 0, Use::refuse, "energy release rate (OPTION 7, 9-11)"},
                                    {"CT2CN", 0, Use::refuse, "stiffness ratio (OPTION 9, 11)"},
                                    {"CN", 0, Use::refuse, "normal stiffness (OPTION 6: _MORTAR only)"}};
  // OPTION 4: NFLS only; SFLS is read by the manual with PARAM = 1 (a friction stress limit).
  static constexpr Rule kAuto4[] = {{"OPTION", 0, Use::honoured, ""}, {"NFLS", 0, Use::honoured, ""},
                                    {"SFLS", 0, Use::refuse, "OPTION 4: a friction stress limit with PARAM = 1"},
                                    {"PARAM", 0, Use::refuse, "OPTION 4: 1 makes SFLS a friction stress limit, "
                                                              "not built (a cap on Coulomb or in its place?)"},
                                    {"ERATEN", 0, Use::refuse, "energy release rate (OPTION 7, 9-11)"},
                                    {"ERATES", 0, Use::refuse, "energy release rate (OPTION 7, 9-11)"},
                                    {"CT2CN", 0, Use::refuse, "stiffness ratio (OPTION 9, 11)"},
                                    {"CN", 0, Use::refuse, "normal stiffness (OPTION 4: _MORTAR only)"}};
  // OPTION 1 (blank, 0): a permanent tie; the manual reads NFLS, SFLS on 2, 3, 4, 6-11 only.
  static constexpr Rule kAuto1[] = {{"OPTION", 0, Use::honoured, ""},
                                    {"NFLS", 0, Use::refuse, "OPTION 1 never fails (give OPTION 3 for failure)"},
                                    {"SFLS", 0, Use::refuse, "OPTION 1 never fails (give OPTION 3 for failure)"},
                                    {"PARAM", 0, Use::refuse, "failure law parameter (not read on OPTION 1)"},
                                    {"ERATEN", 0, Use::refuse, "energy release rate (OPTION 7, 9-11)"},
                                    {"ERATES", 0, Use::refuse, "energy release rate (OPTION 7, 9-11)"},
                                    {"CT2CN", 0, Use::refuse, "stiffness ratio (OPTION 9, 11)"},
                                    {"CN", 0, Use::refuse, "normal stiffness (OPTION 9, 11, 13, 14)"}};
  const bool automatic = c.form == model::ContactForm::automatic_surface_to_surface;
  // OPTION 9 of the automatic card honours the whole card (checked by check_automatic_tiebreak_card4).
  if (!automatic || c.option != 9)
    check_card(ctx, *card4, kw, "card 4",
               c.type == ContactType::tiebreak_nodes ? std::span<const Rule>(kType8)
               : automatic && (c.option == 6 || c.option == 8) ? std::span<const Rule>(kAuto6)
               : automatic && c.option == 4      ? std::span<const Rule>(kAuto4)
               : automatic && (c.option == 0 || c.option == 1) ? std::span<const Rule>(kAuto1)
                                                 : std::span<const Rule>(kType9));
  // Type 9's OPTION selects a failure law; DYNA3D's (0) is built. The automatic card's OPTIONs:
  // check_automatic_tiebreak_card4.
  if (c.type == ContactType::tiebreak_surface && c.form != model::ContactForm::automatic_surface_to_surface)
    field(ctx, card4, kw, "card 4", c.option, {"OPTION", 0, Use::refuse, "failure law (DYNA3D's Type 9 law, 0, is built)"});
}

namespace {

/// IGNORE (optional card C of a contact, card 4 of *CONTROL_CONTACT): the `offset`-th card still in
/// `b`, field `index`; 0, 1 or 2 (anything else: InputError naming file, line and field).
int read_ignore(const Context& ctx, const Block& b, std::size_t offset, int index, const char* card) {
  int ignore = 0;
  if (b.next + offset >= b.cards.size()) return ignore;
  const Line& l = b.cards[b.next + offset];
  Card(ctx, l, b.keyword, kStandard).get(index, "IGNORE", ignore);
  if (ignore < 0 || ignore > 2)
    throw InputError(ctx.where(l.number) + b.keyword + " " + card + ": field IGNORE must be 0, 1 or 2 (got " +
                     std::to_string(ignore) + ")");
  return ignore;
}

/// XPENE (*CONTROL_CONTACT card 2, field 5): the next card still in `b`; 0 or blank is LS-DYNA's
/// default 4, a negative value an InputError naming file, line and field.
Real read_xpene(const Context& ctx, const Block& b) {
  Real xpene = 4.0;
  if (b.next >= b.cards.size()) return xpene;
  const Line& l = b.cards[b.next];
  Card(ctx, l, b.keyword, kStandard).get_or_default(4, "XPENE", xpene);
  if (xpene < 0.0)
    throw InputError(ctx.where(l.number) + b.keyword + " card 2: field XPENE must not be negative (got " + num(xpene) +
                     ")");
  return xpene;
}

}  // namespace

void read_contact_optional_cards(const Context& ctx, Block& b, model::Contact& c) {
  read_contact_card_a(ctx, b, c);
  // SNLOG (card B): 1 refused where a part erodes (prepare_eroding_contact), nothing to act on elsewhere.
  if (b.next + 1 < b.cards.size()) Card(ctx, b.cards[b.next + 1], b.keyword, kStandard).get(3, "SNLOG", c.snlog);
  c.ignore = read_ignore(ctx, b, 2, 1, "optional card C");
  if (c.ignore != 0) {
    // Penalty sliding interfaces keep the penetrations; Lagrange is refused when the model is
    // built (interface_spec.cpp); ties and tiebreaks tie their nodes where they are.
    const Line& l = b.cards[b.next + 2];
    const bool tie = is_tied(c.type) || is_tiebreak(c.type) || c.type == ContactType::sliding_only ||
                     c.form == model::ContactForm::force_transducer;  // (a transducer has no spring)
    if (tie)
      act(ctx, l.number, b.keyword, "optional card C",
          {"IGNORE", 0, Use::inert, "initial penetrations kept; this interface ties or constrains its nodes where they are"},
          c.ignore);
  }
  if (c.soft == 2)
    check_remaining(ctx, b, kOptionalSoft2);
  else
    check_remaining(ctx, b, kOptional);
}

void read_control_contact_cards(const Context& ctx, Block& b, model::ControlContact& t, int line) {
  const Line card1{"", line, Format::standard};
  const std::string_view kw = b.keyword;
  field(ctx, &card1, kw, "card 1", t.rwpnal, {"RWPNAL", 0, Use::inert, "penalty rigid walls; refused with a *RIGIDWALL"});
  field(ctx, &card1, kw, "card 1", t.islchk, {"ISLCHK", 1, Use::output, "report of initial penetrations"});
  if (t.shlthk < 0 || t.shlthk > 2)
    throw InputError(ctx.where(line) + b.keyword + " card 1: field SHLTHK must be 0, 1 or 2 (got " +
                     std::to_string(t.shlthk) + ")");
  if (t.penopt != 2)
    field(ctx, &card1, kw, "card 1", t.penopt, {"PENOPT", 1, Use::refuse, "penalty stiffness option"});
  // PENOPT 1, 2 (the master segment's stiffness here); THKCHG 1 (docs/contact.md, "Shell thickness change").
  if (t.thkchg != 1)
    field(ctx, &card1, kw, "card 1", t.thkchg, {"THKCHG", 0, Use::refuse, "shell thickness changes in contact"});
  field(ctx, &card1, kw, "card 1", t.orien, {"ORIEN", 1, Use::refuse, "segment orientation option"});
  if (t.enmass < 0 || t.enmass > 2)  // docs/contact_erosion.md, "ENMASS"
    throw InputError(ctx.where(line) + b.keyword + " card 1: field ENMASS must be 0, 1 or 2 (nodes freed by erosion: 0 "
                     "leave the contact; 1 those of solids, 2 of solids and shells stay as free masses; got " +
                     std::to_string(t.enmass) + ")");
  t.ignore = read_ignore(ctx, b, 2, 0, "card 4");
  t.xpene = read_xpene(ctx, b);
  check_remaining(ctx, b, kControl);
}

}  // namespace slideline::keyword

namespace slideline::keyword::detail {

/// Applies `rules` (one per field, in column order) to card `l`.
void check_card(const Context& ctx, const Line& l, std::string_view keyword, std::string_view card,
                std::span<const Rule> rules) {
  const Card k(ctx, l, keyword, kStandard);
  for (std::size_t i = 0; i < rules.size(); ++i) {
    const Rule& r = rules[i];
    if (r.use == Use::honoured || r.use == Use::unused) continue;
    Real v = r.dflt;
    k.get_or_default(static_cast<int>(i), r.name, v);
    if (v != r.dflt) act(ctx, l.number, keyword, card, r, v);
  }
}

void check_remaining(const Context& ctx, Block& b, std::span<const OptionalCard> cards) {
  std::size_t k = 0;
  while (const Line* l = b.take()) {
    if (k < cards.size()) {
      check_card(ctx, *l, b.keyword, cards[k].name, cards[k].rules);
      ++k;
    } else if (!trim(l->text).empty()) {
      throw NotImplementedError(ctx.where(l->number) + b.keyword + ": a card after " +
                                std::string(cards.back().name) + " is not read; remove it");
    }
  }
}

}  // namespace slideline::keyword::detail
