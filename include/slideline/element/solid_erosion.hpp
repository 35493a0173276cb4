#pragma once
/// Erosion of one-point hexahedra (element_erosion.hpp, erosion_criteria.hpp): the checks the
/// block makes when erosion is enabled and the verdict on one element. Kept apart from
/// hex_block.hpp (its size).
#include <algorithm>
#include <array>
#include <string>

#include "slideline/core/error.hpp"
#include "slideline/core/tensor3.hpp"
#include "slideline/core/lanes.hpp"
#include "slideline/element/cell_output.hpp"
#include "slideline/element/element_erosion.hpp"
#include "slideline/element/erosion_criteria.hpp"

namespace slideline::solid_erosion {

/// Refuses what a part (`part_id`) of one-point solids of law state `State` cannot erode by: a
/// failure strain without a plastic law, NUMFIP asking for more than the one point.
template <class State>
void check(const ErosionCriteria& k, Id part_id) {
  const std::string part = "part " + std::to_string(part_id);
  if constexpr (!requires(const State& s) { s.eps; })
    if (k.plastic_strain > 0.0) throw NotImplementedError(part + ": a failure strain needs a plastic law");
  if (k.has_thresholds() && k.points_needed(1) > 1)
    throw InputError(part + ": NUMFIP of *MAT_ADD_EROSION asks for " + std::to_string(k.points_needed(1)) +
                     " failed points, but a one-point hexahedron has 1");
}

/// Refuses what a part (`part_id`) of element-by-element solids (`form`: "fully integrated
/// hexahedra (ELFORM 2)", "tetrahedra (ELFORM 10)") with `points` integration points, of law state
/// `State`, cannot erode by: a failure strain without a plastic law, NUMFIP asking for more failed
/// points than the element has. The *MAT_ADD_EROSION thresholds, TEROD / CEROD and TDEL are judged
/// by the block (point_verdict, volume_fails).
template <class State>
void check_element_by_element(const ErosionCriteria& k, Id part_id, const char* form, int points) {
  const std::string part = "part " + std::to_string(part_id);
  if constexpr (!requires(const State& s) { s.eps; })
    if (k.plastic_strain > 0.0) throw NotImplementedError(part + ": a failure strain needs a plastic law");
  if (k.has_thresholds() && k.points_needed(points) > points)
    throw InputError(part + ": NUMFIP of *MAT_ADD_EROSION asks for " + std::to_string(k.points_needed(points)) +
                     " failed points, but " + form + " have " + std::to_string(points));
}

/// Whether an integration point fails the *MAT_ADD_EROSION thresholds (ErosionCriteria::point_fails)
/// at time `t`: `sigma` the law's Cauchy stress (without bulk viscosity and damping), `F` the
/// deformation gradient the law saw (its principal logarithmic strains are computed only when a
/// strain threshold is on).
inline bool point_verdict(const ErosionCriteria& k, const Tensor3<Real>& sigma, const Tensor3<Real>& F, Real t) {
  if (!k.has_thresholds()) return false;
  const SymTensor6 s{sigma[0][0], sigma[1][1], sigma[2][2], sigma[0][1], sigma[1][2], sigma[0][2]};
  std::array<Real, 3> e{};
  if (k.needs_strain()) {
    Mat3 f;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) f(i, j) = F[i][j];
    e = ErosionCriteria::principal_log_strains(f);
  }
  return k.point_fails(s, t, e);
}

/// The principal logarithmic strains (erosion_criteria.hpp) of lane `l` of a batch's deformation
/// gradients `F` (at the element's centre, the one point: exact for the element's mean motion).
template <class Lanes>
std::array<Real, 3> log_strains(const Tensor3<Lanes>& F, int l) {
  Mat3 f;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) f(i, j) = F[i][j][l];
  return ErosionCriteria::principal_log_strains(f);
}

/// Whether an element goes, after the law's update, at time `t`: its plastic strain `eps` reached
/// the failure strain; or NCS thresholds hold for its law stress `law` and principal logarithmic
/// strains `e` (erosion_criteria.hpp; read only when a strain criterion is set); or its stable
/// step `dt_e` (read only when TDEL is set) is below TDEL.
inline bool fails(const ErosionCriteria& k, Real eps, const SymTensor6& law, Real t, Real dt_e,
                  const std::array<Real, 3>& e = {}) {
  if (k.plastic_strain > 0.0 && eps >= k.plastic_strain) return true;
  if (k.has_thresholds() && k.point_fails(law, t, e)) return true;
  return k.min_step > 0.0 && dt_e < k.min_step;
}

/// A deleted element of a batch `bt` (from element e0; `ne` elements, the spare lanes of a last
/// partial batch repeat the last) is evaluated at its reference geometry at rest (its forces are
/// discarded): its nodes may have gone anywhere since, and an inverted deleted element must not
/// stop the run.
template <class Batch>
void freeze_deleted(Batch& bt, Index e0, const ElementErosion& erosion, Index ne) {
  for (int l = 0; l < kLanes; ++l) {
    if (!erosion.deleted(std::min(e0 + l, ne - 1))) continue;
    for (int k = 0; k < 8; ++k) {
      bt.x[k][l] = bt.x0[k][l];
      bt.y[k][l] = bt.y0[k][l];
      bt.z[k][l] = bt.z0[k][l];
      bt.vx[k][l] = bt.vy[k][l] = bt.vz[k][l] = 0.0;
    }
  }
}

/// Whether an element of relative volume `j` = V/V0 goes by TEROD / CEROD of *MAT_NULL
/// (ErosionCriteria::max_relative_volume, min_relative_volume; 0: not used).
inline bool volume_fails(const ErosionCriteria& k, Real j) {
  return (k.max_relative_volume > 0.0 && j > k.max_relative_volume) ||
         (k.min_relative_volume > 0.0 && j < k.min_relative_volume);
}

}  // namespace slideline::solid_erosion
