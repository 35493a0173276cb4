// Simulation: the constraint phase of a cycle (docs/solver.md, "Constraint order"): tied slaves
// condensed onto their masters, rigid bodies, supports, Lagrange-multiplier contact, reactions.
#include "slideline/core/parallel.hpp"
#include "slideline/solver/simulation.hpp"
#include "slideline/solver/total_force.hpp"

namespace slideline {

void Simulation::apply_constraints(const StepPlan& plan) {
  // 1. tied slaves condensed onto their masters (totals formed for every contact model);
  // 2. rigid bodies from the total loads and effective masses;
  // 3. supports prescribe their components (they win over rigid bodies and ties);
  // 4. Lagrange-multiplier contact at the predicted x^{n+1}, with the components fixed by 2-3
  //    immovable; then 2-3 again so that rigid bodies carry the contact forces on their nodes;
  // 5. support reactions from the final loads.
  // Tied slaves follow their masters after the velocity and position updates.
  if (has_contact()) condense_ties();
  constrain_rigid_bodies(plan);
  prescribe_supports(plan);
  if (has_contact()) {
    const StepTimes times{t_, dt_, plan.dt_avg, plan.dt_next, cycle_, dt_initial_};
    ConstraintView view{nodes_,
                        effective_mass(),
                        alpha_,
                        {roles_.fixed(0), roles_.fixed(1), roles_.fixed(2)},
                        roles_.rigid(),
                        nodes_.a,
                        f_total_,
                        nodes_.f_contact};
    contacts_.enforce(view, times);
    if (!constraints_.empty()) {
      constrain_rigid_bodies(plan);
      prescribe_supports(plan);
    }
  }
  compute_reactions();
}

ConstraintLoads Simulation::constraint_loads() const {
  if (!has_contact()) return ConstraintLoads{nodes_.mass, nodes_};
  return ConstraintLoads{effective_mass(), nodes_, &f_total_, &m_total_};
}

void Simulation::condense_ties() {
  // Total loads: the nodes' own, then tied slaves moved onto their masters.
  const Index n = static_cast<Index>(nodes_.size());
  const bool condensing = contacts_.condenses();
  const bool rotations = has_rotations_;
  parallel_for(n, [&](Index i) {
    for (int c = 0; c < 3; ++c) f_total_[c][i] = total_force(nodes_, c, i);
    if (rotations)
      for (int c = 0; c < 3; ++c) m_total_[c][i] = total_moment(nodes_, c, i);
    if (condensing) {
      mass_eff_[i] = nodes_.mass[i];
      rot_inertia_eff_[i] = nodes_.rot_inertia[i];
    }
  });
  if (!condensing) return;
  contacts_.condense(nodes_, CondenseView{mass_eff_, f_total_, rot_inertia_eff_, m_total_});
  const auto kinds = roles_.kinds();
  parallel_for(n, [&](Index i) {
    if (kinds[i] == kFree) return;  // unchanged by the condensation
    const Real m = mass_eff_[i];
    const Real inv = m > 0.0 ? 1.0 / m : 0.0;
    nodes_.a.x[i] = f_total_.x[i] * inv;
    nodes_.a.y[i] = f_total_.y[i] * inv;
    nodes_.a.z[i] = f_total_.z[i] * inv;
    if (rotations && nodes_.has_rotation[i]) {
      const Real ri = rot_inertia_eff_[i];
      const Real rinv = ri > 0.0 ? 1.0 / ri : 0.0;
      nodes_.alpha.x[i] = m_total_.x[i] * rinv;
      nodes_.alpha.y[i] = m_total_.y[i] * rinv;
      nodes_.alpha.z[i] = m_total_.z[i] * rinv;
    }
  });
}

void Simulation::constrain_rigid_bodies(const StepPlan& plan) {
  ConstraintLoads loads = constraint_loads();
  loads.dt_avg = plan.dt_avg;
  loads.dt_next = plan.dt_next;
  for (auto& c : constraints_) c->constrain_accelerations(loads, nodes_, t_);
}

void Simulation::prescribe_supports(const StepPlan& plan) {
  // The velocity each supported component must have over the coming step v^{n+1/2}: zero for a
  // fixed component; a displacement curve lands the node exactly on u(t^{n+1}); a velocity curve
  // gives v(t^{n+1/2}) (the midpoint rule: x follows the integral of the curve to second order,
  // exactly while the curve is linear over the step); an acceleration curve is a(t^n), integrated
  // by the same central difference as free nodes: v^{n+1/2} = v^{n-1/2} + a(t^n) dt_avg.
  const Real dt_new = plan.dt_next;
  if (roles_.has_timed_supports()) roles_.refresh_supports(supports_, t_);
  for (auto& g : supports_)
    for (const auto& s : g.supports) {
      const int c = static_cast<int>(s.axis);
      if (s.rotational || !s.active(t_)) continue;  // the velocity update zeroes fixed rotations
      for (Index i : s.nodes) {
        Real vnew = 0.0;
        if (s.has_curve) {
          switch (s.kind) {
            case Prescribed::displacement:
              vnew = (s.scale * s.curve(t_ + dt_new) - (nodes_.x[c][i] - nodes_.x0[c][i])) / dt_new;
              break;
            case Prescribed::velocity: vnew = s.scale * s.curve(t_ + 0.5 * dt_new); break;
            case Prescribed::acceleration: vnew = nodes_.v[c][i] + s.scale * s.curve(t_) * plan.dt_avg; break;
          }
        }
        nodes_.a[c][i] = (vnew - nodes_.v[c][i]) / plan.dt_avg;  // the velocity update lands on vnew
      }
    }
}

void Simulation::compute_reactions() {
  // R = F - m a_required: the force the body exerts on the support, including the load that
  // contact (penalty, Lagrange, or condensed tied slaves) carries into a supported node.
  const bool total = has_contact();
  const auto mass = effective_mass();
  for (auto& g : supports_) {
    Vec3 r = Vec3::Zero();
    for (const auto& s : g.supports) {
      if (s.rotational || !s.active(t_)) continue;
      const int c = static_cast<int>(s.axis);
      for (Index i : s.nodes) {
        const Real f = total ? f_total_[c][i] : total_force<false>(nodes_, c, i);
        r[c] += f - mass[i] * nodes_.a[c][i];
      }
    }
    g.reaction = r;
  }
}

}  // namespace slideline
