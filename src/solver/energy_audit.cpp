#include "slideline/solver/energy_audit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace slideline {

Real EnergyReport::relative_balance_error() const {
  const Real scale =
      std::max({std::abs(external) + std::abs(support) + std::abs(constraint) + kinetic0 + std::abs(mass_scaling), kinetic,
                std::abs(internal) + hourglass + bulk_viscosity + damping + std::abs(contact) + friction + eroded(),
                std::numeric_limits<Real>::min()});
  return balance_error() / scale;
}

NodalEnergySums dictated_node_sums(const NodalFields& nodes, std::span<const Index> idx, std::span<const Vec3> v_old,
                                   std::span<const Vec3> w_old, const VelocityStep& step) {
  NodalEnergySums e;
  for (std::size_t k = 0; k < idx.size(); ++k) {
    const Index i = idx[k];
    // One dof of mass (or rotary inertia) m: velocity before and after, internal and external load.
    const auto book = [&](Real m, Real vold, Real vnew, Real fi, Real fe) {
      const DofMotion d = book_dof(e, m, vold, vnew, fi, fe, step);
      const Real f = m * (vnew - vold) / step.dt_avg - fi - fe;  // the tie's force on the dof
      // On the first cycle book_dof's d.dnext is the travel under the impulse f dt_avg, so a slave
      // that starts with a velocity other than its master point's and is stopped dead there books
      // what the impulse does (docs/contact.md, "A tie that starts with a relative velocity").
      e.contact.add(f, d.dprev, d.dnext);
    };
    for (int c = 0; c < 3; ++c)
      book(nodes.mass[i], v_old[k][c], nodes.v[c][i], nodes.f_int[c][i], nodes.f_ext[c][i]);
    if (nodes.has_rotation[i] && nodes.rot_inertia[i] > 0.0)
      for (int c = 0; c < 3; ++c)
        book(nodes.rot_inertia[i], w_old[k][c], nodes.omega[c][i], nodes.m_int[c][i], nodes.m_ext[c][i]);
  }
  return e;
}

Real kinetic_energy(const NodalFields& nodes, std::span<const Index> idx) {
  Real k = 0.0;
  for (Index i : idx) {
    k += 0.5 * nodes.mass[i] * nodes.v.get(i).squaredNorm();
    if (nodes.has_rotation[i]) k += 0.5 * nodes.rot_inertia[i] * nodes.omega.get(i).squaredNorm();
  }
  return k;
}

Real translational_kinetic_energy(const NodalFields& nodes, std::span<const Index> idx) {
  Real k = 0.0;
  for (Index i : idx) k += 0.5 * nodes.mass[i] * nodes.v.get(i).squaredNorm();
  return k;
}

}  // namespace slideline
