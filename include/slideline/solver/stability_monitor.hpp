#pragma once
/// The stability monitor: stops a run whose step collapses or whose energy balance fails, with a
/// message that names where (the element or interface that sets the step, the node that went
/// non-finite or moves fastest).
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "slideline/contact/contact_manager.hpp"
#include "slideline/core/types.hpp"
#include "slideline/element/element_block.hpp"
#include "slideline/mesh/nodal_fields.hpp"
#include "slideline/solver/energy_ledger.hpp"
#include "slideline/solver/exchange.hpp"
#include "slideline/solver/part_energy_monitor.hpp"
#include "slideline/solver/simulation_controls.hpp"

namespace slideline {

/// What sets the step now, for messages: "hex8 element 12 of part 3" or "contact interface 'x'".
/// Built only when a message needs it.
std::string describe_step_controller(const StepVotes& votes, const ContactManager& contacts);

/// The model a message describes.
struct MonitoredModel {
  const NodalFields& nodes;
  const std::vector<std::unique_ptr<ElementBlock>>& blocks;
  const ContactManager& contacts;
};

class StabilityMonitor {
 public:
  /// Before a cycle from (t, cycle): the planned step must be finite and positive, not below
  /// controls.dt_min_fraction x the first step, and must advance the time. Throws InstabilityError.
  void check_step(const StepPlan& plan, const StepVotes& votes, Real t, long cycle, const SimulationControls& controls,
                  const ContactManager& contacts);
  /// After the velocity update at (t, cycle): finite energies, the hourglass and negative internal
  /// energy checks of `parts`, the balance error within controls' warning and limit.
  void check_energy(const EnergyReport& e, PartEnergyMonitor& parts, const MonitoredModel& model, Real t, long cycle,
                    const SimulationControls& controls);
  /// |balance error| of `e` over the largest energy in play so far.
  Real energy_error_fraction(const EnergyReport& e) const;
  /// Set once the energy balance error first passed controls.energy_error_warning.
  const std::optional<EnergyWarning>& energy_warning() const { return energy_warning_; }
  /// Set once the contact forces first did more than kContactEnergyWarning of the largest energy
  /// in play more work on the bodies than they took from them (relative_error: that excess over
  /// the energy in play). Every ledger term is a nodal work, so the balance cannot see energy that
  /// contact creates; this is where it shows.
  const std::optional<EnergyWarning>& contact_energy_warning() const { return contact_warning_; }
  static constexpr Real kContactEnergyWarning = 0.05;

 private:
  Real dt_first_ = 0.0;     // the first step taken (for dt_min_fraction)
  Real peak_energy_ = 0.0;  // largest energy in play so far
  std::optional<EnergyWarning> energy_warning_;
  std::optional<EnergyWarning> contact_warning_;
};

}  // namespace slideline
