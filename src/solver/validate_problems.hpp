#pragma once
// Internal to the validation layer (validate_model*.cpp): the list of problems a model has, kept
// until every check has run, and the small field checks they share. Not installed.
#include <cstdio>
#include <string>
#include <vector>

#include "slideline/core/diagnostics.hpp"
#include "slideline/core/error.hpp"
#include "slideline/model/model.hpp"
#include "slideline/solver/build.hpp"

namespace slideline::validation {

struct Problems {
  std::vector<Diagnostic> input;          // bad input
  std::vector<Diagnostic> unimplemented;  // valid but not implemented yet

  void bad(const model::Source& src, std::string msg) { input.push_back({src.file, src.line, std::move(msg)}); }
  void todo(const model::Source& src, std::string msg) {
    unimplemented.push_back({src.file, src.line, std::move(msg)});
  }
  // The same, for messages that carry their own place ("file:line: ..." as describe() writes it,
  // or a card and id): the text the builder gave when it found them, kept to the letter.
  void bad(std::string msg) { input.push_back({std::string(), 0, std::move(msg)}); }
  void todo(std::string msg) { unimplemented.push_back({std::string(), 0, std::move(msg)}); }

  bool empty() const { return input.empty() && unimplemented.empty(); }

  [[noreturn]] void raise() const {
    std::string what;
    for (const auto* list : {&input, &unimplemented})
      for (const auto& d : *list) {
        if (!what.empty()) what += '\n';
        what += to_string(d);
      }
    if (input.empty()) throw NotImplementedError(what);
    throw InputError(what);
  }
};

inline std::string num(Real v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

/// Parts, sections, hourglass cards and the elements' nodes (validate_parts.cpp).
void check_parts(const model::Model& m, Problems& p);

/// Supports, prescribed motions on rigid parts, loads, damping, curves, the remaining controls and
/// contact titles (validate_loads.cpp).
void check_loads(const model::Model& m, Problems& p);

/// The fields of the initial-velocity cards that are not run or out of range
/// (validate_initial.cpp).
void check_initial_velocities(const model::Model& m, Problems& p);

}  // namespace slideline::validation
