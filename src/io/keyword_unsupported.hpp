#pragma once
// Internal to the keyword reader: what to do with a keyword no handler reads. The classification
// table (docs/keywords.md, "Unsupported cards") says whether it is an output or tuning card (one
// warning per keyword) or a card that carries physics (an error, or a dropped card listed in
// model::Model::unsupported with ReadOptions::ignore_unsupported). Not installed.
#include <string>
#include <string_view>
#include <vector>

#include "keyword_card.hpp"

namespace slideline::keyword {

enum class CardKind : std::uint8_t { output, physics };

struct Classification {
  CardKind kind;
  std::string_view what;  // "material", "output request", ...
};

/// The class of a keyword no handler reads (first matching prefix of the table; physics when none
/// matches: a card we do not know may carry physics).
Classification classify(std::string_view keyword);

/// The unsupported cards of one deck, gathered while reading.
class UnsupportedLog {
 public:
  /// Records a block no handler read (`cards`: its number of data lines, some maybe not kept).
  void add(const Context& ctx, Block& block, int cards);
  /// Emits one warning per output/tuning keyword; then throws NotImplementedError listing the
  /// physics cards (one line per keyword), or with `ignore` moves them to model.unsupported and
  /// warns about each.
  void finish(model::Model& model, std::vector<Diagnostic>* warnings, bool ignore);

 private:
  struct Skipped {
    std::string keyword;
    model::Source src;
    int count = 0;
    int cards = 0;
  };
  std::vector<Skipped> output_;
  std::vector<model::UnsupportedCard> physics_;
};

/// The id namespace a keyword's first field defines ("material", "section", "node set", ...), or
/// "" when it defines none we track.
std::string_view defined_kind(std::string_view keyword);

/// The unsupported card that defined id `id` of kind `kind` (see defined_kind), or nullptr.
const model::UnsupportedCard* find_unsupported(const model::Model& m, std::string_view kind, Id id);

/// "*MAT_X (line 72)" or "*MAT_X (other.k:72)" when the card is in another file than `from`.
std::string card_and_place(const model::UnsupportedCard& u, const std::string& from);

}  // namespace slideline::keyword
