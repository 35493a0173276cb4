#pragma once
/// J2 plasticity with isotropic hardening along a piecewise linear curve of yield stress against
/// effective plastic strain, and strain-rate scaling of the yield stress: LS-DYNA material 24,
/// *MAT_PIECEWISE_LINEAR_PLASTICITY (LS-DYNA Keyword User's Manual Vol. II, MAT_024).
///
///   yield stress  sigma_y = phi(rate) * curve(eps)
///   phi           1 + (rate / C)^(1/P) (Cowper-Symonds), or a curve of phi against the rate, or 1
///   rate          VP = 0: the effective total strain rate sqrt(2/3 D':D');
///                 VP = 1: the effective plastic strain rate d_eps / dt (viscoplastic: the
///                 increment solves |xi_trial|_vm - 3 G d_eps = phi(d_eps / dt) curve(eps + d_eps))
///
/// The curve is extrapolated past its last point with its last slope, and is flat from zero plastic
/// strain to a first point beyond zero. The stress update is the J2 predictor / radial-return corrector (j2_return.hpp) on the
/// Green-Naghdi rate; the increment is exact for a piecewise linear curve at fixed phi (VP = 0:
/// solved segment by segment), and found by bisection to round-off for VP = 1.
#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "slideline/core/lanes.hpp"
#include "slideline/core/tensor3.hpp"
#include "slideline/core/types.hpp"
#include "slideline/material/j2_return.hpp"
#include "slideline/material/solid_material.hpp"

namespace slideline {

/// The constants of PiecewisePlasticity.
struct PiecewisePlasticityConstants {
  Real density = 0.0;  ///< mass/length^3
  Real youngs = 0.0;   ///< force/length^2
  Real poisson = 0.0;
  /// (effective plastic strain, yield stress force/length^2), strains increasing, at least one point.
  std::vector<std::pair<Real, Real>> hardening;
  Real rate_c = 0.0;  ///< Cowper-Symonds C (1/time); 0: none
  Real rate_p = 0.0;  ///< Cowper-Symonds P
  /// (strain rate 1/time, factor phi), rates increasing; constant outside. Empty: none.
  std::vector<std::pair<Real, Real>> rate_curve;
  bool viscoplastic = false;  ///< VP = 1
};

/// A SolidMaterial (solid_material.hpp) whose state is J2State (sigma, back = 0, `eps`).
class PiecewisePlasticity : public IsotropicModuli {
 public:
  template <class T>
  using State = J2State<T>;

  explicit PiecewisePlasticity(PiecewisePlasticityConstants k)
      : IsotropicModuli(k.density, k.youngs, k.youngs / (2.0 * (1.0 + k.poisson)),
                        k.youngs * k.poisson / ((1.0 + k.poisson) * (1.0 - 2.0 * k.poisson))),
        k_(std::move(k)) {
    auto& h = k_.hardening;  // flat from zero plastic strain to a first point beyond it
    if (!h.empty() && h.front().first > 0.0) h.insert(h.begin(), {0.0, h.front().second});
  }

  const PiecewisePlasticityConstants& constants() const { return k_; }

  /// Why these constants make no law, or empty.
  std::string problem() const {
    const auto& h = k_.hardening;
    if (h.empty()) return "the yield curve has no points";
    if (h.front().first < 0.0 || !(h.front().second > 0.0))
      return "the yield curve must start at a non-negative plastic strain with a positive stress";
    for (std::size_t i = 1; i < h.size(); ++i)
      if (!(h[i].first > h[i - 1].first)) return "the plastic strains of the yield curve must increase";
    for (std::size_t i = 0; i + 1 < h.size(); ++i)
      if (!(slope(i) > -3.0 * shear_modulus()))
        return "the yield curve softens faster than -3 G (the return is not unique)";
    for (std::size_t i = 1; i < k_.rate_curve.size(); ++i)
      if (!(k_.rate_curve[i].first > k_.rate_curve[i - 1].first))
        return "the strain rates of the rate-scaling curve must increase";
    return {};
  }

  /// The yield curve at the effective plastic strain e.
  Real yield_stress(Real e) const {
    const auto& h = k_.hardening;
    const std::size_t k = segment(e);
    return h[k].second + slope(k) * (e - h[k].first);
  }

  /// phi at the strain rate `rate` (1/time).
  Real rate_factor(Real rate) const {
    if (k_.rate_c > 0.0) return 1.0 + std::pow(std::max(rate, 0.0) / k_.rate_c, 1.0 / k_.rate_p);
    const auto& c = k_.rate_curve;
    if (c.empty()) return 1.0;
    if (rate <= c.front().first) return c.front().second;
    if (rate >= c.back().first) return c.back().second;
    const auto it = std::upper_bound(c.begin(), c.end(), rate, [](Real r, const auto& p) { return r < p.first; });
    const auto& a = *(it - 1);
    const auto& b = *it;
    return a.second + (b.second - a.second) * (rate - a.first) / (b.first - a.first);
  }

  /// The yield stress after a plastic increment `d_eps` from `eps` (force/length^2): phi curve(eps +
  /// d_eps), phi at the total strain rate `rate` (1/time), or with VP = 1 at d_eps / dt.
  Real flow_stress(Real eps, Real d_eps, Real rate, Real dt) const {
    return rate_factor(k_.viscoplastic ? d_eps / dt : rate) * yield_stress(eps + d_eps);
  }
  /// Isotropic hardening only: no back stress.
  Real kinematic_modulus() const { return 0.0; }
  /// Whether the yield stress depends on the strain rate.
  bool rate_dependent() const { return k_.rate_c > 0.0 || !k_.rate_curve.empty(); }

  /// The plastic strain increment of one element: `vm` the trial von Mises stress, `eps` the
  /// plastic strain, `rate` the total strain rate, dt the step.
  Real increment(Real vm, Real eps, Real rate, Real dt) const {
    const Real g3 = 3.0 * shear_modulus();
    if (k_.viscoplastic) {
      if (!(vm > flow_stress(eps, 0.0, 0.0, 1.0))) return 0.0;
      Real lo = 0.0, hi = vm / g3;  // the residual is positive at lo and not positive at hi
      for (int it = 0; it < 60; ++it) {
        const Real mid = 0.5 * (lo + hi);
        (vm - g3 * mid - flow_stress(eps, mid, rate, dt) > 0.0 ? lo : hi) = mid;
      }
      return 0.5 * (lo + hi);
    }
    const Real phi = rate_factor(rate);
    if (!(vm > phi * yield_stress(eps))) return 0.0;
    const auto& h = k_.hardening;
    for (std::size_t k = segment(eps);; ++k) {
      const Real d = (vm - phi * (h[k].second + slope(k) * (eps - h[k].first))) / (g3 + phi * slope(k));
      if (k + 1 >= h.size() || eps + d <= h[k + 1].first) return d;
    }
  }

  /// Internal energy per unit volume of a state (j2_return.hpp), force/length^2.
  template <class T>
  T energy_density(const State<T>& s) const {
    return j2_energy_density(s, shear_modulus(), bulk_modulus());
  }

  /// The SolidMaterial step (j2_return.hpp); the increment is solved one element (lane) at a time.
  template <class T>
  Tensor3<T> update(State<T>& s, const Tensor3<T>& F, const Tensor3<T>& D, Real dt) const {
    const Real mu = shear_modulus();
    const J2Trial<T> t = j2_predict(s, F, D, dt, mu, lame_lambda());
    T d_eps;
    if constexpr (std::is_same_v<T, Real>) {
      d_eps = increment(t.vm, s.eps, t.rate, dt);
    } else {
      for (int l = 0; l < kLanes; ++l) d_eps[l] = increment(t.vm[l], s.eps[l], t.rate[l], dt);
    }
    return j2_correct(s, t, d_eps, mu, 0.0);
  }

 private:
  /// The segment holding plastic strain e: the last point at or below e (the first point when e is
  /// below it, the last when beyond).
  std::size_t segment(Real e) const {
    const auto& h = k_.hardening;
    const auto it = std::upper_bound(h.begin(), h.end(), e, [](Real x, const auto& p) { return x < p.first; });
    return it == h.begin() ? 0 : static_cast<std::size_t>(it - h.begin()) - 1;
  }
  /// The slope of the segment starting at point k (the last one's continues the one before it;
  /// a one-point curve is flat).
  Real slope(std::size_t k) const {
    const auto& h = k_.hardening;
    if (h.size() < 2) return 0.0;
    const std::size_t a = std::min(k, h.size() - 2);
    return (h[a + 1].second - h[a].second) / (h[a + 1].first - h[a].first);
  }

  PiecewisePlasticityConstants k_;
};

}  // namespace slideline
