#pragma once
/// Questions about the cards a reader dropped (model::Model::unsupported, kept with
/// ReadOptions::ignore_unsupported), so that a message can name the real cause of a dangling id:
/// "part 1 uses *MAT_PIECEWISE_LINEAR_PLASTICITY (line 72), not supported".
#include <string>
#include <string_view>

#include "slideline/model/model.hpp"

namespace slideline::model {

/// The id namespace a keyword's first field defines ("material", "section", "node set", ...), or
/// "" when it defines none we track.
std::string_view defined_kind(std::string_view keyword);

/// The dropped card that defined id `id` of kind `kind` (see defined_kind), or nullptr.
const UnsupportedCard* find_unsupported(const Model& m, std::string_view kind, Id id);

/// "*MAT_X (line 72)", or "*MAT_X (other.k:72)" when the card is in another file than `from`.
std::string card_and_place(const UnsupportedCard& u, const std::string& from);

}  // namespace slideline::model
