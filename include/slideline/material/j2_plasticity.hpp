#pragma once
/// J2 (von Mises) plasticity with bilinear hardening mixed between isotropic and kinematic, and
/// Cowper-Symonds strain-rate scaling of the yield stress: LS-DYNA material 3,
/// *MAT_PLASTIC_KINEMATIC (LS-DYNA Keyword User's Manual Vol. II, MAT_003; Theory Manual,
/// "Elastic-plastic with kinematic hardening").
///
///   plastic hardening modulus  Ep = E Et / (E - Et)            (Et = ETAN, the tangent modulus)
///   yield stress               sigma_y = phi (sigma_0 + beta Ep eps)
///   back stress rate           alpha' = (1 - beta) Ep eps' (3/2) xi / |xi|_vm
///   rate factor                phi = 1 + (rate / C)^(1/P)  (1 when C = 0)
///
/// beta = 1 is isotropic hardening, beta = 0 kinematic; eps the effective plastic strain, xi the
/// deviatoric stress less the back stress, rate the effective total strain rate
/// sqrt(2/3 D':D') (LS-DYNA's VP = 0: the yield stress is scaled by the total strain rate).
///
/// Stress update: hypoelastic, on the Green-Naghdi rate. The state holds the stress and the back
/// stress in the unrotated frame (sigma_hat = R^T sigma R, F = R U); each step rotates D into
/// that frame, adds the elastic trial increment (lambda tr(d) I + 2 G d) dt, and returns the
/// deviatoric part radially onto the yield surface. With linear hardening the radial return is
/// exact in one step: d_eps = <f> / (3 G + phi beta Ep + (1 - beta) Ep), f the trial overstress.
#include "slideline/core/tensor3.hpp"
#include "slideline/core/types.hpp"
#include "slideline/material/lane_math.hpp"
#include "slideline/material/j2_return.hpp"
#include "slideline/material/solid_material.hpp"

namespace slideline {

/// The constants of J2Plasticity (force/length^2 unless said).
struct J2PlasticityConstants {
  Real density = 0.0;  ///< mass/length^3
  Real youngs = 0.0;
  Real poisson = 0.0;
  Real yield = 0.0;    ///< initial yield stress sigma_0
  Real tangent = 0.0;  ///< tangent modulus Et of the bilinear uniaxial curve, 0 <= Et < E
  Real beta = 0.0;     ///< hardening mix: 1 isotropic, 0 kinematic
  Real rate_c = 0.0;   ///< Cowper-Symonds C (1/time); 0: no rate effect
  Real rate_p = 0.0;   ///< Cowper-Symonds P (dimensionless)
};

/// A SolidMaterial (solid_material.hpp) whose state is the unrotated stress, the unrotated back
/// stress and the effective plastic strain `eps`.
class J2Plasticity : public IsotropicModuli {
 public:
  /// sigma, back (unrotated stress and back stress) and `eps`, the effective plastic strain.
  template <class T>
  using State = J2State<T>;

  explicit J2Plasticity(const J2PlasticityConstants& k)
      : IsotropicModuli(k.density, k.youngs, k.youngs / (2.0 * (1.0 + k.poisson)),
                        k.youngs * k.poisson / ((1.0 + k.poisson) * (1.0 - 2.0 * k.poisson))),
        k_(k),
        ep_(k.youngs * k.tangent / (k.youngs - k.tangent)) {}

  const J2PlasticityConstants& constants() const { return k_; }
  /// The plastic hardening modulus Ep = E Et / (E - Et).
  Real hardening_modulus() const { return ep_; }
  /// The rate factor phi at the effective strain rate `rate` (1/time).
  template <class T>
  T rate_factor(const T& rate) const {
    if (!(k_.rate_c > 0.0)) return lane_math::zero<T>() + 1.0;
    return 1.0 + lane_math::power(rate / k_.rate_c, 1.0 / k_.rate_p);
  }

  /// The yield stress phi (sigma_0 + beta Ep eps) at the rate factor `phi` and the effective
  /// plastic strain `eps` (force/length^2).
  template <class T>
  T yield_radius(const T& phi, const T& eps) const {
    return phi * (k_.yield + k_.beta * ep_ * eps);
  }
  /// The yield stress after a plastic increment `d_eps` from `eps` at the effective total strain
  /// rate `rate` (1/time); dt unused (the J2 plane-stress return, shell_plasticity.hpp, asks every
  /// law the same way).
  Real flow_stress(Real eps, Real d_eps, Real rate, Real /*dt*/) const {
    return yield_radius(rate_factor(rate), eps + d_eps);
  }
  /// The kinematic hardening modulus (1 - beta) Ep: the back stress moves by it times d_eps along
  /// the flow direction.
  Real kinematic_modulus() const { return (1.0 - k_.beta) * ep_; }
  /// Whether the yield stress depends on the strain rate.
  bool rate_dependent() const { return k_.rate_c > 0.0; }

  /// Internal energy per unit volume of a state (j2_return.hpp), force/length^2.
  template <class T>
  T energy_density(const State<T>& s) const {
    return j2_energy_density(s, shear_modulus(), bulk_modulus());
  }

  /// The SolidMaterial step: advances the state over dt by D (1/time), rotated into the frame of
  /// F's polar rotation (j2_return.hpp), and returns the Cauchy stress R sigma_hat R^T.
  template <class T>
  Tensor3<T> update(State<T>& s, const Tensor3<T>& F, const Tensor3<T>& D, Real dt) const {
    const Real mu = shear_modulus();
    const J2Trial<T> t = j2_predict(s, F, D, dt, mu, lame_lambda());
    const T phi = rate_factor(t.rate);
    const T over = t.vm - yield_radius(phi, s.eps);
    const T d_eps = lane_math::larger(over, lane_math::zero<T>()) /
                    (3.0 * mu + phi * k_.beta * ep_ + (1.0 - k_.beta) * ep_);
    return j2_correct(s, t, d_eps, mu, (1.0 - k_.beta) * ep_);
  }

 private:
  J2PlasticityConstants k_;
  Real ep_;
};

}  // namespace slideline
