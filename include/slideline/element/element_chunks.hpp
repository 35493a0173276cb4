#pragma once
/// ElementChunks: the per-chunk results of the element-by-element solid blocks (TetBlock,
/// FullHexBlock): each chunk's smallest step and its element, its first failed element and its
/// bulk-viscosity, damping and element powers. Sized once (no allocation in a step) and reduced in
/// chunk order, so the results do not depend on the thread count.
#include <limits>
#include <vector>

#include "slideline/core/parallel.hpp"
#include "slideline/core/types.hpp"
#include "slideline/element/element_block.hpp"

namespace slideline {

class ElementChunks {
 public:
  explicit ElementChunks(Index element_count) {
    const auto nc = static_cast<std::size_t>(chunk_count(element_count));
    dt_.assign(nc, 0.0);
    visc_.assign(nc, 0.0);
    damp_.assign(nc, 0.0);
    power_.assign(nc, 0.0);
    zero_.assign(nc, 0.0);
    dt_element_.assign(nc, 0);
    bad_.assign(nc, -1);
  }

  /// Runs `element(e)` over the `count` elements chunk by chunk (in parallel); its result has the
  /// element's step `dt`, `failed`, and the powers `visc`, `damp` and `power`.
  template <class Element>
  void scan(Index count, Element&& element) {
    parallel_for_chunks(count, [&](Index b, Index end, Index chunk) {
      Real dtmin = std::numeric_limits<Real>::max(), visc = 0.0, damp = 0.0, power = 0.0;
      Index argmin = b, bad = -1;
      for (Index e = b; e < end; ++e) {
        const auto r = element(e);
        if (r.dt < dtmin) {
          dtmin = r.dt;
          argmin = e;
        }
        if (bad < 0 && r.failed) bad = e;
        visc += r.visc;
        damp += r.damp;
        power += r.power;
      }
      dt_[chunk] = dtmin;
      dt_element_[chunk] = argmin;
      visc_[chunk] = visc;
      damp_[chunk] = damp;
      power_[chunk] = power;
      bad_[chunk] = bad;
    });
  }

  /// reduce_element_chunks of the last scan (no hourglass power: these blocks have none).
  Real reduce(BlockEnergy& energy, const char* kind, const std::vector<Id>& ids, Id part, const char* failure) const {
    return reduce_element_chunks(dt_, zero_, visc_, damp_, power_, bad_, energy, kind, ids, part, failure);
  }

  /// Deck id of the element with the smallest step at the last scan (-1 without elements).
  Id smallest_step_element(const std::vector<Id>& ids) const {
    return ids.empty() ? Id{-1} : ids[static_cast<std::size_t>(dt_element_[argmin_chunk(dt_)])];
  }

 private:
  std::vector<Real> dt_, visc_, damp_, power_, zero_;
  std::vector<Index> dt_element_, bad_;
};

}  // namespace slideline
