#pragma once
// Internal to the keyword reader: deck lines grouped into keyword blocks, and field access on one
// card (fixed columns or free format) with located error messages. Not installed.
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "slideline/core/types.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/model/model.hpp"

namespace slideline::keyword {

struct Line {
  std::string_view text;
  int number = 0;  // 1-based line number in the file
};

/// One keyword and the data cards under it (comment lines removed, blank lines kept: a blank
/// card is a card of defaults).
struct Block {
  std::string keyword;  // upper-case, with the leading '*'
  int line = 0;
  std::vector<Line> cards;
  std::size_t next = 0;

  bool done() const { return next >= cards.size(); }
  /// The next card, or nullptr when the block is exhausted.
  const Line* take() { return done() ? nullptr : &cards[next++]; }
};

/// Reading state shared by the card handlers.
struct Context {
  std::string file;
  std::vector<Diagnostic>* warnings = nullptr;
  void warn(int line, std::string message) const {
    if (warnings) warnings->push_back({file, line, std::move(message)});
  }
  model::Source source(int line) const { return {file, line}; }
};

// Column layouts (field widths) of the card formats.
inline constexpr int kStandard[] = {10, 10, 10, 10, 10, 10, 10, 10};
inline constexpr int kNodeCard[] = {8, 16, 16, 16, 8, 8};
inline constexpr int kElementCard[] = {8, 8, 8, 8, 8, 8, 8, 8, 8, 8};
inline constexpr int kCurvePoint[] = {20, 20};

/// Field access on one card. Blank fields leave the target untouched (the model default).
class Card {
 public:
  Card(const Context& ctx, const Line& line, std::string_view keyword, std::span<const int> widths);

  /// Number of fields the layout or free-format card holds.
  int size() const { return static_cast<int>(free_ ? free_fields_.size() : widths_.size()); }
  bool blank(int i) const;
  /// The trimmed text of field i ("" when absent).
  std::string_view raw(int i) const;

  void get(int i, const char* name, Real& out) const;
  void get(int i, const char* name, int& out) const;
  void get(int i, const char* name, Id& out) const;
  /// True when every field is blank.
  bool all_blank() const;
  int line() const { return line_.number; }

 private:
  [[noreturn]] void fail(int i, const char* name, const char* expected) const;

  const Context& ctx_;
  Line line_;
  std::string_view keyword_;
  std::span<const int> widths_;
  bool free_ = false;
  std::vector<std::string_view> free_fields_;
};

/// Parses a real number (Fortran 'D' exponents accepted); false if not a finite number.
bool parse_real(std::string_view s, Real& out);
/// Parses an integer (an integral real such as "3." is accepted); false if not an integer.
bool parse_integer(std::string_view s, Id& out);

std::string_view trim(std::string_view s);

/// A heading card: the whole line, trimmed.
std::string heading(const Line& line);
/// An _ID card: ID in columns 1-10 and the heading after it (or "id, heading" in free format).
void read_id_heading(const Context& ctx, const Line& line, std::string_view keyword, Id& id,
                     std::string& title);

}  // namespace slideline::keyword

namespace slideline::keyword {

/// Reads one block into the model. Returns false when the keyword is not supported (the caller
/// warns). Throws InputError on a malformed card.
bool read_block(const Context& ctx, Block& block, model::Model& model);

/// The *CONTACT_... family (keyword_contacts.cpp). Returns false for an unsupported contact type.
bool read_contact(const Context& ctx, Block& block, model::Model& model);

/// Warns about non-blank cards left in a block whose reader took what it needs.
void warn_extra_cards(const Context& ctx, Block& block);

}  // namespace slideline::keyword
