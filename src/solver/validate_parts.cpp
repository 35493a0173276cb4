// validate_model, the parts: what each part with elements asks of its section, hourglass card and
// material (the checks build_elements relies on), and the nodes' constraint codes. A dangling id
// is check_references' to report (and the builder's lookup's): it is passed over here.
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <unordered_map>
#include <variant>
#include <vector>

#include "build_support.hpp"
#include "slideline/solver/material_registry.hpp"
#include "validate_problems.hpp"

namespace slideline::validation {
namespace {

/// The part ids with elements in order of first appearance (solids, then shells), each with the
/// kinds of element it has: the order build_elements builds them in.
struct PartUse {
  bool solids = false, shells = false;
  const model::ShellElement* triangle = nullptr;  ///< the part's first triangular shell (N3 = N4)
  bool quads = false;                             ///< the part has quadrilateral shells
  const model::SolidElement* degenerate = nullptr;  ///< the part's first solid with repeated nodes
};

std::vector<std::pair<Id, PartUse>> parts_in_use(const model::Model& m) {
  std::vector<std::pair<Id, PartUse>> out;
  std::unordered_map<Id, std::size_t> at;
  const auto use = [&](Id pid) -> PartUse& {
    const auto [it, fresh] = at.try_emplace(pid, out.size());
    if (fresh) out.push_back({pid, {}});
    return out[it->second].second;
  };
  for (const auto& e : m.solids) {
    PartUse& u = use(e.pid);
    u.solids = true;
    if (!u.degenerate) {
      std::array<Id, 8> n = e.n;
      std::sort(n.begin(), n.end());
      if (std::unique(n.begin(), n.end()) != n.end()) u.degenerate = &e;
    }
  }
  for (const auto& e : m.shells) {
    PartUse& u = use(e.pid);
    u.shells = true;
    if (e.n[2] != e.n[3]) u.quads = true;
    else if (!u.triangle) u.triangle = &e;
  }
  return out;
}

template <class T, class Key>
std::unordered_map<Id, const T*> by_id(const std::vector<T>& items, Key key) {
  std::unordered_map<Id, const T*> out;
  for (const auto& it : items) out.emplace(key(it), &it);
  return out;
}

template <class Map>
auto find(const Map& map, Id id) -> decltype(map.begin()->second) {
  const auto f = map.find(id);
  return f == map.end() ? nullptr : f->second;
}

/// The section of a shell part with quadrilaterals (`quads`) and/or triangles: ELFORM 2 (0) runs
/// quads as Belytschko-Tsay and triangles as the C0 triangle, as LS-DYNA does; ELFORM 4 (the C0
/// triangle) is taken for a part of triangles only.
void check_shell_section(const model::SectionShell& sec, bool quads, Problems& p) {
  if (sec.elform == 4 && quads)
    p.todo(describe(sec.src) + ": field ELFORM of *SECTION_SHELL: 4 (C0 triangle) on a part with quadrilateral "
                               "shells is not implemented (ELFORM 2 runs quadrilaterals as Belytschko-Tsay and "
                               "triangles, N3 = N4, as C0 triangles)");
  else if (sec.elform != 2 && sec.elform != 0 && sec.elform != 4)
    p.todo(describe(sec.src) + ": field ELFORM of *SECTION_SHELL: " + std::to_string(sec.elform) +
           " is not implemented (only 2, Belytschko-Tsay quadrilaterals and C0 triangles, and 4, C0 triangles)");
  if (!(sec.t[0] > 0.0))
    p.bad(describe(sec.src) + ": field T1 of *SECTION_SHELL must be positive (got " + std::to_string(sec.t[0]) +
          ")");
  for (int k = 1; k < 4; ++k)
    if (sec.t[k] != 0.0 && sec.t[k] != sec.t[0]) {
      p.todo(describe(sec.src) + ": varying nodal shell thicknesses (T2-T4 != T1) are not implemented");
      break;
    }
}

void check_rigid(const model::MatRigid& mat, Problems& p) {
  if (mat.cmo == 1.0) {
    for (const auto& [code, field] : {std::pair{mat.con1, "CON1"}, std::pair{mat.con2, "CON2"}})
      if (!rigid_constraint_code(code))
        p.bad(describe(mat.src) + ": field " + field + " of *MAT_RIGID must be 0 to 7 (got " +
              std::to_string(code) + ")");
  } else if (mat.cmo != 0.0) {
    p.todo(describe(mat.src) + ": *MAT_RIGID CMO = -1 (constraints in a local system) is not implemented");
  }
}

/// A deformable part of shells: its section, the material's shell law, the hourglass type.
void check_shell_part(const model::Part& part, const model::SectionShell* sec, bool quads, const MaterialLaws& laws,
                      int ihq, Problems& p) {
  if (sec) check_shell_section(*sec, quads, p);
  if (!laws.shell)
    p.todo(describe(part.src) + ": part " + std::to_string(part.pid) +
           " combines shells with " + laws.keyword + ", which is not implemented");
  if (ihq < 0 || ihq > 6)
    p.todo(describe(part.src) + ": hourglass type IHQ=" + std::to_string(ihq) + " for shells of part " +
           std::to_string(part.pid) + " is not implemented (shells take the viscous types 1-3 and the stiffness "
           "types 4-6)");
  if (sec && (shell_nip(*sec) < 1 || shell_nip(*sec) > 10))
    p.bad(describe(sec->src) + ": field NIP of *SECTION_SHELL must be 1 to 10 (got " + std::to_string(sec->nip) +
          ")");
}

/// A deformable part of hexahedra: its section, the hourglass type, the material's solid law.
void check_solid_part(const model::Part& part, const model::SectionSolid* sec, const MaterialLaws& laws, int ihq,
                      Problems& p) {
  const int elform = sec ? sec->elform : 1;
  if (elform != 1 && elform != 0 && elform != 2 && elform != 10)
    p.todo(describe(sec->src) + ": field ELFORM of *SECTION_SOLID: " + std::to_string(elform) +
           " is not implemented (1 the one-point hexahedron, 2 the fully integrated selective-reduced "
           "hexahedron, 10 the one-point tetrahedron)");
  // Tetrahedra and fully integrated hexahedra have no hourglass modes: IHQ and QM do not act on
  // them (nor in LS-DYNA).
  if ((elform == 0 || elform == 1) && !hex_hourglass_kind(ihq))
    p.todo(describe(part.src) + ": hourglass type IHQ=" + std::to_string(ihq) + " of part " +
           std::to_string(part.pid) + " is not implemented (use 1-3 viscous, 4-5 Flanagan-Belytschko stiffness, 6 assumed strain or 10 physical "
           "stiffness)");
  if (!laws.solid)
    p.todo(describe(part.src) + ": part " + std::to_string(part.pid) + " combines solids with " + laws.keyword +
           (std::string(laws.keyword) == "*MAT_NULL" ? " (a solid of it needs an equation of state, *EOS_...)" : "") +
           ", which is not implemented");
}

/// The equation of state of a part (EOSID, `eos` its card or null) and the *MAT_NULL fields that
/// act on one element kind only: an EOS goes with *MAT_NULL solids (the other laws have their own
/// pressure); YM, PR with null shells (LS-DYNA: "used for null beams and shells only"); PC, MU,
/// TEROD, CEROD with null solids.
void check_eos_use(const model::Part& part, const model::Material& mat, const model::Eos* eos, bool solids,
                   const model::SectionSolid* sec, int ihq, Problems& p) {
  const std::string who = "part " + std::to_string(part.pid);
  const auto* null = std::get_if<model::MatNull>(&mat);
  if (eos && (!null || !solids)) {
    p.bad(part.src, who + ": field EOSID = " + std::to_string(part.eosid) + " of *PART: an equation of state goes "
                    "with *MAT_NULL solids; " + (null ? std::string("a null shell has no pressure")
                                                      : "material " + std::to_string(part.mid) + " has its own pressure"));
    return;
  }
  if (!null) return;
  if (!solids) {
    // YM and PR set a null shell's step and contact stiffness.
    if (!(null->ym > 0.0) || !std::isfinite(null->ym))
      p.bad(null->src, "field YM of *MAT_NULL must be positive (got " + num(null->ym) + ")");
    if (!(null->pr > -1.0 && null->pr < 0.5))
      p.bad(null->src, "field PR of *MAT_NULL must be in (-1, 0.5) (got " + num(null->pr) + ")");
    for (const auto& [name, v] : {std::pair{"PC", null->pc}, std::pair{"MU", null->mu}, std::pair{"TEROD", null->terod},
                                  std::pair{"CEROD", null->cerod}})
      if (v != 0.0)
        p.todo(null->src, std::string("field ") + name + " = " + num(v) + " of *MAT_NULL acts on solids (with an "
                          "equation of state); shell " + who + " has no pressure: leave it blank");
    return;
  }
  if (!eos) return;  // check_solid_part: a null solid needs an equation of state
  for (const auto& [name, v] : {std::pair{"YM", null->ym}, std::pair{"PR", null->pr}})
    if (v != 0.0)
      p.todo(null->src, std::string("field ") + name + " = " + num(v) + " of *MAT_NULL is used for null shells and "
                        "beams only; solid " + who + " takes its stiffness from its equation of state: leave it blank");
  const int elform = sec ? sec->elform : 1;
  if (elform != 0 && elform != 1)
    p.todo(sec->src, "field ELFORM of *SECTION_SOLID: " + std::to_string(elform) + " with *MAT_NULL (" + who +
                         ") is not implemented (null solids run as one-point hexahedra, ELFORM 1)");
  if ((elform == 0 || elform == 1) && (ihq == 6 || ihq == 10))
    p.todo(part.src, "hourglass type IHQ=" + std::to_string(ihq) + " of *MAT_NULL " + who + " is not implemented "
                     "(it needs a Young's modulus; a null solid takes 1-3 viscous or 4-5 stiffness, on the EOS's bulk modulus)");
  const auto [card, v0, src] = std::visit(
      [](const auto& x) { return std::tuple{model::eos_keyword(x), x.v0, x.src}; }, *eos);
  if (v0 != 0.0 && v0 != 1.0)
    p.todo(src, std::string("field V0 = ") + num(v0) + " of " + card + " is not implemented (an initial relative "
                "volume other than 1: give 0 or 1)");
  const EquationOfState law = equation_of_state(*eos, null->ro);
  if (const std::string why = law.problem(); !why.empty()) {
    p.bad(src, why);
    return;
  }
  const NullSolid solid(null->ro, null->pc, null->mu, law);
  if (!(solid.bulk_modulus() > 0.0) || !std::isfinite(solid.bulk_modulus()))
    p.bad(src, std::string(card) + " " + std::to_string(part.eosid) + ": the sound speed at the reference state "
               "(V = V0, E = E0) must be positive (dp/drho = " + num(solid.bulk_modulus() / null->ro) +
               "): a null solid's step, hourglass and contact stiffness read it");
}

/// *BOUNDARY_PRESCRIBED_MOTION_RIGID drives a *MAT_RIGID part with elements. `unresolved`: parts
/// with elements whose card or material is missing (check_references reports them).
void check_rigid_motions(const model::Model& m, const std::set<Id>& in_use, const std::set<Id>& rigid,
                         const std::set<Id>& unresolved, Problems& p) {
  for (const auto& pm : m.prescribed_motions) {
    if (pm.target != model::PrescribedMotion::Target::rigid || rigid.count(pm.nsid) || unresolved.count(pm.nsid))
      continue;
    p.bad(describe(pm.src) + ": field PID of " + pm.keyword() + " refers to part " + std::to_string(pm.nsid) +
          (in_use.count(pm.nsid) ? ", which is not a *MAT_RIGID part" : ", which has no elements in the deck"));
  }
}

/// Supports and motions on nodes of rigid parts would tear the nodes off their bodies: the first
/// such node of each card (in deck order of *NODE), named with its part, as the builder named it.
class RigidNodes {
 public:
  RigidNodes(const model::Model& m, const std::set<Id>& rigid) : m_(m) {
    for (std::size_t i = 0; i < m.nodes.size(); ++i) index_.emplace(m.nodes[i].id, i);
    std::unordered_map<Id, std::size_t> rank;  // rigid part -> its place in build order
    for (const auto& [pid, use] : parts_in_use(m))
      if (rigid.count(pid)) rank.emplace(pid, rank.size());
    const auto add = [&](Id pid, const auto& element_nodes) {
      const auto r = rank.find(pid);
      if (r == rank.end()) return;
      for (Id n : element_nodes) {
        const auto [it, fresh] = part_.try_emplace(n, pid);
        if (!fresh && r->second < rank.at(it->second)) it->second = pid;
      }
    };
    for (const auto& e : m.solids) add(e.pid, e.n);
    for (const auto& e : m.shells) add(e.pid, e.n);
  }

  void check(bool single, Id id, const model::Source& src, const std::string& card, Problems& p) const {
    if (part_.empty()) return;
    std::vector<std::pair<std::size_t, Id>> nodes;  // (deck index, id)
    const auto add = [&](Id n) {
      if (const auto f = index_.find(n); f != index_.end()) nodes.emplace_back(f->second, n);
    };
    if (single) {
      add(id);
    } else if (const auto s = std::find_if(m_.node_sets.begin(), m_.node_sets.end(),
                                           [&](const model::NodeSet& x) { return x.sid == id; });
               s != m_.node_sets.end()) {
      for (Id n : s->nodes) add(n);
    }
    std::sort(nodes.begin(), nodes.end());
    for (const auto& [i, n] : nodes)
      if (const auto f = part_.find(n); f != part_.end()) {
        p.bad(describe(src) + ": " + card + " constrains node " + std::to_string(n) + " of rigid part " +
              std::to_string(f->second) +
              "; constrain a rigid part through its *MAT_RIGID (CMO = 1, CON1, CON2) or move it with "
              "*BOUNDARY_PRESCRIBED_MOTION_RIGID instead");
        return;
      }
  }

 private:
  const model::Model& m_;
  std::unordered_map<Id, std::size_t> index_;
  std::unordered_map<Id, Id> part_;  // node id -> the first rigid part (build order) it belongs to
};

/// *NODE TC/RC: codes 0-7 (as *MAT_RIGID's CON1/CON2); the first bad node of each field.
void check_node_codes(const model::Model& m, Problems& p) {
  for (const char* field : {"TC", "RC"})
    for (const auto& nd : m.nodes) {
      const int code = field[0] == 'T' ? nd.tc : nd.rc;
      if (rigid_constraint_code(code)) continue;
      p.bad("*NODE " + std::to_string(nd.id) + ": field " + field + " must be 0-7 (0 free, 1 x, 2 y, 3 z, 4 xy, " +
            "5 yz, 6 zx, 7 xyz), got " + std::to_string(code));
      break;
    }
}

void check_rigid_nodes(const model::Model& m, const std::set<Id>& rigid, Problems& p) {
  if (rigid.empty()) return;
  const RigidNodes nodes(m, rigid);
  for (const auto& nd : m.nodes)
    if (nd.tc != 0 || nd.rc != 0) nodes.check(true, nd.id, {"*NODE " + std::to_string(nd.id), 0}, "field TC/RC", p);
  for (const auto& spc : m.spcs)
    nodes.check(spc.node, spc.nsid, spc.src, spc.node ? "*BOUNDARY_SPC_NODE" : "*BOUNDARY_SPC_SET", p);
  for (const auto& pm : m.prescribed_motions)
    if (pm.target != model::PrescribedMotion::Target::rigid)
      nodes.check(pm.target == model::PrescribedMotion::Target::node, pm.nsid, pm.src, pm.keyword(), p);
}

}  // namespace

void check_parts(const model::Model& m, Problems& p) {
  check_node_codes(m, p);
  const auto parts = by_id(m.parts, [](const model::Part& x) { return x.pid; });
  const auto ssec = by_id(m.solid_sections, [](const model::SectionSolid& x) { return x.secid; });
  const auto shsec = by_id(m.shell_sections, [](const model::SectionShell& x) { return x.secid; });
  const auto hgs = by_id(m.hourglasses, [](const model::Hourglass& x) { return x.hgid; });
  const auto mats = by_id(m.materials, [](const model::Material& x) { return model::material_id(x); });
  std::set<Id> in_use, rigid, unresolved;
  for (const auto& [pid, use] : parts_in_use(m)) {
    in_use.insert(pid);
    const model::Part* part = find(parts, pid);
    if (!part) {
      unresolved.insert(pid);
      continue;
    }
    if (use.solids && use.shells) {
      p.bad(describe(part->src) + ": part " + std::to_string(pid) +
            " has both solid and shell elements; one part takes one section");
      unresolved.insert(pid);
      continue;
    }
    const model::Material* mat = find(mats, part->mid);
    if (!mat) {
      unresolved.insert(pid);
      continue;
    }
    int ihq = m.control_hourglass.ihq;
    if (part->hgid != 0) {
      const model::Hourglass* h = find(hgs, part->hgid);
      if (!h) {
        unresolved.insert(pid);
        continue;
      }
      ihq = h->ihq;
    }
    const model::Eos* eos = part->eosid != 0 ? model::find_eos(m.eos, part->eosid) : nullptr;
    if (part->eosid != 0 && !eos) {  // check_references names it
      unresolved.insert(pid);
      continue;
    }
    check_eos_use(*part, *mat, eos, use.solids, use.solids ? find(ssec, part->secid) : nullptr, ihq, p);
    const MaterialLaws laws = material_laws(*mat, m.curves, eos);
    const model::SectionShell* shell_sec = use.shells ? find(shsec, part->secid) : nullptr;
    if (laws.rigid) {
      rigid.insert(pid);
      check_rigid(std::get<model::MatRigid>(*mat), p);
      if (const model::SectionSolid* sec = use.solids ? find(ssec, part->secid) : nullptr; sec && sec->elform == 10)
        p.todo(describe(sec->src) + ": field ELFORM of *SECTION_SOLID: 10 (tetrahedra) in *MAT_RIGID part " +
               std::to_string(pid) + " is not implemented (rigid parts take hexahedra and shells)");
      if (use.triangle)
        p.todo(model::element_source(m, *use.triangle),
               "*ELEMENT_SHELL " + std::to_string(use.triangle->id) + " of rigid part " + std::to_string(pid) +
                   " is a triangle (N3 = N4): triangles in rigid parts are not implemented (deformable "
                   "shell parts run them as C0 triangles)");
      if (shell_sec) check_shell_section(*shell_sec, use.quads, p);
    } else if (use.shells) {
      check_shell_part(*part, shell_sec, use.quads, laws, ihq, p);
      // *CONTROL_SHELL ISTUPD: the blocks refuse what they cannot (enable_thickness_update); the
      // same refusals here, so that `blockcontact check` lists them with the others.
      if (m.shell_istupd != 0 && laws.shell) {
        const std::string at = describe(m.shell_istupd_src) + ": field ISTUPD of *CONTROL_SHELL: part " +
                               std::to_string(pid) + ": ";
        if (std::holds_alternative<NullShell>(*laws.shell))
          p.todo(at + "its material carries no stress, so the normal strain of plane stress is not defined: "
                      "*CONTROL_SHELL ISTUPD is not implemented on it");
        else if (m.shell_istupd == 4 && std::holds_alternative<ElasticShell>(*laws.shell))
          p.todo(at + "*CONTROL_SHELL ISTUPD = 4 (elastic strains left out) acts on elastic-plastic materials; "
                      "this part's is elastic");
      }
      if (use.triangle && m.shell_esort == 2)
        p.todo(describe(m.shell_esort_src) + ": field ESORT of *CONTROL_SHELL: 2 (DKT triangular shells) is not "
                                             "implemented, and part " + std::to_string(pid) + " has triangles (*ELEMENT_SHELL " +
               std::to_string(use.triangle->id) + ", N3 = N4): they run as C0 triangles (ESORT 1); give 0 or 1");
    } else {
      const model::SectionSolid* sec = find(ssec, part->secid);
      check_solid_part(*part, sec, laws, ihq, p);
      if (use.degenerate && m.solid_esort == 1 && sec && (sec->elform == 0 || sec->elform == 1 || sec->elform == 2))
        p.todo(describe(m.solid_esort_src) + ": field ESORT of *CONTROL_SOLID: 1 sorts degenerate solids into "
                                             "ELFORM 10 tetrahedra and ELFORM 15 pentahedra, which is not implemented "
                                             "for the solids of an ELFORM " + std::to_string(sec->elform == 0 ? 1 : sec->elform) +
               " section, and part " + std::to_string(pid) + " has one (*ELEMENT_SOLID " +
               std::to_string(use.degenerate->id) + ", repeated nodes); give 0 (collapsed hexahedra) or the "
               "tetrahedra an ELFORM 10 section");
    }
  }
  check_rigid_motions(m, in_use, rigid, unresolved, p);
  check_rigid_nodes(m, rigid, p);
}

}  // namespace slideline::validation
