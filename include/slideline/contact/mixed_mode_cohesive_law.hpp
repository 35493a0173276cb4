#pragma once
/// The mixed-mode bilinear traction-separation law of *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK
/// OPTION 9 (LS-DYNA: "discrete crack model with power law and B-K damage models ... see *MAT_138";
/// *MAT_COHESIVE_MIXED_MODE; Camanho and Davila, NASA/TM-2002-211737). Per unit area, on the opening
/// delta_I = max(0, delta . n) and the slip delta_II = |tangential part of delta|:
///
///   stiffnesses   EN = CN, ET = CT2CN x CN;  peak tractions T = NFLS, S = SFLS
///   onset (pure)  d1 = T / EN, d2 = S / ET
///   mixity        beta = delta_II / delta_I,  delta_m = sqrt(delta_I^2 + delta_II^2)
///   onset         delta_0 = d1 d2 sqrt((1 + beta^2) / (d2^2 + (beta d1)^2))   (delta_I > 0; else d2)
///   final, power law (XMU = PARAM > 0):
///     delta_F = 2 (1 + beta^2) / delta_0 [ (EN / GIC)^XMU + (ET beta^2 / GIIC)^XMU ]^(-1 / XMU)
///   final, B-K (XMU = -PARAM > 0):
///     delta_F = 2 / (delta_0 (EN + beta^2 ET) / (1 + beta^2)) [GIC + (GIIC - GIC) (beta^2 ET / (EN + beta^2 ET))^XMU]
///   (delta_I = 0: delta_F = 2 GIIC / S in both), GIC = ERATEN, GIIC = ERATES.
///   damage        D = delta_F (delta_m - delta_0) / (delta_m (delta_F - delta_0)), clamped to [0, 1],
///                 never decreasing (the largest reached so far; LS-DYNA keeps the largest delta_m,
///                 which is the same for a proportional path)
///   tractions     t = -(1 - D) (EN delta_I n + ET delta_II);  the closing part of delta . n is not
///                 damaged (it is contact, pushed by the tie's compression stiffness).
/// For a proportional path the energy per unit area to full separation is
///   pure mode I: GIC;  pure mode II: GIIC;  mixed, power law with XMU = 1: G with
///   G_I / GIC + G_II / GIIC = 1, G_I / G_II = EN / (ET beta^2)
/// (the area under the bilinear curve, (1/2) K_m delta_0 delta_F with K_m the mixed-mode secant).
///
/// OPTION 6 uses the same curve with EN = ET (the tie's isotropic penalty stiffness), the onset
/// above (on a proportional path it is the stress criterion (sigma_n / NFLS)^2 + (sigma_s / SFLS)^2
/// = 1 of OPTION 2) and delta_F = PARAM (CCRIT) for every mix (`fixed_final`). Along the path the
/// traction is then (1 - D_m) sigma_0 with D_m = (delta_m - delta_0) / (CCRIT - delta_0), the
/// manual's damage linear in the distance, sigma_0 the traction at onset; D above is the same
/// curve written as a secant damage of the spring. Energy to separation: (1/2) sigma_0 CCRIT.
#include <algorithm>
#include <cmath>

#include "slideline/core/types.hpp"

namespace slideline {

struct MixedModeCohesiveLaw {
  Real en = 0.0;     ///< normal stiffness per unit area (stress / length)
  Real et = 0.0;     ///< tangential stiffness per unit area
  Real t = 0.0;      ///< peak normal traction (NFLS)
  Real s = 0.0;      ///< peak shear traction (SFLS)
  Real gic = 0.0;    ///< mode I energy release rate (ERATEN, stress x length)
  Real giic = 0.0;   ///< mode II energy release rate (ERATES)
  Real xmu = 1.0;    ///< mixing exponent (|PARAM|)
  bool bk = false;   ///< PARAM < 0: Benzeggagh-Kenane; else the power law
  /// > 0: the final separation for every mode mix instead of the energy rule (OPTION 6: PARAM, the
  /// critical distance CCRIT; gic, giic, xmu, bk unused). 0: OPTION 9's energy rule.
  Real fixed_final = 0.0;

  /// Onset and final mixed-mode separations for opening dI >= 0 and slip dII >= 0 (length).
  void separations(Real dI, Real dII, Real& d0, Real& dF) const {
    const Real d1 = t / en, d2 = s / et;
    if (!(dI > 0.0)) {
      d0 = d2;
      dF = fixed_final > 0.0 ? fixed_final : 2.0 * giic / s;
      return;
    }
    const Real b = dII / dI, b2 = b * b;
    d0 = d1 * d2 * std::sqrt((1.0 + b2) / (d2 * d2 + b2 * d1 * d1));
    if (fixed_final > 0.0) {
      dF = fixed_final;
      return;
    }
    if (!bk) {
      const Real sum = std::pow(en / gic, xmu) + std::pow(et * b2 / giic, xmu);
      dF = 2.0 * (1.0 + b2) / d0 * std::pow(sum, -1.0 / xmu);
    } else {
      const Real km = (en + b2 * et) / (1.0 + b2);
      const Real gc = gic + (giic - gic) * std::pow(b2 * et / (en + b2 * et), xmu);
      dF = 2.0 * gc / (d0 * km);
    }
  }

  /// The damage for opening dI >= 0 and slip dII >= 0, not below `previous`.
  Real damage(Real dI, Real dII, Real previous) const {
    const Real dm = std::sqrt(dI * dI + dII * dII);
    Real d0 = 0.0, dF = 0.0;
    separations(dI, dII, d0, dF);
    if (!(dm > d0)) return previous;
    const Real d = dF > d0 ? dF * (dm - d0) / (dm * (dF - d0)) : 1.0;
    return std::clamp(std::max(d, previous), 0.0, 1.0);
  }
};

}  // namespace slideline
