#pragma once
/// Where a card of a deck came from, for messages. Provenance, not content: two locations always
/// compare equal, so that the defaulted operator== of every model struct compares what a card
/// says, and a deck read back from its written copy (another file, other lines) equals the model
/// it was written from. Compare `.file` and `.line` themselves to test a location.
#include <string>

namespace slideline::model {

/// A card's file and line. line = 0 when built programmatically.
struct Source {
  std::string file;
  int line = 0;
  friend bool operator==(const Source&, const Source&) { return true; }
};

/// The compact form for cards that come by the million (elements, *INITIAL_VELOCITY_NODE): the
/// line in Model::files[file] (line 0 = generated); model::element_source turns it into a Source.
struct CardLine {
  int line = 0;
  int file = 0;
  friend bool operator==(const CardLine&, const CardLine&) { return true; }
};

}  // namespace slideline::model
