#include "slideline/solver/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "slideline/core/error.hpp"
#include "slideline/core/parallel.hpp"

namespace slideline {

namespace {
// Energy partial sums per chunk: kinetic, then (a, b) halves of the trapezoid for internal,
// external, damping, support and constraint work (see compute_reactions_and_velocities).
constexpr int kEnergyTerms = 11;

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

Real EnergyReport::relative_balance_error() const {
  const Real scale = std::max({std::abs(external) + std::abs(support) + std::abs(constraint) + kinetic0,
                               kinetic,
                               std::abs(internal) + hourglass + bulk_viscosity + damping,
                               std::numeric_limits<Real>::min()});
  return balance_error() / scale;
}

Index Simulation::element_count() const {
  Index n = 0;
  for (const auto& b : blocks) n += b->element_count();
  return n;
}

MeshDescription Simulation::mesh_description() const {
  MeshDescription m;
  m.node_ids = nodes.ids;
  const std::size_t n = nodes.size();
  m.x0.resize(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    m.x0[3 * i] = nodes.x0.x[i];
    m.x0[3 * i + 1] = nodes.x0.y[i];
    m.x0[3 * i + 2] = nodes.x0.z[i];
  }
  for (const auto& b : blocks) {
    const auto conn = b->connectivity();
    auto& dst = b->nodes_per_element() == 8 ? m.hex_connectivity : m.quad_connectivity;
    if (b->nodes_per_element() == 8 || b->nodes_per_element() == 4)
      dst.insert(dst.end(), conn.begin(), conn.end());
  }
  return m;
}

void Simulation::initialize() {
  const Index n = static_cast<Index>(nodes.size());
  if (controls.end_time <= 0.0 && controls.max_cycles <= 0)
    throw InputError("simulation: end time must be positive (got " +
                     std::to_string(controls.end_time) + ")");
  if (!(controls.dt_scale > 0.0 && controls.dt_scale <= 1.0))
    throw InputError("simulation: time-step scale factor must be in (0, 1] (got " +
                     std::to_string(controls.dt_scale) + ")");

  // Masses and corner slots.
  std::vector<std::pair<Index, Index>> force_pairs, moment_pairs;
  Index fbase = 0, mbase = 0;
  std::vector<std::vector<Real>> block_mass;  // mass each block lumps to each node
  std::vector<Real> before;
  for (auto& b : blocks) {
    b->set_slot_base(fbase, mbase);
    before = nodes.mass;
    b->initialize(nodes);
    block_mass.emplace_back(nodes.mass);
    for (Index i = 0; i < n; ++i) block_mass.back()[i] -= before[i];
    const auto conn = b->connectivity();
    for (std::size_t k = 0; k < conn.size(); ++k) {
      if (conn[k] < 0 || conn[k] >= n)
        throw InputError("element block of part " + std::to_string(b->part_id()) +
                         " refers to a node index out of range");
      force_pairs.emplace_back(conn[k], fbase + static_cast<Index>(k));
      if (b->has_moments()) moment_pairs.emplace_back(conn[k], mbase + static_cast<Index>(k));
    }
    fbase += static_cast<Index>(conn.size());
    if (b->has_moments()) mbase += static_cast<Index>(conn.size());
  }
  corners_.force.resize(fbase);
  corners_.moment.resize(mbase);
  corners_.force_slots.build(n, force_pairs);
  if (mbase > 0) corners_.moment_slots.build(n, moment_pairs);
  for (auto& c : constraints) c->initialize(nodes);
  has_rotations_ = std::any_of(nodes.has_rotation.begin(), nodes.has_rotation.end(),
                               [](std::uint8_t r) { return r != 0; });
  constrained_.assign(n, 0);
  constrained_nodes_.clear();
  for (const auto& c : constraints)
    for (Index i : c->constrained_nodes()) {
      if (i < 0 || i >= n) throw InputError("a nodal constraint refers to a node index out of range");
      if (!constrained_[i]) constrained_nodes_.push_back(i);
      constrained_[i] = 1;
    }

  // Body loads act on the mass of the loaded parts only.
  for (auto& bl : body_loads) {
    std::vector<Real> m(n, 0.0);
    for (std::size_t k = 0; k < blocks.size(); ++k)
      if (bl.parts.empty() ||
          std::find(bl.parts.begin(), bl.parts.end(), blocks[k]->part_id()) != bl.parts.end())
        for (Index i = 0; i < n; ++i) m[i] += block_mass[k][i];
    bl.nodes.clear();
    bl.mass.clear();
    for (Index i = 0; i < n; ++i)
      if (m[i] > 0.0) {
        bl.nodes.push_back(i);
        bl.mass.push_back(m[i]);
      }
  }

  // Supports.
  for (auto& f : fixed_) f.assign(n, 0);
  for (auto& f : fixed_rot_) f.assign(n, 0);
  for (const auto& g : supports)
    for (const auto& s : g.supports)
      for (Index i : s.nodes) {
        if (i < 0 || i >= n) throw InputError("support " + g.name + " refers to a missing node");
        (s.rotational ? fixed_rot_ : fixed_)[static_cast<int>(s.axis)][i] = 1;
      }

  // Damping.
  alpha_.assign(n, 0.0);
  has_damping_curves_ = false;
  for (const auto& d : damping) has_damping_curves_ = has_damping_curves_ || d.has_curve;
  update_damping_coefficients();

  // History channels.
  channels_.clear();
  for (const auto& c : contacts) {
    channels_.push_back({"interfaces/" + c->name() + "/slave_force", 3});
    channels_.push_back({"interfaces/" + c->name() + "/master_force", 3});
  }
  for (const auto& g : supports) channels_.push_back({"supports/" + g.name + "/reaction", 3});
  constraint_outputs_.clear();
  std::vector<std::string> names;
  for (const auto& c : constraints) {
    names.clear();
    c->append_output_names(names);
    for (auto& s : names) channels_.push_back({std::move(s), 3});
    constraint_outputs_.push_back(3 * names.size());
  }
  for (Index i : history_nodes) {
    if (i < 0 || i >= n) throw InputError("history node index out of range");
    channels_.push_back({"nodes/" + std::to_string(nodes.ids[i]) + "/displacement", 3});
  }
  for (const char* e : {"kinetic", "internal", "hourglass", "bulk_viscosity", "damping", "external",
                        "support", "constraint", "balance_error"})
    channels_.push_back({std::string("energy/") + e, 1});
  std::size_t width = 0;
  for (const auto& c : channels_) width += c.components;
  history_values_.assign(width, 0.0);
  state_values_.assign(3 * static_cast<std::size_t>(n), 0.0);
  chunk_e_.assign(static_cast<std::size_t>(chunk_count(n)) * kEnergyTerms, 0.0);

  for (auto& c : contacts) c->initialize(nodes);
  t_ = 0.0;
  dt_ = 0.0;
  cycle_ = 0;
  energy_ = EnergyReport{};
  stress_work_ = external_work_ = damping_work_ = support_work_ = constraint_work_ = 0.0;
  compute_forces();
  if (!(dt_crit_ > 0.0) || !std::isfinite(dt_crit_))
    throw InputError("simulation: no stable time step (is there at least one element?)");
  initialized_ = true;
}

void Simulation::update_damping_coefficients() {
  if (!has_damping_curves_ && cycle_ > 0) return;
  std::fill(alpha_.begin(), alpha_.end(), 0.0);
  for (const auto& d : damping) {
    const Real a = d.value(t_);
    if (d.nodes.empty())
      for (Real& v : alpha_) v += a;
    else
      for (Index i : d.nodes) alpha_[i] += a;
  }
}

void Simulation::compute_forces() {
  const auto t0 = std::chrono::steady_clock::now();
  Real dtc = std::numeric_limits<Real>::max();
  BlockEnergy be;
  try {
    Real dt_other = std::numeric_limits<Real>::max();  // steps of blocks that do not bound it
    for (auto& b : blocks) {
      const Real d = b->compute_forces(nodes, dt_, corners_, be);
      if (b->bounds_time_step())
        dtc = std::min(dtc, d);
      else
        dt_other = std::min(dt_other, d);
    }
    if (dtc == std::numeric_limits<Real>::max()) dtc = dt_other;
  } catch (const InstabilityError& e) {
    throw InstabilityError(std::string(e.what()) + " at t = " + std::to_string(t_) +
                               ", cycle " + std::to_string(cycle_),
                           t_, cycle_);
  }
  corners_.gather(nodes.f_int, nodes.m_int);
  element_seconds_ += seconds_since(t0);
  // Hourglass and bulk-viscosity powers at t^n, integrated over the coming average step.
  const Real dt_avg = cycle_ == 0 ? 0.0 : dt_;
  energy_.hourglass += be.hourglass_power * dt_avg;
  energy_.bulk_viscosity += be.viscous_power * dt_avg;

  // External forces, in parallel: serial node loops here would cap the two-thread speed-up.
  const Index n = static_cast<Index>(nodes.size());
  const bool rotations = has_rotations_;
  parallel_for(n, [&](Index i) {
    nodes.f_ext.x[i] = 0.0;
    nodes.f_ext.y[i] = 0.0;
    nodes.f_ext.z[i] = 0.0;
    if (rotations) {
      nodes.m_ext.x[i] = 0.0;
      nodes.m_ext.y[i] = 0.0;
      nodes.m_ext.z[i] = 0.0;
    }
  });
  for (const auto& bl : body_loads) {
    const Real acc = bl.scale * bl.curve(t_);
    auto& f = nodes.f_ext[static_cast<int>(bl.axis)];
    // bl.nodes is unique, so the iterations write distinct entries.
    parallel_for(static_cast<Index>(bl.nodes.size()),
                 [&](Index k) { f[bl.nodes[k]] += bl.mass[k] * acc; });
  }
  const auto t1 = std::chrono::steady_clock::now();
  for (auto& c : contacts) {
    c->apply_forces(nodes, t_, dt_);
    dtc = std::min(dtc, c->stable_dt());
  }
  contact_seconds_ += seconds_since(t1);
  dt_crit_ = dtc;
}

void Simulation::form_accelerations() {
  const Index n = static_cast<Index>(nodes.size());
  parallel_for(n, [&](Index i) {
    const Real m = nodes.mass[i];
    const Real inv = m > 0.0 ? 1.0 / m : 0.0;
    nodes.a.x[i] = (nodes.f_int.x[i] + nodes.f_ext.x[i]) * inv;
    nodes.a.y[i] = (nodes.f_int.y[i] + nodes.f_ext.y[i]) * inv;
    nodes.a.z[i] = (nodes.f_int.z[i] + nodes.f_ext.z[i]) * inv;
  });
}

void Simulation::compute_reactions_and_velocities(Real dt_avg, Real dt_new) {
  // Prescribed velocity of each supported component over the coming step. Zero unless the
  // support follows a displacement curve; then it lands the node exactly on u(t^{n+1}).
  for (auto& g : supports) {
    Vec3 r = Vec3::Zero();
    for (const auto& s : g.supports) {
      if (s.rotational) continue;
      const int c = static_cast<int>(s.axis);
      for (Index i : s.nodes) {
        Real vnew = 0.0;
        if (s.has_curve) {
          const Real u_now = nodes.x[c][i] - nodes.x0[c][i];
          vnew = (s.scale * s.curve(t_ + dt_new) - u_now) / dt_new;
        }
        const Real m = nodes.mass[i];
        const Real vold = nodes.v[c][i];
        const Real a_req = (vnew - vold) / dt_avg;
        r[c] += nodes.f_int[c][i] + nodes.f_ext[c][i] - m * a_req;
        nodes.a[c][i] = a_req;  // the velocity update below then lands on vnew (see there)
      }
    }
    g.reaction = r;
  }

  const Index n = static_cast<Index>(nodes.size());
  const Real dt_old = dt_;
  // The kinetic energy at t^n is that of the mean of the half-step velocities, except at t = 0:
  // there the initial velocity is v(0) itself (the first step is a half step from it), and the
  // mean would put an O(dt) offset into the balance that never goes away.
  const bool first = cycle_ == 0;
  parallel_for_chunks(n, [&](Index b, Index end, Index chunk) {
    Real e[kEnergyTerms] = {};
    for (Index i = b; i < end; ++i) {
      const Real m = nodes.mass[i];
      if (m <= 0.0) continue;
      const Real al = alpha_[i];
      for (int c = 0; c < 3; ++c) {
        const Real vold = nodes.v[c][i];
        Real vnew;
        if (fixed_[c][i]) {
          vnew = vold + dt_avg * nodes.a[c][i];  // a holds the required acceleration
        } else {
          const Real h = 0.5 * al * dt_avg;
          vnew = ((1.0 - h) * vold + dt_avg * nodes.a[c][i]) / (1.0 + h);
        }
        nodes.v[c][i] = vnew;
        const Real vbar = 0.5 * (vold + vnew);
        const Real dprev = 0.5 * dt_old * vold;  // half of x^n - x^{n-1}
        const Real dnext = 0.5 * dt_new * vnew;  // half of x^{n+1} - x^n
        const Real fi = nodes.f_int[c][i];
        const Real fe = nodes.f_ext[c][i];
        const Real fd = fixed_[c][i] ? 0.0 : -al * m * vbar;
        const Real fs = fixed_[c][i] ? m * (vnew - vold) / dt_avg - fi - fe : 0.0;
        // A constrained node's acceleration is the constraint's, not (fi + fe) / m: the
        // difference is the force the constraint applies (a support on the same component wins).
        const Real fc = constrained_[i] && !fixed_[c][i] ? m * (vnew - vold) / dt_avg - fi - fe - fd : 0.0;
        const Real vk = first ? vold : vbar;
        e[0] += 0.5 * m * vk * vk;
        e[1] -= fi * dprev;
        e[2] -= fi * dnext;
        e[3] += fe * dprev;
        e[4] += fe * dnext;
        e[5] -= fd * dprev;
        e[6] -= fd * dnext;
        e[7] += fs * dprev;
        e[8] += fs * dnext;
        e[9] += fc * dprev;
        e[10] += fc * dnext;
      }
      if (nodes.has_rotation[i] && nodes.rot_inertia[i] > 0.0) {
        const Real inertia = nodes.rot_inertia[i];
        const Real h = 0.5 * al * dt_avg;
        for (int c = 0; c < 3; ++c) {
          const Real wold = nodes.omega[c][i];
          const Real mom = nodes.m_int[c][i] + nodes.m_ext[c][i];
          const Real wnew =
              fixed_rot_[c][i] ? 0.0 : ((1.0 - h) * wold + dt_avg * mom / inertia) / (1.0 + h);
          nodes.omega[c][i] = wnew;
          const Real wbar = 0.5 * (wold + wnew);
          const Real dprev = 0.5 * dt_old * wold;
          const Real dnext = 0.5 * dt_new * wnew;
          const Real wk = first ? wold : wbar;
          e[0] += 0.5 * inertia * wk * wk;
          e[1] -= nodes.m_int[c][i] * dprev;
          e[2] -= nodes.m_int[c][i] * dnext;
          e[3] += nodes.m_ext[c][i] * dprev;
          e[4] += nodes.m_ext[c][i] * dnext;
          e[5] += al * inertia * wbar * dprev;
          e[6] += al * inertia * wbar * dnext;
          if (constrained_[i] && !fixed_rot_[c][i]) {
            const Real mc = inertia * (wnew - wold) / dt_avg - mom + al * inertia * wbar;
            e[9] += mc * dprev;
            e[10] += mc * dnext;
          }
        }
      }
    }
    std::copy(e, e + kEnergyTerms, chunk_e_.begin() + static_cast<std::ptrdiff_t>(chunk) * kEnergyTerms);
  });
  Real e[kEnergyTerms] = {};
  const Index nchunks = chunk_count(n);
  for (Index c = 0; c < nchunks; ++c)
    for (int k = 0; k < kEnergyTerms; ++k) e[k] += chunk_e_[static_cast<std::size_t>(c) * kEnergyTerms + k];
  // The works up to t^n are the committed sums plus the (a) halves; the (b) halves belong to the
  // next interval and are committed now.
  energy_.kinetic = e[0];
  if (cycle_ == 0) energy_.kinetic0 = e[0];
  stress_work_ += e[1];
  energy_.external = external_work_ + e[3];
  energy_.damping = damping_work_ + e[5];
  energy_.support = support_work_ + e[7];
  energy_.constraint = constraint_work_ + e[9];
  energy_.internal = stress_work_ - energy_.hourglass - energy_.bulk_viscosity;
  stress_work_ += e[2];
  external_work_ += e[3] + e[4];
  damping_work_ += e[5] + e[6];
  support_work_ += e[7] + e[8];
  constraint_work_ += e[9] + e[10];
}

void Simulation::update_positions(Real dt_new) {
  const Index n = static_cast<Index>(nodes.size());
  parallel_for(n, [&](Index i) {
    nodes.x.x[i] += dt_new * nodes.v.x[i];
    nodes.x.y[i] += dt_new * nodes.v.y[i];
    nodes.x.z[i] += dt_new * nodes.v.z[i];
  });
}

Real Simulation::constrained_kinetic_energy() const {
  // Half-step velocities of the constrained nodes (serial: a fixed summation order).
  Real k = 0.0;
  for (Index i : constrained_nodes_) {
    k += 0.5 * nodes.mass[i] * nodes.v.get(i).squaredNorm();
    if (nodes.has_rotation[i]) k += 0.5 * nodes.rot_inertia[i] * nodes.omega.get(i).squaredNorm();
  }
  return k;
}

void Simulation::collect_history(std::vector<Real>& values) const {
  std::size_t k = 0;
  auto put3 = [&](const Vec3& v) {
    values[k++] = v[0];
    values[k++] = v[1];
    values[k++] = v[2];
  };
  for (const auto& c : contacts) {
    put3(c->slave_force());
    put3(c->master_force());
  }
  for (const auto& g : supports) put3(g.reaction);
  for (std::size_t c = 0; c < constraints.size(); ++c) {
    constraints[c]->write_output_values(std::span<Real>(values).subspan(k, constraint_outputs_[c]));
    k += constraint_outputs_[c];
  }
  for (Index i : history_nodes) put3(nodes.displacement(i));
  const EnergyReport& e = energy_;
  for (Real v : {e.kinetic, e.internal, e.hourglass, e.bulk_viscosity, e.damping, e.external,
                 e.support, e.constraint, e.balance_error()})
    values[k++] = v;
}

void Simulation::write_outputs(const std::vector<OutputSink*>& sinks, bool force) {
  const Real tol = 1e-9 * std::max(dt_crit_, 1e-300);
  const Real hi = controls.history_interval;
  const bool history_due =
      force || hi <= 0.0 || last_history_ < 0.0 || t_ >= next_output_time(hi, last_history_) - tol;
  if (history_due && t_ != last_history_) {
    collect_history(history_values_);
    for (auto* s : sinks) s->write_history(t_, history_values_);
    last_history_ = t_;
  }
  const Real si = controls.state_interval;
  if (si > 0.0 &&
      (force || last_state_ < 0.0 || t_ >= next_output_time(si, last_state_) - tol) &&
      t_ != last_state_) {
    const std::size_t n = nodes.size();
    for (std::size_t i = 0; i < n; ++i) {
      state_values_[3 * i] = nodes.x.x[i] - nodes.x0.x[i];
      state_values_[3 * i + 1] = nodes.x.y[i] - nodes.x0.y[i];
      state_values_[3 * i + 2] = nodes.x.z[i] - nodes.x0.z[i];
    }
    for (auto* s : sinks) s->write_state(t_, state_values_);
    last_state_ = t_;
  }
}

Real Simulation::next_output_time(Real interval, Real after) const {
  // Output times are exact multiples of the interval: the first one strictly after `after`
  // (a time that already sits on a multiple, to round-off, counts as that multiple).
  if (after < 0.0) return 0.0;
  const Real k = std::floor(after / interval + 1e-9) + 1.0;
  return k * interval;
}

bool Simulation::step() {
  if (!initialized_) initialize();
  if (finished_) return false;
  const Real end = controls.end_time;
  // Time tolerance relative to the run's own time scale (an absolute one would swallow whole
  // steps of a nanosecond-scale run), far above the round-off of t.
  const Real tol_t =
      1e-12 * (end > 0.0 ? end : std::max({t_, controls.history_interval, controls.state_interval}));
  const bool at_end = (controls.end_time > 0.0 && t_ >= end - tol_t) ||
                      (controls.max_cycles > 0 && cycle_ >= controls.max_cycles);

  // The coming step: the scaled stable step, shortened to land exactly on the next output time.
  Real dt_new = controls.dt_scale * dt_crit_;
  if (controls.dt_max > 0.0) dt_new = std::min(dt_new, controls.dt_max);
  Real target = end > 0.0 ? end : std::numeric_limits<Real>::infinity();
  if (controls.history_interval > 0.0)
    target = std::min(target, next_output_time(controls.history_interval, t_));
  if (controls.state_interval > 0.0)
    target = std::min(target, next_output_time(controls.state_interval, t_));
  // The last output multiple can fall an ulp short of the end time (50 x 2e-6 < 1e-4): land on
  // the end time itself, or the run would end there and record its last values at the wrong time.
  if (end > 0.0 && target >= end - tol_t) target = end;
  bool lands = false;
  if (!at_end && target > t_ + tol_t && t_ + dt_new >= target - tol_t) {
    dt_new = target - t_;
    lands = true;
  }
  if (at_end) dt_new = dt_ > 0.0 ? dt_ : dt_new;
  if (!(dt_new > 0.0) || !std::isfinite(dt_new))
    throw InstabilityError("time step collapsed to " + std::to_string(dt_new) + " at t = " +
                               std::to_string(t_) + ", cycle " + std::to_string(cycle_),
                           t_, cycle_);
  const Real dt_avg = cycle_ == 0 ? 0.5 * dt_new : 0.5 * (dt_ + dt_new);

  form_accelerations();
  for (auto& c : constraints) c->constrain_accelerations(nodes, t_);
  for (auto& c : contacts) c->constrain_accelerations(nodes, t_, dt_avg);
  update_damping_coefficients();
  compute_reactions_and_velocities(dt_avg, dt_new);
  if (sinks_ != nullptr) write_outputs(*sinks_, at_end);
  if (at_end) {
    finished_ = true;
    return false;
  }

  update_positions(dt_new);
  t_ = lands ? target : t_ + dt_new;
  dt_ = dt_new;
  ++cycle_;
  // The constraints reset the half-step velocities of their nodes; the kinetic energy that changes
  // is work the constraint does (with constant steps this closes the balance up to a bounded
  // O(dt^2) term, as for unconstrained nodes).
  if (!constraints.empty()) {
    const Real k_before = constrained_kinetic_energy();
    for (auto& c : constraints) c->after_positions(nodes, t_);
    constraint_work_ += constrained_kinetic_energy() - k_before;
  }
  compute_forces();
  return true;
}

void Simulation::run(const std::vector<OutputSink*>& sinks,
                     const std::function<void(const Simulation&)>& progress, long progress_every) {
  if (!initialized_) initialize();
  const MeshDescription mesh = mesh_description();
  for (auto* s : sinks) s->begin(channels_, mesh);
  sinks_ = &sinks;
  try {
    while (step()) {
      if (progress && progress_every > 0 && cycle_ % progress_every == 0) progress(*this);
    }
  } catch (...) {
    for (auto* s : sinks) s->flush();
    sinks_ = nullptr;
    throw;
  }
  for (auto* s : sinks) s->flush();
  sinks_ = nullptr;
}

}  // namespace slideline
