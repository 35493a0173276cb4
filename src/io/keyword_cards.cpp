// Card handlers of the keyword reader (but *CONTACT_..., *CONTROL_..., *INITIAL_..., *PARAMETER); the
// keyword table that dispatches to them is keyword_table.cpp.
// Field orders follow the LS-DYNA keyword manual (docs/keywords.md lists them with sources).
#include <cstdlib>
#include <string>

#include "keyword_card.hpp"
#include "slideline/core/error.hpp"

namespace slideline::keyword {
namespace {

using model::Model;

Card card_of(const Context& ctx, const Line& l, const Block& b,
             std::span<const int> widths = kStandard) {
  return Card(ctx, l, b.keyword, widths);
}

/// The next card, or throws when a block lacks a card it must have.
const Line& require(const Context& ctx, Block& b, const char* what) {
  const Line* l = b.take();
  if (!l)
    throw InputError(ctx.file + ":" + std::to_string(b.line) + ": " + b.keyword + ": missing " +
                     what + " card");
  return *l;
}

/// Skips blank cards; returns the next non-blank card or nullptr. Used by keywords that repeat a
/// record until the next keyword, where a trailing blank line is not a record.
const Line* next_record(Block& b) {
  while (const Line* l = b.take())
    if (!trim(l->text).empty()) return l;
  return nullptr;
}

/// Like next_record, but a blank card counts when a non-blank card follows it: the first card of
/// a record may be a blank heading (an untitled *PART, an empty _TITLE).
const Line* next_record_keep_blank(Block& b) {
  for (std::size_t k = b.next; k < b.cards.size(); ++k)
    if (!trim(b.cards[k].text).empty()) return b.take();
  b.next = b.cards.size();
  return nullptr;
}

}  // namespace

const Line& require_card(const Context& ctx, Block& b, const char* what) { return require(ctx, b, what); }

void read_title(const Context&, Block& b, Model& m) {
  if (const Line* l = b.take()) m.title = heading(*l);
}

void read_nodes(const Context& ctx, Block& b, Model& m) {
  while (const Line* l = next_record(b)) {
    Card c = card_of(ctx, *l, b, kNodeCard);
    model::Node n;
    c.get(0, "NID", n.id);
    c.get(1, "X", n.x[0]);
    c.get(2, "Y", n.x[1]);
    c.get(3, "Z", n.x[2]);
    c.get(4, "TC", n.tc);
    c.get(5, "RC", n.rc);
    m.nodes.push_back(n);
  }
}

static const char* const kNodeNames[] = {"N1", "N2", "N3", "N4", "N5", "N6", "N7", "N8"};

void read_solids(const Context& ctx, Block& b, Model& m) {
  while (const Line* l = next_record(b)) {
    Card c = card_of(ctx, *l, b, kElementCard);
    model::SolidElement e;
    e.at.line = l->number;
    e.at.file = ctx.file_index;
    c.get(0, "EID", e.id);
    c.get(1, "PID", e.pid);
    bool nodes_blank = true;
    for (int k = 2; k < 10; ++k) nodes_blank = nodes_blank && c.blank(k);
    if (nodes_blank && !b.done()) {
      // Two-card layout: EID PID on the first card, N1..N8 on the second.
      const Line& l2 = require(ctx, b, "node");
      Card c2 = card_of(ctx, l2, b, kElementCard);
      for (int k = 0; k < 8; ++k) c2.get(k, kNodeNames[k], e.n[static_cast<std::size_t>(k)]);
    } else {
      for (int k = 0; k < 8; ++k) c.get(k + 2, kNodeNames[k], e.n[static_cast<std::size_t>(k)]);
    }
    m.solids.push_back(e);
  }
}

void read_shells(const Context& ctx, Block& b, Model& m) {
  while (const Line* l = next_record(b)) {
    Card c = card_of(ctx, *l, b, kElementCard);
    model::ShellElement e;
    e.at.line = l->number;
    e.at.file = ctx.file_index;
    c.get(0, "EID", e.id);
    c.get(1, "PID", e.pid);
    for (int k = 0; k < 4; ++k) c.get(k + 2, kNodeNames[k], e.n[static_cast<std::size_t>(k)]);
    m.shells.push_back(e);
  }
}

void read_parts(const Context& ctx, Block& b, Model& m) {
  while (const Line* h = next_record_keep_blank(b)) {
    model::Part p;
    p.title = heading(*h);
    const Line& l = require(ctx, b, "PID");
    Card c = card_of(ctx, l, b);
    c.get(0, "PID", p.pid);
    c.get(1, "SECID", p.secid);
    c.get(2, "MID", p.mid);
    c.get(3, "EOSID", p.eosid);
    c.get(4, "HGID", p.hgid);
    check_unread_fields(ctx, l, b.keyword, StoredCard::part);
    p.src = ctx.source(l.number);
    m.parts.push_back(p);
  }
}

namespace {

/// Calls `record(card line)` for each record of a keyword whose _TITLE option puts a heading
/// card before each record.
template <class F>
void each_titled(const Context& ctx, Block& b, bool titled, F&& record) {
  while (const Line* first = titled ? next_record_keep_blank(b) : next_record(b)) {
    std::string title;
    const Line* l = first;
    if (titled) {
      title = heading(*first);
      l = &require(ctx, b, "data");
    }
    record(*l, title);
  }
}

/// ELFORM 101-105 (user-defined elements) take cards of their own (NIP NXDOF ... then LMC
/// properties) that are not read: refused here, before they could be read as the next section.
/// The rest of the keyword is skipped with it.
void refuse_user_element(const Context& ctx, const Line& l, const Block& b, int elform) {
  if (elform >= 101 && elform <= 105)
    throw NotImplementedError(ctx.where(l.number) + "field ELFORM of " + b.keyword + ": " + std::to_string(elform) +
                              " (a user-defined element) is not supported; its extra cards are not read, so the "
                              "keyword is skipped whole");
}

}  // namespace

void read_section_solid(const Context& ctx, Block& b, Model& m, bool titled) {
  each_titled(ctx, b, titled, [&](const Line& l, const std::string&) {
    Card c = card_of(ctx, l, b);
    model::SectionSolid s;
    c.get(0, "SECID", s.secid);
    c.get_or_default(1, "ELFORM", s.elform);
    refuse_user_element(ctx, l, b, s.elform);
    check_section_fields(ctx, l, nullptr, b.keyword, false);
    s.src = ctx.source(l.number);
    m.solid_sections.push_back(s);
  });
}

void read_section_shell(const Context& ctx, Block& b, Model& m, bool titled) {
  each_titled(ctx, b, titled, [&](const Line& l, const std::string&) {
    Card c = card_of(ctx, l, b);
    model::SectionShell s;
    c.get(0, "SECID", s.secid);
    c.get_or_default(1, "ELFORM", s.elform);
    refuse_user_element(ctx, l, b, s.elform);
    c.get_or_default(2, "SHRF", s.shrf);
    c.get_or_default(3, "NIP", s.nip);
    c.get_or_default(4, "PROPT", s.propt);
    const Line* l2 = b.take();
    if (l2) {
      static const char* const names[] = {"T1", "T2", "T3", "T4"};
      for (int k = 0; k < 4; ++k) card_of(ctx, *l2, b).get(k, names[k], s.t[static_cast<std::size_t>(k)]);
    }
    check_section_fields(ctx, l, l2, b.keyword, true);
    s.src = ctx.source(l.number);
    m.shell_sections.push_back(s);
  });
}

void read_mat_elastic(const Context& ctx, Block& b, Model& m, bool titled) {
  read_material<model::MatElastic>(ctx, b, m, titled, StoredCard::mat_elastic, [](const Card& c, model::MatElastic& mat) {
    c.get(0, "MID", mat.mid);
    c.get(1, "RO", mat.ro);
    c.get(2, "E", mat.e);
    c.get(3, "PR", mat.pr);
  });
}

void read_mat_mooney_rivlin(const Context& ctx, Block& b, Model& m, bool titled) {
  read_material<model::MatMooneyRivlin>(ctx, b, m, titled, StoredCard::mat_mooney_rivlin,
                                         [&](const Card& c, model::MatMooneyRivlin& mat) {
    c.get(0, "MID", mat.mid);
    c.get(1, "RO", mat.ro);
    c.get(2, "PR", mat.pr);
    c.get(3, "A", mat.a);
    c.get(4, "B", mat.b);
    // Card 2 (SGL SW ST LCID) fits A and B to test data. LS-DYNA then computes A and B from the
    // curve (the card's own A and B are not used), so running with the given A and B would be
    // another material: refused.
    if (const Line* l2 = b.take()) {
      Card c2 = card_of(ctx, *l2, b);
      Id lcid = 0;
      c2.get(3, "LCID", lcid);
      if (lcid != 0)
        throw NotImplementedError(ctx.where(l2->number) + b.keyword +
                                  ": fitting A and B to the force-extension curve LCID is not implemented; "
                                  "give A and B and leave LCID blank");
    }
  });
}

void read_mat_rigid(const Context& ctx, Block& b, Model& m, bool titled) {
  read_material<model::MatRigid>(ctx, b, m, titled, StoredCard::mat_rigid, [&](const Card& c, model::MatRigid& mat) {
    c.get(0, "MID", mat.mid);
    c.get(1, "RO", mat.ro);
    c.get(2, "E", mat.e);
    c.get(3, "PR", mat.pr);
    if (const Line* l2 = b.take()) {
      Card c2 = card_of(ctx, *l2, b);
      c2.get(0, "CMO", mat.cmo);
      c2.get(1, "CON1", mat.con1);
      c2.get(2, "CON2", mat.con2);
    }
    b.take();  // card 3 (LCO or A1..V3, alignment for output) has no effect here
  });
}

void read_hourglass(const Context& ctx, Block& b, Model& m, bool titled) {
  each_titled(ctx, b, titled, [&](const Line& l, const std::string&) {
    Card c = card_of(ctx, l, b);
    model::Hourglass h;
    c.get(0, "HGID", h.hgid);
    c.get_or_default(1, "IHQ", h.ihq);
    c.get_or_default(2, "QM", h.qm);
    c.get_or_default(4, "Q1", h.q1);
    c.get_or_default(5, "Q2", h.q2);
    check_hourglass_fields(ctx, l, b.keyword, h.qm);
    h.src = ctx.source(l.number);
    m.hourglasses.push_back(h);
  });
}

namespace {

/// Reads the card after a set's first card: ids, 8 per card, until the next keyword.
template <class Out>
void read_id_list(const Context& ctx, Block& b, const char* name, Out& out) {
  while (const Line* l = b.take()) {
    Card c = card_of(ctx, *l, b);
    for (int k = 0; k < c.size(); ++k) {
      Id id = 0;
      c.get(k, name, id);
      if (id == 0) continue;
      // A list card has 8 fields; LS-DYNA would not read a 9th on a free-format line.
      if (k >= 8)
        throw InputError(ctx.where(l->number) + b.keyword + ": a list card holds at most 8 " + name +
                         " fields (got " + std::to_string(c.size()) + "); continue the list on the next line");
      out.push_back(id);
    }
  }
}

}  // namespace

void read_set_node(const Context& ctx, Block& b, Model& m, bool titled) {
  model::NodeSet s;
  if (titled) s.title = heading(require(ctx, b, "title"));
  const Line& l = require(ctx, b, "SID");
  card_of(ctx, l, b).get(0, "SID", s.sid);
  s.src = ctx.source(l.number);
  read_id_list(ctx, b, "NID", s.nodes);
  m.node_sets.push_back(std::move(s));
}

void read_set_part(const Context& ctx, Block& b, Model& m, bool titled) {
  model::PartSet s;
  if (titled) s.title = heading(require(ctx, b, "title"));
  const Line& l = require(ctx, b, "SID");
  card_of(ctx, l, b).get(0, "SID", s.sid);
  s.src = ctx.source(l.number);
  read_id_list(ctx, b, "PID", s.parts);
  m.part_sets.push_back(std::move(s));
}

void read_set_segment(const Context& ctx, Block& b, Model& m, bool titled) {
  model::SegmentSet s;
  if (titled) s.title = heading(require(ctx, b, "title"));
  const Line& l = require(ctx, b, "SID");
  card_of(ctx, l, b).get(0, "SID", s.sid);
  s.src = ctx.source(l.number);
  while (const Line* sl = next_record(b)) {
    Card c = card_of(ctx, *sl, b);
    std::array<Id, 4> seg{};
    for (int k = 0; k < 4; ++k) c.get(k, kNodeNames[k], seg[static_cast<std::size_t>(k)]);
    s.segments.push_back(seg);
  }
  m.segment_sets.push_back(std::move(s));
}

void read_spc(const Context& ctx, Block& b, Model& m, bool with_id, bool node) {
  const char* const first_field = node ? "NID" : "NSID";
  while (const Line* first = with_id ? next_record_keep_blank(b) : next_record(b)) {
    model::BoundarySpc s;
    s.node = node;
    const Line* l = first;
    if (with_id) {
      read_id_heading(ctx, *first, b.keyword, s.id, s.title);
      l = &require(ctx, b, first_field);
    }
    Card c = card_of(ctx, *l, b);
    c.get(0, first_field, s.nsid);
    c.get(1, "CID", s.cid);
    static const char* const names[] = {"DOFX", "DOFY", "DOFZ", "DOFRX", "DOFRY", "DOFRZ"};
    for (int k = 0; k < 6; ++k) c.get(k + 2, names[k], s.dof[static_cast<std::size_t>(k)]);
    s.src = ctx.source(l->number);
    m.spcs.push_back(s);
  }
}

/// *BOUNDARY_PRESCRIBED_MOTION_SET / _NODE / _RIGID: one card each, the first field names the
/// node set, the node or the rigid part.
void read_prescribed(const Context& ctx, Block& b, Model& m, bool with_id,
                     model::PrescribedMotion::Target target) {
  using Target = model::PrescribedMotion::Target;
  const char* first_field = target == Target::set ? "NSID" : target == Target::node ? "NID" : "PID";
  while (const Line* first = with_id ? next_record_keep_blank(b) : next_record(b)) {
    model::PrescribedMotion p;
    p.target = target;
    const Line* l = first;
    if (with_id) {
      read_id_heading(ctx, *first, b.keyword, p.id, p.title);
      l = &require(ctx, b, first_field);
    }
    Card c = card_of(ctx, *l, b);
    c.get(0, first_field, p.nsid);
    c.get(1, "DOF", p.dof);
    // DOF 9-11 (rotation about a line) adds a card (OFFSET1 OFFSET2 LRB NODE1 NODE2) that is not
    // read: refused here, before it could be read as the next motion; the rest of the keyword is skipped.
    if (std::abs(p.dof) >= 9 && std::abs(p.dof) <= 11)
      throw NotImplementedError(ctx.where(l->number) + "field DOF of " + b.keyword + ": " + std::to_string(p.dof) +
                                " (rotation about a line) is not supported; its extra card is not read, so the "
                                "keyword is skipped whole");
    c.get(2, "VAD", p.vad);
    c.get(3, "LCID", p.lcid);
    c.get_or_default(4, "SF", p.sf);
    c.get(5, "VID", p.vid);
    c.get_or_default(6, "DEATH", p.death);
    c.get(7, "BIRTH", p.birth);
    p.src = ctx.source(l->number);
    m.prescribed_motions.push_back(p);
  }
}

void read_load_node(const Context& ctx, Block& b, Model& m, bool set) {
  while (const Line* l = next_record(b)) {
    Card c = card_of(ctx, *l, b);
    model::LoadNode n;
    n.set = set;
    c.get(0, set ? "NSID" : "NID", n.id);
    c.get(1, "DOF", n.dof);
    c.get(2, "LCID", n.lcid);
    c.get_or_default(3, "SF", n.sf);
    c.get(4, "CID", n.cid);
    c.get(5, "M1", n.m[0]);
    c.get(6, "M2", n.m[1]);
    c.get(7, "M3", n.m[2]);
    n.src = ctx.source(l->number);
    m.nodal_loads.push_back(n);
  }
}

void read_load_body(const Context& ctx, Block& b, Model& m, Axis axis) {
  single_card(ctx, b, [&](const Card& c, const Line& l) {
    model::LoadBody lb;
    lb.axis = axis;
    c.get(0, "LCID", lb.lcid);
    c.get_or_default(1, "SF", lb.sf);
    c.get(2, "LCIDDR", lb.lciddr);
    c.get(3, "XC", lb.xc);
    c.get(4, "YC", lb.yc);
    c.get(5, "ZC", lb.zc);
    c.get(6, "CID", lb.cid);
    lb.src = ctx.source(l.number);
    m.body_loads.push_back(lb);
  });
}

void read_curve(const Context& ctx, Block& b, Model& m, bool titled) {
  model::Curve cv;
  if (titled) cv.title = heading(require(ctx, b, "title"));
  const Line& l = require(ctx, b, "LCID");
  Card c = card_of(ctx, l, b);
  c.get(0, "LCID", cv.lcid);
  c.get(1, "SIDR", cv.sidr);
  c.get_or_default(2, "SFA", cv.sfa);
  c.get_or_default(3, "SFO", cv.sfo);
  c.get(4, "OFFA", cv.offa);
  c.get(5, "OFFO", cv.offo);
  c.get(6, "DATTYP", cv.dattyp);
  check_unread_fields(ctx, l, b.keyword, StoredCard::define_curve);
  cv.src = ctx.source(l.number);
  while (const Line* pl = next_record(b)) {
    Card pc = card_of(ctx, *pl, b, kCurvePoint);
    std::pair<Real, Real> p{0.0, 0.0};
    pc.get(0, "A", p.first);
    pc.get(1, "O", p.second);
    cv.points.push_back(p);
  }
  m.curves.push_back(std::move(cv));
}

void read_box(const Context& ctx, Block& b, Model& m, bool titled) {
  model::Box box;
  if (titled) box.title = heading(require(ctx, b, "title"));
  const Line& l = require(ctx, b, "BOXID");
  Card c = card_of(ctx, l, b);
  c.get(0, "BOXID", box.boxid);
  static const char* const names[] = {"XMN", "XMX", "YMN", "YMX", "ZMN", "ZMX"};
  for (int k = 0; k < 3; ++k) {
    c.get(1 + 2 * k, names[2 * k], box.min[static_cast<std::size_t>(k)]);
    c.get(2 + 2 * k, names[2 * k + 1], box.max[static_cast<std::size_t>(k)]);
  }
  box.src = ctx.source(l.number);
  warn_extra_cards(ctx, b);
  m.boxes.push_back(std::move(box));
}

void read_damping_global(const Context& ctx, Block& b, Model& m) {
  single_card(ctx, b, [&](const Card& c, const Line& l) {
    model::DampingGlobal d;
    c.get(0, "LCID", d.lcid);
    c.get(1, "VALDMP", d.valdmp);
    static const char* const names[] = {"STX", "STY", "STZ", "SRX", "SRY", "SRZ"};
    for (int k = 0; k < 6; ++k) c.get(k + 2, names[k], d.stf[static_cast<std::size_t>(k)]);
    d.src = ctx.source(l.number);
    m.damping_global = d;
  });
}

void read_damping_part(const Context& ctx, Block& b, Model& m, bool set) {
  while (const Line* l = next_record(b)) {
    Card c = card_of(ctx, *l, b);
    model::DampingPartMass d;
    d.set = set;
    c.get(0, set ? "PSID" : "PID", d.pid);
    c.get(1, "LCID", d.lcid);
    c.get_or_default(2, "SF", d.sf);
    c.get(3, "FLAG", d.flag);
    d.src = ctx.source(l->number);
    if (d.flag != 0 && d.flag != 1)
      throw InputError(ctx.where(l->number) + "field FLAG of " + b.keyword + " must be 0 or 1 (got " +
                       std::to_string(d.flag) + ")");
    // FLAG = 1: a second card of per-direction scale factors (the builder decides what it can do).
    if (d.flag == 1) {
      const Line* s = next_record(b);
      if (!s)
        throw InputError(ctx.where(l->number) + b.keyword +
                         " with FLAG = 1 needs a card of scale factors STX STY STZ SRX SRY SRZ");
      Card k = card_of(ctx, *s, b);
      static const char* const names[] = {"STX", "STY", "STZ", "SRX", "SRY", "SRZ"};
      for (int q = 0; q < 6; ++q) k.get(q, names[q], d.stf[static_cast<std::size_t>(q)]);
    }
    m.damping_parts.push_back(d);
  }
}

/// *DAMPING_PART_STIFFNESS (PID COEF), or with _SET (PSID COEF): one record per card.
void read_damping_stiffness(const Context& ctx, Block& b, Model& m, bool set) {
  while (const Line* l = next_record(b)) {
    Card c = card_of(ctx, *l, b);
    model::DampingPartStiffness d;
    d.set = set;
    c.get(0, set ? "PSID" : "PID", d.pid);
    c.get(1, "COEF", d.coef);
    d.src = ctx.source(l->number);
    m.damping_stiffness.push_back(d);
  }
}

void read_load_body_parts(const Context& ctx, Block& b, Model& m) {
  single_card(ctx, b, [&](const Card& k, const Line& l) {
    model::LoadBodyParts p;
    k.get(0, "PSID", p.psid);
    p.src = ctx.source(l.number);
    m.body_load_parts = p;
  });
}

void read_database_history_node(const Context& ctx, Block& b, Model& m) {
  read_id_list(ctx, b, "ID", m.database.history_nodes);
}

void read_database_dt(const Context& ctx, Block& b, Real& dt) {
  single_card(ctx, b, [&](const Card& k, const Line&) { k.get(0, "DT", dt); });
}

}  // namespace slideline::keyword
