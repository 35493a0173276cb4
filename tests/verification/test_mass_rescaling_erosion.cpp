// Mass scaling every cycle (DT2MS with MS1ST = 0) together with element erosion: a deleted element
// votes no step and adds no mass from its deletion on; the mass it had added leaves its nodes at
// the re-evaluation of that cycle, and the kinetic energy that change takes out is booked in
// energy/mass_scaling, so that the balance closes. The strips: mass_rescaling_strips.hpp.
//
// The strip is plastic (J2, yield 0.02 E, tangent 0.1 E, isotropic), pushed at 4 (0.04 c: the
// impact stress rho c v = 0.04 E is twice the yield stress), its elements deleted at a plastic
// strain of 0.1, T = |DT2MS| = 0.99 x the step at rest (a shell compressed plastically widens in its
// plane, so its step falls more slowly than a solid's). Checked every cycle:
//   - the mass-scaling term grows by exactly sum_i 1/2 (m_i' - m_i) |v_i|^2 (+ 1/2 (J_i' - J_i)
//     |omega_i|^2 on shell nodes), the masses before and after the cycle's re-evaluation and the
//     velocities v^{n+1/2} it happens at;
//   - the strip's added mass is the closed form over its live elements (a deleted one adds none);
// and at the end that elements were deleted after having been scaled, and the balance error.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "mass_rescaling_strips.hpp"

using namespace slideline;
using namespace slideline::strips;

namespace {

/// The strip of `kind` of the test; `dt2ms` 0: no mass scaling. Runs to t = 0.06 (about six wave
/// transits) in steps of 0.9 x 0.99 x its step at rest.
StripModel make(Kind kind, Real dt2ms) {
  StripSpec spec;
  spec.kind = kind;
  spec.r = rotation();
  spec.push_speed = 4.0;
  spec.failure_strain = 0.1;
  StripModel model({spec});
  const Real step = 0.9 * 0.99 * reference_step(kind, spec.h);
  model.setup.controls.dt2ms = dt2ms;
  model.setup.controls.dt_scale = 0.9;
  model.setup.controls.dt_max = step;
  model.setup.controls.max_cycles = static_cast<long>(std::ceil(0.06 / step));
  model.setup.controls.mass_scaling_every_cycle = true;
  return model;
}

}  // namespace

TEST(MassRescalingErosion, DeletedElementsStopAddingMassAndTheBalanceCloses) {
  for (Kind kind : {Kind::hex1, Kind::shell, Kind::hex2, Kind::tet}) {
    SCOPED_TRACE(name(kind));
    const Real target = 0.99 * reference_step(kind, 0.1);
    StripModel plain = make(kind, 0.0);
    plain.start();
    while (plain.sim().step()) {
    }
    StripModel model = make(kind, -target);
    model.start();
    const Simulation& sim = model.sim();
    const Strip& s = model.strips[0];
    const NodalFields& nd = sim.nodes();
    std::vector<Real> mass_before, inertia_before;
    std::vector<Real> element_added(s.elements.size(), 0.0);  // each element's added mass before the cycle
    int deleted_scaled = 0, deletions = 0;
    Real worst_term = 0.0, worst_closed = 0.0, removed_at_deletion = 0.0;
    for (;;) {
      mass_before = nd.mass;
      inertia_before = nd.rot_inertia;
      const Real term_before = sim.energy().mass_scaling;
      std::vector<bool> was_deleted(s.elements.size());
      for (std::size_t e = 0; e < s.elements.size(); ++e) {
        was_deleted[e] = deleted(s, sim, e);
        element_added[e] =
            was_deleted[e] ? 0.0 : s.mass[e] * (factor(element_step(s, nd, e), -target) - 1.0);
      }
      if (!model.sim().step()) break;
      // The booked kinetic-energy change of this cycle's re-evaluation.
      Real dk = 0.0, scale = 0.0;
      for (std::size_t i = 0; i < nd.size(); ++i) {
        dk += 0.5 * (nd.mass[i] - mass_before[i]) * nd.v.get(i).squaredNorm();
        if (nd.has_rotation[i]) dk += 0.5 * (nd.rot_inertia[i] - inertia_before[i]) * nd.omega.get(i).squaredNorm();
        scale += 0.5 * nd.mass[i] * nd.v.get(i).squaredNorm();
      }
      const Real term = sim.energy().mass_scaling - term_before;
      worst_term = std::max(worst_term, std::abs(term - dk) / scale);
      // The added mass: the closed form over the live elements.
      const Real expected = closed_form_added(s, sim, -target);
      const Real m0 = s.mass[0] * static_cast<Real>(s.elements.size());
      worst_closed = std::max(worst_closed, std::abs(sim.added_mass().at(0).added - expected) / m0);
      for (std::size_t e = 0; e < s.elements.size(); ++e)
        if (!was_deleted[e] && deleted(s, sim, e)) {
          ++deletions;
          if (element_added[e] > 0.0) {
            ++deleted_scaled;
            removed_at_deletion += element_added[e];
          }
        }
    }
    EXPECT_LT(worst_term, 1e-13);
    EXPECT_LT(worst_closed, 1e-12);
    EXPECT_GT(deletions, 0);
    EXPECT_GT(deleted_scaled, 0);
    // The balance: erosion alone (the same strip without mass scaling) leaves an error of 0.1 to
    // 0.5 % of the energy in play here (measured; the eroding elements' own residual); with mass
    // scaling and its booked term the error stays at that level, while the term itself (the
    // kinetic energy the added and removed masses took in and out) is larger than the error.
    const EnergyReport& en = sim.energy();
    const EnergyReport& ep = plain.sim().energy();
    EXPECT_GT(en.eroded(), 0.0);
    EXPECT_LT(std::abs(en.balance_error()), 2.0 * std::abs(ep.balance_error()));
    EXPECT_LT(std::abs(en.relative_balance_error()), 5e-3) << en.balance_error();
    EXPECT_GT(std::abs(en.mass_scaling), std::abs(en.balance_error()));
    std::printf("%s: %d elements deleted (%d scaled before, their added mass %.4g), added mass now %.4g; "
                "max |booked - 1/2 dm v^2| / K = %.2g, max |added - closed form| / m = %.2g; energy: mass_scaling "
                "%.4g, eroded %.4g, balance error %.3g (%.2g of the energy in play); without mass scaling: %d deleted, "
                "eroded %.4g, balance error %.3g (%.2g)\n",
                name(kind), deletions, deleted_scaled, removed_at_deletion, sim.added_mass().at(0).added, worst_term,
                worst_closed, en.mass_scaling, en.eroded(), en.balance_error(), en.relative_balance_error(),
                static_cast<int>(plain.sim().blocks()[0]->erosion()->deleted_count()), ep.eroded(), ep.balance_error(),
                ep.relative_balance_error());
  }
}
