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
#include "slideline/io/keyword_reader.hpp"
#include "slideline/io/keyword_writer.hpp"
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
  std::printf("patch %-32s %-8s upper [%.4f, %.4f] lower [%.4f, %.4f] worst %.4f drift %.1e", c.name, frame,
              r.upper_min, r.upper_max, r.lower_min, r.lower_max, r.worst(), r.drift);
  if (r.solves.solves > 0)
    std::printf(" sweeps %.1f per solve (max %d, unconverged %ld)",
                static_cast<double>(r.solves.sweeps) / static_cast<double>(r.solves.solves), r.solves.max_sweeps,
                r.solves.unconverged);
  std::printf("\n");
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
    // Mortar coupling (penalty_coupling = 1, a deck's _MORTAR): the goal, 5 %, for two passes
    // (Type 3, Type 12) and for one pass of either side's nodes (Type 10).
    {"t3_penalty_4x4_mortar", T3, P, 4, 1.0, false, 1, 0.05, true},
    {"t3_penalty_5x5_mortar", T3, P, 5, 1.0, false, 1, 0.05, true},
    {"t3_penalty_5x5_sf10_mortar", T3, P, 5, 10.0, false, 1, 0.05, true},
    {"t10_penalty_5x5_mortar", T10, P, 5, 1.0, false, 1, 0.05, true},
    {"t12_penalty_4x4_mortar", T12, P, 4, 1.0, false, 1, 0.05, true},
    {"t12_penalty_5x5_mortar", T12, P, 5, 1.0, false, 1, 0.05, true},
    {"t10_penalty_5x5_fine_slave_mortar", T10, P, 5, 1.0, true, 1, 0.05, true},
    // Lagrange with the mortar transfer (_MORTAR with _LAGRANGE): the goal, 5 %.
    {"t3_lagrange_4x4_mortar", T3, L, 4, 1.0, false, 1, 0.05, true},
    {"t3_lagrange_5x5_mortar", T3, L, 5, 1.0, false, 1, 0.05, true},
    {"t3_lagrange_4x4_fine_slave_mortar", T3, L, 4, 1.0, true, 1, 0.05, true},
    {"t3_lagrange_5x5_fine_slave_mortar", T3, L, 5, 1.0, true, 1, 0.05, true},
    {"t10_lagrange_5x5_mortar", T10, L, 5, 1.0, false, 1, 0.05, true},
};

INSTANTIATE_TEST_SUITE_P(Cases, ContactPatch, ::testing::ValuesIn(kCases),
                         [](const auto& info) { return std::string(info.param.name); });

// The mortar coupling from a deck: each card that takes _MORTAR, on the patch model written as a
// keyword deck (the writer spells the coupling "_MORTAR") and read back. The run reaches the goal
// and the very figures of the model built in C++ (the deck carries the same model), in the global
// frame and rotated.
struct DeckCase {
  const char* name;
  ContactType type;
  model::ContactForm form;
  Enforcement enforcement;
  int lower_cells;
  const char* keyword;  ///< as written, before _ID
};

class ContactPatchDeck : public ::testing::TestWithParam<DeckCase> {};

TEST_P(ContactPatchDeck, MortarFromTheDeckReachesTheSameFigures) {
  const DeckCase& c = GetParam();
  PatchOptions o;
  o.type = c.type;
  o.form = c.form;
  o.enforcement = c.enforcement;
  o.lower_cells = c.lower_cells;
  o.coupling = 1;
  for (const bool rotated : {false, true}) {
    if (rotated) o.rotation = oblique_rotation();
    patch_test::PatchModel p = patch_test::make_patch_model(o);
    const PatchResult direct = run_patch(p, o);
    const std::string deck = write_keyword_string(p.model);
    ASSERT_NE(deck.find("\n" + std::string(c.keyword) + "_ID\n"), std::string::npos) << c.keyword;
    p.model = read_keyword_string(deck, "patch.k");
    ASSERT_EQ(p.model.contacts.size(), 1u);
    EXPECT_EQ(p.model.contacts[0].penalty_coupling, 1);
    const PatchResult r = run_patch(p, o);
    print({c.name, c.type, c.enforcement, c.lower_cells, 1.0, false, 1, 0.05, true},
          rotated ? "rotated" : "global", r);
    EXPECT_LT(r.worst(), 0.05);
    EXPECT_LT(r.drift, 1e-3);
    EXPECT_EQ(r.upper_min, direct.upper_min);
    EXPECT_EQ(r.upper_max, direct.upper_max);
    EXPECT_EQ(r.lower_min, direct.lower_min);
    EXPECT_EQ(r.lower_max, direct.lower_max);
  }
}

constexpr model::ContactForm kDyna3d = model::ContactForm::dyna3d,
                             kTwoSided = model::ContactForm::automatic_surface_to_surface;
constexpr DeckCase kDeckCases[] = {
    {"t3_5x5_deck", T3, kDyna3d, P, 5, "*CONTACT_SURFACE_TO_SURFACE_MORTAR"},
    {"t10_5x5_deck", T10, kDyna3d, P, 5, "*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_MORTAR"},
    {"t12_4x4_deck", T12, kDyna3d, P, 4, "*CONTACT_AUTOMATIC_SINGLE_SURFACE_MORTAR"},
    {"t12_two_sided_4x4_deck", T12, kTwoSided, P, 4, "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_MORTAR"},
    {"t12_two_sided_5x5_deck", T12, kTwoSided, P, 5, "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_MORTAR"},
    {"t3_lagrange_5x5_deck", T3, kDyna3d, L, 5, "*CONTACT_SURFACE_TO_SURFACE_MORTAR_LAGRANGE"},
};

INSTANTIATE_TEST_SUITE_P(Cards, ContactPatchDeck, ::testing::ValuesIn(kDeckCases),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace slideline
