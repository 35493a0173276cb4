// A *CONTACT card resolved once into an InterfaceSpec (contact/interface_spec.hpp): which
// combinations run, the sides, offsets, friction, stiffness factors, failure data, birth and death.
#include "slideline/contact/interface_spec.hpp"

#include <algorithm>

#include "slideline/core/error.hpp"
#include "slideline/core/source_location.hpp"
#include "slideline/element/element_block.hpp"
#include "slideline/mesh/surface_builder.hpp"

namespace slideline {

namespace {

using T = model::ContactType;

std::string card_name(const model::Contact& card) {
  return card.keyword.empty() ? std::string("*CONTACT") : card.keyword;
}

/// "file:line" of the card.
std::string at(const model::Contact& card) { return describe_location(card.src.file, card.src.line); }

/// "file:line: KEYWORD": the start of every message about the card.
std::string where(const model::Contact& card) { return at(card) + ": " + card_name(card); }

std::vector<Id> all_parts(const ContactBuildContext& ctx) {
  std::vector<Id> parts;
  for (const auto& [pid, nodes] : ctx.sets.part_nodes) parts.push_back(pid);
  return parts;
}

const model::Box* find_box(const model::Model& m, Id id) {
  for (const auto& b : m.boxes)
    if (b.boxid == id) return &b;
  return nullptr;
}

bool inside(const model::Box& b, const Vec3& p) {
  for (int k = 0; k < 3; ++k)
    if (p[k] < b.min[static_cast<std::size_t>(k)] || p[k] > b.max[static_cast<std::size_t>(k)]) return false;
  return true;
}

/// The segments of `surf` whose centroid lies in `box` (at the initial coordinates), with
/// adjacency rebuilt.
Surface segments_in_box(const Surface& surf, const model::Box& box, const NodalFields& nodes) {
  Surface out;
  for (Index s = 0; s < surf.segment_count(); ++s) {
    const Index* c = &surf.conn[4 * static_cast<std::size_t>(s)];
    const int n = surf.is_triangle(s) ? 3 : 4;
    Vec3 centroid = Vec3::Zero();
    for (int a = 0; a < n; ++a) centroid += nodes.x0.get(c[a]);
    if (inside(box, centroid / n)) out.append_segment(surf, s);
  }
  build_surface_adjacency(out);
  return out;
}

/// The mortar coupling (penalty_coupling 1, a deck's _MORTAR) is built for the penalty passes with
/// a slave surface (Types 3, 5, 10 and 12) and for the Lagrange constraints of Types 3, 5 and 10
/// (Type 12's mutual-pair rule is per segment); anywhere else it is refused, not ignored.
void check_coupling(const model::Contact& card) {
  if (card.penalty_coupling == 0) return;
  if (card.penalty_coupling != 1)
    throw InputError(where(card) + ": penalty coupling " + std::to_string(card.penalty_coupling) +
                     " is neither 0 (DYNA3D's rule) nor 1 (mortar)");
  const bool penalty_type = card.type == T::surface_to_surface || card.type == T::one_way ||
                            card.type == T::nodes_to_surface || card.type == T::automatic;
  if (!penalty_type)
    throw_contact_not_implemented(card, "the mortar coupling (_MORTAR) of a tied, tiebreak or sliding-only interface");
  if (card.enforcement == model::Enforcement::lagrange && card.type == T::automatic)
    throw_contact_not_implemented(card, "_MORTAR with _LAGRANGE on a type 12 (automatic) interface");
  if (card.sstyp == 4)
    throw_contact_not_implemented(card, "_MORTAR with a node-set slave side (SSTYP 4): the mortar coupling "
                                        "integrates over the slave segments");
}

/// The one table of what runs: throws NotImplementedError (or InputError for a combination that
/// means nothing) before anything is built.
void check_runs(const model::Contact& card) {
  check_coupling(card);
  const bool transducer = card.form == model::ContactForm::force_transducer;  // (the reader warns)
  if (card.penchk != 0 && card.penchk != 1 && !transducer)
    throw_contact_not_implemented(card, "PENCHK = " + std::to_string(card.penchk) + " (card 2; only 1 is built)");
  const bool penalty_sliding = card.enforcement == model::Enforcement::penalty &&
                               (card.type == T::surface_to_surface || card.type == T::one_way ||
                                card.type == T::nodes_to_surface || card.type == T::automatic);
  if (card.penchk == 1 && !penalty_sliding && !transducer)
    throw_contact_not_implemented(card, "PENCHK = 1 (card 2) off the penalty sliding interfaces (Types 3, 5, 10, 12 "
                                        "and the automatic cards)");
  const bool lagrange = card.enforcement == model::Enforcement::lagrange;
  const bool penalty = card.enforcement == model::Enforcement::penalty;
  switch (card.type) {
    case T::tied_surface:
    case T::tied_nodes:
    case T::tied_shell_edge:
      if (lagrange) throw_contact_not_implemented(card, "tied interfaces are kinematic; Lagrange enforcement is not run");
      return;
    case T::sliding_only:
      if (card.fs != 0.0 || card.fd != 0.0)
        throw InputError(where(card) + ": a sliding-only (type 1) interface is frictionless; FS and FD must be 0");
      return;
    case T::tiebreak_nodes:
    case T::tiebreak_surface:
      if (lagrange) throw_contact_not_implemented(card, "tiebreak interfaces are penalty only");
      if (card.vdc != 0.0) throw_contact_not_implemented(card, "viscous contact damping (VDC) of a tiebreak interface");
      if (card.soft != 0 || card.vc != 0.0)
        throw_contact_not_implemented(card, "SOFT = 1 or viscous friction (VC) on a tiebreak interface");
      if (card.sfs <= 0.0) throw InputError(at(card) + ": SFS of " +
                                            card_name(card) + " must be positive");
      return;
    case T::surface_to_surface:
    case T::one_way:
    case T::nodes_to_surface:
    case T::automatic:
      break;
  }
  if (lagrange && card.eroding)
    throw_contact_not_implemented(card, "the eroding cards run with penalty enforcement only");
  if (lagrange && card.form != model::ContactForm::dyna3d)
    throw_contact_not_implemented(card, "the LS-DYNA automatic cards run with penalty enforcement only");
  if (card.form == model::ContactForm::force_transducer) return;  // output only: any side types
  if (lagrange) {
    if (card.sliding_only_option)
      throw_contact_not_implemented(card, "the sliding-only option with Lagrange enforcement is not implemented");
    if (card.vc != 0.0 || card.vdc != 0.0 || card.soft != 0)
      throw_contact_not_implemented(card, "viscous friction (VC), viscous damping (VDC) and SOFT = 1 with Lagrange "
                                          "enforcement");
    return;
  }
  if (!penalty) throw_contact_not_implemented(card);
  if (card.sstyp == 4 && (card.type == T::surface_to_surface || card.type == T::one_way))
    throw_contact_not_implemented(card, "a node-set slave side (SSTYP 4) needs Type 5");
  const bool one_way_automatic = card.form == model::ContactForm::automatic_nodes_to_surface ||
                                 card.form == model::ContactForm::forming_one_way;
  if (card.sstyp == 4 && card.type == T::automatic && !one_way_automatic)
    throw InputError(where(card) + ": SSTYP = 4 (node set) is not a surface");
  if (card.type == T::automatic && card.form == model::ContactForm::dyna3d && card.msid != 0)
    throw_contact_not_implemented(card, "MSID (a master side apart from the slave side) with penalty enforcement");
}

/// The sides, and the checks that need them.
void resolve_sides(const model::Contact& card, const ContactBuildContext& ctx, InterfaceSpec& spec) {
  spec.slave = resolve_contact_side(card, true, ctx);
  spec.node_set_slaves = spec.slave.surface.nodes.empty();
  spec.single_surface = card.type == T::automatic && card.form == model::ContactForm::dyna3d && card.msid == 0;
  // A force transducer's master side is optional (MSID = 0: none).
  const bool no_master = card.form == model::ContactForm::force_transducer && card.msid == 0;
  if (no_master) return;
  spec.master = spec.single_surface ? spec.slave : resolve_contact_side(card, false, ctx);
  if (card.form == model::ContactForm::force_transducer) return;
  if (spec.master.surface.segment_count() == 0)
    throw InputError(at(card) + ": MSID of " + card_name(card) + " selects no master segments");
  if (card.type == T::tiebreak_surface && spec.slave.surface.segment_count() == 0)
    throw InputError(at(card) + ": SSID of " + card_name(card) +
                     " (DYNA3D type 9) must select slave segments (SSTYP 0, 2, 3 or 5), not a node set");
  if (card.type == T::tied_shell_edge)
    for (Index s = 0; s < spec.master.surface.segment_count(); ++s)
      if (spec.master.surface.kind[s] != SegmentKind::shell)
        throw InputError(where(card) + " (DYNA3D type 7) needs a shell master surface; MSID selects solid faces");
}

}  // namespace

ExponentialCoulomb contact_friction(const model::Contact& card) {
  if (card.fs < 0.0 || card.fd < 0.0 || card.dc < 0.0)
    throw InputError(where(card) + ": FS, FD and DC must not be negative");
  ExponentialCoulomb f;
  f.mu_s = card.fs;
  f.mu_k = card.fd > 0.0 ? card.fd : card.fs;  // FD = 0: constant coefficient FS
  f.beta = card.dc;
  return f;
}

InterfaceSpec resolve_interface(const model::Contact& card, std::size_t position, const ContactBuildContext& ctx) {
  check_runs(card);
  InterfaceSpec spec;
  spec.title = contact_title(card, position);
  spec.where = where(card);
  spec.type = card.type;
  spec.form = card.form;
  spec.enforcement = card.enforcement;
  spec.friction = contact_friction(card);
  resolve_sides(card, ctx, spec);
  const bool shells = card.type == T::automatic || ctx.model.control_contact.shlthk > 0;
  spec.slave_shells = ShellOffsetRule{shells, card.sst, card.sfst};
  // A single surface (Type 12 without MSID) is its own master: SST and SFST apply to both roles
  // (the reader refuses MST there).
  spec.master_shells = spec.single_surface ? spec.slave_shells : ShellOffsetRule{shells, card.mst, card.sfmt};
  spec.nodal_radius = card.radius > 0.0 ? card.radius : 0.5 * card.sst * card.sfst;
  spec.follow_thickness = ctx.model.control_contact.thkchg == 1 && card.type == T::automatic;
  if (spec.follow_thickness && ctx.model.shell_istupd != 0 && card.enforcement != model::Enforcement::penalty)
    throw NotImplementedError(spec.where +
                              ": THKCHG = 1 of *CONTROL_CONTACT (the shell offsets follow the thickness of "
                              "*CONTROL_SHELL ISTUPD) with the Lagrange enforcement is not implemented");
  spec.slave_stiffness = ctx.model.control_contact.slsfac * card.sfs;
  spec.master_stiffness = ctx.model.control_contact.slsfac * card.sfm;
  spec.sliding_only = card.sliding_only_option;
  if (card.vdc < 0.0) throw InputError(where(card) + ": VDC (viscous contact damping, % of critical) must be >= 0");
  spec.viscous_damping = card.vdc / 100.0;
  // IGNORE: the card's (optional card C), 0 meaning *CONTROL_CONTACT's (card 4).
  const int ignore = card.ignore != 0 ? card.ignore : ctx.model.control_contact.ignore;
  if (ignore < 0 || ignore > 2)
    throw InputError(where(card) + ": IGNORE must be 0, 1 or 2 (got " + std::to_string(ignore) + ")");
  spec.keep_initial_penetrations = ignore != 0;
  if (spec.keep_initial_penetrations && card.enforcement == model::Enforcement::lagrange)
    throw_contact_not_implemented(card, "IGNORE = 1, 2 (initial penetrations kept; optional card C or "
                                        "*CONTROL_CONTACT card 4) with Lagrange enforcement");
  spec.mortar_coupling = card.penalty_coupling == 1;
  // SOFT = 1 and VC: the reader admits them on the penalty sliding interfaces only.
  if (card.soft == 2) {
    // Segment-based contact (contact/segment_contact.hpp): the two-sided automatic card and the
    // automatic single surface, penalty, with friction (FS, FD, DC) and VDC, without the
    // node-based options.
    const bool s2s = card.form == model::ContactForm::automatic_surface_to_surface;
    const bool single = card.form == model::ContactForm::dyna3d && !card.automatic_general && !card.eroding;
    // Type 3 (*CONTACT_SURFACE_TO_SURFACE): the two-sided pass on solid faces (make_sliding_contact
    // refuses shells, whose one-sided treatment on the non-automatic card is not built).
    const bool type3 = card.type == T::surface_to_surface && card.form == model::ContactForm::dyna3d;
    if (!((card.type == T::automatic && (s2s || single)) || type3))
      throw_contact_not_implemented(card, "SOFT = 2 (segment-based contact, optional card A) is implemented on "
                                          "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE, *CONTACT_AUTOMATIC_SINGLE_SURFACE "
                                          "and *CONTACT_SURFACE_TO_SURFACE only");
    if (card.enforcement != model::Enforcement::penalty)
      throw_contact_not_implemented(card, "SOFT = 2 (segment-based contact) with _LAGRANGE enforcement");
    if (card.vc != 0.0 || card.penchk != 0 || card.penalty_coupling != 0)
      throw_contact_not_implemented(card, "SOFT = 2 (segment-based contact) with VC (viscous friction), PENCHK or "
                                          "_MORTAR is not implemented");
    if (card.sfm != card.sfs)
      throw_contact_not_implemented(card, "SOFT = 2 with SFM other than SFS (one stiffness per segment pair: SFS)");
    spec.segment_based = true;
    spec.search_interval = card.bsort;
  } else if (card.soft != 0 && card.soft != 1) {
    throw_contact_not_implemented(card, "SOFT = " + std::to_string(card.soft) + " (optional card A)");
  }
  if (card.sofscl < 0.0 || card.vc < 0.0) throw InputError(where(card) + ": SOFSCL and VC must not be negative");
  spec.soft_scale = card.soft == 1 ? (card.sofscl > 0.0 ? card.sofscl : 0.1) : 0.0;
  spec.viscous_friction = card.vc;
  const Real xpene = ctx.model.control_contact.xpene;
  if (card.penchk == 1 && !(xpene > 0.0))
    throw InputError(where(card) + ": PENCHK = 1 needs XPENE > 0 (*CONTROL_CONTACT card 2; 0 means 4)");
  spec.penetration_check = card.penchk == 1 ? xpene : 0.0;
  spec.enmass = ctx.model.control_contact.enmass;  // acts on eroding passes only (docs/contact_erosion.md)
  const bool by_segment = card.type == T::tiebreak_surface;
  spec.failure = TiebreakFailure{card.nflf, card.sflf, by_segment ? 2.0 : card.nen, by_segment ? 2.0 : card.mes};
  if (by_segment && card.form == model::ContactForm::automatic_surface_to_surface)
    spec.cohesive = TiebreakCohesive{card.option, card.param, card.eraten, card.erates, card.ct2cn, card.cn};
  spec.window = ContactWindow{card.bt, card.dt};
  spec.transmitted_output = card.type == T::automatic && card.form == model::ContactForm::dyna3d;
  spec.eroding_card = card.eroding;
  spec.snlog = card.snlog;
  spec.interior_faces = !card.eroding || card.erosop == 1 || card.iadj == 1;
  spec.interior_faces_between_parts_only = card.eroding && card.erosop == 0 && card.iadj == 1;
  spec.symmetry_faces_out = card.eroding && card.isym == 1;
  return spec;
}

std::vector<Real> slave_node_offsets(const ContactSide& side, const ShellOffsetRule& rule, Real radius) {
  return node_offsets(side.nodes, side.surface, rule, radius);
}

Surface node_set_faces(const std::vector<Index>& nodes, const ContactBuildContext& ctx, const std::string& context) {
  std::vector<Id> parts;
  for (const auto& [pid, part_nodes] : ctx.sets.part_nodes)
    if (std::any_of(nodes.begin(), nodes.end(),
                    [&](Index n) { return std::binary_search(part_nodes.begin(), part_nodes.end(), n); }))
      parts.push_back(pid);
  Surface faces;
  if (!parts.empty()) faces = build_surface_from_parts(ctx.blocks, ctx.nodes, parts, context);
  build_surface_adjacency(faces);
  return faces;
}

std::string contact_title(const model::Contact& card, std::size_t position) {
  if (!card.title.empty()) return card.title;
  if (card.cid != 0) return "contact_" + std::to_string(card.cid);
  return "contact_" + std::to_string(position);
}

void throw_contact_not_implemented(const model::Contact& card, const std::string& what) {
  const char* enforcement = card.enforcement == model::Enforcement::lagrange    ? ", Lagrange multiplier"
                            : card.enforcement == model::Enforcement::kinematic ? ", kinematic"
                                                                                 : ", penalty";
  throw NotImplementedError(where(card) + " (DYNA3D type " + std::to_string(static_cast<int>(card.type)) +
                            enforcement + ")" +
                            (what.empty() ? std::string(" is not implemented yet") : ": " + what));
}

ContactSide resolve_contact_side(const model::Contact& card, bool slave, const ContactBuildContext& ctx) {
  const Id sid = slave ? card.ssid : card.msid;
  const int typ = slave ? card.sstyp : card.mstyp;
  const std::string field = slave ? "SSID" : "MSID";
  const std::string context = at(card) + ": " + field + " of " + card_name(card);
  // SBOXID / MBOXID (domain limiting): only the side's nodes, and segments whose centroid, lie in
  // the box at the start; applied here once, at build time, so every interface type honours it.
  const Id boxid = slave ? card.sboxid : card.mboxid;
  const model::Box* box = nullptr;
  if (boxid != 0) {
    box = find_box(ctx.model, boxid);
    if (!box)
      throw InputError(at(card) + ": " + std::string(slave ? "SBOXID" : "MBOXID") + " of " + card_name(card) +
                       " refers to undefined box " + std::to_string(boxid) + " (*DEFINE_BOX)");
  }
  const std::string box_note = box ? " inside box " + std::to_string(boxid) : std::string();
  ContactSide side;
  switch (typ) {
    case 0: {
      const auto& segs = ctx.sets.segment_set(sid, context);
      side.surface = build_surface_from_segments(ctx.blocks, ctx.nodes, segs,
                                                 context + " (segment set " + std::to_string(sid) + ")");
      break;
    }
    case 2:
      side.parts = ctx.sets.part_set(sid, context);
      break;
    case 3:
      side.parts = {sid};
      break;
    case 4:
      if (!slave)
        throw InputError(context + ": MSTYP = 4 (node set) cannot be a master surface");
      side.nodes = ctx.sets.node_set(sid, context);
      if (box) {
        std::erase_if(side.nodes, [&](Index n) { return !inside(*box, ctx.nodes.x0.get(n)); });
        if (side.nodes.empty()) throw InputError(context + " selects no nodes" + box_note);
      }
      return side;
    case 5:
      side.parts = all_parts(ctx);
      break;
    default:
      throw InputError(context + ": set type " + std::string(slave ? "SSTYP" : "MSTYP") + " = " +
                       std::to_string(typ) +
                       " is not supported (0 segment set, 2 part set, 3 part, 4 node set, 5 all)");
  }
  if (!side.parts.empty())
    side.surface = build_surface_from_parts(ctx.blocks, ctx.nodes, side.parts, context);
  build_surface_adjacency(side.surface);
  if (box) side.surface = segments_in_box(side.surface, *box, ctx.nodes);
  side.nodes = side.surface.nodes;
  if (side.nodes.empty()) throw InputError(context + " selects no segments" + box_note);
  return side;
}

}  // namespace slideline
