#include "slideline/solver/central_difference.hpp"

#include "slideline/core/parallel.hpp"
#include "slideline/solver/total_force.hpp"

namespace slideline {

namespace {

template <bool kContact>
void form_accelerations_with(NodalFields& nodes, bool rotations) {
  const Index n = static_cast<Index>(nodes.size());
  parallel_for(n, [&](Index i) {
    const Real m = nodes.mass[i];
    const Real inv = m > 0.0 ? 1.0 / m : 0.0;
    nodes.a.x[i] = total_force<kContact>(nodes, 0, i) * inv;
    nodes.a.y[i] = total_force<kContact>(nodes, 1, i) * inv;
    nodes.a.z[i] = total_force<kContact>(nodes, 2, i) * inv;
    if (rotations && nodes.has_rotation[i]) {
      const Real ri = nodes.rot_inertia[i];
      const Real rinv = ri > 0.0 ? 1.0 / ri : 0.0;
      nodes.alpha.x[i] = total_moment<kContact>(nodes, 0, i) * rinv;
      nodes.alpha.y[i] = total_moment<kContact>(nodes, 1, i) * rinv;
      nodes.alpha.z[i] = total_moment<kContact>(nodes, 2, i) * rinv;
    }
  });
}

// The rotational part of one node's update (inertia > 0) and its energy sums.
void update_rotation(NodalFields& nodes, const NodeRoles& roles, Index i, Real al, const VelocityStep& s,
                     NodalEnergySums& e) {
  const Real dt_avg = s.dt_avg;
  const std::uint8_t kind = roles.kinds()[i];
  const Real inertia = nodes.rot_inertia[i];
  const Real h = 0.5 * al * dt_avg;
  for (int c = 0; c < 3; ++c) {
    const Real wold = nodes.omega[c][i];
    const Real mi = nodes.m_int[c][i];
    const Real me = nodes.m_ext[c][i];
    const Real mk = s.with_contact ? nodes.m_contact[c][i] : 0.0;
    const bool fixed = roles.fixed_rot(c)[i] != 0;
    const Real wnew = fixed ? 0.0 : ((1.0 - h) * wold + dt_avg * nodes.alpha[c][i]) / (1.0 + h);
    nodes.omega[c][i] = wnew;
    const DofMotion d = book_dof(e, inertia, wold, wnew, mi, me, s);
    e.contact.add(mk, d.dprev, d.dnext);
    e.damping.add(al * inertia * d.vbar, d.dprev, d.dnext);
    if (kind != kFree && !fixed) {
      const Real mc = inertia * (wnew - wold) / dt_avg - mi - me - mk + al * inertia * d.vbar;
      (kind == kRigid ? e.constraint : e.contact).add(mc, d.dprev, d.dnext);
    }
  }
}

}  // namespace

void form_accelerations(NodalFields& nodes, bool with_contact, bool rotations) {
  // Without contact f_contact stays zero and is not read.
  if (with_contact) form_accelerations_with<true>(nodes, rotations);
  else form_accelerations_with<false>(nodes, rotations);
}

NodalEnergySums update_velocities(NodalFields& nodes, const NodeRoles& roles, std::span<const Real> damping,
                                  const VelocityStep& s, std::span<NodalEnergySums> chunk_sums) {
  const Index n = static_cast<Index>(nodes.size());
  const Real dt_avg = s.dt_avg;
  // The kinetic energy at t^n is that of the mean of the half-step velocities, v(0) itself at
  // t = 0 (book_dof).
  const bool with_contact = s.with_contact;
  const auto kinds = roles.kinds();
  parallel_for_chunks(n, [&](Index b, Index end, Index chunk) {
    NodalEnergySums e;
    for (Index i = b; i < end; ++i) {
      const Real m = nodes.mass[i];
      const std::uint8_t kind = kinds[i];
      if (m <= 0.0 || kind == kDictated) continue;  // tied slaves: dictated_node_sums
      const Real al = damping[i];
      for (int c = 0; c < 3; ++c) {
        const Real vold = nodes.v[c][i];
        const bool fixed = roles.fixed(c)[i] != 0;
        Real vnew;
        if (fixed) {
          vnew = vold + dt_avg * nodes.a[c][i];  // a holds the required acceleration
        } else {
          const Real h = 0.5 * al * dt_avg;
          vnew = ((1.0 - h) * vold + dt_avg * nodes.a[c][i]) / (1.0 + h);
        }
        nodes.v[c][i] = vnew;
        const Real fi = nodes.f_int[c][i];
        const Real fe = nodes.f_ext[c][i];
        const Real fk = with_contact ? nodes.f_contact[c][i] : 0.0;
        const DofMotion d = book_dof(e, m, vold, vnew, fi, fe, s);
        const Real fd = fixed ? 0.0 : -al * m * d.vbar;
        if (with_contact) e.contact.add(fk, d.dprev, d.dnext);
        e.damping.add(-fd, d.dprev, d.dnext);
        if (fixed) {
          e.support.add(m * (vnew - vold) / dt_avg - fi - fe - fk, d.dprev, d.dnext);
        } else if (kind != kFree) {
          // The node's acceleration is the constraint's or the tie's, not the loads' over its own
          // mass: the difference is the force the rigid body or the tie applies.
          const Real fc = m * (vnew - vold) / dt_avg - fi - fe - fk - fd;
          (kind == kRigid ? e.constraint : e.contact).add(fc, d.dprev, d.dnext);
        }
      }
      if (nodes.has_rotation[i] && nodes.rot_inertia[i] > 0.0) update_rotation(nodes, roles, i, al, s, e);
    }
    chunk_sums[static_cast<std::size_t>(chunk)] = e;
  });
  NodalEnergySums total;
  for (const auto& e : chunk_sums) total += e;
  return total;
}

void update_positions(NodalFields& nodes, Real dt) {
  const Index n = static_cast<Index>(nodes.size());
  parallel_for(n, [&](Index i) {
    nodes.x.x[i] += dt * nodes.v.x[i];
    nodes.x.y[i] += dt * nodes.v.y[i];
    nodes.x.z[i] += dt * nodes.v.z[i];
  });
}

}  // namespace slideline
