// validate_model, the initial velocities: the fields of *INITIAL_VELOCITY and
// *INITIAL_VELOCITY_GENERATION that this code does not run, or that are out of range. Each message
// is the one the builder (initial_velocity.cpp) gave when it found the problem itself, to the
// letter; the builder keeps the id lookups (sets, boxes, nodes) and the checks that need the
// velocities resolved per node (two cards on one node, rigid parts).
#include <cmath>
#include <string>

#include "validate_problems.hpp"

namespace slideline::validation {
namespace {

/// "deck.k:12: *INITIAL_VELOCITY" for messages.
template <class Card>
std::string place(const model::Model& m, const Card& c, const char* keyword) {
  return describe(model::element_source(m, c)) + ": " + keyword;
}

void check_set_cards(const model::Model& m, Problems& p) {
  for (const auto& iv : m.initial_velocities) {
    const std::string where = place(m, iv, "*INITIAL_VELOCITY");
    if (iv.icid != 0)
      p.todo(where + ": field ICID (velocities in local coordinate system " + std::to_string(iv.icid) +
             ") is not implemented; give global components with ICID = 0");
    if (iv.nsid < 0 || iv.nsidex < 0 || iv.boxid < 0)
      p.bad(where + ": fields NSID, NSIDEX and BOXID must be 0 or a set/box id");
  }
}

void check_generation_cards(const model::Model& m, Problems& p) {
  for (const auto& g : m.initial_velocity_generations) {
    const std::string where = place(m, g, "*INITIAL_VELOCITY_GENERATION");
    const auto refuse = [&](bool unimplemented, const std::string& what) {
      if (unimplemented) p.todo(where + ": " + what + " is not implemented");
    };
    refuse(g.icid != 0, "field ICID (a local coordinate system)");
    refuse(g.ivatn != 0, "field IVATN = " + std::to_string(g.ivatn) +
                             " (velocities of slave parts and nodes of constrained rigid bodies)");
    refuse(g.phase != 0, "field PHASE = " + std::to_string(g.phase) +
                             " (initialisation after dynamic relaxation; give PHASE = 0)");
    // ID = 0: every node, STYP ignored (the LS-DYNA manual: "if zero, STYP is ignored").
    if (g.id != 0 && (g.styp < 1 || g.styp > 3))
      p.bad(where + ": field STYP must be 1 (part set), 2 (part) or 3 (node set) (got " + std::to_string(g.styp) +
            ")");
    if (g.omega != 0.0) {
      const Real len = g.n.norm();
      if (!(len > 0.0) || !std::isfinite(len))
        p.bad(where + ": OMEGA = " + num(g.omega) + " needs a rotation axis: fields NX NY NZ are all zero");
    }
  }
}

}  // namespace

void check_initial_velocities(const model::Model& m, Problems& p) {
  check_set_cards(m, p);
  check_generation_cards(m, p);
}

}  // namespace slideline::validation
