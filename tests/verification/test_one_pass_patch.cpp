// Types 5 and 10 (one pass) on the contact patch test (issue 18, part 3; docs/contact.md, "The
// contact patch test"): why they did not settle by t = 1.5. They do settle: the mass damping of
// the patch test (VALDMP 150) overdamps a soft mode of the one-pass model (kinetic energy falling
// 11x per 0.25: amplitude rate ~4.9 / s = omega^2 / VALDMP, omega ~ 27 rad/s), so at t = 1.5 the
// figures were still 2e-3 from their end and had moved 2.5e-2 over the last third. With VALDMP 30 the same model is static by t = 1 and stays
// there; the state it settles in is the one-pass concentration (the coarse block's 16 nodes hold
// the fine master surface at points; upper 0.41-1.29, lower 0.37-1.79 of p), the same with
// either damping.
#include <gtest/gtest.h>

#include <cstdio>

#include "contact_patch_model.hpp"

namespace slideline {
namespace {

using patch_test::PatchOptions;
using patch_test::PatchResult;

PatchResult run_one_pass(model::ContactType type, Real damping, Real end_time) {
  PatchOptions o;
  o.type = type;
  o.damping = damping;
  o.end_time = end_time;
  const PatchResult r = patch_test::run_patch(o);
  std::printf("one pass, type %d, VALDMP %.0f, t %.1f: upper [%.4f, %.4f] lower [%.4f, %.4f] drift %.1e\n",
              static_cast<int>(type), damping, end_time, r.upper_min, r.upper_max, r.lower_min, r.lower_max, r.drift);
  return r;
}

// Static by t = 1 with lighter damping (the last third moves < 1e-9), and the state it reaches is
// the one the heavily damped run approaches (within the 2.5e-2 the heavy run still had to go at
// t = 1.5, and to 1e-3 once that run is given t = 3).
TEST(OnePassPatch, SettlesOnceTheMassDampingNoLongerOverdampsIt) {
  for (model::ContactType type : {model::ContactType::one_way, model::ContactType::nodes_to_surface}) {
    const PatchResult light = run_one_pass(type, 30.0, 3.0);
    EXPECT_LT(light.drift, 1e-9);
    const PatchResult heavy = run_one_pass(type, 150.0, 3.0);
    EXPECT_LT(heavy.drift, 1e-3);
    EXPECT_NEAR(heavy.worst(), light.worst(), 1e-3);
  }
}

}  // namespace
}  // namespace slideline
