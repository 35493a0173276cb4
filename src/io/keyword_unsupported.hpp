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
  /// warns about each, or with `blockers` (and not `ignore`) moves them to model.unsupported and
  /// lists the lines it would throw in blockers->unimplemented.
  void finish(model::Model& model, std::vector<Diagnostic>* warnings, bool ignore, Blockers* blockers = nullptr);

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

}  // namespace slideline::keyword
