// check_references: dangling and duplicate ids of a model, each named with its card and line
// (the validation layer, solver/validate_model.hpp).
#include <string>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

#include "issue_groups.hpp"
#include "slideline/model/unsupported.hpp"
#include "slideline/solver/validate_model.hpp"

namespace slideline {
namespace {

using IdSet = std::unordered_set<Id>;

struct Checker {
  std::vector<Diagnostic> out;

  void add(const model::Source& src, std::string message) {
    out.push_back({src.file, src.line, std::move(message)});
  }

  /// Collects ids; reports duplicates.
  template <class Range, class GetId, class GetSrc>
  IdSet collect(const Range& items, const char* what, GetId id_of, GetSrc src_of) {
    IdSet ids;
    for (const auto& it : items) {
      const Id id = id_of(it);
      if (!ids.insert(id).second) add(src_of(it), std::string(what) + " " + std::to_string(id) + " is defined more than once");
    }
    return ids;
  }
};

/// The reference check, phase by phase (the order of the phases is the order of the messages).
class References {
 public:
  explicit References(const model::Model& model) : m_(model) {}

  std::vector<Diagnostic> run() {
    collect_ids();
    check_elements();
    check_parts_and_sets();
    check_boundaries_and_loads();
    check_damping();
    check_initial_velocities();
    check_contacts();
    return std::move(ck_.out);
  }

 private:
  const model::Model& m_;
  Checker ck_;
  IdSet nodes_, parts_, sections_, materials_, eos_, hourglasses_, node_sets_, segment_sets_, part_sets_, curves_, boxes_;

  /// Every id each card kind defines; duplicates reported.
  void collect_ids() {
    const auto no_src = [](const auto&) { return model::Source{}; };
    nodes_ = ck_.collect(m_.nodes, "node", [](const auto& n) { return n.id; }, no_src);
    ck_.collect(m_.solids, "solid element", [](const auto& e) { return e.id; }, [&](const auto& e) { return model::element_source(m_, e); });
    ck_.collect(m_.shells, "shell element", [](const auto& e) { return e.id; }, [&](const auto& e) { return model::element_source(m_, e); });
    parts_ = ck_.collect(m_.parts, "part", [](const auto& p) { return p.pid; }, [](const auto& p) { return p.src; });
    sections_ = ck_.collect(m_.solid_sections, "section", [](const auto& s) { return s.secid; }, [](const auto& s) { return s.src; });
    for (const auto& s : m_.shell_sections)
      if (!sections_.insert(s.secid).second) ck_.add(s.src, "section " + std::to_string(s.secid) + " is defined more than once");
    for (const auto& mat : m_.materials) {
      const Id mid = model::material_id(mat);
      const auto src = std::visit([](const auto& mm) { return mm.src; }, mat);
      if (!materials_.insert(mid).second) ck_.add(src, "material " + std::to_string(mid) + " is defined more than once");
    }
    for (const auto& e : m_.eos) {
      const auto src = std::visit([](const auto& x) { return x.src; }, e);
      if (!eos_.insert(model::eos_id(e)).second)
        ck_.add(src, "equation of state " + std::to_string(model::eos_id(e)) + " is defined more than once");
    }
    hourglasses_ = ck_.collect(m_.hourglasses, "hourglass", [](const auto& h) { return h.hgid; }, [](const auto& h) { return h.src; });
    node_sets_ = ck_.collect(m_.node_sets, "node set", [](const auto& s) { return s.sid; }, [](const auto& s) { return s.src; });
    segment_sets_ = ck_.collect(m_.segment_sets, "segment set", [](const auto& s) { return s.sid; }, [](const auto& s) { return s.src; });
    part_sets_ = ck_.collect(m_.part_sets, "part set", [](const auto& s) { return s.sid; }, [](const auto& s) { return s.src; });
    curves_ = ck_.collect(m_.curves, "curve", [](const auto& c) { return c.lcid; }, [](const auto& c) { return c.src; });
    boxes_ = ck_.collect(m_.boxes, "box", [](const auto& b) { return b.boxid; }, [](const auto& b) { return b.src; });
  }

  /// Elements -> parts and nodes, collapsed over elements.
  void check_elements() {
    IssueGroups element_issues;
    const auto check_element = [&](const auto& e, const char* keyword) {
      const model::Source src = model::element_source(m_, e);
      const std::string who = std::string(keyword) + " " + std::to_string(e.id);
      if (!parts_.count(e.pid)) {
        const std::string what = "refers to undefined part " + std::to_string(e.pid);
        element_issues.add(std::string(keyword) + " " + what, who + " " + what, std::to_string(e.id), src);
      }
      // A 4-node tetrahedron written with N5..N8 blank: validate_model names the element kind.
      bool tet = false;
      if constexpr (std::tuple_size_v<decltype(e.n)> == 8)
        tet = e.n[4] == 0 && e.n[5] == 0 && e.n[6] == 0 && e.n[7] == 0 && e.n[3] != 0;
      for (Id n : e.n)
        if (!nodes_.count(n) && !(tet && n == 0)) {
          std::string what = "refers to undefined node " + std::to_string(n);
          if (n == 0) what += " (a blank node field)";
          element_issues.add(std::string(keyword) + " refers to undefined nodes", who + " " + what,
                             std::to_string(e.id) + " -> " + std::to_string(n), src, "references (element -> node)");
        }
    };
    for (const auto& e : m_.solids) check_element(e, "*ELEMENT_SOLID");
    for (const auto& e : m_.shells) check_element(e, "*ELEMENT_SHELL");
    element_issues.append_to(ck_.out);
  }

  /// A reference to an id that only an unsupported (dropped) card defines names that card.
  bool dropped(const model::Source& from, const std::string& who, std::string_view kind, Id id) {
    if (const auto* u = model::find_unsupported(m_, kind, id)) {
      ck_.add(from, who + " uses " + model::card_and_place(*u, from.file) + ", not supported");
      return true;
    }
    return false;
  }

  /// Parts -> sections, materials, hourglass cards; sets -> nodes and parts.
  void check_parts_and_sets() {
    for (const auto& p : m_.parts) {
      const std::string who = "*PART " + std::to_string(p.pid);
      const std::string part = "part " + std::to_string(p.pid);
      if (!sections_.count(p.secid) && !dropped(p.src, part, "section", p.secid))
        ck_.add(p.src, who + " refers to undefined section " + std::to_string(p.secid));
      if (!materials_.count(p.mid) && !dropped(p.src, part, "material", p.mid))
        ck_.add(p.src, who + " refers to undefined material " + std::to_string(p.mid));
      if (p.hgid != 0 && !hourglasses_.count(p.hgid) && !dropped(p.src, part, "hourglass", p.hgid))
        ck_.add(p.src, who + " refers to undefined hourglass " + std::to_string(p.hgid));
      if (p.eosid != 0 && !eos_.count(p.eosid) && !dropped(p.src, part, "equation of state", p.eosid))
        ck_.add(p.src, who + " refers to undefined equation of state " + std::to_string(p.eosid));
    }
    for (const auto& s : m_.node_sets)
      for (Id n : s.nodes)
        if (!nodes_.count(n))
          ck_.add(s.src, "*SET_NODE_LIST " + std::to_string(s.sid) + " refers to undefined node " + std::to_string(n));
    for (const auto& s : m_.segment_sets)
      for (const auto& seg : s.segments)
        for (Id n : seg)
          if (!nodes_.count(n))
            ck_.add(s.src, "*SET_SEGMENT " + std::to_string(s.sid) + " refers to undefined node " + std::to_string(n));
    for (const auto& s : m_.part_sets)
      for (Id p : s.parts)
        if (!parts_.count(p))
          ck_.add(s.src, "*SET_PART_LIST " + std::to_string(s.sid) + " refers to undefined part " + std::to_string(p));
  }

  /// Supports, prescribed motions and loads -> nodes, sets, parts and curves.
  void check_boundaries_and_loads() {
    for (const auto& s : m_.spcs) {
      if (s.node && !nodes_.count(s.nsid))
        ck_.add(s.src, "*BOUNDARY_SPC_NODE refers to undefined node " + std::to_string(s.nsid));
      if (!s.node && !node_sets_.count(s.nsid) && !dropped(s.src, "*BOUNDARY_SPC_SET", "node set", s.nsid))
        ck_.add(s.src, "*BOUNDARY_SPC_SET refers to undefined node set " + std::to_string(s.nsid));
    }
    for (const auto& l : m_.nodal_loads) {
      if (l.set && !node_sets_.count(l.id) && !dropped(l.src, "*LOAD_NODE_SET", "node set", l.id))
        ck_.add(l.src, "*LOAD_NODE_SET refers to undefined node set " + std::to_string(l.id));
      if (!l.set && !nodes_.count(l.id))
        ck_.add(l.src, "*LOAD_NODE_POINT refers to undefined node " + std::to_string(l.id));
      if (!curves_.count(l.lcid))
        ck_.add(l.src, std::string(l.set ? "*LOAD_NODE_SET" : "*LOAD_NODE_POINT") + " refers to undefined curve " +
                          std::to_string(l.lcid));
    }
    for (const auto& p : m_.prescribed_motions) {
      using Target = model::PrescribedMotion::Target;
      const std::string card = p.keyword();
      const char* what = p.target == Target::set ? "node set" : p.target == Target::node ? "node" : "part";
      const bool defined = p.target == Target::set    ? node_sets_.count(p.nsid) != 0
                           : p.target == Target::node ? nodes_.count(p.nsid) != 0
                                                      : parts_.count(p.nsid) != 0;
      if (!defined && !dropped(p.src, card, what, p.nsid))
        ck_.add(p.src, card + " refers to undefined " + what + " " + std::to_string(p.nsid));
      if (!curves_.count(p.lcid) && !dropped(p.src, card, "curve", p.lcid))
        ck_.add(p.src, card + " refers to undefined curve " + std::to_string(p.lcid));
    }
    for (const auto& l : m_.body_loads)
      if (!curves_.count(l.lcid))
        ck_.add(l.src, std::string("*LOAD_BODY_") + (l.axis == Axis::x ? "X" : l.axis == Axis::y ? "Y" : "Z") +
                          " refers to undefined curve " + std::to_string(l.lcid));
    if (m_.body_load_parts && !part_sets_.count(m_.body_load_parts->psid))
      ck_.add(m_.body_load_parts->src, "*LOAD_BODY_PARTS refers to undefined part set " + std::to_string(m_.body_load_parts->psid));
  }

  /// Damping cards -> curves, parts and part sets.
  void check_damping() {
    if (m_.damping_global && m_.damping_global->lcid != 0 && !curves_.count(m_.damping_global->lcid))
      ck_.add(m_.damping_global->src, "*DAMPING_GLOBAL refers to undefined curve " + std::to_string(m_.damping_global->lcid));
    for (const auto& d : m_.damping_parts) {
      if (d.set && !part_sets_.count(d.pid))
        ck_.add(d.src, "*DAMPING_PART_MASS_SET refers to undefined part set " + std::to_string(d.pid));
      if (!d.set && !parts_.count(d.pid))
        ck_.add(d.src, "*DAMPING_PART_MASS refers to undefined part " + std::to_string(d.pid));
      if (!curves_.count(d.lcid)) ck_.add(d.src, "*DAMPING_PART_MASS refers to undefined curve " + std::to_string(d.lcid));
    }
    for (const auto& d : m_.damping_stiffness) {
      if (d.set && !part_sets_.count(d.pid))
        ck_.add(d.src, "*DAMPING_PART_STIFFNESS_SET refers to undefined part set " + std::to_string(d.pid));
      if (!d.set && !parts_.count(d.pid))
        ck_.add(d.src, "*DAMPING_PART_STIFFNESS refers to undefined part " + std::to_string(d.pid));
    }
  }

  /// Initial velocities -> sets, boxes and nodes (0 = all nodes for NSID and ID); history nodes.
  void check_initial_velocities() {
    // Initial velocities: sets, boxes and nodes (0 = all nodes for NSID and ID).
    for (const auto& iv : m_.initial_velocities) {
      const model::Source src = model::element_source(m_, iv);
      const auto set = [&](Id sid, const char* field) {
        if (sid != 0 && !node_sets_.count(sid) && !dropped(src, "*INITIAL_VELOCITY", "node set", sid))
          ck_.add(src, std::string("*INITIAL_VELOCITY ") + field + " refers to undefined node set " + std::to_string(sid));
      };
      set(iv.nsid, "NSID");
      set(iv.nsidex, "NSIDEX");
      if (iv.boxid != 0 && !boxes_.count(iv.boxid))
        ck_.add(src, "*INITIAL_VELOCITY BOXID refers to undefined box " + std::to_string(iv.boxid));
    }
    for (const auto& g : m_.initial_velocity_generations) {
      if (g.id == 0) continue;
      const model::Source src = model::element_source(m_, g);
      const std::string who = "*INITIAL_VELOCITY_GENERATION ID";
      if (g.styp == 1 && !part_sets_.count(g.id) && !dropped(src, who, "part set", g.id))
        ck_.add(src, who + " refers to undefined part set " + std::to_string(g.id));
      if (g.styp == 2 && !parts_.count(g.id))
        ck_.add(src, who + " refers to undefined part " + std::to_string(g.id));
      if (g.styp == 3 && !node_sets_.count(g.id) && !dropped(src, who, "node set", g.id))
        ck_.add(src, who + " refers to undefined node set " + std::to_string(g.id));
    }
    for (const auto& iv : m_.initial_velocity_nodes)
      if (!nodes_.count(iv.nid))
        ck_.add(model::element_source(m_, iv), "*INITIAL_VELOCITY_NODE refers to undefined node " + std::to_string(iv.nid));
    for (Id n : m_.database.history_nodes)
      if (!nodes_.count(n)) ck_.add(model::Source{}, "*DATABASE_HISTORY_NODE refers to undefined node " + std::to_string(n));
  }

  /// Contact sides (SSTYP/MSTYP) and boxes.
  void check_contacts() {
    // Contact sides: SSTYP/MSTYP 0 segment set, 2 part set, 3 part, 4 node set, 5 all parts.
    const auto check_side = [&](const model::Contact& c, const char* side, Id id, int type) {
      const std::string who = c.keyword.empty() ? std::string("*CONTACT") : c.keyword;
      const auto missing = [&](const char* what) {
        ck_.add(c.src, who + " " + side + " refers to undefined " + what + " " + std::to_string(id));
      };
      switch (type) {
        case 0: if (!segment_sets_.count(id)) missing("segment set"); break;
        case 2: if (!part_sets_.count(id)) missing("part set"); break;
        case 3: if (!parts_.count(id)) missing("part"); break;
        case 4: if (!node_sets_.count(id)) missing("node set"); break;
        case 5: break;
        default:
          ck_.add(c.src, who + " " + side + ": set type " + std::to_string(type) + " is not supported");
      }
    };
    for (const auto& c : m_.contacts) {
      check_side(c, "SSID", c.ssid, c.sstyp);
      // A single-surface card (type 12 as DYNA3D spells it) has no master side; a force
      // transducer's is optional (MSID = 0).
      const bool optional_master = c.form == model::ContactForm::force_transducer && c.msid == 0;
      if ((c.type != model::ContactType::automatic || c.form != model::ContactForm::dyna3d) && !optional_master)
        check_side(c, "MSID", c.msid, c.mstyp);
      const std::string who = c.keyword.empty() ? std::string("*CONTACT") : c.keyword;
      if (c.sboxid != 0 && !boxes_.count(c.sboxid))
        ck_.add(c.src, who + " SBOXID refers to undefined box " + std::to_string(c.sboxid));
      if (c.mboxid != 0 && !boxes_.count(c.mboxid))
        ck_.add(c.src, who + " MBOXID refers to undefined box " + std::to_string(c.mboxid));
    }
  }
};

}  // namespace

std::vector<Diagnostic> check_references(const model::Model& m) {
  // Without nodes or elements every other reference problem is a consequence: say only that.
  if (m.nodes.empty() || (m.solids.empty() && m.shells.empty())) {
    std::vector<Diagnostic> out;
    add_empty_model_problems(m, "the deck defines no", out);
    return out;
  }
  return References(m).run();
}

}  // namespace slideline
