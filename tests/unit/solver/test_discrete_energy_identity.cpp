// The energy ledger against the exact discrete energy identity of the central difference. With
// m (v^{n+1/2} - v^{n-1/2}) = f^n dt (f the total force on a dof) and the works of every force on the
// trapezoid, K^{n+1} - K^n = v^{n+1/2} (f^n + f^{n+1}) dt / 2 holds for K^n = m v^{n-1/2} v^{n+1/2} / 2,
// for any forces (the identity is algebraic). The ledger reports the kinetic energy of the mean
// velocity, which exceeds that K^n by m (v^{n+1/2} - v^{n-1/2})^2 / 8 per dof, so at a constant step
// its balance error must be exactly sum m (v^{n+1/2} - v^{n-1/2})^2 / 8: nothing else, at every
// cycle, whatever the model's frequency content, hourglass and bulk viscosity included
// (central_difference.hpp, book_dof; docs/solver.md, "The discrete energy identity").
//
// What it caught: the first cycle (a half step from v(0)) booked its forces over dt v^{1/2} / 2,
// where a constant force takes a node from v(0) to v^{1/2} over dt_avg (v(0) + v^{1/2}) / 2, and the
// balance kept -(f^0 dt)^2 / (8 m) for ever: zero when nothing acts at t = 0, but the viscous
// hourglass and bulk-viscosity forces of random initial velocities put -13.6 % of the energy in
// play into it on a free 3 x 3 x 10 block (exit 4 at cycle 100 of a stable run), and -17.2 % at
// the end of the second test's block run at its own step by the previous build (exit 0: 75
// cycles, all before the energy checks start at cycle 100).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "slideline/io/keyword_reader.hpp"
#include "slideline/solver/build.hpp"
#include "slideline/solver/simulation.hpp"

namespace slideline {
namespace {

/// A free nx x ny x nz block of unit hexahedra, elastic (rho 1, E 1e4, nu), turned by `turn`
/// (rotation matrix), with initial velocities from `velocity(i, j, k)` (local axes, turned with
/// the block), TSSFAC `tssfac`; `extra` holds more control cards.
template <class Velocity>
std::string free_block(int nx, int ny, int nz, Real nu, const Mat3& turn, Real tssfac, Real end,
                       const std::string& extra, Velocity velocity) {
  const auto id = [&](int i, int j, int k) { return 1 + i + (nx + 1) * (j + (ny + 1) * k); };
  // LCTM = 9 when `extra` defines curve 9 (constant_step).
  const bool lctm = extra.find("*DEFINE_CURVE\n9\n") != std::string::npos;
  std::string s = "*KEYWORD\n*CONTROL_TERMINATION\n" + std::to_string(end) + "\n*CONTROL_TIMESTEP\n0.0," +
                  std::to_string(tssfac) + (lctm ? ",0,0.0,0.0,9" : "") + "\n" + extra + "*NODE\n";
  char line[160];
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        const Vec3 x = turn * Vec3(i, j, k);
        std::snprintf(line, sizeof line, "%d,%.17g,%.17g,%.17g\n", id(i, j, k), x[0], x[1], x[2]);
        s += line;
      }
  s += "*ELEMENT_SOLID\n";
  int e = 0;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        s += std::to_string(++e) + ",1";
        for (int q : {id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                      id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)})
          s += "," + std::to_string(q);
        s += "\n";
      }
  s += "*PART\nblock\n1,1,1\n*SECTION_SOLID\n1,1\n*MAT_ELASTIC\n1,1.0,1.0e4," + std::to_string(nu) +
       "\n*INITIAL_VELOCITY_NODE\n";
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        const Vec3 v = turn * velocity(i, j, k);
        std::snprintf(line, sizeof line, "%d,%.17g,%.17g,%.17g\n", id(i, j, k), v[0], v[1], v[2]);
        s += line;
      }
  return s + "*END\n";
}

/// A fixed pseudo-random number in [-0.5, 0.5) from the node's indices (the same on every
/// platform).
Real noise(int i, int j, int k, int c) {
  std::uint64_t h = 0x9E3779B97F4A7C15ull * static_cast<std::uint64_t>(1 + i + 64 * (j + 64 * (k + 64 * c)));
  h ^= h >> 31;
  h *= 0xBF58476D1CE4E5B9ull;
  h ^= h >> 29;
  return static_cast<Real>(h >> 11) / 9007199254740992.0 - 0.5;
}

/// The largest |balance error - sum m (v^{n+1/2} - v^{n-1/2})^2 / 8| over the cycles at the
/// constant step (the last, cut to the end time, left out), and the largest balance error, both
/// over the largest energy in play; the cycles run.
struct Identity {
  Real residual = 0.0;
  Real balance = 0.0;
  Real kinetic0 = 0.0;
  long cycles = 0;
};

Identity run(const std::string& deck, Real end) {
  SimulationSetup setup = build_setup(read_keyword_string(deck, "deck.k"));
  setup.controls.energy_error_limit = 0.0;  // the balance is what is measured here
  auto sim = std::make_unique<Simulation>(std::move(setup));
  sim->initialize();
  const NodalFields& nodes = sim->nodes();
  const std::size_t n = nodes.size();
  std::vector<Vec3> v_old(n);
  Identity r;
  Real peak = 0.0;
  for (;;) {
    for (std::size_t i = 0; i < n; ++i) v_old[i] = nodes.v.get(static_cast<Index>(i));
    const bool more = sim->step();
    const EnergyReport& e = sim->energy();
    peak = std::max({peak, e.kinetic0, e.kinetic, std::abs(e.internal) + e.hourglass + e.bulk_viscosity});
    if (r.cycles > 0 && more && sim->time() < end - 1e-9) {  // not the first (v(0)) nor the cut last
      Real expected = 0.0;
      for (std::size_t i = 0; i < n; ++i)
        expected += nodes.mass[i] * (nodes.v.get(static_cast<Index>(i)) - v_old[i]).squaredNorm() / 8.0;
      r.residual = std::max(r.residual, std::abs(e.balance_error() - expected) / peak);
    }
    r.balance = std::max(r.balance, std::abs(e.balance_error()) / peak);
    ++r.cycles;
    if (!more) break;
  }
  r.kinetic0 = sim->energy().kinetic0;
  return r;
}

Mat3 turned() { return Eigen::AngleAxis<Real>(0.7, Vec3(1.0, 2.0, 3.0).normalized()).toRotationMatrix(); }

/// A constant step: LCTM caps the step at `dt`, below the stable step of every cycle.
std::string constant_step(Real dt) {
  return "*DEFINE_CURVE\n9\n0.0," + std::to_string(dt) + "\n1000.0," + std::to_string(dt) + "\n";
}

TEST(DiscreteEnergyIdentity, FreeCubeAtItsHighestFrequency) {
  // One free cube (nu = 0: its dilatation mode is at omega = 2 c / h), started in that mode,
  // hourglass and bulk viscosity off, at dt = 0.85 h / c: a stable undamped oscillation at
  // omega dt = 1.7, where the balance error is (omega dt)^2 / 4 = 72 % of the strain energy at
  // the turning points (the monitor would stop it: its limit is off here).
  const std::string controls = "*CONTROL_HOURGLASS\n1,1.0e-20\n*CONTROL_BULK_VISCOSITY\n1.0e-20,1.0e-20\n" +
                               constant_step(8.5e-3);
  for (const Mat3& frame : {Mat3(Mat3::Identity()), turned()}) {
    const auto dilatation = [](int i, int j, int k) -> Vec3 { return Vec3(2 * i - 1, 2 * j - 1, 2 * k - 1) * 1e-3; };
    const std::string deck = free_block(1, 1, 1, 0.0, frame, 0.9, 1.0, controls, dilatation);
    const Identity r = run(deck, 1.0);
    std::printf("free cube%s: %ld cycles, largest balance error %.3e, residual of the identity %.3e\n",
                frame.isIdentity() ? "" : " (turned)", r.cycles, r.balance, r.residual);
    EXPECT_GT(r.cycles, 100);
    EXPECT_NEAR(r.kinetic0, 0.5 * 1.0 * 3e-6, 1e-18);  // 8 nodes of mass 1/8, |v|^2 = 3e-6
    EXPECT_GT(r.balance, 0.5);                         // the (omega dt)^2 / 4 term is there
    EXPECT_LT(r.residual, 1e-12);                      // and it is all there is
  }
}

TEST(DiscreteEnergyIdentity, RandomInitialVelocitiesLeaveNoFirstCycleOffset) {
  // A 3 x 3 x 10 block, nu = 0.3, default hourglass (viscous) and bulk viscosity, every node
  // started at a pseudo-random velocity: the viscous forces act from t = 0. At a constant step
  // the balance is the identity's term at every cycle (before: that less (f^0 dt)^2 / (8 m) for
  // ever; at the block's own step, -17 % of the energy in play at the end).
  for (const Mat3& frame : {Mat3(Mat3::Identity()), turned()}) {
    const auto random = [](int i, int j, int k) -> Vec3 {
      return Vec3(noise(i, j, k, 0), noise(i, j, k, 1), noise(i, j, k, 2)) * 1e-2;
    };
    const std::string deck = free_block(3, 3, 10, 0.3, frame, 0.9, 0.5, constant_step(6e-3), random);
    const Identity r = run(deck, 0.5);
    std::printf("random block%s: %ld cycles, largest balance error %.3e, residual of the identity %.3e\n",
                frame.isIdentity() ? "" : " (turned)", r.cycles, r.balance, r.residual);
    EXPECT_GT(r.cycles, 80);
    EXPECT_LT(r.residual, 1e-12);
  }
}

}  // namespace
}  // namespace slideline
