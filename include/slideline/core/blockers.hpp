#pragma once
/// Everything that stops a deck from running, gathered instead of thrown at the first (the CLI's
/// `check`, ReadOptions::blockers, find_model_problems).
#include <vector>

#include "slideline/core/diagnostics.hpp"

namespace slideline {

/// Bad input (what InputError reports, exit 2) and valid input asking for what is not implemented
/// (NotImplementedError, exit 3). Each message carries its own place (file:line).
struct Blockers {
  std::vector<Diagnostic> input;
  std::vector<Diagnostic> unimplemented;
  bool empty() const { return input.empty() && unimplemented.empty(); }
};

}  // namespace slideline
