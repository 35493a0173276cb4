#include "slideline/solver/build.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <unordered_map>

#include "slideline/core/error.hpp"
#include "slideline/element/hex_block.hpp"
#include "slideline/material/elastic.hpp"
#include "slideline/material/mooney_rivlin.hpp"

namespace slideline {

std::string describe(const model::Source& src) {
  if (src.line <= 0) return src.file.empty() ? "(generated)" : src.file;
  return (src.file.empty() ? std::string("deck") : src.file) + ":" + std::to_string(src.line);
}

namespace {

/// Id -> record lookups with errors that name the referring card.
template <class T>
class IdTable {
 public:
  IdTable(const std::vector<T>& items, Id (*key)(const T&), const char* what) : what_(what) {
    for (const auto& it : items) {
      const Id k = key(it);
      if (!map_.emplace(k, &it).second)
        throw InputError(describe(it.src) + ": duplicate " + what_ + " id " + std::to_string(k));
    }
  }
  const T& at(Id id, const model::Source& from, const char* field) const {
    const auto f = map_.find(id);
    if (f == map_.end())
      throw InputError(describe(from) + ": " + field + " refers to " + what_ + " " +
                       std::to_string(id) + ", which the deck does not define");
    return *f->second;
  }
  bool contains(Id id) const { return map_.count(id) != 0; }

 private:
  std::string what_;
  std::unordered_map<Id, const T*> map_;
};

LoadCurve make_curve(const model::Curve& c) {
  if (c.points.empty())
    throw InputError(describe(c.src) + ": *DEFINE_CURVE " + std::to_string(c.lcid) + " has no points");
  std::vector<std::pair<Real, Real>> pts;
  pts.reserve(c.points.size());
  const Real sfa = c.sfa == 0.0 ? 1.0 : c.sfa;
  const Real sfo = c.sfo == 0.0 ? 1.0 : c.sfo;
  for (const auto& [t, y] : c.points) pts.emplace_back(sfa * t + c.offa, sfo * y + c.offo);
  try {
    return LoadCurve(std::move(pts), "lcid " + std::to_string(c.lcid));
  } catch (const InputError& e) {
    throw InputError(describe(c.src) + ": " + e.what());
  }
}

struct Builder {
  Builder(const model::Model& model, const BuildOptions& options) : m(model), opt(options) {}
  const model::Model& m;
  const BuildOptions& opt;
  std::unique_ptr<Simulation> sim = std::make_unique<Simulation>();
  std::unordered_map<Id, Index> node_index;
  std::map<Id, LoadCurve> curves;
  std::map<Id, std::vector<Index>> part_nodes;  // unique nodes of each part

  Index node(Id id, const model::Source& src, const char* field) const {
    const auto f = node_index.find(id);
    if (f == node_index.end())
      throw InputError(describe(src) + ": " + field + " refers to node " + std::to_string(id) +
                       ", which the deck does not define");
    return f->second;
  }

  const LoadCurve& curve(Id lcid, const model::Source& src, const char* field) const {
    const auto f = curves.find(lcid);
    if (f == curves.end())
      throw InputError(describe(src) + ": " + field + " refers to curve " + std::to_string(lcid) +
                       ", which the deck does not define");
    return f->second;
  }

  void build_nodes() {
    const Index n = static_cast<Index>(m.nodes.size());
    sim->nodes.resize(n);
    for (Index i = 0; i < n; ++i) {
      const auto& nd = m.nodes[i];
      if (!node_index.emplace(nd.id, i).second)
        throw InputError("*NODE: duplicate node id " + std::to_string(nd.id));
      sim->nodes.ids[i] = nd.id;
      sim->nodes.x0.set(i, nd.x);
      sim->nodes.x.set(i, nd.x);
      if (nd.tc != 0 || nd.rc != 0)
        throw NotImplementedError("*NODE " + std::to_string(nd.id) +
                                  ": nodal constraint codes TC/RC are not supported yet; use "
                                  "*BOUNDARY_SPC_SET");
    }
  }

  void build_curves() {
    for (const auto& c : m.curves) {
      if (curves.count(c.lcid))
        throw InputError(describe(c.src) + ": duplicate curve id " + std::to_string(c.lcid));
      curves.emplace(c.lcid, make_curve(c));
    }
  }

  void build_elements() {
    const IdTable<model::Part> parts(m.parts, [](const model::Part& p) { return p.pid; }, "part");
    const IdTable<model::SectionSolid> ssec(
        m.solid_sections, [](const model::SectionSolid& s) { return s.secid; }, "*SECTION_SOLID");
    const IdTable<model::Hourglass> hgs(m.hourglasses, [](const model::Hourglass& h) { return h.hgid; },
                                        "*HOURGLASS");
    std::unordered_map<Id, const model::Material*> mats;
    for (const auto& mat : m.materials)
      if (!mats.emplace(model::material_id(mat), &mat).second)
        throw InputError("duplicate material id " + std::to_string(model::material_id(mat)));

    // Solids grouped by part, in deck order of first appearance.
    std::vector<Id> order;
    std::map<Id, std::pair<std::vector<Index>, std::vector<Id>>> by_part;
    for (const auto& e : m.solids) {
      model::Source src{"*ELEMENT_SOLID " + std::to_string(e.id), 0};
      auto& [conn, ids] = by_part[e.pid];
      if (ids.empty()) order.push_back(e.pid);
      for (Id nid : e.n) conn.push_back(node(nid, src, "a node field"));
      ids.push_back(e.id);
    }
    for (Id pid : order) {
      auto& [conn, ids] = by_part[pid];
      const model::Part& part =
          parts.at(pid, {"*ELEMENT_SOLID " + std::to_string(ids.front()), 0}, "PID");
      const auto& sec = ssec.at(part.secid, part.src, "SECID of *PART");
      if (sec.elform != 1 && sec.elform != 0)
        throw NotImplementedError(describe(sec.src) + ": *SECTION_SOLID ELFORM " +
                                  std::to_string(sec.elform) +
                                  " is not implemented (only 1, the one-point hexahedron)");
      const auto mit = mats.find(part.mid);
      if (mit == mats.end())
        throw InputError(describe(part.src) + ": MID of *PART " + std::to_string(pid) +
                         " refers to material " + std::to_string(part.mid) +
                         ", which the deck does not define");
      HexHourglass hg;
      BulkViscosity bv{m.bulk_viscosity.q1, m.bulk_viscosity.q2};
      int ihq = m.control_hourglass.ihq;
      Real qm = m.control_hourglass.qh;
      if (part.hgid != 0) {
        const auto& h = hgs.at(part.hgid, part.src, "HGID of *PART");
        ihq = h.ihq;
        qm = h.qm;
        bv = {h.q1, h.q2};
      }
      if (ihq == 0 || ihq == 1 || ihq == 2 || ihq == 3) {
        hg.kind = HexHourglass::Kind::viscous;
      } else if (ihq == 10) {
        hg.kind = HexHourglass::Kind::physical_stiffness;
      } else {
        throw NotImplementedError(describe(part.src) + ": hourglass type IHQ=" + std::to_string(ihq) +
                                  " of part " + std::to_string(pid) +
                                  " is not implemented (use 1-3 viscous or 10 physical stiffness)");
      }
      hg.coefficient = qm;
      std::vector<Index> pn(conn);
      std::sort(pn.begin(), pn.end());
      pn.erase(std::unique(pn.begin(), pn.end()), pn.end());
      part_nodes[pid] = pn;
      std::visit(
          [&](const auto& mat) {
            using T = std::decay_t<decltype(mat)>;
            if constexpr (std::is_same_v<T, model::MatMooneyRivlin>) {
              check_positive(mat.ro, "RO", mat.src);
              sim->blocks.push_back(std::make_unique<HexBlock<MooneyRivlin>>(
                  pid, MooneyRivlin(mat.ro, mat.a, mat.b, mat.pr), hg, bv, std::move(conn),
                  std::move(ids)));
            } else if constexpr (std::is_same_v<T, model::MatElastic>) {
              check_positive(mat.ro, "RO", mat.src);
              check_positive(mat.e, "E", mat.src);
              sim->blocks.push_back(std::make_unique<HexBlock<ElasticSolid>>(
                  pid, ElasticSolid(mat.ro, mat.e, mat.pr), hg, bv, std::move(conn), std::move(ids)));
            } else {
              throw NotImplementedError(describe(mat.src) + ": *MAT_RIGID (part " +
                                        std::to_string(pid) + ") is not implemented yet");
            }
          },
          *mit->second);
    }
    if (!m.shells.empty())
      throw NotImplementedError("*ELEMENT_SHELL (element " + std::to_string(m.shells.front().id) +
                                "): shell elements are not implemented yet");
  }

  static void check_positive(Real v, const char* field, const model::Source& src) {
    if (!(v > 0.0))
      throw InputError(describe(src) + ": field " + field + " must be positive (got " +
                       std::to_string(v) + ")");
  }

  std::vector<Index> node_set(Id sid, const model::Source& from, const char* field) const {
    for (const auto& s : m.node_sets)
      if (s.sid == sid) {
        std::vector<Index> out;
        for (Id nid : s.nodes) out.push_back(node(nid, s.src, "*SET_NODE_LIST"));
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
        return out;
      }
    throw InputError(describe(from) + ": " + field + " refers to node set " + std::to_string(sid) +
                     ", which the deck does not define");
  }

  std::vector<Index> parts_nodes(const std::vector<Id>& pids, const model::Source& from) const {
    std::set<Index> all;
    for (Id pid : pids) {
      const auto f = part_nodes.find(pid);
      if (f == part_nodes.end())
        throw InputError(describe(from) + ": refers to part " + std::to_string(pid) +
                         ", which has no elements in the deck");
      all.insert(f->second.begin(), f->second.end());
    }
    return {all.begin(), all.end()};
  }

  std::vector<Id> part_set(Id sid, const model::Source& from, const char* field) const {
    for (const auto& s : m.part_sets)
      if (s.sid == sid) return s.parts;
    throw InputError(describe(from) + ": " + field + " refers to part set " + std::to_string(sid) +
                     ", which the deck does not define");
  }

  void build_boundaries() {
    for (const auto& spc : m.spcs) {
      if (spc.cid != 0)
        throw NotImplementedError(describe(spc.src) +
                                  ": *BOUNDARY_SPC_SET with a local coordinate system (CID) is not "
                                  "implemented");
      SupportGroup g;
      g.name = !spc.title.empty() ? spc.title
                                  : "spc_" + std::to_string(spc.id != 0 ? spc.id : spc.nsid);
      const auto nodes = node_set(spc.nsid, spc.src, "NSID");
      for (int d = 0; d < 6; ++d) {
        if (spc.dof[d] == 0) continue;
        if (spc.dof[d] != 1)
          throw InputError(describe(spc.src) + ": DOF flags of *BOUNDARY_SPC_SET must be 0 or 1");
        Support s;
        s.axis = static_cast<Axis>(d % 3);
        s.rotational = d >= 3;
        s.nodes = nodes;
        g.supports.push_back(std::move(s));
      }
      sim->supports.push_back(std::move(g));
    }
    for (const auto& pm : m.prescribed_motions) {
      if (pm.vad != 2 || pm.dof < 1 || pm.dof > 3)
        throw NotImplementedError(
            describe(pm.src) +
            ": *BOUNDARY_PRESCRIBED_MOTION_SET is implemented for displacements (VAD=2) of "
            "translations (DOF 1-3) only");
      SupportGroup g;
      g.name = !pm.title.empty() ? pm.title
                                 : "motion_" + std::to_string(pm.id != 0 ? pm.id : pm.nsid);
      Support s;
      s.axis = static_cast<Axis>(pm.dof - 1);
      s.nodes = node_set(pm.nsid, pm.src, "NSID");
      s.has_curve = true;
      s.curve = curve(pm.lcid, pm.src, "LCID");
      s.scale = pm.sf;
      g.supports.push_back(std::move(s));
      sim->supports.push_back(std::move(g));
    }
  }

  void build_loads() {
    std::vector<Id> loaded;  // empty = all parts
    if (m.body_load_parts) {
      loaded = part_set(m.body_load_parts->psid, m.body_load_parts->src, "PSID");
      parts_nodes(loaded, m.body_load_parts->src);  // checks that every part exists
    }
    for (const auto& lb : m.body_loads) {
      if (lb.lciddr != 0 || lb.cid != 0)
        throw NotImplementedError(describe(lb.src) +
                                  ": *LOAD_BODY with LCIDDR or CID is not implemented");
      BodyLoad b;
      b.axis = lb.axis;
      // LS-DYNA body loads are base accelerations: the inertial force opposes them.
      b.scale = -lb.sf;
      b.curve = curve(lb.lcid, lb.src, "LCID");
      b.parts = loaded;
      sim->body_loads.push_back(std::move(b));
    }
  }

  void build_damping() {
    if (m.damping_global) {
      const auto& d = *m.damping_global;
      MassDamping md;
      if (d.lcid != 0) {
        md.alpha = 1.0;
        md.has_curve = true;
        md.curve = curve(d.lcid, d.src, "LCID");
      } else {
        md.alpha = d.valdmp;
      }
      for (Real s : d.stf)
        if (s != 0.0 && s != 1.0)
          throw NotImplementedError(describe(d.src) +
                                    ": per-direction damping scale factors STX..SRZ are not "
                                    "implemented");
      sim->damping.push_back(std::move(md));
    }
    for (const auto& d : m.damping_parts) {
      MassDamping md;
      md.alpha = d.sf;
      md.has_curve = true;
      md.curve = curve(d.lcid, d.src, "LCID");
      md.nodes = d.flag == 1 ? parts_nodes(part_set(d.pid, d.src, "PSID"), d.src)
                             : parts_nodes({d.pid}, d.src);
      sim->damping.push_back(std::move(md));
    }
  }

  void build_controls() {
    auto& c = sim->controls;
    c.end_time = opt.end_time > 0.0 ? opt.end_time : m.termination.endtim;
    c.max_cycles = m.termination.endcyc;
    if (!(c.end_time > 0.0) && c.max_cycles <= 0)
      throw InputError("*CONTROL_TERMINATION: ENDTIM must be positive (got " +
                       std::to_string(m.termination.endtim) + ")");
    c.dt_scale = m.timestep.tssfac > 0.0 ? m.timestep.tssfac : 0.9;
    Real hi = 0.0;
    for (Real v : {m.database.rcforc, m.database.spcforc, m.database.nodout, m.database.glstat})
      if (v > 0.0) hi = hi > 0.0 ? std::min(hi, v) : v;
    c.history_interval = hi;
    c.state_interval = m.database.d3plot;
    for (Id nid : m.database.history_nodes)
      sim->history_nodes.push_back(node(nid, {"*DATABASE_HISTORY_NODE", 0}, "NID"));
  }

  void build_contacts() {
    if (!m.contacts.empty()) {
      const auto& c = m.contacts.front();
      throw NotImplementedError(describe(c.src) + ": " +
                                (c.keyword.empty() ? std::string("*CONTACT") : c.keyword) +
                                " (DYNA3D type " + std::to_string(static_cast<int>(c.type)) +
                                ") is not implemented yet");
    }
  }
};

}  // namespace

std::unique_ptr<Simulation> build_simulation(const model::Model& model, const BuildOptions& options) {
  Builder b(model, options);
  b.build_nodes();
  b.build_curves();
  b.build_elements();
  b.build_boundaries();
  b.build_loads();
  b.build_damping();
  b.build_controls();
  b.build_contacts();
  return std::move(b.sim);
}

}  // namespace slideline
