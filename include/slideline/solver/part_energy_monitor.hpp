#pragma once
/// PartEnergyMonitor: the internal and hourglass energies of each part, for two checks of the run
/// (docs/solver.md, "Energy checks per part"):
///  - hourglass energy above kHourglassFraction (10%) of the part's internal energy: a warning,
///    once per part (LS-DYNA practice: results with more hourglass energy than that are suspect);
///  - negative internal energy of a part (the stored energy plus the plastic work cannot be
///    negative): an instability, the run stops (InstabilityError, exit code 4). Checked on the
///    part's elements in the model and, where elements erode, on those deleted (what they held)
///    apart: a total over both would let the positive energy the deleted elements took away hide
///    live elements whose energy went negative;
///  - negative hourglass energy of a part (a viscous control only dissipates, a conservative
///    stiffness only stores): the control is creating energy, the run stops likewise.
/// Energies are the element powers at t^n integrated over the step that ends there, as the energy
/// ledger integrates the hourglass and bulk-viscosity powers; the internal energy is the work of
/// all the element forces net of hourglass, bulk viscosity and stiffness damping.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "slideline/core/types.hpp"
#include "slideline/element/element_block.hpp"

namespace slideline {

/// The first time a part's hourglass energy passed kHourglassFraction of its internal energy.
struct HourglassWarning {
  Id part = 0;
  Real time = 0.0;
  long cycle = 0;
  Real hourglass = 0.0;  ///< the part's hourglass energy then
  Real internal = 0.0;   ///< and its internal energy
};

class PartEnergyMonitor {
 public:
  static constexpr Real kHourglassFraction = 0.1;
  /// Energies below this fraction of the largest energy in play are round-off for both checks.
  static constexpr Real kNegligible = 1e-3;
  /// Internal or hourglass energy below -kNegativeFraction x the largest energy in play is an
  /// instability.
  static constexpr Real kNegativeFraction = 1e-2;

  /// One slot per block (several blocks of one part are summed); energies zeroed.
  void reset(const std::vector<std::unique_ptr<ElementBlock>>& blocks);
  /// Block `block`'s powers at t^n, integrated over `dt` (the step that ends at t^n; 0 at t = 0).
  /// The energies its elements deleted at this evaluation held (e.eroded_internal, e.eroded_hourglass)
  /// are booked to the part's eroded energies (they stay in its internal and hourglass totals).
  void add(std::size_t block, const BlockEnergy& e, Real dt) {
    Slot& s = slots_[part_of_block_[block]];
    s.hourglass += e.hourglass_power * dt;
    s.internal += (e.element_power - e.hourglass_power - e.viscous_power - e.damping_power) * dt;
    if (e.eroded_elements > 0) {
      s.eroded_internal += e.eroded_internal;
      s.eroded_hourglass += e.eroded_hourglass;
    }
  }
  /// Both checks at (t, cycle); `scale` is the largest energy in play so far. Records new
  /// hourglass warnings; throws InstabilityError for a part whose internal or hourglass energy
  /// went negative.
  void check(Real t, long cycle, Real scale);

  /// Warnings so far, in the order they arose (the CLI prints the new ones as they come).
  const std::vector<HourglassWarning>& hourglass_warnings() const { return warnings_; }
  std::size_t part_count() const { return slots_.size(); }
  Id part_id(std::size_t k) const { return slots_[k].part; }
  /// Part k's internal and hourglass energies: of all its elements, the deleted ones' (what they held
  /// when deleted) included.
  Real internal_energy(std::size_t k) const { return slots_[k].internal; }
  Real hourglass_energy(std::size_t k) const { return slots_[k].hourglass; }
  /// What part k's deleted elements held when they were deleted (element erosion; 0 without).
  Real eroded_internal_energy(std::size_t k) const { return slots_[k].eroded_internal; }
  Real eroded_hourglass_energy(std::size_t k) const { return slots_[k].eroded_hourglass; }

 private:
  struct Slot {
    Id part = 0;
    Real internal = 0.0;
    Real hourglass = 0.0;
    Real eroded_internal = 0.0;
    Real eroded_hourglass = 0.0;
    bool warned = false;
    bool stiffness = false;  ///< a block of the part has a stiffness hourglass control
  };
  std::vector<Slot> slots_;                 // one per part, in order of first block
  std::vector<std::size_t> part_of_block_;  // block -> slot
  std::vector<HourglassWarning> warnings_;
};

/// "hourglass energy of part 3 passed 10% of its internal energy at t = ... (cycle ...): ..."
std::string to_string(const HourglassWarning& w);

}  // namespace slideline
