#pragma once
// A test fixture's simulation in its two stages: the fixture and the test fill `setup`, then
// start() constructs the Simulation from it and initialises it; sim() is that simulation from then
// on. Shared by the fixtures that assemble a Simulation directly (no deck).
#include <memory>
#include <stdexcept>

#include "slideline/solver/simulation.hpp"
#include "slideline/solver/simulation_setup.hpp"

namespace slideline::test_support {

class StagedSimulation {
 public:
  /// What the simulation is built from; moved into it (and left empty) by start().
  SimulationSetup setup;

  /// Constructs the simulation from `setup` and initialises it (once).
  void start() {
    if (sim_) throw std::logic_error("StagedSimulation::start() called twice");
    sim_ = std::make_unique<Simulation>(std::move(setup));
    sim_->initialize();
  }
  Simulation& sim() { return checked(); }
  const Simulation& sim() const { return checked(); }

 private:
  Simulation& checked() const {
    if (!sim_) throw std::logic_error("StagedSimulation::sim() before start()");
    return *sim_;
  }
  std::unique_ptr<Simulation> sim_;
};

}  // namespace slideline::test_support
