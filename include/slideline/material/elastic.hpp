#pragma once
/// Linear elastic material for solids, in its St. Venant-Kirchhoff finite-strain form:
///   S = lambda tr(E) I + 2 mu E,  E = (F^T F - I)/2,  sigma = F S F^T / J.
/// Exact linear elasticity at small strain; objective under large rotations.
#include <cmath>

#include "slideline/core/tensor3.hpp"
#include "slideline/core/types.hpp"

namespace slideline {

class ElasticSolid {
 public:
  ElasticSolid(Real density, Real youngs, Real poisson)
      : rho_(density), e_(youngs), nu_(poisson) {
    mu_ = e_ / (2.0 * (1.0 + nu_));
    lambda_ = e_ * nu_ / ((1.0 + nu_) * (1.0 - 2.0 * nu_));
  }

  Real density() const { return rho_; }
  Real shear_modulus() const { return mu_; }
  Real lame_lambda() const { return lambda_; }
  Real youngs_modulus() const { return e_; }
  Real wave_speed() const { return std::sqrt((lambda_ + 2.0 * mu_) / rho_); }

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
    Tensor3<T> S;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) S[i][j] = 2.0 * mu_ * E[i][j];
    const T lambda_tr_e = lambda_ * (E[0][0] + E[1][1] + E[2][2]);
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

 private:
  Real rho_, e_, nu_, mu_, lambda_;
};

}  // namespace slideline
