#pragma once
/// Thread-count-independent parallel loops.
///
/// Work is split into fixed-size chunks whose boundaries do not depend on the number of threads, and
/// reductions combine the per-chunk partial results in chunk order. The result of a reduction is
/// therefore bit-identical for any thread count (including 1).
#include <algorithm>
#include <cstddef>
#include <vector>

#include "slideline/core/types.hpp"

#if defined(_OPENMP)
#include <omp.h>
#endif

namespace slideline {

/// Elements or nodes per chunk; a compile-time constant so that reductions are reproducible.
inline constexpr Index kChunkSize = 512;
/// Loops shorter than this run on the calling thread: a parallel region costs microseconds, more
/// than a small loop, and far more when the cores are shared.
inline constexpr Index kParallelThreshold = 4096;

inline int max_threads() {
#if defined(_OPENMP)
  return omp_get_max_threads();
#else
  return 1;
#endif
}

inline void set_threads(int n) {
#if defined(_OPENMP)
  if (n > 0) omp_set_num_threads(n);
#else
  (void)n;
#endif
}

/// Calls body(i) for i in [0, n). Iterations must be independent.
template <class Body>
void parallel_for(Index n, Body&& body) {
#pragma omp parallel for schedule(static) if (n >= kParallelThreshold)
  for (Index i = 0; i < n; ++i) body(i);
}

/// Number of reduction chunks for n items.
inline Index chunk_count(Index n) { return (n + kChunkSize - 1) / kChunkSize; }

/// Calls body(begin, end, chunk) for every fixed-size chunk of [0, n), in parallel.
template <class Body>
void parallel_for_chunks(Index n, Body&& body) {
  const Index nchunks = chunk_count(n);
#pragma omp parallel for schedule(static) if (n >= kParallelThreshold)
  for (Index c = 0; c < nchunks; ++c) {
    const Index b = c * kChunkSize;
    body(b, std::min<Index>(n, b + kChunkSize), c);
  }
}

/// Deterministic sum of the values `partial[c]` written per chunk.
template <class T>
T ordered_sum(const std::vector<T>& partial, T zero) {
  T s = zero;
  for (const T& p : partial) s += p;
  return s;
}

}  // namespace slideline
