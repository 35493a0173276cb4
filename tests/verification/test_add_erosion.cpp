// *MAT_ADD_EROSION (stress, pressure, strain and time thresholds, NCS, EXCL, NUMFIP) and TDEL of
// *MAT_PIECEWISE_LINEAR_PLASTICITY (element/erosion_criteria.hpp; docs/solver.md, "Failure and
// erosion"), against closed forms.
//
// One unit cube of *MAT_ELASTIC with nu = 0 (St. Venant-Kirchhoff: lambda = 0, so uniaxial stress
// leaves the lateral stretches at 1) pulled or pushed along x by the stretch L(t): the Cauchy
// stress is sigma = E L (L^2 - 1) / 2, the pressure -sigma / 3, the von Mises stress and (in
// tension) the largest principal stress |sigma|, the strain energy E/2 ((L^2 - 1) / 2)^2 per unit
// reference volume. A threshold s is met at the L solving sigma(L) = s, i.e. at the time the
// prescribed end displacement reaches L - 1. A Belytschko-Tsay shell strip (nu = 0, hypoelastic
// in its co-rotational frame) in membrane tension has sigma = E ln L and, its thickness t staying
// constant, holds the work t E (L ln L - L + 1) per unit reference area.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "slideline/io/keyword_reader.hpp"
#include "test_support/kuhn_tets.hpp"
#include "slideline/solver/build.hpp"
#include "slideline/solver/simulation.hpp"

namespace slideline {
namespace {

constexpr Real kE = 1000.0, kRho = 1e-5;

/// The end displacement: the velocity ramps from 0 to v along a half cosine over [0, t_ramp],
/// then holds (as tests/verification/test_erosion.cpp).
struct Pull {
  Real v, t_ramp;
  Real at(Real t) const {
    const Real pi = std::acos(-1.0);
    if (t >= t_ramp) return v * (t - 0.5 * t_ramp);
    return 0.5 * v * (t - t_ramp / pi * std::sin(pi * t / t_ramp));
  }
  /// The time u reaches `d` after the ramp.
  Real time_of(Real d) const { return d / v + 0.5 * t_ramp; }
  std::string curve(Real t_end) const {
    std::ostringstream o;
    o << std::setprecision(17) << "*DEFINE_CURVE\n1\n";
    for (int i = 0; i <= 100; ++i) o << t_ramp * i / 100 << "," << at(t_ramp * i / 100) << "\n";
    o << t_end << "," << at(t_end) << "\n";
    return o.str();
  }
};

/// Cauchy stress of the nu = 0 St. Venant-Kirchhoff cube at stretch L, and the stretch at which
/// it equals s (Newton from L = 1; sigma is increasing in L).
Real svk_stress(Real L) { return kE * L * (L * L - 1.0) / 2.0; }
Real svk_stretch(Real s) {
  Real L = 1.0;
  for (int i = 0; i < 50; ++i) L -= (svk_stress(L) - s) / (kE * (3.0 * L * L - 1.0) / 2.0);
  return L;
}
Real svk_energy(Real L) {
  const Real e = (L * L - 1.0) / 2.0;
  return 0.5 * kE * e * e;
}

/// One unit cube (nodes 1-8), material `mat` (its MID 1, part 1) and the cards `extra`; x = 0
/// held in x, and y = 0 in y, z = 0 in z (uniaxial stress) or every node in y and z (`lateral`:
/// uniaxial strain); the face x = 1 moved by `pull`. `elform` 1 or 2: one hexahedron of that
/// form; 10: six tetrahedra (tests/test_support/kuhn_tets.hpp).
std::string cube(const std::string& mat, const std::string& extra, const Pull& pull, Real end_time,
                 bool lateral = false, int elform = 1) {
  std::ostringstream o;
  o << std::setprecision(17) << "*KEYWORD\n*CONTROL_TERMINATION\n" << end_time << ",\n*SECTION_SOLID\n1," << elform
    << "\n" << mat << extra << "*PART\ncube\n1,1,1\n*NODE\n";
  for (int k = 0; k <= 1; ++k)
    for (int j = 0; j <= 1; ++j)
      for (int i = 0; i <= 1; ++i) o << 1 + i + 2 * j + 4 * k << "," << i << "," << j << "," << k << "\n";
  o << "*ELEMENT_SOLID\n";
  if (elform == 10) {
    for (int t = 0; t < 6; ++t) {
      const auto tet = test_support::kuhn_tets()[static_cast<std::size_t>(t)];
      o << t + 1 << ",1," << tet[0] + 1 << "," << tet[1] + 1 << "," << tet[2] + 1;
      for (int r = 0; r < 5; ++r) o << "," << tet[3] + 1;
      o << "\n";
    }
  } else {
    o << "1,1,1,2,4,3,5,6,8,7\n";
  }
  o << "*SET_NODE_LIST\n1\n1,3,5,7\n*SET_NODE_LIST\n2\n"
    << (lateral ? "1,2,3,4,5,6,7,8" : "1,2,5,6") << "\n*SET_NODE_LIST\n3\n" << (lateral ? "1,2,3,4,5,6,7,8" : "1,2,3,4")
    << "\n*SET_NODE_LIST\n4\n2,4,6,8\n*BOUNDARY_SPC_SET\n1,0,1,0,0\n*BOUNDARY_SPC_SET\n2,0,0,1,0\n"
    << "*BOUNDARY_SPC_SET\n3,0,0,0,1\n*BOUNDARY_PRESCRIBED_MOTION_SET\n4,1,2,1\n"
    << pull.curve(1.0) << "*END\n";
  return o.str();
}

std::string elastic() {
  std::ostringstream o;
  o << std::setprecision(17) << "*MAT_ELASTIC\n1," << kRho << "," << kE << ",0.0\n";
  return o.str();
}

/// *MAT_ADD_EROSION for material 1 from its two cards.
std::string add_erosion(const std::string& card1, const std::string& card2) {
  return "*MAT_ADD_EROSION\n" + card1 + "\n" + card2 + "\n";
}

/// A run's x reaction on the held face per step, the step ends and sizes, the element's
/// deletion time, the energies.
struct CubeRun {
  std::vector<Real> t, dt, reaction;
  Real deleted_at = -1.0;
  EnergyReport energy;
  /// The last step that ends at or before time `td` (before a deletion: once the cube is gone,
  /// nothing bounds the step).
  Real step_at(Real td) const {
    std::size_t k = 0;
    while (k + 1 < t.size() && t[k + 1] <= td) ++k;
    return dt[k];
  }
  /// The step that judges a deletion expected at `t_expected`: the last one before it or before
  /// the deletion, whichever comes first.
  Real judging_step(Real t_expected) const {
    return step_at(deleted_at >= 0.0 ? std::min(t_expected, deleted_at) : t_expected);
  }
  /// Index of the first step that starts at or after `td`.
  std::size_t first_step_after(Real td) const {
    std::size_t k = 0;
    while (k < t.size() && t[k] <= td) ++k;
    return k;
  }
};

CubeRun run(const std::string& text, const char* held) {
  auto sim = build_simulation(read_keyword_string(text, "cube.k"));
  const SupportGroup* group = nullptr;
  for (const auto& g : sim->supports())
    if (g.name == held) group = &g;
  EXPECT_NE(group, nullptr) << held;
  CubeRun r;
  bool more = true;
  while (more) {
    more = sim->step();
    r.dt.push_back(sim->time() - (r.t.empty() ? 0.0 : r.t.back()));
    r.t.push_back(sim->time());
    r.reaction.push_back(group ? group->reaction.x() : 0.0);
  }
  const ElementErosion* er = std::as_const(*sim->blocks().at(0)).erosion();
  EXPECT_NE(er, nullptr);
  if (er) r.deleted_at = er->deletion_times()[0];
  r.energy = sim->energy();
  return r;
}

/// Runs the cube with `add` under `pull`, expecting deletion within one step of `t_expected`;
/// returns the run.
CubeRun expect_deleted_at(const std::string& add, const Pull& pull, Real t_expected, const char* what,
                      bool lateral = false, int elform = 1) {
  const CubeRun r = run(cube(elastic(), add, pull, t_expected + 0.01, lateral, elform), "spc_1");
  const Real dt = r.judging_step(t_expected);
  std::printf("%s: deleted at t = %.7f, closed form %.7f (%.2f steps of %.3g)\n", what, r.deleted_at, t_expected,
              (r.deleted_at - t_expected) / dt, dt);
  EXPECT_GE(r.deleted_at, 0.0) << what;
  EXPECT_NEAR(r.deleted_at, t_expected, dt) << what;
  return r;
}

}  // namespace

// SIGVM on the cube pulled in tension: deleted within a step of the time sigma(L) = SIGVM; the
// reaction is SIGVM (times the unit section) just before and exactly 0 from the deleting
// evaluation on; the eroded energy is the strain energy at L; the balance closes.
TEST(AddErosion, VonMisesDeletesTheCubeAtTheClosedFormStretch) {
  const Pull pull{0.1, 0.05};
  const Real s = 20.0, L = svk_stretch(s);
  const CubeRun r = expect_deleted_at(add_erosion("1", ",,20.0"), pull, pull.time_of(L - 1.0), "SIGVM 20");
  const std::size_t k = r.first_step_after(r.deleted_at);
  ASSERT_GT(k, 1u);
  ASSERT_LT(k + 1, r.t.size());
  std::printf("reaction before %.6g (closed form %.6g)\n", r.reaction[k - 1], -s);
  EXPECT_NEAR(std::abs(r.reaction[k - 1]), s, 0.005 * s);
  for (std::size_t j = k; j < r.t.size(); ++j) ASSERT_EQ(r.reaction[j], 0.0) << "t = " << r.t[j];
  const Real w = svk_energy(L);
  std::printf("eroded %.7g, closed form %.7g (rel %.2e); internal left %.3g; balance error %.3g\n", r.energy.eroded(), w,
              r.energy.eroded() / w - 1.0, r.energy.internal, r.energy.balance_error());
  EXPECT_NEAR(r.energy.eroded(), w, 0.01 * w);
  EXPECT_NEAR(r.energy.internal, 0.0, 1e-3 * w);
  EXPECT_LT(std::abs(r.energy.balance_error()), 1e-3 * w);
}

// SIGP1 in tension (sigma = SIGP1), MNPRES in tension (pressure -sigma/3 <= MNPRES, so sigma =
// -3 MNPRES) and MXPRES in compression (pressure >= MXPRES: sigma = -3 MXPRES, the cube pushed).
// A threshold of the other sign never holds on the way: MXPRES in tension, SIGP1 in compression.
TEST(AddErosion, PrincipalStressAndPressureThresholds) {
  const Pull pull{0.1, 0.05}, push{-0.1, 0.05};
  expect_deleted_at(add_erosion("1", ",15.0"), pull, pull.time_of(svk_stretch(15.0) - 1.0), "SIGP1 15");
  expect_deleted_at(add_erosion("1", "-5.0"), pull, pull.time_of(svk_stretch(15.0) - 1.0), "MNPRES -5");
  expect_deleted_at(add_erosion("1,,5.0", ""), push, push.time_of(svk_stretch(-15.0) - 1.0), "MXPRES 5");
  // The other signs: nothing deleted within the same time.
  const Real t_end = pull.time_of(svk_stretch(15.0) - 1.0) + 0.02;
  EXPECT_LT(run(cube(elastic(), add_erosion("1,,5.0", ""), pull, t_end), "spc_1").deleted_at, 0.0);
  EXPECT_LT(run(cube(elastic(), add_erosion("1", ",15.0"), push, t_end), "spc_1").deleted_at, 0.0);
}

// FAILTM alone: deleted at the first evaluation at or after it. NCS = 2 with SIGVM and FAILTM:
// deleted when both hold, i.e. at the later of the two times, either way round.
TEST(AddErosion, FailureTimeAndTwoCriteriaAtOnce) {
  const Pull pull{0.1, 0.05};
  const CubeRun r = expect_deleted_at(add_erosion("1", ",,,,,,,0.1"), pull, 0.1, "FAILTM 0.1");
  EXPECT_GE(r.deleted_at, 0.1);
  const Real t_vm = pull.time_of(svk_stretch(20.0) - 1.0);  // about 0.223
  expect_deleted_at(add_erosion("1,,,,,,,2", ",,20.0,,,,,0.3"), pull, 0.3, "NCS 2: SIGVM then FAILTM 0.3");
  expect_deleted_at(add_erosion("1,,,,,,,2", ",,20.0,,,,,0.1"), pull, t_vm, "NCS 2: FAILTM 0.1 then SIGVM");
  // NCS 1 with the same two: the earlier.
  expect_deleted_at(add_erosion("1", ",,20.0,,,,,0.1"), pull, 0.1, "NCS 1: FAILTM 0.1 first");
}

// EXCL = 7.5: every field equal to it is excluded, SIGVM alone acts. Without EXCL, MNPRES = 7.5
// (pressure <= 7.5 holds at rest) deletes the cube at its first evaluation.
TEST(AddErosion, ExclusionNumber) {
  const Pull pull{0.1, 0.05};
  expect_deleted_at(add_erosion("1,7.5,7.5,7.5,7.5,7.5", "7.5,7.5,20.0,7.5,7.5,7.5,7.5,7.5"), pull,
                    pull.time_of(svk_stretch(20.0) - 1.0), "EXCL 7.5, SIGVM 20");
  const CubeRun r = run(cube(elastic(), add_erosion("1", "7.5,,20.0"), pull, 0.05), "spc_1");
  EXPECT_EQ(r.deleted_at, 0.0);
}

// The strain criteria (principal logarithmic strains, erosion_criteria.hpp) on the nu = 0 cube,
// whose F is diag(L, 1, 1): strains (ln L, 0, 0). MXEPS is met at ln L = MXEPS; EFFEPS at
// (2/3) ln L = EFFEPS (the uniaxial (2/3)(1 + nu) eps, nu = 0); VOLEPS > 0 at ln J = ln L = VOLEPS,
// VOLEPS < 0 pushed at ln L = VOLEPS; MNEPS pushed at ln L = MNEPS; EPSSH at (e1 - e3)/2 = |ln L|/2
// pulled and pushed. Pushed, the bulk viscosity q = rho h (Q1 h trD^2 + Q2 c |trD|) (h = L the
// characteristic length, trD = v / L, LS-DYNA's Q1 = 1.5, Q2 = 0.06) is a pressure that stretches
// the free lateral faces by q / E (nu = 0; 6e-7 here, seen in the nodes), so ln J = ln L + 2 q / E
// and (e1 - e3)/2 = (q / E - ln L)/2: the closed forms for VOLEPS < 0 and EPSSH pushed include it
// (0.15 and 0.04 steps). A threshold of the other sign never holds on the way. MXEPS's run also
// books the strain energy at L as eroded and closes the balance.
TEST(AddErosion, StrainThresholds) {
  const Pull pull{0.1, 0.05}, push{-0.1, 0.05};
  const auto at = [](const Pull& p, Real ln_l) { return p.time_of(std::exp(ln_l) - 1.0); };
  const CubeRun r = expect_deleted_at(add_erosion("1", ",,,0.02"), pull, at(pull, 0.02), "MXEPS 0.02");
  const Real w = svk_energy(std::exp(0.02));
  std::printf("eroded %.7g, closed form %.7g (rel %.2e); balance error %.3g\n", r.energy.eroded(), w,
              r.energy.eroded() / w - 1.0, r.energy.balance_error());
  EXPECT_NEAR(r.energy.eroded(), w, 0.01 * w);
  EXPECT_LT(std::abs(r.energy.balance_error()), 1e-3 * w);
  expect_deleted_at(add_erosion("1,,,,0.02", ""), pull, at(pull, 0.03), "EFFEPS 0.02");
  expect_deleted_at(add_erosion("1,,,,,0.025", ""), pull, at(pull, 0.025), "VOLEPS 0.025");
  // The lateral strain q / E of the pushed cube at ln L (after the ramp, |v| = 0.1).
  const auto lateral = [](Real ln_l) {
    const Real h = std::exp(ln_l), trd = 0.1 / h, c = std::sqrt(kE / kRho);
    return kRho * h * (1.5 * h * trd * trd + 0.06 * c * trd) / kE;
  };
  expect_deleted_at(add_erosion("1,,,,,-0.025", ""), push, at(push, -0.025 - 2.0 * lateral(-0.025)), "VOLEPS -0.025");
  expect_deleted_at(add_erosion("1,,,-0.02", ""), push, at(push, -0.02), "MNEPS -0.02");
  expect_deleted_at(add_erosion("1", ",,,,0.01"), pull, at(pull, 0.02), "EPSSH 0.01 pulled");
  expect_deleted_at(add_erosion("1", ",,,,0.01"), push, at(push, -0.02 + lateral(-0.02)), "EPSSH 0.01 pushed");
  const Real t_end = at(pull, 0.03) + 0.02;
  EXPECT_LT(run(cube(elastic(), add_erosion("1", ",,,0.02"), push, t_end), "spc_1").deleted_at, 0.0);
  EXPECT_LT(run(cube(elastic(), add_erosion("1,,,,,0.025", ""), push, t_end), "spc_1").deleted_at, 0.0);
  EXPECT_LT(run(cube(elastic(), add_erosion("1,,,-0.02", ""), pull, t_end), "spc_1").deleted_at, 0.0);
}

// The thresholds on the other solid forms, the same cube and closed forms: one fully integrated
// hexahedron (ELFORM 2: its 8 Gauss points judged, NUMFIP of them must fail) and six tetrahedra
// (ELFORM 10, one point each). The state is uniform, so every point fails at once: NUMFIP = 8
// deletes the hexahedron at the same time as NUMFIP = 1 (8 of 8 points), and the eroded energy is
// the strain energy of the whole cube at L whatever the form.
TEST(AddErosion, FullyIntegratedHexahedronAndTetrahedra) {
  const Pull pull{0.1, 0.05};
  const Real L_vm = svk_stretch(20.0), L_eps = std::exp(0.02);
  for (int elform : {2, 10}) {
    const std::string form = "ELFORM " + std::to_string(elform);
    CubeRun r = expect_deleted_at(add_erosion("1", ",,20.0"), pull, pull.time_of(L_vm - 1.0),
                                  (form + ": SIGVM 20").c_str(), false, elform);
    const Real w = svk_energy(L_vm);
    std::printf("%s: eroded %.7g, closed form %.7g (rel %.2e); balance error %.3g\n", form.c_str(), r.energy.eroded(),
                w, r.energy.eroded() / w - 1.0, r.energy.balance_error());
    EXPECT_NEAR(r.energy.eroded(), w, 0.01 * w) << form;
    EXPECT_NEAR(r.energy.internal, 0.0, 1e-3 * w) << form;
    EXPECT_LT(std::abs(r.energy.balance_error()), 1e-3 * w) << form;
    expect_deleted_at(add_erosion("1", ",,,0.02"), pull, pull.time_of(L_eps - 1.0), (form + ": MXEPS 0.02").c_str(),
                      false, elform);
  }
  expect_deleted_at(add_erosion("1,,,,,,8", ",,20.0"), pull, pull.time_of(L_vm - 1.0), "ELFORM 2: SIGVM 20, NUMFIP 8",
                    false, 2);
  expect_deleted_at(add_erosion("1,,,,,,-100", ",,20.0"), pull, pull.time_of(L_vm - 1.0),
                    "ELFORM 2: SIGVM 20, NUMFIP -100 (every point)", false, 2);
  // A threshold of the other sign never holds: the hexahedron pushed past the same stretch stays.
  const Pull push{-0.1, 0.05};
  EXPECT_LT(run(cube(elastic(), add_erosion("1", ",,,0.02"), push, pull.time_of(L_eps - 1.0) + 0.02, false, 2), "spc_1")
                .deleted_at,
            0.0);
}

// TDEL of *MAT_PIECEWISE_LINEAR_PLASTICITY (SIGY far above the stress: elastic) on the cube
// crushed in uniaxial strain at the speed v: its step is h / (q + sqrt(q^2 + c^2)) with h = 1 - u
// its height (volume over largest face), c = sqrt(E/rho) (nu = 0) and the bulk viscosity term
// q = 0.06 c + 1.5 v (LS-DYNA's defaults: Q2 c + Q1 h |tr D|, tr D = -v/h), so it is deleted
// when h = TDEL (q + sqrt(q^2 + c^2)).
TEST(AddErosion, TdelDeletesACrushedCube) {
  const Pull push{-2.0, 0.01};
  const Real c = std::sqrt(kE / kRho), q = 0.06 * c + 1.5 * 2.0;
  const Real tdel = 0.7 / (q + std::sqrt(q * q + c * c));  // at h = 0.7
  std::ostringstream mat;
  mat << std::setprecision(17) << "*MAT_PIECEWISE_LINEAR_PLASTICITY\n1," << kRho << "," << kE << ",0.0,1e20,,,"
      << tdel << "\n\n\n\n";
  const Real t_expected = push.time_of(-0.3);
  const CubeRun r = run(cube(mat.str(), "", push, t_expected + 0.01, true), "spc_1");
  const Real dt = r.judging_step(t_expected);
  std::printf("TDEL %.4g: deleted at t = %.7f, closed form %.7f (%.2f steps of %.3g)\n", tdel, r.deleted_at, t_expected,
              (r.deleted_at - t_expected) / dt, dt);
  EXPECT_NEAR(r.deleted_at, t_expected, dt);
  for (std::size_t j = r.first_step_after(r.deleted_at); j < r.t.size(); ++j) ASSERT_EQ(r.reaction[j], 0.0);
  EXPECT_LT(std::abs(r.energy.balance_error()), 1e-3 * r.energy.eroded());
}

// ERODE = 1 of *CONTROL_TIMESTEP with DTMIN of *CONTROL_TERMINATION: the elastic cube crushed in
// uniaxial strain as above (its step h / (q + sqrt(q^2 + c^2)), q = 0.06 c + 1.5 v) is deleted when
// TSSFAC (0.9) times its step falls below TSMIN = DTMIN x the first step dt0 (the cube at rest, q =
// 0), i.e. at h = DTMIN dt0 / 0.9 (q + sqrt(q^2 + c^2)); the run goes on to its end time, the
// reaction is 0 from then on and the balance closes. Without ERODE the same deck stops there.
TEST(AddErosion, ErodeDeletesASolidBelowTsmin) {
  const Pull push{-2.0, 0.01};
  const Real c = std::sqrt(kE / kRho), q = 0.06 * c + 1.5 * 2.0;
  const Real dtmin = 0.7 * c / (q + std::sqrt(q * q + c * c));  // h near 0.7 for dt0 = 0.9 / c
  const Real t_end = push.time_of(-0.3) + 0.01;
  const auto deck = [&](int erode) {
    std::string d = cube(elastic(), "", push, t_end, true);
    std::ostringstream o;
    o << std::setprecision(17) << ",0," << dtmin << "\n*CONTROL_TIMESTEP\n,,,,,," << erode << "\n*SECTION_SOLID";
    const std::size_t at = d.find(",\n*SECTION_SOLID");
    return d.replace(at, std::string(",\n*SECTION_SOLID").size(), o.str());
  };
  const CubeRun r = run(deck(1), "spc_1");
  const Real h = dtmin * r.dt[0] / 0.9 * (q + std::sqrt(q * q + c * c));
  const Real t_expected = push.time_of(h - 1.0);
  const Real dt = r.judging_step(t_expected);
  std::printf("ERODE: first step %.6g (0.9/c = %.6g); deleted at t = %.7f, closed form %.7f (h = %.4f; %.2f steps of "
              "%.3g); run ended at %.4f of %.4f\n",
              r.dt[0], 0.9 / c, r.deleted_at, t_expected, h, (r.deleted_at - t_expected) / dt, dt, r.t.back(), t_end);
  EXPECT_NEAR(r.deleted_at, t_expected, dt);
  EXPECT_NEAR(r.t.back(), t_end, 1e-9);
  for (std::size_t j = r.first_step_after(r.deleted_at); j < r.t.size(); ++j) ASSERT_EQ(r.reaction[j], 0.0);
  EXPECT_LT(std::abs(r.energy.balance_error()), 1e-3 * r.energy.eroded());
  // ERODE = 0: the run stops when the step falls below TSMIN.
  try {
    run(deck(0), "spc_1");
    ADD_FAILURE() << "ERODE 0: the run did not stop";
  } catch (const InstabilityError& e) {
    EXPECT_NE(std::string(e.what()).find("fell below"), std::string::npos) << e.what();
  }
}

}  // namespace slideline
