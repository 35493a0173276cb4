// Keywords no handler reads: the classification table, the warnings and errors they give, and
// the lookups that let later checks name a dropped card ("part 1 uses *MAT_... (line 72)").
#include "keyword_unsupported.hpp"

#include <algorithm>
#include <iterator>
#include <map>

#include "slideline/core/error.hpp"
#include "slideline/io/keyword_table.hpp"
#include "slideline/model/unsupported.hpp"

namespace slideline::keyword {
namespace {

// First matching prefix wins, so the specific rules come before the general ones. A keyword that
// matches nothing is treated as physics: silently dropping a card we do not know is how a run
// gives a wrong answer with exit code 0.
constexpr UnsupportedKeywordClass kRules[] = {
    {"*CONTROL_IMPLICIT", true, "implicit analysis control"},
    {"*CONTROL_", false, "control or tuning card"},
    {"*DATABASE_", false, "output request"},
    {"*PARAMETER_DUPLICATION", false, "parameter redefinition control"},
    {"*COMMENT", false, "comment"},
    {"*MAT_", true, "material"},
    {"*MAT", true, "material"},
    {"*SECTION_", true, "section"},
    {"*ELEMENT_", true, "element kind"},
    {"*LOAD_", true, "load"},
    {"*BOUNDARY_", true, "boundary condition"},
    {"*INITIAL_", true, "initial condition"},
    {"*CONSTRAINED_", true, "constraint"},
    {"*RIGIDWALL", true, "rigid wall"},
    {"*CONTACT_", true, "contact type"},
    {"*CONTACT", true, "contact type"},
    {"*PART", true, "part option"},
    {"*EOS", true, "equation of state"},
    {"*HOURGLASS", true, "hourglass option"},
    {"*DAMPING_", true, "damping"},
    {"*DEFINE_", true, "definition (curve, table, box, coordinate system, ...)"},
    {"*SET_", true, "set"},
    {"*NODE", true, "node option"},
    {"*INCLUDE", true, "include option"},
    {"*PARAMETER", true, "parameter option"},
};

bool starts_with(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }

/// The first field of the block's first data card (after a _TITLE heading), when an integer.
Id first_id(const Context& ctx, Block& block) {
  std::size_t k = 0;
  const std::string_view kw = block.keyword;
  if (kw.size() > 6 && kw.substr(kw.size() - 6) == "_TITLE") ++k;
  for (; k < block.cards.size(); ++k) {
    if (trim(block.cards[k].text).empty()) continue;
    try {
      Card c(ctx, block.cards[k], block.keyword, kStandard);
      Id id = 0;
      if (parse_integer(c.raw(0), id)) return id;
    } catch (const Error&) {
      // An undefined &parameter: the id is only for messages.
    }
    return 0;
  }
  return 0;
}

std::string plural(int n, const char* what) {
  return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
}

/// "part 1, 3" of the parts (or other items) that refer to the dropped card, or "".
std::string users(const model::Model& m, const model::UnsupportedCard& u) {
  const std::string_view kind = model::defined_kind(u.keyword);
  std::vector<std::string> who;
  if (u.id != 0) {
    for (const auto& p : m.parts) {
      if ((kind == "material" && p.mid == u.id) || (kind == "section" && p.secid == u.id) ||
          (kind == "equation of state" && p.eosid == u.id) || (kind == "hourglass" && p.hgid == u.id))
        who.push_back("part " + std::to_string(p.pid));
    }
    if (kind == "node set")
      for (const auto& s : m.spcs)
        if (s.nsid == u.id) who.push_back("*BOUNDARY_SPC_SET (line " + std::to_string(s.src.line) + ")");
    if (kind == "curve")
      for (const auto& b : m.body_loads)
        if (b.lcid == u.id) who.push_back("*LOAD_BODY (line " + std::to_string(b.src.line) + ")");
  }
  if (who.empty()) return "";
  std::string s = "; used by ";
  for (std::size_t i = 0; i < who.size() && i < 3; ++i) s += (i ? ", " : "") + who[i];
  if (who.size() > 3) s += " and " + std::to_string(who.size() - 3) + " more";
  return s;
}

}  // namespace

Classification classify(std::string_view keyword) {
  for (const auto& r : kRules)
    if (starts_with(keyword, r.prefix)) return {r.physics ? CardKind::physics : CardKind::output, r.what};
  return {CardKind::physics, "keyword not in slideline's tables"};
}

void UnsupportedLog::add(const Context& ctx, Block& block, int cards) {
  const auto c = classify(block.keyword);
  if (c.kind == CardKind::output) {
    for (auto& s : output_)
      if (s.keyword == block.keyword) {
        ++s.count;
        s.cards += cards;
        return;
      }
    output_.push_back({block.keyword, ctx.source(block.line), 1, cards});
    return;
  }
  physics_.push_back({block.keyword, first_id(ctx, block), cards, ctx.source(block.line)});
}

void UnsupportedLog::finish(model::Model& model, std::vector<Diagnostic>* warnings, bool ignore, Blockers* blockers) {
  if (warnings)
    for (const auto& s : output_) {
      std::string msg = s.keyword + " skipped: " + std::string(classify(s.keyword).what) +
                        " that slideline does not use";
      if (s.count > 1) msg += " (" + plural(s.count, "keyword") + ", first here)";
      warnings->push_back({s.src.file, s.src.line, std::move(msg)});
    }
  if (physics_.empty()) return;

  // One line per keyword: the first occurrence, the count and the ids.
  std::vector<std::string> order;
  std::map<std::string, std::vector<const model::UnsupportedCard*>> groups;
  for (const auto& u : physics_) {
    auto& g = groups[u.keyword];
    if (g.empty()) order.push_back(u.keyword);
    g.push_back(&u);
  }
  std::vector<Diagnostic> lines;
  for (const auto& kw : order) {
    const auto& g = groups[kw];
    const auto& first = *g.front();
    const std::string_view kind = model::defined_kind(kw);
    std::string detail(classify(kw).what);
    if (!kind.empty() && first.id != 0) {
      detail += " " + std::to_string(first.id);
      for (std::size_t i = 1; i < g.size() && i < 4; ++i) detail += ", " + std::to_string(g[i]->id);
      if (g.size() > 4) detail += ", ...";
    }
    for (const auto* u : g) {
      detail += users(model, *u);
      if (detail.size() > 200) break;
    }
    std::string msg = kw + " (" + detail + ")";
    if (g.size() > 1) msg += " x" + std::to_string(g.size()) + ", first here,";
    msg += ignore ? " dropped: not supported (--ignore-unsupported)" : " is not supported";
    lines.push_back({first.src.file, first.src.line, std::move(msg)});
  }
  if (ignore) {
    if (warnings) warnings->insert(warnings->end(), lines.begin(), lines.end());
    model.unsupported = std::move(physics_);
    return;
  }
  const std::string summary = std::to_string(physics_.size()) +
                              " unsupported card(s) that carry physics: the deck cannot be run as written "
                              "(blockcontact --ignore-unsupported drops them and lists what it dropped)";
  if (blockers) {
    blockers->unimplemented.insert(blockers->unimplemented.end(), lines.begin(), lines.end());
    blockers->unimplemented.push_back({std::string(), 0, summary});
    model.unsupported = std::move(physics_);
    return;
  }
  std::string what;
  for (const auto& d : lines) what += to_string(d) + "\n";
  throw NotImplementedError(what + summary);
}

}  // namespace slideline::keyword

namespace slideline {

const std::vector<UnsupportedKeywordClass>& unsupported_keyword_classes() {
  static const std::vector<UnsupportedKeywordClass> classes(std::begin(keyword::kRules), std::end(keyword::kRules));
  return classes;
}

std::vector<Diagnostic> describe_dropped(const model::Model& m) {
  std::vector<Diagnostic> out;
  for (const auto& u : m.unsupported) {
    std::string msg = u.keyword;
    if (u.id != 0) msg += " (id " + std::to_string(u.id) + ")";
    msg += " dropped, " + std::to_string(u.cards) + " card(s)";
    out.push_back({u.src.file, u.src.line, std::move(msg)});
  }
  return out;
}

}  // namespace slideline
