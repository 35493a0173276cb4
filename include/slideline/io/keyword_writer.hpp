#pragma once
/// LS-DYNA keyword deck writer: the inverse of read_keyword_file. Cards are written in fixed
/// format when every value fits its column exactly, otherwise in free (comma-separated) format,
/// so that reading the written deck gives back the same model (reals are written in their
/// shortest exact decimal form).
#include <string>

#include "slideline/model/model.hpp"

namespace slideline {

/// The deck text of a model, from *KEYWORD to *END.
std::string write_keyword_string(const model::Model& model);

/// Writes the deck to `path`. Throws Error when the file cannot be written.
void write_keyword_file(const model::Model& model, const std::string& path);

}  // namespace slideline
