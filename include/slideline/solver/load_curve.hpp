#pragma once
/// Piecewise-linear load curve, held constant beyond its first and last points.
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "slideline/core/error.hpp"
#include "slideline/core/types.hpp"

namespace slideline {

class LoadCurve {
 public:
  LoadCurve() = default;
  /// points: (t, value) pairs with strictly increasing t.
  explicit LoadCurve(std::vector<std::pair<Real, Real>> points, std::string name = {})
      : pts_(std::move(points)), name_(std::move(name)) {
    if (pts_.empty()) throw InputError("load curve " + name_ + " has no points");
    for (std::size_t i = 1; i < pts_.size(); ++i)
      if (!(pts_[i].first > pts_[i - 1].first))
        throw InputError("load curve " + name_ + ": abscissae must increase (point " +
                         std::to_string(i + 1) + ")");
  }

  /// A curve that is `value` at every time.
  static LoadCurve constant(Real value) { return LoadCurve({{0.0, value}}, "constant"); }

  Real operator()(Real t) const {
    if (t <= pts_.front().first) return pts_.front().second;
    if (t >= pts_.back().first) return pts_.back().second;
    const auto it = std::upper_bound(pts_.begin(), pts_.end(), t,
                                     [](Real v, const auto& p) { return v < p.first; });
    const auto& [t1, y1] = *it;
    const auto& [t0, y0] = *(it - 1);
    return y0 + (y1 - y0) * (t - t0) / (t1 - t0);
  }

  const std::vector<std::pair<Real, Real>>& points() const { return pts_; }
  const std::string& name() const { return name_; }

 private:
  std::vector<std::pair<Real, Real>> pts_{{0.0, 0.0}};
  std::string name_;
};

}  // namespace slideline
