#pragma once
/// DYNA3D's own figures on the 19 problems (src/scenarios/dyna3d_reported.json, compiled into the
/// library; each figure cites its report section), read with a minimal JSON parser (objects,
/// arrays, numbers, strings, true/false/null): the bar the verification table prints beside each
/// measurement.
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "slideline/core/types.hpp"

namespace slideline::scenarios {

/// A parsed JSON value.
struct JsonValue {
  enum class Kind : std::uint8_t { null, boolean, number, string, array, object };
  Kind kind = Kind::null;
  bool boolean = false;
  double number = 0.0;
  std::string string;
  std::vector<JsonValue> array;
  std::map<std::string, JsonValue> object;

  /// Member `key` of an object, or nullptr (also when this is not an object).
  const JsonValue* find(const std::string& key) const;
};

/// Parses JSON text. Throws InputError with the offset of the first malformed character.
JsonValue parse_json(const std::string& text);

class Dyna3dReported {
 public:
  Dyna3dReported() = default;  ///< no figures (every lookup gives nullopt)
  explicit Dyna3dReported(JsonValue root) : root_(std::move(root)) {}
  /// Reads and parses a file; throws Error when it cannot be read or parsed.
  static Dyna3dReported load(const std::string& path);
  /// The figures compiled into the library (src/scenarios/dyna3d_reported.json).
  static Dyna3dReported builtin();

  /// The figure `key` of `problem`: a number, or the entry `pairing` (else "all") of an object.
  std::optional<Real> figure(const std::string& problem, const std::string& key,
                             const std::string& pairing = "") const;
  /// The text `key` of `problem` (a string, or the entry `pairing` / "all" of an object); empty
  /// when absent. E.g. the report's wording of a figure ("interpenetration_wording").
  std::string text(const std::string& problem, const std::string& key, const std::string& pairing = "") const;
  /// The report section (and table or figure) the figure `key` of `problem` is taken from; empty
  /// when the file gives none.
  std::string section(const std::string& problem, const std::string& key) const;
  bool empty() const { return root_.kind != JsonValue::Kind::object; }

 private:
  const JsonValue* entry(const std::string& problem, const std::string& key, const std::string& pairing) const;
  JsonValue root_;
};

/// The text of src/scenarios/dyna3d_reported.json, compiled in at build time.
const char* dyna3d_reported_json();

}  // namespace slideline::scenarios
