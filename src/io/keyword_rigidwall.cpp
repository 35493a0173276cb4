// *RIGIDWALL_PLANAR and *RIGIDWALL_PLANAR_FINITE (with _ID): a stationary plane, or rectangle,
// enforced kinematically (solver/rigid_wall.hpp). Each wall is [ID card] card 1, card 2 [, the
// _FINITE card]; a block may hold several. Fields the solver does not honour are refused naming
// file, line and field; the other *RIGIDWALL keywords (_MOVING, _ORTHO, _FORCES, _GEOMETRIC) are
// refused by keyword_unsupported.cpp.
#include <string>

#include "keyword_card.hpp"
#include "slideline/core/error.hpp"

namespace slideline::keyword {
namespace {

using model::Model;

/// True while a non-blank card is left (a trailing blank line is not a wall).
bool more_walls(const Block& b) {
  for (std::size_t k = b.next; k < b.cards.size(); ++k)
    if (!trim(b.cards[k].text).empty()) return true;
  return false;
}

[[noreturn]] void refuse(const Context& ctx, const Line& l, const Block& b, const char* card, const char* field,
                         Real v, const char* what) {
  throw NotImplementedError(ctx.where(l.number) + b.keyword + " " + card + ": field " + field + " = " +
                            std::to_string(v) + " (" + what + ") is not implemented; leave it blank or 0");
}

void read_card1(const Context& ctx, const Line& l, const Block& b, model::RigidWallPlanar& w) {
  const Card c(ctx, l, b.keyword, kStandard);
  c.get(0, "NSID", w.nsid);
  c.get(1, "NSIDEX", w.nsidex);
  c.get(2, "BOXID", w.boxid);
  c.get(3, "OFFSET", w.offset);
  c.get(4, "BIRTH", w.birth);
  c.get(5, "DEATH", w.death);
  c.get_or_default(6, "RWKSF", w.rwksf);
  if (w.death == 0.0) w.death = 1e20;  // blank or 0: the wall never dies
  if (w.boxid != 0) refuse(ctx, l, b, "card 1", "BOXID", static_cast<Real>(w.boxid), "slave nodes in a box");
  if (w.offset != 0.0) refuse(ctx, l, b, "card 1", "OFFSET", w.offset, "slave nodes within a distance");
  if (w.rwksf != 1.0)
    ctx.warn(l.number, b.keyword + " card 1: field RWKSF = " + std::to_string(w.rwksf) +
                           " (penalty scale of penalty walls, RWPNAL > 0, which are refused) has nothing to act on "
                           "here; ignored");
}

void read_card2(const Context& ctx, const Line& l, const Block& b, model::RigidWallPlanar& w) {
  const Card c(ctx, l, b.keyword, kStandard);
  static const char* const names[] = {"XT", "YT", "ZT", "XH", "YH", "ZH"};
  for (int k = 0; k < 3; ++k) {
    c.get(k, names[k], w.tail[k]);
    c.get(3 + k, names[3 + k], w.head[k]);
  }
  c.get(6, "FRIC", w.fric);
  c.get(7, "WVEL", w.wvel);
  if (w.fric < 0.0 || w.fric > 1.0)
    refuse(ctx, l, b, "card 2", "FRIC", w.fric, "0 frictionless, 1 no sliding, between a Coulomb coefficient; "
                                                "other values");
  if (w.wvel != 0.0) refuse(ctx, l, b, "card 2", "WVEL", w.wvel, "welding above a normal velocity");
}

void read_finite_card(const Context& ctx, const Line& l, const Block& b, model::RigidWallPlanar& w) {
  const Card c(ctx, l, b.keyword, kStandard);
  static const char* const names[] = {"XHEV", "YHEV", "ZHEV"};
  for (int k = 0; k < 3; ++k) c.get(k, names[k], w.edge_head[k]);
  c.get(3, "LENL", w.lenl);
  c.get(4, "LENM", w.lenm);
  w.finite = true;
}

void read_walls(const Context& ctx, Block& b, Model& m, bool with_id, bool finite) {
  while (more_walls(b)) {
    model::RigidWallPlanar w;
    if (with_id) read_id_heading(ctx, require_card(ctx, b, "RWID"), b.keyword, w.id, w.title);
    const Line& l1 = require_card(ctx, b, "NSID");
    read_card1(ctx, l1, b, w);
    w.src = ctx.source(l1.number);
    read_card2(ctx, require_card(ctx, b, "XT"), b, w);
    if (finite) read_finite_card(ctx, require_card(ctx, b, "XHEV"), b, w);
    m.rigid_walls.push_back(std::move(w));
  }
}

}  // namespace

void read_rigidwall_planar(const Context& ctx, Block& b, Model& m, bool with_id) {
  read_walls(ctx, b, m, with_id, false);
}

void read_rigidwall_planar_finite(const Context& ctx, Block& b, Model& m, bool with_id) {
  read_walls(ctx, b, m, with_id, true);
}

}  // namespace slideline::keyword
