#pragma once
/// What every solid integration point adds to its law's stress besides the law (bulk viscosity,
/// stiffness damping) and the stable step of a solid, for the scalar (one element at a time)
/// solid kernels: the tetrahedron (tet_block.hpp) and the fully integrated hexahedron
/// (full_hex_block.hpp). The same formulas as the batched one-point hexahedron (hex_block.hpp).
#include <cmath>

#include "slideline/core/tensor3.hpp"
#include "slideline/core/types.hpp"
#include "slideline/element/block_options.hpp"

namespace slideline::solid_terms {

/// The block's constants: dilatational wave speed c (length/time), reference density rho0
/// (mass/length^3), Lame constants (force/length^2), bulk viscosity, damping coefficient beta (time).
struct Constants {
  Real c, rho0, lambda, mu;
  BulkViscosity bulk;
  Real beta;
};

/// The powers (force x length / time) of the terms added to one point's stress, and the viscous
/// term of its step (1/time x length, see stable_step).
struct Added {
  Real visc = 0.0, damp = 0.0, qdt = 0.0;
};

/// Adds to `sigma` the bulk viscosity of a compressing point (tr D < 0):
/// q = rho len (Q2 len trD^2 - Q1 c trD), and, when beta > 0, the damping stress
/// beta (lambda trD I + 2 mu D). `vol` the volume the point stands for, `rho` the current density,
/// `len` the characteristic length, `trd` tr D (1/time): the trace the bulk viscosity acts on
/// (the element's mean dilatation rate for a selective-reduced element).
inline Added add_viscous_stress(Tensor3<Real>& sigma, const Tensor3<Real>& d, Real trd, Real vol, Real rho,
                                Real len, const Constants& k) {
  Added a;
  if (trd < 0.0) {
    const Real q = rho * len * (k.bulk.quadratic * len * trd * trd - k.bulk.linear * k.c * trd);
    for (int i = 0; i < 3; ++i) sigma[i][i] -= q;
    a.visc = -q * trd * vol;
    a.qdt = k.bulk.linear * k.c + k.bulk.quadratic * len * (-trd);
  }
  if (k.beta > 0.0) {
    const Real trd_d = d[0][0] + d[1][1] + d[2][2];
    Real p = 0.0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const Real s = k.beta * (2.0 * k.mu * d[i][j] + (i == j ? k.lambda * trd_d : 0.0));
        sigma[i][j] += s;
        p += s * d[i][j];
      }
    a.damp = vol * p;
    // (2 / w)(sqrt(1 + xi^2) - xi) with w = 2 c / len and xi = beta w / 2.
    a.qdt += k.beta * k.c * k.c / len;
  }
  return a;
}

/// The stable step len / (qdt + sqrt(qdt^2 + c^2)) of a solid of characteristic length `len`.
inline Real stable_step(Real len, Real qdt, Real c) { return len / (qdt + std::sqrt(qdt * qdt + c * c)); }

/// D = sym(L), L a velocity gradient (1/time).
inline Tensor3<Real> symmetric_part(const Tensor3<Real>& l) {
  Tensor3<Real> d;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) d[i][j] = 0.5 * (l[i][j] + l[j][i]);
  return d;
}

}  // namespace slideline::solid_terms
