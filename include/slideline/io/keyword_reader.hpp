#pragma once
/// LS-DYNA keyword deck reader: fills a model::Model card by card (see docs/keywords.md for every
/// supported card, field, default and the DYNA3D contact type each contact card maps to).
///
/// Input rules: fixed 10-character fields, 8 per card (*NODE: id 8, coordinates 16, tc/rc 8;
/// *ELEMENT_*: 8-character fields); a card holding a comma is free format; `$` starts a comment
/// line; a blank field keeps the model.hpp default (LS-DYNA's). Long (`*KEYWORD LONG=Y`, `*NODE +`)
/// and I10 formats, `*INCLUDE`, `*PARAMETER` / `*PARAMETER_EXPRESSION` (&name fields) are read.
///
/// Cards the reader does not read are classified (docs/keywords.md, "Unsupported cards"): output
/// and tuning cards are skipped with one warning per keyword; a card that carries physics
/// (material, section, element kind, load, boundary or initial condition, constraint, rigid wall,
/// contact type, implicit control, or any keyword not in the tables) is an error naming the card
/// and its line, unless ReadOptions::ignore_unsupported drops it (then it is listed in
/// Model::unsupported and in the warnings). A malformed field throws InputError naming the file,
/// line, columns, field and card. The reader never crashes: every failure is an slideline::Error.
#include <string>
#include <string_view>
#include <vector>

#include "slideline/core/blockers.hpp"
#include "slideline/core/diagnostics.hpp"
#include "slideline/model/model.hpp"

namespace slideline {

struct ReadOptions {
  /// Drop unsupported physics cards (listing each in Model::unsupported and in the warnings)
  /// instead of throwing NotImplementedError.
  bool ignore_unsupported = false;
  /// When given, the reader goes on past what stops a deck and lists it here instead of throwing:
  /// a card that is malformed or refused (InputError, NotImplementedError) is skipped whole, with
  /// the rest of its keyword block, and reading goes on at the next keyword; the unsupported
  /// physics cards (unless ignore_unsupported) are listed one line per keyword and dropped into
  /// Model::unsupported. A model read with blockers is for reporting (`blockcontact check`), not
  /// for running. Files that cannot be opened and non-text input still throw.
  Blockers* blockers = nullptr;
};

/// Reads a keyword deck from a file (and the files it *INCLUDEs, relative to the including file).
/// Warnings (ignored output cards, fields read but not honoured) are appended to `warnings` when
/// given, as they are found, so a caller can print them when an error follows. Throws InputError
/// when a file cannot be opened or a card is malformed, NotImplementedError when the deck holds
/// unsupported physics cards (all of them listed, one line per keyword). References between ids
/// are not checked here: call check_references() (solver/validate_model.hpp) on the result.
model::Model read_keyword_file(const std::string& path, std::vector<Diagnostic>* warnings = nullptr,
                               const ReadOptions& options = {});

/// Reads a keyword deck held in memory; `name` stands in for the file name in messages (and
/// *INCLUDE paths are relative to its directory).
model::Model read_keyword_string(std::string_view text, const std::string& name,
                                 std::vector<Diagnostic>* warnings = nullptr,
                                 const ReadOptions& options = {});

/// One line per dropped card kind of Model::unsupported: "file:line: *KEYWORD (N cards, ids ...)
/// dropped". For a run log.
std::vector<Diagnostic> describe_dropped(const model::Model& model);

}  // namespace slideline
