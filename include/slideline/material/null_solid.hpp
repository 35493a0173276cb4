#pragma once
/// *MAT_NULL on solids: no deviatoric stiffness; the pressure of the part's equation of state
/// (equation_of_state.hpp) and the viscous deviatoric stress 2 MU dev(D) (MU a dynamic
/// viscosity: simple shear at the rate gamma' gives the shear stress MU gamma').
///
/// The internal energy E per unit reference volume is the law's state, advanced each step by the
/// work of the pressure and the viscous stress on the trapezoid rule,
///   E1 = E0 - (p0 + p1) / 2 (J1 - J0) + J1 (s : D) dt,     J = V / V0 = det F,
/// and since every EOS here is linear in E (p = A + B E) the update is solved in closed form
/// (implicit in E, no iteration): E1 = (E0 - (p0 + A) dJ / 2 + w) / (1 + B dJ / 2). When the
/// pressure falls below the cutoff PC it is PC, and E1 is the trapezoid with p1 = PC.
/// The hexahedron adds the bulk viscosity's work -q dJ to E after the update (the shock heating
/// an EOS with an energy term needs); the energy ledger books it as bulk-viscosity energy
/// (docs/solver.md).
#include <algorithm>
#include <cmath>
#include <type_traits>

#include "slideline/core/lanes.hpp"
#include "slideline/core/tensor3.hpp"
#include "slideline/core/types.hpp"
#include "slideline/material/equation_of_state.hpp"
#include "slideline/material/lane_math.hpp"

namespace slideline {

/// A SolidMaterial (solid_material.hpp).
class NullSolid {
 public:
  /// `e` E - E0, `dj` J - 1 and `dp` p - p(V0, E0) at the last update (so a value-initialised
  /// state is the reference state), and `sound_speed` (length/time) the element's step reads
  /// (the larger of the current state's and the reference's), set by each update.
  template <class T>
  struct State {
    T e = lane_math::zero<T>();
    T dj = lane_math::zero<T>();
    T dp = lane_math::zero<T>();
    T sound_speed = lane_math::zero<T>();
  };

  /// `density` rho0 (mass/length^3), `pc` the pressure cutoff (<= 0, force/length^2), `mu` the
  /// dynamic viscosity (force time/length^2).
  NullSolid(Real density, Real pc, Real mu, EquationOfState eos)
      : rho_(density), pc_(pc), mu_(mu), eos_(std::move(eos)) {
    const Real e0 = eos_.initial_energy();
    const EquationOfState::Split s = eos_.at(1.0);
    p0_ = std::max(s.pressure(e0), pc_);
    c0sq_ = EquationOfState::sound_speed_squared(s, 1.0, e0, p0_, rho_);
  }

  Real density() const { return rho_; }
  /// The reference sound speed sqrt(dp/drho) at V = V0, E = E0 (0 when the EOS has no stiffness
  /// there: refused by validation).
  Real wave_speed() const { return std::sqrt(std::max(c0sq_, 0.0)); }
  /// The reference bulk modulus rho0 c0^2: the hourglass stiffness, the stiffness damping and the
  /// contact stiffness read it.
  Real bulk_modulus() const { return rho_ * std::max(c0sq_, 0.0); }
  Real shear_modulus() const { return 0.0; }
  Real lame_lambda() const { return bulk_modulus(); }
  /// No Young's modulus: the forms that need one (IHQ 6, 10) are refused for null solids.
  Real youngs_modulus() const { return 0.0; }
  Real pressure_cutoff() const { return pc_; }
  Real viscosity() const { return mu_; }
  const EquationOfState& eos() const { return eos_; }
  /// The pressure at the reference state.
  Real reference_pressure() const { return p0_; }

  /// E per unit reference volume (force/length^2), for the cell output.
  template <class T>
  T energy_density(const State<T>& s) const {
    return s.e + eos_.initial_energy();
  }

  /// SolidMaterial::update: the relative volume J = det F.
  template <class T>
  Tensor3<T> update(State<T>& s, const Tensor3<T>& F, const Tensor3<T>& D, Real dt) const {
    return update_volume(s, determinant(F), D, dt);
  }

  /// The update at relative volume `j` = V/V0: the one-point hexahedron hands its volume ratio
  /// (exact for any shape) rather than det F of its centroid's gradient, which departs from it in
  /// an element with hourglass deformation (hex_block.hpp).
  template <class T>
  Tensor3<T> update_volume(State<T>& s, const T& j, const Tensor3<T>& D, Real dt) const {
    const T mean = (D[0][0] + D[1][1] + D[2][2]) / 3.0;
    Tensor3<T> sigma;
    T power = lane_math::zero<T>();
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        sigma[a][b] = (2.0 * mu_) * (a == b ? T(D[a][b] - mean) : D[a][b]);
        power += sigma[a][b] * D[a][b];
      }
    const T work = j * power * dt;  // viscous work per unit reference volume over the step
    if constexpr (std::is_same_v<T, Real>) {
      point(s.e, s.dj, s.dp, s.sound_speed, j, work);
    } else {
      for (int l = 0; l < kLanes; ++l) point(s.e[l], s.dj[l], s.dp[l], s.sound_speed[l], j[l], work[l]);
    }
    for (int a = 0; a < 3; ++a) sigma[a][a] -= s.dp + p0_;
    return sigma;
  }

 private:
  /// One point's pressure and energy update to relative volume j with viscous work `work`.
  void point(Real& e, Real& dj, Real& dp, Real& c, Real j, Real work) const {
    const Real e_old = eos_.initial_energy() + e;
    const Real p_old = p0_ + dp;
    const Real d = j - (1.0 + dj);
    const EquationOfState::Split s = eos_.at(j);
    Real e_new = (e_old - 0.5 * (p_old + s.a) * d + work) / (1.0 + 0.5 * s.b * d);
    Real p_new = s.pressure(e_new);
    const bool cut = p_new < pc_;
    if (cut) {
      p_new = pc_;
      e_new = e_old - 0.5 * (p_old + pc_) * d + work;
    }
    e = e_new - eos_.initial_energy();
    dj = j - 1.0;
    dp = p_new - p0_;
    // At the cutoff the pressure has no tangent: the reference speed (the floor) sets the step.
    const Real csq = cut ? 0.0 : EquationOfState::sound_speed_squared(s, j, e_new, p_new, rho_);
    c = std::sqrt(std::max(csq, c0sq_));
  }

  Real rho_, pc_, mu_;
  EquationOfState eos_;
  Real p0_ = 0.0, c0sq_ = 0.0;
};

}  // namespace slideline
