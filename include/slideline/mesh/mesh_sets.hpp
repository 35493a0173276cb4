#pragma once
/// The deck's node, part and segment sets, resolved to internal node indices, kept in the runtime
/// so that contact interfaces (and anything else built after the mesh) can look them up by the
/// deck's set id. Filled by build_setup; set ids are the deck's (each kind of set has its own
/// id space, as in LS-DYNA).
#include <array>
#include <map>
#include <string>
#include <vector>

#include "slideline/core/error.hpp"
#include "slideline/core/types.hpp"

namespace slideline {

/// 4 internal node indices of a segment, in the deck's order (n3 == n4 for a triangle).
using SegmentNodes = std::array<Index, 4>;

struct MeshSets {
  std::map<Id, std::vector<Index>> node_sets;           ///< set id -> sorted unique node indices
  std::map<Id, std::vector<Id>> part_sets;              ///< set id -> part ids, deck order
  std::map<Id, std::vector<SegmentNodes>> segment_sets; ///< set id -> segments, deck order
  std::map<Id, std::vector<Index>> part_nodes;          ///< part id -> sorted unique node indices
  std::map<Id, std::string> node_set_titles, part_set_titles, segment_set_titles;  ///< "" if none

  /// The nodes of node set `sid`. Throws InputError "<context> refers to node set <sid>, which
  /// the deck does not define" when it is missing; `context` names the card and field, e.g.
  /// "deck.k:12: SSID".
  const std::vector<Index>& node_set(Id sid, const std::string& context) const {
    return find(node_sets, sid, "node set", context);
  }
  /// The part ids of part set `sid`; throws InputError like node_set.
  const std::vector<Id>& part_set(Id sid, const std::string& context) const {
    return find(part_sets, sid, "part set", context);
  }
  /// The segments of segment set `sid`; throws InputError like node_set.
  const std::vector<SegmentNodes>& segment_set(Id sid, const std::string& context) const {
    return find(segment_sets, sid, "segment set", context);
  }
  /// The nodes of part `pid`; throws InputError when the part has no elements.
  const std::vector<Index>& nodes_of_part(Id pid, const std::string& context) const {
    const auto f = part_nodes.find(pid);
    if (f == part_nodes.end())
      throw InputError(context + " refers to part " + std::to_string(pid) +
                       ", which has no elements in the deck");
    return f->second;
  }

 private:
  template <class T>
  static const T& find(const std::map<Id, T>& sets, Id sid, const char* what,
                       const std::string& context) {
    const auto f = sets.find(sid);
    if (f == sets.end())
      throw InputError(context + " refers to " + what + " " + std::to_string(sid) +
                       ", which the deck does not define");
    return f->second;
  }
};

}  // namespace slideline
