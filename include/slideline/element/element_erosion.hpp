#pragma once
/// Element erosion from the material's failure strain (*MAT_PLASTIC_KINEMATIC FS,
/// *MAT_PIECEWISE_LINEAR_PLASTICITY FAIL; docs/solver.md, "Failure and erosion"): the bookkeeping
/// an element block keeps when its elements can be deleted. An element is deleted at the first
/// force evaluation whose plastic strain (after the law's update) reaches the failure strain; from
/// then on its forces, hourglass forces and stress are zero, it votes no step, and its mass stays
/// on its nodes. The energy it held (the work of its stress and hourglass forces up to its last
/// evaluation before deletion, integrated per element) is booked as eroded energy (solver/
/// energy_ledger.hpp), so the balance still closes.
///
/// Everything is sized by enable() (no allocation in a step); each element is written only by the
/// chunk that holds it and the chunk sums are reduced in chunk order, so the deletions and the
/// eroded energies do not depend on the thread count.
#include <algorithm>
#include <limits>
#include <span>
#include <vector>

#include "slideline/core/parallel.hpp"
#include "slideline/core/types.hpp"
#include "slideline/element/erosion_criteria.hpp"

namespace slideline {

class ElementErosion {
 public:
  /// True once enable() was called with a criterion (erosion_criteria.hpp).
  bool active() const { return active_; }
  /// The effective plastic strain (dimensionless) at which an element is deleted; 0: never.
  Real failure_strain() const { return fail_; }
  /// What deletes an element.
  const ErosionCriteria& criteria() const { return criteria_; }
  /// The time deletions are stamped with (that of the force evaluation running).
  Real time() const { return time_; }

  /// Enables erosion at the failure strain `fail` > 0 for `count` elements (`padded` >= count
  /// entries, for blocks that run whole batches of lanes).
  void enable(Real fail, Index count, Index padded) {
    ErosionCriteria c;
    c.plastic_strain = fail;
    enable(c, count, padded);
  }
  /// Enables erosion by `criteria` (at least one set) for `count` elements (`padded` >= count).
  void enable(const ErosionCriteria& criteria, Index count, Index padded) {
    criteria_ = criteria;
    active_ = criteria.any();
    fail_ = criteria.plastic_strain;
    tdel_ = criteria.min_step;
    count_ = count;
    deleted_at_.assign(static_cast<std::size_t>(padded), -1.0);
    held_internal_.assign(static_cast<std::size_t>(padded), 0.0);
    held_hourglass_.assign(static_cast<std::size_t>(padded), 0.0);
    const auto nc = static_cast<std::size_t>(chunk_count(count));
    chunk_internal_.assign(nc, 0.0);
    chunk_hourglass_.assign(nc, 0.0);
    chunk_deleted_.assign(nc, 0);
  }

  /// ERODE (criteria().erode_below_tsmin): from now on an element whose stable step (before the
  /// run's scale factor) is below `floor` (time: TSMIN / TSSFAC) is deleted, as by TDEL (the larger
  /// of the two applies). No effect without erode_below_tsmin.
  void set_step_floor(Real floor) {
    if (criteria_.erode_below_tsmin) criteria_.min_step = std::max(tdel_, floor);
  }

  /// The time (of the force evaluation about to run) that deletions are stamped with.
  void set_time(Real t) { time_ = t; }

  /// Whether element e is deleted.
  bool deleted(Index e) const { return deleted_at_[static_cast<std::size_t>(e)] >= 0.0; }
  /// Per element (element order), the time it was deleted at; -1 while it is not.
  std::span<const Real> deletion_times() const { return {deleted_at_.data(), static_cast<std::size_t>(count_)}; }
  /// How many elements are deleted.
  Index deleted_count() const {
    Index n = 0;
    for (Index e = 0; e < count_; ++e) n += deleted(e) ? 1 : 0;
    return n;
  }

  /// One element's evaluation: `eps` its plastic strain after the law's update, `internal` and
  /// `hourglass` the powers of its stress and hourglass forces (force x length / time) over the
  /// step `dt` (time); `chunk` the chunk (parallel.hpp) that holds it. Returns true when the
  /// element is deleted (now or before): the caller then zeroes its forces, powers and step.
  /// Deletes it (stamping the time, booking what it held) when eps reaches the failure strain;
  /// else adds the step's work to what it holds.
  bool update(Index e, Index chunk, Real eps, Real internal, Real hourglass, Real dt) {
    return update_failed(e, chunk, fail_ > 0.0 && eps >= fail_, internal, hourglass, dt);
  }
  /// update() with the verdict of the criteria given: `fails` deletes element e now.
  /// `internal_prev`, `hourglass_prev`: the powers of the last evaluation's forces at this step's
  /// rates, the first half of the step's trapezoidal work (then `internal`, `hourglass` are the
  /// second half, this evaluation's); a deleted element's forces are zero from this evaluation on,
  /// so it books the first half alone.
  bool update_failed(Index e, Index chunk, bool fails, Real internal, Real hourglass, Real dt,
                     Real internal_prev = 0.0, Real hourglass_prev = 0.0) {
    const auto i = static_cast<std::size_t>(e);
    if (deleted_at_[i] >= 0.0) return true;
    held_internal_[i] += internal_prev * dt;
    held_hourglass_[i] += hourglass_prev * dt;
    if (fails) {
      deleted_at_[i] = time_;
      chunk_internal_[static_cast<std::size_t>(chunk)] += held_internal_[i];
      chunk_hourglass_[static_cast<std::size_t>(chunk)] += held_hourglass_[i];
      ++chunk_deleted_[static_cast<std::size_t>(chunk)];
      return true;
    }
    held_internal_[i] += internal * dt;
    held_hourglass_[i] += hourglass * dt;
    return false;
  }

  /// The energies the elements deleted at the last evaluation held (chunk order), added to
  /// `internal` and `hourglass`; returns how many were deleted then. Clears the chunk sums for
  /// the next evaluation (call once per evaluation, after the element loop).
  Index reduce(Real& internal, Real& hourglass) {
    Index n = 0;
    for (std::size_t c = 0; c < chunk_deleted_.size(); ++c) {
      if (chunk_deleted_[c] == 0) continue;
      internal += chunk_internal_[c];
      hourglass += chunk_hourglass_[c];
      n += chunk_deleted_[c];
      chunk_internal_[c] = chunk_hourglass_[c] = 0.0;
      chunk_deleted_[c] = 0;
    }
    return n;
  }

 private:
  ErosionCriteria criteria_;
  bool active_ = false;
  Real fail_ = 0.0;
  Real tdel_ = 0.0;  ///< the criteria's own min_step (TDEL), under a step floor
  Real time_ = 0.0;
  Index count_ = 0;
  std::vector<Real> deleted_at_;                     ///< per element: deletion time, -1 alive
  std::vector<Real> held_internal_, held_hourglass_;  ///< per element: work of its forces so far
  std::vector<Real> chunk_internal_, chunk_hourglass_;
  std::vector<Index> chunk_deleted_;
};

/// One element of an element-by-element block (TetBlock, FullHexBlock) under erosion: a deleted
/// element's corner forces are zeroed (`zero(e)`) and it adds nothing (R{}, step +max); a live one
/// runs `forces(e)` (R: dt, visc, damp, power, failed), then is deleted when `strain(e)` (its
/// plastic strain after the update) reaches the failure strain or its step r.dt falls below the
/// criteria's min_step (TDEL). Without erosion: `forces(e)`.
template <class R, class Forces, class Strain, class Zero>
R eroding_element(ElementErosion& erosion, Index e, Real dt, Forces&& forces, Strain&& strain, Zero&& zero) {
  const auto deleted = [&] {
    zero(e);
    R r{};
    r.dt = std::numeric_limits<Real>::max();
    return r;
  };
  if (!erosion.active()) return forces(e);
  if (erosion.deleted(e)) return deleted();
  R r = forces(e);
  if (r.failed) return r;
  const ErosionCriteria& k = erosion.criteria();
  bool fails = (k.plastic_strain > 0.0 && strain(e) >= k.plastic_strain) || (k.min_step > 0.0 && r.dt < k.min_step);
  if constexpr (requires { r.erodes; }) fails = fails || r.erodes;  // the element's own verdict (thresholds)
  // The element's total work on the ledger's trapezoid (the first half from the forces its corner
  // slots held before); its bulk viscosity and damping on the rectangle, as the block books them.
  if (erosion.update_failed(e, e / kChunkSize, fails, 0.5 * r.power - r.visc - r.damp, 0.0, dt, 0.5 * r.power_prev))
    return deleted();
  return r;
}

}  // namespace slideline
