#pragma once
/// LS-DYNA keyword deck reader: fills a model::Model card by card (see docs/keywords.md for every
/// supported card, field, default and the DYNA3D contact type each contact card maps to).
///
/// Input rules: fixed 10-character fields, 8 per card (*NODE: id 8, coordinates 16, tc/rc 8;
/// *ELEMENT_*: 8-character fields); a card holding a comma is free format; `$` starts a comment
/// line; a blank field keeps the model.hpp default (LS-DYNA's). An unknown keyword is skipped with
/// a warning naming it and its line; a malformed field throws InputError naming the file, line,
/// columns, field and card. The reader never crashes: every failure is an slideline::Error.
#include <string>
#include <string_view>
#include <vector>

#include "slideline/model/model.hpp"

namespace slideline {

/// A located message: a warning of the reader or a problem found by check_references.
/// line = 0 when the item has no card line (e.g. elements, which carry no model::Source).
struct Diagnostic {
  std::string file;
  int line = 0;
  std::string message;
};

/// "file:line: message" (or "message" when file is empty).
std::string to_string(const Diagnostic& d);

/// Reads a keyword deck from a file. Warnings (unknown keywords, ignored cards) are appended to
/// `warnings` when given. Throws InputError when the file cannot be opened or a card is malformed.
/// References between ids are not checked here: call check_references() on the result.
model::Model read_keyword_file(const std::string& path, std::vector<Diagnostic>* warnings = nullptr);

/// Reads a keyword deck held in memory; `name` stands in for the file name in messages.
model::Model read_keyword_string(std::string_view text, const std::string& name,
                                 std::vector<Diagnostic>* warnings = nullptr);

/// Every dangling or duplicate id in a model: elements referring to undefined nodes or parts,
/// parts to undefined sections, materials or hourglass cards, sets to undefined nodes or parts,
/// boundary conditions, loads and contacts to undefined sets, parts or curves. Empty when clean.
std::vector<Diagnostic> check_references(const model::Model& model);

}  // namespace slideline
