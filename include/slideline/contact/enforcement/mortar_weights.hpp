#pragma once
/// Mortar (consistent) coupling weights of one slave node: how a force acting at slave node i is
/// shared among the master nodes so that a uniform pressure reaches both sides as the consistent
/// nodal forces of their own meshes (the contact patch test; docs/contact.md, "The contact patch
/// test"):
///   w_a = (1/W) integral over the node's slave segments of N_i N_a dA,   W = integral of N_i dA,
/// N_i the slave node's bilinear shape function, N_a the master shape functions at the closest
/// point of each integration point (points whose projection lies beside the master surface are
/// left out of both integrals). The weights sum to 1. Integration: 4 x 4 Gauss points on each
/// slave segment, projected by tracking from the slave node's own master segment. No allocation.
#include <array>
#include <cmath>

#include "slideline/contact/search/segment_tracking.hpp"
#include "slideline/mesh/surface.hpp"

namespace slideline {

/// Whether a slave segment of unit normal n_s (a shell when `shell`) faces a master of normal
/// n_master: a solid face must oppose it (n_s . n_m <= -0.5), a shell (either side usable) be
/// roughly parallel (|n_s . n_m| >= 0.5). A block's side faces meeting its contact face at an
/// edge do not face the master.
inline bool faces_master(const Vec3& n_s, bool shell, const Vec3& n_master) {
  const Real d = n_s.dot(n_master);
  return shell ? std::abs(d) >= 0.5 : d <= -0.5;
}

/// Unit normal of slave segment s (zero when degenerate).
inline Vec3 slave_segment_normal(const Surface& slave, Index s, const Vec3Field& x) {
  const auto c = segment_corners(slave, s, x);
  const Vec3 a = (c[2] - c[0]).cross(c[3] - c[1]);
  const Real len = a.norm();
  return len > 0.0 ? Vec3(a / len) : Vec3::Zero();
}

/// A master segment to start tracking from that faces a slave segment of normal n_s: `start`
/// when it does, else its first edge neighbour that does (a node at a flush edge may hold the
/// master's side face, and tracking from a face the point lies behind does not leave it), else
/// `start`.
inline Index facing_seed(const Surface& master, Index start, const Vec3& n_s, bool shell, const Vec3Field& x) {
  const auto normal = [&](Index t) {
    const auto c = segment_corners(master, t, x);
    const Vec3 a = (c[2] - c[0]).cross(c[3] - c[1]);
    return a.norm() > 0.0 ? Vec3(a.normalized()) : Vec3::Zero();
  };
  if (faces_master(n_s, shell, normal(start))) return start;
  for (Index j = master.segment_neighbors.begin(start); j < master.segment_neighbors.end(start); ++j) {
    const Index t = master.segment_neighbors.value[static_cast<std::size_t>(j)];
    if (faces_master(n_s, shell, normal(t))) return t;
  }
  return start;
}

/// The master nodes a slave node is coupled to and their weights (sum 1).
struct MortarWeights {
  static constexpr int capacity = 48;
  int count = 0;
  Real area = 0.0;  ///< W: the integral of N_i over the part of the node's segments over the master
  Vec3 normal = Vec3::Zero();  ///< N_i-weighted mean master normal over that part (unit)
  std::array<Index, capacity> node{};
  std::array<Real, capacity> weight{};

  void add(Index n, Real w) {
    for (int k = 0; k < count; ++k)
      if (node[static_cast<std::size_t>(k)] == n) {
        weight[static_cast<std::size_t>(k)] += w;
        return;
      }
    if (count == capacity) return;  // the caller sees the lost weight in the sum
    node[static_cast<std::size_t>(count)] = n;
    weight[static_cast<std::size_t>(count++)] = w;
  }
};

/// Weights of slave node `node` (row `row` of `slave`), starting the projections from master
/// segment `start`; an integration point counts where its slave segment faces the master at its
/// closest point (faces_master). False (out untouched in meaning) when the node has a triangular segment, no
/// integration point lands on the master, or the master nodes exceed the capacity.
inline bool mortar_weights(const Surface& slave, Index row, Index node, const Surface& master, Index start,
                           const Vec3Field& x, MortarWeights& out) {
  static constexpr Real gp[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
  static constexpr Real gw[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
  static constexpr Real cxi[4] = {-1, 1, 1, -1}, ceta[4] = {-1, -1, 1, 1};
  out.count = 0;
  Real total = 0.0;
  Vec3 nsum = Vec3::Zero();
  Index seg_m = start;
  for (Index j = slave.node_segments.begin(row); j < slave.node_segments.end(row); ++j) {
    const Index s = slave.node_segments.value[static_cast<std::size_t>(j)];
    if (slave.is_triangle(s)) return false;
    const Vec3 ns = slave_segment_normal(slave, s, x);
    const bool shell = slave.kind[static_cast<std::size_t>(s)] == SegmentKind::shell;
    seg_m = facing_seed(master, seg_m, ns, shell, x);
    const Index* c = &slave.conn[4 * static_cast<std::size_t>(s)];
    int k = 0;
    while (k < 4 && c[k] != node) ++k;
    if (k == 4) return false;
    std::array<Vec3, 4> p{x.get(c[0]), x.get(c[1]), x.get(c[2]), x.get(c[3])};
    for (int u = 0; u < 4; ++u)
      for (int v = 0; v < 4; ++v) {
        const Real xi = gp[u], eta = gp[v];
        Vec3 xq = Vec3::Zero(), dxi = Vec3::Zero(), deta = Vec3::Zero();
        for (int a = 0; a < 4; ++a) {
          xq += 0.25 * (1 + cxi[a] * xi) * (1 + ceta[a] * eta) * p[static_cast<std::size_t>(a)];
          dxi += 0.25 * cxi[a] * (1 + ceta[a] * eta) * p[static_cast<std::size_t>(a)];
          deta += 0.25 * ceta[a] * (1 + cxi[a] * xi) * p[static_cast<std::size_t>(a)];
        }
        const Real ni = 0.25 * (1 + cxi[k] * xi) * (1 + ceta[k] * eta);
        const Real da = dxi.cross(deta).norm() * gw[u] * gw[v];
        const SegmentProjection sp = track_segment(xq, seg_m, master, x);
        const Projection& pr = sp.projection;
        if ((xq - pr.point - pr.gap * pr.normal).norm() > 1e-3 * pr.size) continue;  // beside the master
        if (!faces_master(ns, shell, pr.normal)) continue;
        seg_m = sp.segment;
        nsum += ni * da * pr.normal;
        const Index* cm = &master.conn[4 * static_cast<std::size_t>(seg_m)];
        for (int a = 0; a < 4; ++a)
          if (pr.shape[static_cast<std::size_t>(a)] != 0.0) out.add(cm[a], ni * pr.shape[static_cast<std::size_t>(a)] * da);
        total += ni * da;
      }
  }
  if (!(total > 0.0) || out.count == MortarWeights::capacity || !(nsum.norm() > 0.0)) return false;
  Real sum = 0.0;
  for (int k = 0; k < out.count; ++k) sum += out.weight[static_cast<std::size_t>(k)];
  if (std::abs(sum - total) > 1e-9 * total) return false;
  for (int k = 0; k < out.count; ++k) out.weight[static_cast<std::size_t>(k)] /= total;
  out.area = total;
  out.normal = nsum.normalized();
  return true;
}

}  // namespace slideline
