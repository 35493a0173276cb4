#pragma once
/// The central-difference update of the nodal state, as free functions of their inputs:
///   a^n = F^n / m;  v^{n+1/2} = ((1 - h) v^{n-1/2} + dt_avg a^n) / (1 + h), h = alpha dt_avg / 2;
///   x^{n+1} = x^n + dt_next v^{n+1/2}.
/// The velocity update also forms the cycle's energy sums: the audit needs v^{n-1/2}, v^{n+1/2}
/// and the forces of each node together, and one pass over the nodal arrays is cheaper than two.
#include <span>

#include "slideline/core/types.hpp"
#include "slideline/mesh/nodal_fields.hpp"
#include "slideline/solver/energy_ledger.hpp"
#include "slideline/solver/node_roles.hpp"
#include "slideline/solver/simulation_controls.hpp"

namespace slideline {

/// a = F / m and, for nodes with rotations, alpha = M / I, from the total loads (total_force.hpp;
/// contact loads read only `with_contact`). Nodes without mass (inertia) get zero.
void form_accelerations(NodalFields& nodes, bool with_contact, bool rotations);

/// The step of one velocity update.
struct VelocityStep {
  Real dt_prev = 0.0;  ///< t^n - t^{n-1} (0 on the first cycle)
  Real dt_avg = 0.0;   ///< the velocity step (StepPlan::dt_avg)
  Real dt_next = 0.0;  ///< t^{n+1} - t^n
  bool first = false;  ///< the first cycle: the kinetic energy is that of v(0) itself
  bool with_contact = false;
};

/// v^{n+1/2} and omega^{n+1/2} of every node with mass except tied slaves (kDictated), damped by
/// `damping` (1/time, per node); components a support fixes take the acceleration in `nodes.a`
/// undamped, rotations a support fixes are zeroed. Returns the energy sums of the cycle (work
/// halves of each force, kinetic energy at t^n), summed per chunk into `chunk_sums` (size
/// chunk_count(n)) and then in chunk order, so that the sums do not depend on the thread count.
NodalEnergySums update_velocities(NodalFields& nodes, const NodeRoles& roles, std::span<const Real> damping,
                                  const VelocityStep& step, std::span<NodalEnergySums> chunk_sums);

/// The motion of one degree of freedom over a velocity update, for the work halves of its loads.
struct DofMotion {
  Real vbar;   ///< (v^{n-1/2} + v^{n+1/2}) / 2
  Real dprev;  ///< half of x^n - x^{n-1}
  /// Half of x^{n+1} - x^n; on the first cycle dt_avg (v(0) + v^{1/2}) / 2, the travel of a node
  /// taken from v(0) to v^{1/2} by a constant force over the half step dt_avg = dt / 2.
  Real dnext;
};

/// Books into `e` the kinetic energy at t^n of one degree of freedom of mass (or rotary inertia)
/// `m` whose velocity went from `vold` to `vnew` (v(0) itself on the first cycle, else the mean
/// velocity), and the work halves of its internal (`fi`) and external (`fe`) loads; returns its
/// motion for the works the caller books next. The one rule of the velocity update's energy sums
/// (update_velocities, tied slaves in energy_audit.hpp).
///
/// With these sums the balance of any model at a constant step is exactly
/// sum m (v^{n+1/2} - v^{n-1/2})^2 / 8 = sum (f^n dt)^2 / (8 m): the mean-velocity kinetic energy
/// exceeds m v^{n-1/2} v^{n+1/2} / 2, which the central difference conserves with the trapezoid's
/// works, by that much (docs/solver.md, "The discrete energy identity"). It is bounded by
/// (omega dt)^2 / 4 of the energy of a mode of frequency omega and grows with a mode that
/// diverges by reversing its sign every step, which is what makes the balance an instability
/// detector. The first cycle is a half step from v(0): its forces are booked over
/// dnext = dt_avg (v(0) + v^{1/2}) / 2, the travel under a constant force, which leaves no offset
/// (over dt v^{1/2} / 2 the balance kept -(f^0 dt)^2 / (8 m) for ever).
inline DofMotion book_dof(NodalEnergySums& e, Real m, Real vold, Real vnew, Real fi, Real fe,
                          const VelocityStep& s) {
  const DofMotion d{0.5 * (vold + vnew), 0.5 * s.dt_prev * vold,
                    s.first ? s.dt_avg * 0.5 * (vold + vnew) : 0.5 * s.dt_next * vnew};
  const Real vk = s.first ? vold : d.vbar;
  e.kinetic += 0.5 * m * vk * vk;
  e.stress.add(-fi, d.dprev, d.dnext);
  e.external.add(fe, d.dprev, d.dnext);
  return d;
}

/// x^{n+1} = x^n + dt v^{n+1/2}.
void update_positions(NodalFields& nodes, Real dt);

}  // namespace slideline
