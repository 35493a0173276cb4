// blockcontact check <deck>: read and validate a deck, report counts and every problem.
#include <fmt/core.h>

#include <algorithm>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "commands.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/model/contact_keywords.hpp"
#include "slideline/solver/build.hpp"
#include "slideline/solver/validate_model.hpp"

namespace blockcontact {

namespace {

/// "type 3 surface to surface", from the contact keyword table.
std::string contact_type_name(const slideline::model::Contact& c) {
  const auto* k = slideline::model::contact_keyword(c);
  return k ? fmt::format("type {} {}", k->dyna3d_type, k->name) : std::string("?");
}

void print_counts(const std::string& deck, const slideline::model::Model& m) {
  fmt::print("{}\n", deck);
  if (!m.title.empty()) fmt::print("  title     {}\n", m.title);
  fmt::print("  nodes     {}\n", m.nodes.size());
  fmt::print("  elements  {} ({} solid, {} shell)\n", m.solids.size() + m.shells.size(), m.solids.size(),
             m.shells.size());
  fmt::print("  parts     {} (sections {}, materials {})\n", m.parts.size(),
             m.solid_sections.size() + m.shell_sections.size(), m.materials.size());
  fmt::print("  sets      {} ({} node, {} segment, {} part)\n",
             m.node_sets.size() + m.segment_sets.size() + m.part_sets.size(), m.node_sets.size(),
             m.segment_sets.size(), m.part_sets.size());
  const auto coded = std::count_if(m.nodes.begin(), m.nodes.end(), [](const auto& n) { return n.tc != 0 || n.rc != 0; });
  fmt::print("  supports  {} SPC, {} prescribed motion, {} node(s) with *NODE TC/RC codes\n", m.spcs.size(),
             m.prescribed_motions.size(), coded);
  fmt::print("  loads     {} body load(s), {} curve(s)\n", m.body_loads.size(), m.curves.size());
  fmt::print("  contacts  {}\n", m.contacts.size());
  for (const auto& c : m.contacts)
    fmt::print("    {:<28} {:<20} {} ({})\n", c.title.empty() ? fmt::format("#{}", c.cid) : c.title,
               contact_type_name(c), slideline::model::enforcement_name(c.enforcement), c.keyword);
  fmt::print("  end time  {:g}\n", m.termination.endtim);
}

/// Prints one stage's blockers ("error: " bad input, "not implemented: " the rest), each message
/// once over all stages (`seen`: a dropped card's users are named by the reference check and the
/// validation layer alike), and counts them into `total`; returns whether any was bad input.
bool print_blockers(const slideline::Blockers& b, std::set<std::string>& seen, std::size_t& total) {
  const auto print = [&](const std::vector<slideline::Diagnostic>& list, const char* kind) {
    for (const auto& d : list) {
      const std::string text = slideline::to_string(d);
      if (!seen.insert(text).second) continue;
      fmt::print(stderr, "{}: {}\n", kind, text);
      ++total;
    }
  };
  print(b.input, "error");
  print(b.unimplemented, "not implemented");
  return !b.input.empty();
}

/// A reference to a card the reader listed as unsupported is that feature missing, as the
/// validation layer says (its not-implemented list holds the same line), not bad input; with
/// --ignore-unsupported it stays an error, as in `run`.
void move_dropped_references(slideline::Blockers& refs, const slideline::Blockers& validation) {
  auto& in = refs.input;
  for (auto it = in.begin(); it != in.end();) {
    const std::string text = slideline::to_string(*it);
    const bool missing = std::any_of(validation.unimplemented.begin(), validation.unimplemented.end(),
                                     [&](const slideline::Diagnostic& d) { return slideline::to_string(d) == text; });
    if (!missing) {
      ++it;
      continue;
    }
    refs.unimplemented.push_back(*it);
    it = in.erase(it);
  }
}

int run_check(const std::string& deck, bool ignore_unsupported) {
  std::size_t warnings = 0;
  // Every blocker at once, stage by stage: what the reader skipped (malformed or refused cards,
  // unsupported keywords), dangling ids, and what the validation layer refuses (element forms,
  // material constants, fields not implemented).
  slideline::Blockers reader;
  const auto m = read_deck(deck, ignore_unsupported, warnings, &reader);
  print_counts(deck, m);
  slideline::Blockers refs;
  refs.input = slideline::check_references(m);
  slideline::Blockers validation;
  if (!m.nodes.empty() && (!m.solids.empty() || !m.shells.empty()))  // else the references said so
    validation = slideline::find_model_problems(m);
  if (!ignore_unsupported) move_dropped_references(refs, validation);
  std::size_t total = 0;
  std::set<std::string> seen;
  bool bad = false;
  for (const auto* stage : {&reader, &refs, &validation}) bad = print_blockers(*stage, seen, total) || bad;
  if (total > 0) {
    fmt::print(stderr, "{}: {} problem(s); the deck cannot be run as written\n", deck, total);
    return bad ? kBadInput : kNotImplemented;
  }
  print_dropped(m);
  // Everything `run` checks before its first step: the build (element kinds, volumes and node
  // order, materials, controls, unsupported features) and the initialisation (masses, first step).
  StderrDiagnostics diagnostics;  // outlives sim
  slideline::BuildOptions build;
  build.diagnostics = &diagnostics;
  auto sim = slideline::build_simulation(m, build);
  sim->initialize();
  fmt::print("ok ({} warning(s){})\n", warnings,
             m.unsupported.empty() ? "" : fmt::format(", {} card(s) dropped", m.unsupported.size()));
  return kOk;
}

}  // namespace

void register_check(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("check", "Read and validate a keyword deck without running it");
  auto deck = std::make_shared<std::string>();
  auto ignore = std::make_shared<bool>(false);
  cmd->add_option("deck", *deck, "Keyword deck (.k)")->required()->check(CLI::ExistingFile);
  cmd->add_flag("--ignore-unsupported", *ignore,
                "Accept a deck with unsupported physics cards: drop them and list them");
  cmd->callback([deck, ignore, &exit_code] { exit_code = run_check(*deck, *ignore); });
}

}  // namespace blockcontact
