#include <stdexcept>

#include "slideline/core/error.hpp"
#include "slideline/solver/output_sink.hpp"

namespace slideline {

Real History::value(const std::string& path, std::size_t r, int c) const {
  const int col = find(path);
  if (col < 0) throw Error("history has no channel '" + path + "'");
  return data_.at(r * static_cast<std::size_t>(width_) + static_cast<std::size_t>(col + c));
}

std::vector<Real> History::series(const std::string& path, int c) const {
  std::vector<Real> s(records());
  for (std::size_t r = 0; r < records(); ++r) s[r] = value(path, r, c);
  return s;
}

Real History::mean(const std::string& path, int c, Real t0, Real t1) const {
  Real sum = 0.0;
  int count = 0;
  for (std::size_t r = 0; r < records(); ++r)
    if (time_[r] >= t0 - 1e-12 && time_[r] <= t1 + 1e-12) {
      sum += value(path, r, c);
      ++count;
    }
  if (count == 0)
    throw Error("history channel '" + path + "' has no record in [" + std::to_string(t0) + ", " +
                std::to_string(t1) + "]");
  return sum / count;
}

}  // namespace slideline
