// validate_model, the initial velocities: the fields of *INITIAL_VELOCITY and
// *INITIAL_VELOCITY_GENERATION that this code does not run, or that are out of range, and the
// local systems (ICID) they name. Each message
// is the one the builder (initial_velocity.cpp) gave when it found the problem itself, to the
// letter; the builder keeps the id lookups (sets, boxes, nodes) and the checks that need the
// velocities resolved per node (two cards on one node, rigid parts).
#include <cmath>
#include <string>

#include "slideline/solver/coordinate_axes.hpp"
#include "validate_problems.hpp"

namespace slideline::validation {
namespace {

/// "deck.k:12: *INITIAL_VELOCITY" for messages.
template <class Card>
std::string place(const model::Model& m, const Card& c, const char* keyword) {
  return describe(model::element_source(m, c)) + ": " + keyword;
}

/// ICID: the velocities' local system, taken at t = 0 (a system that moves with its nodes has not
/// moved yet): it must exist and span a plane.
void check_icid(const model::Model& m, Problems& p, Id icid, const std::string& where) {
  if (icid == 0) return;
  try {
    local_axes(m, icid, where + " field ICID");
  } catch (const InputError& e) {
    p.bad(e.what());
  }
}

void check_set_cards(const model::Model& m, Problems& p) {
  for (const auto& iv : m.initial_velocities) {
    const std::string where = place(m, iv, "*INITIAL_VELOCITY");
    check_icid(m, p, iv.icid, where);
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
    check_icid(m, p, g.icid, where);
    // The manual gives VX VY VZ in the local system; whether the axis NX NY NZ is too it leaves open.
    refuse(g.icid != 0 && g.omega != 0.0,
           "field ICID with OMEGA != 0 (a spin about an axis given with a local system: the manual says "
           "VX VY VZ are local, not whether NX NY NZ are; give the axis and the velocities in global "
           "components, ICID = 0, or the spin on its own card)");
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
  for (const auto& iv : m.initial_velocity_nodes)
    check_icid(m, p, iv.icid, place(m, iv, "*INITIAL_VELOCITY_NODE"));
}

}  // namespace slideline::validation
