#pragma once
/// The contract between a solid's constitutive law and the element loop that runs it
/// (mfem's HyperelasticModel / Laghos' quadrature data: the law apart from the integrator).
///
/// A law is a small value (its constants) with a nested `State<T>`: what it remembers per element
/// between steps (nothing for a hyperelastic law; the stress and plastic strain for an
/// incremental one). T is `Real` for one element or `Lanes` for a batch of kLanes elements (one
/// per SIMD lane), so the formula is written once, as in core/tensor3.hpp. A value-initialised
/// state is the reference (unstressed) state. The element owns the states (HexBlock keeps one
/// State<Lanes> per batch) and calls `update` once per element and step.
#include <cmath>
#include <concepts>

#include "slideline/core/lanes.hpp"
#include "slideline/core/tensor3.hpp"
#include "slideline/core/types.hpp"

namespace slideline {

/// A solid law: `update(state, F, D, dt)` advances `state` over the step dt (time) and returns the
/// Cauchy stress (force/length^2) at the deformation gradient F (dimensionless), D being the rate
/// of deformation sym(grad v) (1/time); both Tensor3, for T = Real and T = Lanes. The small-strain
/// constants (density mass/length^3, moduli force/length^2, dilatational wave speed length/time)
/// set the time step, the hourglass stiffness, the stiffness damping and the contact stiffness.
template <class M>
concept SolidMaterial =
    std::copy_constructible<M> && std::default_initializable<typename M::template State<Real>> &&
    std::default_initializable<typename M::template State<Lanes>> &&
    requires(const M m, typename M::template State<Real>& s, typename M::template State<Lanes>& sl,
             const Tensor3<Real>& F, const Tensor3<Real>& D, const Tensor3<Lanes>& Fl,
             const Tensor3<Lanes>& Dl, Real dt) {
      { m.update(s, F, D, dt) } -> std::same_as<Tensor3<Real>>;
      { m.update(sl, Fl, Dl, dt) } -> std::same_as<Tensor3<Lanes>>;
      { m.density() } -> std::convertible_to<Real>;
      { m.wave_speed() } -> std::convertible_to<Real>;
      { m.bulk_modulus() } -> std::convertible_to<Real>;
      { m.shear_modulus() } -> std::convertible_to<Real>;
      { m.lame_lambda() } -> std::convertible_to<Real>;
      { m.youngs_modulus() } -> std::convertible_to<Real>;
    };

/// The small-strain isotropic constants a solid law reports (the SolidMaterial queries other than
/// update), written once for every law: a law derives from it and hands its constants over.
class IsotropicModuli {
 public:
  Real density() const { return rho_; }
  Real shear_modulus() const { return mu_; }
  Real lame_lambda() const { return lambda_; }
  Real youngs_modulus() const { return e_; }
  /// K = lambda + 2 G / 3.
  Real bulk_modulus() const { return lambda_ + 2.0 / 3.0 * mu_; }
  /// Small-strain dilatational wave speed sqrt((lambda + 2G) / rho).
  Real wave_speed() const { return std::sqrt((lambda_ + 2.0 * mu_) / rho_); }

 protected:
  IsotropicModuli(Real density, Real youngs, Real shear, Real lambda)
      : rho_(density), e_(youngs), mu_(shear), lambda_(lambda) {}

 private:
  Real rho_, e_, mu_, lambda_;
};

/// The state of a law that remembers nothing (a hyperelastic law: the stress is a function of F).
template <class T>
struct NoState {};

}  // namespace slideline
