// The keyword table: every keyword the reader reads, with its options, a one-line description and
// its card handler. The reader's dispatch (read_block, is_supported) and `blockcontact keywords`
// (supported_keywords) both go through it, so a keyword is read if and only if it is listed.
// Adding a keyword: its handler, then its row here (docs/keywords.md, "Adding a keyword"); a
// contact card is a row of model/contact_keywords.hpp instead, and appears here by itself.
#include <string>
#include <string_view>
#include <vector>

#include "keyword_card.hpp"
#include "slideline/io/keyword_table.hpp"

namespace slideline::keyword {
namespace {

using model::Model;
using Handler = void (*)(const Context&, Block&, Model&, const KeywordMatch&);

struct Entry {
  std::string name;
  /// The final option, '|' between alternatives ("_ID|_TITLE"); "" when none.
  std::string_view options;
  /// Options that come before the final one, each at most once, in any order (the contacts'
  /// _LAGRANGE, _SLIDING_ONLY and _MORTAR); bit k of KeywordMatch::modifiers is the k-th.
  std::string_view modifiers;
  std::string description;
  Handler read;
  const model::ContactKeyword* contact = nullptr;
};

template <void (*F)(const Context&, Block&, Model&)>
void plain(const Context& c, Block& b, Model& m, const KeywordMatch&) {
  F(c, b, m);
}

template <void (*F)(const Context&, Block&, Model&, bool)>
void with_option(const Context& c, Block& b, Model& m, const KeywordMatch& k) {
  F(c, b, m, k.option);
}

template <Real model::DatabaseControl::*Dt>
void database_dt(const Context& c, Block& b, Model& m, const KeywordMatch&) {
  read_database_dt(c, b, m.database.*Dt);
}

template <Axis A>
void load_body(const Context& c, Block& b, Model& m, const KeywordMatch&) {
  read_load_body(c, b, m, A);
}

template <model::PrescribedMotion::Target T>
void prescribed(const Context& c, Block& b, Model& m, const KeywordMatch& k) {
  read_prescribed(c, b, m, k.option, T);
}

template <bool Node>
void spc(const Context& c, Block& b, Model& m, const KeywordMatch& k) {
  read_spc(c, b, m, k.option, Node);
}

template <bool Set>
void load_node(const Context& c, Block& b, Model& m, const KeywordMatch&) {
  read_load_node(c, b, m, Set);
}

template <void (*F)(const Context&, Block&)>
void parameters(const Context& c, Block& b, Model&, const KeywordMatch&) {
  F(c, b);
}

void nothing(const Context&, Block&, Model&, const KeywordMatch&) {}

// The contact rows' modifiers: bit 0 _LAGRANGE, bit 1 _SLIDING_ONLY, bit 2 _MORTAR. Every contact
// row takes all three, so that _SLIDING_ONLY or _MORTAR where it means nothing is an error naming
// it (read_contact), not an unknown keyword.
constexpr std::string_view kContactModifiers = "_LAGRANGE|_SLIDING_ONLY|_MORTAR";

void contact(const Context& c, Block& b, Model& m, const KeywordMatch& k) {
  read_contact(c, b, m, *k.contact, k.option, ContactOptions{(k.modifiers & 1u) != 0, (k.modifiers & 2u) != 0,
                                                             (k.modifiers & 4u) != 0});
}

using Target = model::PrescribedMotion::Target;
using Db = model::DatabaseControl;

struct Row {
  std::string_view name, options, description;
  Handler read;
};

constexpr Row kRows[] = {
    {"*KEYWORD", "", "start of the deck; LONG=Y and I10=Y set the file's card format", nothing},
    {"*TITLE", "", "the deck's title", plain<read_title>},
    {"*KEYWORD_ID", "", "start of the deck with an identification card (PROJECT NUM STAGE, kept as text)",
     plain<read_keyword_id>},
    {"*CONTROL_TERMINATION", "", "end time (ENDTIM), end cycle, minimum step, energy change",
     plain<read_control_termination>},
    {"*CONTROL_TIMESTEP", "", "time-step scale factor TSSFAC, step controls, DT2MS mass scaling", plain<read_control_timestep>},
    {"*CONTROL_HOURGLASS", "", "default hourglass type and coefficient", plain<read_control_hourglass>},
    {"*CONTROL_BULK_VISCOSITY", "", "default bulk viscosity (quadratic Q1, linear Q2)",
     plain<read_control_bulk_viscosity>},
    {"*CONTROL_CONTACT", "", "contact defaults (SLSFAC penalty scale, shell thickness, orientation)",
     plain<read_control_contact>},
    {"*CONTROL_SHELL", "",
     "shell controls: ESORT, ISTUPD (1, 4) and INTGRD stored; the other fields at their default or refused (THEORY, "
     "BWC, ...)",
     plain<read_control_fields>},
    {"*CONTROL_ACCURACY", "", "accuracy controls: OSU, INN, ... at their defaults or refused", plain<read_control_fields>},
    {"*CONTROL_SOLID", "", "solid controls: every field at its default or refused", plain<read_control_fields>},
    {"*DATABASE_RCFORC", "", "output interval of the contact interface forces", database_dt<&Db::rcforc>},
    {"*DATABASE_SPCFORC", "", "output interval of the support reactions", database_dt<&Db::spcforc>},
    {"*DATABASE_NODOUT", "", "output interval of the node histories", database_dt<&Db::nodout>},
    {"*DATABASE_GLSTAT", "", "output interval of the global energies", database_dt<&Db::glstat>},
    {"*DATABASE_BINARY_D3PLOT", "", "output interval of the field states", database_dt<&Db::d3plot>},
    {"*DATABASE_HISTORY_NODE", "", "nodes whose histories are written", plain<read_database_history_node>},
    {"*NODE", "", "nodes: id and coordinates", plain<read_nodes>},
    {"*ELEMENT_SOLID", "", "8-node hexahedra (one or two cards each)", plain<read_solids>},
    {"*ELEMENT_SHELL", "", "4-node shells", plain<read_shells>},
    {"*PART", "", "part: section, material and hourglass ids", plain<read_parts>},
    {"*SECTION_SOLID", "_TITLE", "solid section (ELFORM 1: one-point hexahedron)", with_option<read_section_solid>},
    {"*SECTION_SHELL", "_TITLE", "shell section: formulation, integration points, thickness",
     with_option<read_section_shell>},
    {"*MAT_ELASTIC", "_TITLE", "material 1: linear elastic (solids and shells)", with_option<read_mat_elastic>},
    {"*MAT_001", "_TITLE", "material 1 by number: as *MAT_ELASTIC", with_option<read_mat_elastic>},
    {"*MAT_MOONEY-RIVLIN_RUBBER", "_TITLE", "material 27: Mooney-Rivlin rubber (solids)",
     with_option<read_mat_mooney_rivlin>},
    {"*MAT_027", "_TITLE", "material 27 by number: as *MAT_MOONEY-RIVLIN_RUBBER", with_option<read_mat_mooney_rivlin>},
    {"*MAT_RIGID", "_TITLE", "material 20: rigid body, with its constraints", with_option<read_mat_rigid>},
    {"*MAT_020", "_TITLE", "material 20 by number: as *MAT_RIGID", with_option<read_mat_rigid>},
    {"*MAT_PLASTIC_KINEMATIC", "_TITLE", "material 3: J2 plasticity, isotropic/kinematic hardening (solids, shells)",
     with_option<read_mat_plastic_kinematic>},
    {"*MAT_003", "_TITLE", "material 3 by number: as *MAT_PLASTIC_KINEMATIC", with_option<read_mat_plastic_kinematic>},
    {"*MAT_PIECEWISE_LINEAR_PLASTICITY", "_TITLE", "material 24: J2 plasticity, yield curve (solids, shells)",
     with_option<read_mat_piecewise_linear>},
    {"*MAT_024", "_TITLE", "material 24 by number: as *MAT_PIECEWISE_LINEAR_PLASTICITY", with_option<read_mat_piecewise_linear>},
    {"*MAT_NULL", "_TITLE", "material 9: shells with mass only; solids with an equation of state (EOSID of *PART)",
     with_option<read_mat_null>},
    {"*MAT_009", "_TITLE", "material 9 by number: as *MAT_NULL", with_option<read_mat_null>},
    {"*EOS_LINEAR_POLYNOMIAL", "", "equation of state 1: p = C0 + C1 mu + ... + (C4 + C5 mu + C6 mu^2) E (*MAT_NULL solids)",
     plain<read_eos_linear_polynomial>},
    {"*EOS_GRUNEISEN", "", "equation of state 4: Mie-Gruneisen on the shock Hugoniot Us = C + S1 up + ... (*MAT_NULL solids)",
     plain<read_eos_gruneisen>},
    {"*EOS_TABULATED", "", "equation of state 9: p = C(ln V) + GAMA T(ln V) E, 10-point tables (*MAT_NULL solids)",
     plain<read_eos_tabulated>},
    {"*MAT_ADD_EROSION", "_TITLE", "failure criteria of a material: pressure, principal and von Mises stress, time",
     with_option<read_mat_add_erosion>},
    {"*HOURGLASS", "_TITLE", "hourglass control of the parts that name it", with_option<read_hourglass>},
    {"*SET_NODE_LIST", "_TITLE", "node set", with_option<read_set_node>},
    {"*SET_NODE", "_TITLE", "node set (as *SET_NODE_LIST)", with_option<read_set_node>},
    {"*SET_NODE_LIST_GENERATE", "_TITLE", "node set of id ranges (defined nodes with BEG <= id <= END)",
     with_option<read_set_node_generate>},
    {"*SET_NODE_GENERAL", "_TITLE", "node set by rules: ALL, NODE, PART, BOX (DNODE, DPART, DBOX remove)",
     with_option<read_set_node_general>},
    {"*SET_SEGMENT", "_TITLE", "segment set: 4 nodes per segment", with_option<read_set_segment>},
    {"*SET_PART_LIST", "_TITLE", "part set", with_option<read_set_part>},
    {"*SET_PART", "_TITLE", "part set (as *SET_PART_LIST)", with_option<read_set_part>},
    {"*BOUNDARY_SPC_SET", "_ID", "fixed degrees of freedom of a node set (reactions output)", spc<false>},
    {"*BOUNDARY_SPC_NODE", "_ID", "fixed degrees of freedom of one node", spc<true>},
    {"*BOUNDARY_PRESCRIBED_MOTION_SET", "_ID", "prescribed displacement, velocity or acceleration of a node set",
     prescribed<Target::set>},
    {"*BOUNDARY_PRESCRIBED_MOTION_NODE", "_ID", "prescribed motion of one node", prescribed<Target::node>},
    {"*BOUNDARY_PRESCRIBED_MOTION_RIGID", "_ID", "prescribed motion of a rigid part", prescribed<Target::rigid>},
    {"*LOAD_NODE_POINT", "", "concentrated force on a node, scaled by a curve", load_node<false>},
    {"*LOAD_NODE_SET", "", "concentrated force on each node of a set", load_node<true>},
    {"*LOAD_BODY_X", "", "body acceleration in x (load = acceleration x mass)", load_body<Axis::x>},
    {"*LOAD_BODY_Y", "", "body acceleration in y", load_body<Axis::y>},
    {"*LOAD_BODY_Z", "", "body acceleration in z", load_body<Axis::z>},
    {"*LOAD_BODY_PARTS", "", "the part set the body loads act on", plain<read_load_body_parts>},
    {"*RIGIDWALL_PLANAR", "_ID", "stationary planar rigid wall, kinematic, with friction and force output",
     with_option<read_rigidwall_planar>},
    {"*RIGIDWALL_PLANAR_FINITE", "_ID", "stationary rectangular rigid wall (as *RIGIDWALL_PLANAR)",
     with_option<read_rigidwall_planar_finite>},
    {"*INITIAL_VELOCITY", "", "initial velocity of a node set", plain<read_initial_velocity>},
    {"*INITIAL_VELOCITY_NODE", "", "initial velocity of single nodes", plain<read_initial_velocity_node>},
    {"*INITIAL_VELOCITY_GENERATION", "", "initial velocity of a part or part set (translation and rotation)",
     plain<read_initial_velocity_generation>},
    {"*DEFINE_CURVE", "_TITLE", "load curve (piecewise linear, with scale factors and offsets)",
     with_option<read_curve>},
    {"*DEFINE_BOX", "_TITLE", "box (limits a contact side to what lies inside it)", with_option<read_box>},
    {"*DEFINE_COORDINATE_SYSTEM", "_TITLE", "local Cartesian system from three points (origin, x axis, x-y plane)",
     with_option<read_define_coordinate_system>},
    {"*DEFINE_COORDINATE_NODES", "_TITLE", "local Cartesian system from three nodes", with_option<read_define_coordinate_nodes>},
    {"*DEFINE_COORDINATE_VECTOR", "_TITLE", "local Cartesian system from two vectors (x axis, x-y plane)",
     with_option<read_define_coordinate_vector>},
    {"*DAMPING_GLOBAL", "", "mass-proportional damping of the whole model", plain<read_damping_global>},
    {"*DAMPING_PART_MASS", "_SET", "mass-proportional damping of a part (or a part set)",
     with_option<read_damping_part>},
    {"*DAMPING_PART_STIFFNESS", "_SET", "stiffness-proportional damping of a part (or a part set)",
     with_option<read_damping_stiffness>},
    {"*PARAMETER", "_LOCAL", "named values, used in fields as &name", parameters<read_parameter_values>},
    {"*PARAMETER_EXPRESSION", "_LOCAL", "named values computed from an expression",
     parameters<read_parameter_expressions>},
};

/// "contact, DYNA3D type 3 surface to surface; penalty unless _LAGRANGE". Whether a type runs
/// with Lagrange multipliers is checked when the model is built (check_runs, interface_spec.cpp).
std::string contact_description(const model::ContactKeyword& k) {
  // An LS-DYNA card without a DYNA3D number (model::ContactForm): runs with the type's pass.
  if (k.form == model::ContactForm::force_transducer)
    return "contact force transducer: the contact force on its side(s) as an interface history; adds no force";
  if (k.eroding)
    return "contact, LS-DYNA " + std::string(k.name) + ": the automatic pass of DYNA3D type 12 with its surfaces "
           "updated as elements erode (card 4: ISYM, EROSOP, IADJ); penalty";
  if (k.form != model::ContactForm::dyna3d && k.type == model::ContactType::tiebreak_surface)
    return "contact, LS-DYNA " + std::string(k.name) + ": OPTION 1, DYNA3D type 9's tie and failure law, then the "
           "automatic surface-to-surface pass; penalty";
  if (k.form != model::ContactForm::dyna3d)
    return "contact, LS-DYNA " + std::string(k.name) + " on DYNA3D type " + std::to_string(k.dyna3d_type) +
           "'s automatic pass; penalty (_LAGRANGE is refused when the model is built)" +
           (k.mortar_option ? "; _MORTAR: mortar coupling" : "");
  std::string s = "contact, DYNA3D type " + std::to_string(k.dyna3d_type) + " " + std::string(k.name) + "; " +
                  std::string(model::enforcement_name(k.enforcement)) + " unless _LAGRANGE";
  if (k.sliding_option) s += "; _SLIDING_ONLY: no separation";
  if (k.mortar_option) s += "; _MORTAR: mortar coupling";
  return s;
}

const std::vector<Entry>& table() {
  static const std::vector<Entry> entries = [] {
    std::vector<Entry> e;
    for (const auto& r : kRows)
      e.push_back({std::string(r.name), r.options, "", std::string(r.description), r.read, nullptr});
    for (const auto& k : model::kContactKeywords)
      e.push_back({std::string(k.keyword), "_ID|_TITLE", kContactModifiers, contact_description(k), contact, &k});
    return e;
  }();
  return entries;
}

/// Removes from the end of `s` the first alternative of `list` ('|'-separated) that ends it;
/// returns its index, or -1 when none does.
int strip_alternative(std::string_view& s, std::string_view list) {
  for (int k = 0; !list.empty(); ++k) {
    const auto bar = list.find('|');
    const std::string_view alt = list.substr(0, bar);
    if (!alt.empty() && s.size() >= alt.size() && s.substr(s.size() - alt.size()) == alt) {
      s.remove_suffix(alt.size());
      return k;
    }
    if (bar == std::string_view::npos) break;
    list.remove_prefix(bar + 1);
  }
  return -1;
}

/// Whether `kw` is the entry's name followed by modifiers (each at most once) and at most one
/// final option, filling `out`.
bool matches(const Entry& e, std::string_view kw, KeywordMatch& out) {
  if (kw.substr(0, e.name.size()) != e.name) return false;
  std::string_view rest = kw.substr(e.name.size());
  out = KeywordMatch{};
  out.contact = e.contact;
  out.option = strip_alternative(rest, e.options) >= 0;
  while (!rest.empty()) {
    const int k = strip_alternative(rest, e.modifiers);
    if (k < 0 || (out.modifiers & (1u << k)) != 0) return false;
    out.modifiers |= 1u << k;
  }
  return true;
}

const Entry* find_entry(std::string_view kw, KeywordMatch& match) {
  for (const auto& e : table())
    if (matches(e, kw, match)) return &e;
  return nullptr;
}

/// "[_SLIDING_ONLY][_MORTAR][_LAGRANGE][_ID|_TITLE]": what a reader of the deck may write after the
/// name (a contact's _SLIDING_ONLY and _MORTAR only where they mean something).
std::string option_text(const Entry& e) {
  std::string s;
  if (e.contact && e.contact->sliding_option) s += "[_SLIDING_ONLY]";
  if (e.contact && e.contact->mortar_option) s += "[_MORTAR]";
  if (e.contact) s += "[_LAGRANGE]";
  if (!e.options.empty()) s.append("[").append(e.options).append("]");
  return s;
}

}  // namespace

bool is_supported(std::string_view kw) {
  KeywordMatch match;
  return find_entry(kw, match) != nullptr;
}

bool read_block(const Context& ctx, Block& block, model::Model& model) {
  KeywordMatch match;
  const Entry* e = find_entry(block.keyword, match);
  if (!e) return false;
  e->read(ctx, block, model, match);
  return true;
}

}  // namespace slideline::keyword

namespace slideline {

const std::vector<KeywordInfo>& supported_keywords() {
  static const std::vector<KeywordInfo> info = [] {
    std::vector<KeywordInfo> v;
    for (const auto& e : keyword::table()) v.push_back({e.name, keyword::option_text(e), e.description});
    return v;
  }();
  return info;
}

bool reads_keyword(std::string_view keyword) { return keyword::is_supported(keyword); }

}  // namespace slideline
