#pragma once
// The rules the keyword reader applies to the fields it does not store (keyword_contact_fields.cpp,
// keyword_control_fields.cpp): each field at its manual default passes (blank and 0 mean the
// default); otherwise it is refused (NotImplementedError naming file, line, card and field) or, when
// it only tunes output, speed or the step, or acts on a feature this code lacks, warned about.
#include <cstdint>
#include <span>
#include <string_view>

#include "keyword_card.hpp"

namespace slideline::keyword::detail {

/// What happens to a field that is not at its default.
enum class Use : std::uint8_t {
  honoured,  ///< read into the model and acted on elsewhere: not checked here
  refuse,    ///< changes the physics and is not implemented: NotImplementedError
  output,    ///< only tunes output this code does not write: warning
  speed,     ///< only tunes speed (search cadence, sorting): warning
  inert,     ///< acts only on a feature this code refuses or lacks (says which): warning
  unused,    ///< a field the manual leaves unused
  step,      ///< only chooses the time step (the stable step is always respected): warning
};

struct Rule {
  const char* name;
  Real dflt;  ///< the manual's default (what 0 and blank mean)
  Use use;
  const char* what;
};

/// One optional card: its name in messages and its fields' rules.
struct OptionalCard {
  const char* name;
  std::span<const Rule> rules;
};

/// Applies `rules` (one per field, in column order) to card `l`.
void check_card(const Context& ctx, const Line& l, std::string_view keyword, std::string_view card,
                std::span<const Rule> rules);
/// Applies `cards` in order to the block's remaining cards; a card beyond them that is not blank
/// is refused.
void check_remaining(const Context& ctx, Block& b, std::span<const OptionalCard> cards);

}  // namespace slideline::keyword::detail
