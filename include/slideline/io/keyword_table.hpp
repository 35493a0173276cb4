#pragma once
/// The keyword reader's table, read only: every keyword read_keyword_file reads (its dispatch goes
/// through this same table, src/io/keyword_table.cpp), and the classes of keywords it knows and
/// does not read (src/io/keyword_unsupported.cpp). `blockcontact keywords` prints both.
#include <string>
#include <string_view>
#include <vector>

namespace slideline {

/// One keyword the reader reads.
struct KeywordInfo {
  std::string name;         ///< e.g. "*SECTION_SHELL"
  /// The options it may carry, as written after the name: "[_TITLE]",
  /// "[_SLIDING_ONLY][_LAGRANGE][_ID|_TITLE]" (bracketed: optional; '|': one of), or "".
  std::string options;
  std::string description;  ///< one line: what the card is
};

/// Every keyword the reader reads, in table order (controls and output, mesh and parts, sets,
/// boundaries and loads, initial conditions, curves, parameters, contacts).
const std::vector<KeywordInfo>& supported_keywords();

/// True when the reader reads `keyword` as written (upper case, options included, no format suffix).
bool reads_keyword(std::string_view keyword);

/// A class of keywords the reader knows and does not read: those starting with `prefix` (and not
/// in supported_keywords()).
struct UnsupportedKeywordClass {
  std::string_view prefix;
  bool physics;           ///< refused (an error, or dropped with --ignore-unsupported); else skipped with a warning
  std::string_view what;  ///< "material", "output request", ...
};

/// The classes in the order they are tried (the first matching prefix wins); a keyword matching
/// none is refused as physics.
const std::vector<UnsupportedKeywordClass>& unsupported_keyword_classes();

}  // namespace slideline
