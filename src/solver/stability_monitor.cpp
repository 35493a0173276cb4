#include "slideline/solver/stability_monitor.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "slideline/core/error.hpp"

namespace slideline {

namespace {

std::string describe_node(const MonitoredModel& m, Index i) {
  std::string s = "node " + std::to_string(m.nodes.ids[i]);
  // Through the declared topology: a rigid part may hold hexahedra and shells (no one node count).
  for (const auto& b : m.blocks) {
    const auto conn = b->connectivity();
    std::string found;
    b->topology().for_each_element([&](const TopologyRun& r, Index e, std::size_t offset) {
      if (!found.empty()) return;
      for (int k = 0; k < r.topology->nodes; ++k)
        if (conn[offset + static_cast<std::size_t>(k)] == i) {
          found = " (" + b->kind() + " element " + std::to_string(b->element_id(e)) + " of part " +
                  std::to_string(b->part_id()) + ")";
          return;
        }
    });
    if (!found.empty()) return s + found;
  }
  return s;
}

std::string locate_non_finite(const MonitoredModel& m) {
  // The rare path: the first node whose state is not finite.
  const NodalFields& nodes = m.nodes;
  const Index n = static_cast<Index>(nodes.size());
  for (Index i = 0; i < n; ++i)
    for (const Vec3Field* f : {&nodes.x, &nodes.v, &nodes.a, &nodes.f_int, &nodes.f_ext, &nodes.f_contact})
      if (!f->get(i).allFinite()) {
        const char* what = f == &nodes.x ? "position" : f == &nodes.v ? "velocity" : f == &nodes.a ? "acceleration"
                           : f == &nodes.f_int ? "internal force" : f == &nodes.f_ext ? "external force"
                                                                                        : "contact force";
        return std::string("a non-finite ") + what + " at " + describe_node(m, i);
      }
  return "a non-finite energy (no nodal field is non-finite)";
}

Index fastest_node(const NodalFields& nodes) {
  Index worst = 0;
  Real kmax = -1.0;
  for (Index i = 0; i < static_cast<Index>(nodes.size()); ++i) {
    const Real k = nodes.mass[i] * nodes.v.get(i).squaredNorm();
    if (k > kmax) {
      kmax = k;
      worst = i;
    }
  }
  return worst;
}

std::string at(Real t, long cycle) { return " at t = " + std::to_string(t) + ", cycle " + std::to_string(cycle); }

}  // namespace

std::string describe_step_controller(const StepVotes& votes, const ContactManager& contacts) {
  if (votes.contact_controls()) {
    std::size_t k = 0;
    for (std::size_t c = 1; c < contacts.size(); ++c)
      if (contacts.active(c) && (!contacts.active(k) || contacts[c].stable_dt() < contacts[k].stable_dt())) k = c;
    return contacts.size() > 0 ? "contact interface '" + contacts[k].name() + "'" : std::string("a contact interface");
  }
  const ElementBlock* b = votes.block;
  if (b == nullptr) return "no element";
  const Id e = b->smallest_step_element();
  return b->kind() + (e >= 0 ? " element " + std::to_string(e) : std::string(" elements")) + " of part " +
         std::to_string(b->part_id());
}

void StabilityMonitor::check_step(const StepPlan& plan, const StepVotes& votes, Real t, long cycle,
                                  const SimulationControls& controls, const ContactManager& contacts) {
  const auto set_by = [&] { return "; the step is set by " + describe_step_controller(votes, contacts); };
  if (!(plan.dt_next > 0.0) || !std::isfinite(plan.dt_next))
    throw InstabilityError("time step collapsed to " + std::to_string(plan.dt_next) + at(t, cycle) + set_by(), t,
                           cycle);
  if (cycle == 0) dt_first_ = plan.dt_next;
  // With ERODE the elements' own steps are judged (the solids below TSMIN have just been deleted
  // by the same floor, Simulation::step), not a step shortened to land on an output time.
  const bool below = controls.erode_below_dt_min
                         ? votes.stable() < controls.dt_min_fraction * dt_first_ / controls.dt_scale
                         : plan.dt_next < controls.dt_min_fraction * dt_first_;
  if (controls.dt_min_fraction > 0.0 && !plan.at_end && below && plan.t_next < controls.end_time)
    throw InstabilityError("time step " + std::to_string(plan.dt_next) + " fell below " +
                               std::to_string(controls.dt_min_fraction) + " x the first step (" +
                               std::to_string(dt_first_) + ")" + at(t, cycle) + set_by(),
                           t, cycle);
  if (!plan.at_end && !(plan.t_next > t))
    throw InstabilityError("time no longer advances at t = " + std::to_string(t) + " (step " +
                               std::to_string(plan.dt_next) + "), cycle " + std::to_string(cycle) + set_by(),
                           t, cycle);
}

Real StabilityMonitor::energy_error_fraction(const EnergyReport& e) const {
  const Real peak = std::max(peak_energy_, std::numeric_limits<Real>::min());
  return std::abs(e.balance_error()) / peak;
}

void StabilityMonitor::check_energy(const EnergyReport& e, PartEnergyMonitor& parts, const MonitoredModel& model,
                                    Real t, long cycle, const SimulationControls& controls) {
  // A NaN or an infinity anywhere in the nodal state reaches the energy sums of this cycle.
  const Real bal = e.balance_error();
  if (!std::isfinite(bal) || !std::isfinite(e.kinetic))
    throw InstabilityError(locate_non_finite(model) + at(t, cycle), t, cycle);
  peak_energy_ = std::max({peak_energy_, std::abs(e.external) + std::abs(e.support) + std::abs(e.constraint) + e.kinetic0 + std::abs(e.mass_scaling),
                           e.kinetic, std::abs(e.internal) + e.hourglass + e.bulk_viscosity + e.damping +
                                          std::abs(e.contact) + e.friction});
  if (cycle < kEnergyCheckStart) return;
  parts.check(t, cycle, peak_energy_);  // hourglass warnings; negative internal energy stops
  const Real err = energy_error_fraction(e);
  if (controls.energy_error_warning > 0.0 && err > controls.energy_error_warning && !energy_warning_)
    energy_warning_ = EnergyWarning{t, cycle, err};
  if (controls.energy_error_limit > 0.0 && err > controls.energy_error_limit)
    // Where it started: the node with the largest kinetic energy.
    throw InstabilityError("energy balance error " + std::to_string(100.0 * err) + "% exceeds the limit of " +
                               std::to_string(100.0 * controls.energy_error_limit) + "%" + at(t, cycle) +
                               "; the fastest node is " + describe_node(model, fastest_node(model.nodes)),
                           t, cycle);
  // Every ledger term is a nodal work, so energy that contact creates balances: it shows only as
  // contact forces that did more work on the bodies than they took from them (penalty springs
  // store, friction dissipates: contact + friction >= 0 for a contact that creates nothing).
  const Real created = -(e.contact + e.friction) / std::max(peak_energy_, std::numeric_limits<Real>::min());
  if (created > kContactEnergyWarning && !contact_warning_) contact_warning_ = EnergyWarning{t, cycle, created};
}

}  // namespace slideline
