// *MAT_NULL on shells (material/null_shell.hpp): a skin of shells without stiffness on a solid
// block is a contact surface. In sslide3p's shell-on-shell pairing the master skin (elastic in the
// spec) is made null: the solid block under it carries the load, and the interface still passes
// the full compressive load P_y = 10 to the block's supports.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "slideline/scenarios/sslide.hpp"
#include "slideline/scenarios/sslide_criteria.hpp"
#include "slideline/scenarios/two_block.hpp"
#include "slideline/core/error.hpp"
#include "slideline/solver/output_sink.hpp"
#include "slideline/solver/build.hpp"

using namespace slideline;

TEST(NullShell, NullSkinCarriesTheContactLoad) {
  scenarios::SslideProblem pr = scenarios::make_sslide_problem("sslide3p");
  const scenarios::SslidePairing* pair = nullptr;
  for (const auto& p : pr.pairings)
    if (p.name == "shell_on_shell") pair = &p;
  ASSERT_NE(pair, nullptr);
  ASSERT_NE(pair->skin_part, 0);
  pr.model.materials.push_back(model::MatNull{9, 0.1, 1000.0, 0.1, "null_skin", {}});
  for (auto& part : pr.model.parts)
    if (part.pid == pair->skin_part) part.mid = 9;
  pr.model.termination.endtim = 0.3;  // the vertical load is held from t = 0.1; no x load yet
  auto sim = build_simulation(pr.model);
  History h;
  sim->run({&h});
  const std::size_t last = h.records() - 1;
  const Real fy = h.value(scenarios::sslide_force_channel(pr, *pair), last, 1);
  const Real ry = h.value(scenarios::sslide_support_channel(pair->bottom_support), last, 1);
  EXPECT_NEAR(fy, 10.0, 0.2);
  EXPECT_NEAR(ry, -10.0, 0.2);
  RecordProperty("slave_force_y", std::to_string(fy));
}

// On solids *MAT_NULL needs an equation of state: the build refuses it, naming the part and why.
TEST(NullShell, SolidOfNullMaterialIsRefused) {
  model::Model m = scenarios::make_solid_pair_model({});
  m.materials.at(0) = model::MatNull{std::visit([](const auto& x) { return x.mid; }, m.materials.at(0)), 0.01, 1000.0,
                                     0.1, "null", {}};
  try {
    build_simulation(m);
    FAIL() << "built";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("combines solids with *MAT_NULL (a solid of it needs an equation of state"),
              std::string::npos)
        << e.what();
  }
}
