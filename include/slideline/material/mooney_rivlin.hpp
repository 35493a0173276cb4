#pragma once
/// Compressible Mooney-Rivlin rubber, DYNA3D material 27 / LS-DYNA *MAT_MOONEY-RIVLIN_RUBBER.
///
///   W = A (I1 - 3) + B (I2 - 3) + C (I3^-2 - 1) + D (I3 - 1)^2,
///   C = A/2 + B,   D = [A (5 nu - 2) + B (11 nu - 5)] / [2 (1 - 2 nu)],
///
/// with I1, I2, I3 the invariants of the right Cauchy-Green tensor (I3 = J^2). C and D make the
/// reference state stress free and give the small-strain moduli G = 2 (A + B) and
/// lambda = 2 G nu / (1 - 2 nu). Cauchy stress (Bt = left Cauchy-Green tensor F F^T):
///   sigma = (2/J) [ (W1 + I1 W2) Bt - W2 Bt^2 ] + 2 J W3 I.
/// Reference: LS-DYNA Theory Manual, material 27; Hallquist, DYNA3D User Manual (Lin 2005).
#include <cmath>

#include "slideline/core/tensor3.hpp"
#include "slideline/core/types.hpp"
#include "slideline/material/solid_material.hpp"

namespace slideline {

/// A SolidMaterial (solid_material.hpp) without state: the stress is a function of F alone. Its
/// small-strain constants: G = 2 (A + B), lambda = 2 G nu / (1 - 2 nu), E = 2 G (1 + nu).
class MooneyRivlin : public IsotropicModuli {
 public:
  template <class T>
  using State = NoState<T>;

  /// `density` mass/length^3, `a`, `b` force/length^2, `poisson` in (-1, 0.5).
  MooneyRivlin(Real density, Real a, Real b, Real poisson)
      : MooneyRivlin(density, a, b, poisson, 2.0 * (a + b)) {}

  /// The SolidMaterial step: the Cauchy stress at F (the rate of deformation and dt do not enter).
  template <class T>
  Tensor3<T> update(State<T>& /*state*/, const Tensor3<T>& F, const Tensor3<T>& /*D*/,
                    Real /*dt*/) const {
    return cauchy_stress(F);
  }

  /// Strain energy W(F) per unit reference volume (force/length^2), the formula above.
  template <class T>
  T energy_density(const Tensor3<T>& F) const {
    const Tensor3<T> bt = times_transpose(F);
    const T J = determinant(F);
    const T i1 = bt[0][0] + bt[1][1] + bt[2][2];
    T bb = bt[0][0] * 0.0;  // tr(Bt^2), for I2 = (I1^2 - tr(Bt^2)) / 2
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) bb += bt[i][j] * bt[j][i];
    const T i2 = 0.5 * (i1 * i1 - bb);
    const T i3 = J * J;
    return a_ * (i1 - 3.0) + b_ * (i2 - 3.0) + c_ * (1.0 / (i3 * i3) - 1.0) + d_ * (i3 - 1.0) * (i3 - 1.0);
  }

  /// Cauchy stress for the deformation gradient F (3x3, dimensionless).
  Mat3 cauchy_stress(const Mat3& F) const { return to_mat3(cauchy_stress(to_tensor3(F))); }

  /// Cauchy stress for deformation gradients F with components of type T: Real for one element,
  /// Lanes for a batch of elements (one per lane).
  template <class T>
  Tensor3<T> cauchy_stress(const Tensor3<T>& F) const {
    const Tensor3<T> bt = times_transpose(F);
    const T J = determinant(F);
    const T i1 = bt[0][0] + bt[1][1] + bt[2][2];
    const T i3 = J * J;
    const Real w1 = a_;
    const Real w2 = b_;
    const T w3 = -2.0 * c_ / (i3 * i3 * i3) + 2.0 * d_ * (i3 - 1.0);
    const T two_over_j = 2.0 / J;
    const T s1 = two_over_j * (w1 + i1 * w2);
    Tensor3<T> s;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) s[i][j] = s1 * bt[i][j];
    if (w2 != 0.0) {  // B = 0 (the spec's rubber) skips a product
      const Tensor3<T> bt2 = product(bt, bt);
      const T s2 = two_over_j * w2;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) s[i][j] -= s2 * bt2[i][j];
    }
    const T p = 2.0 * J * w3;
    for (int i = 0; i < 3; ++i) s[i][i] += p;
    return s;
  }

 private:
  /// `g` = 2 (A + B), the small-strain shear modulus.
  MooneyRivlin(Real density, Real a, Real b, Real poisson, Real g)
      : IsotropicModuli(density, 2.0 * g * (1.0 + poisson), g, 2.0 * g * poisson / (1.0 - 2.0 * poisson)),
        a_(a),
        b_(b),
        c_(0.5 * a + b),
        d_((a * (5.0 * poisson - 2.0) + b * (11.0 * poisson - 5.0)) / (2.0 * (1.0 - 2.0 * poisson))) {}

  Real a_, b_, c_, d_;
};

}  // namespace slideline
