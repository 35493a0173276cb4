#pragma once
// Internal to the keyword reader: deck lines grouped into keyword blocks, and field access on one
// card (fixed columns or free format, standard or long format, &parameter substitution) with
// located error messages. Not installed.
#include <deque>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "slideline/core/types.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/model/contact_keywords.hpp"
#include "slideline/model/model.hpp"

namespace slideline::keyword {

/// Field widths of a card: standard, I10 (fields narrower than 10 become 10) or long (every
/// field 20 wide).
enum class Format : std::uint8_t { standard, i10, wide };

struct Line {
  std::string_view text;
  int number = 0;  // 1-based line number in the file
  Format format = Format::standard;
};

/// One keyword and the data cards under it (comment lines removed, blank lines kept: a blank
/// card is a card of defaults).
struct Block {
  std::string keyword;  // upper-case, with the leading '*' and without a format suffix (+ - %)
  int line = 0;
  std::vector<Line> cards;
  std::size_t next = 0;

  bool done() const { return next >= cards.size(); }
  /// The next card, or nullptr when the block is exhausted.
  const Line* take() { return done() ? nullptr : &cards[next++]; }
};

/// A *PARAMETER value: its type letter (R, I or C) and the text substituted for &name.
struct Parameter {
  char type = 'R';
  std::string text;
  Real value = 0.0;  // for R and I
};

/// One line of a *SET_NODE_GENERAL (OPTION E1..E7) or one range of *SET_NODE_LIST_GENERATE
/// (option "RANGE", ids {BEG, END}), resolved once the whole deck is read (keyword_sets.cpp).
struct NodeSetRule {
  std::string option;
  std::vector<Id> ids;
  std::string file;
  int line = 0;
};

/// A node set whose nodes depend on cards that may come later (nodes, elements, boxes).
struct PendingNodeSet {
  std::size_t index = 0;  // into model::Model::node_sets
  std::vector<NodeSetRule> rules;
};

/// Reading state shared by the card handlers of every file of a deck (the main file and its
/// *INCLUDEs). Each file has its own Context pointing at it.
struct DeckState {
  std::map<std::string, Parameter, std::less<>> parameters;  // upper-case names
  std::vector<PendingNodeSet> node_sets;                      // generated sets, resolved at the end
};

/// Reading state of one file.
struct Context {
  std::string file;
  std::vector<Diagnostic>* warnings = nullptr;
  DeckState* deck = nullptr;
  int file_index = 0;  // index of `file` in model::Model::files
  void warn(int line, std::string message) const {
    if (warnings) warnings->push_back({file, line, std::move(message)});
  }
  model::Source source(int line) const { return {file, line}; }
  /// "file:line: "
  std::string where(int line) const { return file + ":" + std::to_string(line) + ": "; }
};

// Column layouts (field widths) of the card formats.
inline constexpr int kStandard[] = {10, 10, 10, 10, 10, 10, 10, 10};
inline constexpr int kNodeCard[] = {8, 16, 16, 16, 8, 8};
inline constexpr int kElementCard[] = {8, 8, 8, 8, 8, 8, 8, 8, 8, 8};
inline constexpr int kCurvePoint[] = {20, 20};

/// Field access on one card. Blank fields leave the target untouched (the model default).
/// A field holding `&name` (or `-&name`) takes the value of *PARAMETER name.
class Card {
 public:
  Card(const Context& ctx, const Line& line, std::string_view keyword, std::span<const int> widths);

  /// Number of fields the layout or free-format card holds.
  int size() const { return static_cast<int>(free_ ? free_fields_.size() : widths_.size()); }
  bool blank(int i) const;
  /// The trimmed text of field i ("" when absent), parameters substituted.
  std::string_view raw(int i) const;

  void get(int i, const char* name, Real& out) const;
  void get(int i, const char* name, int& out) const;
  void get(int i, const char* name, Id& out) const;
  /// LS-DYNA's rule for a field with a manual default: blank and 0 both mean the default, which is
  /// the value `out` holds on entry (the model's default). Any other value is stored.
  void get_or_default(int i, const char* name, Real& out) const;
  void get_or_default(int i, const char* name, int& out) const;
  /// True when every field is blank.
  bool all_blank() const;
  int line() const { return line_.number; }

 private:
  [[noreturn]] void fail(int i, const char* name, const char* expected) const;
  /// Refuses a number written across the end of field i or of the field before it (fixed format).
  void check_field_boundaries(int i, const char* name) const;
  std::string_view field_text(int i) const;
  int width(int k) const;
  std::string place(int i) const;

  const Context& ctx_;
  Line line_;
  std::string_view keyword_;
  std::span<const int> widths_;
  bool free_ = false;
  std::vector<std::string_view> free_fields_;
  mutable std::deque<std::string> substituted_;  // texts of &name fields (a deque: views stay valid)
};

/// Parses a real number (Fortran 'D' exponents and exponents without a letter, "1.5-3", accepted);
/// false if not a finite number.
bool parse_real(std::string_view s, Real& out);
/// Parses an integer (an integral real such as "3." is accepted); false if not an integer.
bool parse_integer(std::string_view s, Id& out);

std::string_view trim(std::string_view s);
std::string upper(std::string_view s);

/// A heading card: the whole line, trimmed.
std::string heading(const Line& line);
/// An _ID card: ID in columns 1-10 and the heading after it (or "id, heading" in free format).
void read_id_heading(const Context& ctx, const Line& line, std::string_view keyword, Id& id,
                     std::string& title);

}  // namespace slideline::keyword

namespace slideline::keyword {

/// How a keyword as written matched its row of the keyword table (keyword_table.cpp): whether it
/// carries the row's final option (_TITLE, _ID, _SET or _LOCAL) and which of the row's other
/// options (bit k: the k-th; the contact rows' _LAGRANGE, _SLIDING_ONLY and _MORTAR) it carries.
struct KeywordMatch {
  bool option = false;
  unsigned modifiers = 0;
  const model::ContactKeyword* contact = nullptr;  ///< the contact rows' card
};

/// Reads one block into the model through the keyword table. Returns false when the keyword is
/// not supported (the caller classifies it, see keyword_unsupported.cpp). Throws InputError on a
/// malformed card.
bool read_block(const Context& ctx, Block& block, model::Model& model);

/// True when read_block handles this keyword (so its cards are worth keeping in memory).
bool is_supported(std::string_view keyword);

/// The options of a contact keyword as written (before its _ID / _TITLE).
struct ContactOptions {
  bool lagrange = false;  ///< _LAGRANGE
  bool sliding = false;   ///< _SLIDING_ONLY
  bool mortar = false;    ///< _MORTAR
};

/// A *CONTACT_... card of the contact keyword table's row `row` (keyword_contacts.cpp); `heading`
/// for the _ID / _TITLE option.
void read_contact(const Context& ctx, Block& block, model::Model& model, const model::ContactKeyword& row,
                  bool heading, ContactOptions options);

// keyword_initial.cpp: *INITIAL_VELOCITY, _NODE and _GENERATION.
void read_initial_velocity(const Context& ctx, Block& block, model::Model& model);
void read_initial_velocity_node(const Context& ctx, Block& block, model::Model& model);
void read_initial_velocity_generation(const Context& ctx, Block& block, model::Model& model);

// keyword_parameters.cpp: *PARAMETER and *PARAMETER_EXPRESSION (with or without _LOCAL).
void read_parameter_values(const Context& ctx, Block& block);
void read_parameter_expressions(const Context& ctx, Block& block);
/// Evaluates an arithmetic expression over numbers and parameters (keyword_parameters.cpp);
/// throws InputError naming `where` on a syntax error, an unknown name or a non-finite result.
Real evaluate_expression(std::string_view expr, const DeckState& deck, const std::string& where);

/// Warns about non-blank cards left in a block whose reader took what it needs.
void warn_extra_cards(const Context& ctx, Block& block);

/// The next card of `b`, or throws InputError "missing <what> card" naming the keyword's line.
const Line& require_card(const Context& ctx, Block& b, const char* what);

/// Cards whose fields beyond those the model stores are checked by check_unread_fields (the order
/// of its rule tables in keyword_contact_fields.cpp).
enum class StoredCard : std::uint8_t {
  part,                     ///< *PART card 2: GRAV, ADPOPT, TMID
  mat_elastic,              ///< *MAT_ELASTIC: DA, DB, K
  mat_mooney_rivlin,        ///< *MAT_MOONEY-RIVLIN_RUBBER card 1: REF
  mat_rigid,                ///< *MAT_RIGID card 1: N, COUPLE, M (ALIAS is text)
  control_bulk_viscosity,   ///< BTYPE, TSTYPE
  control_termination,      ///< ENDMAS, NOSOL
  control_timestep,         ///< card 1: ERODE, MS1ST
  control_timestep_card2,   ///< DT2MSF, DT2MSLC, IMSCL, RMSCL, EMSCL, IHDO
  define_curve,             ///< LCINT
  none,                     ///< a card whose reader stores every field it reads
};
/// Refuses (NotImplementedError naming file, line and field) or warns about the fields of `card`
/// that the reader does not store when they are not at their manual default (0 and blank both
/// mean the default): what was read and dropped before. docs/keywords.md lists them.
void check_unread_fields(const Context& ctx, const Line& card, std::string_view keyword, StoredCard which);

/// One *MAT_... card group: the title (when titled), card 1 read by `fields` (its Card, with the
/// block to take further cards from), then the title, source and model entry every material
/// shares. Adding a material = a model struct and one call of this with its fields.
/// `card1` names the rules for the fields of card 1 that the model does not store (check_unread_fields).
template <class Mat, class Fields>
void read_material(const Context& ctx, Block& b, model::Model& m, bool titled, StoredCard card1, Fields&& fields) {
  std::string title = titled ? heading(require_card(ctx, b, "title")) : std::string();
  const Line& l = require_card(ctx, b, "MID");
  Mat mat;
  fields(Card(ctx, l, b.keyword, kStandard), mat);
  check_unread_fields(ctx, l, b.keyword, card1);
  mat.title = std::move(title);
  mat.src = ctx.source(l.number);
  m.materials.emplace_back(std::move(mat));
  warn_extra_cards(ctx, b);
}

/// read_material for a card whose reader stores every field of card 1.
template <class Mat, class Fields>
void read_material(const Context& ctx, Block& b, model::Model& m, bool titled, Fields&& fields) {
  read_material<Mat>(ctx, b, m, titled, StoredCard::none, std::forward<Fields>(fields));
}

/// Runs `f` on the first card of a single-card keyword (no card: all defaults).
template <class F>
void single_card(const Context& ctx, Block& b, F&& f) {
  if (const Line* l = b.take()) f(Card(ctx, *l, b.keyword, kStandard), *l);
  warn_extra_cards(ctx, b);
}

// keyword_cards.cpp: the other card handlers. `titled` / `with_id` / `set`: the keyword carries its
// table row's option (_TITLE, _ID, _SET).
void read_title(const Context& ctx, Block& block, model::Model& model);
void read_nodes(const Context& ctx, Block& block, model::Model& model);
void read_solids(const Context& ctx, Block& block, model::Model& model);
void read_shells(const Context& ctx, Block& block, model::Model& model);
void read_parts(const Context& ctx, Block& block, model::Model& model);
void read_section_solid(const Context& ctx, Block& block, model::Model& model, bool titled);
void read_section_shell(const Context& ctx, Block& block, model::Model& model, bool titled);
void read_mat_elastic(const Context& ctx, Block& block, model::Model& model, bool titled);
void read_mat_mooney_rivlin(const Context& ctx, Block& block, model::Model& model, bool titled);
void read_mat_rigid(const Context& ctx, Block& block, model::Model& model, bool titled);
void read_mat_plastic_kinematic(const Context& ctx, Block& block, model::Model& model, bool titled);
void read_mat_piecewise_linear(const Context& ctx, Block& block, model::Model& model, bool titled);
void read_mat_null(const Context& ctx, Block& block, model::Model& model, bool titled);
/// *EOS_LINEAR_POLYNOMIAL, *EOS_GRUNEISEN, *EOS_TABULATED (keyword_eos.cpp).
void read_eos_linear_polynomial(const Context& ctx, Block& block, model::Model& model);
void read_eos_gruneisen(const Context& ctx, Block& block, model::Model& model);
void read_eos_tabulated(const Context& ctx, Block& block, model::Model& model);
/// *MAT_ADD_EROSION (keyword_add_erosion.cpp).
void read_mat_add_erosion(const Context& ctx, Block& block, model::Model& model, bool titled);
void read_hourglass(const Context& ctx, Block& block, model::Model& model, bool titled);
void read_set_node(const Context& ctx, Block& block, model::Model& model, bool titled);
void read_set_part(const Context& ctx, Block& block, model::Model& model, bool titled);
void read_set_segment(const Context& ctx, Block& block, model::Model& model, bool titled);
/// *BOUNDARY_SPC_SET (`node` false) or _NODE.
void read_spc(const Context& ctx, Block& block, model::Model& model, bool with_id, bool node);
void read_prescribed(const Context& ctx, Block& block, model::Model& model, bool with_id,
                     model::PrescribedMotion::Target target);
/// *LOAD_NODE_POINT (`set` false) or _SET.
void read_load_node(const Context& ctx, Block& block, model::Model& model, bool set);
void read_load_body(const Context& ctx, Block& block, model::Model& model, Axis axis);
void read_load_body_parts(const Context& ctx, Block& block, model::Model& model);
void read_curve(const Context& ctx, Block& block, model::Model& model, bool titled);
void read_box(const Context& ctx, Block& block, model::Model& model, bool titled);
void read_damping_global(const Context& ctx, Block& block, model::Model& model);
void read_damping_part(const Context& ctx, Block& block, model::Model& model, bool set);
void read_damping_stiffness(const Context& ctx, Block& block, model::Model& model, bool set);
void read_database_history_node(const Context& ctx, Block& block, model::Model& model);
/// *DATABASE_...: one card, DT the output interval, into `dt`.
void read_database_dt(const Context& ctx, Block& block, Real& dt);

// keyword_sets.cpp: *KEYWORD_ID, *SET_NODE_LIST_GENERATE and *SET_NODE_GENERAL (`titled`: _TITLE).
void read_keyword_id(const Context& ctx, Block& block, model::Model& model);
void read_set_node_generate(const Context& ctx, Block& block, model::Model& model, bool titled);
void read_set_node_general(const Context& ctx, Block& block, model::Model& model, bool titled);
/// Fills the node lists of the generated sets once every file of the deck is read (their nodes,
/// parts and boxes may come after them). Throws InputError naming the card's file, line and field
/// for a part or box the deck does not define.
void resolve_node_sets(const DeckState& deck, model::Model& model);

// keyword_coordinate_systems.cpp: *DEFINE_COORDINATE_SYSTEM, _NODES and _VECTOR (`titled`: _TITLE).
void read_define_coordinate_system(const Context& ctx, Block& block, model::Model& model, bool titled);
void read_define_coordinate_nodes(const Context& ctx, Block& block, model::Model& model, bool titled);
void read_define_coordinate_vector(const Context& ctx, Block& block, model::Model& model, bool titled);

// keyword_rigidwall.cpp: *RIGIDWALL_PLANAR and *RIGIDWALL_PLANAR_FINITE (`with_id`: the _ID option).
void read_rigidwall_planar(const Context& ctx, Block& block, model::Model& model, bool with_id);
void read_rigidwall_planar_finite(const Context& ctx, Block& block, model::Model& model, bool with_id);

// keyword_controls.cpp: *CONTROL_HOURGLASS, _BULK_VISCOSITY, _TERMINATION, _TIMESTEP, _CONTACT.
void read_control_hourglass(const Context& ctx, Block& block, model::Model& model);
void read_control_bulk_viscosity(const Context& ctx, Block& block, model::Model& model);
void read_control_termination(const Context& ctx, Block& block, model::Model& model);
void read_control_timestep(const Context& ctx, Block& block, model::Model& model);
void read_control_contact(const Context& ctx, Block& block, model::Model& model);
/// *CONTROL_SHELL, *CONTROL_ACCURACY, *CONTROL_SOLID: nothing to store; every field checked.
void read_control_fields(const Context& ctx, Block& block, model::Model& model);

// keyword_contact_fields.cpp: the fields of *CONTACT_... and *CONTROL_CONTACT that the solver does
// not act on. Each is at its default, refused (NotImplementedError naming file, line and field) or,
// when it only tunes output or speed or cannot act here, warned about. See docs/contact.md.

/// Checks cards 1-3 (and the tiebreak card 4, `card4`, may be null) of a contact already read into
/// `c` against what its type and enforcement honour. `lines` are cards 1, 2 and 3 (null if absent).
void check_contact_fields(const Context& ctx, const model::Contact& c, const Line* card1, const Line* card2,
                          const Line* card3, const Line* card4);
/// Refuses the *SECTION_SOLID / *SECTION_SHELL (`shell`) fields the model does not hold when they
/// are not at their default (AET; QR/IRID, ICOMP, SETYP, NLOC, MAREA, IDOF, EDGSET); PROPT warns.
void check_section_fields(const Context& ctx, const Line& card1, const Line* card2, std::string_view keyword,
                          bool shell);
/// Refuses *HOURGLASS QB / QW other than 0 or QM (the shell hourglass takes QM for every mode).
void check_hourglass_fields(const Context& ctx, const Line& card, std::string_view keyword, Real qm);
/// Checks every card left in a *CONTROL_SHELL, *CONTROL_ACCURACY, *CONTROL_SOLID or
/// *CONTROL_BULK_VISCOSITY block (its Q1 Q2 are read by its handler): a field that changes the
/// physics and is not at its default is refused; a card beyond the manual's is refused.
void check_control_fields(const Context& ctx, Block& block);
/// keyword_contact_eroding.cpp: card 4 of *CONTACT_ERODING_... (ISYM EROSOP IADJ; the next card
/// left in `block`, if any) into `c`: ISYM, EROSOP and IADJ 0 or 1.
void read_eroding_card4(const Context& ctx, Block& block, model::Contact& c);
/// Reads the optional cards A-F of a *CONTACT_... keyword (what is left in the block): IGNORE of
/// card C into `c`, the other fields checked.
void read_contact_optional_cards(const Context& ctx, Block& block, model::Contact& c);
// keyword_contact_options.cpp: SOFT and SOFSCL (optional card A), VC (card 2).
/// Reads SOFT and SOFSCL from the next card left in `block` (optional card A, if any) into `c`:
/// SOFT = 1 honoured on the penalty sliding interfaces, warned about on kinematic ties and
/// Type 1, refused on tiebreaks and Lagrange; SOFT = 2, 4, 6 refused; other values an input error.
void read_contact_card_a(const Context& ctx, const Block& block, model::Contact& c);
/// Checks VC of card 2 (`card2`, may be null): honoured on the penalty sliding interfaces with
/// friction, warned about where there is no friction to cap, refused elsewhere; < 0 an input error.
void check_viscous_friction(const Context& ctx, const model::Contact& c, const Line* card2);
/// *CONTACT_FORCE_TRANSDUCER_PENALTY cards 1-3 (null if absent): SSID, MSID, SSTYP, MSTYP, BT and
/// DT are honoured; any other field off its default is warned about (nothing for it to act on).
void check_transducer_fields(const Context& ctx, const model::Contact& c, const Line* card1, const Line* card2,
                             const Line* card3);
/// Reads cards 2-6 of *CONTROL_CONTACT (what is left in the block) and checks card 1's fields
/// that the solver does not act on.
void read_control_contact_cards(const Context& ctx, Block& block, model::ControlContact& card1, int card1_line);

}  // namespace slideline::keyword
