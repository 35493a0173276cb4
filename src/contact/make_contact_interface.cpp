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

const model::Box* find_box(const model::Model& m, Id id) {
  for (const auto& b : m.boxes)
    if (b.boxid == id) return &b;
  return nullptr;
}

bool inside(const model::Box& b, const Vec3& p) {
  for (int k = 0; k < 3; ++k)
    if (p[k] < b.min[static_cast<std::size_t>(k)] || p[k] > b.max[static_cast<std::size_t>(k)]) return false;
  return true;
}

/// The segments of `surf` whose centroid lies in `box` (at the initial coordinates), with
/// adjacency rebuilt.
Surface segments_in_box(const Surface& surf, const model::Box& box, const NodalFields& nodes) {
  Surface out;
  for (Index s = 0; s < surf.segment_count(); ++s) {
    const Index* c = &surf.conn[4 * static_cast<std::size_t>(s)];
    const int n = surf.is_triangle(s) ? 3 : 4;
    Vec3 centroid = Vec3::Zero();
    for (int a = 0; a < n; ++a) centroid += nodes.x0.get(c[a]);
    if (!inside(box, centroid / n)) continue;
    out.conn.insert(out.conn.end(), c, c + 4);
    out.block.push_back(surf.block[s]);
    out.element.push_back(surf.element[s]);
    out.part.push_back(surf.part[s]);
    out.kind.push_back(surf.kind[s]);
    out.thickness.push_back(surf.thickness[s]);
  }
  build_surface_adjacency(out);
  return out;
}

}  // namespace

Surface node_set_faces(const std::vector<Index>& nodes, const ContactBuildContext& ctx, const std::string& context) {
  std::vector<Id> parts;
  for (const auto& [pid, part_nodes] : ctx.sets.part_nodes)
    if (std::any_of(nodes.begin(), nodes.end(),
                    [&](Index n) { return std::binary_search(part_nodes.begin(), part_nodes.end(), n); }))
      parts.push_back(pid);
  Surface faces;
  if (!parts.empty()) faces = build_surface_from_parts(ctx.blocks, ctx.nodes, parts, context);
  build_surface_adjacency(faces);
  return faces;
}

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
  // SBOXID / MBOXID (domain limiting): only the side's nodes, and segments whose centroid, lie in
  // the box at the start; applied here once, at build time, so every interface type honours it.
  const Id boxid = slave ? card.sboxid : card.mboxid;
  const model::Box* box = nullptr;
  if (boxid != 0) {
    box = find_box(ctx.model, boxid);
    if (!box)
      throw InputError(describe(card.src) + ": " + std::string(slave ? "SBOXID" : "MBOXID") + " of " + card_name(card) +
                       " refers to undefined box " + std::to_string(boxid) + " (*DEFINE_BOX)");
  }
  const std::string box_note = box ? " inside box " + std::to_string(boxid) : std::string();
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
      if (box) {
        std::erase_if(side.nodes, [&](Index n) { return !inside(*box, ctx.nodes.x0.get(n)); });
        if (side.nodes.empty()) throw InputError(context + " selects no nodes" + box_note);
      }
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
  if (box) side.surface = segments_in_box(side.surface, *box, ctx.nodes);
  side.nodes = side.surface.nodes;
  if (side.nodes.empty()) throw InputError(context + " selects no segments" + box_note);
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
