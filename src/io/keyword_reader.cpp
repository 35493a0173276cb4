// Keyword deck reader: splitting a deck into keyword blocks, field parsing with located errors,
// and the entry points. The card handlers are in keyword_cards.cpp and keyword_contacts.cpp.
#include "slideline/io/keyword_reader.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "keyword_card.hpp"
#include "slideline/core/error.hpp"

namespace slideline {

std::string to_string(const Diagnostic& d) {
  if (d.file.empty()) return d.message;
  if (d.line <= 0) return d.file + ": " + d.message;
  return d.file + ":" + std::to_string(d.line) + ": " + d.message;
}

namespace keyword {

std::string_view trim(std::string_view s) {
  const auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

bool parse_real(std::string_view s, Real& out) {
  s = trim(s);
  if (s.empty() || s.size() > 64) return false;
  // Copy to a buffer: Fortran writes 'D' exponents and a leading '+', which from_chars rejects.
  char buf[72];
  std::size_t n = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    char c = s[i];
    if (i == 0 && c == '+') continue;
    if (c == 'd' || c == 'D') c = 'e';
    buf[n++] = c;
  }
  if (n == 0) return false;
  // from_chars also accepts "inf" and "nan": only digits, sign, point and exponent are numbers.
  for (std::size_t i = 0; i < n; ++i) {
    const char c = buf[i];
    if (!(std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+' ||
          c == 'e' || c == 'E'))
      return false;
  }
  double v = 0.0;
  const auto r = std::from_chars(buf, buf + n, v, std::chars_format::general);
  if (r.ec != std::errc() || r.ptr != buf + n || !std::isfinite(v)) return false;
  out = v;
  return true;
}

bool parse_integer(std::string_view s, Id& out) {
  s = trim(s);
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (s.empty()) return false;
  Id v = 0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (r.ec == std::errc() && r.ptr == s.data() + s.size()) {
    out = v;
    return true;
  }
  // Some writers put integers in real format ("3." or "3.0"): accept integral values.
  Real x = 0.0;
  if (!parse_real(s, x)) return false;
  if (x != std::floor(x) || std::abs(x) > 9.0e15) return false;
  out = static_cast<Id>(x);
  return true;
}

Card::Card(const Context& ctx, const Line& line, std::string_view keyword,
           std::span<const int> widths)
    : ctx_(ctx), line_(line), keyword_(keyword), widths_(widths) {
  if (line_.text.find(',') != std::string_view::npos) {
    free_ = true;
    std::string_view rest = line_.text;
    while (true) {
      const auto comma = rest.find(',');
      free_fields_.push_back(trim(rest.substr(0, comma)));
      if (comma == std::string_view::npos) break;
      rest.remove_prefix(comma + 1);
    }
  }
}

std::string_view Card::raw(int i) const {
  if (i < 0) return {};
  if (free_) return i < static_cast<int>(free_fields_.size()) ? free_fields_[i] : std::string_view{};
  if (i >= static_cast<int>(widths_.size())) return {};
  std::size_t start = 0;
  for (int k = 0; k < i; ++k) start += static_cast<std::size_t>(widths_[k]);
  if (start >= line_.text.size()) return {};
  return trim(line_.text.substr(start, static_cast<std::size_t>(widths_[i])));
}

bool Card::blank(int i) const { return raw(i).empty(); }

bool Card::all_blank() const { return trim(line_.text).empty(); }

void Card::fail(int i, const char* name, const char* expected) const {
  std::string where;
  if (free_) {
    where = "free-format field " + std::to_string(i + 1);
  } else {
    int start = 0;
    for (int k = 0; k < i; ++k) start += widths_[k];
    where = "columns " + std::to_string(start + 1) + "-" + std::to_string(start + widths_[i]);
  }
  throw InputError(ctx_.file + ":" + std::to_string(line_.number) + ": " + where + " (field " +
                   name + " of " + std::string(keyword_) + "): expected " + expected + ", got '" +
                   std::string(raw(i)) + "'");
}

void Card::get(int i, const char* name, Real& out) const {
  const auto s = raw(i);
  if (s.empty()) return;
  if (!parse_real(s, out)) fail(i, name, "a real number");
}

void Card::get(int i, const char* name, Id& out) const {
  const auto s = raw(i);
  if (s.empty()) return;
  if (!parse_integer(s, out)) fail(i, name, "an integer");
}

void Card::get(int i, const char* name, int& out) const {
  const auto s = raw(i);
  if (s.empty()) return;
  Id v = 0;
  if (!parse_integer(s, v) || v < std::numeric_limits<int>::min() ||
      v > std::numeric_limits<int>::max())
    fail(i, name, "an integer");
  out = static_cast<int>(v);
}

std::string heading(const Line& line) { return std::string(trim(line.text)); }

void read_id_heading(const Context& ctx, const Line& line, std::string_view keyword, Id& id,
                     std::string& title) {
  // Free format only when a comma falls inside the ID columns, so that a fixed-format heading may
  // itself hold commas.
  const auto comma = line.text.find(',');
  std::string_view id_text;
  std::string_view rest;
  int first = 1;
  int last = 10;
  if (comma != std::string_view::npos && comma < 10) {
    id_text = line.text.substr(0, comma);
    rest = line.text.substr(comma + 1);
    last = static_cast<int>(comma);
  } else {
    id_text = line.text.substr(0, std::min<std::size_t>(10, line.text.size()));
    rest = line.text.size() > 10 ? line.text.substr(10) : std::string_view{};
  }
  const auto t = trim(id_text);
  if (!t.empty() && !parse_integer(t, id))
    throw InputError(ctx.file + ":" + std::to_string(line.number) + ": columns " +
                     std::to_string(first) + "-" + std::to_string(last) + " (field ID of " +
                     std::string(keyword) + "): expected an integer, got '" + std::string(t) + "'");
  title = std::string(trim(rest));
}

void warn_extra_cards(const Context& ctx, Block& block) {
  int extra = 0;
  int first = 0;
  while (const Line* l = block.take()) {
    if (trim(l->text).empty()) continue;
    if (extra++ == 0) first = l->number;
  }
  if (extra > 0)
    ctx.warn(first, std::to_string(extra) + " extra card(s) of " + block.keyword +
                        " (line " + std::to_string(block.line) + ") ignored");
}

namespace {

std::string upper(std::string_view s) {
  std::string u(s);
  for (auto& c : u) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return u;
}

/// Splits the text into keyword blocks, dropping comments and everything after *END.
std::vector<Block> split_blocks(std::string_view text, const Context& ctx) {
  std::vector<Block> blocks;
  int number = 0;
  int orphan_line = 0;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    const auto nl = text.find('\n', pos);
    std::string_view line = text.substr(pos, nl == std::string_view::npos ? text.size() - pos : nl - pos);
    pos = nl == std::string_view::npos ? text.size() + 1 : nl + 1;
    ++number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (!line.empty() && line.front() == '$') continue;
    if (!line.empty() && line.front() == '*') {
      auto end = line.find_first_of(" \t");
      std::string kw = upper(line.substr(0, end));
      if (end != std::string_view::npos) {
        const auto rest = trim(line.substr(end));
        // Long format ("*NODE +" or "*KEYWORD LONG=Y") changes every column width.
        if (rest == "+" || (kw == "*KEYWORD" && upper(rest).find("LONG") != std::string::npos))
          throw InputError(ctx.file + ":" + std::to_string(number) + ": " + kw +
                           ": long-format (20-character) cards are not supported");
      }
      if (!kw.empty() && (kw.back() == '+' || kw.back() == '-')) {
        if (kw.back() == '+')
          throw InputError(ctx.file + ":" + std::to_string(number) + ": " + kw +
                           ": long-format (20-character) cards are not supported");
        kw.pop_back();
      }
      if (kw == "*END") break;
      blocks.push_back(Block{kw, number, {}, 0});
      continue;
    }
    if (blocks.empty()) {
      if (!trim(line).empty() && orphan_line == 0) orphan_line = number;
      continue;
    }
    blocks.back().cards.push_back(Line{line, number});
  }
  if (orphan_line != 0) ctx.warn(orphan_line, "data lines before the first keyword ignored");
  return blocks;
}

}  // namespace
}  // namespace keyword

model::Model read_keyword_string(std::string_view text, const std::string& name,
                                 std::vector<Diagnostic>* warnings) {
  keyword::Context ctx{name, warnings};
  model::Model model;
  auto blocks = keyword::split_blocks(text, ctx);
  for (auto& block : blocks) {
    if (!keyword::read_block(ctx, block, model))
      ctx.warn(block.line, "unknown keyword " + block.keyword + " skipped (" +
                               std::to_string(block.cards.size()) + " card(s))");
  }
  return model;
}

model::Model read_keyword_file(const std::string& path, std::vector<Diagnostic>* warnings) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the keyword file");
  std::ostringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  return read_keyword_string(text, path, warnings);
}

}  // namespace slideline
