// The spec's 19 problems, one test each: build, run, and require every criterion of every pairing
// (docs/verification.md). A problem whose interface type is not implemented yet is skipped with
// the builder's reason; once it builds, every criterion must hold.
#include <gtest/gtest.h>

#include <filesystem>

#include "slideline/core/error.hpp"
#include "slideline/scenarios/sslide_criteria.hpp"
#include "slideline/solver/build.hpp"

namespace slideline::scenarios {
namespace {

Dyna3dReported reported() {
  std::string dir = SLIDELINE_SPEC_DIR;
  if (!std::filesystem::exists(dir + "/dyna3d_reported.json")) dir = find_spec_dir(SLIDELINE_SOURCE_DIR);
  if (dir.empty()) throw Error("dyna3d_reported.json not found from " SLIDELINE_SOURCE_DIR);
  return Dyna3dReported::load(dir + "/dyna3d_reported.json");
}

class SslideSuite : public ::testing::TestWithParam<std::string> {};

TEST_P(SslideSuite, EveryCriterionHolds) {
  const auto problem = make_sslide_problem(GetParam());
  std::unique_ptr<Simulation> sim;
  try {
    sim = build_simulation(problem.model);
  } catch (const NotImplementedError& e) {
    GTEST_SKIP() << "not run: " << e.what();
  }
  History history;
  sim->run({&history});
  ASSERT_NEAR(sim->time(), problem.model.termination.endtim, 1e-12);
  const auto rows = evaluate_sslide_criteria(problem, sslide_histories(history, problem), reported());
  ASSERT_FALSE(rows.empty());
  for (const auto& r : rows)
    if (!r.pass)
      ADD_FAILURE() << r.pairing << ": " << r.criterion << " = " << r.measured << ", bound " << r.bound
                    << (r.dyna3d ? " (DYNA3D " + std::to_string(*r.dyna3d) + ")" : std::string())
                    << (r.note.empty() ? "" : " [" + r.note + "]");
}

INSTANTIATE_TEST_SUITE_P(Problems, SslideSuite, ::testing::ValuesIn(sslide_problem_names()),
                         [](const ::testing::TestParamInfo<std::string>& i) { return i.param; });

}  // namespace
}  // namespace slideline::scenarios
