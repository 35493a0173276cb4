#pragma once
// Field-by-field comparison of two model::Model, for the keyword round-trip tests. Every field is
// compared exactly except model::Source (where a card came from differs between two decks) and
// Contact::keyword (the spelling as written: _TITLE and _ID give the same contact).
#include <sstream>
#include <string>
#include <vector>

#include "slideline/model/model.hpp"

namespace slideline::test {

class ModelDiff {
 public:
  std::vector<std::string> diffs;

  template <class T>
  void eq(const std::string& what, const T& a, const T& b) {
    if (!(a == b)) {
      std::ostringstream s;
      s << what << ": ";
      print(s, a);
      s << " != ";
      print(s, b);
      diffs.push_back(s.str());
    }
  }
  template <class T, class F>
  void list(const std::string& what, const std::vector<T>& a, const std::vector<T>& b, F each) {
    eq(what + ".size", a.size(), b.size());
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) each(what + "[" + std::to_string(i) + "]", a[i], b[i]);
  }

 private:
  template <class T>
  static void print(std::ostream& s, const T& v) {
    if constexpr (requires { s << v; }) {
      if constexpr (std::is_floating_point_v<T>) s.precision(17);
      s << v;
    } else if constexpr (requires { v.size(); v[0]; }) {
      s << "[";
      for (std::size_t i = 0; i < v.size(); ++i) {
        if (i) s << ",";
        print(s, v[i]);
      }
      s << "]";
    } else if constexpr (requires { v.first; v.second; }) {
      s << "(";
      print(s, v.first);
      s << ",";
      print(s, v.second);
      s << ")";
    } else if constexpr (std::is_enum_v<T>) {
      s << static_cast<long>(v);
    } else {
      s << "?";
    }
  }
};

#define SL_EQ(field) d.eq(w + "." #field, a.field, b.field)

inline std::vector<std::string> model_differences(const model::Model& ma, const model::Model& mb) {
  ModelDiff d;
  {
    const auto& a = ma;
    const auto& b = mb;
    const std::string w = "model";
    SL_EQ(title);
    SL_EQ(control_hourglass.ihq); SL_EQ(control_hourglass.qh);
    SL_EQ(bulk_viscosity.q1); SL_EQ(bulk_viscosity.q2);
    SL_EQ(termination.endtim); SL_EQ(termination.endcyc); SL_EQ(termination.dtmin); SL_EQ(termination.endeng);
    SL_EQ(timestep.dtinit); SL_EQ(timestep.tssfac); SL_EQ(timestep.isdo); SL_EQ(timestep.tslimt);
    SL_EQ(timestep.dt2ms); SL_EQ(timestep.lctm);
    SL_EQ(control_contact.slsfac); SL_EQ(control_contact.rwpnal); SL_EQ(control_contact.islchk);
    SL_EQ(control_contact.shlthk); SL_EQ(control_contact.penopt); SL_EQ(control_contact.thkchg);
    SL_EQ(control_contact.orien); SL_EQ(control_contact.enmass);
    SL_EQ(database.rcforc); SL_EQ(database.spcforc); SL_EQ(database.nodout); SL_EQ(database.glstat);
    SL_EQ(database.d3plot); SL_EQ(database.history_nodes);
    d.eq(w + ".body_load_parts?", a.body_load_parts.has_value(), b.body_load_parts.has_value());
    if (a.body_load_parts && b.body_load_parts) SL_EQ(body_load_parts->psid);
    d.eq(w + ".damping_global?", a.damping_global.has_value(), b.damping_global.has_value());
    if (a.damping_global && b.damping_global) {
      SL_EQ(damping_global->lcid); SL_EQ(damping_global->valdmp); SL_EQ(damping_global->stf);
    }
  }
  d.list("nodes", ma.nodes, mb.nodes, [&](const std::string& w, const auto& a, const auto& b) {
    SL_EQ(id); SL_EQ(x[0]); SL_EQ(x[1]); SL_EQ(x[2]); SL_EQ(tc); SL_EQ(rc);
  });
  d.list("solids", ma.solids, mb.solids, [&](const std::string& w, const auto& a, const auto& b) {
    SL_EQ(id); SL_EQ(pid); SL_EQ(n);
  });
  d.list("shells", ma.shells, mb.shells, [&](const std::string& w, const auto& a, const auto& b) {
    SL_EQ(id); SL_EQ(pid); SL_EQ(n);
  });
  d.list("parts", ma.parts, mb.parts, [&](const std::string& w, const auto& a, const auto& b) {
    SL_EQ(pid); SL_EQ(title); SL_EQ(secid); SL_EQ(mid); SL_EQ(eosid); SL_EQ(hgid);
  });
  d.list("solid_sections", ma.solid_sections, mb.solid_sections,
         [&](const std::string& w, const auto& a, const auto& b) { SL_EQ(secid); SL_EQ(elform); });
  d.list("shell_sections", ma.shell_sections, mb.shell_sections, [&](const std::string& w, const auto& a, const auto& b) {
    SL_EQ(secid); SL_EQ(elform); SL_EQ(shrf); SL_EQ(nip); SL_EQ(propt); SL_EQ(t);
  });
  d.list("materials", ma.materials, mb.materials, [&](const std::string& w, const auto& ma_, const auto& mb_) {
    d.eq(w + ".kind", ma_.index(), mb_.index());
    if (ma_.index() != mb_.index()) return;
    if (const auto* pa = std::get_if<model::MatElastic>(&ma_)) {
      const auto& a = *pa;
      const auto& b = std::get<model::MatElastic>(mb_);
      SL_EQ(mid); SL_EQ(ro); SL_EQ(e); SL_EQ(pr); SL_EQ(title);
    } else if (const auto* pm = std::get_if<model::MatMooneyRivlin>(&ma_)) {
      const auto& a = *pm;
      const auto& b = std::get<model::MatMooneyRivlin>(mb_);
      SL_EQ(mid); SL_EQ(ro); SL_EQ(pr); SL_EQ(a); SL_EQ(b); SL_EQ(title);
    } else {
      const auto& a = std::get<model::MatRigid>(ma_);
      const auto& b = std::get<model::MatRigid>(mb_);
      SL_EQ(mid); SL_EQ(ro); SL_EQ(e); SL_EQ(pr); SL_EQ(cmo); SL_EQ(con1); SL_EQ(con2); SL_EQ(title);
    }
  });
  d.list("hourglasses", ma.hourglasses, mb.hourglasses, [&](const std::string& w, const auto& a, const auto& b) {
    SL_EQ(hgid); SL_EQ(ihq); SL_EQ(qm); SL_EQ(q1); SL_EQ(q2);
  });
  d.list("node_sets", ma.node_sets, mb.node_sets, [&](const std::string& w, const auto& a, const auto& b) {
    SL_EQ(sid); SL_EQ(title); SL_EQ(nodes);
  });
  d.list("segment_sets", ma.segment_sets, mb.segment_sets, [&](const std::string& w, const auto& a, const auto& b) {
    SL_EQ(sid); SL_EQ(title); SL_EQ(segments);
  });
  d.list("part_sets", ma.part_sets, mb.part_sets, [&](const std::string& w, const auto& a, const auto& b) {
    SL_EQ(sid); SL_EQ(title); SL_EQ(parts);
  });
  d.list("spcs", ma.spcs, mb.spcs, [&](const std::string& w, const auto& a, const auto& b) {
    SL_EQ(id); SL_EQ(title); SL_EQ(nsid); SL_EQ(node); SL_EQ(cid); SL_EQ(dof);
  });
  d.list("prescribed_motions", ma.prescribed_motions, mb.prescribed_motions,
         [&](const std::string& w, const auto& a, const auto& b) {
           SL_EQ(id); SL_EQ(title); SL_EQ(nsid); SL_EQ(dof); SL_EQ(vad); SL_EQ(lcid); SL_EQ(sf); SL_EQ(vid);
           SL_EQ(death); SL_EQ(birth); SL_EQ(target);
         });
  d.list("nodal_loads", ma.nodal_loads, mb.nodal_loads, [&](const std::string& w, const auto& a, const auto& b) {
    SL_EQ(set); SL_EQ(id); SL_EQ(dof); SL_EQ(lcid); SL_EQ(sf); SL_EQ(cid); SL_EQ(m);
  });
  d.list("body_loads", ma.body_loads, mb.body_loads, [&](const std::string& w, const auto& a, const auto& b) {
    SL_EQ(axis); SL_EQ(lcid); SL_EQ(sf); SL_EQ(lciddr); SL_EQ(xc); SL_EQ(yc); SL_EQ(zc); SL_EQ(cid);
  });
  d.list("curves", ma.curves, mb.curves, [&](const std::string& w, const auto& a, const auto& b) {
    SL_EQ(lcid); SL_EQ(title); SL_EQ(sidr); SL_EQ(sfa); SL_EQ(sfo); SL_EQ(offa); SL_EQ(offo); SL_EQ(dattyp);
    SL_EQ(points);
  });
  d.list("boxes", ma.boxes, mb.boxes, [&](const std::string& w, const auto& a, const auto& b) {
    SL_EQ(boxid); SL_EQ(title); SL_EQ(min); SL_EQ(max);
  });
  d.list("initial_velocities", ma.initial_velocities, mb.initial_velocities,
         [&](const std::string& w, const auto& a, const auto& b) {
           SL_EQ(nsid); SL_EQ(nsidex); SL_EQ(boxid); SL_EQ(irigid); SL_EQ(icid); SL_EQ(v); SL_EQ(vr); SL_EQ(ve);
           SL_EQ(vre);
         });
  d.list("initial_velocity_generations", ma.initial_velocity_generations, mb.initial_velocity_generations,
         [&](const std::string& w, const auto& a, const auto& b) {
           SL_EQ(id); SL_EQ(styp); SL_EQ(omega); SL_EQ(v); SL_EQ(ivatn); SL_EQ(icid); SL_EQ(xc); SL_EQ(n);
           SL_EQ(phase); SL_EQ(irigid);
         });
  d.list("initial_velocity_nodes", ma.initial_velocity_nodes, mb.initial_velocity_nodes,
         [&](const std::string& w, const auto& a, const auto& b) { SL_EQ(nid); SL_EQ(v); SL_EQ(vr); });
  d.list("damping_parts", ma.damping_parts, mb.damping_parts, [&](const std::string& w, const auto& a, const auto& b) {
    SL_EQ(pid); SL_EQ(lcid); SL_EQ(sf); SL_EQ(flag); SL_EQ(set); SL_EQ(stf);
  });
  d.list("damping_stiffness", ma.damping_stiffness, mb.damping_stiffness,
         [&](const std::string& w, const auto& a, const auto& b) { SL_EQ(pid); SL_EQ(coef); SL_EQ(set); });
  d.list("contacts", ma.contacts, mb.contacts, [&](const std::string& w, const auto& a, const auto& b) {
    SL_EQ(cid); SL_EQ(title); SL_EQ(type); SL_EQ(enforcement); SL_EQ(sliding_only_option);
    SL_EQ(automatic_general);
    SL_EQ(ssid); SL_EQ(msid); SL_EQ(sstyp); SL_EQ(mstyp); SL_EQ(sboxid); SL_EQ(mboxid); SL_EQ(spr); SL_EQ(mpr);
    SL_EQ(fs); SL_EQ(fd); SL_EQ(dc); SL_EQ(vc); SL_EQ(vdc); SL_EQ(penchk); SL_EQ(bt); SL_EQ(dt);
    SL_EQ(sfs); SL_EQ(sfm); SL_EQ(sst); SL_EQ(mst); SL_EQ(sfst); SL_EQ(sfmt); SL_EQ(fsf); SL_EQ(vsf);
    SL_EQ(nflf); SL_EQ(sflf); SL_EQ(nen); SL_EQ(mes); SL_EQ(option); SL_EQ(nfls); SL_EQ(sfls); SL_EQ(radius);
  });
  return d.diffs;
}

#undef SL_EQ

}  // namespace slideline::test
