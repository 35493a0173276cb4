// Card handlers of the plasticity and null materials (*MAT_PLASTIC_KINEMATIC,
// *MAT_PIECEWISE_LINEAR_PLASTICITY, *MAT_NULL); the keyword table that dispatches to them is
// keyword_table.cpp. Field orders follow the LS-DYNA keyword manual (docs/keywords.md).
#include <string>
#include <utility>

#include "keyword_card.hpp"
#include "slideline/core/error.hpp"

namespace slideline::keyword {

using model::Model;

namespace {

/// The failure strain of field `name` (column `col` of `c`) as the model keeps it: 0 for one no
/// element reaches, 0 (LS-DYNA: "failure is not considered") or the manual's default 1e21 and
/// anything from 1e20 up (deck writers print the default); else the strain at which elements
/// erode (docs/solver.md, "Failure and erosion"). A negative value (LS-DYNA: a user failure
/// subroutine) is refused.
Real failure_strain(const Context& ctx, const Block& b, const Card& c, int col, const char* name) {
  Real strain = 0.0;
  c.get(col, name, strain);
  if (strain < 0.0)
    throw NotImplementedError(ctx.where(c.line()) + b.keyword + ": field " + name + " = " + std::string(c.raw(col)) +
                              " (a user failure subroutine) is not implemented; give the failure strain (> 0), or"
                              " leave it blank, 0 or 1e21 (no failure)");
  return strain >= 1e20 ? 0.0 : strain;
}

}  // namespace

void read_mat_plastic_kinematic(const Context& ctx, Block& b, Model& m, bool titled) {
  read_material<model::MatPlasticKinematic>(ctx, b, m, titled, [&](const Card& c, model::MatPlasticKinematic& mat) {
    c.get(0, "MID", mat.mid);
    c.get(1, "RO", mat.ro);
    c.get(2, "E", mat.e);
    c.get(3, "PR", mat.pr);
    c.get(4, "SIGY", mat.sigy);
    c.get(5, "ETAN", mat.etan);
    c.get(6, "BETA", mat.beta);
    const Line* l2 = b.take();
    if (!l2) return;
    Card c2 = Card(ctx, *l2, b.keyword, kStandard);
    c2.get(0, "SRC", mat.src_c);
    c2.get(1, "SRP", mat.srp);
    Real vp = 0.0;
    mat.fs = failure_strain(ctx, b, c2, 2, "FS");  // erodes elements at that plastic strain
    c2.get(3, "VP", vp);
    // VP = 1 (viscoplastic) and -1 (deviatoric rate) are other rate formulations. Running without
    // them would be another material: refused.
    if (vp != 0.0)
      throw NotImplementedError(ctx.where(l2->number) + b.keyword +
                                ": field VP = " + std::string(c2.raw(3)) +
                                " is not implemented (only VP = 0: the yield stress scaled by the total strain rate)");
  });
}

void read_mat_piecewise_linear(const Context& ctx, Block& b, Model& m, bool titled) {
  using Mat = model::MatPiecewiseLinearPlasticity;
  read_material<Mat>(ctx, b, m, titled, [&](const Card& c, Mat& mat) {
    c.get(0, "MID", mat.mid);
    c.get(1, "RO", mat.ro);
    c.get(2, "E", mat.e);
    c.get(3, "PR", mat.pr);
    c.get(4, "SIGY", mat.sigy);
    c.get(5, "ETAN", mat.etan);
    // FAIL erodes elements at a plastic strain (0 and the default 1e21: never); TDEL erodes
    // elements whose stable step falls below it (0: never; docs/solver.md, "Failure and erosion").
    mat.fail = failure_strain(ctx, b, c, 6, "FAIL");
    c.get(7, "TDEL", mat.tdel);
    if (mat.tdel < 0.0)
      throw InputError(ctx.where(c.line()) + b.keyword + ": card 1 field TDEL = " + std::string(c.raw(7)) +
                       " must be >= 0 (the smallest element step kept; blank or 0: none)");
    const Line* l2 = b.take();
    if (!l2) return;
    Card c2 = Card(ctx, *l2, b.keyword, kStandard);
    c2.get(0, "C", mat.c);
    c2.get(1, "P", mat.p);
    c2.get(2, "LCSS", mat.lcss);
    c2.get(3, "LCSR", mat.lcsr);
    c2.get(4, "VP", mat.vp);
    Id lcf = 0;
    c2.get(5, "LCF", lcf);
    if (mat.vp != 0.0 && mat.vp != 1.0)
      throw NotImplementedError(ctx.where(l2->number) + b.keyword + ": field VP = " + std::string(c2.raw(4)) +
                                " is not implemented (0: total strain rate, 1: viscoplastic)");
    if (lcf != 0)
      throw NotImplementedError(ctx.where(l2->number) + b.keyword + ": field LCF (failure curve) is not implemented");
    if (mat.lcsr != 0 && mat.c != 0.0)
      throw InputError(ctx.where(l2->number) + b.keyword + ": give the rate scaling either by C and P or by LCSR, not both");
    static const char* const eps_names[] = {"EPS1", "EPS2", "EPS3", "EPS4", "EPS5", "EPS6", "EPS7", "EPS8"};
    static const char* const es_names[] = {"ES1", "ES2", "ES3", "ES4", "ES5", "ES6", "ES7", "ES8"};
    for (auto [names, out] : {std::pair{eps_names, &mat.eps}, std::pair{es_names, &mat.es}}) {
      const Line* l = b.take();
      if (!l) return;
      Card ct = Card(ctx, *l, b.keyword, kStandard);
      for (int k = 0; k < 8; ++k) ct.get(k, names[k], (*out)[static_cast<std::size_t>(k)]);
    }
  });
}

void read_mat_null(const Context& ctx, Block& b, Model& m, bool titled) {
  read_material<model::MatNull>(ctx, b, m, titled, [&](const Card& c, model::MatNull& mat) {
    c.get(0, "MID", mat.mid);
    c.get(1, "RO", mat.ro);
    // PC, MU, TEROD, CEROD act on solids (with an equation of state), YM and PR on shells:
    // validate_parts refuses each on the other kind.
    c.get(2, "PC", mat.pc);
    c.get(3, "MU", mat.mu);
    c.get(4, "TEROD", mat.terod);
    c.get(5, "CEROD", mat.cerod);
    c.get(6, "YM", mat.ym);
    c.get(7, "PR", mat.pr);
  });
}

}  // namespace slideline::keyword
