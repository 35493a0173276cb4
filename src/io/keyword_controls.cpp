// *CONTROL_... cards: hourglass, bulk viscosity, termination, time step and contact. Fields whose
// manual default is not 0 take the default for 0 as for blank (Card::get_or_default).
#include <string>
#include <string_view>

#include "keyword_card.hpp"
#include "slideline/core/error.hpp"

namespace slideline::keyword {
namespace {

using model::Model;

}  // namespace

void read_control_hourglass(const Context& ctx, Block& b, Model& m) {
  single_card(ctx, b, [&](const Card& k, const Line&) {
    k.get_or_default(0, "IHQ", m.control_hourglass.ihq);
    k.get_or_default(1, "QH", m.control_hourglass.qh);
  });
}

void read_control_bulk_viscosity(const Context& ctx, Block& b, Model& m) {
  single_card(ctx, b, [&](const Card& k, const Line& l) {
    k.get_or_default(0, "Q1", m.bulk_viscosity.q1);
    k.get_or_default(1, "Q2", m.bulk_viscosity.q2);
    // TYPE (default 1): the bulk viscosity here acts on solids and on shells alike, which is
    // LS-DYNA's -1 and -2 (-2 without its energy); 1 leaves shells out there (docs/keywords.md).
    int type = 1;
    k.get_or_default(2, "TYPE", type);
    if (type != 1 && type != -1 && type != -2)
      throw NotImplementedError(ctx.where(l.number) + b.keyword + " card 1: field TYPE = " + std::to_string(type) +
                                " (bulk viscosity type) is not implemented; give 1, -1 or -2");
    check_unread_fields(ctx, l, b.keyword, StoredCard::control_bulk_viscosity);
  });
}

void read_control_fields(const Context& ctx, Block& b, Model& m) {
  // *CONTROL_SHELL ESORT (card 1, field 2) is stored: whether triangles run as C0 (0, 1) or DKT (2,
  // refused by the part checks where triangles exist); the other fields are checked as a whole.
  if (b.keyword == "*CONTROL_SHELL" && !b.done()) {
    const Line& l = b.cards[b.next];
    const Card k(ctx, l, b.keyword, kStandard);
    k.get(1, "ESORT", m.shell_esort);
    if (m.shell_esort < 0 || m.shell_esort > 2)
      throw InputError(ctx.where(l.number) + "*CONTROL_SHELL card 1: field ESORT = " + std::to_string(m.shell_esort) +
                       " must be 0, 1 or 2");
    m.shell_esort_src = ctx.source(l.number);
    // ISTUPD (field 4): 1 and 4 are stored (the shell blocks follow their thickness); 2 and 3 ask
    // it of thick shells (8-node *SECTION_TSHELL), which are not implemented.
    k.get(3, "ISTUPD", m.shell_istupd);
    if (m.shell_istupd != 0 && m.shell_istupd != 1 && m.shell_istupd != 4)
      throw NotImplementedError(ctx.where(l.number) + "*CONTROL_SHELL card 1: field ISTUPD = " +
                                std::to_string(m.shell_istupd) +
                                " (shell thickness change) is not implemented; give 0, 1 (membrane straining "
                                "changes the thickness) or 4 (its plastic part alone)");
    m.shell_istupd_src = ctx.source(l.number);
    // Card 2, field 2: INTGRD, the through-thickness rule (0 Gauss, 1 Lobatto).
    if (b.next + 1 < b.cards.size()) {
      const Line& l2 = b.cards[b.next + 1];
      const Card k2(ctx, l2, b.keyword, kStandard);
      k2.get(1, "INTGRD", m.shell_intgrd);
      if (m.shell_intgrd != 0 && m.shell_intgrd != 1)
        throw InputError(ctx.where(l2.number) + "*CONTROL_SHELL card 2: field INTGRD = " +
                         std::to_string(m.shell_intgrd) + " must be 0 (Gauss) or 1 (Lobatto)");
    }
  }
  // *CONTROL_ACCURACY INN (card 1, field 2) is stored: invariant node numbering of shells and solids.
  if (b.keyword == "*CONTROL_ACCURACY" && !b.done()) {
    const Line& l = b.cards[b.next];
    const Card k(ctx, l, b.keyword, kStandard);
    k.get(1, "INN", m.accuracy_inn);
    if (m.accuracy_inn == 0) m.accuracy_inn = 1;  // blank and 0: the default, off
    if (m.accuracy_inn < -4 || m.accuracy_inn > 4 || m.accuracy_inn == -1 || m.accuracy_inn == -3)
      throw InputError(ctx.where(l.number) + "*CONTROL_ACCURACY card 1: field INN = " + std::to_string(m.accuracy_inn) +
                       " must be 1 (off), 2 or -2 (shells), 3 (solids), 4 or -4 (both)");
    m.accuracy_inn_src = ctx.source(l.number);
  }
  // *CONTROL_SOLID ESORT (card 1, field 1) is stored: the part checks refuse 1 where it would sort.
  if (b.keyword == "*CONTROL_SOLID" && !b.done()) {
    const Line& l = b.cards[b.next];
    const Card k(ctx, l, b.keyword, kStandard);
    k.get(0, "ESORT", m.solid_esort);
    if (m.solid_esort != 0 && m.solid_esort != 1)
      throw NotImplementedError(ctx.where(l.number) + "*CONTROL_SOLID card 1: field ESORT = " +
                                std::to_string(m.solid_esort) + " is not implemented; give 0 or 1");
    m.solid_esort_src = ctx.source(l.number);
  }
  check_control_fields(ctx, b);
}

void read_control_termination(const Context& ctx, Block& b, Model& m) {
  m.termination.src = ctx.source(b.line);
  single_card(ctx, b, [&](const Card& k, const Line& l) {
    m.termination.src = ctx.source(l.number);
    k.get(0, "ENDTIM", m.termination.endtim);
    k.get(1, "ENDCYC", m.termination.endcyc);
    k.get(2, "DTMIN", m.termination.dtmin);
    k.get(3, "ENDENG", m.termination.endeng);
    k.get_or_default(4, "ENDMAS", m.termination.endmas);
    check_unread_fields(ctx, l, b.keyword, StoredCard::control_termination);
  });
}

void read_control_timestep(const Context& ctx, Block& b, Model& m) {
  auto& t = m.timestep;
  t.src = ctx.source(b.line);
  if (const Line* l1 = b.take()) {
    const Line& l = *l1;
    const Card k(ctx, l, b.keyword, kStandard);
    t.src = ctx.source(l.number);
    k.get(0, "DTINIT", t.dtinit);
    k.get_or_default(1, "TSSFAC", t.tssfac);
    k.get(2, "ISDO", t.isdo);
    k.get(3, "TSLIMT", t.tslimt);
    k.get(4, "DT2MS", t.dt2ms);
    k.get(5, "LCTM", t.lctm);
    k.get(6, "ERODE", t.erode);
    k.get(7, "MS1ST", t.ms1st);
    // Read (the writer keeps them) but not honoured by the solver: say so. These only choose the
    // step (the stable step is always respected); DT2MS (mass scaling, once with MS1ST = 1, every
    // cycle with MS1ST = 0: docs/solver.md, "Mass scaling") and LCTM are the builder's business.
    const auto ignored = [&](bool set, const char* field, const char* what) {
      if (set)
        ctx.warn(l.number, std::string("*CONTROL_TIMESTEP: field ") + field + " (" + what +
                               ") is read but not honoured; the run does without it");
    };
    ignored(t.dtinit != 0.0, "DTINIT", "initial time step");
    ignored(t.isdo != 0, "ISDO", "shell time-step length option");
    // TSLIMT lowers the moduli of shells whose step falls below it (LS-DYNA: elastic-plastic
    // shells): physics, not implemented.
    if (t.tslimt != 0.0)
      throw NotImplementedError(ctx.where(l.number) + "*CONTROL_TIMESTEP card 1: field TSLIMT = " +
                                std::string(k.raw(3)) + " (shell minimum time step: lowers the moduli of shells whose "
                                "step falls below it) is not implemented; running without it would be a different "
                                "model (leave it blank or give its default 0)");
    if (t.erode != 0 && t.erode != 1)
      throw InputError(ctx.where(l.number) + "*CONTROL_TIMESTEP card 1: field ERODE = " + std::string(k.raw(6)) +
                       " must be 0 or 1");
    if (t.ms1st != 0 && t.ms1st != 1)
      throw InputError(ctx.where(l.number) + "*CONTROL_TIMESTEP card 1: field MS1ST = " + std::to_string(t.ms1st) +
                       " must be 0 or 1");
    check_unread_fields(ctx, l, b.keyword, StoredCard::control_timestep);
  }
  // Card 2: mass-scaling options (refused) and the solid time-step method (warned).
  if (const Line* l2 = b.take()) check_unread_fields(ctx, *l2, b.keyword, StoredCard::control_timestep_card2);
  warn_extra_cards(ctx, b);
}

void read_control_contact(const Context& ctx, Block& b, Model& m) {
  auto& t = m.control_contact;
  int line = b.line;
  if (const Line* l = b.take()) {
    Card k(ctx, *l, b.keyword, kStandard);
    line = l->number;
    k.get_or_default(0, "SLSFAC", t.slsfac);
    k.get(1, "RWPNAL", t.rwpnal);
    k.get_or_default(2, "ISLCHK", t.islchk);
    k.get(3, "SHLTHK", t.shlthk);
    k.get_or_default(4, "PENOPT", t.penopt);
    k.get(5, "THKCHG", t.thkchg);
    k.get_or_default(6, "ORIEN", t.orien);
    k.get(7, "ENMASS", t.enmass);
  }
  // Cards 2-6: each field at its default, refused or warned about (keyword_contact_fields.cpp).
  read_control_contact_cards(ctx, b, t, line);
}

}  // namespace slideline::keyword
