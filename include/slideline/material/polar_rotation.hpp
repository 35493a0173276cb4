#pragma once
/// The rotation R of the polar decomposition F = R U, for T = Real or Lanes. An incremental law
/// that keeps its stress in the unrotated frame (sigma_hat = R^T sigma R, updated by
/// d_hat = R^T D R) integrates the Green-Naghdi rate of the Cauchy stress, which is objective:
/// a rigid rotation of the body (F = Q, D = 0) leaves sigma_hat as it is and turns sigma with Q.
#include "slideline/core/tensor3.hpp"
#include "slideline/material/lane_math.hpp"

namespace slideline {

/// R of F = R U (F regular with det F > 0), by Newton's iteration X <- (g X + X^-T / g) / 2 with
/// the determinant scaling g = |det X|^(-1/3) (Higham 1986, "Computing the polar decomposition
/// with applications", SIAM J. Sci. Stat. Comput. 7(4)). A fixed count of 10 steps: it converges
/// quadratically and reaches round-off within 6 steps for any stretch below a factor of 100, and
/// the same count for every element keeps an element's bits independent of its batch-mates.
template <class T>
Tensor3<T> polar_rotation(const Tensor3<T>& F) {
  Tensor3<T> x = F;
  for (int it = 0; it < 10; ++it) {
    const Tensor3<T> inv = inverse(x);
    const T g = 1.0 / lane_math::abs_cbrt(determinant(x));
    const T half_g = 0.5 * g, half_inv_g = 0.5 / g;
    Tensor3<T> next;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) next[i][j] = half_g * x[i][j] + half_inv_g * inv[j][i];
    x = next;
  }
  return x;
}

/// R^T a R.
template <class T>
Tensor3<T> rotate_to_unrotated(const Tensor3<T>& R, const Tensor3<T>& a) {
  Tensor3<T> ar = product(a, R), r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r[i][j] = R[0][i] * ar[0][j] + R[1][i] * ar[1][j] + R[2][i] * ar[2][j];
  return r;
}

/// R a R^T.
template <class T>
Tensor3<T> rotate_to_current(const Tensor3<T>& R, const Tensor3<T>& a) {
  Tensor3<T> ra = product(R, a), r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r[i][j] = ra[i][0] * R[j][0] + ra[i][1] * R[j][1] + ra[i][2] * R[j][2];
  return r;
}

}  // namespace slideline
