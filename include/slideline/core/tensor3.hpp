#pragma once
/// 3x3 tensors of any scalar type: `Real` for one element, `Lanes` for a batch of elements. The
/// material laws and the hexahedron kernel write their formulas once, on Tensor3<T>, and use them
/// for both.
#include <array>

#include "slideline/core/types.hpp"

namespace slideline {

/// Row-major 3x3 tensor, t[i][j].
template <class T>
using Tensor3 = std::array<std::array<T, 3>, 3>;

template <class T>
T determinant(const Tensor3<T>& a) {
  return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
         a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
         a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

/// Inverse by cofactors (the tensor must be regular).
template <class T>
Tensor3<T> inverse(const Tensor3<T>& a) {
  Tensor3<T> r;
  r[0][0] = a[1][1] * a[2][2] - a[1][2] * a[2][1];
  r[1][0] = a[1][2] * a[2][0] - a[1][0] * a[2][2];
  r[2][0] = a[1][0] * a[2][1] - a[1][1] * a[2][0];
  const T inv_det = 1.0 / (a[0][0] * r[0][0] + a[0][1] * r[1][0] + a[0][2] * r[2][0]);
  r[0][1] = a[0][2] * a[2][1] - a[0][1] * a[2][2];
  r[1][1] = a[0][0] * a[2][2] - a[0][2] * a[2][0];
  r[2][1] = a[0][1] * a[2][0] - a[0][0] * a[2][1];
  r[0][2] = a[0][1] * a[1][2] - a[0][2] * a[1][1];
  r[1][2] = a[0][2] * a[1][0] - a[0][0] * a[1][2];
  r[2][2] = a[0][0] * a[1][1] - a[0][1] * a[1][0];
  for (auto& row : r)
    for (T& v : row) v *= inv_det;
  return r;
}

/// a a^T (symmetric).
template <class T>
Tensor3<T> times_transpose(const Tensor3<T>& a) {
  Tensor3<T> r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j <= i; ++j) {
      r[i][j] = a[i][0] * a[j][0] + a[i][1] * a[j][1] + a[i][2] * a[j][2];
      if (j != i) r[j][i] = r[i][j];
    }
  return r;
}

/// a^T a (symmetric).
template <class T>
Tensor3<T> transpose_times(const Tensor3<T>& a) {
  Tensor3<T> r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j <= i; ++j) {
      r[i][j] = a[0][i] * a[0][j] + a[1][i] * a[1][j] + a[2][i] * a[2][j];
      if (j != i) r[j][i] = r[i][j];
    }
  return r;
}

/// a b.
template <class T>
Tensor3<T> product(const Tensor3<T>& a, const Tensor3<T>& b) {
  Tensor3<T> r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
  return r;
}

inline Tensor3<Real> to_tensor3(const Mat3& m) {
  Tensor3<Real> t;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) t[i][j] = m(i, j);
  return t;
}

inline Mat3 to_mat3(const Tensor3<Real>& t) {
  Mat3 m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m(i, j) = t[i][j];
  return m;
}

}  // namespace slideline
