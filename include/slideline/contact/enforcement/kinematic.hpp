#pragma once
/// Kinematic tie kernels (docs/solver.md, constraint order): a tied slave node's mass and force
/// are condensed onto its master nodes with the master shape functions N_a, the simulation
/// integrates the masters, and the slave then takes v_s = sum N_a v_a, x_s = sum N_a x_a + d_s.
/// With rotations (shell edges, Type 7; shell-on-shell ties) the rotary inertia and moment are
/// condensed the same way and omega_s = sum N_a omega_a: the slave's rotation is the N-weighted
/// average of its masters' rotations.
#include <array>

#include "slideline/contact/search/tie_search.hpp"
#include "slideline/core/types.hpp"
#include "slideline/mesh/nodal_fields.hpp"

namespace slideline::kinematic {

/// Adds N_a * value to each master of t in `f`.
inline void scatter(const TiePoint& t, Vec3Field& f, const Vec3& value) {
  for (int a = 0; a < 4; ++a)
    if (t.shape[a] != 0.0) f.add(t.master[a], t.shape[a] * value);
}

/// Adds N_a * value to each master of t in `s`.
inline void scatter(const TiePoint& t, std::span<Real> s, Real value) {
  for (int a = 0; a < 4; ++a) s[t.master[a]] += t.shape[a] * value;
}

/// True when the slave and all of its (weighted) masters carry rotational degrees of freedom.
inline bool ties_rotation(const TiePoint& t, const NodalFields& nodes) {
  if (!nodes.has_rotation[t.slave]) return false;
  for (int a = 0; a < 4; ++a)
    if (t.shape[a] != 0.0 && !nodes.has_rotation[t.master[a]]) return false;
  return true;
}

}  // namespace slideline::kinematic
