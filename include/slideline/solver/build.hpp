#pragma once
/// Turns a model description (deck semantics, ids) into a runnable Simulation (physical
/// semantics, dense indices). Every reference is checked; errors name the card and its line.
#include <memory>

#include "slideline/model/model.hpp"
#include "slideline/solver/simulation.hpp"
#include "slideline/solver/simulation_setup.hpp"

namespace slideline {

struct BuildOptions {
  /// Overrides *CONTROL_TERMINATION's ENDTIM when > 0.
  Real end_time = 0.0;
  /// Where the simulation's warnings go (initial penetrations moved out, untied slaves, an
  /// unconverged Lagrange solve); null drops them. Must outlive the simulation.
  DiagnosticSink* diagnostics = nullptr;
};

/// Builds the setup a Simulation is constructed from (simulation_setup.hpp); a caller that adjusts
/// it before the run (the CLI's energy-limit flag, a test) changes the value, then constructs.
/// Throws InputError for a bad reference or value, NotImplementedError for a card this version
/// cannot run yet (naming the card and its line).
SimulationSetup build_setup(const model::Model& model, const BuildOptions& options = {});

/// build_setup, then the Simulation constructed from it with options.diagnostics as its sink.
/// Throws as build_setup does.
std::unique_ptr<Simulation> build_simulation(const model::Model& model, const BuildOptions& options = {});

/// "file:line" of a card, or "(generated)" when it was built programmatically.
std::string describe(const model::Source& src);

}  // namespace slideline
