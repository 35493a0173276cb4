// *CONTACT_... cards: cards 1-3 and the tiebreak card 4 of a keyword of the contact keyword table
// (model/contact_keywords.hpp), whose name the keyword table (keyword_table.cpp) has matched. See
// docs/keywords.md, "Contact".
#include <cstdio>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>

#include "keyword_card.hpp"
#include "slideline/core/error.hpp"

namespace slideline::keyword {
namespace {

using model::ContactType;
using model::Enforcement;

/// Card 1: the sides.
void read_card1(const Card& k, model::Contact& c) {
  k.get(0, "SSID", c.ssid);
  k.get(1, "MSID", c.msid);
  k.get(2, "SSTYP", c.sstyp);
  k.get(3, "MSTYP", c.mstyp);
  k.get(4, "SBOXID", c.sboxid);
  k.get(5, "MBOXID", c.mboxid);
  k.get(6, "SPR", c.spr);
  k.get(7, "MPR", c.mpr);
}

/// Card 2: friction, damping, birth and death.
void read_card2(const Card& k, model::Contact& c) {
  k.get(0, "FS", c.fs);
  k.get(1, "FD", c.fd);
  k.get(2, "DC", c.dc);
  k.get(3, "VC", c.vc);
  k.get(4, "VDC", c.vdc);
  k.get(5, "PENCHK", c.penchk);
  k.get(6, "BT", c.bt);
  k.get(7, "DT", c.dt);
  if (c.dt == 0.0) c.dt = 1e20;  // LS-DYNA: DT = 0 is the default 1e20 (never dies)
}

/// Card 3: blank and 0 mean the manual's default (1 for the scale factors).
void read_card3(const Card& k, model::Contact& c) {
  k.get_or_default(0, "SFS", c.sfs);
  k.get_or_default(1, "SFM", c.sfm);
  k.get(2, "SST", c.sst);
  k.get(3, "MST", c.mst);
  k.get_or_default(4, "SFST", c.sfst);
  k.get_or_default(5, "SFMT", c.sfmt);
  k.get_or_default(6, "FSF", c.fsf);
  k.get_or_default(7, "VSF", c.vsf);
}

/// Card 4 of the tiebreak types: the failure fields (forces for Type 8, stresses for Type 9).
void read_tiebreak_card4(const Card& k, model::Contact& c) {
  if (c.type == ContactType::tiebreak_nodes) {
    k.get(0, "NFLF", c.nflf);
    k.get(1, "SFLF", c.sflf);
    k.get_or_default(2, "NEN", c.nen);
    k.get_or_default(3, "MES", c.mes);
  } else {
    k.get(0, "OPTION", c.option);
    k.get(1, "NFLS", c.nfls);
    k.get(2, "SFLS", c.sfls);
    k.get(3, "PARAM", c.param);
    k.get(4, "ERATEN", c.eraten);
    k.get(5, "ERATES", c.erates);
    k.get(6, "CT2CN", c.ct2cn);
    k.get(7, "CN", c.cn);
  }
}

/// Why an OPTION of *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK is not built (docs/contact.md,
/// "Automatic tiebreak": the table of options).
std::string unbuilt_tiebreak_option(int option) {
  switch (option) {
    case 5: return "OPTION 5 is a damage curve of the crack opening (SFLS a curve, NFLS a yield stress)";
    case 7: return "OPTION 7 (Dycoss discrete crack model, PARAM a friction angle) is defined in Lemmen and Meijer "
                   "(2001), not by the manual's text";
    case 10: case 11: return "OPTION " + std::to_string(option) + " is the offset-shell variant of OPTION " +
                             std::to_string(option == 10 ? 7 : 9) + "; shell segments are built on OPTION 8 only";
    case 13: case 14: return "OPTION 13 and 14 are the *MAT_240 elastoplastic rate-dependent law with extra cards";
    default: return option < 0 ? "negative OPTION transfers moments (shells) or reads temperature curves (MORTAR)"
                               : "OPTION " + std::to_string(option) + " is not a tiebreak law of the manual";
  }
}

/// *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK card 4. Built: OPTION 1 (blank and 0 its
/// default: nodes in contact and those coming into contact stick for good; NFLS, SFLS refused by
/// check_contact_fields), OPTION 3 (as 1, failing by the stress criterion), OPTION 2 (the stress
/// criterion, then the automatic contact), OPTION 4 (a normal tie with friction), OPTION 6 (the criterion, then damage linear in the distance,
/// complete at PARAM = CCRIT), OPTION 8 (6 on shells with thickness offsets) and OPTION 9 (the mixed-mode bilinear traction-separation law with PARAM,
/// ERATEN, ERATES, CT2CN, CN). Every other OPTION is refused saying why; NFLS, SFLS < 0 (curves)
/// are refused. On OPTION 2, PARAM..CN off their blank default are refused by
/// check_contact_fields (keyword_contact_fields.cpp).
void check_automatic_tiebreak_card4(const Context& ctx, const model::Contact& c, const Line* card4, int line) {
  const std::string at = ctx.where(card4 ? card4->number : line) + c.keyword + " card 4";
  if (!card4) throw InputError(at + " (OPTION NFLS SFLS PARAM ...) is missing");
  if (c.option < 0 || c.option == 5 || c.option == 7 || c.option > 9)
    throw NotImplementedError(at + ": field OPTION = " + std::to_string(c.option) + " is not implemented (" +
                              unbuilt_tiebreak_option(c.option) +
                              "); built: blank, 0 and 1 (nodes in contact and those coming into contact stick "
                              "permanently), 2 (failure by (sigma_n / NFLS)^2 + (sigma_s / SFLS)^2 >= 1, then "
                              "automatic surface-to-surface contact), 3 (as 1, failing by that criterion), 4 (a "
                              "normal tie failing by NFLS, sliding with friction), 6 (that criterion, then linear "
                              "softening to zero at PARAM), 8 (6 on offset shells) and 9 (mixed-mode bilinear "
                              "traction-separation)");
  const auto value = [](Real v) {
    char s[32];
    std::snprintf(s, sizeof s, "%g", v);
    return std::string(s);
  };
  for (const auto& [name, v] : {std::pair<const char*, Real>{"NFLS", c.nfls}, {"SFLS", c.sfls}}) {
    if (v >= 0.0) continue;
    throw NotImplementedError(at + ": field " + name + " = " + value(v) +
                              " < 0 (a curve in recent manuals) is not implemented; give a stress >= 0");
  }
  if (c.option == 4 && !(c.nfls > 0.0))
    throw InputError(at + ": field NFLS = " + value(c.nfls) +
                     ": OPTION 4 needs the normal failure stress > 0 (its tie fails by NFLS only)");
  if (c.option == 6 || c.option == 8) {
    // OPTION 6 (8: on offset shells): the criterion's stresses start the damage, PARAM (CCRIT)
    // completes it; no defaults.
    for (const auto& [name, v, what] :
         {std::tuple<const char*, Real, const char*>{"NFLS", c.nfls, "the normal failure stress"},
          {"SFLS", c.sfls, "the shear failure stress"},
          {"PARAM", c.param, "the critical distance CCRIT"}})
      if (!(v > 0.0))
        throw InputError(at + ": field " + name + " = " + value(v) + ": OPTION " + std::to_string(c.option) +
                         " needs " + what + " > 0");
    return;
  }
  if (c.option != 9) return;
  // OPTION 9: the peak tractions and the energy release rates have no default.
  for (const auto& [name, v, what] :
       {std::tuple<const char*, Real, const char*>{"NFLS", c.nfls, "the peak normal traction"},
        {"SFLS", c.sfls, "the peak shear traction"},
        {"ERATEN", c.eraten, "the mode I energy release rate"},
        {"ERATES", c.erates, "the mode II energy release rate"}})
    if (!(v > 0.0))
      throw InputError(at + ": field " + name + " = " + value(v) + ": OPTION 9 needs " + what + " > 0");
  for (const auto& [name, v] : {std::pair<const char*, Real>{"CT2CN", c.ct2cn}, {"CN", c.cn}})
    if (v < 0.0) throw InputError(at + ": field " + name + " = " + value(v) + " < 0 (blank or 0: the default)");
}

/// "*CONTACT_SURFACE_TO_SURFACE, ... and *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE": the rows that
/// take _MORTAR.
std::string mortar_keywords() {
  std::string s;
  std::string_view last;
  for (const auto& k : model::kContactKeywords) {
    if (!k.mortar_option) continue;
    if (!last.empty()) s += (s.empty() ? "" : ", ") + std::string(last);
    last = k.keyword;
  }
  return s + " and " + std::string(last);
}

}  // namespace

void read_contact(const Context& ctx, Block& b, model::Model& m, const model::ContactKeyword& row,
                  bool with_heading, ContactOptions options) {
  model::Contact c;
  c.keyword = b.keyword;
  c.type = row.type;
  c.automatic_general = row.automatic_general;
  c.form = row.form;
  c.eroding = row.eroding;
  c.enforcement = options.lagrange ? Enforcement::lagrange : row.enforcement;
  if (options.mortar) {
    // The coupling changes the physics: refuse it where it is not built (the model build refuses
    // it on a type 12 _LAGRANGE card and with a node-set slave side).
    if (!row.mortar_option)
      throw InputError(ctx.where(b.line) + b.keyword + ": _MORTAR is an option of " + mortar_keywords() + " only");
    c.penalty_coupling = 1;
  }
  if (options.sliding) {
    if (row.sliding_option)
      c.sliding_only_option = true;
    else
      // The option changes the physics (no separation): refuse it where it means nothing.
      throw InputError(ctx.where(b.line) + b.keyword +
                       ": _SLIDING_ONLY is an option of *CONTACT_ONE_WAY_SURFACE_TO_SURFACE only (type 1 "
                       "sliding is *CONTACT_SLIDING_ONLY)");
  }

  const Line* l = b.take();
  if (with_heading) {
    if (!l) throw InputError(ctx.file + ":" + std::to_string(b.line) + ": " + b.keyword + ": missing ID card");
    read_id_heading(ctx, *l, b.keyword, c.cid, c.title);
    l = b.take();
  }
  if (!l) throw InputError(ctx.file + ":" + std::to_string(b.line) + ": " + b.keyword + ": missing card 1 (SSID MSID ...)");
  c.src = ctx.source(l->number);
  const Line* card1 = l;
  const Line* card2 = nullptr;
  const Line* card3 = nullptr;
  const Line* card4 = nullptr;
  read_card1(Card(ctx, *l, b.keyword, kStandard), c);
  if ((l = card2 = b.take())) read_card2(Card(ctx, *l, b.keyword, kStandard), c);
  if ((l = card3 = b.take())) read_card3(Card(ctx, *l, b.keyword, kStandard), c);
  if (c.type == ContactType::tiebreak_nodes || c.type == ContactType::tiebreak_surface) {
    if ((l = card4 = b.take())) read_tiebreak_card4(Card(ctx, *l, b.keyword, kStandard), c);
    // The model keeps one pair of failure fields for both tiebreak types (stresses for type 9).
    if (c.type == ContactType::tiebreak_surface) {
      c.nflf = c.nfls;
      c.sflf = c.sfls;
    }
    if (c.form == model::ContactForm::automatic_surface_to_surface) check_automatic_tiebreak_card4(ctx, c, card4, b.line);
  }
  if (c.eroding) read_eroding_card4(ctx, b, c);
  // Type 5 with discrete slave nodes: SST is the nodal contact radius.
  if (c.type == ContactType::nodes_to_surface && c.sstyp == 4) c.radius = c.sst;
  if (c.form == model::ContactForm::force_transducer)
    check_transducer_fields(ctx, c, card1, card2, card3);
  else
    check_contact_fields(ctx, c, card1, card2, card3, card4);
  read_contact_optional_cards(ctx, b, c);
  m.contacts.push_back(std::move(c));
}

}  // namespace slideline::keyword
