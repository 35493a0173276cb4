// *DEFINE_COORDINATE_SYSTEM, *DEFINE_COORDINATE_NODES and *DEFINE_COORDINATE_VECTOR (each with
// _TITLE): local Cartesian systems (model/coordinate_system.hpp). Field orders from the LS-DYNA
// keyword manual (docs/keywords.md, "Local coordinate systems"). The reader records the cards; the
// builder resolves a system to its axes where a card names it and refuses a degenerate one, or a
// moving one where the card acts through the run.
#include <string>

#include "keyword_card.hpp"
#include "slideline/core/error.hpp"

namespace slideline::keyword {
namespace {

using model::CoordinateSystem;

/// True while a non-blank card is left (a trailing blank line is not a system).
bool more_cards(const Block& b) {
  for (std::size_t k = b.next; k < b.cards.size(); ++k)
    if (!trim(b.cards[k].text).empty()) return true;
  return false;
}

void get_vec(const Card& c, int first, const char* const names[3], Vec3& v) {
  for (int k = 0; k < 3; ++k) c.get(first + k, names[k], v[k]);
}

/// One system per loop: [title] then its card(s); `read` fills the system from the block.
template <class Read>
void read_systems(const Context& ctx, Block& b, model::Model& m, bool titled, CoordinateSystem::Kind kind,
                  Read read) {
  while (more_cards(b)) {
    CoordinateSystem s;
    s.kind = kind;
    if (titled) s.title = heading(require_card(ctx, b, "title"));
    const Line& l = require_card(ctx, b, "CID");
    const Card c(ctx, l, b.keyword, kStandard);
    c.get(0, "CID", s.cid);
    if (s.cid <= 0)
      throw InputError(ctx.where(l.number) + b.keyword + ": field CID must be a positive id (got " +
                       std::to_string(s.cid) + ")");
    s.src = ctx.source(l.number);
    read(c, l, s);
    m.coordinate_systems.push_back(std::move(s));
    if (titled) break;  // one title, one system
  }
  warn_extra_cards(ctx, b);
}

}  // namespace

void read_define_coordinate_system(const Context& ctx, Block& b, model::Model& m, bool titled) {
  read_systems(ctx, b, m, titled, CoordinateSystem::Kind::points, [&](const Card& c, const Line&, CoordinateSystem& s) {
    static const char* const o[] = {"X0", "Y0", "Z0"};
    static const char* const x[] = {"XL", "YL", "ZL"};
    static const char* const p[] = {"XP", "YP", "ZP"};
    get_vec(c, 1, o, s.origin);
    get_vec(c, 4, x, s.axis);
    c.get(7, "CIDL", s.cidl);
    const Card c2(ctx, require_card(ctx, b, "XP YP ZP"), b.keyword, kStandard);
    get_vec(c2, 0, p, s.plane);
  });
}

void read_define_coordinate_nodes(const Context& ctx, Block& b, model::Model& m, bool titled) {
  read_systems(ctx, b, m, titled, CoordinateSystem::Kind::nodes, [&](const Card& c, const Line& l, CoordinateSystem& s) {
    c.get(1, "N1", s.nodes[0]);
    c.get(2, "N2", s.nodes[1]);
    c.get(3, "N3", s.nodes[2]);
    c.get(4, "FLAG", s.flag);
    if (s.flag != 0 && s.flag != 1)
      throw InputError(ctx.where(l.number) + b.keyword + ": field FLAG must be 0 (fixed at t = 0) or 1 (moves "
                       "with the nodes); got " + std::to_string(s.flag));
    const std::string dir = upper(c.raw(5));
    if (dir.empty() || dir == "X" || dir == "0") s.dir = 0;
    else if (dir == "Y") s.dir = 1;
    else if (dir == "Z") s.dir = 2;
    else
      throw InputError(ctx.where(l.number) + b.keyword + ": field DIR must be X, Y or Z (the axis along N1 -> "
                       "N2; blank: X); got '" + dir + "'");
  });
}

void read_define_coordinate_vector(const Context& ctx, Block& b, model::Model& m, bool titled) {
  read_systems(ctx, b, m, titled, CoordinateSystem::Kind::vectors, [&](const Card& c, const Line&, CoordinateSystem& s) {
    static const char* const x[] = {"XX", "YX", "ZX"};
    static const char* const v[] = {"XV", "YV", "ZV"};
    get_vec(c, 1, x, s.axis);
    get_vec(c, 4, v, s.plane);
    c.get(7, "NID", s.nodes[0]);
  });
}

}  // namespace slideline::keyword
