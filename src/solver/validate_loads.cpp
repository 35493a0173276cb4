// validate_model, what acts on the mesh: supports, loads, damping, curves, the controls the
// builder reads beyond those validate_model.cpp checks, and contact titles. Each message is the
// one the builder gave when it found the problem itself, to the letter.
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "build_support.hpp"
#include "slideline/solver/coordinate_axes.hpp"
#include "slideline/contact/interface_spec.hpp"
#include "validate_problems.hpp"

namespace slideline::validation {
namespace {

/// The local system `cid` that a card acts in through the run, resolved at t = 0: undefined or
/// degenerate is bad input; one that moves with its nodes (NODES FLAG = 1, VECTOR NID) is refused
/// (LS-DYNA turns such a card with the nodes each step; here a system is fixed).
std::optional<LocalAxes> fixed_frame(const model::Model& m, Problems& p, Id cid, const std::string& user) {
  try {
    LocalAxes a = local_axes(m, cid, user);
    if (a.system->moves()) {
      p.todo(user + " = " + std::to_string(cid) + ": the system moves with its nodes (" +
             (a.system->kind == model::CoordinateSystem::Kind::nodes ? "FLAG = 1" : "NID != 0") +
             "), which is not implemented for a card that acts through the run; give a fixed system");
      return std::nullopt;
    }
    return a;
  } catch (const InputError& e) {
    p.bad(e.what());
    return std::nullopt;
  }
}

void check_supports(const model::Model& m, Problems& p) {
  for (const auto& spc : m.spcs) {
    const char* const card = spc.node ? "*BOUNDARY_SPC_NODE" : "*BOUNDARY_SPC_SET";
    if (spc.cid != 0)
      if (const auto a = fixed_frame(m, p, spc.cid, describe(spc.src) + ": " + card + " field CID");
          a && !axis_permutation(a->r))
        p.todo(describe(spc.src) + ": " + card + " field CID = " + std::to_string(spc.cid) +
               ": constraints along axes that are not global axes (skew constraints) are not implemented; a "
               "system whose axes are global axes (in any order or sense) is accepted");
    if (std::any_of(spc.dof.begin(), spc.dof.end(), [](int d) { return d != 0 && d != 1; }))
      p.bad(describe(spc.src) + ": DOF flags of " + card + " must be 0 or 1");
  }
}

void check_nodal_and_body_loads(const model::Model& m, Problems& p) {
  for (const auto& lb : m.body_loads) {
    if (lb.lciddr != 0)
      p.todo(describe(lb.src) + ": *LOAD_BODY with LCIDDR (dynamic relaxation) is not implemented");
    if (lb.cid != 0) fixed_frame(m, p, lb.cid, describe(lb.src) + ": *LOAD_BODY field CID");
  }
  for (const auto& l : m.nodal_loads) {
    const std::string card = l.set ? "*LOAD_NODE_SET" : "*LOAD_NODE_POINT";
    if (l.cid != 0) fixed_frame(m, p, l.cid, describe(l.src) + ": " + card + " field CID");
    if (l.dof == 4 || l.dof == 8)
      p.todo(describe(l.src) + ": " + card + " DOF " + std::to_string(l.dof) +
             " (follower force or moment) is not implemented");
    else if (l.dof < 1 || l.dof > 7)
      p.bad(describe(l.src) + ": field DOF of " + card +
            " must be 1-3 (force along x, y, z) or 5-7 (moment about x, y, z); got " + std::to_string(l.dof));
  }
}

void check_damping(const model::Model& m, Problems& p) {
  if (m.damping_global && !common_direction_factor(m.damping_global->stf))
    p.todo(describe(m.damping_global->src) +
           ": per-direction damping scale factors STX..SRZ are not implemented; only one factor for every "
           "direction is accepted");
  // FLAG = 1 is LS-DYNA's per-direction scale-factor card, not a part set (that is _SET).
  for (const auto& d : m.damping_parts)
    if (d.flag == 1 && !common_direction_factor(d.stf))
      p.todo(describe(d.src) +
             ": per-direction damping scale factors STX..SRZ (FLAG = 1) are not implemented; only one factor for "
             "every direction is accepted");
  for (const auto& d : m.damping_stiffness) {
    if (d.coef > 0.0)
      p.todo(describe(d.src) + ": *DAMPING_PART_STIFFNESS COEF = " + std::to_string(d.coef) +
             " > 0 selects LS-DYNA's approximate fraction of critical damping at high frequencies, "
             "whose formulation is not published; give COEF = -beta (beta in time units, the "
             "classical Rayleigh coefficient: fraction of critical damping beta * omega / 2)");
    if (!std::isfinite(d.coef))
      p.bad(describe(d.src) + ": field COEF of *DAMPING_PART_STIFFNESS must be finite");
  }
}

/// Every curve as the builder makes it (scale factors and offsets applied), and the step bound
/// LCTM of *CONTROL_TIMESTEP, which must be positive everywhere.
void check_curves(const model::Model& m, Problems& p) {
  const Id lctm = m.timestep.lctm;
  for (const auto& c : m.curves) {
    try {
      const LoadCurve curve = make_curve(c);
      if (lctm == 0 || c.lcid != lctm) continue;
      for (const auto& [t, v] : curve.points())
        if (!(v > 0.0)) {
          p.bad(describe(m.timestep.src) + ": curve " + std::to_string(lctm) +
                " (LCTM, the largest step against time) must be positive everywhere (got " + std::to_string(v) +
                " at t = " + std::to_string(t) + ")");
          break;
        }
    } catch (const InputError& e) {
      p.bad(e.what());
    }
  }
}

void check_termination_and_step(const model::Model& m, Problems& p) {
  const auto& term = m.termination;
  if (term.dtmin < 0.0 || !std::isfinite(term.dtmin))
    p.bad(describe(term.src) + ": field DTMIN of *CONTROL_TERMINATION must be 0 or positive (got " +
          std::to_string(term.dtmin) + ")");
  if (term.endeng < 0.0 || !std::isfinite(term.endeng))
    p.bad(describe(term.src) + ": field ENDENG of *CONTROL_TERMINATION must be 0 or a positive percentage (got " +
          std::to_string(term.endeng) + ")");
  if (!std::isfinite(m.timestep.dt2ms))
    p.bad(describe(m.timestep.src) + ": field DT2MS of *CONTROL_TIMESTEP must be finite (got " +
          std::to_string(m.timestep.dt2ms) + ")");
  if (m.termination.endmas < 0.0 || !std::isfinite(m.termination.endmas))
    p.bad(describe(term.src) + ": field ENDMAS of *CONTROL_TERMINATION must be 0 or a positive percentage (got " +
          std::to_string(m.termination.endmas) + ")");
}

/// *RIGIDWALL_PLANAR: kinematic walls only (RWPNAL of *CONTROL_CONTACT = 0, its default).
void check_rigid_walls(const model::Model& m, Problems& p) {
  if (m.rigid_walls.empty() || m.control_contact.rwpnal == 0.0) return;
  p.todo(describe(m.rigid_walls.front().src) + ": *RIGIDWALL_PLANAR with RWPNAL = " +
         std::to_string(m.control_contact.rwpnal) +
         " of *CONTROL_CONTACT (penalty rigid walls) is not implemented; the walls here are kinematic (RWPNAL = 0)");
}

void check_contact_titles(const model::Model& m, Problems& p) {
  std::vector<std::string> titles;
  for (std::size_t k = 0; k < m.contacts.size(); ++k) {
    const auto& card = m.contacts[k];
    const std::string title = contact_title(card, k + 1);
    if (std::find(titles.begin(), titles.end(), title) != titles.end())
      p.bad(describe(card.src) + ": contact title '" + title +
            "' is used by an earlier contact; output channels need distinct titles");
    titles.push_back(title);
  }
}

}  // namespace

void check_loads(const model::Model& m, Problems& p) {
  check_supports(m, p);
  check_nodal_and_body_loads(m, p);
  check_damping(m, p);
  check_curves(m, p);
  check_termination_and_step(m, p);
  check_contact_titles(m, p);
  check_rigid_walls(m, p);
}

}  // namespace slideline::validation
