#pragma once
/// Where an input error comes from, as every message starts: the one rule for a deck card's location.
#include <string>

namespace slideline {

/// "file:line" of a deck card, "file" when the line is unknown, "deck:line" without a file name,
/// "(generated)" for a card built programmatically (no file, no line).
inline std::string describe_location(const std::string& file, int line) {
  if (line <= 0) return file.empty() ? "(generated)" : file;
  return (file.empty() ? std::string("deck") : file) + ":" + std::to_string(line);
}

}  // namespace slideline
