#pragma once
/// The criteria that delete an element (docs/solver.md, "Failure and erosion"): the material's own
/// failure strain (FS of *MAT_PLASTIC_KINEMATIC, FAIL of *MAT_PIECEWISE_LINEAR_PLASTICITY), the
/// stress and time criteria of *MAT_ADD_EROSION (MXPRES, MNPRES, SIGP1, SIGVM, FAILTM, combined
/// by NCS, counted over a shell's through-thickness points by NUMFIP), and a minimum element step
/// (TDEL of *MAT_PIECEWISE_LINEAR_PLASTICITY). Any one of the three groups deletes.
///
/// Stresses are Cauchy stresses of the law (without bulk viscosity and stiffness damping), in the
/// order xx, yy, zz, xy, yz, xz (force/length^2); pressure p = -(xx + yy + zz) / 3 is positive in
/// compression, as LS-DYNA's.
#include <algorithm>
#include <array>
#include <cmath>

#include "slideline/core/types.hpp"

namespace slideline {

struct ErosionCriteria {
  /// The material's failure strain (effective plastic strain, dimensionless); 0: none.
  Real plastic_strain = 0.0;

  /// One *MAT_ADD_EROSION threshold: `on` false when the field is excluded (blank, 0 or EXCL).
  struct Threshold {
    bool on = false;
    Real value = 0.0;
  };
  Threshold mxpres;  ///< fails when p >= MXPRES (force/length^2)
  Threshold mnpres;  ///< fails when p <= MNPRES
  Threshold sigp1;   ///< fails when the largest principal stress >= SIGP1
  Threshold sigvm;   ///< fails when the von Mises stress >= SIGVM
  Threshold failtm;  ///< fails when the time t >= FAILTM
  /// NCS: how many of the thresholds above must hold at once at a point (>= 1).
  int ncs = 1;
  /// NUMFIP of *MAT_ADD_EROSION (shells): > 0 the number of through-thickness points that must
  /// fail; in [-100, 0) minus the percentage of them; below -100, |NUMFIP| - 100 points.
  Real numfip = 1.0;

  /// TDEL: an element whose stable step (time, before the run's scale factor TSSFAC) falls below
  /// it is deleted; 0: none.
  Real min_step = 0.0;

  /// Whether a *MAT_ADD_EROSION threshold is on.
  bool has_thresholds() const { return mxpres.on || mnpres.on || sigp1.on || sigvm.on || failtm.on; }
  /// Whether a threshold reads the stress.
  bool needs_stress() const { return mxpres.on || mnpres.on || sigp1.on || sigvm.on; }
  /// Whether anything can delete an element.
  bool any() const { return plastic_strain > 0.0 || has_thresholds() || min_step > 0.0; }

  /// The number of *MAT_ADD_EROSION thresholds that hold at a point of stress `s` at time `t`.
  int thresholds_met(const std::array<Real, 6>& s, Real t) const {
    int n = 0;
    if (mxpres.on || mnpres.on) {
      const Real p = -(s[0] + s[1] + s[2]) / 3.0;
      n += (mxpres.on && p >= mxpres.value) ? 1 : 0;
      n += (mnpres.on && p <= mnpres.value) ? 1 : 0;
    }
    if (sigp1.on && max_principal(s) >= sigp1.value) ++n;
    if (sigvm.on && von_mises(s) >= sigvm.value) ++n;
    if (failtm.on && t >= failtm.value) ++n;
    return n;
  }
  /// Whether a point of stress `s` fails at time `t` (NCS thresholds hold at once).
  bool point_fails(const std::array<Real, 6>& s, Real t) const { return has_thresholds() && thresholds_met(s, t) >= ncs; }

  /// How many of `points` through-thickness points must fail for a shell to go (NUMFIP).
  int points_needed(int points) const {
    if (numfip >= 0.0) return std::max(1, static_cast<int>(numfip));
    if (numfip < -100.0) return static_cast<int>(-numfip - 100.0);
    // A percentage: the least count whose share of the points reaches it.
    const int n = static_cast<int>(std::ceil(-numfip * points / 100.0 - 1e-12));
    return std::max(1, n);
  }

  /// The largest principal value of a symmetric tensor (xx, yy, zz, xy, yz, xz): the largest root
  /// of its characteristic cubic, in the trigonometric form (no iteration, no allocation).
  static Real max_principal(const std::array<Real, 6>& s) {
    const Real m = (s[0] + s[1] + s[2]) / 3.0;
    const Real a = s[0] - m, b = s[1] - m, c = s[2] - m;
    const Real off = s[3] * s[3] + s[4] * s[4] + s[5] * s[5];
    const Real q2 = (a * a + b * b + c * c + 2.0 * off) / 6.0;  // J2 / 3
    if (q2 <= 0.0) return m;
    const Real q = std::sqrt(q2);
    // det of the deviator over q^3, halved: cos(3 theta).
    const Real det = a * (b * c - s[4] * s[4]) - s[3] * (s[3] * c - s[4] * s[5]) + s[5] * (s[3] * s[4] - b * s[5]);
    const Real r = std::clamp(det / (2.0 * q2 * q), Real(-1), Real(1));
    return m + 2.0 * q * std::cos(std::acos(r) / 3.0);
  }
  /// von Mises equivalent stress sqrt(3 J2).
  static Real von_mises(const std::array<Real, 6>& s) {
    const Real a = s[0] - s[1], b = s[1] - s[2], c = s[2] - s[0];
    return std::sqrt(0.5 * (a * a + b * b + c * c) + 3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
  }
};

}  // namespace slideline
