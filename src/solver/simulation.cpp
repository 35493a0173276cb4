// Simulation: initialisation job by job, the cycle as a flat list of phases, the step plan and
// the run loop. The phases live beside it: simulation_forces.cpp (forces and dt votes),
// simulation_constraints.cpp (the constraint phase), central_difference.cpp (the update),
// energy_audit.cpp, output_recorder.cpp, stability_monitor.cpp, node_roles.cpp.
#include "slideline/solver/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "slideline/core/error.hpp"
#include "slideline/core/parallel.hpp"
#include "slideline/solver/energy_audit.hpp"
#include "slideline/solver/step_control.hpp"

namespace slideline {

Simulation::Simulation(SimulationSetup setup, std::unique_ptr<Exchange> exchange)
    : nodes_(std::move(setup.nodes)),
      blocks_(std::move(setup.blocks)),
      constraints_(std::move(setup.constraints)),
      contacts_(std::move(setup.contacts)),
      body_loads_(std::move(setup.body_loads)),
      nodal_loads_(std::move(setup.nodal_loads)),
      supports_(std::move(setup.supports)),
      damping_(std::move(setup.damping)),
      history_nodes_(std::move(setup.history_nodes)),
      sets_(std::move(setup.sets)),
      controls_(std::move(setup.controls)),
      exchange_(exchange ? std::move(exchange) : std::make_unique<SingleProcessExchange>()) {}

Index Simulation::element_count() const {
  Index n = 0;
  for (const auto& b : blocks_) n += b->element_count();
  return n;
}

MeshDescription Simulation::mesh_description() const {
  MeshDescription m;
  m.node_ids = nodes_.ids;
  const std::size_t n = nodes_.size();
  m.x0.resize(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    m.x0[3 * i] = nodes_.x0.x[i];
    m.x0[3 * i + 1] = nodes_.x0.y[i];
    m.x0[3 * i + 2] = nodes_.x0.z[i];
  }
  m.cells = cells_by_topology(mesh_blocks(blocks_));
  m.cell_info = output_cell_info(blocks_, m.cells);
  return m;
}

// ---- Initialisation --------------------------------------------------------------------------

void Simulation::initialize() {
  check_controls();
  const Index n = static_cast<Index>(nodes_.size());
  const auto block_mass = lump_masses();
  check_nodal_moments();
  // Who dictates each node's motion: rigid bodies first (their node lists are known before they
  // initialise), then contact ties (known after the interfaces initialise, initialize_contacts).
  roles_.assign_rigid(n, constraints_);
  if (rescaling_.active()) refuse_unsupported_rescaling();
  resolve_body_loads(block_mass);
  if (rescaling_.active() && !body_loads_.empty()) rescaling_.attach_body_loads(body_loads_, blocks_, corners_.force_slots);
  roles_.assign_supports(n, supports_, t_);
  alpha_.assign(n, 0.0);
  has_damping_curves_ = std::any_of(damping_.begin(), damping_.end(), [](const MassDamping& d) { return d.has_curve; });
  update_damping_coefficients();
  t_ = 0.0;
  dt_ = 0.0;
  dt_initial_ = 0.0;  // set by the first assemble_forces()
  cycle_ = 0;
  initialize_contacts();
  block_step_.assign(blocks_.size(), std::numeric_limits<Real>::max());
  if (has_contact() && controls_.contact_step_with_elements) element_steps_.build(blocks_, n);
  recorder_.build_channels(output_sources());
  chunk_e_.assign(static_cast<std::size_t>(chunk_count(n)), NodalEnergySums{});
  ledger_.reset();
  part_energy_.reset(blocks_);
  block_energy_.assign(blocks_.size(), BlockEnergy{});
  votes_ = assemble_forces();
  const Real dt_stable = votes_.stable();
  if (!(dt_stable > 0.0) || !std::isfinite(dt_stable))
    throw InputError("simulation: no stable time step (is there at least one element?)");
  last_vote_ = dt_stable;
  initialized_ = true;
}

void Simulation::check_controls() const {
  if (controls_.end_time <= 0.0 && controls_.max_cycles <= 0)
    throw InputError("simulation: end time must be positive (got " + std::to_string(controls_.end_time) + ")");
  if (!(controls_.dt_scale > 0.0 && controls_.dt_scale <= 1.0))
    throw InputError("simulation: time-step scale factor must be in (0, 1] (got " +
                     std::to_string(controls_.dt_scale) + ")");
}

std::vector<std::vector<Real>> Simulation::lump_masses() {
  const Index n = static_cast<Index>(nodes_.size());
  std::vector<std::pair<Index, Index>> force_pairs, moment_pairs;
  Index fbase = 0, mbase = 0;
  std::vector<std::vector<Real>> block_mass;  // mass each block lumps to each node
  std::vector<Real> before;
  for (auto& b : blocks_) {
    b->set_slot_base(fbase, mbase);
    before = nodes_.mass;
    b->initialize(nodes_);
    if (controls_.dt2ms != 0.0) scale_block_mass(*b, before);  // MS1ST = 0: the physical mass only
    block_mass.emplace_back(nodes_.mass);
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
  Index largest = 0;
  for (const auto& b : blocks_) largest = std::max<Index>(largest, static_cast<Index>(b->connectivity().size()));
  corner_power_chunks_.assign(static_cast<std::size_t>(chunk_count(largest)), 0.0);
  corners_.force.resize(fbase);
  corners_.moment.resize(mbase);
  corners_.force_slots.build(n, force_pairs);
  if (mbase > 0) corners_.moment_slots.build(n, moment_pairs);
  has_rotations_ = std::any_of(nodes_.has_rotation.begin(), nodes_.has_rotation.end(),
                               [](std::uint8_t r) { return r != 0; });
  if (controls_.dt2ms != 0.0 && controls_.mass_scaling_every_cycle)
    rescaling_.initialize(blocks_, nodes_, corners_.force_slots, fbase, corners_.moment_slots, mbase, controls_.dt2ms,
                          added_mass_);
  check_added_mass();
  return block_mass;
}

void Simulation::scale_block_mass(ElementBlock& block, const std::vector<Real>& before) {
  Real lumped = 0.0;  // the block's physical mass, in node order (thread-count independent)
  for (std::size_t i = 0; i < before.size(); ++i) lumped += nodes_.mass[i] - before[i];
  if (controls_.mass_scaling_every_cycle) {  // MS1ST = 0: MassRescaling sets the added mass
    added_mass_.push_back(PartAddedMass{block.part_id(), lumped, 0.0, 0, block.element_count(), 0.0});
    return;
  }
  added_mass_.push_back(slideline::scale_block_mass(block, nodes_, lumped, controls_.dt2ms));
}

void Simulation::refuse_unsupported_rescaling() const {
  // What takes the nodal masses once, at the start, would miss the mass added later.
  const char* what = "mass scaling re-evaluated every cycle (DT2MS with MS1ST = 0 of *CONTROL_TIMESTEP)";
  const auto rigid = roles_.rigid();
  for (Index i : rescaling_.scaled_nodes())
    if (rigid[static_cast<std::size_t>(i)])
      throw NotImplementedError(std::string(what) + ": node " + std::to_string(nodes_.ids[static_cast<std::size_t>(i)]) +
                                " belongs to a rigid body and to a deformable element; the body takes its mass "
                                "properties once, at the start (MS1ST = 1 scales the masses once)");
}

void Simulation::check_added_mass_in_run() const {
  Real mass = 0.0, added = 0.0;
  for (const auto& p : added_mass_) {
    mass += p.mass;
    added += p.added;
  }
  if (mass > 0.0 && 100.0 * added / mass > controls_.added_mass_limit_percent)
    throw InstabilityError("mass scaling (DT2MS with MS1ST = 0 of *CONTROL_TIMESTEP) has added " + std::to_string(added) +
                               ", " + std::to_string(100.0 * added / mass) + "% of the model's mass " +
                               std::to_string(mass) + ", more than ENDMAS of *CONTROL_TERMINATION allows (" +
                               std::to_string(controls_.added_mass_limit_percent) + "%) at t = " + std::to_string(t_) +
                               ", cycle " + std::to_string(cycle_),
                           t_, cycle_);
}

void Simulation::check_added_mass() const {
  Real mass = 0.0, added = 0.0;
  for (const auto& p : added_mass_) {
    mass += p.mass;
    added += p.added;
  }
  if (mass > 0.0 && 100.0 * added / mass > controls_.added_mass_limit_percent)
    throw InputError("simulation: mass scaling (DT2MS of *CONTROL_TIMESTEP) adds " + std::to_string(added) + ", " +
                     std::to_string(100.0 * added / mass) + "% of the model's mass " + std::to_string(mass) +
                     ", more than ENDMAS of *CONTROL_TERMINATION allows (" +
                     std::to_string(controls_.added_mass_limit_percent) + "%)");
}

void Simulation::check_nodal_moments() const {
  // A moment on a node without rotational degrees of freedom would be lost: refuse it.
  for (const auto& nl : nodal_loads_)
    if (nl.moment)
      for (Index i : nl.nodes)
        if (!nodes_.has_rotation[i])
          throw InputError(nl.source + ": a moment (DOF 5-7) on node " + std::to_string(nodes_.ids[i]) +
                           ", which has no rotational degrees of freedom (only shell nodes do)");
}

void Simulation::resolve_body_loads(const std::vector<std::vector<Real>>& block_mass) {
  // Body loads act on the mass of the loaded parts only.
  const Index n = static_cast<Index>(nodes_.size());
  for (auto& bl : body_loads_) {
    std::vector<Real> m(n, 0.0);
    for (std::size_t k = 0; k < blocks_.size(); ++k)
      if (bl.parts.empty() ||
          std::find(bl.parts.begin(), bl.parts.end(), blocks_[k]->part_id()) != bl.parts.end())
        for (Index i = 0; i < n; ++i) m[i] += block_mass[k][i];
    bl.nodes.clear();
    bl.mass.clear();
    for (Index i = 0; i < n; ++i)
      if (m[i] > 0.0) {
        bl.nodes.push_back(i);
        bl.mass.push_back(m[i]);
      }
  }
}

void Simulation::refuse_timed_ties_on_rigid_bodies() const {
  // A rigid body's mass properties take the slaves tied to its nodes once, at the start
  // (initialize_contacts): a tie onto a rigid body that is born or dies mid-run would change them.
  // Ties whose masters are all deformable, and rigid walls (no body, no mass), are not concerned.
  const auto rigid = roles_.rigid();
  for (std::size_t k = 0; k < contacts_.size(); ++k) {
    if (!contacts_.window(k).timed() || !contacts_[k].condenses()) continue;
    for (Index i : contacts_[k].tie_master_nodes())
      if (rigid[static_cast<std::size_t>(i)])
        throw NotImplementedError("contact " + contacts_[k].name() +
                                  ": a tied interface with a birth or death time (BT, DT) whose master surface is on "
                                  "a rigid body (node " + std::to_string(nodes_.ids[static_cast<std::size_t>(i)]) +
                                  ") is not supported: the body takes the mass of the slaves tied to it once, at the "
                                  "start");
  }
}

void Simulation::initialize_contacts() {
  // Contact interfaces, then the nodes their ties dictate, then the rigid bodies (which need the
  // effective mass: a slave tied to a rigid master moves with the body).
  const Index n = static_cast<Index>(nodes_.size());
  contacts_.initialize(ContactContext{nodes_, blocks_, &sets_, roles_.rigid(), diagnostics_});
  contacts_.resolve_initial_penetrations(nodes_);
  refuse_timed_ties_on_rigid_bodies();
  classify_contact_nodes();
  if (has_contact()) {
    f_total_.resize(n);
    m_total_.resize(n);
  }
  mass_eff_ = nodes_.mass;
  rot_inertia_eff_ = nodes_.rot_inertia;
  if (contacts_.condenses()) {
    // The condensed mass of constant ties, for the rigid bodies' mass properties.
    f_total_.fill(0.0);
    m_total_.fill(0.0);
    contacts_.condense(nodes_, CondenseView{mass_eff_, f_total_, rot_inertia_eff_, m_total_});
  }
  for (auto& c : constraints_) c->initialize(nodes_, effective_mass());
}

void Simulation::classify_contact_nodes() {
  roles_.classify_contacts(contacts_, nodes_);
  dictated_v_old_.assign(roles_.dictated_nodes().size(), Vec3::Zero());
  dictated_w_old_.assign(roles_.dictated_nodes().size(), Vec3::Zero());
}

OutputSources Simulation::output_sources() const {
  return OutputSources{nodes_,         blocks_,          contacts_,
                       supports_,      constraints_,     history_nodes_,
                       ledger_.report(), rescaling_.active() ? std::span<const PartAddedMass>(added_mass_)
                                                             : std::span<const PartAddedMass>(),
                       &part_energy_};
}

void Simulation::update_damping_coefficients() {
  if (!has_damping_curves_ && cycle_ > 0) return;
  std::fill(alpha_.begin(), alpha_.end(), 0.0);
  for (const auto& d : damping_) {
    const Real a = d.value(t_);
    if (d.nodes.empty())
      for (Real& v : alpha_) v += a;
    else
      for (Index i : d.nodes) alpha_[i] += a;
  }
}

// ---- The step --------------------------------------------------------------------------------

StepPlan Simulation::plan_step() const {
  StepPlan p;
  const Real end = controls_.end_time;
  // Time tolerance relative to the run's own time scale (an absolute one would swallow whole
  // steps of a nanosecond-scale run), far above the round-off of t.
  const Real tol_t =
      1e-12 * (end > 0.0 ? end : std::max({t_, controls_.history_interval, controls_.state_interval}));
  p.at_end = (end > 0.0 && t_ >= end - tol_t) ||
             (controls_.max_cycles > 0 && cycle_ >= controls_.max_cycles);

  // The scaled stable step, divided so as to land exactly on the next output time.
  Real dt_new = controls_.dt_scale * votes_.stable();
  if (controls_.dt_max > 0.0) dt_new = std::min(dt_new, controls_.dt_max);
  if (controls_.has_dt_max_curve) dt_new = std::min(dt_new, controls_.dt_max_curve(t_));
  Real target = end > 0.0 ? end : std::numeric_limits<Real>::infinity();
  if (controls_.history_interval > 0.0)
    target = std::min(target, next_output_time(controls_.history_interval, t_));
  if (controls_.state_interval > 0.0)
    target = std::min(target, next_output_time(controls_.state_interval, t_));
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
  // The forces at t^n and the step they vote for (votes_) came from the last cycle's
  // assemble_forces(), or initialize()'s for t = 0.
  const StepPlan plan = plan_step();
  monitor_.check_step(plan, votes_, t_, cycle_, controls_, contacts_);
  // ERODE: once the first step is known, solids below TSMIN = DTMIN x it are deleted (the
  // element's own step is compared before the scale factor).
  if (cycle_ == 0 && controls_.erode_below_dt_min)
    for (auto& b : blocks_)
      if (ElementErosion* er = b->erosion()) er->set_step_floor(controls_.dt_min_fraction * plan.dt_next / controls_.dt_scale);
  form_accelerations(nodes_, has_contact(), has_rotations_);
  apply_constraints(plan);
  update_damping_coefficients();
  const VelocityStep vs = velocity_step(plan);
  remember_dictated_velocities();
  NodalEnergySums sums = update_velocities(nodes_, roles_, alpha_, vs, chunk_e_);
  if (!roles_.dictated_nodes().empty()) sums += follow_ties(vs);
  book_energies(sums);
  monitor_.check_energy(ledger_.report(), part_energy_, MonitoredModel{nodes_, blocks_, contacts_}, t_, cycle_,
                        controls_);
  const Real output_tol = 1e-9 * std::max(votes_.stable(), 1e-300);
  recorder_.record(output_sources(), t_, controls_.history_interval, controls_.state_interval, output_tol,
                   plan.at_end);
  if (plan.at_end) {
    finished_ = true;
    return false;
  }
  advance(plan);
  votes_ = assemble_forces();  // the forces at t^{n+1}: the next cycle's loads and stable step
  // Once every element has eroded (and no interface votes) nothing bounds the step: the last
  // vote is kept, so the nodes left flying (with their loads and damping) are integrated as they
  // were, not in one step to the next output time (docs/solver.md, "Failure and erosion").
  // (A vote of the largest finite number, or infinity, is no vote: exchange.hpp.)
  if (votes_.stable() < std::numeric_limits<Real>::max()) last_vote_ = votes_.stable();
  else votes_.elements = last_vote_;
  if (rescaling_.active()) check_added_mass_in_run();  // ENDMAS, as the masses change
  return true;
}

VelocityStep Simulation::velocity_step(const StepPlan& plan) const {
  return VelocityStep{dt_, plan.dt_avg, plan.dt_next, cycle_ == 0, has_contact()};
}

void Simulation::remember_dictated_velocities() {
  const auto dictated = roles_.dictated_nodes();
  for (std::size_t k = 0; k < dictated.size(); ++k) {
    dictated_v_old_[k] = nodes_.v.get(dictated[k]);
    dictated_w_old_[k] = nodes_.omega.get(dictated[k]);
  }
}

NodalEnergySums Simulation::follow_ties(const VelocityStep& vs) {
  contacts_.follow_velocities(nodes_);
  return dictated_node_sums(nodes_, roles_.dictated_nodes(), dictated_v_old_, dictated_w_old_, vs);
}

void Simulation::book_energies(NodalEnergySums sums) {
  // Exchange point 3 (exchange.hpp): the energy sums over all processes.
  Real friction = contacts_.friction_work();
  exchange_->sum_energies(sums, friction);
  ledger_.book(sums, cycle_ == 0);
  ledger_.set_friction(friction);
}

void Simulation::advance(const StepPlan& plan) {
  update_positions(nodes_, plan.dt_next);
  t_ = plan.t_next;
  dt_ = plan.dt_next;
  ++cycle_;
  // The constraints reset the half-step velocities of their nodes; the kinetic energy that changes
  // is work the constraint does (with constant steps this closes the balance up to a bounded
  // O(dt^2) term, as for unconstrained nodes).
  if (!constraints_.empty()) {
    const Real k_before = kinetic_energy(nodes_, roles_.constrained_nodes());
    for (auto& c : constraints_) c->after_positions(effective_mass(), nodes_, t_);
    // Exchange point 3 (exchange.hpp): the work of the resets over all processes.
    ledger_.add_constraint_work(exchange_->sum_reset_work(kinetic_energy(nodes_, roles_.constrained_nodes()) - k_before));
  }
  const auto dictated = roles_.dictated_nodes();
  if (!dictated.empty()) {
    // A rigid master's reset moved its nodes: the slaves follow again (the change of their
    // kinetic energy is work of the tie).
    if (!constraints_.empty()) {
      const Real k_before = translational_kinetic_energy(nodes_, dictated);
      contacts_.follow_velocities(nodes_);
      ledger_.add_contact_work(exchange_->sum_reset_work(translational_kinetic_energy(nodes_, dictated) - k_before));
    }
    contacts_.follow_positions(nodes_);
  }
}

void Simulation::run(const std::vector<OutputSink*>& sinks,
                     const std::function<void(const Simulation&)>& progress, long progress_every) {
  if (!initialized_) initialize();
  recorder_.begin(sinks, mesh_description(), blocks_);
  try {
    while (step()) {
      if (progress && progress_every > 0 && cycle_ % progress_every == 0) progress(*this);
    }
  } catch (...) {
    recorder_.end();
    throw;
  }
  recorder_.end();
}

}  // namespace slideline
