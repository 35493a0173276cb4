#pragma once
/// Equations of state of a *MAT_NULL solid (null_solid.hpp): the pressure p(mu, E) of the
/// compression mu = rho / rho0 - 1 = V0 / V - 1 and the internal energy E per unit reference
/// volume (force/length^2), for LS-DYNA's *EOS_LINEAR_POLYNOMIAL, *EOS_GRUNEISEN and
/// *EOS_TABULATED (docs/keywords.md, "Equations of state"). Each is linear in E,
/// p = A(mu) + B(mu) E, which is what the law's implicit-in-E energy update needs.
#include <array>
#include <cmath>
#include <string>

#include "slideline/core/types.hpp"

namespace slideline {

class EquationOfState {
 public:
  enum class Kind { linear_polynomial, gruneisen, tabulated };

  /// p = A + B E at one state, with dA/dmu and dB/dmu (mu = V0/V - 1).
  struct Split {
    Real a = 0.0, b = 0.0, da = 0.0, db = 0.0;
    Real pressure(Real e) const { return a + b * e; }
  };

  /// *EOS_LINEAR_POLYNOMIAL: C0..C6 (force/length^2, C4..C6 dimensionless), E0.
  static EquationOfState linear_polynomial(const std::array<Real, 7>& c, Real e0) {
    EquationOfState s(Kind::linear_polynomial, e0);
    for (std::size_t i = 0; i < 7; ++i) s.k_[i] = c[i];
    return s;
  }
  /// *EOS_GRUNEISEN: reference density rho0, C (length/time), S1..S3, GAMAO, A, E0.
  static EquationOfState gruneisen(Real rho0, Real c, Real s1, Real s2, Real s3, Real gamma0, Real a, Real e0) {
    EquationOfState s(Kind::gruneisen, e0);
    s.k_ = {rho0 * c * c, s1, s2, s3, gamma0, a};
    return s;
  }
  /// *EOS_TABULATED: ln(V/V0) points EV1 > ... > EV10, C and T at them (force/length^2), GAMA.
  static EquationOfState tabulated(const std::array<Real, 10>& ev, const std::array<Real, 10>& c,
                                   const std::array<Real, 10>& t, Real gamma, Real e0) {
    EquationOfState s(Kind::tabulated, e0);
    s.ev_ = ev;
    s.c_ = c;
    s.t_ = t;
    s.k_[0] = gamma;
    return s;
  }

  Kind kind() const { return kind_; }
  /// E0: the internal energy per unit reference volume at t = 0.
  Real initial_energy() const { return e0_; }

  /// A, B and their slopes at relative volume j = V/V0 > 0.
  Split at(Real j) const {
    const Real mu = 1.0 / j - 1.0;
    Split s;
    switch (kind_) {
      case Kind::linear_polynomial: {
        // C2 mu^2 and C6 mu^2 act in compression only (the manual: set to zero when mu < 0).
        const Real c2 = mu > 0.0 ? k_[2] : 0.0, c6 = mu > 0.0 ? k_[6] : 0.0;
        s.a = k_[0] + mu * (k_[1] + mu * (c2 + mu * k_[3]));
        s.da = k_[1] + mu * (2.0 * c2 + 3.0 * mu * k_[3]);
        s.b = k_[4] + mu * (k_[5] + mu * c6);
        s.db = k_[5] + 2.0 * mu * c6;
        return s;
      }
      case Kind::gruneisen: {
        const Real rc2 = k_[0], s1 = k_[1], s2 = k_[2], s3 = k_[3], g0 = k_[4], a = k_[5];
        s.b = g0 + a * mu;
        s.db = a;
        if (!(mu > 0.0)) {  // expanded: rho0 C^2 mu
          s.a = rc2 * mu;
          s.da = rc2;
          return s;
        }
        // Compressed: rho0 C^2 mu (1 + (1 - g0/2) mu - a/2 mu^2) / den^2,
        // den = 1 - (S1 - 1) mu - S2 mu^2 / (mu + 1) - S3 mu^3 / (mu + 1)^2.
        const Real k1 = 1.0 - 0.5 * g0, k2 = 0.5 * a, m1 = mu + 1.0;
        const Real num = rc2 * mu * (1.0 + mu * (k1 - k2 * mu));
        const Real dnum = rc2 * (1.0 + mu * (2.0 * k1 - 3.0 * k2 * mu));
        const Real den = 1.0 - (s1 - 1.0) * mu - s2 * mu * mu / m1 - s3 * mu * mu * mu / (m1 * m1);
        const Real dden = -(s1 - 1.0) - s2 * mu * (mu + 2.0) / (m1 * m1) - s3 * mu * mu * (mu + 3.0) / (m1 * m1 * m1);
        s.a = num / (den * den);
        s.da = dnum / (den * den) - 2.0 * num * dden / (den * den * den);
        return s;
      }
      case Kind::tabulated: {
        // eps = ln(V/V0), the table descending: the segment [EV(i+1), EV(i)] holding eps, the end
        // segments extended beyond the table (linear extrapolation). At a point the segment on its
        // compression side: the reference state's slope (eps = 0 is usually a point) is then the
        // compressive one (the tension side is mostly cut by PC).
        const Real eps = std::log(j);
        std::size_t i = 0;
        while (i < 8 && eps <= ev_[i + 1]) ++i;
        const Real h = ev_[i + 1] - ev_[i];
        const Real w = (eps - ev_[i]) / h;
        const Real gamma = k_[0];
        const Real dc = (c_[i + 1] - c_[i]) / h, dt = (t_[i + 1] - t_[i]) / h;
        s.a = c_[i] + w * (c_[i + 1] - c_[i]);
        s.b = gamma * (t_[i] + w * (t_[i + 1] - t_[i]));
        // d eps / d mu = -1 / (1 + mu) = -j.
        s.da = -j * dc;
        s.db = -j * gamma * dt;
        return s;
      }
    }
    return s;
  }

  /// The squared isentropic sound speed (length^2/time^2) at relative volume j, energy e and
  /// pressure p: dp/drho at constant entropy, (dp/dmu + dp/dE dE/dmu) / rho0 with
  /// dE/dmu = p / (1 + mu)^2 = p j^2 (dE = -p dV per unit reference volume).
  static Real sound_speed_squared(const Split& s, Real j, Real e, Real p, Real rho0) {
    return (s.da + s.db * e + s.b * p * j * j) / rho0;
  }

  /// Why the constants cannot run ("" when they can): a tabulated EOS needs EV strictly
  /// descending; a Gruneisen one C > 0.
  std::string problem() const {
    if (kind_ == Kind::tabulated)
      for (std::size_t i = 0; i + 1 < ev_.size(); ++i)
        if (!(ev_[i] > ev_[i + 1]))
          return "*EOS_TABULATED: EV" + std::to_string(i + 1) + " .. EV10 must descend strictly (EV" +
                 std::to_string(i + 1) + " = " + std::to_string(ev_[i]) + ", EV" + std::to_string(i + 2) + " = " +
                 std::to_string(ev_[i + 1]) + ")";
    return {};
  }

 private:
  EquationOfState(Kind k, Real e0) : kind_(k), e0_(e0) {}

  Kind kind_;
  Real e0_;
  std::array<Real, 7> k_{};  ///< the coefficients (see the factories)
  std::array<Real, 10> ev_{}, c_{}, t_{};
};

}  // namespace slideline
