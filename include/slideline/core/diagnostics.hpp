#pragma once
/// Located messages (a problem or a warning with the file and line of the card it is about) and
/// the sink the library hands its warnings to: the library never prints. A caller passes a sink
/// in (BuildOptions::diagnostics, which the builder hands on to the contact interfaces); without
/// one, warnings are dropped. The CLI passes a sink that writes each warning to stderr.
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

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

/// Where the library's warnings go.
class DiagnosticSink {
 public:
  virtual ~DiagnosticSink() = default;
  /// One warning. Called from the thread that runs the simulation, never from a parallel region.
  virtual void warning(const Diagnostic& d) = 0;
};

/// A sink that keeps every warning (tests; callers that show them later).
class DiagnosticList final : public DiagnosticSink {
 public:
  void warning(const Diagnostic& d) override { warnings.push_back(d); }
  std::vector<Diagnostic> warnings;
};

/// Hands a warning without a card location (`fmt`, printf-style, and its arguments) to `sink`;
/// nothing when `sink` is null.
template <class... Args>
void warn(DiagnosticSink* sink, const char* fmt, Args... args) {
  if (!sink) return;
  const int n = std::snprintf(nullptr, 0, fmt, args...);
  std::string message(static_cast<std::size_t>(n > 0 ? n : 0), '\0');
  if (n > 0) std::snprintf(message.data(), message.size() + 1, fmt, args...);
  sink->warning({std::string(), 0, std::move(message)});
}

}  // namespace slideline
