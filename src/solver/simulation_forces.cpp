// Simulation: the force assembly at t^n. Element, external and contact forces into their own
// buffers (f_int, f_ext, f_contact and the moments), and the stable step they vote for, returned
// as a value (the one place the step is decided; plan_step() scales it).
#include <chrono>
#include <limits>

#include "slideline/core/error.hpp"
#include "slideline/core/parallel.hpp"
#include "slideline/solver/simulation.hpp"

namespace slideline {

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

StepVotes Simulation::assemble_forces() {
  StepVotes local;
  local.elements = compute_internal_forces(local.block);
  if (rescaling_.active()) {
    // MS1ST = 0: the factors from the steps just computed; the masses change at v^{n+1/2}, and
    // that kinetic energy is booked (not at the start: the first kinetic energy has the new mass).
    const MassRescaling::Result r =
        rescaling_.rescale(blocks_, nodes_, corners_.force_slots, false, added_mass_, block_step_);
    if (r.controlling) {
      local.elements = r.step;
      local.block = r.controlling;
    }
    if (initialized_) ledger_.add_mass_scaling_work(r.kinetic_change);
  }
  if (dt_initial_ == 0.0 && has_contact()) {
    // The initial step the SOFT = 1 springs are sized by (over all processes, as the step is;
    // the one exchange call more, once, only in a model with contact).
    StepVotes e;
    e.elements = e.contact = local.elements;
    dt_initial_ = controls_.dt_scale * exchange_->min_dt(e).elements;
  }
  compute_external_forces();
  local.contact = apply_contact_forces();
  // Exchange points 1 and 2 (exchange.hpp): the forces of shared nodes, the step over all processes.
  exchange_->sum_forces(nodes_);
  return exchange_->min_dt(local);
}

Real Simulation::compute_internal_forces(const ElementBlock*& controlling) {
  const auto t0 = std::chrono::steady_clock::now();
  Real dtc = std::numeric_limits<Real>::max();
  controlling = nullptr;
  try {
    Real dt_other = std::numeric_limits<Real>::max();  // steps of blocks that do not bound it
    const ElementBlock* controlling_other = nullptr;
    for (std::size_t k = 0; k < blocks_.size(); ++k) {
      const auto& b = blocks_[k];
      block_energy_[k] = BlockEnergy{};
      if (ElementErosion* er = b->erosion()) er->set_time(t_);
      // The power of the block's last forces at this step's rates, before it overwrites them: the
      // block's work over the step is the trapezoid of the two powers, as the ledger's nodal
      // work is (the parts' internal energies then sum to the ledger's).
      const Real previous = corners_.power(b->connectivity(), b->force_slot_base(), b->moment_slot_base(),
                                           b->has_moments(), nodes_, corner_power_chunks_);
      const Real d = b->compute_forces(nodes_, dt_, corners_, block_energy_[k]);
      block_energy_[k].element_power = 0.5 * (previous + block_energy_[k].element_power);
      block_step_[k] = d;
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
  } catch (const InstabilityError& e) {
    throw InstabilityError(std::string(e.what()) + " at t = " + std::to_string(t_) +
                               ", cycle " + std::to_string(cycle_),
                           t_, cycle_);
  }
  corners_.gather(nodes_.f_int, nodes_.m_int);
  element_seconds_ += seconds_since(t0);
  // Exchange point 3 (exchange.hpp): the element powers at t^n over all processes, integrated
  // over the step that ends at t^n, per part and in total.
  exchange_->sum_block_energies(block_energy_);
  BlockEnergy be;
  for (std::size_t k = 0; k < blocks_.size(); ++k) {
    be += block_energy_[k];
    part_energy_.add(k, block_energy_[k], cycle_ == 0 ? 0.0 : dt_);
  }
  ledger_.add_element_powers(be.hourglass_power, be.viscous_power, be.damping_power,
                             cycle_ == 0 ? 0.0 : dt_);
  if (be.eroded_elements > 0) ledger_.add_eroded(be.eroded_internal, be.eroded_hourglass);
  return dtc;
}

void Simulation::compute_external_forces() {
  // In parallel: serial node loops here would cap the two-thread speed-up.
  const Index n = static_cast<Index>(nodes_.size());
  const bool rotations = has_rotations_;
  parallel_for(n, [&](Index i) {
    nodes_.f_ext.x[i] = 0.0;
    nodes_.f_ext.y[i] = 0.0;
    nodes_.f_ext.z[i] = 0.0;
    if (rotations) {
      nodes_.m_ext.x[i] = 0.0;
      nodes_.m_ext.y[i] = 0.0;
      nodes_.m_ext.z[i] = 0.0;
    }
  });
  for (const auto& bl : body_loads_) {
    const Real acc = bl.scale * bl.curve(t_);
    auto& f = nodes_.f_ext[static_cast<int>(bl.axis)];
    // bl.nodes is unique, so the iterations write distinct entries.
    parallel_for(static_cast<Index>(bl.nodes.size()),
                 [&](Index k) { f[bl.nodes[k]] += bl.mass[k] * acc; });
  }
  // Serial and in card order: a node may appear in several loads (same sum for any thread count).
  for (const auto& nl : nodal_loads_) {
    const Real v = nl.scale * nl.curve(t_);
    auto& f = nl.moment ? nodes_.m_ext[static_cast<int>(nl.axis)] : nodes_.f_ext[static_cast<int>(nl.axis)];
    for (Index i : nl.nodes) f[i] += v;
  }
}

Real Simulation::apply_contact_forces() {
  if (!has_contact()) return std::numeric_limits<Real>::max();
  const auto t0 = std::chrono::steady_clock::now();
  // Birth and death (BT, DT): the interfaces that act in the cycle from t_ (contact_manager.hpp).
  if (contacts_.update_activity(t_)) classify_contact_nodes();
  nodes_.f_contact.fill(0.0);
  if (has_rotations_) nodes_.m_contact.fill(0.0);
  // The coming step is not known yet (the interfaces vote for it here).
  StepTimes times{t_, dt_, 0.0, 0.0, cycle_, dt_initial_};
  if (element_steps_.built()) {
    // Each spring's vote counts the elements on its nodes (contact/element_steps_view.hpp).
    element_steps_.update(block_step_);
    times.element_steps = element_steps_.view();
  }
  const Real dtc = contacts_.apply_forces(nodes_, times, ContactForceView{nodes_.f_contact, nodes_.m_contact});
  contact_seconds_ += seconds_since(t0);
  return dtc;
}

}  // namespace slideline
