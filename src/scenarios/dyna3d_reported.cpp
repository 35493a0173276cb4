#include "slideline/scenarios/dyna3d_reported.hpp"

#include <cctype>
#include <cstdlib>
#include <string>
#include <fstream>
#include <sstream>

#include "slideline/core/error.hpp"

namespace slideline::scenarios {

const JsonValue* JsonValue::find(const std::string& key) const {
  if (kind != Kind::object) return nullptr;
  const auto f = object.find(key);
  return f == object.end() ? nullptr : &f->second;
}

namespace {

class Parser {
 public:
  explicit Parser(const std::string& s) : s_(s) {}

  JsonValue document() {
    JsonValue v = value();
    skip();
    if (p_ != s_.size()) fail("trailing characters");
    return v;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError("JSON: " + what + " at offset " + std::to_string(p_));
  }
  void skip() {
    while (p_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[p_]))) ++p_;
  }
  bool eat(char c) {
    skip();
    if (p_ < s_.size() && s_[p_] == c) {
      ++p_;
      return true;
    }
    return false;
  }
  void expect(char c) {
    if (!eat(c)) fail(std::string("expected '") + c + "'");
  }
  bool word(const char* w) {
    const std::string ws(w);
    if (s_.compare(p_, ws.size(), ws) == 0) {
      p_ += ws.size();
      return true;
    }
    return false;
  }

  JsonValue value() {
    skip();
    if (p_ >= s_.size()) fail("unexpected end");
    JsonValue v;
    const char c = s_[p_];
    if (c == '{') {
      ++p_;
      v.kind = JsonValue::Kind::object;
      if (eat('}')) return v;
      do {
        skip();
        std::string key = string();
        expect(':');
        v.object[key] = value();
      } while (eat(','));
      expect('}');
    } else if (c == '[') {
      ++p_;
      v.kind = JsonValue::Kind::array;
      if (eat(']')) return v;
      do v.array.push_back(value());
      while (eat(','));
      expect(']');
    } else if (c == '"') {
      v.kind = JsonValue::Kind::string;
      v.string = string();
    } else if (word("null")) {
      v.kind = JsonValue::Kind::null;
    } else if (word("true")) {
      v.kind = JsonValue::Kind::boolean;
      v.boolean = true;
    } else if (word("false")) {
      v.kind = JsonValue::Kind::boolean;
    } else {
      const char* begin = s_.c_str() + p_;
      char* end = nullptr;
      v.number = std::strtod(begin, &end);
      if (end == begin) fail("expected a value");
      v.kind = JsonValue::Kind::number;
      p_ += static_cast<std::size_t>(end - begin);
    }
    return v;
  }

  std::string string() {
    if (p_ >= s_.size() || s_[p_] != '"') fail("expected a string");
    ++p_;
    std::string out;
    while (p_ < s_.size() && s_[p_] != '"') {
      char c = s_[p_++];
      if (c == '\\') {
        if (p_ >= s_.size()) break;
        const char e = s_[p_++];
        switch (e) {
          case 'n': c = '\n'; break;
          case 't': c = '\t'; break;
          case 'u': p_ += 4; c = '?'; break;  // not needed for the spec's ASCII file
          default: c = e;
        }
      }
      out += c;
    }
    if (p_ >= s_.size()) fail("unterminated string");
    ++p_;
    return out;
  }

  const std::string& s_;
  std::size_t p_ = 0;
};

}  // namespace

JsonValue parse_json(const std::string& text) { return Parser(text).document(); }

Dyna3dReported Dyna3dReported::load(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError("cannot read " + path);
  std::stringstream ss;
  ss << in.rdbuf();
  try {
    return Dyna3dReported(parse_json(ss.str()));
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
}

Dyna3dReported Dyna3dReported::builtin() {
  try {
    return Dyna3dReported(parse_json(dyna3d_reported_json()));
  } catch (const InputError& e) {
    throw InputError(std::string("built-in dyna3d_reported.json: ") + e.what());
  }
}

const JsonValue* Dyna3dReported::entry(const std::string& problem, const std::string& key,
                                       const std::string& pairing) const {
  const JsonValue* p = root_.find(problem);
  const JsonValue* v = p ? p->find(key) : nullptr;
  if (!v || v->kind != JsonValue::Kind::object) return v;
  const JsonValue* e = pairing.empty() ? nullptr : v->find(pairing);
  return e ? e : v->find("all");
}

std::optional<Real> Dyna3dReported::figure(const std::string& problem, const std::string& key,
                                           const std::string& pairing) const {
  const JsonValue* v = entry(problem, key, pairing);
  if (v && v->kind == JsonValue::Kind::number) return v->number;
  return std::nullopt;
}

std::string Dyna3dReported::text(const std::string& problem, const std::string& key,
                                 const std::string& pairing) const {
  const JsonValue* v = entry(problem, key, pairing);
  return v && v->kind == JsonValue::Kind::string ? v->string : std::string();
}

std::string Dyna3dReported::section(const std::string& problem, const std::string& key) const {
  const JsonValue* p = root_.find(problem);
  const JsonValue* s = p ? p->find("sections") : nullptr;
  const JsonValue* v = s ? s->find(key) : nullptr;
  return v && v->kind == JsonValue::Kind::string ? v->string : std::string();
}

}  // namespace slideline::scenarios
