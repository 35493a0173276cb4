#pragma once
/// DYNA3D's own figures on the 19 problems (../shared/spec/dyna3d_reported.json), read with a
/// minimal JSON parser (objects, arrays, numbers, strings, true/false/null): the bar the
/// verification table prints beside each measurement.
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

  /// The figure `key` of `problem`: a number, or the entry `pairing` (else "all") of an object.
  std::optional<Real> figure(const std::string& problem, const std::string& key,
                             const std::string& pairing = "") const;
  bool empty() const { return root_.kind != JsonValue::Kind::object; }

 private:
  JsonValue root_;
};

/// The directory holding dyna3d_reported.json: `start` and its ancestors are searched for
/// `shared/spec/dyna3d_reported.json` (the repository lives next to `shared/`, possibly a level
/// deeper for a worktree). Empty when not found.
std::string find_spec_dir(const std::string& start);

}  // namespace slideline::scenarios
