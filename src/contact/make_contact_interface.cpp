#include "slideline/contact/make_contact_interface.hpp"

#include <algorithm>

#include "slideline/contact/make_tiebreak_contact.hpp"
#include "slideline/core/error.hpp"
#include "slideline/mesh/surface_builder.hpp"
#include "slideline/solver/build.hpp"

namespace slideline {

namespace {

std::string card_name(const model::Contact& card) {
  return card.keyword.empty() ? std::string("*CONTACT") : card.keyword;
}

std::vector<Id> all_parts(const ContactBuildContext& ctx) {
  std::vector<Id> parts;
  for (const auto& [pid, nodes] : ctx.sets.part_nodes) parts.push_back(pid);
  return parts;
}

}  // namespace

std::string contact_title(const model::Contact& card, std::size_t position) {
  if (!card.title.empty()) return card.title;
  if (card.cid != 0) return "contact_" + std::to_string(card.cid);
  return "contact_" + std::to_string(position);
}

void throw_contact_not_implemented(const model::Contact& card, const std::string& what) {
  const char* enforcement = card.enforcement == model::Enforcement::lagrange    ? ", Lagrange multiplier"
                            : card.enforcement == model::Enforcement::kinematic ? ", kinematic"
                                                                                 : ", penalty";
  throw NotImplementedError(describe(card.src) + ": " + card_name(card) + " (DYNA3D type " +
                            std::to_string(static_cast<int>(card.type)) + enforcement + ")" +
                            (what.empty() ? std::string(" is not implemented yet") : ": " + what));
}

ContactSide resolve_contact_side(const model::Contact& card, bool slave, const ContactBuildContext& ctx) {
  const Id sid = slave ? card.ssid : card.msid;
  const int typ = slave ? card.sstyp : card.mstyp;
  const std::string field = slave ? "SSID" : "MSID";
  const std::string context = describe(card.src) + ": " + field + " of " + card_name(card);
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
  side.nodes = side.surface.nodes;
  if (side.nodes.empty()) throw InputError(context + " selects no segments");
  return side;
}

std::unique_ptr<ContactAlgorithm> make_contact_interface(const model::Contact& card, std::size_t position,
                                                         const ContactBuildContext& ctx) {
  const std::string title = contact_title(card, position);
  using T = model::ContactType;
  const bool lagrange = card.enforcement == model::Enforcement::lagrange;
  switch (card.type) {
    case T::tied_surface:
    case T::tied_nodes:
    case T::tied_shell_edge:
      return make_tied_contact(card, title, ctx);
    case T::sliding_only:
      return make_sliding_only_contact(card, title, ctx);
    case T::surface_to_surface:
    case T::one_way:
      return lagrange ? make_lagrange_contact(card, title, ctx) : make_sliding_contact(card, title, ctx);
    case T::nodes_to_surface:
    case T::automatic:
      return lagrange ? make_lagrange_contact(card, title, ctx)
                      : make_node_and_automatic_contact(card, title, ctx);
    case T::tiebreak_nodes:
    case T::tiebreak_surface:
      return make_tiebreak_contact(card, title, ctx);
  }
  throw_contact_not_implemented(card);
}

}  // namespace slideline
