// PartEnergyMonitor: per-part hourglass warning, negative internal and hourglass energy checks
// (include/slideline/solver/part_energy_monitor.hpp).
#include "slideline/solver/part_energy_monitor.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

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
    if (b->stiffness_hourglass()) slots_[part_of_block_.back()].stiffness = true;
  }
}

void PartEnergyMonitor::check(Real t, long cycle, Real scale) {
  if (!(scale > 0.0)) return;  // nothing in play yet
  const Real negligible = kNegligible * scale;
  // An energy of a part below -kNegativeFraction x the largest energy in play stops the run.
  const auto stop_if_negative = [&](const Slot& s, const char* energy, Real value, const char* why) {
    if (value < -kNegativeFraction * scale)
      throw InstabilityError(std::string("the ") + energy + " energy of part " + std::to_string(s.part) +
                                 " went negative (" + num(value) + ", beyond " + num(100.0 * kNegativeFraction) +
                                 "% of the largest energy in play, " + num(scale) + ") at t = " + num(t) +
                                 ", cycle " + std::to_string(cycle) + ": " + why,
                             t, cycle);
  };
  for (Slot& s : slots_) {
    stop_if_negative(s, "internal", s.internal,
                     "its material is elastic, so a mode without stiffness (hourglass, mechanism) is growing");
    if (s.eroded_internal != 0.0 || s.eroded_hourglass != 0.0) {
      // With erosion, the elements still in the model and the deleted ones apart (each element's
      // energy is the work done on it: neither sum can go negative).
      stop_if_negative(s, "internal (elements not eroded)", s.internal - s.eroded_internal,
                       "the work done on the part's remaining elements is negative: energy is created in "
                       "them (an unstable contact or hourglass mode, or a material law that is not "
                       "dissipative on this path)");
      stop_if_negative(s, "internal (eroded elements)", s.eroded_internal,
                       "the elements deleted so far held negative energy when they were deleted");
    }
    // A conservative stiffness only stores: its trapezoidal work is the stored energy, which cannot
    // go negative unless the control creates energy (a stiffness form whose reference the
    // element's plastic distortion has moved, for one). A viscous force's work is the trapezoid of
    // a force that lags the velocity by half a step: it can dip below zero after a kick, so it is
    // not judged (ElementBlock::stiffness_hourglass).
    if (s.stiffness)
      stop_if_negative(s, "hourglass", s.hourglass,
                       "the hourglass control is creating energy (try *CONTROL_HOURGLASS / *HOURGLASS IHQ 1-6)");
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
