// The shell thickness change of *CONTROL_SHELL ISTUPD and the strain criteria of *MAT_ADD_EROSION
// on shells (docs/solver.md, "Shell thickness change" and "Failure and erosion"), from decks: a
// 1 x 1 strip (one Belytschko-Tsay shell, thickness t0 = 0.1) pulled along x at the speed v after a
// half-cosine ramp, its width free, so that it is in uniaxial stress (quasi-static: v / c ~ 1e-4).
// Logarithmic strains: eps = ln L (L the length), ln W (W the width).
//  - Elastic: d eps_zz = -nu / (1 - nu) (d eps_xx + d eps_yy), so t / t0 = exp(-nu / (1 - nu) (ln L
//    + ln W)) exactly for the element, and in uniaxial stress (ln W = -nu ln L) t / t0 = exp(-nu ln L).
//  - Elastic-plastic (J2, plastic flow at constant volume): ln(L W t / t0) = (1 - 2 nu) sigma / E, and
//    in uniaxial stress t / t0 = exp(-nu sigma / E - eps_p / 2), eps_p the effective plastic strain;
//    ISTUPD = 4 (the plastic part alone) exp(-eps_p / 2). The force is sigma W t: the thinned section.
//  - Strain erosion (nu = 0: strains (ln L, 0, 0)): MXEPS at ln L = MXEPS, EFFEPS at 2/3 ln L =
//    EFFEPS; nu = 0.3: strains (ln L, -nu ln L, -nu ln L), EFFEPS at 2/3 (1 + nu) ln L.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "slideline/element/element_block.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/solver/build.hpp"
#include "slideline/solver/simulation.hpp"

namespace slideline {
namespace {

/// The strip deck: material card `mat` (MID 1), `extra` cards, pulled at v after t_ramp to end_time.
std::string strip(const std::string& mat, const std::string& extra, Real v, Real t_ramp, Real end_time) {
  std::ostringstream o;
  o << std::setprecision(17) << "*KEYWORD\n*CONTROL_TERMINATION\n" << end_time
    << ",\n*SECTION_SHELL\n1,2,1.0,3\n0.1,0.1,0.1,0.1\n" << mat << extra
    << "*PART\nstrip\n1,1,1\n*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n*ELEMENT_SHELL\n1,1,1,2,3,4\n"
    << "*BOUNDARY_SPC_NODE\n1,0,1,1,1,1,1,1\n*BOUNDARY_SPC_NODE\n4,0,1,0,1,1,1,1\n*BOUNDARY_SPC_NODE\n"
    << "2,0,0,0,1,1,1,1\n*BOUNDARY_SPC_NODE\n3,0,0,0,1,1,1,1\n*SET_NODE_LIST\n4\n2,3\n"
    << "*BOUNDARY_PRESCRIBED_MOTION_SET\n4,1,2,1\n*DEFINE_CURVE\n1\n";
  const Real pi = std::acos(-1.0);
  for (int i = 0; i <= 100; ++i) {
    const Real t = t_ramp * i / 100;
    o << t << "," << 0.5 * v * (t - t_ramp / pi * std::sin(pi * t / t_ramp)) << "\n";
  }
  o << 10.0 << "," << v * (10.0 - 0.5 * t_ramp) << "\n*END\n";
  return o.str();
}

std::string elastic(Real rho, Real e, Real nu) {
  std::ostringstream o;
  o << std::setprecision(17) << "*MAT_ELASTIC\n1," << rho << "," << e << "," << nu << "\n";
  return o.str();
}

/// The strip at its end: length, mean width of its two ends, area, thickness, x reaction
/// (supports at x = 0: its magnitude), the element's global stress xx, yy and plastic strain.
struct StripEnd {
  Real length = 0.0, width = 0.0, area = 0.0, thickness = 0.0, force = 0.0, sigma = 0.0, sigma_yy = 0.0, eps_p = 0.0;
};

StripEnd run_strip(const std::string& deck) {
  auto sim = build_simulation(read_keyword_string(deck, "strip.k"));
  while (sim->step()) {
  }
  StripEnd out;
  const NodalFields& n = sim->nodes();
  out.length = n.x.x[1];
  out.width = 0.5 * (n.x.y[2] - n.x.y[1] + n.x.y[3] - n.x.y[0]);
  for (Index k = 0; k < 4; ++k)  // shoelace (the strip stays in z = 0)
    out.area += 0.5 * (n.x.x[k] * n.x.y[(k + 1) % 4] - n.x.x[(k + 1) % 4] * n.x.y[k]);
  const ElementBlock& b = *sim->blocks().at(0);
  out.thickness = b.current_thickness().empty() ? 0.1 : b.current_thickness()[0];
  for (const auto& g : sim->supports())
    if (g.name == "spc_node_1" || g.name == "spc_node_4") out.force += g.reaction.x();
  std::vector<CellOutput> c(1);
  b.cell_outputs(n, c);
  out.force = std::abs(out.force);
  out.sigma = c[0].stress[0];
  out.sigma_yy = c[0].stress[1];
  out.eps_p = c[0].plastic_strain;
  return out;
}

}  // namespace

// Elastic strip (E = 1e4, nu = 0.3) pulled to L = 1.02 with ISTUPD = 1: the element's thickness is
// (A / A0)^(-nu / (1 - nu)) (A its area: the one-point rate d_xx + d_yy is d ln A / dt exactly) to
// 1e-9, and the uniaxial exp(-nu ln L) to 1e-6 (the measured ends' width lags L^-nu by 2e-5 in the
// run: the strip's in-plane modes; the element's mean strain does not); the force is sigma W t with
// t the current thickness (W the mean width; it differs from sigma W t0 by nu ln L = 0.6 %).
TEST(ShellThickness, ElasticStripThinsAsExpMinusNuEps) {
  const Real nu = 0.3, v = 0.1, t_ramp = 0.05;
  const std::string deck =
      strip(elastic(1e-3, 1e4, nu), "*CONTROL_SHELL\n0,0,0,1\n", v, t_ramp, 0.02 / v + 0.5 * t_ramp);
  const StripEnd r = run_strip(deck);
  const Real ln_l = std::log(r.length);
  const Real pointwise = 0.1 * std::pow(r.area, -nu / (1.0 - nu)), uniaxial = 0.1 * std::exp(-nu * ln_l);
  const Real sigma = r.sigma;
  std::printf("L %.8f W %.8f (L^-nu %.8f): t %.10g, element closed form %.10g (rel %.2e), uniaxial %.10g (rel %.2e)\n",
              r.length, r.width, std::pow(r.length, -nu), r.thickness, pointwise, r.thickness / pointwise - 1.0,
              uniaxial, r.thickness / uniaxial - 1.0);
  std::printf("force %.8g, sigma W t %.8g (rel %.2e), sigma W t0 %.8g (rel %.2e); stress %.8g, E ln L %.8g\n",
              r.force, sigma * r.width * r.thickness, r.force / (sigma * r.width * r.thickness) - 1.0,
              sigma * r.width * 0.1, r.force / (sigma * r.width * 0.1) - 1.0, r.sigma, 1e4 * ln_l);
  EXPECT_NEAR(r.thickness / pointwise, 1.0, 1e-9);
  EXPECT_NEAR(r.thickness / uniaxial, 1.0, 1e-6);
  EXPECT_NEAR(r.force / (sigma * r.width * r.thickness), 1.0, 1e-3);
  EXPECT_GT(std::abs(r.force / (sigma * r.width * 0.1) - 1.0), 4e-3);  // the section's thickness is not it
}

// Elastic-plastic strip (*MAT_PLASTIC_KINEMATIC, E = 1e4, nu = 0.3, SIGY = 10, ETAN = 100,
// isotropic) pulled to L = 1.3: ISTUPD = 1 thins it to exp((1 - 2 nu) (s_xx + s_yy) / E) / A (A the
// area; 1e-9) and
// to the uniaxial exp(-nu sigma / E - eps_p / 2) (0.5 %), ISTUPD = 4 to exp(-eps_p / 2) (0.5 %); the
// force is the flow stress times the thinned section W t (0.5 %); without ISTUPD W t0 (0.5 %).
TEST(ShellThickness, PlasticStripThinsAtConstantPlasticVolume) {
  const Real e = 1e4, nu = 0.3, sy = 10.0, et = 100.0, ep = e * et / (e - et), v = 0.5, t_ramp = 0.05;
  std::ostringstream mat;
  mat << "*MAT_PLASTIC_KINEMATIC\n1,1e-3," << e << "," << nu << "," << sy << "," << et << ",1.0\n";
  for (int istupd : {1, 4, 0}) {
    const std::string control = istupd == 0 ? "" : "*CONTROL_SHELL\n0,0,0," + std::to_string(istupd) + "\n";
    const StripEnd r = run_strip(strip(mat.str(), control, v, t_ramp, 0.3 / v + 0.5 * t_ramp));
    const Real volume = 0.1 * std::exp((1.0 - 2.0 * nu) * (r.sigma + r.sigma_yy) / e) / r.area;
    const Real uniaxial = istupd == 4 ? 0.1 * std::exp(-0.5 * r.eps_p)
                          : istupd == 1 ? 0.1 * std::exp(-nu * r.sigma / e - 0.5 * r.eps_p)
                                        : 0.1;
    const Real flow = sy + ep * r.eps_p;
    std::printf("ISTUPD %d: L %.6f W %.6f eps_p %.6f sigma %.6g (flow %.6g): t %.8g, uniaxial closed form %.8g (rel "
                "%.2e), volume %.8g (rel %.2e); force %.6g, flow W t %.6g (rel %.2e)\n",
                istupd, r.length, r.width, r.eps_p, r.sigma, flow, r.thickness, uniaxial, r.thickness / uniaxial - 1.0,
                volume, r.thickness / volume - 1.0, r.force, flow * r.width * r.thickness,
                r.force / (flow * r.width * r.thickness) - 1.0);
    ASSERT_GT(r.eps_p, 0.2);
    if (istupd == 1) EXPECT_NEAR(r.thickness / volume, 1.0, 1e-9);
    EXPECT_NEAR(r.thickness / uniaxial, 1.0, 5e-3);
    EXPECT_NEAR(r.sigma / flow, 1.0, 5e-3);
    EXPECT_NEAR(r.force / (flow * r.width * r.thickness), 1.0, 5e-3);
  }
}

namespace {

/// The strip of *MAT_ELASTIC (E = 1000, rho = 1e-5, `nu`) eroding by `add` (*MAT_ADD_EROSION), pulled
/// at v = 0.1: the deletion time, the force just before and after, the eroded energy and the balance.
struct ErosionRun {
  Real deleted_at = -1.0, step = 0.0, force_before = 0.0, force_after = 0.0, eroded = 0.0, balance = 0.0;
};
ErosionRun erode_strip(Real nu, const std::string& add, Real end_time) {
  const Real v = 0.1, t_ramp = 0.05;
  auto sim = build_simulation(read_keyword_string(strip(elastic(1e-5, 1000.0, nu), add, v, t_ramp, end_time), "e.k"));
  std::vector<Real> times{0.0}, force{0.0};
  while (sim->step()) {
    times.push_back(sim->time());
    Real f = 0.0;
    for (const auto& g : sim->supports())
      if (g.name == "spc_node_1" || g.name == "spc_node_4") f += g.reaction.x();
    force.push_back(f);
  }
  ErosionRun out;
  const ElementErosion* er = std::as_const(*sim->blocks().at(0)).erosion();
  out.deleted_at = er->deletion_times()[0];
  std::size_t k = 0;
  while (k < times.size() && times[k] <= out.deleted_at) ++k;
  if (k > 1 && k < times.size()) {
    out.step = times[k - 1] - times[k - 2];
    out.force_before = force[k - 1];
    out.force_after = force[k];
  }
  out.eroded = sim->energy().eroded();
  out.balance = sim->energy().balance_error();
  return out;
}

}  // namespace

// MXEPS and EFFEPS on the strip: deleted within a step of the time ln L reaches the threshold
// (nu = 0: MXEPS 0.02 at ln L = 0.02, EFFEPS 0.02 at ln L = 0.03; nu = 0.3: EFFEPS 0.02 at ln L =
// 0.03 / 1.3); the force is E ln L t before and 0 after; the energy eroded is the strain energy held,
// t E (L ln L - L + 1) for nu = 0 (the stress criteria's booking), and the balance closes.
TEST(ShellThickness, StrainErosionAtTheClosedFormStretch) {
  const Real v = 0.1, t_ramp = 0.05;
  const auto time_of = [&](Real ln_l) { return (std::exp(ln_l) - 1.0) / v + 0.5 * t_ramp; };
  struct Case {
    Real nu;
    const char* add;
    Real ln_l;
    const char* what;
  };
  for (const Case& c : {Case{0.0, "*MAT_ADD_EROSION\n1\n,,,0.02\n", 0.02, "MXEPS 0.02"},
                        Case{0.0, "*MAT_ADD_EROSION\n1,,,,0.02\n\n", 0.03, "EFFEPS 0.02"},
                        Case{0.3, "*MAT_ADD_EROSION\n1,,,,0.02\n\n", 0.03 / 1.3, "EFFEPS 0.02, nu 0.3"},
                        Case{0.3, "*MAT_ADD_EROSION\n1,,,-0.006\n\n", 0.006 / 0.3, "MNEPS -0.006, nu 0.3"}}) {
    const Real expected = time_of(c.ln_l);
    const ErosionRun r = erode_strip(c.nu, c.add, expected + 0.02);
    std::printf("%s: deleted at %.7f, closed form %.7f (%.2f steps); force before %.6g after %.6g; eroded %.6g, "
                "balance %.3g\n",
                c.what, r.deleted_at, expected, (r.deleted_at - expected) / r.step, r.force_before, r.force_after,
                r.eroded, r.balance);
    ASSERT_GT(r.deleted_at, 0.0) << c.what;
    EXPECT_NEAR(r.deleted_at, expected, r.step) << c.what;
    EXPECT_EQ(r.force_after, 0.0) << c.what;
    EXPECT_LT(std::abs(r.balance), 1e-3 * r.eroded) << c.what;
    if (c.nu == 0.0) {
      const Real l = std::exp(c.ln_l);
      EXPECT_NEAR(std::abs(r.force_before), 1000.0 * c.ln_l * 0.1, 0.005 * 1000.0 * c.ln_l * 0.1) << c.what;
      const Real w = 0.1 * 1000.0 * (l * std::log(l) - l + 1.0);
      EXPECT_NEAR(r.eroded, w, 0.01 * w) << c.what;
    }
  }
}

}  // namespace slideline
