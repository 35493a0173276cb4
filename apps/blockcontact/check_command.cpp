// blockcontact check <deck>: read and validate a deck, report counts and every problem.
#include <fmt/core.h>

#include <map>
#include <memory>
#include <string>

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

int run_check(const std::string& deck, bool ignore_unsupported) {
  std::size_t warnings = 0;
  const auto m = read_deck(deck, ignore_unsupported, warnings);
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
  fmt::print("  supports  {} SPC, {} prescribed motion\n", m.spcs.size(), m.prescribed_motions.size());
  fmt::print("  loads     {} body load(s), {} curve(s)\n", m.body_loads.size(), m.curves.size());
  fmt::print("  contacts  {}\n", m.contacts.size());
  for (const auto& c : m.contacts)
    fmt::print("    {:<28} {:<20} {} ({})\n", c.title.empty() ? fmt::format("#{}", c.cid) : c.title,
               contact_type_name(c), slideline::model::enforcement_name(c.enforcement), c.keyword);
  fmt::print("  end time  {:g}\n", m.termination.endtim);
  const auto problems = slideline::check_references(m);
  for (const auto& p : problems) fmt::print(stderr, "error: {}\n", slideline::to_string(p));
  if (!problems.empty()) {
    fmt::print(stderr, "{}: {} problem(s)\n", deck, problems.size());
    return kBadInput;
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
