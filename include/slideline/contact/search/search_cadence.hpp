#pragma once
/// When to run the broad phase again.
///
/// Rule: a broad-phase search inflates every segment box by `margin`. Between two searches a slave
/// node and a master segment can each move by at most d_max, the largest nodal displacement since
/// the last search over every node of the interface (slave and master nodes), so their distance
/// closes by at most 2 d_max. The candidates of the last search therefore stay complete while
/// 2 d_max < margin; a new search is due as soon as d_max >= margin / 2. In between, each slave
/// node keeps its segment and re-projects locally (segment_tracking.hpp).
/// The displacement is the Euclidean one, which bounds the per-axis box movement from above.
#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include "slideline/core/parallel.hpp"
#include "slideline/core/types.hpp"
#include "slideline/mesh/nodal_fields.hpp"

namespace slideline {

class SearchCadence {
 public:
  SearchCadence() = default;

  /// Watches the nodes `nodes` (internal indices: the union of the interface's slave and master
  /// nodes) with the search margin `margin` (length, > 0). Allocates.
  SearchCadence(std::span<const Index> nodes, Real margin)
      : nodes_(nodes.begin(), nodes.end()), margin_(margin) {
    ref_x_.resize(nodes_.size(), 0.0);
    ref_y_.resize(nodes_.size(), 0.0);
    ref_z_.resize(nodes_.size(), 0.0);
    partial_.resize(static_cast<std::size_t>(chunk_count(static_cast<Index>(nodes_.size()))), 0.0);
  }

  /// Records the coordinates x (SoA, length) of a search that has just run. No allocation.
  void mark_searched(const Vec3Field& x) {
    parallel_for(static_cast<Index>(nodes_.size()), [&](Index i) {
      const Index n = nodes_[static_cast<std::size_t>(i)];
      ref_x_[static_cast<std::size_t>(i)] = x.x[n];
      ref_y_[static_cast<std::size_t>(i)] = x.y[n];
      ref_z_[static_cast<std::size_t>(i)] = x.z[n];
    });
    searched_ = true;
  }

  /// Largest Euclidean displacement (length) of a watched node since the last mark_searched().
  /// No allocation; the same value for any thread count.
  Real max_displacement(const Vec3Field& x) {
    const Index n = static_cast<Index>(nodes_.size());
    parallel_for_chunks(n, [&](Index b, Index e, Index c) {
      Real m2 = 0.0;
      for (Index i = b; i < e; ++i) {
        const std::size_t k = static_cast<std::size_t>(i);
        const Index node = nodes_[k];
        const Real dx = x.x[node] - ref_x_[k], dy = x.y[node] - ref_y_[k], dz = x.z[node] - ref_z_[k];
        m2 = std::max(m2, dx * dx + dy * dy + dz * dz);
      }
      partial_[static_cast<std::size_t>(c)] = m2;
    });
    Real m2 = 0.0;
    for (Index c = 0; c < chunk_count(n); ++c) m2 = std::max(m2, partial_[static_cast<std::size_t>(c)]);
    return std::sqrt(m2);
  }

  /// True when a new broad-phase search is due: never searched yet, or max_displacement(x) >=
  /// margin / 2 (see the file comment). No allocation.
  bool is_due(const Vec3Field& x) { return !searched_ || max_displacement(x) >= 0.5 * margin_; }

  Real margin() const { return margin_; }

 private:
  std::vector<Index> nodes_;
  std::vector<Real> ref_x_, ref_y_, ref_z_;
  std::vector<Real> partial_;
  Real margin_ = 0.0;
  bool searched_ = false;
};

}  // namespace slideline
