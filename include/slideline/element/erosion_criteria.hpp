#pragma once
/// The criteria that delete an element (docs/solver.md, "Failure and erosion"): the material's own
/// failure strain (FS of *MAT_PLASTIC_KINEMATIC, FAIL of *MAT_PIECEWISE_LINEAR_PLASTICITY), the
/// stress, strain and time criteria of *MAT_ADD_EROSION (MXPRES, MNPRES, SIGP1, SIGVM, MNEPS,
/// EFFEPS, VOLEPS, MXEPS, EPSSH, FAILTM, combined by NCS, counted over a shell's through-thickness
/// points by NUMFIP), and a minimum element step (TDEL of *MAT_PIECEWISE_LINEAR_PLASTICITY). Any
/// one of the three groups deletes.
///
/// Stresses are Cauchy stresses of the law (without bulk viscosity and stiffness damping), in the
/// order xx, yy, zz, xy, yz, xz (force/length^2); pressure p = -(xx + yy + zz) / 3 is positive in
/// compression, as LS-DYNA's.
///
/// Strains are the principal values e1 >= e2 >= e3 of the logarithmic (Hencky) strain in the
/// current configuration, ln V = ln(F F^T) / 2 (F the deformation gradient): the integral of the
/// rate of deformation D over the history for any motion whose principal axes of stretch stay
/// fixed in the material, and objective. Its trace is ln J (J the volume ratio).
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
  Threshold mxpres;  ///< fails when p > MXPRES (force/length^2)
  Threshold mnpres;  ///< fails when p < MNPRES
  Threshold sigp1;   ///< fails when the largest principal stress > SIGP1
  Threshold sigvm;   ///< fails when the von Mises stress > SIGVM
  Threshold failtm;  ///< fails when the time t >= FAILTM
  Threshold mneps;   ///< fails when the smallest principal strain e3 < MNEPS
  Threshold effeps;  ///< fails when the effective strain sqrt(2/3 e'_ij e'_ij) > EFFEPS
  Threshold voleps;  ///< fails when the volumetric strain ln J > VOLEPS (> 0), < VOLEPS (< 0)
  Threshold mxeps;   ///< fails when the largest principal strain e1 > MXEPS
  Threshold epssh;   ///< fails when the tensorial shear strain (e1 - e3) / 2 > EPSSH
  /// NCS: how many of the thresholds above must hold at once at a point (>= 1).
  int ncs = 1;
  /// NUMFIP of *MAT_ADD_EROSION (shells): > 0 the number of through-thickness points that must
  /// fail; in [-100, 0) minus the percentage of them; below -100, |NUMFIP| - 100 points.
  Real numfip = 1.0;

  /// TDEL: an element whose stable step (time, before the run's scale factor TSSFAC) falls below
  /// it is deleted; 0: none.
  Real min_step = 0.0;
  /// ERODE of *CONTROL_TIMESTEP (solids): the element is also deleted when its step falls below
  /// TSMIN / TSSFAC; min_step is raised to that once the first step is known
  /// (ElementErosion::set_step_floor).
  bool erode_below_tsmin = false;
  /// TEROD / CEROD of *MAT_NULL (solids): the element is deleted when its relative volume V/V0
  /// exceeds max_relative_volume or falls below min_relative_volume; 0: not used.
  Real max_relative_volume = 0.0;
  Real min_relative_volume = 0.0;

  /// Whether a *MAT_ADD_EROSION threshold is on.
  bool has_thresholds() const { return mxpres.on || mnpres.on || sigp1.on || sigvm.on || failtm.on || needs_strain(); }
  /// Whether a threshold reads the strain.
  bool needs_strain() const { return mneps.on || effeps.on || voleps.on || mxeps.on || epssh.on; }
  /// Whether a threshold reads the stress.
  bool needs_stress() const { return mxpres.on || mnpres.on || sigp1.on || sigvm.on; }
  /// Whether anything can delete an element.
  bool any() const {
    return plastic_strain > 0.0 || has_thresholds() || min_step > 0.0 || erode_below_tsmin ||
           max_relative_volume > 0.0 || min_relative_volume > 0.0;
  }

  /// The number of *MAT_ADD_EROSION thresholds that hold at a point of stress `s` and principal
  /// logarithmic strains `e` (descending; read only when needs_strain()) at time `t`. A threshold
  /// holds once it is passed, strictly (the manual: "if the value is exceeded"): so a threshold of
  /// 0 kept by EXCL != 0 holds in the first tension, not at rest (the manual's own example, MNPRES
  /// = 0 with EXCL to keep a material out of tension, would otherwise delete every element at t = 0).
  int thresholds_met(const std::array<Real, 6>& s, Real t, const std::array<Real, 3>& e = {}) const {
    int n = 0;
    if (mxpres.on || mnpres.on) {
      const Real p = -(s[0] + s[1] + s[2]) / 3.0;
      n += (mxpres.on && p > mxpres.value) ? 1 : 0;
      n += (mnpres.on && p < mnpres.value) ? 1 : 0;
    }
    if (sigp1.on && max_principal(s) > sigp1.value) ++n;
    if (sigvm.on && von_mises(s) > sigvm.value) ++n;
    if (failtm.on && t >= failtm.value) ++n;
    if (needs_strain()) {
      n += (mxeps.on && e[0] > mxeps.value) ? 1 : 0;
      n += (mneps.on && e[2] < mneps.value) ? 1 : 0;
      n += (epssh.on && 0.5 * (e[0] - e[2]) > epssh.value) ? 1 : 0;
      if (voleps.on) {
        const Real v = e[0] + e[1] + e[2];
        n += (voleps.value > 0.0 ? v > voleps.value : v < voleps.value) ? 1 : 0;
      }
      n += (effeps.on && effective_strain(e) > effeps.value) ? 1 : 0;
    }
    return n;
  }
  /// Whether a point of stress `s` and principal strains `e` fails at time `t` (NCS thresholds
  /// hold at once).
  bool point_fails(const std::array<Real, 6>& s, Real t, const std::array<Real, 3>& e = {}) const {
    return has_thresholds() && thresholds_met(s, t, e) >= ncs;
  }

  /// How many of `points` through-thickness points must fail for a shell to go (NUMFIP).
  int points_needed(int points) const {
    if (numfip >= 0.0) return std::max(1, static_cast<int>(numfip));
    if (numfip < -100.0) return static_cast<int>(-numfip - 100.0);
    // A percentage: the least count whose share of the points reaches it.
    const int n = static_cast<int>(std::ceil(-numfip * points / 100.0 - 1e-12));
    return std::max(1, n);
  }

  /// The principal values of a symmetric tensor (xx, yy, zz, xy, yz, xz), largest first:
  /// Eigen's symmetric QR solver on the fixed-size 3x3 matrix (no allocation), accurate to a few
  /// round-offs of the tensor's norm also where two or three principal values coincide (the
  /// closed-form trigonometric root loses half the digits there).
  static std::array<Real, 3> principal_values(const std::array<Real, 6>& s) {
    Mat3 m;
    m << s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2];
    const Eigen::SelfAdjointEigenSolver<Mat3> eig(m, Eigen::EigenvaluesOnly);
    const Vec3& v = eig.eigenvalues();  // ascending
    return {v[2], v[1], v[0]};
  }
  /// The largest principal value of a symmetric tensor (xx, yy, zz, xy, yz, xz).
  static Real max_principal(const std::array<Real, 6>& s) { return principal_values(s)[0]; }

  /// The principal logarithmic strains e1 >= e2 >= e3 of the deformation gradient F (its
  /// determinant > 0): half the logarithms of the eigenvalues of F F^T (the squared principal
  /// stretches).
  static std::array<Real, 3> principal_log_strains(const Mat3& F) {
    const Mat3 b = F * F.transpose();
    const std::array<Real, 3> l = principal_values({b(0, 0), b(1, 1), b(2, 2), b(0, 1), b(1, 2), b(0, 2)});
    return {0.5 * std::log(l[0]), 0.5 * std::log(l[1]), 0.5 * std::log(l[2])};
  }
  /// The effective strain sqrt(2/3 e'_ij e'_ij) of principal strains `e` (e' their deviator).
  static Real effective_strain(const std::array<Real, 3>& e) {
    const Real m = (e[0] + e[1] + e[2]) / 3.0;
    const Real a = e[0] - m, b = e[1] - m, c = e[2] - m;
    return std::sqrt(2.0 / 3.0 * (a * a + b * b + c * c));
  }
  /// von Mises equivalent stress sqrt(3 J2).
  static Real von_mises(const std::array<Real, 6>& s) {
    const Real a = s[0] - s[1], b = s[1] - s[2], c = s[2] - s[0];
    return std::sqrt(0.5 * (a * a + b * b + c * c) + 3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
  }
};

}  // namespace slideline
