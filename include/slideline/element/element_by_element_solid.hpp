#pragma once
/// What the element-by-element solid blocks (full_hex_block.hpp: ELFORM 2, tet_block.hpp:
/// ELFORM 10) share around their own element routine: the loop over elements with erosion and
/// mass scaling, the per-chunk sums, and mass scaling's once / every-cycle bookkeeping. The block
/// keeps its geometry, law states and element routine; this part keeps everything that only
/// depends on "one element, Corners corners, mass rho V0".
#include <algorithm>
#include <array>
#include <limits>
#include <span>
#include <vector>

#include "slideline/element/element_block.hpp"
#include "slideline/element/element_chunks.hpp"
#include "slideline/element/element_erosion.hpp"
#include "slideline/element/element_mass_scaling.hpp"
#include "slideline/element/mass_scaling_once.hpp"

namespace slideline {

/// The shared part of a block of `Corners`-node solids evaluated one element at a time.
template <int Corners>
class ElementByElementSolid {
 public:
  explicit ElementByElementSolid(Index elements) : chunks_(elements) {}

  /// ElementBlock::compute_forces's loop: `forces(e)` evaluates element e (its Sums-like result
  /// R: dt, visc, damp, power, failed, optionally erodes) and writes its corner forces into
  /// `out`; `strain(e)` is its effective plastic strain (erosion by a failure strain). A deleted
  /// element's corner forces are zeroed and it adds no step. Returns the block's smallest step
  /// (ElementChunks::reduce: `kind` and `failure` name a failed element in the error).
  template <class R, class Forces, class Strain>
  Real forces(Index elements, Real dt, const std::array<Real*, 3>& out, BlockEnergy& energy, const char* kind,
              const std::vector<Id>& ids, Id part, const char* failure, Forces&& element, Strain&& strain) {
    Real* raw = rescaling_.raw_steps();
    const Real* factor = step_factor_.empty() ? nullptr : step_factor_.data();
    chunks_.scan(elements, [&](Index e) {
      const R r = eroding_element<R>(
          erosion_, e, dt, [&](Index k) { return with_step_factor(element(k), k, raw, factor); }, strain,
          [&](Index k) {
            for (int i = 0; i < 3; ++i) std::fill_n(out[i] + Corners * static_cast<std::size_t>(k), Corners, 0.0);
          });
      if (raw && r.dt == std::numeric_limits<Real>::max()) raw[e] = r.dt;  // deleted: adds no mass
      return r;
    });
    if (erosion_.active()) energy.eroded_elements += erosion_.reduce(energy.eroded_internal, energy.eroded_hourglass);
    return chunks_.reduce(energy, kind, ids, part, failure);
  }

  /// ElementBlock::scale_element_masses (MS1ST = 1): element e's rho V0 / Corners per corner
  /// times factor[e].
  Real scale_masses(std::span<const Real> factor, const Index* conn, Real rho, const std::vector<Real>& volume0,
                    NodalFields& nodes) {
    const auto n = static_cast<Index>(volume0.size());
    step_factor_.assign(volume0.size(), 1.0);
    const auto share = [&](Index e) {
      return ElementMassScaling::CornerShare{rho * volume0[static_cast<std::size_t>(e)] / Corners, 0.0, Corners * e,
                                             Corners};
    };
    return scale_corner_masses(n, factor, conn, share, nodes, step_factor_.data());
  }

  /// ElementBlock::enable_mass_rescaling: the element loop keeps its steps before the factors.
  void enable_rescaling(Index elements) {
    rescaling_.enable(elements, elements);
    step_factor_.assign(static_cast<std::size_t>(elements), 1.0);
  }
  /// The buffer the block's reference_steps fill before the first re-evaluation.
  std::span<Real> raw_steps(Index elements) { return rescaling_.raw_steps_span(elements); }
  /// ElementBlock::rescale_element_masses (MS1ST = 0): element e's physical mass rho V0 over its
  /// corners.
  RescaledBlock rescale(Real dt2ms, Real rho, const std::vector<Real>& volume0, std::span<Real> corner_added) {
    return rescaling_.rescale(static_cast<Index>(volume0.size()), Corners, dt2ms,
                              [&](Index e) { return rho * volume0[static_cast<std::size_t>(e)]; }, step_factor_.data(),
                              corner_added);
  }

  Id smallest_step_element(const std::vector<Id>& ids) const { return chunks_.smallest_step_element(ids); }

  ElementErosion& erosion() { return erosion_; }
  const ElementErosion& erosion() const { return erosion_; }

 private:
  ElementChunks chunks_;           ///< per-chunk steps, failures and powers (sized at construction)
  ElementErosion erosion_;         ///< inactive unless the block enables erosion
  std::vector<Real> step_factor_;  ///< sqrt of the mass-scaling factor per element; empty: none
  ElementMassScaling rescaling_;   ///< MS1ST = 0: the steps before the factors (inactive otherwise)
};

}  // namespace slideline
