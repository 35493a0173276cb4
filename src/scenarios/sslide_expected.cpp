// Closed-form answers of the sslide problems (report section 5), the channel names the criteria
// read, and loading those channels from a run (in memory or HDF5).
#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "slideline/core/error.hpp"
#include "slideline/io/hdf5_reader.hpp"
#include "slideline/scenarios/sslide_criteria.hpp"

namespace slideline::scenarios {

namespace {
Real ramp(Real s) { return std::clamp(s, 0.0, 1.0); }
Real sign_of(Real v) { return v < 0.0 ? -1.0 : 1.0; }
}  // namespace

SslideExpected sslide_expected(const SslideProblem& pr, const SslidePairing& p, Real t) {
  using Ideal = SslideIdealization;
  const Real load_y = p.py * ramp(t / 0.1);          // compression > 0: F_y on the upper body
  const Real load_x = p.px * ramp((t - 0.3) / 0.1);  // applied along +x
  const Real fs = pr.mu_s * std::abs(p.py), fk = pr.mu_k * std::abs(p.py);
  SslideExpected e;
  e.force.y() = load_y;
  switch (pr.idealization) {
    case Ideal::frictionless: break;
    case Ideal::tied: e.force.x() = -load_x; break;
    case Ideal::frictional:
      // Stuck while the load is below f_s; once it exceeds f_s the block slides against f_k.
      if (std::abs(p.px) > fs && std::abs(load_x) >= fs && t > 0.3)
        e.force.x() = -sign_of(p.px) * fk;
      else
        e.force.x() = -load_x;
      break;
    case Ideal::tension_failure: {
      const Real ff = pr.failure_force * pr.cells;
      if (std::abs(load_y) >= ff && t >= pr.failure_time) e.force.y() = 0.0;
      break;
    }
    case Ideal::shear_failure: {
      const Real ff = pr.failure_force * pr.cells;
      e.force.x() = (std::abs(load_x) >= ff && t >= pr.failure_time) ? -sign_of(p.px) * fk : -load_x;
      break;
    }
  }
  e.reaction = -e.force;
  return e;
}

std::string sslide_force_channel(const SslideProblem& problem, const SslidePairing& p) {
  const char* leaf = problem.type == model::ContactType::automatic ? "transmitted_force" : "slave_force";
  return "interfaces/" + p.contact_title + "/" + leaf;
}
std::string sslide_master_channel(const SslidePairing& p) { return "interfaces/" + p.contact_title + "/master_force"; }
std::string sslide_support_channel(const std::string& title) { return "supports/" + title + "/reaction"; }
std::string sslide_first_failure_channel(const SslidePairing& p) {
  return "interfaces/" + p.contact_title + "/first_failure_stress";
}
std::string sslide_node_channel(Id node) { return "nodes/" + std::to_string(node) + "/displacement"; }

std::vector<std::string> sslide_channels(const SslideProblem& problem) {
  std::vector<std::string> v;
  for (const auto& p : problem.pairings) {
    v.push_back(sslide_force_channel(problem, p));
    if (problem.type != model::ContactType::automatic) v.push_back(sslide_master_channel(p));
    if (problem.type == model::ContactType::tiebreak_surface) v.push_back(sslide_first_failure_channel(p));
    v.push_back(sslide_support_channel(p.bottom_support));
    v.push_back(sslide_support_channel(p.right_support));
    v.push_back(sslide_node_channel(p.monitor.slave_node));
    v.push_back(sslide_node_channel(p.monitor.leading_node));
    for (Id n : p.monitor.master_nodes) v.push_back(sslide_node_channel(n));
    for (const auto& seg : p.monitor.path)
      for (Id n : seg.nodes) v.push_back(sslide_node_channel(n));
  }
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

SslideHistories sslide_histories(const History& history, const SslideProblem& problem) {
  SslideHistories h;
  h.time = history.time();
  for (const auto& path : sslide_channels(problem)) {
    if (history.find(path) < 0) continue;
    const auto x = history.series(path, 0), y = history.series(path, 1), z = history.series(path, 2);
    auto& s = h.channels[path];
    s.resize(x.size());
    for (std::size_t r = 0; r < x.size(); ++r) s[r] = Vec3(x[r], y[r], z[r]);
  }
  return h;
}

SslideHistories sslide_histories_from_hdf5(const std::string& file, const SslideProblem& problem) {
  SslideHistories h;
  h.time = read_hdf5_dataset(file, "/time").values;
  for (const auto& path : sslide_channels(problem)) {
    if (!hdf5_exists(file, "/" + path)) continue;
    const auto d = read_hdf5_dataset(file, "/" + path);
    if (d.dims.size() != 2 || d.dims[1] != 3 || d.dims[0] != h.time.size())
      throw Error(file + ": /" + path + " is not an (n x 3) dataset matching /time");
    auto& s = h.channels[path];
    s.resize(d.dims[0]);
    for (std::size_t r = 0; r < d.dims[0]; ++r) s[r] = Vec3(d.values[3 * r], d.values[3 * r + 1], d.values[3 * r + 2]);
  }
  return h;
}

std::vector<Vec3> sslide_relative_displacement(const SslidePairing& p, const SslideHistories& h) {
  const auto s = h.channels.find(sslide_node_channel(p.monitor.slave_node));
  if (s == h.channels.end() || p.monitor.path.empty()) return {};
  std::vector<std::array<const std::vector<Vec3>*, 4>> m(p.monitor.path.size());
  for (std::size_t g = 0; g < m.size(); ++g)
    for (int k = 0; k < 4; ++k) {
      const auto f = h.channels.find(sslide_node_channel(p.monitor.path[g].nodes[k]));
      if (f == h.channels.end()) return {};
      m[g][k] = &f->second;
    }
  std::vector<Vec3> rel(s->second.size());
  std::vector<std::array<Vec3, 4>> u(m.size());
  for (std::size_t r = 0; r < rel.size(); ++r) {
    for (std::size_t g = 0; g < m.size(); ++g)
      for (int k = 0; k < 4; ++k) u[g][k] = (*m[g][k])[r];
    rel[r] = tracked_relative_displacement(p.monitor, s->second[r], u);
  }
  return rel;
}

namespace {
/// Current x extent and, per segment of the monitor's row, its nodes' current positions at record r.
bool current_row(const SslidePairing& p, const SslideHistories& h, std::size_t r,
                 std::vector<std::array<Vec3, 4>>& x) {
  x.assign(p.monitor.path.size(), {});
  for (std::size_t g = 0; g < x.size(); ++g)
    for (std::size_t k = 0; k < 4; ++k) {
      const auto f = h.channels.find(sslide_node_channel(p.monitor.path[g].nodes[k]));
      if (f == h.channels.end() || r >= f->second.size()) return false;
      x[g][k] = p.monitor.path[g].x0[k] + f->second[r];
    }
  return !x.empty();
}
}  // namespace

std::optional<std::pair<Real, Real>> sslide_master_slope_range(const SslidePairing& p, const SslideHistories& h,
                                                                std::size_t r) {
  std::vector<std::array<Vec3, 4>> x;
  if (!current_row(p, h, r, x)) return std::nullopt;
  Real xmin = 1e300;
  for (const auto& seg : p.monitor.path)
    for (const auto& x0 : seg.x0) xmin = std::min(xmin, x0.x());
  Real lo = 1e300, hi = -1e300;
  for (std::size_t g = 0; g < x.size(); ++g) {
    const auto& x0 = p.monitor.path[g].x0;
    Real left = 1e300, right = -1e300;
    for (const auto& c : x0) left = std::min(left, c.x()), right = std::max(right, c.x());
    // The upper body spans [xmin + 0.03, xmin + 1.03] (sslide.hpp, "Geometry"): take the segments
    // it covers by more than half.
    if (std::min(right, xmin + 1.03) - std::max(left, xmin + 0.03) < 0.5 * (right - left)) continue;
    Real y_left = 0.0, y_right = 0.0, x_left = 0.0, x_right = 0.0;
    for (std::size_t k = 0; k < 4; ++k) {
      const bool is_left = x0[k].x() < 0.5 * (left + right);
      (is_left ? y_left : y_right) += 0.5 * x[g][k].y();
      (is_left ? x_left : x_right) += 0.5 * x[g][k].x();
    }
    const Real s = (y_right - y_left) / (x_right - x_left);
    lo = std::min(lo, s), hi = std::max(hi, s);
  }
  if (lo > hi) return std::nullopt;
  return std::make_pair(lo, hi);
}

std::optional<bool> sslide_monitor_over_master(const SslidePairing& p, const SslideHistories& h, std::size_t r) {
  std::vector<std::array<Vec3, 4>> x;
  const auto s = h.channels.find(sslide_node_channel(p.monitor.slave_node));
  if (s == h.channels.end() || r >= s->second.size() || !current_row(p, h, r, x)) return std::nullopt;
  Real left = 1e300, right = -1e300;
  for (const auto& seg : x)
    for (const auto& c : seg) left = std::min(left, c.x()), right = std::max(right, c.x());
  const Real xs = p.monitor.slave_x0.x() + s->second[r].x();
  return xs >= left && xs <= right;
}

SslideEdgeCrossing sslide_edge_crossing(const SslidePairing& p, const SslideHistories& h) {
  SslideEdgeCrossing e;
  const auto lead = h.channels.find(sslide_node_channel(p.monitor.leading_node));
  if (lead == h.channels.end()) return e;
  std::vector<std::array<Vec3, 4>> x;
  for (std::size_t r = 0; r < h.time.size(); ++r) {
    if (r >= lead->second.size() || !current_row(p, h, r, x)) return e;
    Real edge = -1e300;  // the +x end of the lower block's top face in the slave's row, now
    for (const auto& seg : x)
      for (const auto& c : seg) edge = std::max(edge, c.x());
    const Real xl = p.monitor.leading_x0.x() + lead->second[r].x();
    if (std::isnan(xl) || std::isnan(edge)) return e;  // unjudgeable: the rows that need it fail
    if (xl > edge) {
      e.recorded = true;
      e.time = h.time[r];
      return e;
    }
  }
  e.recorded = true;
  return e;
}

}  // namespace slideline::scenarios
