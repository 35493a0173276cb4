// PartEnergyMonitor: per-part hourglass warning, negative internal and hourglass energy checks
// (include/slideline/solver/part_energy_monitor.hpp).
#include "slideline/solver/part_energy_monitor.hpp"

#include <algorithm>
#include <cstdio>

#include "slideline/core/error.hpp"

namespace slideline {

namespace {
std::string num(Real v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}
}  // namespace

void PartEnergyMonitor::reset(const std::vector<std::unique_ptr<ElementBlock>>& blocks) {
  slots_.clear();
  part_of_block_.clear();
  warnings_.clear();
  for (const auto& b : blocks) {
    const auto it = std::find_if(slots_.begin(), slots_.end(), [&](const Slot& s) { return s.part == b->part_id(); });
    part_of_block_.push_back(static_cast<std::size_t>(it - slots_.begin()));
    if (it == slots_.end()) slots_.push_back(Slot{b->part_id()});
  }
}

void PartEnergyMonitor::check(Real t, long cycle, Real scale) {
  if (!(scale > 0.0)) return;  // nothing in play yet
  const Real negligible = kNegligible * scale;
  for (Slot& s : slots_) {
    if (s.internal < -kNegativeFraction * scale)
      throw InstabilityError("the internal energy of part " + std::to_string(s.part) + " went negative (" +
                                 num(s.internal) + ", beyond " + num(100.0 * kNegativeFraction) +
                                 "% of the largest energy in play, " + num(scale) + ") at t = " + num(t) +
                                 ", cycle " + std::to_string(cycle) +
                                 ": its material is elastic, so a mode without stiffness (hourglass, mechanism) "
                                 "is growing",
                             t, cycle);
    // A viscous hourglass force only dissipates and a conservative stiffness only stores: the
    // hourglass energy of a part cannot go negative unless the control creates energy (a stiffness
    // form whose reference the element's plastic distortion has moved, for one).
    if (s.hourglass < -kNegativeFraction * scale)
      throw InstabilityError("the hourglass energy of part " + std::to_string(s.part) + " went negative (" +
                                 num(s.hourglass) + ", beyond " + num(100.0 * kNegativeFraction) +
                                 "% of the largest energy in play, " + num(scale) + ") at t = " + num(t) +
                                 ", cycle " + std::to_string(cycle) +
                                 ": the hourglass control is creating energy (try *CONTROL_HOURGLASS / "
                                 "*HOURGLASS IHQ 1-5)",
                             t, cycle);
    if (!s.warned && s.hourglass > negligible && s.hourglass > kHourglassFraction * std::max<Real>(s.internal, 0.0)) {
      s.warned = true;
      warnings_.push_back(HourglassWarning{s.part, t, cycle, s.hourglass, s.internal});
    }
  }
}

std::string to_string(const HourglassWarning& w) {
  return "hourglass energy of part " + std::to_string(w.part) + " passed " +
         num(100.0 * PartEnergyMonitor::kHourglassFraction) + "% of its internal energy at t = " + num(w.time) +
         " (cycle " + std::to_string(w.cycle) + "): " + num(w.hourglass) + " against " + num(w.internal) +
         " (LS-DYNA practice keeps it under 10%: hourglass modes may spoil the results)";
}

}  // namespace slideline
