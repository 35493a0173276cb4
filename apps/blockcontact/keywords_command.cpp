// blockcontact keywords [--unsupported]: the keywords the reader reads, one line each, from the
// reader's own table (slideline/io/keyword_table.hpp); with --unsupported, the keyword classes it
// knows and does not read, and what it does with them.
#include <fmt/core.h>

#include <algorithm>
#include <memory>
#include <string>

#include "commands.hpp"
#include "slideline/io/keyword_table.hpp"

namespace blockcontact {

namespace {

int print_supported() {
  const auto& keywords = slideline::supported_keywords();
  std::size_t width = 0;
  for (const auto& k : keywords) width = std::max(width, k.name.size() + k.options.size());
  for (const auto& k : keywords) fmt::print("{:<{}}  {}\n", k.name + k.options, width, k.description);
  return kOk;
}

int print_unsupported() {
  fmt::print("Keywords the reader knows and does not read (first matching prefix; not those listed by\n"
             "`blockcontact keywords`):\n");
  for (const auto& c : slideline::unsupported_keyword_classes())
    fmt::print("{:<28} {}: {}\n", std::string(c.prefix) + "...", c.what,
               c.physics ? "refused, it carries physics (--ignore-unsupported drops it and lists it)"
                         : "skipped with a warning, it only tunes output or speed");
  fmt::print("{:<28} {}\n", "any other keyword", "refused: a card we do not know may carry physics");
  return kOk;
}

}  // namespace

void register_keywords(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("keywords", "List the keywords the deck reader reads");
  auto unsupported = std::make_shared<bool>(false);
  cmd->add_flag("--unsupported", *unsupported,
                "List instead the keyword classes the reader knows and refuses or skips, with why");
  cmd->callback([unsupported, &exit_code] { exit_code = *unsupported ? print_unsupported() : print_supported(); });
}

}  // namespace blockcontact
