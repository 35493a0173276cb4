#pragma once
// Internal: the same problem found on many items (elements, mostly) reported as one line with a
// count and the first few items, instead of one line each (a tetrahedral mesh gave thousands).
// Used by check_references and validate_model (the validation layer). Not installed.
#include <map>
#include <string>
#include <vector>

#include "slideline/core/diagnostics.hpp"
#include "slideline/model/model.hpp"

namespace slideline {

class IssueGroups {
 public:
  /// One occurrence: `key` names the problem ("*ELEMENT_SOLID refers to an undefined node"),
  /// `single` is the message when it is alone, `item` labels the occurrence ("7" or "7 -> node 3")
  /// and `unit` names what is counted ("elements").
  void add(const std::string& key, std::string single, std::string item, const model::Source& src,
           const char* unit = "elements") {
    auto [it, fresh] = groups_.try_emplace(key);
    if (fresh) {
      order_.push_back(key);
      units_[key] = unit;
    }
    it->second.push_back({std::move(single), std::move(item), src});
  }

  bool empty() const { return order_.empty(); }

  /// Groups of up to `individual` occurrences give one Diagnostic each; larger ones one line.
  void append_to(std::vector<Diagnostic>& out, std::size_t individual = 3, std::size_t shown = 3) const {
    for (const auto& key : order_) {
      const auto& g = groups_.at(key);
      if (g.size() <= individual) {
        for (const auto& o : g) out.push_back({o.src.file, o.src.line, o.single});
        continue;
      }
      std::string msg = key + ": " + std::to_string(g.size()) + " " + units_.at(key) + " (first: ";
      for (std::size_t i = 0; i < shown && i < g.size(); ++i) msg += (i ? ", " : "") + g[i].item;
      msg += g.size() > shown ? ", ...)" : ")";
      out.push_back({g.front().src.file, g.front().src.line, std::move(msg)});
    }
  }

 private:
  struct Occurrence {
    std::string single, item;
    model::Source src;
  };
  std::vector<std::string> order_;
  std::map<std::string, std::vector<Occurrence>> groups_;
  std::map<std::string, std::string> units_;
};

/// "<subject> nodes (*NODE): nothing to run" and the same for elements, located at the deck's main
/// file, when the model has none (`subject`: "the deck defines no", "the model has no").
inline void add_empty_model_problems(const model::Model& m, const std::string& subject, std::vector<Diagnostic>& out) {
  const std::string file = m.files.empty() ? std::string() : m.files.front();
  if (m.nodes.empty()) out.push_back({file, 0, subject + " nodes (*NODE): nothing to run"});
  if (m.solids.empty() && m.shells.empty())
    out.push_back({file, 0, subject + " elements (*ELEMENT_SOLID, *ELEMENT_SHELL): nothing to run"});
}

}  // namespace slideline
