// Keyword deck writer. Each card is written in fixed columns when every value fits with a space to
// spare, else as a free-format (comma-separated) card, so that no digit is lost: reals are written
// in their shortest exact form (std::to_chars), which the reader parses back to the same double.
#include "slideline/io/keyword_writer.hpp"

#include <charconv>
#include <fstream>
#include <span>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "slideline/core/error.hpp"
#include "slideline/core/overloaded.hpp"
#include "slideline/model/contact_keywords.hpp"

namespace slideline {
namespace {

constexpr int kStandard[] = {10, 10, 10, 10, 10, 10, 10, 10};
constexpr int kNodeCard[] = {8, 16, 16, 16, 8, 8};
constexpr int kElementCard[] = {8, 8, 8, 8, 8, 8, 8, 8, 8, 8};
constexpr int kCurvePoint[] = {20, 20};

std::string real_text(Real v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  std::string s(buf, r.ptr);
  // "1" reads back as 1.0 too, but a point tells a reader of the deck that the field is real.
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

/// One card being written: field texts, then laid out fixed or free.
class CardOut {
 public:
  explicit CardOut(std::span<const int> widths = kStandard) : widths_(widths) {}
  CardOut& r(Real v) { fields_.push_back(real_text(v)); return *this; }
  CardOut& i(Id v) { fields_.push_back(std::to_string(v)); return *this; }
  CardOut& blank() { fields_.emplace_back(); return *this; }

  std::string str() const {
    bool fits = fields_.size() <= widths_.size();
    for (std::size_t k = 0; fits && k < fields_.size(); ++k)
      fits = static_cast<int>(fields_[k].size()) < widths_[k];
    std::string out;
    if (fits) {
      for (std::size_t k = 0; k < fields_.size(); ++k)
        out += std::string(static_cast<std::size_t>(widths_[k]) - fields_[k].size(), ' ') + fields_[k];
    } else {
      for (std::size_t k = 0; k < fields_.size(); ++k) out += (k ? "," : "") + fields_[k];
      if (fields_.size() == 1) out += ",";  // a comma marks the card as free format
    }
    while (!out.empty() && out.back() == ' ') out.pop_back();
    return out + "\n";
  }

 private:
  std::span<const int> widths_;
  std::vector<std::string> fields_;
};

/// "ID + heading" card of the _ID options: the id in columns 1-10 and the heading after it.
std::string id_heading(Id id, const std::string& title) {
  std::string s = std::to_string(id);
  if (s.size() >= 10) return s + "," + title + "\n";
  return std::string(10 - s.size(), ' ') + s + title + "\n";
}

/// A heading card on its own line. A heading starting with '*' or '$' would read as a keyword or
/// comment: it gets a leading space (which the reader trims).
std::string heading(const std::string& title) {
  if (!title.empty() && (title.front() == '*' || title.front() == '$')) return " " + title + "\n";
  return title + "\n";
}

void write_initial_velocities(const model::Model& m, std::string& o) {
  const auto velocity = [](CardOut& c, const Vec3& v, const Vec3& vr) {
    for (int k = 0; k < 3; ++k) c.r(v[k]);
    for (int k = 0; k < 3; ++k) c.r(vr[k]);
  };
  for (const auto& iv : m.initial_velocities) {
    o += "*INITIAL_VELOCITY\n$#    NSID    NSIDEX     BOXID    IRIGID      ICID\n";
    o += CardOut().i(iv.nsid).i(iv.nsidex).i(iv.boxid).i(iv.irigid).i(iv.icid).str();
    o += "$#      VX        VY        VZ       VXR       VYR       VZR\n";
    CardOut c;
    velocity(c, iv.v, iv.vr);
    o += c.str();
    if (iv.nsidex > 0) {
      CardOut e;
      velocity(e, iv.ve, iv.vre);
      o += "$#     VXE       VYE       VZE      VXRE      VYRE      VZRE\n" + e.str();
    }
  }
  for (const auto& g : m.initial_velocity_generations) {
    o += "*INITIAL_VELOCITY_GENERATION\n";
    o += "$#      ID      STYP     OMEGA        VX        VY        VZ     IVATN      ICID\n";
    o += CardOut().i(g.id).i(g.styp).r(g.omega).r(g.v[0]).r(g.v[1]).r(g.v[2]).i(g.ivatn).i(g.icid).str();
    o += "$#      XC        YC        ZC        NX        NY        NZ     PHASE    IRIGID\n";
    o += CardOut().r(g.xc[0]).r(g.xc[1]).r(g.xc[2]).r(g.n[0]).r(g.n[1]).r(g.n[2]).i(g.phase).i(g.irigid).str();
  }
  if (!m.initial_velocity_nodes.empty()) {
    o += "*INITIAL_VELOCITY_NODE\n$#     NID        VX        VY        VZ       VXR       VYR       VZR      ICID\n";
    for (const auto& iv : m.initial_velocity_nodes) {
      CardOut c;
      c.i(iv.nid);
      velocity(c, iv.v, iv.vr);
      if (iv.icid != 0) c.i(iv.icid);
      o += c.str();
    }
  }
}

/// One case per material card and no generic case: a card added to model::Material without a case
/// here does not compile (instead of being left out of the written deck).
void write_materials(const model::Model& m, std::string& o) {
  for (const auto& mat : m.materials)
    std::visit(Overloaded{
                   [&](const model::MatElastic& e) {
                     o += e.title.empty() ? "*MAT_ELASTIC\n" : "*MAT_ELASTIC_TITLE\n" + heading(e.title);
                     o += "$#     MID        RO         E        PR\n";
                     o += CardOut().i(e.mid).r(e.ro).r(e.e).r(e.pr).str();
                   },
                   [&](const model::MatMooneyRivlin& mr) {
                     o += mr.title.empty() ? "*MAT_MOONEY-RIVLIN_RUBBER\n"
                                           : "*MAT_MOONEY-RIVLIN_RUBBER_TITLE\n" + heading(mr.title);
                     o += "$#     MID        RO        PR         A         B\n";
                     o += CardOut().i(mr.mid).r(mr.ro).r(mr.pr).r(mr.a).r(mr.b).str();
                     o += "$#     SGL        SW        ST      LCID\n\n";
                   },
                   [&](const model::MatPlasticKinematic& pk) {
                     o += pk.title.empty() ? "*MAT_PLASTIC_KINEMATIC\n"
                                           : "*MAT_PLASTIC_KINEMATIC_TITLE\n" + heading(pk.title);
                     o += "$#     MID        RO         E        PR      SIGY      ETAN      BETA\n";
                     o += CardOut().i(pk.mid).r(pk.ro).r(pk.e).r(pk.pr).r(pk.sigy).r(pk.etan).r(pk.beta).str();
                     o += "$#     SRC       SRP        FS        VP\n";
                     CardOut rate = CardOut().r(pk.src_c).r(pk.srp);
                     if (pk.fs != 0.0) rate.r(pk.fs);  // written only when set: decks without it read as before
                     o += rate.str();
                   },
                   [&](const model::MatPiecewiseLinearPlasticity& pw) {
                     o += pw.title.empty() ? "*MAT_PIECEWISE_LINEAR_PLASTICITY\n"
                                           : "*MAT_PIECEWISE_LINEAR_PLASTICITY_TITLE\n" + heading(pw.title);
                     o += "$#     MID        RO         E        PR      SIGY      ETAN      FAIL      TDEL\n";
                     CardOut c1 = CardOut().i(pw.mid).r(pw.ro).r(pw.e).r(pw.pr).r(pw.sigy).r(pw.etan);
                     if (pw.fail != 0.0 || pw.tdel != 0.0) c1.r(pw.fail);  // written only when set, as FS above
                     if (pw.tdel != 0.0) c1.r(pw.tdel);
                     o += c1.str();
                     o += "$#       C         P      LCSS      LCSR        VP\n";
                     o += CardOut().r(pw.c).r(pw.p).i(pw.lcss).i(pw.lcsr).r(pw.vp).str();
                     CardOut eps, es;
                     for (int k = 0; k < 8; ++k) {
                       eps.r(pw.eps[static_cast<std::size_t>(k)]);
                       es.r(pw.es[static_cast<std::size_t>(k)]);
                     }
                     o += "$#    EPS1      EPS2      EPS3      EPS4      EPS5      EPS6      EPS7      EPS8\n";
                     o += eps.str();
                     o += "$#     ES1       ES2       ES3       ES4       ES5       ES6       ES7       ES8\n";
                     o += es.str();
                   },
                   [&](const model::MatNull& nl) {
                     o += nl.title.empty() ? "*MAT_NULL\n" : "*MAT_NULL_TITLE\n" + heading(nl.title);
                     o += "$#     MID        RO        PC        MU     TEROD     CEROD        YM        PR\n";
                     o += CardOut().i(nl.mid).r(nl.ro).r(nl.pc).r(nl.mu).r(nl.terod).r(nl.cerod).r(nl.ym).r(nl.pr).str();
                   },
                   [&](const model::MatRigid& rg) {
                     o += rg.title.empty() ? "*MAT_RIGID\n" : "*MAT_RIGID_TITLE\n" + heading(rg.title);
                     o += "$#     MID        RO         E        PR\n";
                     o += CardOut().i(rg.mid).r(rg.ro).r(rg.e).r(rg.pr).str();
                     o += "$#     CMO      CON1      CON2\n";
                     o += CardOut().r(rg.cmo).i(rg.con1).i(rg.con2).str();
                   },
               },
               mat);
  // *MAT_ADD_EROSION: an excluded threshold (and every criterion not built) is written as EXCL.
  for (const auto& a : m.add_erosions) {
    o += a.title.empty() ? "*MAT_ADD_EROSION\n" : "*MAT_ADD_EROSION_TITLE\n" + heading(a.title);
    const auto th = [&](const std::optional<Real>& v) { return v ? *v : a.excl; };
    o += "$#     MID      EXCL    MXPRES     MNEPS    EFFEPS    VOLEPS    NUMFIP       NCS\n";
    o += CardOut().i(a.mid).r(a.excl).r(th(a.mxpres)).r(th(a.mneps)).r(th(a.effeps)).r(th(a.voleps)).r(a.numfip).i(a.ncs).str();
    o += "$#  MNPRES     SIGP1     SIGVM     MXEPS     EPSSH     SIGTH   IMPULSE    FAILTM\n";
    o += CardOut().r(th(a.mnpres)).r(th(a.sigp1)).r(th(a.sigvm)).r(th(a.mxeps)).r(th(a.epssh)).r(a.excl).r(a.excl)
             .r(th(a.failtm)).str();
  }
  // Equations of state (the parts' EOSID).
  static constexpr int kTableCard[] = {16, 16, 16, 16, 16};
  for (const auto& eos : m.eos)
    std::visit(Overloaded{
                   [&](const model::EosLinearPolynomial& e) {
                     o += "*EOS_LINEAR_POLYNOMIAL\n$#   EOSID        C0        C1        C2        C3        C4        C5        C6\n";
                     CardOut c;
                     c.i(e.eosid);
                     for (Real v : e.c) c.r(v);
                     o += c.str() + "$#      E0        V0\n" + CardOut().r(e.e0).r(e.v0).str();
                   },
                   [&](const model::EosGruneisen& e) {
                     o += "*EOS_GRUNEISEN\n$#   EOSID         C        S1        S2        S3     GAMAO         A        E0\n";
                     o += CardOut().i(e.eosid).r(e.c).r(e.s1).r(e.s2).r(e.s3).r(e.gamma0).r(e.a).r(e.e0).str();
                     o += "$#      V0\n" + CardOut().r(e.v0).str();
                   },
                   [&](const model::EosTabulated& e) {
                     o += "*EOS_TABULATED\n$#   EOSID      GAMA        E0        V0\n";
                     o += CardOut().i(e.eosid).r(e.gama).r(e.e0).r(e.v0).str();
                     for (const auto* t : {&e.ev, &e.c, &e.t})
                       for (int half = 0; half < 2; ++half) {
                         CardOut c(kTableCard);
                         for (int k = 0; k < 5; ++k) c.r((*t)[static_cast<std::size_t>(5 * half + k)]);
                         o += c.str();
                       }
                   },
               },
               eos);
}

/// The card's row of the contact keyword table.
const model::ContactKeyword& contact_row(const model::Contact& c) {
  const model::ContactKeyword* k = model::contact_keyword(c);
  if (!k) throw Error("contact of type " + std::to_string(static_cast<int>(c.type)) + " has no keyword");
  return *k;
}

void write_contacts(const model::Model& m, std::string& o) {
  using model::ContactType;
  for (const auto& c : m.contacts) {
    const model::ContactKeyword& row = contact_row(c);
    std::string kw(row.keyword);
    if (row.sliding_option && c.sliding_only_option) kw += "_SLIDING_ONLY";
    // The mortar coupling is written wherever it is set: the reader refuses it, by name, on a card
    // that does not take it, rather than a deck losing it.
    if (c.penalty_coupling == 1) kw += "_MORTAR";
    else if (c.penalty_coupling != 0)
      throw Error("contact penalty_coupling " + std::to_string(c.penalty_coupling) + " has no keyword (0 or 1)");
    if (c.enforcement == model::Enforcement::lagrange) kw += "_LAGRANGE";
    const bool with_id = c.cid != 0 || !c.title.empty();
    o += kw + (with_id ? "_ID\n" : "\n");
    if (with_id) o += id_heading(c.cid, c.title);
    o += "$#    SSID      MSID     SSTYP     MSTYP    SBOXID    MBOXID       SPR       MPR\n";
    o += CardOut().i(c.ssid).i(c.msid).i(c.sstyp).i(c.mstyp).i(c.sboxid).i(c.mboxid).i(c.spr).i(c.mpr).str();
    o += "$#      FS        FD        DC        VC       VDC    PENCHK        BT        DT\n";
    o += CardOut().r(c.fs).r(c.fd).r(c.dc).r(c.vc).r(c.vdc).i(c.penchk).r(c.bt).r(c.dt).str();
    // Type 5 with a node set: SST carries the nodal radius.
    const bool radius_in_sst = c.type == ContactType::nodes_to_surface && c.sstyp == 4 && c.radius != 0.0;
    o += "$#     SFS       SFM       SST       MST      SFST      SFMT       FSF       VSF\n";
    o += CardOut().r(c.sfs).r(c.sfm).r(radius_in_sst ? c.radius : c.sst).r(c.mst).r(c.sfst).r(c.sfmt)
             .r(c.fsf).r(c.vsf).str();
    if (c.eroding) {
      o += "$#    ISYM    EROSOP      IADJ\n";
      o += CardOut().i(c.isym).i(c.erosop).i(c.iadj).str();
    }
    if (c.type == ContactType::tiebreak_nodes) {
      o += "$#    NFLF      SFLF       NEN       MES\n";
      o += CardOut().r(c.nflf).r(c.sflf).r(c.nen).r(c.mes).str();
    } else if (c.type == ContactType::tiebreak_surface) {
      // PARAM..CN (OPTION 9 of the automatic card) only when given, so other decks write as before.
      const bool law = c.param != 0.0 || c.eraten != 0.0 || c.erates != 0.0 || c.ct2cn != 0.0 || c.cn != 0.0;
      o += law ? "$#  OPTION      NFLS      SFLS     PARAM    ERATEN    ERATES     CT2CN        CN\n"
               : "$#  OPTION      NFLS      SFLS\n";
      const Real nfls = c.nfls != 0.0 ? c.nfls : c.nflf, sfls = c.sfls != 0.0 ? c.sfls : c.sflf;
      o += law ? CardOut().i(c.option).r(nfls).r(sfls).r(c.param).r(c.eraten).r(c.erates).r(c.ct2cn).r(c.cn).str()
               : CardOut().i(c.option).r(nfls).r(sfls).str();
    }
    const bool card_a = c.soft != 0 || c.sofscl != 0.1;
    if (card_a) {
      o += "$#    SOFT    SOFSCL\n";
      o += CardOut().i(c.soft).r(c.sofscl).str();
    }
    if (c.ignore != 0) {
      o += card_a ? "$# optional card B (defaults), C: IGAP IGNORE\n\n"
                  : "$# optional cards A and B (defaults), C: IGAP IGNORE\n\n\n";
      o += CardOut().blank().i(c.ignore).str();
    }
  }
}

template <class Ids>
void write_id_list(const Ids& ids, std::string& o) {
  for (std::size_t k = 0; k < ids.size(); k += 8) {
    CardOut c;
    for (std::size_t j = k; j < ids.size() && j < k + 8; ++j) c.i(ids[j]);
    o += c.str();
  }
}

/// The control cards (termination, time step, hourglass, bulk viscosity, contact).
void write_controls(const model::Model& m, std::string& o) {
  if (m.termination.endmas != 1e8) {
    o += "*CONTROL_TERMINATION\n$#  ENDTIM    ENDCYC     DTMIN    ENDENG    ENDMAS\n";
    o += CardOut().r(m.termination.endtim).i(m.termination.endcyc).r(m.termination.dtmin).r(m.termination.endeng)
             .r(m.termination.endmas).str();
  } else if (m.termination.endeng != 0.0) {
    o += "*CONTROL_TERMINATION\n$#  ENDTIM    ENDCYC     DTMIN    ENDENG\n";
    o += CardOut().r(m.termination.endtim).i(m.termination.endcyc).r(m.termination.dtmin).r(m.termination.endeng).str();
  } else if (m.termination.dtmin != 0.0) {
    o += "*CONTROL_TERMINATION\n$#  ENDTIM    ENDCYC     DTMIN\n";
    o += CardOut().r(m.termination.endtim).i(m.termination.endcyc).r(m.termination.dtmin).str();
  } else {
    o += "*CONTROL_TERMINATION\n$#  ENDTIM    ENDCYC\n";
    o += CardOut().r(m.termination.endtim).i(m.termination.endcyc).str();
  }
  const auto& ts = m.timestep;
  if (ts.ms1st != 0 || ts.erode != 0) {
    o += "*CONTROL_TIMESTEP\n$#  DTINIT    TSSFAC      ISDO    TSLIMT     DT2MS      LCTM     ERODE     MS1ST\n";
    o += CardOut().r(ts.dtinit).r(ts.tssfac).i(ts.isdo).r(ts.tslimt).r(ts.dt2ms).i(ts.lctm).i(ts.erode).i(ts.ms1st).str();
  } else {
    o += "*CONTROL_TIMESTEP\n$#  DTINIT    TSSFAC      ISDO    TSLIMT     DT2MS      LCTM\n";
    o += CardOut().r(ts.dtinit).r(ts.tssfac).i(ts.isdo).r(ts.tslimt).r(ts.dt2ms).i(ts.lctm).str();
  }
  o += "*CONTROL_HOURGLASS\n$#     IHQ        QH\n";
  o += CardOut().i(m.control_hourglass.ihq).r(m.control_hourglass.qh).str();
  o += "*CONTROL_BULK_VISCOSITY\n$#      Q1        Q2\n";
  o += CardOut().r(m.bulk_viscosity.q1).r(m.bulk_viscosity.q2).str();
  // *CONTROL_SHELL: the fields stored (ESORT, ISTUPD; INTGRD on card 2), when one is not 0.
  if (m.shell_esort != 0 || m.shell_istupd != 0 || m.shell_intgrd != 0) {
    o += "*CONTROL_SHELL\n$#  WRPANG     ESORT     IRNXX    ISTUPD\n";
    o += CardOut().i(0).i(m.shell_esort).i(0).i(m.shell_istupd).str();
    if (m.shell_intgrd != 0) {
      o += "$# ROTASCL    INTGRD\n";
      o += CardOut().i(0).i(m.shell_intgrd).str();
    }
  }
  const auto& cc = m.control_contact;
  o += "*CONTROL_CONTACT\n$#  SLSFAC    RWPNAL    ISLCHK    SHLTHK    PENOPT    THKCHG     ORIEN    ENMASS\n";
  o += CardOut().r(cc.slsfac).r(cc.rwpnal).i(cc.islchk).i(cc.shlthk).i(cc.penopt).i(cc.thkchg).i(cc.orien)
           .i(cc.enmass).str();
  if (cc.ignore != 0 || cc.xpene != 4.0) {
    o += "$#  USRSTR    USRFRC     NSBCS    INTERM     XPENE\n";
    o += CardOut().i(0).i(0).i(0).i(0).r(cc.xpene).str();
    o += "$# card 3 (defaults), card 4: IGNORE\n\n";
    o += CardOut().i(cc.ignore).str();
  }
}

/// The output cards.
void write_database(const model::Model& m, std::string& o) {
  const auto& db = m.database;
  const std::pair<const char*, Real> dbs[] = {{"*DATABASE_RCFORC", db.rcforc}, {"*DATABASE_SPCFORC", db.spcforc},
                                              {"*DATABASE_NODOUT", db.nodout}, {"*DATABASE_GLSTAT", db.glstat},
                                              {"*DATABASE_BINARY_D3PLOT", db.d3plot}};
  for (const auto& [kw, dt] : dbs)
    if (dt != 0.0) o += std::string(kw) + "\n$#      DT\n" + CardOut().r(dt).str();
  if (!db.history_nodes.empty()) {
    o += "*DATABASE_HISTORY_NODE\n";
    write_id_list(db.history_nodes, o);
  }
}

/// Parts, sections, materials and hourglass cards.
void write_parts(const model::Model& m, std::string& o) {
  for (const auto& p : m.parts) {
    o += "*PART\n" + heading(p.title);
    o += "$#     PID     SECID       MID     EOSID      HGID\n";
    o += CardOut().i(p.pid).i(p.secid).i(p.mid).i(p.eosid).i(p.hgid).str();
  }
  for (const auto& s : m.solid_sections) {
    o += "*SECTION_SOLID\n$#   SECID    ELFORM\n" + CardOut().i(s.secid).i(s.elform).str();
  }
  for (const auto& s : m.shell_sections) {
    o += "*SECTION_SHELL\n$#   SECID    ELFORM      SHRF       NIP     PROPT\n";
    o += CardOut().i(s.secid).i(s.elform).r(s.shrf).i(s.nip).r(s.propt).str();
    o += "$#      T1        T2        T3        T4\n";
    o += CardOut().r(s.t[0]).r(s.t[1]).r(s.t[2]).r(s.t[3]).str();
  }
  write_materials(m, o);
  for (const auto& h : m.hourglasses) {
    o += "*HOURGLASS\n$#    HGID       IHQ        QM       IBQ        Q1        Q2\n";
    o += CardOut().i(h.hgid).i(h.ihq).r(h.qm).blank().r(h.q1).r(h.q2).str();
  }
}

/// Node, segment and part sets.
void write_sets(const model::Model& m, std::string& o) {
  for (const auto& s : m.node_sets) {
    o += s.title.empty() ? "*SET_NODE_LIST\n" : "*SET_NODE_LIST_TITLE\n" + heading(s.title);
    o += "$#     SID\n" + CardOut().i(s.sid).str();
    write_id_list(s.nodes, o);
  }
  for (const auto& s : m.segment_sets) {
    o += s.title.empty() ? "*SET_SEGMENT\n" : "*SET_SEGMENT_TITLE\n" + heading(s.title);
    o += "$#     SID\n" + CardOut().i(s.sid).str();
    for (const auto& seg : s.segments) o += CardOut().i(seg[0]).i(seg[1]).i(seg[2]).i(seg[3]).str();
  }
  for (const auto& s : m.part_sets) {
    o += s.title.empty() ? "*SET_PART_LIST\n" : "*SET_PART_LIST_TITLE\n" + heading(s.title);
    o += "$#     SID\n" + CardOut().i(s.sid).str();
    write_id_list(s.parts, o);
  }
}

/// Supports, prescribed motions, loads and initial velocities.
void write_rigid_walls(const model::Model& m, std::string& o) {
  for (const auto& w : m.rigid_walls) {
    const bool with_id = w.id != 0 || !w.title.empty();
    const std::string kw = w.finite ? "*RIGIDWALL_PLANAR_FINITE" : "*RIGIDWALL_PLANAR";
    o += with_id ? kw + "_ID\n" + id_heading(w.id, w.title) : kw + "\n";
    o += "$#    NSID    NSIDEX     BOXID    OFFSET     BIRTH     DEATH     RWKSF\n";
    o += CardOut().i(w.nsid).i(w.nsidex).i(w.boxid).r(w.offset).r(w.birth).r(w.death).r(w.rwksf).str();
    o += "$#      XT        YT        ZT        XH        YH        ZH      FRIC      WVEL\n";
    o += CardOut().r(w.tail.x()).r(w.tail.y()).r(w.tail.z()).r(w.head.x()).r(w.head.y()).r(w.head.z()).r(w.fric)
             .r(w.wvel).str();
    if (w.finite) {
      o += "$#    XHEV      YHEV      ZHEV      LENL      LENM\n";
      o += CardOut().r(w.edge_head.x()).r(w.edge_head.y()).r(w.edge_head.z()).r(w.lenl).r(w.lenm).str();
    }
  }
}

void write_boundaries_and_loads(const model::Model& m, std::string& o) {
  for (const auto& s : m.spcs) {
    const bool with_id = s.id != 0 || !s.title.empty();
    const std::string kw = s.node ? "*BOUNDARY_SPC_NODE" : "*BOUNDARY_SPC_SET";
    o += with_id ? kw + "_ID\n" + id_heading(s.id, s.title) : kw + "\n";
    o += s.node ? "$#     NID       CID      DOFX      DOFY      DOFZ     DOFRX     DOFRY     DOFRZ\n"
                : "$#    NSID       CID      DOFX      DOFY      DOFZ     DOFRX     DOFRY     DOFRZ\n";
    CardOut c;
    c.i(s.nsid).i(s.cid);
    for (int d : s.dof) c.i(d);
    o += c.str();
  }
  for (const auto& p : m.prescribed_motions) {
    using Target = model::PrescribedMotion::Target;
    const bool with_id = p.id != 0 || !p.title.empty();
    const std::string kw = std::string("*BOUNDARY_PRESCRIBED_MOTION_") +
                           (p.target == Target::set ? "SET" : p.target == Target::node ? "NODE" : "RIGID");
    o += with_id ? kw + "_ID\n" + id_heading(p.id, p.title) : kw + "\n";
    o += p.target == Target::set    ? "$#    NSID"
         : p.target == Target::node ? "$#     NID"
                                    : "$#     PID";
    o += "       DOF       VAD      LCID        SF       VID     DEATH     BIRTH\n";
    o += CardOut().i(p.nsid).i(p.dof).i(p.vad).i(p.lcid).r(p.sf).i(p.vid).r(p.death).r(p.birth).str();
  }
  for (const auto& l : m.nodal_loads) {
    o += l.set ? "*LOAD_NODE_SET\n$#    NSID       DOF      LCID        SF       CID        M1        M2        M3\n"
               : "*LOAD_NODE_POINT\n$#     NID       DOF      LCID        SF       CID        M1        M2        M3\n";
    o += CardOut().i(l.id).i(l.dof).i(l.lcid).r(l.sf).i(l.cid).i(l.m[0]).i(l.m[1]).i(l.m[2]).str();
  }
  for (const auto& l : m.body_loads) {
    o += std::string("*LOAD_BODY_") + (l.axis == Axis::x ? "X" : l.axis == Axis::y ? "Y" : "Z") + "\n";
    o += "$#    LCID        SF    LCIDDR        XC        YC        ZC       CID\n";
    o += CardOut().i(l.lcid).r(l.sf).i(l.lciddr).r(l.xc).r(l.yc).r(l.zc).i(l.cid).str();
  }
  write_initial_velocities(m, o);
  write_rigid_walls(m, o);
  if (m.body_load_parts) o += "*LOAD_BODY_PARTS\n$#    PSID\n" + CardOut().i(m.body_load_parts->psid).str();
}

/// Mass and stiffness damping.
void write_damping(const model::Model& m, std::string& o) {
  if (m.damping_global) {
    const auto& d = *m.damping_global;
    o += "*DAMPING_GLOBAL\n$#    LCID    VALDMP       STX       STY       STZ       SRX       SRY       SRZ\n";
    CardOut c;
    c.i(d.lcid).r(d.valdmp);
    for (Real s : d.stf) c.r(s);
    o += c.str();
  }
  for (const auto& d : m.damping_parts) {
    o += d.set ? "*DAMPING_PART_MASS_SET\n$#    PSID      LCID        SF      FLAG\n"
               : "*DAMPING_PART_MASS\n$#     PID      LCID        SF      FLAG\n";
    o += CardOut().i(d.pid).i(d.lcid).r(d.sf).i(d.flag).str();
    if (d.flag == 1) {
      o += "$#     STX       STY       STZ       SRX       SRY       SRZ\n";
      CardOut c;
      for (Real s : d.stf) c.r(s);
      o += c.str();
    }
  }
  for (const auto& d : m.damping_stiffness) {
    o += d.set ? "*DAMPING_PART_STIFFNESS_SET\n$#    PSID      COEF\n"
               : "*DAMPING_PART_STIFFNESS\n$#     PID      COEF\n";
    o += CardOut().i(d.pid).r(d.coef).str();
  }
}

/// Load curves and boxes.
void write_curves_and_boxes(const model::Model& m, std::string& o) {
  for (const auto& cv : m.curves) {
    o += cv.title.empty() ? "*DEFINE_CURVE\n" : "*DEFINE_CURVE_TITLE\n" + heading(cv.title);
    o += "$#    LCID      SIDR       SFA       SFO      OFFA      OFFO    DATTYP\n";
    o += CardOut().i(cv.lcid).i(cv.sidr).r(cv.sfa).r(cv.sfo).r(cv.offa).r(cv.offo).i(cv.dattyp).str();
    o += "$#                 A                   O\n";
    for (const auto& [a, v] : cv.points) o += CardOut(kCurvePoint).r(a).r(v).str();
  }
  for (const auto& box : m.boxes) {
    o += box.title.empty() ? "*DEFINE_BOX\n" : "*DEFINE_BOX_TITLE\n" + heading(box.title);
    o += "$#   BOXID       XMN       XMX       YMN       YMX       ZMN       ZMX\n";
    o += CardOut().i(box.boxid).r(box.min[0]).r(box.max[0]).r(box.min[1]).r(box.max[1]).r(box.min[2]).r(box.max[2]).str();
  }
}

/// Local coordinate systems, each in the form the deck gave it.
void write_coordinate_systems(const model::Model& m, std::string& o) {
  using Kind = model::CoordinateSystem::Kind;
  for (const auto& s : m.coordinate_systems) {
    const char* kw = s.kind == Kind::points  ? "*DEFINE_COORDINATE_SYSTEM"
                     : s.kind == Kind::nodes ? "*DEFINE_COORDINATE_NODES"
                                             : "*DEFINE_COORDINATE_VECTOR";
    o += std::string(kw) + (s.title.empty() ? "\n" : "_TITLE\n" + heading(s.title));
    switch (s.kind) {
      case Kind::points:
        o += "$#     CID        X0        Y0        Z0        XL        YL        ZL      CIDL\n";
        o += CardOut().i(s.cid).r(s.origin[0]).r(s.origin[1]).r(s.origin[2]).r(s.axis[0]).r(s.axis[1]).r(s.axis[2])
                 .i(s.cidl).str();
        o += "$#      XP        YP        ZP\n" + CardOut().r(s.plane[0]).r(s.plane[1]).r(s.plane[2]).str();
        break;
      case Kind::nodes: {
        static const char* const dirs[] = {"X", "Y", "Z"};
        o += "$#     CID        N1        N2        N3      FLAG       DIR\n";
        std::string c = CardOut().i(s.cid).i(s.nodes[0]).i(s.nodes[1]).i(s.nodes[2]).i(s.flag).str();
        c.pop_back();  // the newline; DIR is text, right-aligned in its field (or after a comma)
        o += c + (c.find(',') != std::string::npos ? std::string(",") : std::string(9, ' ')) + dirs[s.dir] + "\n";
        break;
      }
      case Kind::vectors:
        o += "$#     CID        XX        YX        ZX        XV        YV        ZV       NID\n";
        o += CardOut().i(s.cid).r(s.axis[0]).r(s.axis[1]).r(s.axis[2]).r(s.plane[0]).r(s.plane[1]).r(s.plane[2])
                 .i(s.nodes[0]).str();
        break;
    }
  }
}

/// Nodes and elements.
void write_mesh(const model::Model& m, std::string& o) {
  if (!m.nodes.empty()) {
    o += "*NODE\n$#   NID               X               Y               Z      TC      RC\n";
    for (const auto& n : m.nodes)
      o += CardOut(kNodeCard).i(n.id).r(n.x[0]).r(n.x[1]).r(n.x[2]).i(n.tc).i(n.rc).str();
  }
  if (!m.solids.empty()) {
    o += "*ELEMENT_SOLID\n$#   EID     PID      N1      N2      N3      N4      N5      N6      N7      N8\n";
    for (const auto& e : m.solids) {
      CardOut c(kElementCard);
      c.i(e.id).i(e.pid);
      for (Id n : e.n) c.i(n);
      o += c.str();
    }
  }
  if (!m.shells.empty()) {
    o += "*ELEMENT_SHELL\n$#   EID     PID      N1      N2      N3      N4\n";
    for (const auto& e : m.shells) o += CardOut(kElementCard).i(e.id).i(e.pid).i(e.n[0]).i(e.n[1]).i(e.n[2]).i(e.n[3]).str();
  }
}

}  // namespace

std::string write_keyword_string(const model::Model& m) {
  std::string o = "*KEYWORD\n";
  if (!m.title.empty()) o += "*TITLE\n" + heading(m.title);
  write_controls(m, o);
  write_database(m, o);
  write_parts(m, o);
  write_sets(m, o);
  write_boundaries_and_loads(m, o);
  write_damping(m, o);
  write_curves_and_boxes(m, o);
  write_coordinate_systems(m, o);
  write_contacts(m, o);
  write_mesh(m, o);
  o += "*END\n";
  return o;
}

void write_keyword_file(const model::Model& model, const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw Error(path + ": cannot open for writing");
  out << write_keyword_string(model);
  if (!out) throw Error(path + ": write failed");
}

}  // namespace slideline
