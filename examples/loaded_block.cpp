// The spec's two solid blocks merged into one body, on the spec's supports under the spec's body
// loads (P_y = 10 down from t = 0 to 0.1, P_x = 3.1 from t = 0.3 to 0.4), damped at 5% of critical
// at 150 rad/s. Prints the support reactions against the static answer (R_y = -10, R_x = 3.1).
#include <cstdio>

#include "slideline/scenarios/two_block.hpp"
#include "slideline/solver/build.hpp"
#include "slideline/solver/output_sink.hpp"

int main() {
  using namespace slideline;
  scenarios::TwoBlockOptions options;
  options.merged = true;
  const model::Model model = scenarios::make_solid_pair_model(options);
  auto sim = build_simulation(model);
  History history;
  sim->run({&history});
  const Real ry = history.mean("supports/bottom_y/reaction", 1, 0.2, 0.3);
  const Real rx = history.mean("supports/right_x/reaction", 0, 0.45, 0.5);
  std::printf("cycles %ld, elements %d\n", sim->cycle(), sim->element_count());
  std::printf("mean R_y over [0.2, 0.3] = %.5f (static answer -10)\n", ry);
  std::printf("mean R_x over [0.45, 0.5] = %.5f (static answer 3.1)\n", rx);
  std::printf("energy balance error = %.3e (relative %.3e)\n", sim->energy().balance_error(),
              sim->energy().relative_balance_error());
  return (ry < -9.95 && ry > -10.05 && rx > 3.069 && rx < 3.131) ? 0 : 1;
}
