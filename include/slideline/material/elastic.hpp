#pragma once
/// Linear elastic material for solids, in its St. Venant-Kirchhoff finite-strain form:
///   S = lambda tr(E) I + 2 mu E,  E = (F^T F - I)/2,  sigma = F S F^T / J.
/// Exact linear elasticity at small strain; objective under large rotations.
#include <cmath>

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

  Mat3 cauchy_stress(const Mat3& F) const {
    const Mat3 E = 0.5 * (F.transpose() * F - Mat3::Identity());
    Mat3 S = 2.0 * mu_ * E;
    S.diagonal().array() += lambda_ * E.trace();
    return F * S * F.transpose() / F.determinant();
  }

 private:
  Real rho_, e_, nu_, mu_, lambda_;
};

}  // namespace slideline
