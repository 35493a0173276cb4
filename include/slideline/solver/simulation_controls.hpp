#pragma once
/// The controls of a run (end time, step scaling, output cadence, stability limits) and the step
/// plan of one cycle.
#include "slideline/core/types.hpp"
#include "slideline/solver/load_curve.hpp"

namespace slideline {

struct SimulationControls {
  Real end_time = 0.0;
  Real dt_scale = 0.9;          ///< time-step scale factor applied to the stable element step
  Real dt_max = 0.0;            ///< upper bound on the step (0 = none)
  /// Upper bound on the step against time (LS-DYNA LCTM of *CONTROL_TIMESTEP), when set.
  bool has_dt_max_curve = false;
  LoadCurve dt_max_curve;
  Real history_interval = 0.0;  ///< 0 = histories at every cycle
  Real state_interval = 0.0;    ///< 0 = no nodal states
  long max_cycles = 0;          ///< 0 = no limit
  /// Stop with an InstabilityError when |energy balance error| exceeds this fraction of the
  /// largest energy in play so far (0 = never). Checked from cycle kEnergyCheckStart on: before
  /// that the energies are round-off and their ratio means nothing.
  Real energy_error_limit = 0.05;
  /// Record a warning (Simulation::energy_warning) the first time the error exceeds this fraction.
  Real energy_error_warning = 0.01;
  /// Stop when the step falls below this fraction of the first step (LS-DYNA's DTMIN of
  /// *CONTROL_TERMINATION; 0 = never), naming the part whose elements control the step.
  Real dt_min_fraction = 1e-4;
  /// ERODE of *CONTROL_TIMESTEP: the solid elements whose step (times dt_scale) falls below
  /// dt_min_fraction x the first step are deleted (their blocks' ErosionCriteria::erode_below_tsmin)
  /// instead of the run stopping.
  bool erode_below_dt_min = false;
  /// Mass scaling (LS-DYNA's DT2MS of *CONTROL_TIMESTEP; 0 = none), applied once at initialize()
  /// (solver/mass_scaling.hpp): < 0 elements whose stable step is below |dt2ms| get mass to make
  /// it |dt2ms|; > 0 every deformable element's mass is scaled to make its step dt2ms.
  Real dt2ms = 0.0;
  /// With dt2ms != 0: re-evaluate the factors from the elements' current steps after every force
  /// evaluation (LS-DYNA's MS1ST = 0, solver/mass_rescaling.hpp) instead of once at initialize()
  /// (MS1ST = 1). Hexahedra (ELFORM 1) only; other deformable blocks refuse.
  bool mass_scaling_every_cycle = false;
  /// The step vote of a contact spring counts the elements on the nodes it joins: 1 / dt^2 =
  /// 1 / dt_e^2 + 1 / dt_c^2 (contact/element_steps_view.hpp; docs/solver.md, "The step of a node
  /// with elements and a contact spring"), the bound the pair's highest frequency obeys. On by
  /// default since session 19. Off: each spring votes alone (LS-DYNA's rule, the default before),
  /// which is unstable wherever a node's spring and elements are of a stiffness (TSSFAC sqrt(1 +
  /// r^2) > 1 with r the ratio of the two votes: a null column striking a plate at TSSFAC 0.9
  /// leaves 5.7 % faster than it came, exit 0); the CLI's --contact-step-springs-alone.
  bool contact_step_with_elements = true;
  /// initialize() refuses a model whose mass scaling adds more than this percentage of its mass
  /// (LS-DYNA's ENDMAS of *CONTROL_TERMINATION; its default 1e8 is no limit).
  Real added_mass_limit_percent = 1e8;
};

/// The first cycle at which the energy balance is checked against the limits above.
inline constexpr long kEnergyCheckStart = 100;

/// The first time the energy balance error passed SimulationControls::energy_error_warning.
struct EnergyWarning {
  Real time = 0.0;
  long cycle = 0;
  Real relative_error = 0.0;
};

/// The step Simulation::plan_step() decides for the coming cycle.
struct StepPlan {
  Real dt_next = 0.0;  ///< t^{n+1} - t^n
  Real dt_avg = 0.0;   ///< the velocity step (dt_prev + dt_next) / 2, dt_next / 2 on the first cycle
  Real t_next = 0.0;   ///< t^{n+1} (exactly the output or end time it lands on, if it lands)
  bool at_end = false; ///< the end time or cycle limit is reached: record and stop
};

}  // namespace slideline
