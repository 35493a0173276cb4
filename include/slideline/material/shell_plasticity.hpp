#pragma once
/// J2 (von Mises) plasticity at a shell's through-thickness point, in plane stress (sigma_zz = 0):
/// *MAT_PLASTIC_KINEMATIC (003) and *MAT_PIECEWISE_LINEAR_PLASTICITY (024) on Belytschko-Tsay
/// shells. The yield stress, its hardening and rate scaling, and the kinematic hardening modulus
/// are the hexahedron laws' own (J2Plasticity::flow_stress, PiecewisePlasticity::flow_stress); this
/// file holds only the plane-stress return.
///
/// The return (Simo & Taylor 1986; Simo & Hughes, Computational Inelasticity, section 3.4): the
/// elastic predictor adds C : d dt in the element's co-rotational frame (ElasticShell), then, if
/// the trial point lies outside the yield surface, the backward-Euler projection onto it, solved
/// exactly: in the basis (xx + yy, xx - yy, xy) the plane-stress elasticity C and the von Mises
/// matrix P are both diagonal, so the relative stress xi = sigma - b (b the back stress) after a
/// consistency parameter g is xi_i = xi_trial_i / (1 + g (c_i + 2 Hk / 3)), with c = E / (3 (1 -
/// nu)), 2 G, 2 G. The one scalar unknown g solves
///     |xi(g)|_vm = flow_stress(eps + 2/3 g |xi(g)|_vm)
/// (a decreasing function of g), bracketed and solved by the Illinois method to round-off. LS-DYNA's
/// default for these shells iterates on the thickness strain instead (three secant steps); at
/// convergence both land on the same point.
///
/// b is kept as the in-plane tensor whose deviator is the 3-D back stress (b_zz = 0): with the
/// hexahedron law's Prager rule (the 3-D back stress moves by Hk d_eps along the flow direction)
/// it moves by 2/3 Hk g xi. The transverse shear stays elastic. The state also accumulates the
/// plastic work density sigma : d_eps_p, so that energy_density() is the whole internal energy.
#include <array>
#include <cmath>
#include <string>
#include <utility>

#include "slideline/core/types.hpp"
#include "slideline/material/elastic_shell.hpp"
#include "slideline/material/shell_material.hpp"

namespace slideline {

/// A PlaneStressMaterial (shell_material.hpp) from a J2 hexahedron law `Law` (J2Plasticity or
/// PiecewisePlasticity): it needs `flow_stress(eps, d_eps, rate, dt)`, `kinematic_modulus()`,
/// `rate_dependent()`, `density()`, `youngs_modulus()` and `constants().poisson`.
template <class Law>
class ShellPlasticity {
 public:
  /// The stress (ElasticShell's part), the in-plane back stress b (xx, yy, xy), the effective
  /// plastic strain `eps` and the plastic work density `work` (force/length^2).
  struct State : ElasticShell::State {
    std::array<Real, 3> back{};
    Real eps = 0.0;
    Real work = 0.0;
  };

  explicit ShellPlasticity(Law law)
      : law_(std::move(law)), elastic_(law_.density(), law_.youngs_modulus(), law_.constants().poisson) {
    const Real nu = law_.constants().poisson;
    c_[0] = law_.youngs_modulus() / (3.0 * (1.0 - nu));
    c_[1] = c_[2] = 2.0 * elastic_.shear_modulus();
    h_ = 2.0 / 3.0 * law_.kinematic_modulus();
  }

  const Law& law() const { return law_; }
  Real density() const { return elastic_.density(); }
  Real youngs_modulus() const { return elastic_.youngs_modulus(); }
  Real shear_modulus() const { return elastic_.shear_modulus(); }
  Real bulk_modulus() const { return elastic_.bulk_modulus(); }
  /// The elastic plate wave speed (the step is the elastic one).
  Real wave_speed() const { return elastic_.wave_speed(); }
  /// The elastic stiffness (hourglass control and stiffness damping see the elastic moduli).
  PlaneStressStiffness stiffness() const { return elastic_.stiffness(); }

  std::string problem() const {
    std::string why = elastic_.problem();
    if constexpr (requires { law_.problem(); })
      if (why.empty()) why = law_.problem();
    return why;
  }

  /// The PlaneStressMaterial step: the elastic predictor, then the plane-stress return (above).
  ShellStress update(State& s, const ShellRate& d, Real dt, Real shear_factor) const {
    elastic_.update(s, d, dt, shear_factor);
    constexpr Real r2 = 0.70710678118654752440;  // 1 / sqrt(2)
    const Real x0 = s.sigma[0] - s.back[0], x1 = s.sigma[1] - s.back[1];
    const Trial t{{(x0 + x1) * r2, (x0 - x1) * r2, s.sigma[2] - s.back[2]}, s.eps,
                  law_.rate_dependent() ? effective_rate(d) : 0.0, dt};
    const Real r0 = residual(t, 0.0);
    if (!(r0 > 0.0)) return s.sigma;
    const Real g = solve(t, r0);
    const Real q = 1.0 + h_ * g;
    const Real b0 = t.a[0] / (1.0 + g * (c_[0] + h_)), b1 = t.a[1] / (1.0 + g * (c_[1] + h_));
    const std::array<Real, 3> xi{(b0 + b1) * r2, (b0 - b1) * r2, t.a[2] / (1.0 + g * (c_[2] + h_))};
    // d_eps_p = g P xi (engineering shear); P xi = (2 xi_xx - xi_yy, 2 xi_yy - xi_xx, 6 xi_xy) / 3.
    const std::array<Real, 3> dp{g * (2.0 * xi[0] - xi[1]) / 3.0, g * (2.0 * xi[1] - xi[0]) / 3.0, 2.0 * g * xi[2]};
    for (int i = 0; i < 3; ++i) {
      s.sigma[i] = s.back[i] + q * xi[i];
      s.back[i] += h_ * g * xi[i];
    }
    s.eps += 2.0 / 3.0 * g * vm(t, g);
    s.work += s.sigma[0] * dp[0] + s.sigma[1] * dp[1] + s.sigma[2] * dp[2];
    return s.sigma;
  }

  ShellStress stress(const State& s) const { return s.sigma; }

  /// Internal energy per unit volume (force/length^2): the elastic energy the stress holds plus
  /// the plastic work done so far.
  Real energy_density(const State& s, Real shear_factor) const {
    return elastic_.energy_density(s, shear_factor) + s.work;
  }

 private:
  /// A step's trial point: xi_trial in the diagonal basis, the plastic strain, the rate, dt.
  struct Trial {
    std::array<Real, 3> a;
    Real eps, rate, dt;
  };

  /// |xi(g)|_vm = sqrt(a0^2 / 2 + 3/2 a1^2 + 3 a2^2) of the relative stress after g.
  Real vm(const Trial& t, Real g) const {
    const Real b0 = t.a[0] / (1.0 + g * (c_[0] + h_));
    const Real b1 = t.a[1] / (1.0 + g * (c_[1] + h_));
    const Real b2 = t.a[2] / (1.0 + g * (c_[2] + h_));
    return std::sqrt(0.5 * b0 * b0 + 1.5 * b1 * b1 + 3.0 * b2 * b2);
  }
  /// The consistency residual at g: positive outside the yield surface.
  Real residual(const Trial& t, Real g) const {
    const Real v = vm(t, g);
    return v - law_.flow_stress(t.eps, 2.0 / 3.0 * g * v, t.rate, t.dt);
  }
  /// The root g > 0 of the residual (r0 = residual(0) > 0): bracketed by doubling from the
  /// radial-return estimate, then the Illinois method until the bracket stops shrinking.
  Real solve(const Trial& t, Real r0) const {
    Real lo = 0.0, flo = r0;
    Real hi = 0.5 * r0 / (vm(t, 0.0) * c_[1]), fhi = residual(t, hi);
    for (int k = 0; k < 200 && fhi > 0.0; ++k) {
      lo = hi;
      flo = fhi;
      hi *= 2.0;
      fhi = residual(t, hi);
    }
    // flo, fhi: the residuals at the ends, halved by the Illinois rule; rlo, rhi: unscaled.
    Real rlo = flo, rhi = fhi;
    int side = 0;
    for (int k = 0; k < 200 && rhi != 0.0; ++k) {
      const Real g = (lo * fhi - hi * flo) / (fhi - flo);
      if (!(g > lo && g < hi)) break;  // the bracket is at round-off
      const Real fg = residual(t, g);
      if (fg > 0.0) {
        lo = g;
        flo = rlo = fg;
        if (side == -1) fhi *= 0.5;
        side = -1;
      } else {
        hi = g;
        fhi = rhi = fg;
        if (side == 1) flo *= 0.5;
        side = 1;
      }
    }
    return rlo < -rhi ? lo : hi;
  }

  /// The effective total strain rate sqrt(2/3 D:D) with d_zz = -(d_xx + d_yy) (the isochoric
  /// thickness rate of plastic flow; the plane-stress d_zz is not known before the return).
  static Real effective_rate(const ShellRate& d) {
    const Real dzz = -(d.xx + d.yy);
    const Real dd = d.xx * d.xx + d.yy * d.yy + dzz * dzz + 0.5 * (d.xy * d.xy + d.yz * d.yz + d.xz * d.xz);
    return std::sqrt(2.0 / 3.0 * dd);
  }

  Law law_;
  ElasticShell elastic_;
  std::array<Real, 3> c_{};  ///< the eigenvalues of C P: E / (3 (1 - nu)), 2 G, 2 G
  Real h_ = 0.0;             ///< 2/3 Hk
};

}  // namespace slideline
