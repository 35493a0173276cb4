#include "block_mesh.hpp"

#include <algorithm>
#include <cmath>

namespace slideline::scenarios::detail {

std::vector<Real> lines(Real start, Real length, int n) {
  std::vector<Real> v(n + 1);
  for (int k = 0; k <= n; ++k) v[k] = start + length * k / n;
  return v;
}

std::vector<Real> merge_lines(std::vector<Real> a, const std::vector<Real>& b, Real lo, Real hi) {
  for (Real v : b)
    if (v > lo && v < hi) a.push_back(v);
  std::sort(a.begin(), a.end());
  a.erase(std::unique(a.begin(), a.end(), [](Real p, Real q) { return std::abs(p - q) < 1e-12; }),
          a.end());
  return a;
}

namespace {
std::tuple<long long, long long, long long> key(const Vec3& x) {
  auto q = [](Real v) { return static_cast<long long>(std::llround(v * 1e9)); };
  return {q(x[0]), q(x[1]), q(x[2])};
}
}  // namespace

Grid MeshWriter::add_nodes(std::vector<Real> xs, std::vector<Real> ys, std::vector<Real> zs, bool share) {
  Grid g{std::move(xs), std::move(ys), std::move(zs), {}};
  g.node.resize(g.xs.size() * g.ys.size() * g.zs.size());
  for (std::size_t k = 0; k < g.zs.size(); ++k)
    for (std::size_t j = 0; j < g.ys.size(); ++j)
      for (std::size_t i = 0; i < g.xs.size(); ++i) {
        const Vec3 x = g.coord(i, j, k);
        Id id = 0;
        if (share) {
          const auto f = shared_.find(key(x));
          if (f != shared_.end()) id = f->second;
        }
        if (id == 0) {
          id = next_node_++;
          m_.nodes.push_back({id, x, 0, 0});
          shared_.emplace(key(x), id);
        }
        g.node[i + g.xs.size() * (j + g.ys.size() * k)] = id;
      }
  return g;
}

Grid MeshWriter::add_grid(std::vector<Real> xs, std::vector<Real> ys, std::vector<Real> zs, Id pid, bool share) {
  Grid g = add_nodes(std::move(xs), std::move(ys), std::move(zs), share);
  for (std::size_t k = 0; k + 1 < g.zs.size(); ++k)
    for (std::size_t j = 0; j + 1 < g.ys.size(); ++j)
      for (std::size_t i = 0; i + 1 < g.xs.size(); ++i) {
        model::SolidElement e;
        e.id = next_elem_++;
        e.pid = pid;
        e.n = {g.at(i, j, k),         g.at(i + 1, j, k),         g.at(i + 1, j + 1, k),
               g.at(i, j + 1, k),     g.at(i, j, k + 1),         g.at(i + 1, j, k + 1),
               g.at(i + 1, j + 1, k + 1), g.at(i, j + 1, k + 1)};
        m_.solids.push_back(e);
      }
  return g;
}

void MeshWriter::add_shells(const Grid& g, Id pid, bool reverse) {
  const std::array<std::size_t, 3> n{g.xs.size(), g.ys.size(), g.zs.size()};
  int flat = -1;
  for (int d = 0; d < 3; ++d)
    if (n[d] == 1) flat = d;
  // The two in-plane directions a < b.
  const int a = flat == 0 ? 1 : 0;
  const int b = flat == 2 ? 1 : 2;
  auto at = [&](std::size_t ia, std::size_t ib) {
    std::array<std::size_t, 3> ijk{0, 0, 0};
    ijk[a] = ia;
    ijk[b] = ib;
    return g.at(ijk[0], ijk[1], ijk[2]);
  };
  for (std::size_t ib = 0; ib + 1 < n[b]; ++ib)
    for (std::size_t ia = 0; ia + 1 < n[a]; ++ia) {
      model::ShellElement e;
      e.id = next_elem_++;
      e.pid = pid;
      e.n = {at(ia, ib), at(ia + 1, ib), at(ia + 1, ib + 1), at(ia, ib + 1)};
      if (reverse) std::swap(e.n[1], e.n[3]);
      m_.shells.push_back(e);
    }
}

std::vector<Id> layer_nodes(const Grid& g, std::size_t j) {
  std::vector<Id> v;
  for (std::size_t k = 0; k < g.zs.size(); ++k)
    for (std::size_t i = 0; i < g.xs.size(); ++i) v.push_back(g.at(i, j, k));
  return v;
}

std::vector<Id> x_face_nodes(const Grid& g, std::size_t i) {
  std::vector<Id> v;
  for (std::size_t k = 0; k < g.zs.size(); ++k)
    for (std::size_t j = 0; j < g.ys.size(); ++j) v.push_back(g.at(i, j, k));
  return v;
}

std::vector<std::array<Id, 4>> layer_segments(const Grid& g, std::size_t j, bool normal_up) {
  std::vector<std::array<Id, 4>> s;
  for (std::size_t k = 0; k + 1 < g.zs.size(); ++k)
    for (std::size_t i = 0; i + 1 < g.xs.size(); ++i) {
      // (i,k) (i+1,k) (i+1,k+1) (i,k+1) turns counter-clockwise seen from -y.
      std::array<Id, 4> q{g.at(i, j, k), g.at(i + 1, j, k), g.at(i + 1, j, k + 1), g.at(i, j, k + 1)};
      if (normal_up) std::swap(q[1], q[3]);
      s.push_back(q);
    }
  return s;
}

Id nearest_in_layer(const Grid& g, std::size_t j, Real x, Real z) {
  Id best = 0;
  Real d = 1e300;
  for (std::size_t k = 0; k < g.zs.size(); ++k)
    for (std::size_t i = 0; i < g.xs.size(); ++i) {
      const Real dd = std::hypot(g.xs[i] - x, g.zs[k] - z);
      if (dd < d) {
        d = dd;
        best = g.at(i, j, k);
      }
    }
  return best;
}

std::size_t cell_of(const std::vector<Real>& lines, Real v) {
  std::size_t c = 0;
  while (c + 2 < lines.size() && lines[c + 1] <= v) ++c;
  return c;
}

}  // namespace slideline::scenarios::detail
