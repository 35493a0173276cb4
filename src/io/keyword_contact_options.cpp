// The contact options of issue 20 that change the penalty springs and the friction of the penalty
// sliding interfaces (Types 3, 5, 10, 12 and the automatic cards): SOFT and SOFSCL of optional
// card A, VC of card 2. Each is honoured there; elsewhere it is refused (file, line, field) or,
// where the interface has nothing for it to act on, warned about. docs/contact.md, "Contact card
// fields" and "Soft constraint (SOFT = 1)".
#include <cstdio>
#include <string>

#include "keyword_card.hpp"
#include "slideline/core/error.hpp"

namespace slideline::keyword {
namespace {

using model::ContactType;
using model::Enforcement;

std::string num(Real v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

bool transducer(const model::Contact& c) { return c.form == model::ContactForm::force_transducer; }
bool kinematic_constraint(const model::Contact& c) {
  return c.type == ContactType::tied_surface || c.type == ContactType::tied_nodes ||
         c.type == ContactType::tied_shell_edge || c.type == ContactType::sliding_only;
}
bool tiebreak(const model::Contact& c) {
  return c.type == ContactType::tiebreak_nodes || c.type == ContactType::tiebreak_surface;
}
/// The interfaces whose springs are PenaltyPass springs: penalty Types 3, 5, 10, 12 and the
/// automatic cards.
bool penalty_sliding(const model::Contact& c) {
  return c.enforcement == Enforcement::penalty && !kinematic_constraint(c) && !tiebreak(c) && !transducer(c);
}

/// "KEYWORD card: field NAME = v (what)", prefixed with "file:line: " for an error (`ctx`), not
/// for a warning (which carries its file and line itself).
std::string field_text(const Context* ctx, int line, const model::Contact& c, const char* card, const char* name,
                       Real v, const char* what) {
  return (ctx ? ctx->where(line) : std::string()) + c.keyword + " " + card + ": field " + name + " = " + num(v) +
         " (" + what + ")";
}

/// SOFT = 2 (segment-based contact, contact/segment_contact.hpp): its fields of optional card A.
/// Built: SBOPT 2 (planar segments; 0 is 2), DEPTH 2 (surface penetration only; 0 is 2), on
/// *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE, *CONTACT_AUTOMATIC_SINGLE_SURFACE and *CONTACT_SURFACE_TO_SURFACE
/// (Type 3: solid faces only, the build refuses shells). Every other value is
/// refused by name (file, line, field, value); LCIDAB (an airbag's thickness curve) is refused.
/// BSORT >= 0 is honoured (cycles between searches, SegmentContact::set_search_interval); < 0 (a
/// load curve of the interval) is refused.
void read_segment_based_fields(const Context& ctx, const Line& l, const Card& k, model::Contact& c) {
  const bool s2s = c.form == model::ContactForm::automatic_surface_to_surface;
  const bool single =
      c.type == ContactType::automatic && c.form == model::ContactForm::dyna3d && !c.automatic_general && !c.eroding;
  const bool type3 = c.type == ContactType::surface_to_surface && c.form == model::ContactForm::dyna3d;
  if (!(s2s || single || type3) || !penalty_sliding(c))
    throw NotImplementedError(field_text(&ctx, l.number, c, "optional card A", "SOFT", 2,
                                         "segment-based penalty contact") +
                              " is implemented on *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE, "
                              "*CONTACT_AUTOMATIC_SINGLE_SURFACE and *CONTACT_SURFACE_TO_SURFACE (penalty) only");
  int lcidab = 0, sbopt = 0, depth = 0;
  k.get(2, "LCIDAB", lcidab);
  k.get(4, "SBOPT", sbopt);
  k.get(5, "DEPTH", depth);
  k.get(6, "BSORT", c.bsort);
  if (c.bsort < 0)
    throw NotImplementedError(field_text(&ctx, l.number, c, "optional card A", "BSORT", c.bsort,
                                         "load curve of the bucket sort interval") +
                              " is not implemented; give the number of cycles between searches (0: chosen here)");
  if (lcidab != 0)
    throw NotImplementedError(field_text(&ctx, l.number, c, "optional card A", "LCIDAB", lcidab,
                                         "airbag thickness curve of SOFT = 2") +
                              " is not implemented; leave it blank");
  if (sbopt != 0 && sbopt != 2) {
    const char* what = sbopt == 1   ? "pinball edge checking"
                       : sbopt == 3 ? "warped segment checking"
                       : sbopt == 4 ? "sliding option"
                       : sbopt == 5 ? "warped segment checking and sliding option"
                                    : nullptr;
    if (!what)
      throw InputError(field_text(&ctx, l.number, c, "optional card A", "SBOPT", sbopt,
                                  "segment-based contact options") + ": must be 0 to 5");
    throw NotImplementedError(field_text(&ctx, l.number, c, "optional card A", "SBOPT", sbopt, what) +
                              " is not implemented; SBOPT = 2 (planar segments, the default) is");
  }
  if (depth != 0 && depth != 2)
    throw NotImplementedError(field_text(&ctx, l.number, c, "optional card A", "DEPTH", depth,
                                         "segment-based search depth and edge-to-edge checks") +
                              " is not implemented; DEPTH = 2 (surface penetration only, the default) is");
}

}  // namespace

void read_contact_card_a(const Context& ctx, const Block& b, model::Contact& c) {
  if (b.next >= b.cards.size()) return;
  const Line& l = b.cards[b.next];
  const Card k(ctx, l, b.keyword, kStandard);
  k.get(0, "SOFT", c.soft);
  k.get_or_default(1, "SOFSCL", c.sofscl);
  const char* soft_what = "penalty stiffness formulation";
  if (c.soft == 2) {
    read_segment_based_fields(ctx, l, k, c);
    if (c.sofscl != 0.1)
      ctx.warn(l.number, field_text(nullptr, l.number, c, "optional card A", "SOFSCL", c.sofscl,
                                    "scale of the SOFT = 1 stiffness") +
                             " acts only with SOFT = 1; ignored");
    return;
  }
  if (c.soft == 4 || c.soft == 6)
    throw NotImplementedError(field_text(&ctx, l.number, c, "optional card A", "SOFT", c.soft, soft_what) +
                              " is not implemented; give SOFT = 0, 1 or 2");
  if (c.soft != 0 && c.soft != 1)
    throw InputError(field_text(&ctx, l.number, c, "optional card A", "SOFT", c.soft, soft_what) +
                     ": must be 0, 1, 2, 4 or 6");
  if (c.sofscl < 0.0)
    throw InputError(field_text(&ctx, l.number, c, "optional card A", "SOFSCL", c.sofscl,
                                "scale of the SOFT = 1 stiffness") + ": must not be negative");
  if (c.soft == 0) {
    if (c.sofscl != 0.1)
      ctx.warn(l.number, field_text(nullptr, l.number, c, "optional card A", "SOFSCL", c.sofscl,
                                    "scale of the SOFT = 1 stiffness") +
                             " acts only with SOFT = 1; ignored");
    return;
  }
  if (penalty_sliding(c)) return;  // honoured (PenaltyPassOptions::soft_scale)
  const char* soft1 = "soft-constraint stiffness";
  if (kinematic_constraint(c) || transducer(c)) {
    ctx.warn(l.number, field_text(nullptr, l.number, c, "optional card A", "SOFT", 1, soft1) +
                           " has nothing to act on here (this interface is a kinematic constraint or a force "
                           "transducer, without a spring); ignored");
    c.soft = 0;
    return;
  }
  throw NotImplementedError(field_text(&ctx, l.number, c, "optional card A", "SOFT", 1, soft1) +
                            " is implemented on the penalty sliding interfaces (Types 3, 5, 10, 12 and the automatic "
                            "cards) only, not with Lagrange enforcement or on a tiebreak");
}

void check_viscous_friction(const Context& ctx, const model::Contact& c, const Line* card2) {
  if (!card2 || c.vc == 0.0) return;
  const char* what = "viscous friction: the tangential force capped at VC x the contact area";
  const std::string text = field_text(&ctx, card2->number, c, "card 2", "VC", c.vc, what);
  if (c.vc < 0.0) throw InputError(text + ": must not be negative");
  const bool frictional = c.fs > 0.0 || c.fd > 0.0;
  if (penalty_sliding(c) && frictional) return;  // honoured (PenaltyPassOptions::viscous_friction)
  if (kinematic_constraint(c) || transducer(c) || (penalty_sliding(c) && !frictional)) {
    ctx.warn(card2->number, field_text(nullptr, card2->number, c, "card 2", "VC", c.vc, what) +
                                " has nothing to act on here (no friction: FS and FD are 0, or the interface "
                                "does not slide); ignored");
    return;
  }
  throw NotImplementedError(text + " is implemented on the penalty sliding interfaces (Types 3, 5, 10, 12 and the "
                                   "automatic cards) only, not with Lagrange enforcement or on a tiebreak");
}

void check_transducer_fields(const Context& ctx, const model::Contact& c, const Line* card1, const Line* card2,
                             const Line* card3) {
  // Output only: every field that would shape a contact force has nothing to act on.
  struct Field {
    const Line* line;
    const char* card;
    const char* name;
    Real value, dflt;
  };
  const Field fields[] = {
      {card1, "card 1", "SPR", Real(c.spr), 0}, {card1, "card 1", "MPR", Real(c.mpr), 0},
      {card1, "card 1", "SBOXID", Real(c.sboxid), 0}, {card1, "card 1", "MBOXID", Real(c.mboxid), 0},
      {card2, "card 2", "FS", c.fs, 0},   {card2, "card 2", "FD", c.fd, 0},   {card2, "card 2", "DC", c.dc, 0},
      {card2, "card 2", "VC", c.vc, 0},   {card2, "card 2", "VDC", c.vdc, 0},
      {card2, "card 2", "PENCHK", Real(c.penchk), 0},
      {card3, "card 3", "SFS", c.sfs, 1}, {card3, "card 3", "SFM", c.sfm, 1}, {card3, "card 3", "SST", c.sst, 0},
      {card3, "card 3", "MST", c.mst, 0}, {card3, "card 3", "SFST", c.sfst, 1}, {card3, "card 3", "SFMT", c.sfmt, 1},
      {card3, "card 3", "FSF", c.fsf, 1}, {card3, "card 3", "VSF", c.vsf, 1},
  };
  for (const Field& f : fields)
    if (f.line && f.value != f.dflt)
      ctx.warn(f.line->number, field_text(nullptr, f.line->number, c, f.card, f.name, f.value, "a contact field") +
                                   " has nothing to act on here (a force transducer adds no force); ignored");
}

}  // namespace slideline::keyword
