#pragma once
/// The stress update the J2 (von Mises) laws share: the elastic predictor on the Green-Naghdi rate
/// and the radial-return corrector, for T = Real or Lanes. A law supplies only the plastic strain
/// increment (its hardening and rate law): J2Plasticity (j2_plasticity.hpp) in closed form,
/// PiecewisePlasticity (piecewise_plasticity.hpp) by walking its curve.
///
/// The state keeps the stress and the back stress in the unrotated frame (sigma_hat = R^T sigma R,
/// F = R U); a step rotates D into that frame with R(F), adds (lambda tr(d) I + 2 G d) dt and, once
/// the law has its increment d_eps, removes 3 G d_eps xi / |xi|_vm from the stress (xi = s - alpha
/// the trial deviator less the back stress, |xi|_vm = sqrt(3/2 xi:xi)) and adds Hk d_eps xi / |xi|_vm
/// to the back stress (Hk the kinematic hardening modulus).
#include <limits>

#include "slideline/core/tensor3.hpp"
#include "slideline/core/types.hpp"
#include "slideline/material/lane_math.hpp"
#include "slideline/material/polar_rotation.hpp"

namespace slideline {

/// What a J2 law remembers per element (T = Real or Lanes).
template <class T>
struct J2State {
  Tensor3<T> sigma = lane_math::zero_tensor<T>();  ///< unrotated Cauchy stress R^T sigma R (force/length^2)
  Tensor3<T> back = lane_math::zero_tensor<T>();   ///< unrotated back stress (deviatoric)
  T eps = lane_math::zero<T>();                    ///< effective plastic strain
  /// Plastic work per unit reference volume (force/length^2): the sum over the steps of
  /// J sigma : d eps_p, J = det F the step's volume ratio, so that `work` x V0 is the plastic work
  /// of the element, each increment taken at the volume it was done in (as the stress power is
  /// integrated). A density per current volume times the volume at output time is off by the
  /// elastic volume change since (docs/output.md, parts/<id>/plastic_work).
  T work = lane_math::zero<T>();
};

/// Internal energy per unit volume of a J2 state (force/length^2): the elastic energy its stress
/// holds, s':s' / (4 G) + p^2 / (2 K) (small elastic strains), plus the plastic work (per unit
/// reference volume; the two volumes differ by the small elastic volume change).
template <class T>
T j2_energy_density(const J2State<T>& s, Real mu, Real bulk) {
  const T p = (s.sigma[0][0] + s.sigma[1][1] + s.sigma[2][2]) / 3.0;
  T dev2 = lane_math::zero<T>();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const T d = i == j ? T(s.sigma[i][j] - p) : s.sigma[i][j];
      dev2 += d * d;
    }
  return dev2 / (4.0 * mu) + p * p / (2.0 * bulk) + s.work;
}

/// The elastic predictor of a step: the rotation, xi, its von Mises measure and the effective total
/// strain rate sqrt(2/3 D':D') (1/time).
template <class T>
struct J2Trial {
  Tensor3<T> R, xi;
  T vm, rate;
  T jac;  ///< det F: the volume ratio the plastic work increment is weighted by
};

/// Adds the elastic trial increment to `s.sigma` (moduli mu, lambda force/length^2, D 1/time, dt
/// time) and returns the trial.
template <class T>
J2Trial<T> j2_predict(J2State<T>& s, const Tensor3<T>& F, const Tensor3<T>& D, Real dt, Real mu,
                      Real lambda) {
  J2Trial<T> t;
  t.R = polar_rotation(F);
  t.jac = determinant(F);
  const Tensor3<T> d = rotate_to_unrotated(t.R, D);
  const T tr_d = d[0][0] + d[1][1] + d[2][2];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) s.sigma[i][j] += 2.0 * mu * dt * d[i][j];
  for (int i = 0; i < 3; ++i) s.sigma[i][i] += lambda * dt * tr_d;
  const T mean = (s.sigma[0][0] + s.sigma[1][1] + s.sigma[2][2]) / 3.0;
  const T mean_d = tr_d / 3.0;
  T xi2 = lane_math::zero<T>(), d2 = lane_math::zero<T>();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const T dev_d = i == j ? T(d[i][j] - mean_d) : d[i][j];
      t.xi[i][j] = s.sigma[i][j] - s.back[i][j];
      if (i == j) t.xi[i][j] -= mean;
      xi2 += t.xi[i][j] * t.xi[i][j];
      d2 += dev_d * dev_d;
    }
  t.vm = lane_math::root(1.5 * xi2);
  t.rate = lane_math::root((2.0 / 3.0) * d2);
  return t;
}

/// The corrector: returns the trial stress radially by the plastic strain increment `d_eps` (>= 0,
/// zero where elastic), moves the back stress by the kinematic modulus `hk` (force/length^2), and
/// returns the Cauchy stress R sigma_hat R^T.
template <class T>
Tensor3<T> j2_correct(J2State<T>& s, const J2Trial<T>& t, const T& d_eps, Real mu, Real hk) {
  // xi's share that flows: d_eps / |xi|_vm (0 when elastic, so a zero xi is never divided by).
  const T k = d_eps / lane_math::larger(t.vm, lane_math::zero<T>() + std::numeric_limits<Real>::min());
  const T ks = 3.0 * mu * k, kb = hk * k;
  T power = lane_math::zero<T>();  // sigma : xi after the return; d eps_p = 3/2 k xi
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      s.sigma[i][j] -= ks * t.xi[i][j];
      if (hk != 0.0) s.back[i][j] += kb * t.xi[i][j];
      power += s.sigma[i][j] * t.xi[i][j];
    }
  s.eps += d_eps;
  s.work += 1.5 * k * power * t.jac;
  return rotate_to_current(t.R, s.sigma);
}

}  // namespace slideline
