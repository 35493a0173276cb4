// *KEYWORD_ID and the node sets whose nodes are generated rather than listed:
// *SET_NODE_LIST_GENERATE (id ranges) and *SET_NODE_GENERAL (ALL, NODE, PART, BOX and their
// deleting forms). Their nodes depend on nodes, elements and boxes that may come later in the
// deck, so the handlers record the rules and resolve_node_sets fills the sets once the whole deck
// is read; the model then holds a plain node list (the writer writes it as *SET_NODE_LIST).
#include <algorithm>
#include <set>
#include <string>
#include <string_view>

#include "keyword_card.hpp"
#include "slideline/core/error.hpp"

namespace slideline::keyword {
namespace {

using model::Model;

/// The options of *SET_NODE_GENERAL that are resolved here; the others are refused by name.
constexpr std::string_view kGeneralOptions[] = {"ALL", "NODE", "PART", "BOX", "DNODE", "DPART", "DBOX"};

/// Reads the optional title and the SID card, adds an empty set to the model and returns its
/// pending record. DA1..DA4 and SOLVER are not read (as for *SET_NODE_LIST).
PendingNodeSet& begin_set(const Context& ctx, Block& b, Model& m, bool titled) {
  model::NodeSet s;
  if (titled) {
    const Line* t = b.take();
    if (!t) throw InputError(ctx.where(b.line) + b.keyword + ": missing title card");
    s.title = heading(*t);
  }
  const Line* l = b.take();
  if (!l) throw InputError(ctx.where(b.line) + b.keyword + ": missing SID card");
  Card(ctx, *l, b.keyword, kStandard).get(0, "SID", s.sid);
  s.src = ctx.source(l->number);
  m.node_sets.push_back(std::move(s));
  if (!ctx.deck) throw Error(ctx.where(b.line) + b.keyword + ": read outside a deck");
  ctx.deck->node_sets.push_back({m.node_sets.size() - 1, {}});
  return ctx.deck->node_sets.back();
}

/// Node ids of the deck's elements of the parts `pids`.
void add_part_nodes(const Model& m, const std::vector<Id>& pids, std::set<Id>& out) {
  const auto wanted = [&](Id pid) { return std::find(pids.begin(), pids.end(), pid) != pids.end(); };
  for (const auto& e : m.solids)
    if (wanted(e.pid)) out.insert(e.n.begin(), e.n.end());
  for (const auto& e : m.shells)
    if (wanted(e.pid)) out.insert(e.n.begin(), e.n.end());
}

/// Node ids of the deck's nodes inside box `boxid` (initial coordinates, boundaries included).
void add_box_nodes(const Model& m, const model::Box& box, std::set<Id>& out) {
  for (const auto& n : m.nodes) {
    bool inside = true;
    for (int c = 0; c < 3; ++c)
      inside = inside && n.x[c] >= box.min[static_cast<std::size_t>(c)] && n.x[c] <= box.max[static_cast<std::size_t>(c)];
    if (inside) out.insert(n.id);
  }
}

/// The nodes one rule names (before adding or deleting them).
std::set<Id> rule_nodes(const Model& m, const NodeSetRule& r, std::string_view kind) {
  std::set<Id> nodes;
  if (kind == "ALL") {
    for (const auto& n : m.nodes) nodes.insert(n.id);
  } else if (kind == "RANGE") {
    for (const auto& n : m.nodes)
      if (n.id >= r.ids[0] && n.id <= r.ids[1]) nodes.insert(n.id);
  } else if (kind == "NODE") {
    nodes.insert(r.ids.begin(), r.ids.end());  // undefined ids: check_references names them
  } else if (kind == "PART") {
    for (Id pid : r.ids)
      if (std::none_of(m.parts.begin(), m.parts.end(), [&](const model::Part& p) { return p.pid == pid; }))
        throw InputError(r.file + ":" + std::to_string(r.line) + ": field E of *SET_NODE_GENERAL (PART) refers to part " +
                         std::to_string(pid) + ", which the deck does not define");
    add_part_nodes(m, r.ids, nodes);
  } else {  // BOX
    for (Id boxid : r.ids) {
      const auto box = std::find_if(m.boxes.begin(), m.boxes.end(), [&](const model::Box& x) { return x.boxid == boxid; });
      if (box == m.boxes.end())
        throw InputError(r.file + ":" + std::to_string(r.line) + ": field E of *SET_NODE_GENERAL (BOX) refers to box " +
                         std::to_string(boxid) + ", which the deck does not define (*DEFINE_BOX)");
      add_box_nodes(m, *box, nodes);
    }
  }
  return nodes;
}

}  // namespace

void read_keyword_id(const Context&, Block& b, Model& m) {
  // The identification (PROJECT NUM STAGE) names the run only: kept as the title unless the deck
  // has a *TITLE (which, coming later, replaces it).
  if (const Line* l = b.take())
    if (m.title.empty()) m.title = heading(*l);
}

void read_set_node_generate(const Context& ctx, Block& b, Model& m, bool titled) {
  PendingNodeSet& set = begin_set(ctx, b, m, titled);
  static const char* const names[] = {"B1BEG", "B1END", "B2BEG", "B2END", "B3BEG", "B3END", "B4BEG", "B4END"};
  while (const Line* l = b.take()) {
    const Card c(ctx, *l, b.keyword, kStandard);
    for (int k = 0; k < 4; ++k) {
      Id beg = 0, end = 0;
      c.get(2 * k, names[2 * k], beg);
      c.get(2 * k + 1, names[2 * k + 1], end);
      if (beg == 0 && end == 0) continue;
      if (beg <= 0 || end < beg)
        throw InputError(ctx.where(l->number) + "fields " + names[2 * k] + ", " + names[2 * k + 1] + " of " +
                         b.keyword + ": a range of node ids needs 0 < BEG <= END (got " + std::to_string(beg) +
                         ", " + std::to_string(end) + ")");
      set.rules.push_back({"RANGE", {beg, end}, ctx.file, l->number});
    }
    if (c.size() > 8 && !c.blank(8))
      throw InputError(ctx.where(l->number) + b.keyword + ": a card holds at most 4 ranges (8 fields)");
  }
}

void read_set_node_general(const Context& ctx, Block& b, Model& m, bool titled) {
  PendingNodeSet& set = begin_set(ctx, b, m, titled);
  while (const Line* l = b.take()) {
    const Card c(ctx, *l, b.keyword, kStandard);
    if (c.all_blank()) continue;
    const std::string option = upper(c.raw(0));
    if (std::find(std::begin(kGeneralOptions), std::end(kGeneralOptions), option) == std::end(kGeneralOptions))
      throw NotImplementedError(ctx.where(l->number) + "field OPTION of " + b.keyword + ": '" + option +
                                "' is not supported (only ALL, NODE, PART, BOX and DNODE, DPART, DBOX)");
    NodeSetRule r{option, {}, ctx.file, l->number};
    static const char* const names[] = {"E1", "E2", "E3", "E4", "E5", "E6", "E7"};
    for (int k = 1; k < 8; ++k) {
      Id id = 0;
      c.get(k, names[k - 1], id);
      if (id != 0) r.ids.push_back(id);
    }
    set.rules.push_back(std::move(r));
  }
}

void resolve_node_sets(const DeckState& deck, Model& m) {
  for (const auto& pending : deck.node_sets) {
    std::set<Id> nodes;
    for (const auto& r : pending.rules) {
      const bool remove = r.option.front() == 'D';  // DNODE, DPART, DBOX (the options are checked when read)
      const std::string_view kind = remove ? std::string_view(r.option).substr(1) : std::string_view(r.option);
      const std::set<Id> named = rule_nodes(m, r, kind);
      if (remove) {
        for (Id n : named) nodes.erase(n);
      } else {
        nodes.insert(named.begin(), named.end());
      }
    }
    m.node_sets[pending.index].nodes.assign(nodes.begin(), nodes.end());
  }
}

}  // namespace slideline::keyword
