// validate_model: located input checks before a build (see validate_model.hpp).
#include "slideline/solver/validate_model.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <unordered_map>

#include "issue_groups.hpp"
#include "validate_problems.hpp"
#include "slideline/core/error.hpp"
#include "slideline/core/overloaded.hpp"
#include "slideline/element/hex8.hpp"
#include "slideline/model/unsupported.hpp"
#include "slideline/solver/material_registry.hpp"

namespace slideline {
namespace {

using validation::num;
using validation::Problems;

// Material constants beyond this magnitude overflow the products the solver forms (wave speeds,
// energies): no consistent unit system needs them.
constexpr Real kMaxConstant = 1e30;

/// degenerate_kind of a tetrahedron (compared by address).
constexpr const char* kTetrahedra =
    "4-node tetrahedra (written as degenerate *ELEMENT_SOLID, N4 = N5 = ... = N8 or N5..N8 blank)";
/// degenerate_kind of a pentahedron and of a pyramid (compared by address): LS-DYNA's forms
/// N1 N2 N3 N4 N5 N5 N6 N6 and N1 N2 N3 N4 N5 N5 N5 N5, which ELFORM 1 and 2 parts run as
/// hexahedra with the collapsed nodes (docs/solver.md, "Pentahedra and pyramids").
constexpr const char* kPentahedra = "6-node pentahedra (degenerate *ELEMENT_SOLID, N5 = N6 and N7 = N8)";
constexpr const char* kPyramids = "5-node pyramids (degenerate *ELEMENT_SOLID, N5 = N6 = N7 = N8)";

void positive(Problems& p, const model::Source& src, const char* card, const char* field, Real v) {
  if (!(v > 0.0) || !std::isfinite(v))
    p.bad(src, std::string("field ") + field + " of " + card + " must be positive (got " + num(v) + ")");
  else if (v > kMaxConstant)
    p.bad(src, std::string("field ") + field + " of " + card + " is " + num(v) + ", beyond " + num(kMaxConstant) +
                   " (check the units)");
}

void poisson(Problems& p, const model::Source& src, const char* card, Real v) {
  if (!(v > -1.0 && v < 0.5))
    p.bad(src, std::string("field PR of ") + card + " must be in (-1, 0.5) (got " + num(v) + ")");
}

void check_plastic_kinematic(const model::MatPlasticKinematic& x, Problems& p) {
  const char* card = "*MAT_PLASTIC_KINEMATIC";
  positive(p, x.src, card, "RO", x.ro);
  positive(p, x.src, card, "E", x.e);
  poisson(p, x.src, card, x.pr);
  positive(p, x.src, card, "SIGY", x.sigy);
  if (!(x.etan >= 0.0 && x.etan < x.e))
    p.bad(x.src, std::string("field ETAN of ") + card + " must be in [0, E) (got " + num(x.etan) + ")");
  if (!(x.beta >= 0.0 && x.beta <= 1.0))
    p.bad(x.src, std::string("field BETA of ") + card + " must be in [0, 1] (got " + num(x.beta) + ")");
  if (!(x.src_c >= 0.0) || !std::isfinite(x.src_c))
    p.bad(x.src, std::string("field SRC of ") + card + " must not be negative (got " + num(x.src_c) + ")");
  if (x.src_c > 0.0 && !(x.srp > 0.0 && std::isfinite(x.srp)))
    p.bad(x.src, std::string("field SRP of ") + card + " must be positive when SRC is given (got " + num(x.srp) + ")");
}

void check_piecewise_linear(const model::Model& m, const model::MatPiecewiseLinearPlasticity& x, Problems& p) {
  const char* card = "*MAT_PIECEWISE_LINEAR_PLASTICITY";
  bool curves_ok = true;
  for (const auto& [id, field] : {std::pair{x.lcss, "LCSS"}, std::pair{x.lcsr, "LCSR"}})
    if (id != 0 && std::none_of(m.curves.begin(), m.curves.end(), [&](const model::Curve& c) { return c.lcid == id; })) {
      p.bad(x.src, std::string("field ") + field + " of " + card + " refers to curve " + std::to_string(id) +
                       ", which is not defined");
      curves_ok = false;
    }
  if (curves_ok && x.e > 0.0 && x.pr > -1.0 && x.pr < 0.5) {
    try {
      const MaterialLaws laws = material_laws(model::Material{x}, m.curves);
      const std::string why = std::get<PiecewisePlasticity>(*laws.solid).problem();
      if (!why.empty()) p.bad(x.src, std::string(card) + ": " + why + " (LCSS, or EPS/ES, or SIGY/ETAN)");
    } catch (const InputError& e) {
      p.bad(x.src, e.what());
    }
  }
  positive(p, x.src, card, "RO", x.ro);
  positive(p, x.src, card, "E", x.e);
  poisson(p, x.src, card, x.pr);
  if (x.lcss == 0 && x.es[0] == 0.0) {  // SIGY and ETAN give the curve
    positive(p, x.src, card, "SIGY", x.sigy);
    if (!(x.etan >= 0.0 && x.etan < x.e))
      p.bad(x.src, std::string("field ETAN of ") + card + " must be in [0, E) (got " + num(x.etan) + ")");
  }
  if (!(x.c >= 0.0) || !std::isfinite(x.c))
    p.bad(x.src, std::string("field C of ") + card + " must not be negative (got " + num(x.c) + ")");
  if (x.c > 0.0 && !(x.p > 0.0 && std::isfinite(x.p)))
    p.bad(x.src, std::string("field P of ") + card + " must be positive when C is given (got " + num(x.p) + ")");
}

void check_materials(const model::Model& m, Problems& p) {
  // One case per alternative of model::Material and no generic one: a new material does not
  // compile until it is checked here.
  for (const auto& mat : m.materials) {
    std::visit(
        Overloaded{
            [&](const model::MatElastic& x) {
              positive(p, x.src, "*MAT_ELASTIC", "RO", x.ro);
              positive(p, x.src, "*MAT_ELASTIC", "E", x.e);
              poisson(p, x.src, "*MAT_ELASTIC", x.pr);
            },
            [&](const model::MatMooneyRivlin& x) {
              const char* card = "*MAT_MOONEY-RIVLIN_RUBBER";
              positive(p, x.src, card, "RO", x.ro);
              poisson(p, x.src, card, x.pr);
              if (!std::isfinite(x.a) || !std::isfinite(x.b) || std::abs(x.a) > kMaxConstant ||
                  std::abs(x.b) > kMaxConstant || !(x.a + x.b > 0.0))
                p.bad(x.src, std::string("fields A, B of ") + card +
                                 " must give a positive shear modulus 2(A + B) (got A = " + num(x.a) +
                                 ", B = " + num(x.b) + ")");
            },
            [&](const model::MatPlasticKinematic& x) { check_plastic_kinematic(x, p); },
            [&](const model::MatPiecewiseLinearPlasticity& x) { check_piecewise_linear(m, x, p); },
            [&](const model::MatNull& x) {  // YM, PR: shells (validate_parts); PC, MU, TEROD, CEROD: solids
              const char* card = "*MAT_NULL";
              positive(p, x.src, card, "RO", x.ro);
              if (!(x.pc <= 0.0) || !std::isfinite(x.pc))
                p.bad(x.src, std::string("field PC of ") + card + " is a pressure cutoff in tension and must not be "
                                                                  "positive (got " + num(x.pc) + ")");
              for (const auto& [name, v] : {std::pair{"MU", x.mu}, std::pair{"TEROD", x.terod}, std::pair{"CEROD", x.cerod}})
                if (!(v >= 0.0) || !std::isfinite(v))
                  p.bad(x.src, std::string("field ") + name + " of " + card + " must not be negative (got " + num(v) + ")");
              if (x.terod > 0.0 && !(x.terod > 1.0))
                p.bad(x.src, std::string("field TEROD of ") + card + " is the relative volume V/V0 of erosion in tension "
                                                                     "and must exceed 1 (got " + num(x.terod) + ")");
              if (x.cerod > 0.0 && !(x.cerod < 1.0))
                p.bad(x.src, std::string("field CEROD of ") + card + " is the relative volume V/V0 of erosion in "
                                                                     "compression and must be below 1 (got " + num(x.cerod) + ")");
            },
            [&](const model::MatRigid& x) {
              positive(p, x.src, "*MAT_RIGID", "RO", x.ro);
              positive(p, x.src, "*MAT_RIGID", "E", x.e);
              poisson(p, x.src, "*MAT_RIGID", x.pr);
            },
        },
        mat);
  }
}

void check_controls(const model::Model& m, const BuildOptions& o, Problems& p) {
  const auto& ts = m.timestep;
  if (!std::isfinite(ts.tssfac) || ts.tssfac < 0.0 || ts.tssfac > 1.0)
    p.bad(ts.src, "field TSSFAC of *CONTROL_TIMESTEP must be in (0, 1] (0 = the default 0.9; got " +
                      num(ts.tssfac) + ")");
  const Real end = o.end_time > 0.0 ? o.end_time : m.termination.endtim;
  if (!(end > 0.0) && m.termination.endcyc <= 0) {
    if (m.termination.src.line > 0)
      p.bad(m.termination.src, "field ENDTIM of *CONTROL_TERMINATION must be positive (got " +
                                   num(m.termination.endtim) + ")");
    else
      p.bad({m.files.empty() ? std::string() : m.files.front(), 0},
            "no end time: the deck has no *CONTROL_TERMINATION with ENDTIM > 0");
  }
  for (const auto& pm : m.prescribed_motions) {
    const std::string card = pm.keyword();
    const bool rigid = pm.target == model::PrescribedMotion::Target::rigid;
    // VAD: 0 velocity, 1 acceleration (nodes only in LS-DYNA), 2 displacement are run; 3 (velocity
    // against displacement) and 4 (relative displacement) are LS-DYNA forms not implemented here.
    if (pm.vad == 3 || pm.vad == 4)
      p.todo(pm.src, "field VAD of " + card + ": " +
                         (pm.vad == 3 ? "velocity against displacement" : "relative displacement") +
                         " (VAD " + std::to_string(pm.vad) +
                         ") is not implemented (0 velocity, 1 acceleration, 2 displacement are)");
    else if (pm.vad < 0 || pm.vad > 4)
      p.bad(pm.src, "field VAD of " + card + " must be 0 to 4 (got " + std::to_string(pm.vad) + ")");
    else if (pm.vad == 1 && rigid)
      p.bad(pm.src, "field VAD of " + card +
                        ": LS-DYNA prescribes accelerations (VAD 1) on nodes only, not on rigid bodies");
    // DOF: the translations 1-3 are run, and the rotations 5-7 of a rigid part. Rotations of
    // nodes, 4/-4/8/-8 (along VID), 9-12 (rotation about an axis through the body, radial motion)
    // and -1..-3 (not in the LS-DYNA manual's list) are not.
    const bool rigid_rotation = rigid && pm.dof >= 5 && pm.dof <= 7;
    if ((pm.dof < 1 || pm.dof > 3) && !rigid_rotation) {
      if (pm.dof >= -12 && pm.dof <= 12 && pm.dof != 0)
        p.todo(pm.src, "field DOF of " + card + ": DOF " + std::to_string(pm.dof) + " is not implemented (DOF 1-3, the translations, are" +
                           (rigid ? ", and 5-7, the rotations)" : "; rotations 5-7 on _RIGID only)"));
      else
        p.bad(pm.src, "field DOF of " + card + " must be 1 to 12, -4 or -8 (got " + std::to_string(pm.dof) + ")");
    }
    if (pm.vid != 0)
      p.todo(pm.src, "field VID of " + card + ": a motion along a vector is not implemented (got VID " +
                         std::to_string(pm.vid) + ")");
    if (!(pm.death > pm.birth))
      p.bad(pm.src, card + ": DEATH (" + num(pm.death) + ") must be after BIRTH (" + num(pm.birth) + ")");
  }
}

/// BT and DT of the *CONTACT cards (card 2). Negative values are LS-DYNA's dynamic-relaxation
/// forms (and DT = -9999 a birth/death curve), which this solver does not have.
void check_contact_times(const model::Model& m, Problems& p) {
  for (const auto& c : m.contacts) {
    const std::string card = c.keyword.empty() ? std::string("*CONTACT") : c.keyword;
    if (c.bt < 0.0 || c.dt < 0.0) {
      p.todo(c.src, std::string("field ") + (c.bt < 0.0 ? "BT" : "DT") + " of " + card + " (card 2) is negative (" +
                        num(c.bt < 0.0 ? c.bt : c.dt) +
                        "): birth and death during dynamic relaxation, or a birth/death curve, are not implemented");
      continue;
    }
    if (!(c.dt > c.bt))
      p.bad(c.src, "field DT of " + card + " (card 2): the death time (" + num(c.dt) +
                       ") must be after the birth time BT (" + num(c.bt) + ")");
  }
}

/// The kind of a degenerate hexahedron, or nullptr for eight distinct nodes.
const char* degenerate_kind(const std::array<Id, 8>& n) {
  const std::set<Id> distinct(n.begin(), n.end());
  if (distinct.size() == 8) return nullptr;
  const bool tail_blank = n[4] == 0 && n[5] == 0 && n[6] == 0 && n[7] == 0;
  const bool tail_n4 = n[4] == n[3] && n[5] == n[3] && n[6] == n[3] && n[7] == n[3];
  if ((tail_blank || tail_n4) && std::set<Id>(n.begin(), n.begin() + 4).size() == 4) return kTetrahedra;
  if (n[4] == n[5] && n[6] == n[7] && distinct.size() == 6) return kPentahedra;
  if (n[4] == n[5] && n[5] == n[6] && n[6] == n[7] && distinct.size() == 5) return kPyramids;
  return nullptr;
}

/// The ELFORM of each part's *SECTION_SOLID (parts without one are left out: check_references
/// reports them).
std::unordered_map<Id, int> solid_forms(const model::Model& m) {
  std::unordered_map<Id, int> form_of_section, form;
  for (const auto& s : m.solid_sections) form_of_section.emplace(s.secid, s.elform);
  for (const auto& part : m.parts)
    if (const auto f = form_of_section.find(part.secid); f != form_of_section.end()) form.emplace(part.pid, f->second);
  return form;
}

/// The shape of one *ELEMENT_SOLID against its part's ELFORM: a tetrahedron (N1 N2 N3 N4 N4 N4 N4
/// N4, or N5-N8 blank) in an ELFORM 10 part; in an ELFORM 1 (0) or 2 part eight distinct nodes, a
/// pentahedron N1 N2 N3 N4 N5 N5 N6 N6 or a pyramid N1 N2 N3 N4 N5 N5 N5 N5 (run, as LS-DYNA
/// does, as hexahedra with the collapsed nodes); then its volume.
void check_solid(const model::Model& m, const model::SolidElement& e, int elform,
                 const std::unordered_map<Id, std::size_t>& node_of, IssueGroups& bad, IssueGroups& unimplemented) {
  const auto src = model::element_source(m, e);
  const std::string id = std::to_string(e.id);
  const char* kind = degenerate_kind(e.n);
  const bool tet_form = elform == 10;
  const bool hex_form = elform == 0 || elform == 1 || elform == 2;
  const bool distinct = std::set<Id>(e.n.begin(), e.n.end()).size() == 8;
  const bool fits = tet_form ? kind == kTetrahedra
                             : distinct || (hex_form && (kind == kPentahedra || kind == kPyramids));
  if (!fits) {
    if (tet_form)
      bad.add("*ELEMENT_SOLID: elements of an ELFORM 10 (tetrahedron) part that are not tetrahedra "
              "(N1 N2 N3 N4 N4 N4 N4 N4)",
              "*ELEMENT_SOLID " + id + " is in a part of *SECTION_SOLID ELFORM 10 but is not a tetrahedron "
              "(N1 N2 N3 N4 N4 N4 N4 N4)", id, src);
    else if (kind)
      unimplemented.add(std::string("*ELEMENT_SOLID: ") + kind + " are not supported in a part of ELFORM " +
                            std::to_string(elform) + (kind == kTetrahedra ? " (use ELFORM 10)" : " (use ELFORM 1 or 2)"),
                        "*ELEMENT_SOLID " + id + " is one of the " + kind + ", which are not supported in a part of "
                        "ELFORM " + std::to_string(elform), id, src);
    else
      bad.add("*ELEMENT_SOLID: degenerate hexahedra (repeated nodes in a form slideline does not know)",
              "*ELEMENT_SOLID " + id + " repeats a node", id, src);
    return;
  }
  const int nn = tet_form ? 4 : 8;
  hex8::NodeMat X;
  for (int k = 0; k < nn; ++k) {
    const auto f = node_of.find(e.n[static_cast<std::size_t>(k)]);
    if (f == node_of.end()) return;  // check_references reports it
    X.row(k) = m.nodes[f->second].x.transpose();
  }
  const Real v = tet_form ? (X.row(1) - X.row(0)).dot((X.row(2) - X.row(0)).cross(X.row(3) - X.row(0))) / 6.0
                          : hex8::volume(X, hex8::volume_gradient(X));
  if (!(v > 0.0))
    bad.add(std::string("*ELEMENT_SOLID: non-positive volume (inverted ") +
                (tet_form ? "tetrahedra: list N1-N3 counter-clockwise seen from N4)"
                          : "hexahedra: list N1-N4 counter-clockwise seen from the face N5-N8)"),
            "*ELEMENT_SOLID " + id + " has non-positive volume " + num(v) +
                (tet_form ? " (inverted: list N1-N3 counter-clockwise seen from N4)"
                          : " (inverted: list N1-N4 counter-clockwise seen from the face N5-N8)"),
            id, src);
}

void check_elements(const model::Model& m, Problems& p) {
  std::unordered_map<Id, std::size_t> node_of;
  for (std::size_t i = 0; i < m.nodes.size(); ++i) node_of.emplace(m.nodes[i].id, i);
  const std::unordered_map<Id, int> forms = solid_forms(m);
  IssueGroups unimplemented, bad;
  for (const auto& e : m.solids) {
    const auto f = forms.find(e.pid);
    check_solid(m, e, f == forms.end() ? 1 : f->second, node_of, bad, unimplemented);
  }
  for (const auto& e : m.shells) {
    const auto src = model::element_source(m, e);
    const std::string id = std::to_string(e.id);
    const std::set<Id> distinct(e.n.begin(), e.n.end());
    // A triangle (N3 = N4, three distinct nodes) runs as the C0 triangle (check_parts refuses it
    // in a rigid part).
    if (e.n[2] == e.n[3] && distinct.size() == 3) continue;
    if (distinct.size() != 4)
      bad.add("*ELEMENT_SHELL: degenerate quadrilaterals (repeated nodes)",
              "*ELEMENT_SHELL " + id + " repeats a node", id, src);
  }
  bad.append_to(p.input, 1);
  unimplemented.append_to(p.unimplemented, 1);
}

/// Parts that use a card the reader dropped (--ignore-unsupported): name the card, not a
/// dangling id, when a caller builds without check_references.
void check_dropped_references(const model::Model& m, Problems& p) {
  if (m.unsupported.empty()) return;
  for (const auto& part : m.parts) {
    const std::pair<std::string_view, Id> uses[] = {
        {"material", part.mid}, {"section", part.secid}, {"hourglass", part.hgid}, {"equation of state", part.eosid}};
    for (const auto& [kind, id] : uses)
      if (id != 0)
        if (const auto* u = model::find_unsupported(m, kind, id))
          p.todo(part.src, "part " + std::to_string(part.pid) + " uses " + model::card_and_place(*u, part.src.file) +
                               ", not supported");
  }
}

}  // namespace

void validate_model(const model::Model& m, const BuildOptions& options) {
  Blockers b = find_model_problems(m, options);
  Problems p{std::move(b.input), std::move(b.unimplemented)};
  if (!p.empty()) p.raise();
}

Blockers find_model_problems(const model::Model& m, const BuildOptions& options) {
  Problems p;
  add_empty_model_problems(m, "the model has no", p.input);
  check_dropped_references(m, p);
  check_materials(m, p);
  check_controls(m, options, p);
  check_contact_times(m, p);
  check_elements(m, p);
  validation::check_parts(m, p);
  validation::check_loads(m, p);
  validation::check_initial_velocities(m, p);
  return {std::move(p.input), std::move(p.unimplemented)};
}

}  // namespace slideline
