#pragma once
/// Linear elastic material for solids, in its St. Venant-Kirchhoff finite-strain form:
///   S = lambda tr(E) I + 2 mu E,  E = (F^T F - I)/2,  sigma = F S F^T / J.
/// Exact linear elasticity at small strain; objective under large rotations.
#include <cmath>

#include "slideline/core/tensor3.hpp"
#include "slideline/core/types.hpp"
#include "slideline/material/solid_material.hpp"

namespace slideline {

/// A SolidMaterial (solid_material.hpp) without state: the stress is a function of F alone.
class ElasticSolid : public IsotropicModuli {
 public:
  template <class T>
  using State = NoState<T>;

  /// `density` mass/length^3, `youngs` force/length^2, `poisson` in (-1, 0.5).
  ElasticSolid(Real density, Real youngs, Real poisson)
      : IsotropicModuli(density, youngs, youngs / (2.0 * (1.0 + poisson)),
                        youngs * poisson / ((1.0 + poisson) * (1.0 - 2.0 * poisson))) {}

  /// The SolidMaterial step: the Cauchy stress at F (the rate of deformation and dt do not enter).
  template <class T>
  Tensor3<T> update(State<T>& /*state*/, const Tensor3<T>& F, const Tensor3<T>& /*D*/,
                    Real /*dt*/) const {
    return cauchy_stress(F);
  }

  /// Strain energy W = lambda/2 tr(E)^2 + mu E : E per unit reference volume (force/length^2).
  template <class T>
  T energy_density(const Tensor3<T>& F) const {
    Tensor3<T> E = transpose_times(F);
    for (int i = 0; i < 3; ++i) E[i][i] -= 1.0;
    T ee = E[0][0] * 0.0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) ee += 0.25 * E[i][j] * E[i][j];
    const T tr = 0.5 * (E[0][0] + E[1][1] + E[2][2]);
    return 0.5 * lame_lambda() * tr * tr + shear_modulus() * ee;
  }

  /// Cauchy stress for the deformation gradient F (3x3, dimensionless).
  Mat3 cauchy_stress(const Mat3& F) const { return to_mat3(cauchy_stress(to_tensor3(F))); }

  /// Cauchy stress for deformation gradients F with components of type T: Real for one element,
  /// Lanes for a batch of elements (one per lane).
  template <class T>
  Tensor3<T> cauchy_stress(const Tensor3<T>& F) const {
    Tensor3<T> E = transpose_times(F);  // E = (F^T F - I) / 2
    for (int i = 0; i < 3; ++i) E[i][i] -= 1.0;
    for (auto& row : E)
      for (T& v : row) v *= 0.5;
    const Real mu = shear_modulus(), lambda = lame_lambda();
    Tensor3<T> S;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) S[i][j] = 2.0 * mu * E[i][j];
    const T lambda_tr_e = lambda * (E[0][0] + E[1][1] + E[2][2]);
    for (int i = 0; i < 3; ++i) S[i][i] += lambda_tr_e;
    const Tensor3<T> fs = product(F, S);
    const T inv_j = 1.0 / determinant(F);
    Tensor3<T> s;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j <= i; ++j) {
        s[i][j] = (fs[i][0] * F[j][0] + fs[i][1] * F[j][1] + fs[i][2] * F[j][2]) * inv_j;
        s[j][i] = s[i][j];
      }
    return s;
  }
};

}  // namespace slideline
