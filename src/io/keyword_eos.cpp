// Card handlers of the equations of state (*EOS_LINEAR_POLYNOMIAL, *EOS_GRUNEISEN,
// *EOS_TABULATED), which *MAT_NULL solids take through EOSID of *PART; the keyword table that
// dispatches to them is keyword_table.cpp. Field orders follow the LS-DYNA keyword manual
// (docs/keywords.md, "Equations of state").
#include <array>
#include <string>

#include "keyword_card.hpp"
#include "slideline/core/error.hpp"

namespace slideline::keyword {

using model::Model;

namespace {

/// Five 16-wide fields: the table cards of *EOS_TABULATED.
constexpr int kTableCard[] = {16, 16, 16, 16, 16};

/// Refuses a non-blank field `from`.. of card `c` that the manual does not define.
void refuse_beyond(const Context& ctx, const Block& b, const Card& c, int from) {
  for (int k = from; k < c.size(); ++k)
    if (!c.blank(k))
      throw InputError(ctx.where(c.line()) + b.keyword + ": field " + std::to_string(k + 1) + " = " +
                       std::string(c.raw(k)) + " of this card is not a field of the card (leave it blank)");
}

/// Reads the ten values of one *EOS_TABULATED table (two cards of five), named `name`1..10.
void read_table(const Context& ctx, Block& b, const char* name, std::array<Real, 10>& out) {
  for (int half = 0; half < 2; ++half) {
    const std::string what = std::string(name) + (half == 0 ? "1-5" : "6-10");
    const Line& l = require_card(ctx, b, what.c_str());
    const Card c(ctx, l, b.keyword, kTableCard);
    for (int k = 0; k < 5; ++k) {
      const std::string field = std::string(name) + std::to_string(5 * half + k + 1);
      c.get(k, field.c_str(), out[static_cast<std::size_t>(5 * half + k)]);
    }
  }
}

}  // namespace

void read_eos_linear_polynomial(const Context& ctx, Block& b, Model& m) {
  model::EosLinearPolynomial e;
  const Line& l = require_card(ctx, b, "EOSID");
  const Card c(ctx, l, b.keyword, kStandard);
  c.get(0, "EOSID", e.eosid);
  static const char* const names[] = {"C0", "C1", "C2", "C3", "C4", "C5", "C6"};
  for (int k = 0; k < 7; ++k) c.get(k + 1, names[k], e.c[static_cast<std::size_t>(k)]);
  if (const Line* l2 = b.take()) {
    const Card c2(ctx, *l2, b.keyword, kStandard);
    c2.get(0, "E0", e.e0);
    c2.get(1, "V0", e.v0);
    refuse_beyond(ctx, b, c2, 2);
  }
  e.src = ctx.source(l.number);
  m.eos.emplace_back(e);
  warn_extra_cards(ctx, b);
}

void read_eos_gruneisen(const Context& ctx, Block& b, Model& m) {
  model::EosGruneisen e;
  const Line& l = require_card(ctx, b, "EOSID");
  const Card c(ctx, l, b.keyword, kStandard);
  c.get(0, "EOSID", e.eosid);
  c.get(1, "C", e.c);
  c.get(2, "S1", e.s1);
  c.get(3, "S2", e.s2);
  c.get(4, "S3", e.s3);
  c.get(5, "GAMAO", e.gamma0);
  c.get(6, "A", e.a);
  c.get(7, "E0", e.e0);
  if (const Line* l2 = b.take()) {
    const Card c2(ctx, *l2, b.keyword, kStandard);
    c2.get(0, "V0", e.v0);
    c2.get(2, "LCID", e.lcid);
    if (!c2.blank(1)) refuse_beyond(ctx, b, c2, 1);
    refuse_beyond(ctx, b, c2, 3);
    if (e.lcid != 0)
      throw NotImplementedError(ctx.where(l2->number) + b.keyword + ": field LCID = " + std::string(c2.raw(2)) +
                                " (a curve id) is not implemented; leave it blank");
  }
  e.src = ctx.source(l.number);
  m.eos.emplace_back(e);
  warn_extra_cards(ctx, b);
}

void read_eos_tabulated(const Context& ctx, Block& b, Model& m) {
  model::EosTabulated e;
  const Line& l = require_card(ctx, b, "EOSID");
  const Card c(ctx, l, b.keyword, kStandard);
  c.get(0, "EOSID", e.eosid);
  c.get(1, "GAMA", e.gama);
  c.get(2, "E0", e.e0);
  c.get(3, "V0", e.v0);
  refuse_beyond(ctx, b, c, 4);
  read_table(ctx, b, "EV", e.ev);
  read_table(ctx, b, "C", e.c);
  read_table(ctx, b, "T", e.t);
  e.src = ctx.source(l.number);
  m.eos.emplace_back(e);
  warn_extra_cards(ctx, b);
}

}  // namespace slideline::keyword
