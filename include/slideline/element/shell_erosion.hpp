#pragma once
/// Erosion of Belytschko-Tsay shells (element_erosion.hpp, erosion_criteria.hpp): the checks a
/// shell block makes when erosion is enabled, and the verdict on one element from the laws'
/// states at its through-thickness points. Kept apart from shell_block.hpp (its size).
#include <array>
#include <string>

#include "slideline/core/error.hpp"
#include "slideline/element/cell_output.hpp"
#include "slideline/element/erosion_criteria.hpp"
#include "slideline/element/shell_bt.hpp"
#include "slideline/mesh/corner_buffer.hpp"

namespace slideline::shell_erosion {

/// Refuses what a shell part (`part_id`, `quads` of `elements` quadrilaterals, `points`
/// through-thickness points) cannot erode by: a failure strain without a plastic law, a stress or
/// strain threshold on a law without stress (*MAT_NULL: no plane-stress normal strain either), C0
/// triangles, NUMFIP beyond the points.
template <class State>
void check(const ErosionCriteria& k, Id part_id, Index quads, Index elements, int points) {
  const std::string part = "part " + std::to_string(part_id);
  if constexpr (!requires(const State& s) { s.eps; })
    if (k.plastic_strain > 0.0) throw NotImplementedError(part + ": a failure strain needs a plastic law");
  if constexpr (!requires(const State& s) { s.sigma; })
    if (k.needs_stress())
      throw NotImplementedError(part + ": its material carries no stress, so a stress criterion of"
                                " *MAT_ADD_EROSION can never hold");
  if constexpr (!requires(const State& s) { s.sigma; })
    if (k.needs_strain())
      throw NotImplementedError(part + ": its material carries no stress, so the normal strain of plane stress is not"
                                " defined: the strain criteria of *MAT_ADD_EROSION are not implemented on it");
  if (k.max_relative_volume > 0.0 || k.min_relative_volume > 0.0)
    throw NotImplementedError(part + ": TEROD / CEROD of *MAT_NULL erode solids; a shell has no relative volume");
  if (quads < elements) throw NotImplementedError(part + ": erosion of C0 triangles is not implemented");
  if (k.has_thresholds() && k.points_needed(points) > points)
    throw InputError(part + ": NUMFIP of *MAT_ADD_EROSION asks for " + std::to_string(k.points_needed(points)) +
                     " failed through-thickness points, but its section has " + std::to_string(points));
}

/// Whether a quadrilateral goes, from the states `st` of its `points` through-thickness points
/// after the update, at time `t` with stable step `dt_e`: every point's plastic strain reached
/// the failure strain; or NUMFIP points meet NCS thresholds (each point's law stress in the
/// element frame, sigma_zz = 0, and, read when a strain criterion is set, its accumulated strain
/// `strain[ip]`: xx, yy, zz, xy, yz, xz, shell_thickness::PointStrains); or dt_e < TDEL.
/// The principal values, largest first, of a shell point's strain (xx, yy, zz, xy, yz, xz: the
/// time integral of the rate of deformation in the co-rotating element frame, which is the
/// logarithmic strain while the principal axes of stretch stay fixed in the material, as for the
/// hexahedra's ln V; erosion_criteria.hpp).
inline std::array<Real, 3> principal_log_strains(const std::array<Real, 6>& e) {
  return ErosionCriteria::principal_values(e);
}

template <class State>
bool fails(const ErosionCriteria& k, const State* st, int points, Real t, Real dt_e,
           const std::array<Real, 6>* strain = nullptr) {
  if (k.plastic_strain > 0.0) {
    Real eps = plastic_strain_of(st[0]);
    for (int ip = 1; ip < points; ++ip) eps = std::min(eps, plastic_strain_of(st[ip]));
    if (eps >= k.plastic_strain) return true;
  }
  if (k.has_thresholds()) {
    int failed = 0;
    for (int ip = 0; ip < points; ++ip) {
      std::array<Real, 6> s{};
      if constexpr (requires { st[ip].sigma; }) {
        const auto& p = st[ip].sigma;  // local xx, yy, xy, yz, xz
        s = {p[0], p[1], 0.0, p[2], p[3], p[4]};
      }
      const std::array<Real, 3> e =
          k.needs_strain() ? principal_log_strains(strain[ip]) : std::array<Real, 3>{};
      failed += k.point_fails(s, t, e) ? 1 : 0;
    }
    if (failed >= k.points_needed(points)) return true;
  }
  return k.min_step > 0.0 && dt_e < k.min_step;
}

/// -sum (f . v + m . omega) of the forces and moments in a quadrilateral's corner slots (from s0,
/// m0) at velocities V and angular velocities W: before the element writes its new ones, the power
/// of its last forces at this step's rates (the first half of its trapezoidal work).
inline Real previous_corner_power(const CornerBuffer& c, Index s0, Index m0, const shell_bt::NodeMat& V,
                                  const shell_bt::NodeMat& W) {
  Real p = 0.0;
  for (int k = 0; k < 4; ++k)
    p -= c.force.x[s0 + k] * V(k, 0) + c.force.y[s0 + k] * V(k, 1) + c.force.z[s0 + k] * V(k, 2) +
         c.moment.x[m0 + k] * W(k, 0) + c.moment.y[m0 + k] * W(k, 1) + c.moment.z[m0 + k] * W(k, 2);
  return p;
}

}  // namespace slideline::shell_erosion
