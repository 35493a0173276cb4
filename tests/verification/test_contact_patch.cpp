// The contact patch test (issue 18, part 3; docs/contact.md, "The contact patch test"): a 3 x 3
// block squeezed onto a 4 x 4 or 5 x 5 block by a uniform pressure p, footprints 1e-3 apart on
// every side (non-matching meshes, edges not flush), stiffness hourglass control. The exact static
// state is uniform compression: sigma_yy = -p in every element next to the interface, on both
// sides. Each case also runs rotated about an oblique axis (sigma turned back, R^T sigma R).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "contact_patch_model.hpp"
#include "slideline/solver/build.hpp"

namespace slideline {
namespace {

using patch_test::PatchOptions;
using patch_test::PatchResult;
using patch_test::run_patch;
using model::ContactType;
using model::Enforcement;

/// A rotation by 37 degrees about the axis (1, 2, 3) / |(1, 2, 3)|.
Mat3 oblique_rotation() {
  return Eigen::AngleAxis<Real>(37.0 * M_PI / 180.0, Vec3(1.0, 2.0, 3.0).normalized()).toRotationMatrix();
}

struct PatchCase {
  const char* name;
  ContactType type;
  Enforcement enforcement;
  int lower_cells;
  Real sfs;
  bool lower_is_slave;
  int coupling;       ///< model::Contact::penalty_coupling (1 mortar)
  Real bound;         ///< largest |sigma_yy / (-p) - 1| allowed
  bool static_state;  ///< the run settles (the figures stop moving) by its end
};

void print(const PatchCase& c, const char* frame, const PatchResult& r) {
  std::printf("patch %-32s %-8s upper [%.4f, %.4f] lower [%.4f, %.4f] worst %.4f drift %.1e\n", c.name, frame,
              r.upper_min, r.upper_max, r.lower_min, r.lower_max, r.worst(), r.drift);
}

class ContactPatch : public ::testing::TestWithParam<PatchCase> {};

// Each case: the spread of sigma_yy / (-p) next to the interface within its bound, the same in the
// copy rotated about an oblique axis (to 1e-6), and a settled state where the case reaches one.
TEST_P(ContactPatch, NormalStressNextToTheInterface) {
  const PatchCase& c = GetParam();
  PatchOptions o;
  o.type = c.type;
  o.enforcement = c.enforcement;
  o.lower_cells = c.lower_cells;
  o.sfs = c.sfs;
  o.lower_is_slave = c.lower_is_slave;
  o.coupling = c.coupling;
  const PatchResult r = run_patch(o);
  print(c, "global", r);
  o.rotation = oblique_rotation();
  const PatchResult rr = run_patch(o);
  print(c, "rotated", rr);
  EXPECT_LT(r.worst(), c.bound);
  EXPECT_NEAR(rr.worst(), r.worst(), 1e-6);
  if (c.static_state) EXPECT_LT(r.drift, 1e-3);
}

// The goal (issue 18) is 5 %. Cases marked "known limit" do not meet it; their bound is the
// measured figure rounded up (docs/contact.md, "The contact patch test", says why), so that a
// change that makes them worse is seen.
constexpr ContactType T3 = ContactType::surface_to_surface, T5 = ContactType::nodes_to_surface,
                      T10 = ContactType::one_way, T12 = ContactType::automatic;
constexpr Enforcement P = Enforcement::penalty, L = Enforcement::lagrange;
constexpr PatchCase kCases[] = {
    // DYNA3D's stiffness rule (the default): known limits.
    {"t3_penalty_4x4", T3, P, 4, 1.0, false, 0, 0.14, true},
    {"t3_penalty_5x5", T3, P, 5, 1.0, false, 0, 0.27, true},
    {"t3_penalty_5x5_sf10", T3, P, 5, 10.0, false, 0, 0.12, true},
    {"t12_penalty_4x4", T12, P, 4, 1.0, false, 0, 0.14, true},
    {"t12_penalty_5x5", T12, P, 5, 1.0, false, 0, 0.27, true},
    {"t10_penalty_5x5", T10, P, 5, 1.0, false, 0, 0.80, false},
    {"t5_penalty_5x5", T5, P, 5, 1.0, false, 0, 0.80, false},
    {"t10_penalty_5x5_fine_slave", T10, P, 5, 1.0, true, 0, 0.75, false},
    // Lagrange multipliers (one pass, node on segment): known limits.
    {"t3_lagrange_4x4", T3, L, 4, 1.0, false, 0, 0.22, true},
    {"t3_lagrange_5x5", T3, L, 5, 1.0, false, 0, 0.46, true},
    {"t3_lagrange_5x5_fine_slave", T3, L, 5, 1.0, true, 0, 0.09, true},
    {"t12_lagrange_4x4", T12, L, 4, 1.0, false, 0, 0.14, true},
    {"t12_lagrange_5x5", T12, L, 5, 1.0, false, 0, 0.09, true},
    // Mortar coupling (penalty_coupling = 1): the goal, 5 %, for two passes (Type 3) and for one
    // pass of the coarse side's nodes; known limits marked.
    {"t3_penalty_4x4_mortar", T3, P, 4, 1.0, false, 1, 0.05, true},
    {"t3_penalty_5x5_mortar", T3, P, 5, 1.0, false, 1, 0.05, true},
    {"t3_penalty_5x5_sf10_mortar", T3, P, 5, 10.0, false, 1, 0.05, true},
    {"t10_penalty_5x5_mortar", T10, P, 5, 1.0, false, 1, 0.05, true},
    {"t12_penalty_4x4_mortar", T12, P, 4, 1.0, false, 1, 0.05, true},
    {"t12_penalty_5x5_mortar", T12, P, 5, 1.0, false, 1, 0.10, true},            // known limit
    {"t10_penalty_5x5_fine_slave_mortar", T10, P, 5, 1.0, true, 1, 0.11, false},  // known limit
};

INSTANTIATE_TEST_SUITE_P(Cases, ContactPatch, ::testing::ValuesIn(kCases),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace slideline
