// *MAT_ADD_EROSION (docs/keywords.md): failure criteria added to a material. Field order and
// meanings follow the LS-DYNA keyword manual (vol. II, *MAT_ADD_EROSION). Built: MXPRES, MNPRES,
// SIGP1, SIGVM, MNEPS, EFFEPS, VOLEPS, MXEPS, EPSSH, FAILTM, NCS, NUMFIP, EXCL; SIGTH and IMPULSE
// are refused unless excluded, and the optional damage / regularisation cards only when they hold
// their defaults.
#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <tuple>

#include "keyword_card.hpp"
#include "slideline/core/error.hpp"

namespace slideline::keyword {

using model::Model;

namespace {

/// The deck's text of field `i`, or "0" when blank (a blank field is 0).
std::string shown(const Card& c, int i) { return c.blank(i) ? std::string("0 (blank)") : std::string(c.raw(i)); }

}  // namespace

void read_mat_add_erosion(const Context& ctx, Block& b, Model& m, bool titled) {
  model::MatAddErosion add;
  if (titled) add.title = heading(require_card(ctx, b, "title"));
  const Line& l1 = require_card(ctx, b, "MID");
  const Card c1(ctx, l1, b.keyword, kStandard);
  c1.get(0, "MID", add.mid);
  c1.get(1, "EXCL", add.excl);
  add.src = ctx.source(l1.number);
  const Line* l2 = b.take();
  if (!l2)
    throw InputError(ctx.where(l1.number) + b.keyword + ": card 2 (MNPRES SIGP1 SIGVM MXEPS EPSSH SIGTH IMPULSE FAILTM) is missing");
  const Card c2(ctx, *l2, b.keyword, kStandard);

  // A threshold is excluded when it equals EXCL (blank reads 0, so with EXCL blank or 0 every
  // blank or 0 threshold is excluded); MXPRES, MNEPS, EFFEPS and VOLEPS are excluded at 0 in any
  // case (the manual: "automatically excluded to maintain compatibility with old input files").
  const auto value = [&](const Card& c, int i, const char* name, bool zero_excluded) -> std::optional<Real> {
    Real v = 0.0;
    c.get(i, name, v);
    if (v == add.excl || (zero_excluded && v == 0.0)) return std::nullopt;
    return v;
  };
  const auto refuse = [&](const Card& c, int i, const char* name, const std::string& what) {
    throw NotImplementedError(ctx.where(c.line()) + b.keyword + ": card " + (&c == &c1 ? "1" : "2") + " field " +
                              name + " = " + shown(c, i) + " (" + what + ") is not implemented; set it to EXCL (" +
                              (c1.blank(1) ? std::string("blank: 0") : std::string(c1.raw(1))) +
                              ") to exclude it");
  };
  add.mxpres = value(c1, 2, "MXPRES", true);
  add.mneps = value(c1, 3, "MNEPS", true);
  add.effeps = value(c1, 4, "EFFEPS", true);
  add.voleps = value(c1, 5, "VOLEPS", true);
  // A strain that is never negative (the effective and the tensorial shear strain) against a
  // negative threshold would delete every element at once: refused (later manuals also give a
  // negative EFFEPS another meaning, the effective plastic strain, which is not built).
  const auto positive = [&](const Card& c, int i, const char* name, const std::optional<Real>& v) {
    if (v && *v < 0.0)
      throw InputError(ctx.where(c.line()) + b.keyword + ": card " + (&c == &c1 ? "1" : "2") + " field " + name +
                       " = " + std::string(c.raw(i)) + " must be positive (a strain that is never negative)");
  };
  positive(c1, 4, "EFFEPS", add.effeps);
  Real numfip = 0.0, ncs = 0.0;
  c1.get(6, "NUMFIP", numfip);
  c1.get(7, "NCS", ncs);
  add.numfip = numfip == 0.0 ? 1.0 : numfip;  // the manual's default 1
  if (numfip != std::floor(numfip) && numfip > 0.0)
    throw InputError(ctx.where(l1.number) + b.keyword + ": card 1 field NUMFIP = " + std::string(c1.raw(6)) +
                     " must be a whole number of points (or, negative, a percentage)");
  if (ncs < 0.0 || ncs != std::floor(ncs))
    throw InputError(ctx.where(l1.number) + b.keyword + ": card 1 field NCS = " + std::string(c1.raw(7)) +
                     " must be a whole number >= 1 (blank or 0: 1)");
  add.ncs = ncs == 0.0 ? 1 : static_cast<int>(ncs);

  add.mnpres = value(c2, 0, "MNPRES", false);
  add.sigp1 = value(c2, 1, "SIGP1", false);
  add.sigvm = value(c2, 2, "SIGVM", false);
  if (add.sigp1 && *add.sigp1 < 0.0) refuse(c2, 1, "SIGP1", "a curve of the failure stress against the strain rate");
  if (add.sigvm && *add.sigvm < 0.0) refuse(c2, 2, "SIGVM", "a curve of the failure stress against the strain rate");
  add.mxeps = value(c2, 3, "MXEPS", false);
  add.epssh = value(c2, 4, "EPSSH", false);
  if (add.mxeps && *add.mxeps < 0.0)
    refuse(c2, 3, "MXEPS", "a curve of the failure strain against the strain rate");
  positive(c2, 4, "EPSSH", add.epssh);
  for (auto [i, name, what] : {std::tuple{5, "SIGTH", "Tuler-Butcher threshold stress"},
                               std::tuple{6, "IMPULSE", "Tuler-Butcher stress impulse"}})
    if (value(c2, i, name, false)) refuse(c2, i, name, what);
  // FAILTM = 0 (or blank) is not a criterion whatever EXCL: a failure time 0 would delete every
  // element at the start. LS-DYNA's own example birdball.k leaves FAILTM blank with EXCL = 888 and
  // erodes by MXEPS.
  add.failtm = value(c2, 7, "FAILTM", true);
  // FAILTM < 0: |FAILTM|, inactive during dynamic relaxation, which no run here has.
  if (add.failtm) add.failtm = std::abs(*add.failtm);

  int active = 0;
  for (const auto* v : {&add.mxpres, &add.mnpres, &add.sigp1, &add.sigvm, &add.failtm, &add.mneps, &add.effeps,
                        &add.voleps, &add.mxeps, &add.epssh})
    active += v->has_value() ? 1 : 0;
  if (active == 0)
    throw InputError(ctx.where(l1.number) + b.keyword + ": no criterion is set (every one is blank, 0 or EXCL)");
  if (add.ncs > active)
    throw InputError(ctx.where(l1.number) + b.keyword + ": card 1 field NCS = " + std::string(c1.raw(7)) +
                     " asks for more criteria at once than the " + std::to_string(active) + " set");

  // Optional cards 3-5 (damage, forming limit, filter / volume fraction / temperature / step):
  // accepted only at their defaults. Columns are named after the current manual; the older layout
  // of card 3 (IDAM DMGTYP LCSDG ECRIT DMGEXP DCRIT FADEXP LCREGD) has the defaults 1 of DMGEXP
  // and FADEXP in columns 5 and 7.
  struct Optional {
    const char* name;
    Real default_value;
  };
  static const Optional card3[] = {{"IDAM", 0}, {"DMGTYP", 0}, {"LCSDG", 0}, {"ECRIT", 0},
                                   {"DMGEXP", 1}, {"DCRIT", 0}, {"FADEXP", 1}, {"LCREGD", 0}};
  static const Optional card4[] = {{"LCFLD", 0},  {"NSFF", 10},  {"EPSTHIN", 0}, {"ENGCRT", 0},
                                   {"RADCRT", 0}, {"LCEPS12", 0}, {"LCEPS13", 0}, {"LCEPSMX", 0}};
  static const Optional card5[] = {{"DTEFLT", 0}, {"VOLFRAC", 0.5}, {"MXTMP", 0}, {"DTMIN", 0}};
  const std::span<const Optional> cards[] = {card3, card4, card5};
  for (int k = 0; k < 3; ++k) {
    const Line* l = b.take();
    if (!l) break;
    const Card c(ctx, *l, b.keyword, kStandard);
    for (int i = 0; i < static_cast<int>(cards[k].size()); ++i) {
      const Optional& f = cards[k][static_cast<std::size_t>(i)];
      Real v = 0.0;
      c.get(i, f.name, v);
      if (v != 0.0 && v != f.default_value)
        throw NotImplementedError(ctx.where(l->number) + b.keyword + ": card " + std::to_string(k + 3) + " field " +
                                  f.name + " = " + std::string(c.raw(i)) +
                                  " is not implemented; leave it blank (damage, forming-limit and the other optional"
                                  " criteria are not built)");
    }
  }
  while (const Line* l = b.take())
    if (!trim(l->text).empty())
      throw NotImplementedError(ctx.where(l->number) + b.keyword +
                              ": cards after card 5 are not implemented; remove them");
  m.add_erosions.push_back(std::move(add));
}

}  // namespace slideline::keyword
