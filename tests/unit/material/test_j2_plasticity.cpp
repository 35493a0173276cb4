// J2Plasticity (material/j2_plasticity.hpp) and the polar rotation it turns its stress with, against
// closed forms: uniaxial strain (elastic, then flow at the hardened yield stress), objectivity
// under a superposed rotation, Cowper-Symonds scaling, one element and a batch alike.
#include <gtest/gtest.h>

#include <cmath>

#include "slideline/material/j2_plasticity.hpp"
#include "slideline/material/laws.hpp"
#include "slideline/material/piecewise_plasticity.hpp"
#include "slideline/material/polar_rotation.hpp"
#include "slideline/solver/material_registry.hpp"

using namespace slideline;

static_assert(SolidMaterial<J2Plasticity>);
static_assert(SolidMaterial<PiecewisePlasticity>);

namespace {

Tensor3<Real> rotation(Real angle, const Vec3& axis) {
  return to_tensor3(Eigen::AngleAxis<Real>(angle, axis.normalized()).toRotationMatrix());
}

Tensor3<Real> diag(Real a, Real b, Real c) { return {{{a, 0.0, 0.0}, {0.0, b, 0.0}, {0.0, 0.0, c}}}; }

J2PlasticityConstants steel(Real beta) { return {7.8e-9, 2.0e5, 0.3, 250.0, 2.0e3, beta, 0.0, 0.0}; }

/// Drives `law` in uniaxial strain along x at the log strain rate `rate` for `steps` steps of dt,
/// the whole history seen through the rotation Q (F -> Q F Q^T, D -> Q D Q^T); returns the state.
template <class Law>
J2State<Real> uniaxial_strain(const Law& law, Real rate, Real dt, int steps, const Tensor3<Real>& Q,
                              Tensor3<Real>& sigma) {
  J2State<Real> s;
  const Mat3 q = to_mat3(Q);
  for (int n = 1; n <= steps; ++n) {
    const Mat3 F = q * to_mat3(diag(std::exp(rate * dt * n), 1.0, 1.0)) * q.transpose();
    const Mat3 D = q * to_mat3(diag(rate, 0.0, 0.0)) * q.transpose();
    sigma = law.update(s, to_tensor3(F), to_tensor3(D), dt);
  }
  return s;
}

}  // namespace

TEST(PolarRotation, RecoversTheRotationOfAStretch) {
  const Tensor3<Real> Q = rotation(1.1, Vec3(1.0, -2.0, 0.5));
  const Mat3 U = (Mat3() << 1.3, 0.2, -0.1, 0.2, 0.8, 0.05, -0.1, 0.05, 1.1).finished();  // SPD
  const Tensor3<Real> R = polar_rotation(to_tensor3(to_mat3(Q) * U));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(R[i][j], Q[i][j], 1e-14);
}

// Uniaxial strain eps: elastic sigma_xx = (lambda + 2G) eps; past yield the deviator sits on the
// yield surface: sigma_xx - sigma_yy = sigma_0 + Ep eps_p with eps_p = (2 G eps - sigma_0) / (3 G + Ep)
// (isotropic), and the mean stress is K eps throughout. Exact for any step (linear hardening).
TEST(J2Plasticity, UniaxialStrainMatchesTheClosedForm) {
  const J2Plasticity law(steel(1.0));
  const Real G = law.shear_modulus(), K = law.bulk_modulus(), H = law.hardening_modulus();
  Tensor3<Real> sig;
  const Real rate = 1.0, dt = 1e-5;
  for (int steps : {100, 1000}) {  // eps = 1e-3 (elastic), 1e-2 (plastic)
    const auto s = uniaxial_strain(law, rate, dt, steps, diag(1.0, 1.0, 1.0), sig);
    const Real eps = rate * dt * steps;
    const Real ep = std::max(0.0, (2.0 * G * eps - 250.0) / (3.0 * G + H));
    const Real q = ep > 0.0 ? 250.0 + H * ep : 2.0 * G * eps;
    EXPECT_NEAR(s.eps, ep, 1e-12);
    EXPECT_NEAR(sig[0][0] - sig[1][1], q, 1e-9 * q) << steps;
    EXPECT_NEAR(sig[0][0] + 2.0 * sig[1][1], 3.0 * K * eps, 1e-9 * K * eps);
    EXPECT_EQ(sig[1][1], sig[2][2]);
  }
}

// The rotated copy: the same history seen through a rotation gives the rotated stress and the same
// plastic strain; a rigid rotation after loading (D = 0) turns the stress and changes nothing else.
TEST(J2Plasticity, ObjectiveUnderRotation) {
  const J2Plasticity law(steel(0.0));
  const Tensor3<Real> I = diag(1.0, 1.0, 1.0), Q = rotation(0.7, Vec3(0.3, 1.0, -0.4));
  Tensor3<Real> sig, sig_q;
  const auto s = uniaxial_strain(law, 1.0, 1e-5, 800, I, sig);
  auto s_q = uniaxial_strain(law, 1.0, 1e-5, 800, Q, sig_q);
  EXPECT_NEAR(s_q.eps, s.eps, 1e-14);
  const Tensor3<Real> want = rotate_to_current(Q, sig);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(sig_q[i][j], want[i][j], 1e-9 * sig[0][0]);
  // Now rotate the loaded body rigidly by P: F = P Q U Q^T, D = 0.
  const Tensor3<Real> P = rotation(-1.3, Vec3(1.0, 0.2, 0.1));
  const Mat3 F = to_mat3(P) * to_mat3(Q) * to_mat3(diag(std::exp(8e-3), 1.0, 1.0)) * to_mat3(Q).transpose();
  const Tensor3<Real> turned = law.update(s_q, to_tensor3(F), diag(0.0, 0.0, 0.0), 1e-5);
  const Tensor3<Real> want2 = rotate_to_current(P, sig_q);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(turned[i][j], want2[i][j], 1e-9 * sig[0][0]);
  EXPECT_NEAR(s_q.eps, s.eps, 1e-14);
}

// Cowper-Symonds: perfect plasticity in uniaxial strain at rate r flows at von Mises stress
// sigma_0 (1 + (r_eff / C)^(1/P)), r_eff = sqrt(2/3 D':D') = 2 r / 3.
TEST(J2Plasticity, CowperSymondsScalesTheYieldStress) {
  J2PlasticityConstants k = steel(1.0);
  k.tangent = 0.0;
  k.rate_c = 40.4;
  k.rate_p = 5.0;
  const J2Plasticity law(k);
  Tensor3<Real> sig;
  const Real rate = 300.0;
  uniaxial_strain(law, rate, 1e-7, 1000, diag(1.0, 1.0, 1.0), sig);
  const Real want = 250.0 * (1.0 + std::pow(2.0 * rate / 3.0 / 40.4, 0.2));
  EXPECT_NEAR(sig[0][0] - sig[1][1], want, 1e-9 * want);
}

// The batch (Lanes) update is the one-element update in every lane.
TEST(J2Plasticity, BatchMatchesOneElement) {
  const J2Plasticity law(steel(0.5));
  const Tensor3<Real> F = {{{1.02, 0.01, 0.0}, {0.003, 0.99, 0.002}, {0.0, -0.01, 1.0}}};
  const Tensor3<Real> D = {{{30.0, 4.0, -2.0}, {4.0, -10.0, 1.0}, {-2.0, 1.0, -12.0}}};
  J2Plasticity::State<Real> s;
  J2Plasticity::State<Lanes> sl;
  Tensor3<Lanes> Fl, Dl;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Fl[i][j] = Lanes::Constant(F[i][j]);
      Dl[i][j] = Lanes::Constant(D[i][j]);
    }
  Tensor3<Real> sig;
  Tensor3<Lanes> sig_l;
  for (int n = 0; n < 50; ++n) {
    sig = law.update(s, F, D, 1e-5);
    sig_l = law.update(sl, Fl, Dl, 1e-5);
  }
  ASSERT_GT(s.eps, 0.0);
  for (int l = 0; l < kLanes; ++l) {
    EXPECT_NEAR(sl.eps[l], s.eps, 1e-12 * s.eps);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) EXPECT_NEAR(sig_l[i][j][l], sig[i][j], 1e-10 * 250.0);
  }
}

// The deck card maps to the law with its constants, for solids and shells.
TEST(J2Plasticity, RegistryMapsPlasticKinematic) {
  const MaterialLaws laws =
      material_laws(model::MatPlasticKinematic{5, 7.8e-9, 2e5, 0.3, 250.0, 2e3, 0.5, 40.4, 5.0, 0.0, "", {}});
  ASSERT_TRUE(laws.solid);
  ASSERT_TRUE(laws.shell);
  EXPECT_EQ(std::get<ShellPlasticity<J2Plasticity>>(*laws.shell).law().constants().yield, 250.0);
  const auto& law = std::get<J2Plasticity>(*laws.solid);
  EXPECT_EQ(law.constants().yield, 250.0);
  EXPECT_EQ(law.constants().beta, 0.5);
  EXPECT_EQ(law.constants().rate_c, 40.4);
  EXPECT_DOUBLE_EQ(law.hardening_modulus(), 2e5 * 2e3 / (2e5 - 2e3));
  EXPECT_STREQ(laws.keyword, "*MAT_PLASTIC_KINEMATIC");
}

// Uniaxial strain along a three-segment yield curve: the deviator sits on the curve,
// sigma_xx - sigma_yy = curve(eps_p), and is elastic in what is left, 2 G (eps - 3/2 eps_p); both
// exact (the return walks the segments), in each segment and past the last point.
TEST(PiecewisePlasticity, UniaxialStrainStaysOnTheCurve) {
  const PiecewisePlasticity law({7.8e-9, 2.0e5, 0.3, {{0.0, 250.0}, {0.002, 300.0}, {0.01, 340.0}}, 0.0, 0.0, {}, false});
  ASSERT_TRUE(law.problem().empty());
  const Real G = law.shear_modulus();
  Tensor3<Real> sig;
  for (int steps : {200, 400, 1000, 2000}) {  // eps = 2e-3 .. 2e-2
    const auto s = uniaxial_strain(law, 1.0, 1e-5, steps, diag(1.0, 1.0, 1.0), sig);
    const Real eps = 1e-5 * steps, q = sig[0][0] - sig[1][1];
    ASSERT_GT(s.eps, 0.0);
    EXPECT_NEAR(q, law.yield_stress(s.eps), 1e-9 * q) << steps;
    EXPECT_NEAR(q, 2.0 * G * (eps - 1.5 * s.eps), 1e-9 * q) << steps;
  }
  EXPECT_DOUBLE_EQ(law.yield_stress(0.02), 340.0 + 0.01 * 5000.0);  // extrapolated
  EXPECT_FALSE(PiecewisePlasticity({1.0, 1000.0, 0.3, {{0.0, 1.0}, {0.0, 2.0}}, 0.0, 0.0, {}, false}).problem().empty());
}

// VP = 1: the increment solves vm - 3 G d = phi(d / dt) curve(eps + d) (flat curve: sigma_0).
TEST(PiecewisePlasticity, ViscoplasticIncrementSolvesTheRateEquation) {
  const PiecewisePlasticity law({1.0, 1000.0, 0.3, {{0.0, 1.0}}, 0.02, 2.0, {}, true});
  const Real G = law.shear_modulus(), dt = 1e-3, vm = 5.0;
  const Real d = law.increment(vm, 0.0, 0.0, dt);
  EXPECT_NEAR(vm - 3.0 * G * d, 1.0 + std::sqrt(d / dt / 0.02), 1e-12);
  EXPECT_EQ(law.increment(0.9, 0.0, 0.0, dt), 0.0);
}

TEST(J2Plasticity, EnergyDensityIsElasticEnergyPlusPlasticWork) {
  // Uniaxial strain to 1% (eight times the yield strain): along the monotonic path the von Mises
  // stress is SIGY + Ep eps_p for any BETA; the work is per unit reference volume (j2_return.hpp),
  // each increment weighted by the volume ratio J = exp(eps) it was done at, with
  // eps = eps_y + b eps_p (eps_y = SIGY / 2G, b = (3G + Ep) / 2G): the plastic work is
  //   exp(eps_y) int_0^e exp(b x) (SIGY + Ep x) dx
  //     = exp(eps_y) [SIGY (exp(b e) - 1) / b + Ep ((e / b - 1 / b^2) exp(b e) + 1 / b^2)]
  // (SIGY e + Ep e^2 / 2 per unit current volume, 0.6 % less, before); the update books
  // sigma_end : d eps_p per step (first order in the step: 1e-3 here).
  for (Real beta : {0.0, 1.0}) {
    const J2Plasticity law(steel(beta));
    Tensor3<Real> sigma;
    J2State<Real> s = uniaxial_strain(law, 1.0, 1e-4, 100, diag(1.0, 1.0, 1.0), sigma);
    const Real ep = law.hardening_modulus(), e = s.eps, g = law.shear_modulus();
    const Real eps_y = 250.0 / (2.0 * g), b = (3.0 * g + ep) / (2.0 * g), x = std::exp(b * e);
    const Real work = std::exp(eps_y) * (250.0 * (x - 1.0) / b + ep * ((e / b - 1.0 / (b * b)) * x + 1.0 / (b * b)));
    EXPECT_GT(e, 0.005);
    EXPECT_NEAR(s.work, work, 1e-3 * s.work) << "beta " << beta;
    const Real p = (sigma[0][0] + sigma[1][1] + sigma[2][2]) / 3.0, q = sigma[0][0] - sigma[1][1];
    // s':s' = 2/3 q^2 in uniaxial strain (the lateral stresses equal).
    const Real elastic = (2.0 / 3.0) * q * q / (4.0 * law.shear_modulus()) + p * p / (2.0 * law.bulk_modulus());
    EXPECT_NEAR(law.energy_density(s), elastic + s.work, 1e-9 * (elastic + s.work));
  }
}
