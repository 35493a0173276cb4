#pragma once
/// A toy law (issue 19's guide check): linear hypoelastic solid, sigma += dt (lambda tr(D) I +
/// 2 mu D), the stress kept in the law's state. Not objective (no co-rotational rate): a toy.
#include <type_traits>

#include "slideline/core/tensor3.hpp"
#include "slideline/core/types.hpp"
#include "slideline/material/solid_material.hpp"

namespace slideline {

class Hypoelastic : public IsotropicModuli {
 public:
  template <class T>
  struct State {
    Tensor3<T> sigma = zero_tensor<T>();  ///< Cauchy stress (force/length^2)
  };

  Hypoelastic(Real density, Real youngs, Real poisson)
      : IsotropicModuli(density, youngs, youngs / (2.0 * (1.0 + poisson)),
                        youngs * poisson / ((1.0 + poisson) * (1.0 - 2.0 * poisson))) {}

  template <class T>
  Tensor3<T> update(State<T>& s, const Tensor3<T>& /*F*/, const Tensor3<T>& D, Real dt) const {
    const T ltr = lame_lambda() * dt * (D[0][0] + D[1][1] + D[2][2]);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) s.sigma[i][j] += 2.0 * shear_modulus() * dt * D[i][j];
    for (int i = 0; i < 3; ++i) s.sigma[i][i] += ltr;
    return s.sigma;
  }

 private:
  template <class T>
  static Tensor3<T> zero_tensor() {
    Tensor3<T> z;
    for (auto& row : z)
      for (T& v : row) {
        if constexpr (std::is_same_v<T, Real>)
          v = 0.0;
        else
          v = T::Zero();
      }
    return z;
  }
};

}  // namespace slideline
