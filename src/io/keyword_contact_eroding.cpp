// *CONTACT_ERODING_SINGLE_SURFACE, _SURFACE_TO_SURFACE, _NODES_TO_SURFACE: the mandatory card 4
// (ISYM EROSOP IADJ). The cards run as their automatic counterparts with the surfaces updated as
// elements are deleted (docs/contact_erosion.md). Each field is honoured or refused, naming file,
// line, card, field and value; blank and 0 are the same number.
#include <string>

#include "keyword_card.hpp"
#include "slideline/core/error.hpp"

namespace slideline::keyword {

void read_eroding_card4(const Context& ctx, Block& b, model::Contact& c) {
  const Line* l = b.take();
  if (!l) return;  // the card left out: ISYM = EROSOP = IADJ = 0 (the manual's defaults)
  const Card k(ctx, *l, b.keyword, kStandard);
  k.get(0, "ISYM", c.isym);
  k.get(1, "EROSOP", c.erosop);
  k.get(2, "IADJ", c.iadj);
  const std::string at = ctx.where(l->number) + c.keyword + " card 4: field ";
  if (c.isym != 0 && c.isym != 1)
    throw InputError(at + "ISYM must be 0 or 1 (faces on symmetry planes left out of the contact; got " +
                     std::to_string(c.isym) + ")");
  if (c.erosop != 0 && c.erosop != 1)
    throw InputError(at + "EROSOP must be 0 or 1 (got " + std::to_string(c.erosop) + ")");
  if (c.iadj != 0 && c.iadj != 1)
    throw InputError(at + "IADJ must be 0 (faces on the free boundary) or 1 (also the faces between parts, "
                     "the boundary of each part's subset of the mesh; got " + std::to_string(c.iadj) + ")");
  for (int i = 3; i < 8; ++i) {
    Real v = 0.0;
    k.get(i, "(unused)", v);
    if (v != 0.0)
      throw InputError(at + std::to_string(i + 1) + " = " + std::to_string(v) +
                       " is not a field of this card (ISYM EROSOP IADJ)");
  }
  // Optional card B (after card A, the next card still in the block): SNLOG != 0 turns off the
  // shooting-node logic, which the eroding passes always have (docs/contact_erosion.md, "Sudden
  // penetrations"): refused here; on the other cards it is warned (keyword_contact_fields.cpp).
  if (b.next + 1 < b.cards.size()) {
    const Line& lb = b.cards[b.next + 1];
    int snlog = 0;
    Card(ctx, lb, b.keyword, kStandard).get(3, "SNLOG", snlog);
    if (snlog != 0)
      throw NotImplementedError(ctx.where(lb.number) + c.keyword + " optional card B: SNLOG = " +
                                std::to_string(snlog) + " turns off the shooting-node logic, which the eroding "
                                "contacts always have here (sudden penetrations kept as the springs' zero; "
                                "docs/contact_erosion.md): not implemented");
  }
}

}  // namespace slideline::keyword
