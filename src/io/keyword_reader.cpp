// Keyword deck reader: field parsing with located errors and parameter substitution (Card), and
// the entry points, which stream a deck line by line into keyword blocks, follow *INCLUDEs and
// hand each block to its card handler through the keyword table (keyword_table.cpp) or to the
// unsupported-card log (keyword_unsupported.cpp).
#include "slideline/io/keyword_reader.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <streambuf>

#include "keyword_card.hpp"
#include "keyword_unsupported.hpp"
#include "slideline/core/error.hpp"

namespace slideline {

namespace keyword {

std::string_view trim(std::string_view s) {
  const auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

std::string upper(std::string_view s) {
  std::string u(s);
  for (auto& c : u) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return u;
}

bool parse_real(std::string_view s, Real& out) {
  s = trim(s);
  if (s.empty() || s.size() > 64) return false;
  // Copy to a buffer: Fortran writes 'D' exponents, a leading '+', and exponents without a letter
  // ("2.00000-3" = 2e-3, "1.5+2" = 150), which from_chars rejects.
  char buf[72];
  std::size_t n = 0;
  bool exponent = false;
  for (std::size_t i = 0; i < s.size(); ++i) {
    char c = s[i];
    if (i == 0 && c == '+') continue;
    if (c == 'd' || c == 'D' || c == 'e' || c == 'E') {
      c = 'e';
      exponent = true;
    } else if ((c == '+' || c == '-') && n > 0 && !exponent &&
               (std::isdigit(static_cast<unsigned char>(buf[n - 1])) || buf[n - 1] == '.')) {
      buf[n++] = 'e';
      exponent = true;
    }
    buf[n++] = c;
  }
  if (n == 0) return false;
  // from_chars also accepts "inf" and "nan": only digits, sign, point and exponent are numbers.
  for (std::size_t i = 0; i < n; ++i) {
    const char c = buf[i];
    if (!(std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+' || c == 'e'))
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

int Card::width(int k) const {
  const int w = widths_[static_cast<std::size_t>(k)];
  switch (line_.format) {
    case Format::wide: return 20;
    case Format::i10: return std::max(w, 10);
    default: return w;
  }
}

std::string_view Card::field_text(int i) const {
  if (i < 0) return {};
  if (free_) return i < static_cast<int>(free_fields_.size()) ? free_fields_[i] : std::string_view{};
  if (i >= static_cast<int>(widths_.size())) return {};
  std::size_t start = 0;
  for (int k = 0; k < i; ++k) start += static_cast<std::size_t>(width(k));
  if (start >= line_.text.size()) return {};
  return trim(line_.text.substr(start, static_cast<std::size_t>(width(i))));
}

std::string Card::place(int i) const {
  if (free_) return "free-format field " + std::to_string(i + 1);
  int start = 0;
  for (int k = 0; k < i; ++k) start += width(k);
  return "columns " + std::to_string(start + 1) + "-" + std::to_string(start + width(i));
}

std::string_view Card::raw(int i) const {
  const std::string_view s = field_text(i);
  const bool negate = s.size() > 1 && s[0] == '-' && s[1] == '&';
  if (s.empty() || (s[0] != '&' && !negate)) return s;
  const std::string name = upper(trim(s.substr(negate ? 2 : 1)));
  const Parameter* p = nullptr;
  if (ctx_.deck) {
    const auto f = ctx_.deck->parameters.find(name);
    if (f != ctx_.deck->parameters.end()) p = &f->second;
  }
  if (!p)
    throw InputError(ctx_.where(line_.number) + place(i) + " of " + std::string(keyword_) +
                     ": parameter &" + name +
                     " is not defined (a *PARAMETER must come before the cards that use it)");
  auto& text = substituted_.emplace_back();
  if (!negate) {
    text = p->text;
  } else if (p->type == 'C') {
    text = "-" + p->text;
  } else {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", -p->value);
    text = buf;
  }
  return text;
}

bool Card::blank(int i) const { return raw(i).empty(); }

bool Card::all_blank() const { return trim(line_.text).empty(); }

void Card::fail(int i, const char* name, const char* expected) const {
  const std::string_view written = field_text(i);
  std::string got = "'" + std::string(raw(i)) + "'";
  if (raw(i) != written) got += " (from " + std::string(written) + ")";
  throw InputError(ctx_.where(line_.number) + place(i) + " (field " + name + " of " +
                   std::string(keyword_) + "): expected " + expected + ", got " + got);
}

// A number written wider than its fixed-format field runs into the next one, which LS-DYNA (and a
// plain column reader) would silently read as two numbers: "0.123456789" in a 10-column field is
// 0.12345678 and, in the next field, 9. Refused when the field's last column and the next field's
// first column are both written (the next one with a digit, sign or point) and the next field's text
// stops before its own last column (a number of its own fills its field right-justified, or is
// separated by a blank).
void Card::check_field_boundaries(int i, const char* name) const {
  if (free_ || i < 0 || i >= static_cast<int>(widths_.size())) return;
  const std::string_view text = line_.text;
  const auto spills = [&](int k) {  // field k runs into field k + 1
    if (k < 0 || k + 1 >= static_cast<int>(widths_.size())) return false;
    std::size_t start = 0;
    for (int j = 0; j <= k; ++j) start += static_cast<std::size_t>(width(j));
    const std::size_t next_width = static_cast<std::size_t>(width(k + 1));
    if (start == 0 || start >= text.size()) return false;
    const auto written = [](char c) { return c != ' ' && c != '\t'; };
    const char first = text[start];  // a number starts with a digit, a sign or a point; text fields (SOLVER "MECH") do not
    const bool numeric = (first >= '0' && first <= '9') || first == '.' || first == '+' || first == '-';
    if (!written(text[start - 1]) || !numeric) return false;
    const std::string_view next = text.substr(start, next_width);
    return next.size() < next_width || !written(next.back());
  };
  const auto refuse = [&](int k) {
    std::size_t start = 0;
    for (int j = 0; j < k; ++j) start += static_cast<std::size_t>(width(j));
    std::size_t end = start + static_cast<std::size_t>(width(k));
    while (end < text.size() && text[end] != ' ' && text[end] != '\t') ++end;
    throw InputError(ctx_.where(line_.number) + place(k) + " (" + (k == i ? "field " + std::string(name)
                                                                          : "the field before " + std::string(name)) +
                     " of " + std::string(keyword_) + "): '" + std::string(text.substr(start, end - start)) +
                     "' is written across the field's end into the next field's columns; fixed-format fields are " +
                     std::to_string(width(k)) +
                     " columns wide: shorten the number, separate the fields with commas (free format) or use the "
                     "long format");
  };
  if (spills(i - 1)) refuse(i - 1);
  if (spills(i)) refuse(i);
}

void Card::get(int i, const char* name, Real& out) const {
  const auto s = raw(i);
  if (s.empty()) return;
  check_field_boundaries(i, name);
  if (!parse_real(s, out)) fail(i, name, "a real number");
}

void Card::get(int i, const char* name, Id& out) const {
  const auto s = raw(i);
  if (s.empty()) return;
  check_field_boundaries(i, name);
  if (!parse_integer(s, out)) fail(i, name, "an integer");
}

void Card::get(int i, const char* name, int& out) const {
  const auto s = raw(i);
  if (s.empty()) return;
  check_field_boundaries(i, name);
  Id v = 0;
  if (!parse_integer(s, v) || v < std::numeric_limits<int>::min() ||
      v > std::numeric_limits<int>::max())
    fail(i, name, "an integer");
  out = static_cast<int>(v);
}

void Card::get_or_default(int i, const char* name, Real& out) const {
  Real v = 0.0;
  get(i, name, v);
  if (v != 0.0) out = v;
}

void Card::get_or_default(int i, const char* name, int& out) const {
  int v = 0;
  get(i, name, v);
  if (v != 0) out = v;
}

std::string heading(const Line& line) { return std::string(trim(line.text)); }

void read_id_heading(const Context& ctx, const Line& line, std::string_view keyword, Id& id,
                     std::string& title) {
  // Free format only when a comma falls inside the ID columns, so that a fixed-format heading may
  // itself hold commas.
  const std::size_t id_width = line.format == Format::wide ? 20 : 10;
  const auto comma = line.text.find(',');
  std::string_view id_text;
  std::string_view rest;
  int last = static_cast<int>(id_width);
  if (comma != std::string_view::npos && comma < id_width) {
    id_text = line.text.substr(0, comma);
    rest = line.text.substr(comma + 1);
    last = static_cast<int>(comma);
  } else {
    id_text = line.text.substr(0, std::min<std::size_t>(id_width, line.text.size()));
    rest = line.text.size() > id_width ? line.text.substr(id_width) : std::string_view{};
  }
  const auto t = trim(id_text);
  if (!t.empty() && !parse_integer(t, id))
    throw InputError(ctx.where(line.number) + "columns 1-" + std::to_string(last) + " (field ID of " +
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

/// A std::streambuf over text held in memory, so that strings and files stream the same way.
class ViewBuf : public std::streambuf {
 public:
  explicit ViewBuf(std::string_view s) {
    char* p = const_cast<char*>(s.data());  // read only: the get area is never written
    setg(p, p, p + s.size());
  }
};

/// Lines of a stream; "\n", "\r\n" and a lone "\r" each end a line.
class LineSource {
 public:
  explicit LineSource(std::streambuf& buf) : buf_(buf) {}
  bool next(std::string& line) {
    line.clear();
    int c = buf_.sbumpc();
    if (c == std::char_traits<char>::eof()) return false;
    while (c != std::char_traits<char>::eof() && c != '\n' && c != '\r') {
      line.push_back(static_cast<char>(c));
      c = buf_.sbumpc();
    }
    if (c == '\r' && buf_.sgetc() == '\n') buf_.sbumpc();
    return true;
  }

 private:
  std::streambuf& buf_;
};

// Blank cards in a row kept in a block: no keyword has more positional cards than this, so longer
// runs of blank lines carry nothing and are not stored (a file of empty lines stays small).
constexpr int kMaxBlankRun = 16;
// Cards kept of a block that no handler reads: enough to find its id; the rest are only counted.
constexpr int kKeptUnsupported = 3;

/// The block being filled while streaming: line texts in one buffer, views made when it is done.
struct PendingBlock {
  std::string keyword;
  int line = 0;
  Format format = Format::standard;
  bool keep_all = true;
  int cards = 0;  // non-comment lines seen
  int blank_run = 0;
  std::string storage;
  struct Ref {
    std::size_t offset, size;
    int number;
  };
  std::vector<Ref> refs;

  void add(std::string_view text, int number) {
    ++cards;
    if (trim(text).empty()) {
      if (++blank_run > kMaxBlankRun) return;
    } else {
      blank_run = 0;
    }
    if (!keep_all && static_cast<int>(refs.size()) >= kKeptUnsupported) return;
    refs.push_back({storage.size(), text.size(), number});
    storage.append(text);
  }

  Block finish() const {
    Block b{keyword, line, {}, 0};
    b.cards.reserve(refs.size());
    for (const auto& r : refs)
      b.cards.push_back(Line{std::string_view(storage).substr(r.offset, r.size), r.number, format});
    return b;
  }
};

constexpr int kMaxIncludeDepth = 32;

/// Reads one file (or string) of a deck into the model, recursing into its *INCLUDEs.
class DeckReader {
 public:
  DeckReader(model::Model& model, DeckState& deck, UnsupportedLog& log, std::vector<Diagnostic>* warnings,
             Blockers* blockers)
      : model_(model), deck_(deck), log_(log), warnings_(warnings), blockers_(blockers) {}

  /// Returns the number of keywords read.
  int read(std::streambuf& buf, const std::string& name, Format format, int depth) {
    Context ctx{name, warnings_, &deck_};
    ctx.file_index = static_cast<int>(model_.files.size());
    model_.files.push_back(name);
    LineSource src(buf);
    std::string text;
    int number = 0;
    int orphan_line = 0;
    int keywords = 0;
    PendingBlock pending;
    bool open = false;
    while (src.next(text)) {
      ++number;
      if (!text.empty() && text.front() == '$') continue;
      if (!text.empty() && text.front() == '*') {
        if (open) process(ctx, pending, depth);
        open = false;
        std::string kw;
        Format block_format = format;
        if (!parse_keyword_line(ctx, text, number, kw, format, block_format)) continue;
        ++keywords;
        if (kw == "*END") break;
        pending = PendingBlock{};
        pending.keyword = std::move(kw);
        pending.line = number;
        pending.format = block_format;
        pending.keep_all = pending.keyword == "*INCLUDE" || is_supported(pending.keyword);
        open = true;
        continue;
      }
      if (!open) {
        if (!trim(text).empty() && orphan_line == 0) orphan_line = number;
        continue;
      }
      pending.add(text, number);
    }
    if (open) process(ctx, pending, depth);
    if (orphan_line != 0) {
      if (keywords == 0)
        throw InputError(ctx.where(orphan_line) +
                         "no keyword cards: this is not an LS-DYNA keyword deck (its cards start "
                         "with '*', e.g. *KEYWORD, *NODE)");
      ctx.warn(orphan_line, "data lines before the first keyword ignored");
    }
    return keywords;
  }

 private:
  /// Splits a keyword line into the keyword and its format; handles *KEYWORD's format options.
  /// Returns false for a line that is only '*'.
  static bool parse_keyword_line(const Context& ctx, std::string_view line, int number, std::string& kw,
                                 Format& file_format, Format& block_format) {
    const auto end = line.find_first_of(" \t");
    kw = upper(line.substr(0, end));
    const std::string rest = end == std::string_view::npos ? std::string() : upper(trim(line.substr(end)));
    if (kw.size() <= 1) {
      ctx.warn(number, "a line holding only '*' ignored");
      return false;
    }
    // Keywords are printable ASCII: anything else means binary data or a corrupted file.
    const auto printable = [](char c) { return c > ' ' && c < 127; };
    if (!std::all_of(kw.begin(), kw.end(), printable)) {
      std::string shown;
      for (char c : kw.substr(0, 24)) {
        if (printable(c)) {
          shown += c;
        } else {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\x%02x", static_cast<unsigned char>(c));
          shown += buf;
        }
      }
      throw InputError(ctx.where(number) + "'" + shown + (kw.size() > 24 ? "...'" : "'") +
                       " is not a keyword (non-text bytes): the file is not a keyword deck, or it is "
                       "corrupted");
    }
    if (kw == "*KEYWORD" || kw == "*KEYWORD_ID") {
      // "*KEYWORD [memory] LONG=Y I10=Y": the format of the rest of this file.
      if (rest.find("LONG=Y") != std::string::npos) file_format = Format::wide;
      else if (rest.find("I10=Y") != std::string::npos) file_format = Format::i10;
      else if (rest.find("LONG=") != std::string::npos || rest.find("I10=") != std::string::npos)
        file_format = Format::standard;
      block_format = file_format;
      return true;
    }
    block_format = file_format;
    // Per-keyword format: a suffix '+' long, '%' I10, '-' standard ("*NODE+" or "*NODE +").
    char suffix = kw.back();
    if (suffix == '+' || suffix == '-' || suffix == '%') {
      kw.pop_back();
    } else if (rest == "+" || rest == "-" || rest == "%") {
      suffix = rest[0];
    } else {
      suffix = 0;
    }
    if (suffix == '+') block_format = Format::wide;
    if (suffix == '%') block_format = Format::i10;
    if (suffix == '-') block_format = Format::standard;
    return true;
  }

  void process(const Context& ctx, const PendingBlock& pending, int depth) {
    Block block = pending.finish();
    if (block.keyword == "*INCLUDE") {
      include(ctx, block, depth);
      return;
    }
    bool read = false;
    try {
      read = read_block(ctx, block, model_);
    } catch (const NotImplementedError& e) {
      if (!blockers_) throw;
      blockers_->unimplemented.push_back({std::string(), 0, e.what()});
      return;
    } catch (const InputError& e) {
      if (!blockers_) throw;
      blockers_->input.push_back({std::string(), 0, e.what()});
      return;
    }
    if (!read) log_.add(ctx, block, pending.cards);
  }

  void include(const Context& ctx, Block& block, int depth) {
    namespace fs = std::filesystem;
    while (const Line* l = block.take()) {
      const std::string name(trim(l->text));
      if (name.empty()) continue;
      fs::path path(name);
      if (path.is_relative()) path = fs::path(ctx.file).parent_path() / path;
      std::error_code ec;
      const fs::path canonical = fs::weakly_canonical(path, ec);
      const std::string key = ec ? path.lexically_normal().string() : canonical.string();
      if (std::find(stack_.begin(), stack_.end(), key) != stack_.end())
        throw InputError(ctx.where(l->number) + "*INCLUDE of '" + name + "' makes a cycle (" + key +
                         " is already being read)");
      if (depth + 1 > kMaxIncludeDepth)
        throw InputError(ctx.where(l->number) + "*INCLUDE nested more than " +
                         std::to_string(kMaxIncludeDepth) + " deep");
      if (fs::is_directory(path, ec))
        throw InputError(ctx.where(l->number) + "*INCLUDE: '" + name + "' is a directory");
      std::ifstream in(path, std::ios::binary);
      if (!in)
        throw InputError(ctx.where(l->number) + "*INCLUDE: cannot open '" + name + "' (looked for " +
                         path.string() + ")");
      stack_.push_back(key);
      read(*in.rdbuf(), path.string(), Format::standard, depth + 1);
      stack_.pop_back();
    }
  }

 public:
  /// Marks the top-level file as being read, so that an include of it is a cycle.
  void enter(std::string canonical_path) { stack_.push_back(std::move(canonical_path)); }

 private:
  std::vector<std::string> stack_;  // canonical paths of the files being read, for cycles
  model::Model& model_;
  DeckState& deck_;
  UnsupportedLog& log_;
  std::vector<Diagnostic>* warnings_;
  Blockers* blockers_;
};

model::Model read_deck(std::streambuf& buf, const std::string& name, std::vector<Diagnostic>* warnings,
                       const ReadOptions& options) {
  model::Model model;
  DeckState deck;
  UnsupportedLog log;
  DeckReader reader(model, deck, log, warnings, options.blockers);
  std::error_code ec;
  const auto canonical = std::filesystem::weakly_canonical(name, ec);
  reader.enter(ec ? name : canonical.string());
  const int keywords = reader.read(buf, name, Format::standard, 0);
  if (keywords == 0)
    throw InputError(name +
                     ": no keyword cards: this is not an LS-DYNA keyword deck (its cards start with "
                     "'*', e.g. *KEYWORD, *NODE)");
  log.finish(model, warnings, options.ignore_unsupported, options.blockers);
  if (!options.blockers) {
    resolve_node_sets(deck, model);
    return model;
  }
  try {
    resolve_node_sets(deck, model);
  } catch (const Error& e) {
    options.blockers->input.push_back({std::string(), 0, e.what()});
  }
  return model;
}

}  // namespace
}  // namespace keyword

model::Model read_keyword_string(std::string_view text, const std::string& name,
                                 std::vector<Diagnostic>* warnings, const ReadOptions& options) {
  keyword::ViewBuf buf(text);
  return keyword::read_deck(buf, name, warnings, options);
}

model::Model read_keyword_file(const std::string& path, std::vector<Diagnostic>* warnings,
                               const ReadOptions& options) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(path + ": is a directory, not a keyword file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the keyword file");
  return keyword::read_deck(*in.rdbuf(), path, warnings, options);
}

}  // namespace slideline
