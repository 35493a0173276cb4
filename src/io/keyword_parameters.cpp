// *PARAMETER and *PARAMETER_EXPRESSION: named values that other cards use as &name (or -&name) in
// place of a field, and the small expression language of *PARAMETER_EXPRESSION
// (docs/keywords.md, "Parameters").
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "keyword_card.hpp"
#include "slideline/core/error.hpp"

namespace slideline::keyword {
namespace {

/// Recursive-descent evaluator: + - * / ** ^, unary signs, parentheses, numbers (1.5, 2e3, 2d3),
/// parameter names (with or without &), pi, and functions of one or two arguments.
class Expression {
 public:
  Expression(std::string_view text, const DeckState& deck, const std::string& where)
      : s_(text), deck_(deck), where_(where) {}

  Real evaluate() {
    const Real v = sum();
    skip();
    if (p_ != s_.size()) fail("unexpected '" + std::string(s_.substr(p_, 1)) + "'");
    if (!std::isfinite(v)) fail("the value is not finite");
    return v;
  }

 private:
  [[noreturn]] void fail(const std::string& why) const {
    throw InputError(where_ + "expression '" + std::string(trim(s_)) + "': " + why + " (at column " +
                     std::to_string(p_ + 1) + ")");
  }
  void skip() {
    while (p_ < s_.size() && (s_[p_] == ' ' || s_[p_] == '\t')) ++p_;
  }
  bool eat(char c) {
    skip();
    if (p_ < s_.size() && s_[p_] == c) {
      ++p_;
      return true;
    }
    return false;
  }
  Real sum() {
    Real v = product();
    while (true) {
      if (eat('+')) v += product();
      else if (eat('-')) v -= product();
      else return v;
    }
  }
  Real product() {
    Real v = power();
    while (true) {
      skip();
      if (p_ + 1 < s_.size() && s_[p_] == '*' && s_[p_ + 1] == '*') return v;  // handled by power
      if (eat('*')) {
        v *= power();
      } else if (eat('/')) {
        const Real d = power();
        if (d == 0.0) fail("division by zero");
        v /= d;
      } else {
        return v;
      }
    }
  }
  /// Bounds the recursion: a pathological line ("((((..." or "----...") must not overflow the stack.
  struct Depth {
    explicit Depth(Expression& e) : e_(e) {
      if (++e_.depth_ > kMaxDepth) e_.fail("nested too deeply");
    }
    ~Depth() { --e_.depth_; }
    Expression& e_;
  };
  static constexpr int kMaxDepth = 200;

  Real power() {
    const Depth guard(*this);
    const Real base = unary();
    skip();
    if (p_ + 1 < s_.size() && s_[p_] == '*' && s_[p_ + 1] == '*') {
      p_ += 2;
      return std::pow(base, power());
    }
    if (eat('^')) return std::pow(base, power());
    return base;
  }
  Real unary() {
    const Depth guard(*this);
    if (eat('-')) return -unary();
    if (eat('+')) return unary();
    return primary();
  }
  Real primary() {
    skip();
    if (p_ >= s_.size()) fail("a value is missing");
    if (eat('(')) {
      const Real v = sum();
      if (!eat(')')) fail("')' expected");
      return v;
    }
    const char c = s_[p_];
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return number();
    if (c == '&' || std::isalpha(static_cast<unsigned char>(c))) return name();
    fail("unexpected '" + std::string(1, c) + "'");
  }
  Real number() {
    const std::size_t start = p_;
    while (p_ < s_.size() && (std::isdigit(static_cast<unsigned char>(s_[p_])) || s_[p_] == '.')) ++p_;
    if (p_ < s_.size() && std::strchr("eEdD", s_[p_]) != nullptr) {
      std::size_t q = p_ + 1;
      if (q < s_.size() && (s_[q] == '+' || s_[q] == '-')) ++q;
      if (q < s_.size() && std::isdigit(static_cast<unsigned char>(s_[q]))) {
        p_ = q;
        while (p_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[p_]))) ++p_;
      }
    }
    Real v = 0.0;
    if (!parse_real(s_.substr(start, p_ - start), v)) fail("bad number");
    return v;
  }
  Real name() {
    eat('&');
    const std::size_t start = p_;
    while (p_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[p_])) || s_[p_] == '_')) ++p_;
    const std::string id = upper(s_.substr(start, p_ - start));
    if (id.empty()) fail("a name is missing after '&'");
    if (eat('(')) {
      Real a[2] = {0.0, 0.0};
      int n = 0;
      do {
        if (n == 2) fail("too many arguments of " + id);
        a[n++] = sum();
      } while (eat(','));
      if (!eat(')')) fail("')' expected after the arguments of " + id);
      return call(id, a, n);
    }
    if (id == "PI") return 3.14159265358979323846;
    const auto f = deck_.parameters.find(id);
    if (f == deck_.parameters.end()) fail("parameter " + id + " is not defined");
    if (f->second.type == 'C') fail("parameter " + id + " is a character parameter");
    return f->second.value;
  }
  Real call(const std::string& f, const Real* a, int n) {
    const auto one = [&](Real (*g)(Real)) {
      if (n != 1) fail(f + " takes one argument");
      return g(a[0]);
    };
    const auto two = [&]() {
      if (n != 2) fail(f + " takes two arguments");
    };
    if (f == "ABS") return one([](Real x) { return std::abs(x); });
    if (f == "SQRT") {
      if (n == 1 && a[0] < 0.0) fail("sqrt of a negative number");
      return one([](Real x) { return std::sqrt(x); });
    }
    if (f == "EXP") return one([](Real x) { return std::exp(x); });
    if (f == "LOG" || f == "LN") {
      if (n == 1 && a[0] <= 0.0) fail("log of a non-positive number");
      return one([](Real x) { return std::log(x); });
    }
    if (f == "LOG10") {
      if (n == 1 && a[0] <= 0.0) fail("log10 of a non-positive number");
      return one([](Real x) { return std::log10(x); });
    }
    if (f == "SIN") return one([](Real x) { return std::sin(x); });
    if (f == "COS") return one([](Real x) { return std::cos(x); });
    if (f == "TAN") return one([](Real x) { return std::tan(x); });
    if (f == "ASIN") return one([](Real x) { return std::asin(x); });
    if (f == "ACOS") return one([](Real x) { return std::acos(x); });
    if (f == "ATAN") return one([](Real x) { return std::atan(x); });
    if (f == "INT" || f == "AINT") return one([](Real x) { return std::trunc(x); });
    if (f == "NINT") return one([](Real x) { return std::round(x); });
    if (f == "ATAN2") return two(), std::atan2(a[0], a[1]);
    if (f == "MIN") return two(), std::min(a[0], a[1]);
    if (f == "MAX") return two(), std::max(a[0], a[1]);
    if (f == "POW") return two(), std::pow(a[0], a[1]);
    if (f == "MOD") {
      two();
      if (a[1] == 0.0) fail("mod by zero");
      return std::fmod(a[0], a[1]);
    }
    fail("unknown function " + f);
  }

  std::string_view s_;
  std::size_t p_ = 0;
  int depth_ = 0;
  const DeckState& deck_;
  const std::string& where_;
};

/// "R name" -> type letter and upper-case name; throws on a bad type or name.
void parse_name(const Context& ctx, int line, std::string_view keyword, std::string_view field,
                char& type, std::string& name) {
  field = trim(field);
  const auto bad = [&](const std::string& why) {
    throw InputError(ctx.where(line) + "field PRMR of " + std::string(keyword) + ": " + why + ", got '" +
                     std::string(field) + "'");
  };
  if (field.empty()) bad("expected a type letter R, I or C and a name");
  type = static_cast<char>(std::toupper(static_cast<unsigned char>(field[0])));
  if (type != 'R' && type != 'I' && type != 'C') bad("the type letter must be R, I or C");
  name = upper(trim(field.substr(1)));
  if (name.empty() || !std::isalpha(static_cast<unsigned char>(name[0]))) bad("expected a name after the type letter");
  for (char c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') bad("a name holds letters, digits and '_'");
}

void define(const Context& ctx, int line, const std::string& name, Parameter p) {
  auto& params = ctx.deck->parameters;
  if (params.count(name)) ctx.warn(line, "parameter " + name + " redefined; the new value is used from here on");
  params[name] = std::move(p);
}

Parameter make_value(const Context& ctx, int line, std::string_view keyword, char type, const std::string& name,
                     Real v) {
  Parameter p;
  p.type = type;
  char buf[40];
  if (type == 'I') {
    const Real t = std::trunc(v);
    if (std::abs(t) > 9.0e15)
      throw InputError(ctx.where(line) + std::string(keyword) + ": integer parameter " + name + " out of range");
    p.value = t;
    std::snprintf(buf, sizeof buf, "%lld", static_cast<long long>(t));
  } else {
    p.value = v;
    std::snprintf(buf, sizeof buf, "%.17g", v);
  }
  p.text = buf;
  return p;
}

}  // namespace

void read_parameter_values(const Context& ctx, Block& b) {
  while (const Line* l = b.take()) {
    if (trim(l->text).empty()) continue;
    Card c(ctx, *l, b.keyword, kStandard);
    for (int k = 0; k < c.size(); k += 2) {
      if (c.blank(k)) {
        if (!c.blank(k + 1))
          throw InputError(ctx.where(l->number) + "*PARAMETER: a value without a name (field " +
                           std::to_string(k + 2) + ")");
        continue;
      }
      char type = 'R';
      std::string name;
      parse_name(ctx, l->number, b.keyword, c.raw(k), type, name);
      const std::string_view value = c.raw(k + 1);
      Parameter p;
      if (type == 'C') {
        p.type = 'C';
        p.text = std::string(value);
      } else {
        Real v = 0.0;
        if (!parse_real(value, v) || (type == 'I' && v != std::trunc(v)))
          throw InputError(ctx.where(l->number) + "*PARAMETER " + name + ": expected " +
                           (type == 'I' ? "an integer" : "a real number") + ", got '" + std::string(value) + "'");
        p = make_value(ctx, l->number, b.keyword, type, name, v);
      }
      define(ctx, l->number, name, std::move(p));
    }
  }
}

void read_parameter_expressions(const Context& ctx, Block& b) {
  while (const Line* l = b.take()) {
    const std::string_view text = l->text;
    if (trim(text).empty()) continue;
    const std::size_t width = l->format == Format::wide ? 20 : 10;
    const auto comma = text.find(',');
    std::string_view prmr, expr;
    if (comma != std::string_view::npos && comma < width) {
      prmr = text.substr(0, comma);
      expr = text.substr(comma + 1);
    } else {
      prmr = text.substr(0, std::min(width, text.size()));
      expr = text.size() > width ? text.substr(width) : std::string_view{};
    }
    char type = 'R';
    std::string name;
    parse_name(ctx, l->number, b.keyword, prmr, type, name);
    if (type == 'C')
      throw InputError(ctx.where(l->number) + b.keyword + ": character expressions are not supported (parameter " +
                       name + ")");
    if (trim(expr).empty()) throw InputError(ctx.where(l->number) + b.keyword + ": parameter " + name + " has no expression");
    const Real v = evaluate_expression(expr, *ctx.deck, ctx.where(l->number) + b.keyword + " " + name + ": ");
    define(ctx, l->number, name, make_value(ctx, l->number, b.keyword, type, name, v));
  }
}

Real evaluate_expression(std::string_view expr, const DeckState& deck, const std::string& where) {
  return Expression(expr, deck, where).evaluate();
}

}  // namespace slideline::keyword
