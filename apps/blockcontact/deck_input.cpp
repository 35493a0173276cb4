// Reading a deck for run and check: warnings are printed even when an error follows, ignored
// physics cards are listed, and the reference check's problems are printed.
#include <fmt/core.h>

#include "commands.hpp"
#include "slideline/io/keyword_reader.hpp"

namespace blockcontact {

slideline::model::Model read_deck(const std::string& deck, bool ignore_unsupported, std::size_t& warning_count,
                                  slideline::Blockers* blockers) {
  std::vector<slideline::Diagnostic> warnings;
  slideline::ReadOptions options;
  options.ignore_unsupported = ignore_unsupported;
  options.blockers = blockers;
  const auto print = [&] {
    for (const auto& w : warnings) fmt::print(stderr, "warning: {}\n", slideline::to_string(w));
    warning_count = warnings.size();
  };
  try {
    auto m = slideline::read_keyword_file(deck, &warnings, options);
    print();
    return m;
  } catch (...) {
    print();  // what the reader saw before the error may explain it
    throw;
  }
}

void print_dropped(const slideline::model::Model& m) {
  if (m.unsupported.empty()) return;
  fmt::print("dropped {} unsupported card(s) (--ignore-unsupported); the results do not include them:\n",
             m.unsupported.size());
  for (const auto& d : slideline::describe_dropped(m)) fmt::print("  dropped: {}\n", slideline::to_string(d));
}

}  // namespace blockcontact
