#pragma once
/// Bulk viscosity of a shell element (shell_block.hpp): a pressure over the thickness on the
/// membrane dilatation rate, kept apart from the block (its size).
#include "slideline/core/types.hpp"
#include "slideline/element/block_options.hpp"
#include "slideline/element/shell_bt.hpp"

namespace slideline::shell_bulk_viscosity {

/// The bulk viscosity q = rho len (Q2 len trd^2 - Q1 c trd) of an element compressing in its plane
/// (trd, the membrane dilatation rate, < 0; else none) of characteristic length `len`, area `area`
/// and thickness `t`: q t is subtracted from the membrane resultants `r`. Its power is added to
/// `p_visc` and the power of the last evaluation's (`prev`: its q t A, replaced by this one's) at
/// this step's rate to `p_prev`: their mean is the step's trapezoidal work, as the ledger's nodal
/// work is (docs/solver.md, "Energies"). Returns its term of the step, len / (qdt + sqrt(qdt^2 + c^2)):
/// qdt = Q1 c + Q2 len |trd|. `rho` density, `c` wave speed.
inline Real add(Real rho, Real c, const BulkViscosity& bulk, Real trd, Real len, Real area, Real t,
                shell_bt::Resultants& r, Real& p_visc, Real& p_prev, Real& prev) {
  p_prev += -prev * trd;
  prev = 0.0;
  if (!(trd < 0.0)) return 0.0;
  const Real q = rho * len * (bulk.quadratic * len * trd * trd - bulk.linear * c * trd);
  r.n[0] -= q * t;
  r.n[1] -= q * t;
  p_visc += -q * trd * area * t;
  prev = q * area * t;
  return bulk.linear * c + bulk.quadratic * len * (-trd);
}

}  // namespace slideline::shell_bulk_viscosity
