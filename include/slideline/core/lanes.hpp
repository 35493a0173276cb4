#pragma once
/// Lane vectors for kernels vectorised across elements: a batch of kLanes elements is processed at
/// once, every scalar of the element algorithm held as one value per element (one SIMD lane each).
/// There are then no horizontal sums or shuffles inside an element; the cost moves to gathering the
/// nodal data of the batch, which `gather_lanes` does with one AVX-512 gather per quantity.
///
/// `Lanes` is an Eigen array, so its coefficient-wise operations vectorise with whatever the
/// build targets (one zmm register with AVX-512, four xmm registers with plain SSE2) and the code
/// stays correct without -march=native.
#include <array>
#include <cstdint>
#if defined(__AVX512F__)
#include <immintrin.h>
#endif

#include "slideline/core/types.hpp"

namespace slideline {

/// Elements per batch: 8 doubles fill one AVX-512 register.
inline constexpr int kLanes = 8;

/// One value per element of a batch.
using Lanes = Eigen::Array<Real, kLanes, 1>;
/// One flag per element of a batch.
using LaneMask = Eigen::Array<bool, kLanes, 1>;

/// base[idx[l]] for l in [0, kLanes): idx points at kLanes node indices.
inline Lanes gather_lanes(const Real* base, const Index* idx) {
  Lanes r;
#if defined(__AVX512F__)
  static_assert(sizeof(Index) == 4, "the gather takes 32-bit indices");
  const __m256i i = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(idx));
  // The masked form with a zero source: the plain one reads an undefined register, which GCC 12
  // warns about.
  _mm512_storeu_pd(r.data(), _mm512_mask_i32gather_pd(_mm512_setzero_pd(), 0xFF, i, base, 8));
#else
  for (int l = 0; l < kLanes; ++l) r[l] = base[idx[l]];
#endif
  return r;
}

/// Correctly rounded square root of every lane. (Eigen 3.4's AVX-512 sqrt of doubles is an
/// rsqrt14 estimate refined by Newton steps under EIGEN_FAST_MATH: not correctly rounded, and NaN
/// for +inf.)
inline Lanes lane_sqrt(const Lanes& a) {
#if defined(__AVX512F__)
  Lanes r;
  _mm512_storeu_pd(r.data(), _mm512_sqrt_pd(_mm512_loadu_pd(a.data())));
  return r;
#else
  return a.sqrt();
#endif
}

/// Writes the 8x8 block `rows[k][l]` (k a node, l a lane) transposed: out[8 l + k] = rows[k][l],
/// i.e. each element's 8 nodal values contiguously (the corner-slot order of a batch).
inline void store_transposed(const std::array<Lanes, 8>& rows, Real* out) {
  static_assert(kLanes == 8, "the transpose is 8x8");
#if defined(__AVX512F__)
  __m512d r[8];
  for (int k = 0; k < 8; ++k) r[k] = _mm512_loadu_pd(rows[k].data());
  // Three butterfly stages: pairs of lanes, pairs of 128-bit blocks, halves of the register.
  __m512d t[8], u[8];
  for (int k = 0; k < 8; k += 2) {
    t[k] = _mm512_unpacklo_pd(r[k], r[k + 1]);
    t[k + 1] = _mm512_unpackhi_pd(r[k], r[k + 1]);
  }
  const __m512i lo = _mm512_setr_epi64(0, 1, 8, 9, 4, 5, 12, 13);
  const __m512i hi = _mm512_setr_epi64(2, 3, 10, 11, 6, 7, 14, 15);
  for (int k = 0; k < 8; k += 4)
    for (int j = 0; j < 2; ++j) {
      u[k + j] = _mm512_permutex2var_pd(t[k + j], lo, t[k + j + 2]);
      u[k + j + 2] = _mm512_permutex2var_pd(t[k + j], hi, t[k + j + 2]);
    }
  const __m512i lo2 = _mm512_setr_epi64(0, 1, 2, 3, 8, 9, 10, 11);
  const __m512i hi2 = _mm512_setr_epi64(4, 5, 6, 7, 12, 13, 14, 15);
  for (int j = 0; j < 4; ++j) {
    r[j] = _mm512_permutex2var_pd(u[j], lo2, u[j + 4]);
    r[j + 4] = _mm512_permutex2var_pd(u[j], hi2, u[j + 4]);
  }
  // r[l] now holds the 8 nodal values of lane l.
  for (int l = 0; l < 8; ++l) _mm512_storeu_pd(out + 8 * l, r[l]);
#else
  for (int l = 0; l < kLanes; ++l)
    for (int k = 0; k < 8; ++k) out[8 * l + k] = rows[k][l];
#endif
}

}  // namespace slideline
