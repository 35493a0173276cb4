#include "slideline/solver/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "slideline/core/error.hpp"
#include "slideline/core/parallel.hpp"
#include "slideline/solver/step_control.hpp"

namespace slideline {

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

Real EnergyReport::relative_balance_error() const {
  const Real scale =
      std::max({std::abs(external) + std::abs(support) + std::abs(constraint) + kinetic0, kinetic,
                std::abs(internal) + hourglass + bulk_viscosity + damping + std::abs(contact) + friction,
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
  has_rotations_ = std::any_of(nodes.has_rotation.begin(), nodes.has_rotation.end(),
                               [](std::uint8_t r) { return r != 0; });
  // A moment on a node without rotational degrees of freedom would be lost: refuse it.
  for (const auto& nl : nodal_loads)
    if (nl.moment)
      for (Index i : nl.nodes)
        if (!nodes.has_rotation[i])
          throw InputError(nl.source + ": a moment (DOF 5-7) on node " + std::to_string(nodes.ids[i]) +
                           ", which has no rotational degrees of freedom (only shell nodes do)");

  // Who dictates each node's motion: rigid bodies first (their node lists are known before they
  // initialise), then contact ties (known after the interfaces initialise, below).
  node_kind_.assign(n, kFree);
  rigid_.assign(n, 0);
  constrained_nodes_.clear();
  for (const auto& c : constraints)
    for (Index i : c->constrained_nodes()) {
      if (i < 0 || i >= n) throw InputError("a nodal constraint refers to a node index out of range");
      if (!rigid_[i]) constrained_nodes_.push_back(i);
      rigid_[i] = 1;
      node_kind_[i] = kRigid;
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
  has_timed_supports_ = false;
  for (const auto& g : supports)
    for (const auto& s : g.supports) {
      has_timed_supports_ = has_timed_supports_ || s.timed();
      for (Index i : s.nodes)
        if (i < 0 || i >= n) throw InputError("support " + g.name + " refers to a missing node");
    }
  for (auto& f : fixed_) f.assign(n, 0);
  for (auto& f : fixed_rot_) f.assign(n, 0);
  refresh_support_flags();

  // Damping.
  alpha_.assign(n, 0.0);
  has_damping_curves_ = false;
  for (const auto& d : damping) has_damping_curves_ = has_damping_curves_ || d.has_curve;
  update_damping_coefficients();

  // Contact interfaces, then the nodes their ties dictate, then the rigid bodies (which need the
  // effective mass: a slave tied to a rigid master moves with the body).
  t_ = 0.0;
  dt_ = 0.0;
  cycle_ = 0;
  contacts.initialize(ContactContext{nodes, blocks, &sets, rigid_});
  contacts.resolve_initial_penetrations(nodes);
  // A rigid body's mass properties take the tied slaves condensed onto it once, here: a tie that
  // is born or dies mid-run would change them.
  if (!constraints.empty())
    for (std::size_t k = 0; k < contacts.size(); ++k)
      if (contacts.window(k).timed() && contacts[k].condenses())
        throw NotImplementedError("contact " + contacts[k].name() +
                                  ": a tied interface with a birth or death time (BT, DT) in a model with rigid "
                                  "bodies is not supported");
  classify_contact_nodes();
  if (!contacts.empty()) {
    f_total_.resize(n);
    m_total_.resize(n);
  }
  mass_eff_ = nodes.mass;
  rot_inertia_eff_ = nodes.rot_inertia;
  if (contacts.condenses()) {
    // The condensed mass of constant ties, for the rigid bodies' mass properties.
    f_total_.fill(0.0);
    m_total_.fill(0.0);
    contacts.condense(nodes, CondenseView{mass_eff_, f_total_, rot_inertia_eff_, m_total_});
  }
  for (auto& c : constraints) c->initialize(nodes, effective_mass());

  // History channels.
  channels_.clear();
  contact_outputs_.clear();
  std::vector<std::string> names;
  for (const auto& c : contacts) {
    channels_.push_back({"interfaces/" + c->name() + "/slave_force", 3});
    channels_.push_back({"interfaces/" + c->name() + "/master_force", 3});
    names.clear();
    c->append_output_names(names);
    for (auto& s : names) channels_.push_back({"interfaces/" + c->name() + "/" + s, 3});
    contact_outputs_.push_back(3 * names.size());
  }
  for (const auto& g : supports) channels_.push_back({"supports/" + g.name + "/reaction", 3});
  constraint_outputs_.clear();
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
  for (const char* e : EnergyReport::names) channels_.push_back({std::string("energy/") + e, 1});
  std::size_t width = 0;
  for (const auto& c : channels_) width += c.components;
  history_values_.assign(width, 0.0);
  state_values_.assign(3 * static_cast<std::size_t>(n), 0.0);
  chunk_e_.assign(static_cast<std::size_t>(chunk_count(n)), NodalEnergySums{});

  ledger_.reset();
  part_energy_.reset(blocks);
  compute_internal_forces();
  compute_external_forces();
  apply_contact_forces();
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

// ---- Forces at t^n -------------------------------------------------------------------------

void Simulation::compute_internal_forces() {
  const auto t0 = std::chrono::steady_clock::now();
  Real dtc = std::numeric_limits<Real>::max();
  BlockEnergy be;
  try {
    Real dt_other = std::numeric_limits<Real>::max();  // steps of blocks that do not bound it
    const ElementBlock* controlling = nullptr;
    const ElementBlock* controlling_other = nullptr;
    for (std::size_t k = 0; k < blocks.size(); ++k) {
      const auto& b = blocks[k];
      BlockEnergy bk;
      const Real d = b->compute_forces(nodes, dt_, corners_, bk);
      be += bk;
      part_energy_.add(k, bk, cycle_ == 0 ? 0.0 : dt_);
      if (b->bounds_time_step()) {
        if (d < dtc) controlling = b.get();
        dtc = std::min(dtc, d);
      } else {
        if (d < dt_other) controlling_other = b.get();
        dt_other = std::min(dt_other, d);
      }
    }
    if (dtc == std::numeric_limits<Real>::max()) {
      dtc = dt_other;
      controlling = controlling_other;
    }
    if (controlling != nullptr && (controlling->part_id() != dt_part_ || dt_kind_.empty())) {
      dt_part_ = controlling->part_id();
      dt_kind_ = controlling->kind();
    }
    dt_block_ = controlling;
  } catch (const InstabilityError& e) {
    throw InstabilityError(std::string(e.what()) + " at t = " + std::to_string(t_) +
                               ", cycle " + std::to_string(cycle_),
                           t_, cycle_);
  }
  corners_.gather(nodes.f_int, nodes.m_int);
  element_seconds_ += seconds_since(t0);
  // Element powers at t^n, integrated over the step that ends at t^n.
  ledger_.add_element_powers(be.hourglass_power, be.viscous_power, be.damping_power,
                             cycle_ == 0 ? 0.0 : dt_);
  dt_elements_ = dtc;
  dt_crit_ = dtc;
}

void Simulation::compute_external_forces() {
  // In parallel: serial node loops here would cap the two-thread speed-up.
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
  // Serial and in card order: a node may appear in several loads (same sum for any thread count).
  for (const auto& nl : nodal_loads) {
    const Real v = nl.scale * nl.curve(t_);
    auto& f = nl.moment ? nodes.m_ext[static_cast<int>(nl.axis)] : nodes.f_ext[static_cast<int>(nl.axis)];
    for (Index i : nl.nodes) f[i] += v;
  }
}

void Simulation::apply_contact_forces() {
  Real dt_contact = std::numeric_limits<Real>::max();
  if (!contacts.empty()) {
    const auto t0 = std::chrono::steady_clock::now();
    // Birth and death (BT, DT): the interfaces that act in the cycle from t_ (contact_manager.hpp).
    if (contacts.update_activity(t_)) classify_contact_nodes();
    nodes.f_contact.fill(0.0);
    if (has_rotations_) nodes.m_contact.fill(0.0);
    // The coming step is not known yet (the interfaces vote for it here).
    const StepTimes times{t_, dt_, 0.0, 0.0, cycle_};
    dt_contact = contacts.apply_forces(nodes, times, ContactForceView{nodes.f_contact, nodes.m_contact});
    contact_seconds_ += seconds_since(t0);
  }
  // Exchange points 1 and 2 (exchange.hpp): the forces of shared nodes, the step over all processes.
  exchange_->sum_forces(nodes);
  const StepVotes votes = exchange_->min_dt(StepVotes{dt_elements_, dt_contact});
  dt_elements_ = votes.elements;
  dt_crit_ = votes.stable();
}

// ---- The step --------------------------------------------------------------------------------

std::string Simulation::step_controller() const {
  if (dt_crit_ < dt_elements_) {
    std::size_t k = 0;
    for (std::size_t c = 1; c < contacts.size(); ++c)
      if (contacts.active(c) && (!contacts.active(k) || contacts[c].stable_dt() < contacts[k].stable_dt())) k = c;
    return contacts.size() > 0 ? "contact interface '" + contacts[k].name() + "'" : std::string("a contact interface");
  }
  if (dt_block_ == nullptr) return "no element";
  const Id e = dt_block_->smallest_step_element();
  return dt_block_->kind() + (e >= 0 ? " element " + std::to_string(e) : std::string(" elements")) + " of part " +
         std::to_string(dt_block_->part_id());
}

StepPlan Simulation::plan_step() const {
  StepPlan p;
  const Real end = controls.end_time;
  // Time tolerance relative to the run's own time scale (an absolute one would swallow whole
  // steps of a nanosecond-scale run), far above the round-off of t.
  const Real tol_t =
      1e-12 * (end > 0.0 ? end : std::max({t_, controls.history_interval, controls.state_interval}));
  p.at_end = (end > 0.0 && t_ >= end - tol_t) ||
             (controls.max_cycles > 0 && cycle_ >= controls.max_cycles);

  // The scaled stable step, divided so as to land exactly on the next output time.
  Real dt_new = controls.dt_scale * dt_crit_;
  if (controls.dt_max > 0.0) dt_new = std::min(dt_new, controls.dt_max);
  if (controls.has_dt_max_curve) dt_new = std::min(dt_new, controls.dt_max_curve(t_));
  Real target = end > 0.0 ? end : std::numeric_limits<Real>::infinity();
  if (controls.history_interval > 0.0)
    target = std::min(target, next_output_time(controls.history_interval, t_));
  if (controls.state_interval > 0.0)
    target = std::min(target, next_output_time(controls.state_interval, t_));
  // The last output multiple can fall an ulp short of the end time (50 x 2e-6 < 1e-4): land on
  // the end time itself, or the run would end there and record its last values at the wrong time.
  if (end > 0.0 && target >= end - tol_t) target = end;
  // Equal steps up to the target: shortening only the last step before each output makes the
  // central difference parametrically unstable (step_control.hpp).
  bool lands = false;
  if (!p.at_end) {
    const StepChoice s = step_towards(t_, target, dt_new, tol_t);
    dt_new = s.dt;
    lands = s.lands;
  }
  if (p.at_end) dt_new = dt_ > 0.0 ? dt_ : dt_new;
  p.dt_next = dt_new;
  p.dt_avg = cycle_ == 0 ? 0.5 * dt_new : 0.5 * (dt_ + dt_new);
  p.t_next = lands ? target : t_ + dt_new;
  return p;
}

bool Simulation::step() {
  if (!initialized_) initialize();
  if (finished_) return false;
  // The forces at t^n (and the stable step) were evaluated at the end of the last cycle, or by
  // initialize() for t = 0.
  const StepPlan plan = plan_step();
  if (!(plan.dt_next > 0.0) || !std::isfinite(plan.dt_next))
    throw InstabilityError("time step collapsed to " + std::to_string(plan.dt_next) + " at t = " +
                               std::to_string(t_) + ", cycle " + std::to_string(cycle_) +
                               "; the step is set by " + step_controller(),
                           t_, cycle_);
  if (cycle_ == 0) dt_first_ = plan.dt_next;
  if (controls.dt_min_fraction > 0.0 && !plan.at_end &&
      plan.dt_next < controls.dt_min_fraction * dt_first_ && plan.t_next < controls.end_time)
    throw InstabilityError("time step " + std::to_string(plan.dt_next) + " fell below " +
                               std::to_string(controls.dt_min_fraction) + " x the first step (" +
                               std::to_string(dt_first_) + ") at t = " + std::to_string(t_) + ", cycle " +
                               std::to_string(cycle_) + "; the step is set by " + step_controller(),
                           t_, cycle_);
  if (!plan.at_end && !(plan.t_next > t_))
    throw InstabilityError("time no longer advances at t = " + std::to_string(t_) + " (step " +
                               std::to_string(plan.dt_next) + "), cycle " + std::to_string(cycle_) +
                               "; the step is set by " + step_controller(),
                           t_, cycle_);
  form_accelerations();
  apply_constraints(plan);
  update_velocities(plan);
  check_stability();
  record_outputs(plan.at_end);
  if (plan.at_end) {
    finished_ = true;
    return false;
  }
  update_positions(plan);
  // Forces at t^{n+1}: the next cycle's loads and stable step.
  compute_internal_forces();
  compute_external_forces();
  apply_contact_forces();
  return true;
}

void Simulation::form_accelerations() {
  const Index n = static_cast<Index>(nodes.size());
  const bool rotations = has_rotations_;
  if (contacts.empty()) {  // no contact forces to read (f_contact stays zero)
    parallel_for(n, [&](Index i) {
      const Real m = nodes.mass[i];
      const Real inv = m > 0.0 ? 1.0 / m : 0.0;
      nodes.a.x[i] = (nodes.f_int.x[i] + nodes.f_ext.x[i]) * inv;
      nodes.a.y[i] = (nodes.f_int.y[i] + nodes.f_ext.y[i]) * inv;
      nodes.a.z[i] = (nodes.f_int.z[i] + nodes.f_ext.z[i]) * inv;
      if (rotations && nodes.has_rotation[i]) {
        const Real ri = nodes.rot_inertia[i];
        const Real rinv = ri > 0.0 ? 1.0 / ri : 0.0;
        nodes.alpha.x[i] = (nodes.m_int.x[i] + nodes.m_ext.x[i]) * rinv;
        nodes.alpha.y[i] = (nodes.m_int.y[i] + nodes.m_ext.y[i]) * rinv;
        nodes.alpha.z[i] = (nodes.m_int.z[i] + nodes.m_ext.z[i]) * rinv;
      }
    });
    return;
  }
  parallel_for(n, [&](Index i) {
    const Real m = nodes.mass[i];
    const Real inv = m > 0.0 ? 1.0 / m : 0.0;
    nodes.a.x[i] = (nodes.f_int.x[i] + nodes.f_ext.x[i] + nodes.f_contact.x[i]) * inv;
    nodes.a.y[i] = (nodes.f_int.y[i] + nodes.f_ext.y[i] + nodes.f_contact.y[i]) * inv;
    nodes.a.z[i] = (nodes.f_int.z[i] + nodes.f_ext.z[i] + nodes.f_contact.z[i]) * inv;
    if (rotations && nodes.has_rotation[i]) {
      const Real ri = nodes.rot_inertia[i];
      const Real rinv = ri > 0.0 ? 1.0 / ri : 0.0;
      nodes.alpha.x[i] = (nodes.m_int.x[i] + nodes.m_ext.x[i] + nodes.m_contact.x[i]) * rinv;
      nodes.alpha.y[i] = (nodes.m_int.y[i] + nodes.m_ext.y[i] + nodes.m_contact.y[i]) * rinv;
      nodes.alpha.z[i] = (nodes.m_int.z[i] + nodes.m_ext.z[i] + nodes.m_contact.z[i]) * rinv;
    }
  });
}

ConstraintLoads Simulation::constraint_loads() const {
  if (contacts.empty()) return ConstraintLoads{nodes.mass, nodes};
  return ConstraintLoads{effective_mass(), nodes, &f_total_, &m_total_};
}

void Simulation::condense_ties() {
  // Total loads: the nodes' own, then tied slaves moved onto their masters.
  const Index n = static_cast<Index>(nodes.size());
  const bool condensing = contacts.condenses();
  const bool rotations = has_rotations_;
  parallel_for(n, [&](Index i) {
    f_total_.x[i] = nodes.f_int.x[i] + nodes.f_ext.x[i] + nodes.f_contact.x[i];
    f_total_.y[i] = nodes.f_int.y[i] + nodes.f_ext.y[i] + nodes.f_contact.y[i];
    f_total_.z[i] = nodes.f_int.z[i] + nodes.f_ext.z[i] + nodes.f_contact.z[i];
    if (rotations) {
      m_total_.x[i] = nodes.m_int.x[i] + nodes.m_ext.x[i] + nodes.m_contact.x[i];
      m_total_.y[i] = nodes.m_int.y[i] + nodes.m_ext.y[i] + nodes.m_contact.y[i];
      m_total_.z[i] = nodes.m_int.z[i] + nodes.m_ext.z[i] + nodes.m_contact.z[i];
    }
    if (condensing) {
      mass_eff_[i] = nodes.mass[i];
      rot_inertia_eff_[i] = nodes.rot_inertia[i];
    }
  });
  if (!condensing) return;
  contacts.condense(nodes, CondenseView{mass_eff_, f_total_, rot_inertia_eff_, m_total_});
  parallel_for(n, [&](Index i) {
    if (node_kind_[i] == kFree) return;  // unchanged by the condensation
    const Real m = mass_eff_[i];
    const Real inv = m > 0.0 ? 1.0 / m : 0.0;
    nodes.a.x[i] = f_total_.x[i] * inv;
    nodes.a.y[i] = f_total_.y[i] * inv;
    nodes.a.z[i] = f_total_.z[i] * inv;
    if (rotations && nodes.has_rotation[i]) {
      const Real ri = rot_inertia_eff_[i];
      const Real rinv = ri > 0.0 ? 1.0 / ri : 0.0;
      nodes.alpha.x[i] = m_total_.x[i] * rinv;
      nodes.alpha.y[i] = m_total_.y[i] * rinv;
      nodes.alpha.z[i] = m_total_.z[i] * rinv;
    }
  });
}

void Simulation::constrain_rigid_bodies(const StepPlan& plan) {
  ConstraintLoads loads = constraint_loads();
  loads.dt_avg = plan.dt_avg;
  loads.dt_next = plan.dt_next;
  for (auto& c : constraints) c->constrain_accelerations(loads, nodes, t_);
}

void Simulation::refresh_support_flags() {
  // The components the active supports prescribe (all supports are active without BIRTH/DEATH).
  if (has_timed_supports_)
    for (const auto& g : supports)
      for (const auto& s : g.supports)
        for (Index i : s.nodes) (s.rotational ? fixed_rot_ : fixed_)[static_cast<int>(s.axis)][i] = 0;
  for (const auto& g : supports)
    for (const auto& s : g.supports)
      if (s.active(t_))
        for (Index i : s.nodes) (s.rotational ? fixed_rot_ : fixed_)[static_cast<int>(s.axis)][i] = 1;
}

void Simulation::prescribe_supports(const StepPlan& plan) {
  // The velocity each supported component must have over the coming step v^{n+1/2}: zero for a
  // fixed component; a displacement curve lands the node exactly on u(t^{n+1}); a velocity curve
  // gives v(t^{n+1/2}) (the midpoint rule: x follows the integral of the curve to second order,
  // exactly while the curve is linear over the step); an acceleration curve is a(t^n), integrated
  // by the same central difference as free nodes: v^{n+1/2} = v^{n-1/2} + a(t^n) dt_avg.
  const Real dt_new = plan.dt_next;
  if (has_timed_supports_) refresh_support_flags();
  for (auto& g : supports)
    for (const auto& s : g.supports) {
      const int c = static_cast<int>(s.axis);
      if (s.rotational || !s.active(t_)) continue;  // the velocity update zeroes fixed rotations
      for (Index i : s.nodes) {
        Real vnew = 0.0;
        if (s.has_curve) {
          switch (s.kind) {
            case Prescribed::displacement:
              vnew = (s.scale * s.curve(t_ + dt_new) - (nodes.x[c][i] - nodes.x0[c][i])) / dt_new;
              break;
            case Prescribed::velocity: vnew = s.scale * s.curve(t_ + 0.5 * dt_new); break;
            case Prescribed::acceleration: vnew = nodes.v[c][i] + s.scale * s.curve(t_) * plan.dt_avg; break;
          }
        }
        nodes.a[c][i] = (vnew - nodes.v[c][i]) / plan.dt_avg;  // the velocity update lands on vnew
      }
    }
}

void Simulation::compute_reactions() {
  // R = F - m a_required: the force the body exerts on the support, including the load that
  // contact (penalty, Lagrange, or condensed tied slaves) carries into a supported node.
  const bool total = !contacts.empty();
  const auto mass = effective_mass();
  for (auto& g : supports) {
    Vec3 r = Vec3::Zero();
    for (const auto& s : g.supports) {
      if (s.rotational || !s.active(t_)) continue;
      const int c = static_cast<int>(s.axis);
      for (Index i : s.nodes) {
        const Real f = total ? f_total_[c][i] : nodes.f_int[c][i] + nodes.f_ext[c][i];
        r[c] += f - mass[i] * nodes.a[c][i];
      }
    }
    g.reaction = r;
  }
}

void Simulation::apply_constraints(const StepPlan& plan) {
  // 1. tied slaves condensed onto their masters (totals formed for every contact model);
  // 2. rigid bodies from the total loads and effective masses;
  // 3. supports prescribe their components (they win over rigid bodies and ties);
  // 4. Lagrange-multiplier contact at the predicted x^{n+1}, with the components fixed by 2-3
  //    immovable; then 2-3 again so that rigid bodies carry the contact forces on their nodes;
  // 5. support reactions from the final loads.
  // Tied slaves follow their masters after the velocity and position updates.
  if (!contacts.empty()) condense_ties();
  constrain_rigid_bodies(plan);
  prescribe_supports(plan);
  if (!contacts.empty()) {
    const StepTimes times{t_, dt_, plan.dt_avg, plan.dt_next, cycle_};
    ConstraintView view{nodes,
                        effective_mass(),
                        alpha_,
                        {fixed_[0], fixed_[1], fixed_[2]},
                        rigid_,
                        nodes.a,
                        f_total_,
                        nodes.f_contact};
    contacts.enforce(view, times);
    if (!constraints.empty()) {
      constrain_rigid_bodies(plan);
      prescribe_supports(plan);
    }
  }
  compute_reactions();
}

void Simulation::update_velocities(const StepPlan& plan) {
  update_damping_coefficients();
  const Real dt_avg = plan.dt_avg;
  const Real dt_new = plan.dt_next;
  for (std::size_t k = 0; k < dictated_nodes_.size(); ++k) {
    dictated_v_old_[k] = nodes.v.get(dictated_nodes_[k]);
    dictated_w_old_[k] = nodes.omega.get(dictated_nodes_[k]);
  }
  const Index n = static_cast<Index>(nodes.size());
  const Real dt_old = dt_;
  // The kinetic energy at t^n is that of the mean of the half-step velocities, except at t = 0:
  // there the initial velocity is v(0) itself (the first step is a half step from it), and the
  // mean would put an O(dt) offset into the balance that never goes away.
  const bool first = cycle_ == 0;
  const bool with_contact = !contacts.empty();
  parallel_for_chunks(n, [&](Index b, Index end, Index chunk) {
    NodalEnergySums e;
    for (Index i = b; i < end; ++i) {
      const Real m = nodes.mass[i];
      const std::uint8_t kind = node_kind_[i];
      if (m <= 0.0 || kind == kDictated) continue;  // tied slaves: book_dictated_nodes
      const Real al = alpha_[i];
      for (int c = 0; c < 3; ++c) {
        const Real vold = nodes.v[c][i];
        const bool fixed = fixed_[c][i] != 0;
        Real vnew;
        if (fixed) {
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
        const Real fk = with_contact ? nodes.f_contact[c][i] : 0.0;
        const Real fd = fixed ? 0.0 : -al * m * vbar;
        const Real vk = first ? vold : vbar;
        e.kinetic += 0.5 * m * vk * vk;
        e.stress.add(-fi, dprev, dnext);
        e.external.add(fe, dprev, dnext);
        if (with_contact) e.contact.add(fk, dprev, dnext);
        e.damping.add(-fd, dprev, dnext);
        if (fixed) {
          e.support.add(m * (vnew - vold) / dt_avg - fi - fe - fk, dprev, dnext);
        } else if (kind != kFree) {
          // The node's acceleration is the constraint's or the tie's, not the loads' over its own
          // mass: the difference is the force the rigid body or the tie applies.
          const Real fc = m * (vnew - vold) / dt_avg - fi - fe - fk - fd;
          (kind == kRigid ? e.constraint : e.contact).add(fc, dprev, dnext);
        }
      }
      if (nodes.has_rotation[i] && nodes.rot_inertia[i] > 0.0) {
        const Real inertia = nodes.rot_inertia[i];
        const Real h = 0.5 * al * dt_avg;
        for (int c = 0; c < 3; ++c) {
          const Real wold = nodes.omega[c][i];
          const Real mi = nodes.m_int[c][i];
          const Real me = nodes.m_ext[c][i];
          const Real mk = with_contact ? nodes.m_contact[c][i] : 0.0;
          const bool fixed = fixed_rot_[c][i] != 0;
          const Real wnew = fixed ? 0.0 : ((1.0 - h) * wold + dt_avg * nodes.alpha[c][i]) / (1.0 + h);
          nodes.omega[c][i] = wnew;
          const Real wbar = 0.5 * (wold + wnew);
          const Real dprev = 0.5 * dt_old * wold;
          const Real dnext = 0.5 * dt_new * wnew;
          const Real wk = first ? wold : wbar;
          e.kinetic += 0.5 * inertia * wk * wk;
          e.stress.add(-mi, dprev, dnext);
          e.external.add(me, dprev, dnext);
          e.contact.add(mk, dprev, dnext);
          e.damping.add(al * inertia * wbar, dprev, dnext);
          if (kind != kFree && !fixed) {
            const Real mc = inertia * (wnew - wold) / dt_avg - mi - me - mk + al * inertia * wbar;
            (kind == kRigid ? e.constraint : e.contact).add(mc, dprev, dnext);
          }
        }
      }
    }
    chunk_e_[static_cast<std::size_t>(chunk)] = e;
  });
  NodalEnergySums total;
  for (const auto& e : chunk_e_) total += e;
  if (!dictated_nodes_.empty()) {
    contacts.follow_velocities(nodes);
    book_dictated_nodes(plan);
    total += dictated_sums_;
  }
  // Exchange point 3 (exchange.hpp): the energy sums over all processes.
  Real friction = contacts.friction_work();
  exchange_->sum_energies(total, friction);
  ledger_.book(total, first);
  ledger_.set_friction(friction);
}

void Simulation::book_dictated_nodes(const StepPlan& plan) {
  // Tied slaves took their masters' velocities: book their kinetic energy and the work of the tie
  // force m (v^{n+1/2} - v^{n-1/2}) / dt - f (damping included: they move as their masters do).
  NodalEnergySums e;
  const bool first = cycle_ == 0;
  for (std::size_t k = 0; k < dictated_nodes_.size(); ++k) {
    const Index i = dictated_nodes_[k];
    // One dof of mass (or rotary inertia) m: velocity before and after, internal and external load.
    const auto book = [&](Real m, Real vold, Real vnew, Real fi, Real fe) {
      const Real vbar = 0.5 * (vold + vnew);
      const Real dprev = 0.5 * dt_ * vold;
      const Real dnext = 0.5 * plan.dt_next * vnew;
      const Real vk = first ? vold : vbar;
      e.kinetic += 0.5 * m * vk * vk;
      e.stress.add(-fi, dprev, dnext);
      e.external.add(fe, dprev, dnext);
      e.contact.add(m * (vnew - vold) / plan.dt_avg - fi - fe, dprev, dnext);
    };
    for (int c = 0; c < 3; ++c)
      book(nodes.mass[i], dictated_v_old_[k][c], nodes.v[c][i], nodes.f_int[c][i], nodes.f_ext[c][i]);
    if (nodes.has_rotation[i] && nodes.rot_inertia[i] > 0.0)
      for (int c = 0; c < 3; ++c)
        book(nodes.rot_inertia[i], dictated_w_old_[k][c], nodes.omega[c][i], nodes.m_int[c][i], nodes.m_ext[c][i]);
  }
  dictated_sums_ = e;
}

void Simulation::update_positions(const StepPlan& plan) {
  const Index n = static_cast<Index>(nodes.size());
  const Real dt_new = plan.dt_next;
  parallel_for(n, [&](Index i) {
    nodes.x.x[i] += dt_new * nodes.v.x[i];
    nodes.x.y[i] += dt_new * nodes.v.y[i];
    nodes.x.z[i] += dt_new * nodes.v.z[i];
  });
  t_ = plan.t_next;
  dt_ = dt_new;
  ++cycle_;
  // The constraints reset the half-step velocities of their nodes; the kinetic energy that changes
  // is work the constraint does (with constant steps this closes the balance up to a bounded
  // O(dt^2) term, as for unconstrained nodes).
  if (!constraints.empty()) {
    const Real k_before = constrained_kinetic_energy();
    for (auto& c : constraints) c->after_positions(effective_mass(), nodes, t_);
    ledger_.add_constraint_work(constrained_kinetic_energy() - k_before);
  }
  if (!dictated_nodes_.empty()) {
    // A rigid master's reset moved its nodes: the slaves follow again (the change of their
    // kinetic energy is work of the tie).
    if (!constraints.empty()) {
      Real k_before = 0.0, k_after = 0.0;
      for (Index i : dictated_nodes_) k_before += 0.5 * nodes.mass[i] * nodes.v.get(i).squaredNorm();
      contacts.follow_velocities(nodes);
      for (Index i : dictated_nodes_) k_after += 0.5 * nodes.mass[i] * nodes.v.get(i).squaredNorm();
      ledger_.add_contact_work(k_after - k_before);
    }
    contacts.follow_positions(nodes);
  }
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

// ---- Stability checks -----------------------------------------------------------------------

Real Simulation::energy_error_fraction() const {
  const Real peak = std::max(peak_energy_, std::numeric_limits<Real>::min());
  return std::abs(ledger_.report().balance_error()) / peak;
}

std::string Simulation::describe_node(Index i) const {
  std::string s = "node " + std::to_string(nodes.ids[i]);
  for (const auto& b : blocks) {
    const auto conn = b->connectivity();
    const auto npe = static_cast<std::size_t>(b->nodes_per_element());
    for (std::size_t k = 0; k < conn.size(); ++k)
      if (conn[k] == i) {
        return s + " (" + b->kind() + " element " + std::to_string(b->element_id(static_cast<Index>(k / npe))) +
               " of part " + std::to_string(b->part_id()) + ")";
      }
  }
  return s;
}

std::string Simulation::locate_non_finite() const {
  // The rare path: the first node whose state is not finite.
  const Index n = static_cast<Index>(nodes.size());
  for (Index i = 0; i < n; ++i)
    for (const Vec3Field* f : {&nodes.x, &nodes.v, &nodes.a, &nodes.f_int, &nodes.f_ext, &nodes.f_contact})
      if (!f->get(i).allFinite()) {
        const char* what = f == &nodes.x ? "position" : f == &nodes.v ? "velocity" : f == &nodes.a ? "acceleration"
                           : f == &nodes.f_int ? "internal force" : f == &nodes.f_ext ? "external force"
                                                                                        : "contact force";
        return std::string("a non-finite ") + what + " at " + describe_node(i);
      }
  return "a non-finite energy (no nodal field is non-finite)";
}

void Simulation::check_stability() {
  // A NaN or an infinity anywhere in the nodal state reaches the energy sums of this cycle.
  const EnergyReport& e = ledger_.report();
  const Real bal = e.balance_error();
  if (!std::isfinite(bal) || !std::isfinite(e.kinetic))
    throw InstabilityError(locate_non_finite() + " at t = " + std::to_string(t_) + ", cycle " +
                               std::to_string(cycle_),
                           t_, cycle_);
  peak_energy_ = std::max({peak_energy_, std::abs(e.external) + std::abs(e.support) + std::abs(e.constraint) + e.kinetic0,
                           e.kinetic, std::abs(e.internal) + e.hourglass + e.bulk_viscosity + e.damping +
                                          std::abs(e.contact) + e.friction});
  if (cycle_ < kEnergyCheckStart) return;
  part_energy_.check(t_, cycle_, peak_energy_);  // hourglass warnings; negative internal energy stops
  const Real err = energy_error_fraction();
  if (controls.energy_error_warning > 0.0 && err > controls.energy_error_warning && !energy_warning_)
    energy_warning_ = EnergyWarning{t_, cycle_, err};
  if (controls.energy_error_limit > 0.0 && err > controls.energy_error_limit) {
    // Where it started: the node with the largest kinetic energy.
    Index worst = 0;
    Real kmax = -1.0;
    for (Index i = 0; i < static_cast<Index>(nodes.size()); ++i) {
      const Real k = nodes.mass[i] * nodes.v.get(i).squaredNorm();
      if (k > kmax) {
        kmax = k;
        worst = i;
      }
    }
    throw InstabilityError("energy balance error " + std::to_string(100.0 * err) + "% exceeds the limit of " +
                               std::to_string(100.0 * controls.energy_error_limit) + "% at t = " +
                               std::to_string(t_) + ", cycle " + std::to_string(cycle_) +
                               "; the fastest node is " + describe_node(worst),
                           t_, cycle_);
  }
}

// ---- Output ----------------------------------------------------------------------------------

void Simulation::collect_history(std::vector<Real>& values) const {
  std::size_t k = 0;
  auto put3 = [&](const Vec3& v) {
    values[k++] = v[0];
    values[k++] = v[1];
    values[k++] = v[2];
  };
  for (std::size_t ci = 0; ci < contacts.size(); ++ci) {
    // An interface before its birth or after its death carries no force.
    const bool on = contacts.active(ci);
    put3(on ? contacts[ci].slave_force() : Vec3::Zero());
    put3(on ? contacts[ci].master_force() : Vec3::Zero());
    const auto extra = std::span<Real>(values).subspan(k, contact_outputs_[ci]);
    if (on) contacts[ci].write_output_values(extra);
    else std::fill(extra.begin(), extra.end(), 0.0);
    k += contact_outputs_[ci];
  }
  for (const auto& g : supports) put3(g.reaction);
  for (std::size_t c = 0; c < constraints.size(); ++c) {
    constraints[c]->write_output_values(std::span<Real>(values).subspan(k, constraint_outputs_[c]));
    k += constraint_outputs_[c];
  }
  for (Index i : history_nodes) put3(nodes.displacement(i));
  for (Real v : ledger_.report().values()) values[k++] = v;
}

void Simulation::record_outputs(bool force) {
  if (sinks_ == nullptr) return;
  const auto& sinks = *sinks_;
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
