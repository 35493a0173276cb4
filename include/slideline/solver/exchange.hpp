#pragma once
/// The three places where a distributed-memory run exchanges data between processes, named so that
/// the MPI work adds an implementation of `Exchange` and touches nothing else in the step.
///
/// A process owns a partition of the elements and holds, besides its own nodes, copies of the nodes
/// it shares with its neighbours. In one cycle (docs/architecture.md, "The time step"):
///  1. after the force gather: the element and contact forces of a shared node are partial sums
///     on each process that holds it; `sum_forces` completes them (a neighbour exchange);
///  2. at the dt reduction: each process votes for the stable step of its own elements and
///     interfaces; `min_dt` returns the minimum over all processes (an all-reduce);
///  3. at the energy sums: each process sums the energies of the nodes and elements it owns;
///     `sum_block_energies` adds the element powers of each block (the ledger's hourglass, bulk
///     viscosity and damping energies and the per-part energies come from them),
///     `sum_energies` the nodal sums of the velocity update and the friction dissipation, and
///     `sum_reset_work` the kinetic energy that the rigid bodies' and ties' resets change after the
///     position update (all-reduces), so that every process sees the same balance.
/// `SingleProcessExchange` is the implementation for one process: every call leaves its argument
/// as it is (one process holds every node and votes alone).
#include <span>

#include "slideline/core/types.hpp"
#include "slideline/element/element_block.hpp"
#include "slideline/mesh/nodal_fields.hpp"
#include "slideline/solver/energy_ledger.hpp"

namespace slideline {

/// The stable steps the force evaluation votes for (unscaled, time): the elements' and the
/// contact interfaces' (the largest finite number when no interface votes). The step is the
/// smaller of the two.
struct StepVotes {
  Real elements = 0.0;
  Real contact = 0.0;
  /// The block whose element sets `elements` (null when none does on this process), for messages.
  const ElementBlock* block = nullptr;
  /// The stable step (the smaller vote).
  Real stable() const { return contact < elements ? contact : elements; }
  /// True when an interface, not an element, sets the step.
  bool contact_controls() const { return stable() < elements; }
};

class Exchange {
 public:
  virtual ~Exchange() = default;
  /// Completes the internal and contact forces and moments (f_int, m_int, f_contact, m_contact)
  /// of the nodes shared with other processes, after the corner gather and the contact forces.
  virtual void sum_forces(NodalFields& nodes) = 0;
  /// The votes' minima over all processes (elements and contact each reduced on its own; `block`
  /// stays this process's).
  virtual StepVotes min_dt(const StepVotes& local) = 0;
  /// Adds the energy sums of all processes into `sums` (the nodal sums of one velocity update)
  /// and `friction` (the interfaces' running friction dissipation).
  virtual void sum_energies(NodalEnergySums& sums, Real& friction) = 0;
  /// Adds the element energies of all processes into `blocks`: this process's powers of each block
  /// at t^n (every process holds a partition of the same blocks, in the same order).
  virtual void sum_block_energies(std::span<BlockEnergy> blocks) = 0;
  /// The sum over all processes of `local`, the work a reset of the half-step velocities did on
  /// this process's nodes (the change of their kinetic energy).
  virtual Real sum_reset_work(Real local) = 0;
};

/// One process: nothing to exchange.
class SingleProcessExchange final : public Exchange {
 public:
  void sum_forces(NodalFields&) override {}
  StepVotes min_dt(const StepVotes& local) override { return local; }
  void sum_energies(NodalEnergySums&, Real&) override {}
  void sum_block_energies(std::span<BlockEnergy>) override {}
  Real sum_reset_work(Real local) override { return local; }
};

}  // namespace slideline
