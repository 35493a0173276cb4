// *MAT_NULL solids with an equation of state through the whole pipeline (deck, reader, builder,
// one-point hexahedra; docs/solver.md, "Null solids"), against closed forms:
//
// - Hydrostatic compression of one unit cube to V/V0 = 0.9, every node's motion prescribed
//   (x = J(t)^(1/3) X, so the element sees exactly that J), slowly (T = 100 against a transit
//   time of 0.03), then held. The pressure equals each EOS at mu = 1/J - 1 and the law's E to
//   1e-10 relative; E is the work p dV plus the bulk viscosity's heat (which the hexahedron adds
//   to E; the ledger books it as bulk-viscosity energy): for the E-free polynomial E0 + int_J^1 p dJ'
//   in closed form plus that heat, to 1e-7; for the gamma-law gas (C4 = C5 = 0.4) the adiabat
//   E = E0 J^-0.4 to 1e-5 of E - E0 (the heat of this slow compression, Q2 rho c len |dJ/dt| dJ
//   with the linear coefficient Q2 = 0.06, is 3e-5 of E - E0). The ledger's internal plus
//   bulk-viscosity energy is the change of E.
// - TEROD / CEROD delete the cube when its J crosses them (within one step of the closed-form
//   time); PC caps the tension.
// - A column of 100 cubes in uniaxial strain (lateral faces held), *MAT_NULL + linear polynomial
//   C1 = K: a front pushed in at one end travels at c = sqrt(K / rho) (the front between x = 20
//   and x = 60 to 1 %; each station's arrival of half the velocity within one element transit
//   h / c of x / c + t_ramp / 2: the mesh smears the front over a few elements); a pulse keeps its
//   height without viscosity (to the mesh's dispersion) and loses it with MU > 0; the energy
//   balance closes as for an elastic column of the same modulus.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "slideline/io/keyword_reader.hpp"
#include "slideline/solver/build.hpp"
#include "slideline/solver/simulation.hpp"

namespace slideline {
namespace {

constexpr Real kRho = 1e-3;

/// J(t) from 1 to j_end along a half cosine over [0, T], then held.
struct Squeeze {
  Real j_end, T;
  Real j(Real t) const {
    const Real pi = std::acos(-1.0);
    return t >= T ? j_end : 1.0 + (j_end - 1.0) * 0.5 * (1.0 - std::cos(pi * t / T));
  }
  /// The time J reaches `target` (between 1 and j_end).
  Real time_of(Real target) const {
    const Real pi = std::acos(-1.0);
    return T / pi * std::acos(1.0 - 2.0 * (target - 1.0) / (j_end - 1.0));
  }
  std::string curve(Real t_end) const {
    std::ostringstream o;
    o << std::setprecision(17) << "*DEFINE_CURVE\n1\n";
    for (int i = 0; i <= 400; ++i) o << T * i / 400 << "," << std::cbrt(j(T * i / 400)) - 1.0 << "\n";
    o << std::max(t_end, 2.0 * T) << "," << std::cbrt(j_end) - 1.0 << "\n";
    return o.str();
  }
};

/// The unit cube (node 1 + i + 2j + 4k at (i, j, k)) of *MAT_NULL `mat` with EOS `eos` (both
/// with id 1), each face at 0 held normal to itself, each face at 1 moved by the displacement of
/// `sq` (nodes on several such faces in each of their directions).
std::string cube(const std::string& mat, const std::string& eos, const Squeeze& sq, Real end_time) {
  std::ostringstream o;
  o << std::setprecision(17) << "*KEYWORD\n*CONTROL_TERMINATION\n" << end_time << ",\n*SECTION_SOLID\n1,1\n"
    << mat << eos << "*PART\ncube\n1,1,1,1\n*NODE\n";
  for (int k = 0; k <= 1; ++k)
    for (int j = 0; j <= 1; ++j)
      for (int i = 0; i <= 1; ++i) o << 1 + i + 2 * j + 4 * k << "," << i << "," << j << "," << k << "\n";
  o << "*ELEMENT_SOLID\n1,1,1,2,4,3,5,6,8,7\n"
    << "*SET_NODE_LIST\n1\n1,3,5,7\n*SET_NODE_LIST\n2\n1,2,5,6\n*SET_NODE_LIST\n3\n1,2,3,4\n"
    << "*SET_NODE_LIST\n4\n2,4,6,8\n*SET_NODE_LIST\n5\n3,4,7,8\n*SET_NODE_LIST\n6\n5,6,7,8\n"
    << "*BOUNDARY_SPC_SET\n1,0,1,0,0\n*BOUNDARY_SPC_SET\n2,0,0,1,0\n*BOUNDARY_SPC_SET\n3,0,0,0,1\n"
    << "*BOUNDARY_PRESCRIBED_MOTION_SET\n4,1,2,1\n*BOUNDARY_PRESCRIBED_MOTION_SET\n5,2,2,1\n"
    << "*BOUNDARY_PRESCRIBED_MOTION_SET\n6,3,2,1\n"
    << sq.curve(end_time) << "*END\n";
  return o.str();
}

std::string null_mat(Real pc = 0.0, Real mu = 0.0, Real terod = 0.0, Real cerod = 0.0) {
  std::ostringstream o;
  o << std::setprecision(17) << "*MAT_NULL\n1," << kRho << "," << pc << "," << mu << "," << terod << "," << cerod << "\n";
  return o.str();
}

/// A cube run's end state: J, the pressure, E (cell output), the energies, the deletion time.
struct CubeEnd {
  Real j = 0.0, p = 0.0, e = 0.0, deleted_at = -1.0;
  std::vector<Real> t;
  EnergyReport energy;
};

CubeEnd run_cube(const std::string& deck) {
  auto sim = build_simulation(read_keyword_string(deck, "cube.k"));
  CubeEnd r;
  while (sim->step()) r.t.push_back(sim->time());
  const Real side = sim->nodes().x.x[7];  // node 8 at (1, 1, 1)
  r.j = side * side * side;
  std::vector<CellOutput> cells(1);
  sim->blocks().at(0)->cell_outputs(sim->nodes(), cells);
  r.p = -(cells[0].stress[0] + cells[0].stress[1] + cells[0].stress[2]) / 3.0;
  r.e = cells[0].energy_density;
  if (const ElementErosion* er = std::as_const(*sim->blocks().at(0)).erosion(); er && !er->deletion_times().empty())
    r.deleted_at = er->deletion_times()[0];
  r.energy = sim->energy();
  return r;
}

const Squeeze kSlow{0.9, 100.0};

TEST(NullSolid, HydrostaticCubeGammaLawGasOnItsAdiabat) {
  const Real e0 = 2.5;
  const CubeEnd r = run_cube(cube(null_mat(), "*EOS_LINEAR_POLYNOMIAL\n1,0,0,0,0,0.4,0.4\n" + std::to_string(e0) + "\n",
                                  kSlow, 110.0));
  EXPECT_NEAR(r.j, 0.9, 1e-14);
  const Real p_eos = 0.4 * r.e / r.j;  // (C4 + C5 mu) E = 0.4 E / J
  std::printf("gamma law: p %.12g, EOS at E %.12g; E %.10g, adiabat %.10g (rel %.2e)\n", r.p, p_eos, r.e,
              e0 * std::pow(r.j, -0.4), r.e / (e0 * std::pow(r.j, -0.4)) - 1.0);
  EXPECT_NEAR(r.p, p_eos, 1e-10 * r.p);
  EXPECT_NEAR(r.e, e0 * std::pow(r.j, -0.4), 1e-5 * (r.e - e0));
  EXPECT_NEAR(r.energy.internal + r.energy.bulk_viscosity, r.e - e0, 1e-3 * (r.e - e0));
}

TEST(NullSolid, HydrostaticCubeEachEquationOfState) {
  const Real mu = 1.0 / 0.9 - 1.0;
  {  // Linear polynomial without E: p and E in closed form.
    const Real c1 = 2.0, c2 = 5.0, c3 = -1.0;
    const CubeEnd r = run_cube(cube(null_mat(), "*EOS_LINEAR_POLYNOMIAL\n1,0,2.0,5.0,-1.0\n", kSlow, 110.0));
    const auto F = [&](Real j) {
      return c1 * (std::log(j) - j) + c2 * (-1.0 / j - 2.0 * std::log(j) + j) +
             c3 * (-0.5 / (j * j) + 3.0 / j + 3.0 * std::log(j) - j);
    };
    std::printf("polynomial: p %.12g (closed form %.12g), E %.10g (closed form %.10g); internal %.10g, bulk "
                "viscosity %.4g, hourglass %.4g\n",
                r.p, c1 * mu + c2 * mu * mu + c3 * mu * mu * mu, r.e, F(1.0) - F(0.9), r.energy.internal,
                r.energy.bulk_viscosity, r.energy.hourglass);
    EXPECT_NEAR(r.p, c1 * mu + c2 * mu * mu + c3 * mu * mu * mu, 1e-10 * r.p);
    // E = the closed-form work + the bulk viscosity's heat (the ledger's, per unit V0 = 1).
    EXPECT_NEAR(r.e, F(1.0) - F(0.9) + r.energy.bulk_viscosity, 1e-7 * r.e);
    EXPECT_NEAR(r.energy.internal, F(1.0) - F(0.9), 1e-7 * r.e);
  }
  {  // Gruneisen (GAMAO = 2, A = 0.5): the compressed form at the law's E.
    const Real c = 40.0, s1 = 1.5, g0 = 2.0, a = 0.5;
    const CubeEnd r = run_cube(cube(null_mat(), "*EOS_GRUNEISEN\n1,40.0,1.5,0,0,2.0,0.5,0.01\n", kSlow, 110.0));
    const Real den = 1.0 - (s1 - 1.0) * mu;
    const Real p_eos = kRho * c * c * mu * (1.0 + (1.0 - g0 / 2) * mu - a / 2 * mu * mu) / (den * den) + (g0 + a * mu) * r.e;
    std::printf("gruneisen: p %.12g, EOS at E %.12g, E %.6g\n", r.p, p_eos, r.e);
    EXPECT_NEAR(r.p, p_eos, 1e-10 * r.p);
    EXPECT_NEAR(r.energy.internal + r.energy.bulk_viscosity, r.e - 0.01, 1e-3 * (r.e - 0.01));
  }
  {  // Tabulated: ln 0.9 = -0.10536 between EV4 = -0.1 and EV5 = -0.15.
    const CubeEnd r = run_cube(cube(null_mat(),
                                    "*EOS_TABULATED\n1,0.5,3.0\n"
                                    "0.1,0.0,-0.05,-0.1,-0.15\n-0.2,-0.25,-0.3,-0.4,-0.5\n"
                                    "-0.05,0.0,0.02,0.05,0.09\n0.14,0.2,0.27,0.45,0.7\n"
                                    "1.0,1.0,1.1,1.2,1.3\n1.4,1.5,1.6,1.7,1.8\n",
                                    kSlow, 110.0));
    const Real w = (std::log(r.j) + 0.1) / -0.05;
    const Real p_eos = 0.05 + 0.04 * w + 0.5 * (1.2 + 0.1 * w) * r.e;
    std::printf("tabulated: p %.12g, EOS at E %.12g, E %.6g\n", r.p, p_eos, r.e);
    EXPECT_NEAR(r.p, p_eos, 1e-10 * r.p);
    EXPECT_NEAR(r.energy.internal + r.energy.bulk_viscosity, r.e - 3.0, 1e-3 * (r.e - 3.0));
  }
}

TEST(NullSolid, RelativeVolumeErodesAndCutoffCapsTension) {
  const std::string eos = "*EOS_LINEAR_POLYNOMIAL\n1,0,2.0\n";
  const Squeeze push{0.85, 1.0}, pull{1.15, 1.0};
  for (const auto& [sq, mat, target] : {std::tuple{push, null_mat(0.0, 0.0, 0.0, 0.9), 0.9},
                                        std::tuple{pull, null_mat(-1.0, 0.0, 1.1, 0.0), 1.1}}) {
    const CubeEnd r = run_cube(cube(mat, eos, sq, 1.2));
    const Real t_expected = sq.time_of(target);
    Real dt = 0.0;
    for (std::size_t k = 1; k < r.t.size(); ++k)
      if (r.t[k] >= t_expected) {
        dt = r.t[k] - r.t[k - 1];
        break;
      }
    std::printf("J = %.2f: deleted at %.6f, closed form %.6f (step %.3g)\n", target, r.deleted_at, t_expected, dt);
    EXPECT_NEAR(r.deleted_at, t_expected, 1.5 * dt) << target;
    // Not before it (1e-4: the curve's displacement is linear between its 400 points, J = (1 + u)^3 not).
    EXPECT_GE(r.deleted_at, t_expected - 1e-4) << target;
    EXPECT_LT(std::abs(r.energy.balance_error()), 1e-3 * std::abs(r.energy.support)) << target;
  }
  // PC = -0.05: pulled to J = 1.1, where C1 mu = -0.18, the pressure stays at -0.05.
  const CubeEnd r = run_cube(cube(null_mat(-0.05), eos, Squeeze{1.1, 1.0}, 1.5));
  EXPECT_EQ(r.deleted_at, -1.0);
  EXPECT_NEAR(r.p, -0.05, 1e-14);
}

/// A column of `n` unit cubes along x (nodes 4 i + 1 .. 4 i + 4 at x = i), every node held in y
/// and z, the end x = 0 driven in x by the velocity curve `curve` (id 1).
std::string column(int n, const std::string& mat, const std::string& eos, const std::string& curve, Real end_time) {
  std::ostringstream o;
  o << std::setprecision(17) << "*KEYWORD\n*CONTROL_TERMINATION\n" << end_time << ",\n*SECTION_SOLID\n1,1\n"
    << mat << eos << "*PART\ncolumn\n1,1,1,1\n*NODE\n";
  const int yz[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int i = 0; i <= n; ++i)
    for (int q = 0; q < 4; ++q) o << 4 * i + q + 1 << "," << i << "," << yz[q][0] << "," << yz[q][1] << "\n";
  o << "*ELEMENT_SOLID\n";
  for (int i = 0; i < n; ++i) {
    o << i + 1 << ",1";
    for (int q = 0; q < 8; ++q) o << "," << 4 * (i + q / 4) + q % 4 + 1;
    o << "\n";
  }
  o << "*SET_NODE_LIST_GENERATE\n1\n1," << 4 * (n + 1) << "\n*SET_NODE_LIST\n2\n1,2,3,4\n"
    << "*BOUNDARY_SPC_SET\n1,0,0,1,1\n*BOUNDARY_PRESCRIBED_MOTION_SET\n2,1,0,1\n" << curve << "*END\n";
  return o.str();
}

/// Velocity curve: a half-cosine ramp to v over t_ramp, then held (`pulse` false), or a half-sine
/// pulse of height v and duration t_ramp, then 0.
std::string velocity(Real v, Real t_ramp, bool pulse) {
  std::ostringstream o;
  const Real pi = std::acos(-1.0);
  o << std::setprecision(17) << "*DEFINE_CURVE\n1\n";
  for (int i = 0; i <= 100; ++i) {
    const Real t = t_ramp * i / 100;
    o << t << "," << (pulse ? v * std::sin(pi * t / t_ramp) : v * 0.5 * (1.0 - std::cos(pi * t / t_ramp))) << "\n";
  }
  o << 10.0 << "," << (pulse ? 0.0 : v) << "\n";
  return o.str();
}

/// Runs the column; returns the x velocity histories of the nodes at x = `at` (first node of each
/// station) and the times.
struct ColumnRun {
  std::vector<Real> t;
  std::vector<std::vector<Real>> v;
  EnergyReport energy;
  /// sum m (v^{n+1/2} - v^{n-1/2})^2 / 8 of the last cycle: what the mean-velocity kinetic energy
  /// exceeds the conserved one by, the balance error of an exact ledger at a constant step
  /// (docs/solver.md, "The discrete energy identity").
  Real identity = 0.0;
};

ColumnRun run_column(const std::string& deck, const std::vector<int>& at) {
  auto sim = build_simulation(read_keyword_string(deck, "column.k"));
  ColumnRun r;
  r.v.resize(at.size());
  const NodalFields& nodes = sim->nodes();
  std::vector<Vec3> v_old(nodes.size());
  for (;;) {
    for (std::size_t i = 0; i < nodes.size(); ++i) v_old[i] = nodes.v.get(static_cast<Index>(i));
    if (!sim->step()) break;
    r.identity = 0.0;
    for (std::size_t i = 0; i < nodes.size(); ++i)
      r.identity += nodes.mass[i] * (nodes.v.get(static_cast<Index>(i)) - v_old[i]).squaredNorm() / 8.0;
    r.t.push_back(sim->time());
    for (std::size_t s = 0; s < at.size(); ++s) r.v[s].push_back(sim->nodes().v.x[static_cast<std::size_t>(4 * at[s])]);
  }
  r.energy = sim->energy();
  return r;
}

/// The time a history first reaches `level` (linear between steps).
Real crossing(const std::vector<Real>& t, const std::vector<Real>& v, Real level) {
  for (std::size_t k = 1; k < t.size(); ++k)
    if (v[k] >= level && v[k - 1] < level) return t[k - 1] + (t[k] - t[k - 1]) * (level - v[k - 1]) / (v[k] - v[k - 1]);
  return -1.0;
}

TEST(NullSolid, ColumnFrontTravelsAtTheSoundSpeed) {
  const Real k = 1.0e3, c = std::sqrt(k / kRho);  // 1000
  const ColumnRun r = run_column(column(100, null_mat(), "*EOS_LINEAR_POLYNOMIAL\n1,0," + std::to_string(k) + "\n",
                                        velocity(1.0, 2e-3, false), 0.07),
                                 {20, 40, 60});
  const Real t20 = crossing(r.t, r.v[0], 0.5), t40 = crossing(r.t, r.v[1], 0.5), t60 = crossing(r.t, r.v[2], 0.5);
  std::printf("front at x = 20, 40, 60: %.5f %.5f %.5f (closed form %.5f %.5f %.5f); speed %.2f, c = %.2f\n", t20,
              t40, t60, 20 / c + 1e-3, 40 / c + 1e-3, 60 / c + 1e-3, 40.0 / (t60 - t20), c);
  EXPECT_NEAR(40.0 / (t60 - t20), c, 0.01 * c);
  for (const auto& [t, x] : {std::pair{t20, 20.0}, std::pair{t40, 40.0}, std::pair{t60, 60.0}}) {
    std::printf("x = %.0f: arrival %.5f, x/c + t_ramp/2 = %.5f (%.2f%%, %.2f element transits)\n", x, t, x / c + 1e-3,
                100 * (t / (x / c + 1e-3) - 1), (t - x / c - 1e-3) * c);
    EXPECT_NEAR(t, x / c + 1e-3, 1.0 / c) << x;  // + half the ramp; within one element transit
  }
  const EnergyReport& en = r.energy;
  std::printf("kinetic %.6g, internal %.6g, bulk viscosity %.4g, hourglass %.3g, support %.6g, balance error %.3g\n",
              en.kinetic, en.internal, en.bulk_viscosity, en.hourglass, en.support, en.balance_error());
  EXPECT_LT(std::abs(r.energy.balance_error()), 1e-3 * r.energy.support);
}

TEST(NullSolid, ColumnViscosityDampsAPulse) {
  const std::string eos = "*EOS_LINEAR_POLYNOMIAL\n1,0,1000.0\n";
  Real ratio[2] = {0.0, 0.0};
  // The same column of *MAT_ELASTIC (nu = 0: its uniaxial-strain modulus is E = K): the balance
  // error of the driven pulse is the prescribed motion's (the work at the driven end), not the law's.
  std::string elastic = column(100, "*MAT_ELASTIC\n1,1e-3,1000.0,0.0\n", "", velocity(1.0, 0.01, true), 0.07);
  elastic.replace(elastic.find("1,1,1,1\n*NODE"), 8, "1,1,1\n");
  const Real elastic_error = run_column(elastic, {10}).energy.balance_error();
  for (int m = 0; m < 2; ++m) {
    const ColumnRun r = run_column(column(100, null_mat(-100.0, m ? 0.2 : 0.0), eos, velocity(1.0, 0.01, true), 0.07),
                                   {10, 50});
    const Real p10 = *std::max_element(r.v[0].begin(), r.v[0].end());
    const Real p50 = *std::max_element(r.v[1].begin(), r.v[1].end());
    ratio[m] = p50 / p10;
    const EnergyReport& en = r.energy;
    std::printf("MU = %.1f: kinetic %.6g, internal %.6g, bulk viscosity %.4g, hourglass %.3g, support %.6g, balance error "
                "%.3g (the identity's term %.3g)\n", m ? 0.2 : 0.0, en.kinetic, en.internal, en.bulk_viscosity,
                en.hourglass, en.support, en.balance_error(), r.identity);
    if (m == 0) {
      std::printf("the elastic column's balance error: %.3g\n", elastic_error);
      EXPECT_NEAR(en.balance_error(), elastic_error, 0.05 * std::abs(elastic_error));
    } else {
      // The viscous law's work is all booked: the balance is the central difference's own term.
      EXPECT_LT(std::abs(en.balance_error() - r.identity), 1e-4 * en.support);
    }
  }
  // A plane wave of angular frequency w in a viscous medium decays as exp(-alpha x),
  // alpha = w^2 (4/3 MU) / (2 rho c^3): for the pulse's w = pi / 0.01 about 0.013 per unit length,
  // exp(-0.53) over the 40 between the stations.
  std::printf("pulse height x = 50 / x = 10: MU = 0: %.4f, MU = 0.2: %.4f (plane-wave estimate %.3f)\n", ratio[0],
              ratio[1], std::exp(-0.53));
  EXPECT_GT(ratio[0], 0.9);            // the mesh's dispersion and the bulk viscosity alone
  EXPECT_LT(ratio[1] / ratio[0], 0.8);  // MU: measured 0.72 against the plane-wave 0.59
  EXPECT_GT(ratio[1], 0.4);
}

}  // namespace
}  // namespace slideline
