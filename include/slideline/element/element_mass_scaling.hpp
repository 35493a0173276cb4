#pragma once
/// Mass scaling re-evaluated every cycle (LS-DYNA's DT2MS with MS1ST = 0 of *CONTROL_TIMESTEP;
/// docs/solver.md, "Mass scaling"): the per-element part a block keeps. The block's element loop
/// stores each element's stable step before any factor (raw_steps()); after the loop the solver
/// asks the block to re-evaluate the factors (T / dt_e)^2 from those steps, and the block writes the
/// mass each element adds to its corners. Everything is sized at enable(); nothing is allocated in
/// a step, and the sums are reduced in chunk order (thread-count independent).
#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include "slideline/core/parallel.hpp"
#include "slideline/core/types.hpp"

namespace slideline {

/// The factor (T / dt_e)^2 mass scaling applies to an element of stable step `dt_e` (time) for the
/// deck's `dt2ms` (T = |dt2ms|; 1 where the element keeps its mass): DT2MS < 0 only elements with
/// dt_e < T, DT2MS > 0 every element; an element without a step (+max or +inf: deleted, rigid)
/// keeps its mass.
inline Real mass_scale_factor(Real dt_e, Real dt2ms) {
  const Real target = std::abs(dt2ms);
  if (dt2ms == 0.0 || !(dt_e < std::numeric_limits<Real>::max())) return 1.0;
  if (dt2ms < 0.0 && dt_e >= target) return 1.0;
  const Real r = target / dt_e;
  return r * r;
}

/// An element loop's step with mass scaling (element-by-element blocks: TetBlock, FullHexBlock):
/// keeps r.dt, the step before any factor, in raw[e] (mass scaling every cycle; null: off) and
/// returns r with its step times factor[e] (null: no factor).
template <class R>
R with_step_factor(R r, Index e, Real* raw, const Real* factor) {
  if (raw) raw[e] = r.dt;
  if (factor) r.dt *= factor[e];
  return r;
}

/// What one re-evaluation did to a block.
struct RescaledBlock {
  Real added = 0.0;  ///< mass the block's elements add now (negative: removed, DT2MS > 0)
  Real step = std::numeric_limits<Real>::max();          ///< smallest element step after the factors
  Real smallest_raw = std::numeric_limits<Real>::max();  ///< smallest element step before them
  Index scaled = 0;  ///< elements whose factor is not 1
};

/// A block's per-element state for MS1ST = 0: the steps its element loop kept, and the chunk sums
/// of a re-evaluation.
class ElementMassScaling {
 public:
  /// Sizes the buffers for `elements` elements (`padded`: the block's padded count, >= elements).
  void enable(Index elements, Index padded) {
    raw_.assign(static_cast<std::size_t>(padded), std::numeric_limits<Real>::max());
    const auto nc = static_cast<std::size_t>(chunk_count(elements));
    chunk_added_.assign(nc, 0.0);
    chunk_step_.assign(nc, 0.0);
    chunk_raw_.assign(nc, 0.0);
    chunk_scaled_.assign(nc, 0);
  }
  bool active() const { return !raw_.empty(); }
  /// Where the element loop writes each element's step before any factor (padded count); null
  /// when inactive (then the loop writes nothing).
  Real* raw_steps() { return raw_.empty() ? nullptr : raw_.data(); }
  std::span<Real> raw_steps_span(Index elements) { return std::span<Real>(raw_).first(static_cast<std::size_t>(elements)); }

  /// Re-evaluates the factors of `elements` elements of `corners` nodes each from the kept steps:
  /// step_factor[e] = sqrt(f_e); corner_added[corners e + k] = element_mass(e) / corners x (f_e - 1)
  /// for each corner k (the mass the element adds to that node, element_mass(e) its physical mass).
  template <class ElementMass>
  RescaledBlock rescale(Index elements, int corners, Real dt2ms, ElementMass&& element_mass, Real* step_factor,
                        std::span<Real> corner_added) {
    return rescale_corners(
        elements, dt2ms,
        [&](Index e) { return CornerShare{element_mass(e) / corners, 0.0, corners * e, corners}; }, step_factor,
        corner_added, {});
  }

  /// One element's lumped share per corner: its physical mass and rotary inertia per corner, its
  /// first corner slot (in the block's own slots, from 0) and its number of corners.
  struct CornerShare {
    Real mass = 0.0;
    Real inertia = 0.0;
    Index first = 0;
    int corners = 0;
  };

  /// The general form, for blocks whose elements differ in corners (shells with triangles) or
  /// carry rotary inertia: `share(e)` gives element e's CornerShare; each of its corners gets
  /// share.mass (f_e - 1) in `corner_added` and, when `corner_inertia` is not empty (the block's
  /// moment slots, laid out as its force slots), share.inertia (f_e - 1) in `corner_inertia`.
  template <class Share>
  RescaledBlock rescale_corners(Index elements, Real dt2ms, Share&& share, Real* step_factor,
                                std::span<Real> corner_added, std::span<Real> corner_inertia) {
    parallel_for_chunks(elements, [&](Index b, Index end, Index chunk) {
      Real added = 0.0, step = std::numeric_limits<Real>::max(), raw = std::numeric_limits<Real>::max();
      Index scaled = 0;
      for (Index e = b; e < end; ++e) {
        const Real dt = raw_[static_cast<std::size_t>(e)];
        const Real f = mass_scale_factor(dt, dt2ms);
        const Real s = std::sqrt(f);
        step_factor[e] = s;
        const CornerShare c = share(e);
        const Real dm = c.mass * (f - 1.0);
        for (int k = 0; k < c.corners; ++k) corner_added[static_cast<std::size_t>(c.first + k)] = dm;
        if (!corner_inertia.empty()) {
          const Real dj = c.inertia * (f - 1.0);
          for (int k = 0; k < c.corners; ++k) corner_inertia[static_cast<std::size_t>(c.first + k)] = dj;
        }
        added += c.corners * dm;
        raw = std::min(raw, dt);
        step = std::min(step, dt * s);
        if (f != 1.0) ++scaled;
      }
      chunk_added_[static_cast<std::size_t>(chunk)] = added;
      chunk_step_[static_cast<std::size_t>(chunk)] = step;
      chunk_raw_[static_cast<std::size_t>(chunk)] = raw;
      chunk_scaled_[static_cast<std::size_t>(chunk)] = scaled;
    });
    RescaledBlock r;
    for (std::size_t c = 0; c < chunk_added_.size(); ++c) {
      r.added += chunk_added_[c];
      r.step = std::min(r.step, chunk_step_[c]);
      r.smallest_raw = std::min(r.smallest_raw, chunk_raw_[c]);
      r.scaled += chunk_scaled_[c];
    }
    return r;
  }

 private:
  std::vector<Real> raw_;  ///< per element (padded), its step before any factor at the last evaluation
  std::vector<Real> chunk_added_, chunk_step_, chunk_raw_;
  std::vector<Index> chunk_scaled_;
};

}  // namespace slideline
