#pragma once
// Comparing two model::Model in the keyword tests: the structs' defaulted operator== decides
// (every field exactly; a card's location never differs, model/source.hpp), and the written decks
// say where two models differ.
#include <sstream>
#include <string>

#include "slideline/io/keyword_writer.hpp"
#include "slideline/model/model.hpp"

namespace slideline::test {

/// What two decks that say the same thing may still differ in: the spelling of a contact keyword
/// (_ID, _TITLE or neither give the same contact) and the files the deck was read from.
inline model::Model content_of(model::Model m) {
  for (auto& c : m.contacts) c.keyword.clear();
  m.files.clear();
  return m;
}

/// "" when the two models say the same (content_of(a) == content_of(b)); else the first line where
/// their written decks differ, or a note that they differ only in fields the writer does not write.
inline std::string model_difference(const model::Model& a, const model::Model& b) {
  const model::Model ca = content_of(a), cb = content_of(b);
  if (ca == cb) return "";
  std::istringstream ta(write_keyword_string(ca)), tb(write_keyword_string(cb));
  std::string la, lb;
  for (int line = 1;; ++line) {
    const bool more_a = static_cast<bool>(std::getline(ta, la));
    const bool more_b = static_cast<bool>(std::getline(tb, lb));
    if (!more_a && !more_b) break;
    if (more_a != more_b || la != lb)
      return "the models differ; written, at line " + std::to_string(line) + ":\n  " + (more_a ? la : "(end)") +
             "\n  " + (more_b ? lb : "(end)");
  }
  return "the models differ in a field the keyword writer does not write";
}

}  // namespace slideline::test
