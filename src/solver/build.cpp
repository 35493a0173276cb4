#include "slideline/solver/build.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <unordered_map>
#include <utility>
#include <vector>

#include "slideline/contact/make_contact_interface.hpp"
#include "slideline/core/error.hpp"
#include "slideline/core/overloaded.hpp"
#include "slideline/core/source_location.hpp"
#include "slideline/element/block_factory.hpp"
#include "slideline/solver/held_axes.hpp"
#include "slideline/solver/material_registry.hpp"
#include "slideline/solver/rigid_body.hpp"
#include "slideline/solver/validate_model.hpp"
#include "build_support.hpp"
#include "erosion_setup.hpp"
#include "slideline/solver/coordinate_axes.hpp"
#include "initial_velocity.hpp"

namespace slideline {

std::string describe(const model::Source& src) { return describe_location(src.file, src.line); }

namespace {

struct Builder {
  Builder(const model::Model& model, const BuildOptions& options) : m(model), opt(options) {}
  const model::Model& m;
  const BuildOptions& opt;
  SimulationSetup setup;
  std::unordered_map<Id, Index> node_index;
  std::map<Id, LoadCurve> curves;
  std::map<Id, std::vector<Index>> part_nodes;  // unique nodes of each part
  std::unordered_map<Index, Id> rigid_node_part;  // node -> the rigid part that moves it
  std::map<Id, RigidBody*> rigid_bodies;          // part id -> its body (owned by setup.constraints)

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
    setup.nodes.resize(n);
    for (Index i = 0; i < n; ++i) {
      const auto& nd = m.nodes[i];
      if (!node_index.emplace(nd.id, i).second)
        throw InputError("*NODE: duplicate node id " + std::to_string(nd.id));
      setup.nodes.ids[i] = nd.id;
      setup.nodes.x0.set(i, nd.x);
      setup.nodes.x.set(i, nd.x);
    }
  }

  void build_curves() {
    for (const auto& c : m.curves) {
      if (curves.count(c.lcid))
        throw InputError(describe(c.src) + ": duplicate curve id " + std::to_string(c.lcid));
      curves.emplace(c.lcid, make_curve(c));
    }
  }

  /// Elements of one part, in deck order.
  struct PartElements {
    std::vector<Index> hex_conn, quad_conn;
    std::vector<Id> hex_ids, quad_ids;
  };

  void build_elements() {
    const IdTable<model::Part> parts(m.parts, [](const model::Part& p) { return p.pid; }, "part");
    const IdTable<model::SectionSolid> ssec(
        m.solid_sections, [](const model::SectionSolid& s) { return s.secid; }, "*SECTION_SOLID");
    const IdTable<model::SectionShell> shsec(
        m.shell_sections, [](const model::SectionShell& s) { return s.secid; }, "*SECTION_SHELL");
    const IdTable<model::Hourglass> hgs(m.hourglasses, [](const model::Hourglass& h) { return h.hgid; },
                                        "*HOURGLASS");
    const std::map<Id, StiffnessDamping> damped = stiffness_damping(m, parts);
    std::unordered_map<Id, const model::Material*> mats;
    for (const auto& mat : m.materials)
      if (!mats.emplace(model::material_id(mat), &mat).second)
        throw InputError("duplicate material id " + std::to_string(model::material_id(mat)));
    const auto add_erosions = add_erosions_by_material(m, mats);

    std::vector<Id> order;
    std::map<Id, PartElements> by_part;
    group_elements_by_part(order, by_part);

    for (Id pid : order) {
      PartElements& g = by_part[pid];
      const Id first_id = g.hex_ids.empty() ? g.quad_ids.front() : g.hex_ids.front();
      const model::Part& part = parts.at(
          pid, {(g.hex_ids.empty() ? "*ELEMENT_SHELL " : "*ELEMENT_SOLID ") + std::to_string(first_id), 0},
          "PID");
      const auto mit = mats.find(part.mid);
      if (mit == mats.end())
        throw InputError(describe(part.src) + ": MID of *PART " + std::to_string(pid) +
                         " refers to material " + std::to_string(part.mid) +
                         ", which the deck does not define");
      std::vector<Index> pn(g.hex_conn);
      pn.insert(pn.end(), g.quad_conn.begin(), g.quad_conn.end());
      std::sort(pn.begin(), pn.end());
      pn.erase(std::unique(pn.begin(), pn.end()), pn.end());
      part_nodes[pid] = pn;

      // Hourglass and bulk viscosity: the part's *HOURGLASS, else the controls.
      BulkViscosity bv{m.bulk_viscosity.q1, m.bulk_viscosity.q2};
      int ihq = m.control_hourglass.ihq;
      Real qm = m.control_hourglass.qh;
      if (part.hgid != 0) {
        const auto& h = hgs.at(part.hgid, part.src, "HGID of *PART");
        ihq = h.ihq;
        qm = h.qm;
        bv = {h.q1, h.q2};
      }

      // Stiffness damping has nothing to act on in a rigid part: build_rigid_part does not take it.
      const model::Eos* eos = part.eosid != 0 ? model::find_eos(m.eos, part.eosid) : nullptr;
      if (part.eosid != 0 && !eos)
        throw InputError(describe(part.src) + ": *PART " + std::to_string(pid) + " refers to undefined equation of state " +
                         std::to_string(part.eosid));
      const MaterialLaws laws = material_laws(*mit->second, m.curves, eos);
      const std::size_t first_block = setup.blocks.size();
      const auto dit = damped.find(pid);
      const StiffnessDamping damping = dit == damped.end() ? StiffnessDamping{} : dit->second;
      if (laws.rigid)
        build_rigid_part(part, std::get<model::MatRigid>(*mit->second), g, pn, shsec);
      else if (!g.quad_ids.empty())
        build_shell_part(part, laws, g, shsec, ihq, qm, bv, damping);
      else
        build_solid_part(part, laws, g, ssec.at(part.secid, part.src, "SECID of *PART"), ihq, qm, bv, damping);
      for (std::size_t b = first_block; b < setup.blocks.size(); ++b) setup.blocks[b]->set_material_id(part.mid);
      const auto ait = add_erosions.find(part.mid);
      const model::MatAddErosion* add = ait == add_erosions.end() ? nullptr : ait->second;
      if (!laws.rigid) enable_erosion(part, laws, add, first_block, g.quad_ids.empty() && m.timestep.erode == 1);
    }
  }

  /// Element erosion of the part's blocks from `first_block` on (element/element_erosion.hpp), when
  /// its material or a *MAT_ADD_EROSION of it sets a criterion (erosion_setup.hpp); a block that
  /// cannot erode so refuses, named by the part and what sets the criterion.
  void enable_erosion(const model::Part& part, const MaterialLaws& laws, const model::MatAddErosion* add,
                      std::size_t first_block, bool erode_below_tsmin) {
    ErosionCriteria k = erosion_criteria(laws, add);
    k.erode_below_tsmin = erode_below_tsmin;
    if (!k.any()) return;
    for (std::size_t b = first_block; b < setup.blocks.size(); ++b) {
      try {
        setup.blocks[b]->enable_erosion(k);
      } catch (const Error& e) {
        const std::string what = describe(part.src) + ": *PART " + std::to_string(part.pid) + ": material " +
                                 std::to_string(part.mid) + " (" + laws.keyword + ") erodes by " +
                                 erosion_description(laws, add) + ": " + e.what();
        if (dynamic_cast<const NotImplementedError*>(&e)) throw NotImplementedError(what);
        throw InputError(what);
      }
    }
  }

  /// Elements grouped by part (connectivity as internal node indices), parts in order of first
  /// appearance.
  void group_elements_by_part(std::vector<Id>& order, std::map<Id, PartElements>& by_part) const {
    auto group = [&](Id pid) -> PartElements& {
      auto [it, fresh] = by_part.try_emplace(pid);
      if (fresh) order.push_back(pid);
      return it->second;
    };
    for (const auto& e : m.solids) {
      const model::Source src{"*ELEMENT_SOLID " + std::to_string(e.id), 0};
      auto& g = group(e.pid);
      // A tetrahedron may leave N5-N8 blank: they stand for N4 (LS-DYNA's degenerate form).
      const bool tail_blank = e.n[4] == 0 && e.n[5] == 0 && e.n[6] == 0 && e.n[7] == 0;
      for (std::size_t k = 0; k < 8; ++k)
        g.hex_conn.push_back(node(tail_blank && k >= 4 ? e.n[3] : e.n[k], src, "a node field"));
      g.hex_ids.push_back(e.id);
    }
    for (const auto& e : m.shells) {
      const model::Source src{"*ELEMENT_SHELL " + std::to_string(e.id), 0};
      auto& g = group(e.pid);
      for (Id nid : e.n) g.quad_conn.push_back(node(nid, src, "a node field"));
      g.quad_ids.push_back(e.id);
    }
  }

  /// A deformable part of solids: its section, hourglass type and law, into one block: HexBlock
  /// (ELFORM 1, the default), FullHexBlock (ELFORM 2) or TetBlock (ELFORM 10: validate_model
  /// checked that every element of the part is a tetrahedron N1 N2 N3 N4 N4 N4 N4 N4, and that no
  /// other form reaches here).
  void build_solid_part(const model::Part& part, const MaterialLaws& laws, PartElements& g,
                        const model::SectionSolid& sec, int ihq, Real qm, BulkViscosity bv,
                        StiffnessDamping damping) {
    const Id pid = part.pid;
    if (sec.elform == 10) {
      std::vector<Index> tets;
      tets.reserve(g.hex_conn.size() / 2);
      for (std::size_t e = 0; e < g.hex_ids.size(); ++e)
        tets.insert(tets.end(), g.hex_conn.begin() + 8 * e, g.hex_conn.begin() + 8 * e + 4);
      setup.blocks.push_back(make_tet_block(pid, *laws.solid, bv, std::move(tets), std::move(g.hex_ids), damping));
      return;
    }
    if (sec.elform == 2) {
      setup.blocks.push_back(
          make_full_hex_block(pid, *laws.solid, bv, std::move(g.hex_conn), std::move(g.hex_ids), damping));
      return;
    }
    const HexHourglass hg = hex_hourglass(ihq, qm);
    setup.blocks.push_back(make_hex_block(pid, *laws.solid, hg, bv, std::move(g.hex_conn),
                                         std::move(g.hex_ids), damping));
  }


  template <class Sections>
  const model::SectionShell& shell_section(const model::Part& part, const Sections& shsec) const {
    return shsec.at(part.secid, part.src, "SECID of *PART");
  }

  template <class Sections>
  void build_shell_part(const model::Part& part, const MaterialLaws& laws, PartElements& g,
                        const Sections& shsec, int ihq, Real qm, const BulkViscosity& bv, StiffnessDamping damping) {
    const auto& sec = shell_section(part, shsec);
    ShellSection ss;
    ss.thickness = sec.t[0];
    ss.nip = shell_nip(sec);
    // *CONTROL_SHELL INTGRD = 1: Gauss-Lobatto; one point is the mid surface in either rule.
    ss.rule = m.shell_intgrd == 1 && ss.nip > 1 ? shell_bt::ThicknessRuleKind::lobatto
                                                    : shell_bt::ThicknessRuleKind::gauss;
    ss.shear_factor = sec.shrf == 0.0 ? 1.0 : sec.shrf;
    // *CONTROL_ACCURACY INN = +-2, +-4: the quadrilaterals' frame invariant under renumbering;
    // 2 and 4 the triangles' too (LS-DYNA's negative values leave triangles with side 1-2).
    ss.invariant_frame = m.accuracy_inn == 2 || m.accuracy_inn == 4 || m.accuracy_inn == -2 || m.accuracy_inn == -4;
    ss.invariant_triangles = m.accuracy_inn == 2 || m.accuracy_inn == 4;
    ss.hourglass_coefficient = qm;
    ss.hourglass_stiffness = ihq >= 4 && ihq <= 6;  // one stiffness form on quadrilaterals, as LS-DYNA
    ss.bulk = bv;
    setup.blocks.push_back(make_shell_block(part.pid, *laws.shell, ss, std::move(g.quad_conn),
                                           std::move(g.quad_ids), damping));
    // *CONTROL_SHELL ISTUPD = 1, 4: the thickness follows the membrane strain (the block refuses
    // what it cannot: a law without stress, 4 on an elastic law).
    if (m.shell_istupd != 0) {
      try {
        setup.blocks.back()->enable_thickness_update(m.shell_istupd);
      } catch (const NotImplementedError& e) {
        throw NotImplementedError(describe(m.shell_istupd_src) + ": field ISTUPD of *CONTROL_SHELL: " + e.what());
      }
    }
  }

  template <class Sections>
  void build_rigid_part(const model::Part& part, const model::MatRigid& mat, PartElements& g,
                        const std::vector<Index>& nodes, const Sections& shsec) {
    std::array<int, 6> fixed{0, 0, 0, 0, 0, 0};
    if (mat.cmo == 1.0) {  // validate_model refused the other CMO values and codes
      const auto t = rigid_constraint_code(mat.con1).value();
      const auto r = rigid_constraint_code(mat.con2).value();
      for (int k = 0; k < 3; ++k) {
        fixed[k] = t[k];
        fixed[3 + k] = r[k];
      }
    }
    Real thickness = 0.0;
    if (!g.quad_ids.empty()) thickness = shell_section(part, shsec).t[0];
    std::vector<Id> ids = g.hex_ids;
    ids.insert(ids.end(), g.quad_ids.begin(), g.quad_ids.end());
    setup.blocks.push_back(make_rigid_mass_block(part.pid, mat.ro, mat.e, mat.pr, std::move(g.hex_conn),
                                                std::move(g.quad_conn), thickness, std::move(ids)));
    auto body = std::make_unique<RigidBody>(part.pid, nodes, fixed);
    rigid_bodies.emplace(part.pid, body.get());
    setup.constraints.push_back(std::move(body));
    for (Index n : nodes) rigid_node_part.emplace(n, part.pid);
  }

  /// Resolves every node, part and segment set into setup.sets (after build_elements, which finds
  /// each part's nodes), so that they outlive the build: contact interfaces look them up by id.
  void build_sets() {
    MeshSets& sets = setup.sets;
    sets.part_nodes = part_nodes;
    for (const auto& s : m.node_sets) {
      const std::string card = "*SET_NODE_LIST " + std::to_string(s.sid);
      std::vector<Index> out;
      for (Id nid : s.nodes) out.push_back(node(nid, s.src, card.c_str()));
      std::sort(out.begin(), out.end());
      out.erase(std::unique(out.begin(), out.end()), out.end());
      if (!sets.node_sets.emplace(s.sid, std::move(out)).second)
        throw InputError(describe(s.src) + ": duplicate *SET_NODE id " + std::to_string(s.sid));
      sets.node_set_titles[s.sid] = s.title;
    }
    std::set<Id> defined_parts;
    for (const auto& p : m.parts) defined_parts.insert(p.pid);
    for (const auto& s : m.part_sets) {
      for (Id pid : s.parts)
        if (!defined_parts.count(pid))
          throw InputError(describe(s.src) + ": *SET_PART " + std::to_string(s.sid) +
                           " refers to part " + std::to_string(pid) + ", which the deck does not define");
      if (!sets.part_sets.emplace(s.sid, s.parts).second)
        throw InputError(describe(s.src) + ": duplicate *SET_PART id " + std::to_string(s.sid));
      sets.part_set_titles[s.sid] = s.title;
    }
    for (const auto& s : m.segment_sets) {
      const std::string card = "*SET_SEGMENT " + std::to_string(s.sid);
      std::vector<SegmentNodes> segs;
      segs.reserve(s.segments.size());
      for (const auto& seg : s.segments) {
        SegmentNodes c;
        for (int k = 0; k < 4; ++k) c[k] = node(seg[k], s.src, card.c_str());
        segs.push_back(c);
      }
      if (!sets.segment_sets.emplace(s.sid, std::move(segs)).second)
        throw InputError(describe(s.src) + ": duplicate *SET_SEGMENT id " + std::to_string(s.sid));
      sets.segment_set_titles[s.sid] = s.title;
    }
  }

  std::vector<Index> node_set(Id sid, const model::Source& from, const char* field) const {
    return setup.sets.node_set(sid, describe(from) + ": " + field);
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
    return setup.sets.part_set(sid, describe(from) + ": " + field);
  }

  void build_boundaries() {
    for (const auto& spc : m.spcs) {
      SupportGroup g;  // DOF flags 0 or 1, a CID whose axes are global axes, no rigid node (validate_model)
      g.name = !spc.title.empty() ? spc.title
                                  : std::string(spc.node ? "spc_node_" : "spc_") +
                                        std::to_string(spc.id != 0 ? spc.id : spc.nsid);
      const auto nodes = spc.node ? std::vector<Index>{node(spc.nsid, spc.src, "NID")}
                                  : node_set(spc.nsid, spc.src, "NSID");
      // CID: DOFX..DOFRZ name the local axes; each is a global axis (validate_model).
      std::array<int, 3> global_axis{0, 1, 2};
      if (spc.cid != 0)
        global_axis = *axis_permutation(local_axes(m, spc.cid, describe(spc.src) + ": field CID").r);
      add_fixed_components(g, nodes, spc.dof, global_axis);
      setup.supports.push_back(std::move(g));
    }
    build_node_constraint_codes();
    for (const auto& pm : m.prescribed_motions) {
      // validate_model let through only the VAD (0-2) and DOF values run here, on no rigid node.
      if (pm.target == model::PrescribedMotion::Target::rigid) {
        build_rigid_motion(pm);
        continue;
      }
      SupportGroup g;
      g.name = !pm.title.empty() ? pm.title
                                 : "motion_" + std::to_string(pm.id != 0 ? pm.id : pm.nsid);
      Support s;
      s.axis = static_cast<Axis>(pm.dof - 1);
      s.nodes = pm.target == model::PrescribedMotion::Target::node
                    ? std::vector<Index>{node(pm.nsid, pm.src, "NID")}
                    : node_set(pm.nsid, pm.src, "NSID");
      s.has_curve = true;
      s.kind = pm.vad == 0 ? Prescribed::velocity : pm.vad == 1 ? Prescribed::acceleration : Prescribed::displacement;
      s.curve = curve(pm.lcid, pm.src, "LCID");
      s.scale = pm.sf;
      s.birth = pm.birth;
      s.death = pm.death;
      g.supports.push_back(std::move(s));
      setup.supports.push_back(std::move(g));
    }
  }

  /// *NODE TC/RC: a support group per distinct pair of codes, `node_tc<TC>_rc<RC>`, fixing the
  /// components the codes name (as a *BOUNDARY_SPC_SET of those nodes would) and reporting their
  /// summed reaction. Codes 0-7 as *MAT_RIGID's CON1/CON2 (validate_model refuses the others).
  void build_node_constraint_codes() {
    std::map<std::pair<int, int>, std::vector<Index>> by_code;  // deck order of *NODE within a code
    for (std::size_t i = 0; i < m.nodes.size(); ++i)
      if (m.nodes[i].tc != 0 || m.nodes[i].rc != 0)
        by_code[{m.nodes[i].tc, m.nodes[i].rc}].push_back(static_cast<Index>(i));
    for (const auto& [code, nodes] : by_code) {
      SupportGroup g;
      g.name = "node_tc" + std::to_string(code.first) + "_rc" + std::to_string(code.second);
      const auto t = rigid_constraint_code(code.first).value();
      const auto r = rigid_constraint_code(code.second).value();
      add_fixed_components(g, nodes, {t[0], t[1], t[2], r[0], r[1], r[2]});
      setup.supports.push_back(std::move(g));
    }
  }

  /// *RIGIDWALL_PLANAR: after the supports (a wall leaves their components alone) and the rigid
  /// parts; appended to the constraints, after the rigid bodies (build_rigid_wall.cpp).
  void build_rigid_walls() {
    const RigidWallContext ctx{setup.sets, setup.supports, rigid_node_part, setup.nodes.ids};
    for (std::size_t k = 0; k < m.rigid_walls.size(); ++k)
      setup.constraints.push_back(make_rigid_wall(m.rigid_walls[k], k + 1, ctx));
  }

  /// v(0) from the *INITIAL_VELOCITY cards (initial_velocity.cpp): after the sets and supports.
  void build_initial_velocities() {
    apply_initial_velocities({m, node_index, setup.sets, rigid_node_part, setup.supports}, setup.nodes);
  }

  /// *BOUNDARY_PRESCRIBED_MOTION_RIGID: drives the centre of mass of a *MAT_RIGID part (DOF 1-3)
  /// or its angular velocity about a global axis (DOF 5-7).
  void build_rigid_motion(const model::PrescribedMotion& pm) {
    // validate_model: PID names a *MAT_RIGID part, DOF is 1-3 or 5-7, VAD is 0 or 2.
    const std::string card = pm.keyword();
    RigidBody* const body = rigid_bodies.at(pm.nsid);
    const bool rotation = pm.dof >= 5 && pm.dof <= 7;
    RigidDrive d;
    d.axis = static_cast<Axis>(rotation ? pm.dof - 5 : pm.dof - 1);
    d.rotation = rotation;
    d.kind = pm.vad == 0 ? Prescribed::velocity : Prescribed::displacement;
    d.curve = curve(pm.lcid, pm.src, "LCID");
    d.scale = pm.sf;
    d.birth = pm.birth;
    d.death = pm.death;
    body->add_drive(std::move(d), describe(pm.src) + ": " + card);
  }

  void build_loads() {
    std::vector<Id> loaded;  // empty = all parts
    if (m.body_load_parts) {
      loaded = part_set(m.body_load_parts->psid, m.body_load_parts->src, "PSID");
      parts_nodes(loaded, m.body_load_parts->src);  // checks that every part exists
    }
    for (const auto& lb : m.body_loads) {
      // CID: the acceleration is along the local axis, its global components one load each.
      for (const auto& [axis, c] : global_components(m, lb.axis, lb.cid, describe(lb.src) + ": field CID")) {
        BodyLoad b;
        b.axis = axis;
        // LS-DYNA body loads are base accelerations: the inertial force opposes them.
        b.scale = -lb.sf * c;
        b.curve = curve(lb.lcid, lb.src, "LCID");
        b.parts = loaded;
        setup.body_loads.push_back(std::move(b));
      }
    }
  }

  void build_nodal_loads() {
    for (const auto& l : m.nodal_loads) {
      const std::string card = l.set ? "*LOAD_NODE_SET" : "*LOAD_NODE_POINT";
      NodalLoad nl;  // validate_model: DOF 1-3 or 5-7, CID 0 or a fixed system

      nl.moment = l.dof >= 5;
      nl.curve = curve(l.lcid, l.src, "LCID");
      nl.nodes = l.set ? node_set(l.id, l.src, "NSID") : std::vector<Index>{node(l.id, l.src, "NID")};
      std::sort(nl.nodes.begin(), nl.nodes.end());
      nl.nodes.erase(std::unique(nl.nodes.begin(), nl.nodes.end()), nl.nodes.end());
      nl.source = describe(l.src) + ": " + card;
      // CID: the force (moment) is along the local axis, its global components one load each.
      const Axis local = static_cast<Axis>(nl.moment ? l.dof - 5 : l.dof - 1);
      for (const auto& [axis, c] : global_components(m, local, l.cid, describe(l.src) + ": field CID")) {
        nl.axis = axis;
        nl.scale = l.sf * c;
        setup.nodal_loads.push_back(nl);
      }
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
      md.alpha *= common_direction_factor(d.stf).value();  // validate_model: one factor
      setup.damping.push_back(std::move(md));
    }
    for (const auto& d : m.damping_parts) {
      MassDamping md;
      md.alpha = d.sf;
      md.has_curve = true;
      md.curve = curve(d.lcid, d.src, "LCID");
      // FLAG = 1 is LS-DYNA's per-direction scale-factor card, not a part set (that is _SET).
      md.alpha *= d.flag == 1 ? common_direction_factor(d.stf).value() : 1.0;  // validate_model: one factor
      md.nodes = d.set ? parts_nodes(part_set(d.pid, d.src, "PSID"), d.src) : parts_nodes({d.pid}, d.src);
      setup.damping.push_back(std::move(md));
    }
  }

  void build_controls() {
    auto& c = setup.controls;
    c.end_time = opt.end_time > 0.0 ? opt.end_time : m.termination.endtim;
    c.max_cycles = m.termination.endcyc;
    c.dt_min_fraction = m.termination.dtmin > 0.0 ? m.termination.dtmin : 1e-4;
    c.erode_below_dt_min = m.timestep.erode == 1;
    if (m.termination.endeng > 0.0) {
      c.energy_error_limit = m.termination.endeng / 100.0;
      c.energy_error_warning = std::min(0.01, 0.2 * c.energy_error_limit);
    }
    c.dt_scale = m.timestep.tssfac > 0.0 ? m.timestep.tssfac : 0.9;
    c.dt2ms = m.timestep.dt2ms;  // mass scaling (solver/mass_scaling.hpp, mass_rescaling.hpp)
    c.mass_scaling_every_cycle = m.timestep.ms1st == 0;  // LS-DYNA's default: every cycle
    c.added_mass_limit_percent = m.termination.endmas > 0.0 ? m.termination.endmas : 1e8;
    if (m.timestep.lctm != 0) {
      // The curve (positive, validate_model) bounds the step; the stable step is still respected below it.
      c.has_dt_max_curve = true;
      c.dt_max_curve = curve(m.timestep.lctm, m.timestep.src, "LCTM");
    }
    Real hi = 0.0;
    for (Real v : {m.database.rcforc, m.database.spcforc, m.database.nodout, m.database.glstat})
      if (v > 0.0) hi = hi > 0.0 ? std::min(hi, v) : v;
    c.history_interval = hi;
    c.state_interval = m.database.d3plot;
    for (Id nid : m.database.history_nodes)
      setup.history_nodes.push_back(node(nid, {"*DATABASE_HISTORY_NODE", 0}, "NID"));
  }

  void build_contacts() {
    const std::vector<std::uint8_t> held = held_axes(setup.supports, setup.nodes.size());  // ISYM = 1
    const ContactBuildContext ctx{m, setup.blocks, setup.nodes, setup.sets, held};
    const std::vector<Id> eroding = eroding_part_of_nodes();
    // Force transducers last: they read the contact forces every other interface has added.
    for (const bool transducers : {false, true})
      for (std::size_t k = 0; k < m.contacts.size(); ++k) {
        const auto& card = m.contacts[k];  // titles distinct (validate_model)
        if ((card.form == model::ContactForm::force_transducer) != transducers) continue;
        if (transducers) check_transducer_measures(card);
        InterfaceSpec spec = resolve_interface(card, k + 1, ctx);
        // Contact with eroding parts: the automatic cards update their surfaces, the others refuse.
        prepare_eroding_contact(spec, ctx, eroding);
        // BT, DT: the manager honours them for every interface type (contact_manager.hpp).
        setup.contacts.add(make_contact_interface(spec, ctx), spec.window);
      }
  }

  /// Per node, the part of the first eroding block that holds it (0: none); empty when no block
  /// erodes.
  std::vector<Id> eroding_part_of_nodes() const {
    std::vector<Id> part;
    for (const auto& b : setup.blocks) {
      if (!std::as_const(*b).erosion()) continue;
      part.resize(setup.nodes.size(), 0);
      for (Index n : b->connectivity())
        if (part[static_cast<std::size_t>(n)] == 0) part[static_cast<std::size_t>(n)] = b->part_id();
    }
    return part;
  }

  /// A force transducer measures f_contact: refused beside an interface whose forces are not
  /// there (kinematic ties and Type 1 condense or constrain; Lagrange multipliers act later).
  void check_transducer_measures(const model::Contact& transducer) const {
    for (const auto& c : m.contacts)
      if (c.enforcement != model::Enforcement::penalty)
        throw NotImplementedError(describe_location(transducer.src.file, transducer.src.line) + ": " +
                                  transducer.keyword + ": a force transducer in a model with a kinematic or "
                                  "Lagrange contact (" + c.keyword + ") is not implemented: it would miss that "
                                  "contact's forces");
  }
};

}  // namespace

SimulationSetup build_setup(const model::Model& model, const BuildOptions& options) {
  validate_model(model, options);  // located, collapsed input errors before anything is built
  Builder b(model, options);
  b.build_nodes();
  b.build_curves();
  b.build_elements();
  b.build_sets();
  b.build_boundaries();
  b.build_initial_velocities();
  b.build_rigid_walls();
  b.build_loads();
  b.build_nodal_loads();
  b.build_damping();
  b.build_controls();
  b.build_contacts();
  return std::move(b.setup);
}

}  // namespace slideline
