#pragma once
// The blockcontact subcommands. Each registers itself on the CLI11 app and returns the process
// exit code through `exit_code` when it runs; a new subcommand (list, generate, verify, keywords) is one
// more register_* function and one call in main.cpp.
#include <CLI/CLI.hpp>

#include <cstddef>
#include <cstdio>
#include <string>

#include "slideline/core/blockers.hpp"
#include "slideline/core/diagnostics.hpp"
#include "slideline/model/model.hpp"

namespace blockcontact {

/// Exit codes: 0 success, 1 other failure, 2 bad input, 3 not implemented, 4 instability,
/// 5 interrupted (SIGINT/SIGTERM; the output files are closed and hold the run up to the stop).
enum ExitCode : int {
  kOk = 0,
  kFailure = 1,
  kBadInput = 2,
  kNotImplemented = 3,
  kInstability = 4,
  kInterrupted = 5
};

void register_run(CLI::App& app, int& exit_code);
void register_check(CLI::App& app, int& exit_code);
void register_generate(CLI::App& app, int& exit_code);
void register_verify(CLI::App& app, int& exit_code);
void register_keywords(CLI::App& app, int& exit_code);

/// Reads a deck, printing the reader's warnings to stderr (also when it then throws).
/// `ignore_unsupported` drops unsupported physics cards instead of failing (deck_input.cpp).
slideline::model::Model read_deck(const std::string& deck, bool ignore_unsupported, std::size_t& warning_count,
                                  slideline::Blockers* blockers = nullptr);
/// Prints the cards --ignore-unsupported dropped, one line each, to stdout (the run log).
void print_dropped(const slideline::model::Model& model);

/// The CLI's sink for the library's warnings (slideline::BuildOptions::diagnostics): each one to
/// stderr as one line, "file:line: message" (the message alone when it has no card location).
class StderrDiagnostics final : public slideline::DiagnosticSink {
 public:
  void warning(const slideline::Diagnostic& d) override {
    std::fprintf(stderr, "%s\n", slideline::to_string(d).c_str());
  }
};

}  // namespace blockcontact
