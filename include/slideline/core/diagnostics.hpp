#pragma once
/// Located messages: a problem or a warning with the file and line of the card it is about.
#include <string>

namespace slideline {

/// A located message. line = 0 when the item has no card line; file "" when it has no file.
struct Diagnostic {
  std::string file;
  int line = 0;
  std::string message;
};

/// "file:line: message", "file: message" without a line, "message" without a file.
inline std::string to_string(const Diagnostic& d) {
  if (d.file.empty()) return d.message;
  if (d.line <= 0) return d.file + ": " + d.message;
  return d.file + ":" + std::to_string(d.line) + ": " + d.message;
}

}  // namespace slideline
