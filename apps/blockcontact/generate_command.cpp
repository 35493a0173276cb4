// blockcontact generate: writes the decks of the 19 sslide problems (docs/verification.md).
#include <fmt/core.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "slideline/io/keyword_writer.hpp"
#include "slideline/scenarios/sslide.hpp"

namespace blockcontact {
namespace {

struct GenerateOptions {
  std::vector<std::string> names;
  bool all = false;
  bool list = false;
  std::string out_dir = ".";
};

int run_generate(const GenerateOptions& o) {
  namespace sc = slideline::scenarios;
  if (o.list) {
    for (const auto& n : sc::sslide_problem_names()) fmt::print("{:<15} {}\n", n, sc::make_sslide_problem(n).description);
    return kOk;
  }
  const auto names = o.all ? sc::sslide_problem_names() : o.names;
  if (names.empty()) {
    fmt::print(stderr, "error: name a problem (blockcontact generate --list) or pass --all\n");
    return kBadInput;
  }
  std::filesystem::create_directories(o.out_dir);
  for (const auto& name : names) {
    const auto problem = sc::make_sslide_problem(name);  // InputError for an unknown name
    const auto path = (std::filesystem::path(o.out_dir) / (name + ".k")).string();
    slideline::write_keyword_file(problem.model, path);
    std::string pairings;
    for (const auto& p : problem.pairings) {
      if (!pairings.empty()) pairings += ", ";
      pairings += p.name;
    }
    fmt::print("{}: {} nodes, {} elements, pairings {}\n", path, problem.model.nodes.size(),
               problem.model.solids.size() + problem.model.shells.size(), pairings);
  }
  return kOk;
}

}  // namespace

void register_generate(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("generate", "Write the decks of the spec's 19 sslide problems");
  auto o = std::make_shared<GenerateOptions>();
  cmd->add_option("names", o->names, "Problem names (sslide1k ... sslide12l_vec)");
  cmd->add_flag("--all", o->all, "All 19 problems");
  cmd->add_flag("--list", o->list, "List the problems and exit");
  cmd->add_option("-o,--output", o->out_dir, "Output directory (created if missing)")->capture_default_str();
  cmd->callback([o, &exit_code] { exit_code = run_generate(*o); });
}

}  // namespace blockcontact
