#pragma once
/// Nodal state as structure-of-arrays (one contiguous array per component).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "slideline/core/types.hpp"

namespace slideline {

/// Three arrays, one per Cartesian component.
struct Vec3Field {
  std::vector<Real> x, y, z;

  void resize(std::size_t n, Real v = 0.0) {
    x.assign(n, v);
    y.assign(n, v);
    z.assign(n, v);
  }
  void fill(Real v) {
    std::fill(x.begin(), x.end(), v);
    std::fill(y.begin(), y.end(), v);
    std::fill(z.begin(), z.end(), v);
  }
  std::size_t size() const { return x.size(); }
  Vec3 get(Index i) const { return {x[i], y[i], z[i]}; }
  void set(Index i, const Vec3& v) {
    x[i] = v[0];
    y[i] = v[1];
    z[i] = v[2];
  }
  void add(Index i, const Vec3& v) {
    x[i] += v[0];
    y[i] += v[1];
    z[i] += v[2];
  }
  std::vector<Real>& operator[](int c) { return c == 0 ? x : (c == 1 ? y : z); }
  const std::vector<Real>& operator[](int c) const { return c == 0 ? x : (c == 1 ? y : z); }
};

/// The rows of an element's N nodes, gathered from a field: row k = field at nodes[k].
template <int N>
Eigen::Matrix<Real, N, 3> gather_rows(const Vec3Field& f, const Index* nodes) {
  Eigen::Matrix<Real, N, 3> m;
  for (int k = 0; k < N; ++k) {
    m(k, 0) = f.x[nodes[k]];
    m(k, 1) = f.y[nodes[k]];
    m(k, 2) = f.z[nodes[k]];
  }
  return m;
}

/// Every nodal quantity of the model. Index i is the dense internal node index; `ids[i]` is the
/// deck's node id. Translational fields are used by every node; rotational fields only by nodes
/// that carry rotations (shell nodes, `has_rotation[i] != 0`).
struct NodalFields {
  std::vector<Id> ids;
  Vec3Field x0;     ///< reference coordinates
  Vec3Field x;      ///< current coordinates
  Vec3Field v;      ///< velocity at the last half step (t^{n-1/2} before, t^{n+1/2} after the update)
  Vec3Field a;      ///< acceleration at t^n
  Vec3Field f_int;  ///< internal (element) forces at t^n, as a residual: the force the elements apply to the node
  Vec3Field f_ext;  ///< external forces at t^n: body loads
  Vec3Field f_contact;  ///< contact forces at t^n (penalty springs, friction, Lagrange multipliers)
  std::vector<Real> mass;  ///< lumped translational mass

  // Rotational degrees of freedom (shells).
  std::vector<std::uint8_t> has_rotation;
  Vec3Field omega;        ///< angular velocity (global frame)
  Vec3Field m_int;        ///< internal moments (residual form)
  Vec3Field m_ext;        ///< external moments
  Vec3Field m_contact;    ///< contact moments (shell-edge ties)
  Vec3Field alpha;        ///< angular acceleration at t^n (global frame)
  std::vector<Real> rot_inertia;  ///< lumped (isotropic) rotary inertia

  std::size_t size() const { return ids.size(); }

  /// Allocates every field for n nodes, zero-filled.
  void resize(std::size_t n) {
    ids.assign(n, 0);
    x0.resize(n);
    x.resize(n);
    v.resize(n);
    a.resize(n);
    f_int.resize(n);
    f_ext.resize(n);
    f_contact.resize(n);
    mass.assign(n, 0.0);
    has_rotation.assign(n, 0);
    omega.resize(n);
    m_int.resize(n);
    m_ext.resize(n);
    m_contact.resize(n);
    alpha.resize(n);
    rot_inertia.assign(n, 0.0);
  }

  Vec3 displacement(Index i) const { return x.get(i) - x0.get(i); }
};

}  // namespace slideline
