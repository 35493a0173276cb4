// A flyer of *MAT_NULL + *EOS_GRUNEISEN hitting a rigid wall (docs/solver.md, "Null solids"):
// a column of 200 unit cubes in uniaxial strain (lateral faces held), moving at -v toward its
// end x = 0, which is held. The wall stops the material behind a shock that runs into the flyer;
// relative to the oncoming material the particle velocity jumps by up = v, so on the Hugoniot
// Us = C + S1 up the shocked state is
//   p = rho0 Us up,   V/V0 = 1 - up / Us,   E = p (1 - V/V0) / 2 = rho0 up^2 / 2,
// and the front runs at Us - up in the wall's frame. LS-DYNA's Gruneisen form gives exactly this
// p at E = E_H for any GAMAO (the (1 - GAMAO/2) mu term cancels GAMAO E_H), so with GAMAO = 2
// the test also checks that the shock heating (the bulk viscosity's work) reaches E.
// rho0 = 1e-3, C = 1000, S1 = 1.5, v = 100: Us = 1150, p = 115, V/V0 = 0.91304, E = 5.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "slideline/io/keyword_reader.hpp"
#include "slideline/solver/build.hpp"
#include "slideline/solver/simulation.hpp"

namespace slideline {
namespace {

constexpr int kN = 200;
constexpr Real kRho = 1e-3, kC = 1000.0, kS1 = 1.5, kV = 100.0;

std::string flyer(Real end_time) {
  std::ostringstream o;
  o << std::setprecision(17) << "*KEYWORD\n*CONTROL_TERMINATION\n" << end_time << ",\n*SECTION_SOLID\n1,1\n"
    << "*MAT_NULL\n1," << kRho << ",-1e6\n*EOS_GRUNEISEN\n1," << kC << "," << kS1 << ",0,0,2.0,0,0\n"
    << "*PART\nflyer\n1,1,1,1\n*NODE\n";
  const int yz[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int i = 0; i <= kN; ++i)
    for (int q = 0; q < 4; ++q) o << 4 * i + q + 1 << "," << i << "," << yz[q][0] << "," << yz[q][1] << "\n";
  o << "*ELEMENT_SOLID\n";
  for (int i = 0; i < kN; ++i) {
    o << i + 1 << ",1";
    for (int q = 0; q < 8; ++q) o << "," << 4 * (i + q / 4) + q % 4 + 1;
    o << "\n";
  }
  o << "*INITIAL_VELOCITY_NODE\n";
  for (int id = 5; id <= 4 * (kN + 1); ++id) o << id << "," << -kV << ",0,0\n";
  o << "*SET_NODE_LIST_GENERATE\n1\n1," << 4 * (kN + 1) << "\n*SET_NODE_LIST\n2\n1,2,3,4\n"
    << "*BOUNDARY_SPC_SET\n1,0,0,1,1\n*BOUNDARY_SPC_SET\n2,0,1,0,0\n*END\n";
  return o.str();
}

TEST(GruneisenImpact, ShockStateOnTheHugoniot) {
  const Real up = kV, us = kC + kS1 * up;
  const Real p_h = kRho * us * up, j_h = 1.0 - up / us, e_h = 0.5 * kRho * up * up;
  const Real t_end = 150.0 / (us - up);  // the front at x = 150
  auto sim = build_simulation(read_keyword_string(flyer(t_end), "flyer.k"));
  while (sim->step()) {
  }
  std::vector<CellOutput> cells(kN);
  sim->blocks().at(0)->cell_outputs(sim->nodes(), cells);
  // Elements 21..100 (x from 20 to 100): well behind the front, clear of the wall's start-up.
  Real p = 0.0, e = 0.0, j = 0.0;
  const auto& x = sim->nodes().x.x;
  for (int i = 20; i < 100; ++i) {
    const auto& s = cells[static_cast<std::size_t>(i)].stress;
    p += -(s[0] + s[1] + s[2]) / 3.0 / 80.0;
    e += cells[static_cast<std::size_t>(i)].energy_density / 80.0;
    j += (x[static_cast<std::size_t>(4 * (i + 1))] - x[static_cast<std::size_t>(4 * i)]) / 80.0;
  }
  // The front: the first element from the wall whose V/V0 is above halfway to the shocked value.
  int front = 0;
  while (front < kN && x[static_cast<std::size_t>(4 * (front + 1))] - x[static_cast<std::size_t>(4 * front)] < 0.5 * (1.0 + j_h))
    ++front;
  const Real x_front = x[static_cast<std::size_t>(4 * front)];
  const EnergyReport en = sim->energy();
  std::printf("shock: p %.3f (Hugoniot %.3f, %.2f%%), V/V0 %.5f (%.5f), E %.4f (%.4f, %.2f%%); front at x = %.1f "
              "(%.1f); energy: kinetic %.4g of %.4g, internal %.4g, bulk viscosity %.4g, hourglass %.3g, "
              "balance error %.2e\n",
              p, p_h, 100 * (p / p_h - 1), j, j_h, e, e_h, 100 * (e / e_h - 1), x_front, (us - up) * t_end,
              en.kinetic, en.kinetic0, en.internal, en.bulk_viscosity, en.hourglass, en.relative_balance_error());
  EXPECT_NEAR(p, p_h, 0.02 * p_h);
  EXPECT_NEAR(j, j_h, 0.002);
  EXPECT_NEAR(e, e_h, 0.05 * e_h);
  EXPECT_NEAR(x_front, (us - up) * t_end, 3.0);  // within 3 elements (2 %)
  EXPECT_LT(std::abs(en.balance_error()), 1e-3 * en.kinetic0);
}

}  // namespace
}  // namespace slideline
