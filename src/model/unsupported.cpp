// Questions about the dropped cards of a model (see model/unsupported.hpp).
#include "slideline/model/unsupported.hpp"

namespace slideline::model {

std::string_view defined_kind(std::string_view kw) {
  if (kw.starts_with("*MAT")) return "material";
  if (kw.starts_with("*SECTION_")) return "section";
  if (kw.starts_with("*EOS")) return "equation of state";
  if (kw.starts_with("*HOURGLASS")) return "hourglass";
  if (kw.starts_with("*SET_NODE")) return "node set";
  if (kw.starts_with("*SET_PART")) return "part set";
  if (kw.starts_with("*SET_SEGMENT")) return "segment set";
  if (kw.starts_with("*DEFINE_CURVE") || kw.starts_with("*DEFINE_TABLE")) return "curve";
  return "";
}

const UnsupportedCard* find_unsupported(const Model& m, std::string_view kind, Id id) {
  for (const auto& u : m.unsupported)
    if (u.id == id && defined_kind(u.keyword) == kind) return &u;
  return nullptr;
}

std::string card_and_place(const UnsupportedCard& u, const std::string& from) {
  if (u.src.file == from || u.src.file.empty()) return u.keyword + " (line " + std::to_string(u.src.line) + ")";
  return u.keyword + " (" + u.src.file + ":" + std::to_string(u.src.line) + ")";
}

}  // namespace slideline::model
