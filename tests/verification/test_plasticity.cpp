// J2 plasticity (*MAT_PLASTIC_KINEMATIC, material/j2_plasticity.hpp) in a bar of hexahedra pulled
// and pushed in uniaxial stress, against the closed-form bilinear curve (true stress against
// logarithmic strain): isotropic and kinematic hardening through a tension-compression cycle (the
// Bauschinger difference), Cowper-Symonds rate scaling, the energy balance with plastic work, and
// the per-part plastic strain and plastic work history channels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "slideline/element/cell_output.hpp"
#include "slideline/element/hex_block.hpp"
#include "slideline/material/j2_plasticity.hpp"
#include "slideline/material/piecewise_plasticity.hpp"
#include "slideline/solver/load_curve.hpp"
#include "slideline/solver/output_sink.hpp"
#include "test_support/bilinear_curve.hpp"
#include "test_support/hex_grid.hpp"
#include "test_support/staged_simulation.hpp"

using namespace slideline;

namespace {

using test_support::Bilinear;

/// A bar of n x 1 x 1 cubic hexahedra of side 1 along x, of J2Plasticity with E = 1000, nu = 0.3,
/// sigma_y = 1 (or of `piecewise`); symmetry supports on x = 0, y = 0, z = 0 and the end x = n driven in x by a
/// displacement curve: uniaxial stress (the lateral faces are free). No bulk viscosity, so the
/// stress is the law's alone. The density is small enough that the bar is quasi-static.
struct PlasticBar : test_support::StagedSimulation {
  test_support::HexGrid g;
  int n;
  Real last_stress = 0.0, last_strain = 0.0;  ///< at the start of the last cycle run
  std::optional<PiecewisePlasticity> piecewise;  ///< run this law instead of J2Plasticity(k)
  J2PlasticityConstants k{1e-5, 1000.0, 0.3, 1.0, 10.0, 1.0, 0.0, 0.0};
  PlasticBar(int n_el, Real beta, Real tangent) : n(n_el) {
    k.beta = beta;
    k.tangent = tangent;
  }
  Bilinear curve() const { return {k.youngs, k.tangent, k.yield, k.beta}; }
  std::vector<Index> face_x(int i) const {
    std::vector<Index> out;
    for (int kk = 0; kk <= 1; ++kk)
      for (int j = 0; j <= 1; ++j) out.push_back(g.node(i, j, kk));
    return out;
  }
  static Support fix(Axis a, std::vector<Index> nodes) {
    Support s;
    s.axis = a;
    s.nodes = std::move(nodes);
    return s;
  }
  /// Builds the bar with the end displacement u(t) given as (t, u) points.
  /// `confined`: the lateral faces are held too (uniaxial strain; see the rate tests).
  void build(const std::vector<std::pair<Real, Real>>& u, Real end_time, bool confined = false) {
    test_support::GridMesh mesh;
    g = mesh.add_box(Vec3::Zero(), Vec3(n, 1.0, 1.0), n, 1, 1);
    mesh.fill(setup.nodes);
    std::vector<Index> y0, z0;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= 1; ++j) {
        y0.push_back(g.node(i, 0, j));
        z0.push_back(g.node(i, j, 0));
        if (confined) {
          y0.push_back(g.node(i, 1, j));
          z0.push_back(g.node(i, j, 1));
        }
      }
    Support drive = fix(Axis::x, face_x(n));
    drive.has_curve = true;
    drive.curve = LoadCurve(u);
    setup.supports = {SupportGroup{"left", {fix(Axis::x, face_x(0))}, Vec3::Zero()},
                      SupportGroup{"sym", {fix(Axis::y, y0), fix(Axis::z, z0)}, Vec3::Zero()},
                      SupportGroup{"right", {drive}, Vec3::Zero()}};
    std::vector<Id> ids;
    for (int i = 0; i < n; ++i) ids.push_back(i + 1);
    if (piecewise)
      setup.blocks.push_back(std::make_unique<HexBlock<PiecewisePlasticity>>(
          1, *piecewise, HexHourglass{}, BulkViscosity{0.0, 0.0}, g.conn(), ids));
    else
      setup.blocks.push_back(std::make_unique<HexBlock<J2Plasticity>>(
          1, J2Plasticity(k), HexHourglass{}, BulkViscosity{0.0, 0.0}, g.conn(), ids));
    setup.controls.end_time = end_time;
    start();
  }
  Real area() const {
    const auto& x = sim().nodes().x;
    return (x.y[g.node(0, 1, 0)] - x.y[g.node(0, 0, 0)]) * (x.z[g.node(0, 0, 1)] - x.z[g.node(0, 0, 0)]);
  }
  /// One cycle; returns false at the end time. `eps` and `stress`: the log strain and true stress
  /// (force on the fixed end over the cross-section) at the start of the cycle, the time the
  /// cycle's reactions are taken at.
  bool step(Real& eps, Real& stress) {
    eps = log_strain();
    const Real a = area();
    const bool more = sim().step();
    stress = sim().supports()[0].reaction.x() / a;  // the force the bar exerts on the support
    return more;
  }
  Real log_strain() const {
    const auto& x = sim().nodes().x;
    return std::log((x.x[g.node(n, 0, 0)] - x.x[g.node(0, 0, 0)]) / n);
  }
};

/// Runs the bar to its end time and returns the largest |true stress - curve| over the run, the
/// curve given as a function of the log strain and of whether the peak strain has passed.
template <class Curve>
Real worst_deviation(PlasticBar& bar, Curve&& curve) {
  Real worst = 0.0, peak = -1.0, eps = 0.0, stress = 0.0;
  bool more = true;
  while (more) {
    more = bar.step(eps, stress);
    peak = std::max(peak, eps);
    worst = std::max(worst, std::abs(stress - curve(eps, peak)));
  }
  bar.last_stress = stress;
  bar.last_strain = eps;
  return worst;
}

/// Appends to `u` the end displacement going from a to b over [t0, t1] along a half cosine (zero
/// velocity at both ends, so the bar is not shaken by a kink), in 200 pieces.
void half_cosine(std::vector<std::pair<Real, Real>>& u, Real a, Real b, Real t0, Real t1) {
  const Real pi = std::acos(-1.0);
  for (int i = u.empty() ? 0 : 1; i <= 200; ++i)
    u.push_back({t0 + (t1 - t0) * i / 200, a + (b - a) * 0.5 * (1.0 - std::cos(pi * i / 200))});
}

/// Pulls the bar to 4% log strain over t in [0, 0.5] and pushes it back to -2% by t = 1.25.
Real cycle(PlasticBar& bar) {
  const Real e1 = std::exp(0.04) - 1.0, e2 = std::exp(-0.02) - 1.0;
  std::vector<std::pair<Real, Real>> u;
  half_cosine(u, 0.0, e1 * bar.n, 0.0, 0.5);
  half_cosine(u, e1 * bar.n, e2 * bar.n, 0.5, 1.25);
  bar.build(u, 1.25);
  const Bilinear c = bar.curve();
  return worst_deviation(bar, [&](Real eps, Real peak) {
    return eps >= peak - 1e-12 ? c.loading(eps) : c.reversed(peak, eps);
  });
}

/// A constant log strain rate `rate` to 4% strain (and on, past the end time, so the rate holds to
/// the last step) in uniaxial strain (the lateral faces held); returns the end time. In uniaxial
/// stress the free sides vibrate, and a yield stress scaled by the total strain rate feeds on that
/// vibration (the rate measure sqrt(2/3 D':D') only grows with it): the flow stress of the
/// undamped one-element bar then swings between about 0.6 and 1.35 times the closed form. Held
/// sides take the vibration out.
Real constant_rate(PlasticBar& bar, Real rate) {
  const Real end = 0.04 / rate;
  std::vector<std::pair<Real, Real>> u;
  for (int i = 0; i <= 24; ++i) u.push_back({end * i / 20, std::exp(rate * end * i / 20) - 1.0});
  bar.build(u, end, true);
  return end;
}

}  // namespace

// Isotropic hardening (BETA = 1): the curve through a tension-compression cycle, the reverse yield
// at -sigma_1, within 0.5% of the peak stress; one element and a bar of three.
TEST(J2PlasticityBar, IsotropicCycleFollowsTheBilinearCurve) {
  for (int n : {1, 3}) {
    PlasticBar bar(n, 1.0, 10.0);
    const Real worst = cycle(bar);
    const Real s1 = bar.curve().loading(0.04);
    EXPECT_LT(worst, 0.005 * s1) << n << " elements";
    RecordProperty("worst_relative_deviation_" + std::to_string(n), std::to_string(worst / s1));
  }
}

// Kinematic hardening (BETA = 0): reverse yield at sigma_1 - 2 sigma_y (the Bauschinger effect),
// not at -sigma_1 as in the isotropic case.
TEST(J2PlasticityBar, KinematicCycleShowsTheBauschingerEffect) {
  PlasticBar bar(1, 0.0, 10.0);
  const Real worst = cycle(bar);
  const Bilinear c = bar.curve();
  const Real s1 = c.loading(0.04);
  EXPECT_LT(worst, 0.005 * s1);
  // The stress at -2% strain: the two closed forms are far apart, and the bar is on its own one.
  const Real kin = c.reversed(0.04, -0.02);
  const Real iso = Bilinear{c.e, c.et, c.sy, 1.0}.reversed(0.04, -0.02);
  EXPECT_GT(std::abs(kin - iso), 0.3 * s1);
  EXPECT_NEAR(bar.last_strain, -0.02, 1e-3);
  EXPECT_NEAR(bar.last_stress, c.reversed(0.04, bar.last_strain), 0.005 * s1);
  EXPECT_GT(std::abs(bar.last_stress - iso), 0.25 * s1);
}

// Plastic work is stress work: it shows up as internal energy and the energy balance closes.
TEST(J2PlasticityBar, PlasticWorkClosesTheEnergyBalance) {
  PlasticBar bar(1, 1.0, 10.0);
  cycle(bar);
  const EnergyReport& e = bar.sim().energy();
  // The work of the uniaxial curve over the cycle (per unit reference volume; the plastic flow
  // keeps the volume, the elastic strain changes it by < 0.1%): trapezoid sums of sigma d eps.
  const Bilinear c = bar.curve();
  Real w = 0.0;
  const int m = 20000;
  for (int i = 0; i < m; ++i) {  // 0 -> 4% -> -2%
    const Real a = 0.04 * i / m, b = 0.04 * (i + 1) / m;
    w += 0.5 * (c.loading(a) + c.loading(b)) * (b - a);
    const Real p = 0.04 - 0.06 * i / m, q = 0.04 - 0.06 * (i + 1) / m;
    w += 0.5 * (c.reversed(0.04, p) + c.reversed(0.04, q)) * (q - p);
  }
  EXPECT_NEAR(e.internal, w, 0.01 * w);
  EXPECT_LT(std::abs(e.balance_error()), 1e-4 * e.internal);
}

// Cowper-Symonds: with perfect plasticity (ETAN = 0), in uniaxial strain at the log strain rate r,
// the deviator flows at sigma_y phi with phi = 1 + (r_eff / C)^(1/P), r_eff = sqrt(2/3 D':D') = 2 r / 3,
// so sigma_xx = K eps + 2/3 sigma_y phi.
TEST(J2PlasticityBar, RateScaledYieldMatchesCowperSymonds) {
  for (Real rate : {0.02, 0.08}) {
    PlasticBar bar(1, 1.0, 0.0);
    bar.k.rate_c = 0.02;
    bar.k.rate_p = 2.0;
    constant_rate(bar, rate);
    worst_deviation(bar, [](Real, Real) { return 0.0; });
    const J2Plasticity law(bar.k);
    const Real want = law.bulk_modulus() * bar.last_strain + 2.0 / 3.0 * (1.0 + std::sqrt(2.0 * rate / 3.0 / 0.02));
    EXPECT_NEAR(bar.last_stress, want, 0.005 * want) << "rate " << rate;
  }
}

namespace {

/// *MAT_PIECEWISE_LINEAR_PLASTICITY's law with E = 1000, nu = 0.3 and the yield curve
/// (0, 1) - (0.01, 1.2) - (0.03, 1.3), extrapolated with the last slope 5.
PiecewisePlasticity curve_law(Real c = 0.0, Real p = 0.0, bool viscoplastic = false) {
  return PiecewisePlasticity({1e-5, 1000.0, 0.3, {{0.0, 1.0}, {0.01, 1.2}, {0.03, 1.3}}, c, p, {}, viscoplastic});
}

}  // namespace

// The yield curve in uniaxial stress: sigma = curve(eps - sigma / E) at every log strain eps, over
// all three segments and the extrapolation (to 5%), within 0.5%; one element and a bar of three.
TEST(PiecewisePlasticityBar, TensionFollowsTheYieldCurve) {
  for (int n : {1, 3}) {
    PlasticBar bar(n, 1.0, 0.0);
    bar.piecewise = curve_law();
    std::vector<std::pair<Real, Real>> u;
    half_cosine(u, 0.0, (std::exp(0.05) - 1.0) * n, 0.0, 0.5);
    bar.build(u, 0.5);
    const PiecewisePlasticity law = curve_law();
    const Real worst = worst_deviation(bar, [&](Real eps, Real) {
      if (eps <= 1e-3) return 1000.0 * eps;
      Real lo = 0.0, hi = 10.0;  // sigma - curve(eps - sigma / E) increases with sigma
      for (int i = 0; i < 100; ++i) {
        const Real mid = 0.5 * (lo + hi);
        (mid - law.yield_stress(eps - mid / 1000.0) > 0.0 ? hi : lo) = mid;
      }
      return lo;
    });
    EXPECT_LT(worst, 0.005 * 1.4) << n << " elements";
    EXPECT_NEAR(bar.last_strain, 0.05, 1e-3);
  }
}

// Rate scaling in uniaxial strain (as above): in steady flow on a flat curve the plastic rate equals
// the total deviatoric rate, so VP = 0 (total rate) and VP = 1 (plastic rate) both give
// sigma_xx = K eps + 2/3 sigma_y (1 + (2 r / 3 C)^(1/P)).
TEST(PiecewisePlasticityBar, CowperSymondsTotalAndViscoplastic) {
  for (bool vp : {false, true}) {
    PlasticBar bar(1, 1.0, 0.0);
    bar.piecewise = PiecewisePlasticity({1e-5, 1000.0, 0.3, {{0.0, 1.0}, {1.0, 1.0}}, 0.02, 2.0, {}, vp});
    const Real rate = 0.08;
    constant_rate(bar, rate);
    worst_deviation(bar, [](Real, Real) { return 0.0; });
    const Real want =
        bar.piecewise->bulk_modulus() * bar.last_strain + 2.0 / 3.0 * (1.0 + std::sqrt(2.0 * rate / 3.0 / 0.02));
    EXPECT_NEAR(bar.last_stress, want, 0.005 * want) << "VP = " << vp;
  }
}

// The per-part plasticity channels (parts/<id>/max_plastic_strain, parts/<id>/plastic_work;
// ElementBlock::plasticity_totals) on the one-element bar pulled to 4% log strain eps in uniaxial
// stress, isotropic hardening (BETA = 1), E = 1000, ETAN = Et = 10, sigma_y = 1:
//   Ep = E Et / (E - Et);  sigma_vm = sigma_y + Ep eps_p (the radial return is exact for linear
//   hardening);  in uniaxial stress eps = sigma / E + eps_p, so eps_p = (1 - Et / E)(eps - sigma_y / E);
//   plastic work per volume w_p = sigma_y eps_p + Ep eps_p^2 / 2 (the area under sigma(eps_p));
// and the energy balance: internal energy = elastic energy + plastic work.
TEST(J2PlasticityBar, PlasticStrainAndWorkChannelsFollowTheClosedForm) {
  PlasticBar bar(1, 1.0, 10.0);
  std::vector<std::pair<Real, Real>> u;
  half_cosine(u, 0.0, std::exp(0.04) - 1.0, 0.0, 0.5);
  const LoadCurve stretch(u);
  bar.build(u, 0.5);
  History h;
  bar.sim().run({&h});
  const Bilinear c = bar.curve();
  const Real ep = c.ep(), eps_y = c.sy / c.e;
  const std::vector<Real> strain = h.series("parts/1/max_plastic_strain"), work = h.series("parts/1/plastic_work");
  ASSERT_EQ(strain.size(), h.records());
  // Against the prescribed stretch: 0 while elastic, then the closed form (the bar is quasi-static;
  // its inertia and the lateral vibration of its free sides move it by < 2e-6 here).
  Real worst = 0.0;
  for (std::size_t r = 0; r < h.records(); ++r) {
    const Real eps = std::log(1.0 + stretch(h.time()[r]));
    const Real want = eps <= eps_y ? 0.0 : (1.0 - c.et / c.e) * (eps - eps_y);
    worst = std::max(worst, std::abs(strain[r] - want));
  }
  EXPECT_LT(worst, 2e-6);
  RecordProperty("worst_plastic_strain_deviation", std::to_string(worst));
  const Real eps_p = strain.back();
  EXPECT_NEAR(eps_p, (1.0 - c.et / c.e) * (0.04 - eps_y), 2e-6);
  // The stress the element holds at the end is on the hardened yield surface: exact to round-off.
  std::vector<CellOutput> cells(1);
  bar.sim().blocks()[0]->cell_outputs(bar.sim().nodes(), cells);
  EXPECT_NEAR(von_mises(cells[0].stress), c.sy + ep * eps_p, 1e-12 * c.sy);
  // Plastic work: the closed-form density times the current volume. The channel weighs each
  // increment by the volume it was done at (j2_return.hpp; it weighed them all by the volume at the
  // record before, 3.2e-5 above this), which is below the current one by at most the growth of the
  // elastic volume strain (1 - 2 nu) sigma / E over the plastic range, 1.6e-4; the law's sum of
  // sigma : d eps_p with the stress at the end of each step adds Ep eps_p d eps_p / 2 (~1e-6).
  const auto& x = bar.sim().nodes().x;
  const Real volume = bar.area() * (x.x[bar.g.node(1, 0, 0)] - x.x[bar.g.node(0, 0, 0)]);
  const Real wp = volume * (c.sy * eps_p + 0.5 * ep * eps_p * eps_p);
  EXPECT_NEAR(work.back(), wp, 1e-4 * wp);
  for (std::size_t r = 1; r < work.size(); ++r) ASSERT_GE(work[r], work[r - 1]);  // monotonic loading
  // The energy balance's internal energy less the elastic energy the stress holds (s':s'/4G + p^2/2K
  // per volume) is the plastic work.
  const SymTensor6& s = cells[0].stress;
  const J2Plasticity law(bar.k);
  const Real p = (s[0] + s[1] + s[2]) / 3.0;
  Real dev2 = 2.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]);
  for (int i = 0; i < 3; ++i) dev2 += (s[i] - p) * (s[i] - p);
  const Real elastic = volume * (dev2 / (4.0 * law.shear_modulus()) + p * p / (2.0 * law.bulk_modulus()));
  EXPECT_NEAR(bar.sim().energy().internal - elastic, work.back(), 1e-3 * work.back());
  EXPECT_NEAR(h.value("energy/internal", h.records() - 1) - elastic, work.back(), 1e-3 * work.back());
}
