#include "slideline/solver/mass_rescaling.hpp"

#include <algorithm>
#include <limits>

#include "slideline/core/parallel.hpp"

namespace slideline {

void MassRescaling::initialize(ElementBlocks& blocks, NodalFields& nodes, const NodeSlots& slots, Index corner_count,
                               const NodeSlots& moment_slots, Index moment_count, Real dt2ms,
                               std::vector<PartAddedMass>& parts) {
  active_ = true;
  dt2ms_ = dt2ms;
  blocks_.clear();
  scaled_nodes_.clear();
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    if (!blocks[k]->bounds_time_step()) continue;  // rigid parts: never scaled
    blocks[k]->enable_mass_rescaling();
    blocks_.push_back(k);
    for (Index i : blocks[k]->connectivity()) scaled_nodes_.push_back(i);
  }
  std::sort(scaled_nodes_.begin(), scaled_nodes_.end());
  scaled_nodes_.erase(std::unique(scaled_nodes_.begin(), scaled_nodes_.end()), scaled_nodes_.end());
  base_mass_ = nodes.mass;
  corner_added_.assign(static_cast<std::size_t>(corner_count), 0.0);
  base_inertia_.clear();
  corner_inertia_.clear();
  moment_slots_ = nullptr;
  if (moment_count > 0) {
    base_inertia_ = nodes.rot_inertia;
    corner_inertia_.assign(static_cast<std::size_t>(moment_count), 0.0);
    moment_slots_ = &moment_slots;
  }
  chunk_dk_.assign(static_cast<std::size_t>(chunk_count(static_cast<Index>(nodes.size()))), 0.0);
  rescale(blocks, nodes, slots, true, parts);
}

MassRescaling::Result MassRescaling::rescale(ElementBlocks& blocks, NodalFields& nodes, const NodeSlots& slots,
                                             bool at_reference, std::vector<PartAddedMass>& parts,
                                             std::span<Real> block_steps) {
  Result r;
  r.step = std::numeric_limits<Real>::max();
  for (std::size_t k : blocks_) {
    ElementBlock& b = *blocks[k];
    const auto own = std::span<Real>(corner_added_).subspan(static_cast<std::size_t>(b.force_slot_base()),
                                                             b.connectivity().size());
    const auto own_inertia = b.has_moments() && !corner_inertia_.empty()
                                 ? std::span<Real>(corner_inertia_).subspan(static_cast<std::size_t>(b.moment_slot_base()),
                                                                            b.connectivity().size())
                                 : std::span<Real>();
    const RescaledBlock rb = b.rescale_element_masses(dt2ms_, at_reference, nodes, own, own_inertia);
    PartAddedMass& p = parts[k];
    p.added = rb.added;
    p.scaled = rb.scaled;
    p.smallest_step = rb.smallest_raw;
    r.added += rb.added;
    if (!block_steps.empty()) block_steps[k] = rb.step;  // the block's vote from now on
    if (rb.step < r.step) {
      r.step = rb.step;
      r.controlling = &b;
    }
  }
  // m_i = physical mass + the node's corner shares, summed in slot-list order.
  const Index n = static_cast<Index>(nodes.size());
  parallel_for_chunks(n, [&](Index b, Index end, Index chunk) {
    Real dk = 0.0;
    for (Index i = b; i < end; ++i) {
      Real m = base_mass_[static_cast<std::size_t>(i)];
      for (Index s = slots.offset[i]; s < slots.offset[i + 1]; ++s)
        m += corner_added_[static_cast<std::size_t>(slots.slot[s])];
      const Real dm = m - nodes.mass[i];
      if (dm != 0.0) dk += 0.5 * dm * nodes.v.get(i).squaredNorm();
      nodes.mass[i] = m;
      if (moment_slots_) {  // shells: the rotary inertia, scaled with the mass
        const NodeSlots& ms = *moment_slots_;
        Real j = base_inertia_[static_cast<std::size_t>(i)];
        for (Index s = ms.offset[i]; s < ms.offset[i + 1]; ++s)
          j += corner_inertia_[static_cast<std::size_t>(ms.slot[s])];
        const Real dj = j - nodes.rot_inertia[i];
        if (dj != 0.0 && nodes.has_rotation[i]) dk += 0.5 * dj * nodes.omega.get(i).squaredNorm();
        nodes.rot_inertia[i] = j;
      }
    }
    chunk_dk_[static_cast<std::size_t>(chunk)] = dk;
  });
  r.kinetic_change = ordered_sum(chunk_dk_, 0.0);
  if (loads_)
    for (std::size_t l = 0; l < load_masses_.size(); ++l) {
      const LoadMasses& lm = load_masses_[l];
      std::vector<Real>& mass = (*loads_)[l].mass;
      for (std::size_t j = 0; j < mass.size(); ++j) {
        Real m = lm.base[j];
        for (Index s = lm.offset[j]; s < lm.offset[j + 1]; ++s) m += corner_added_[static_cast<std::size_t>(lm.slot[s])];
        mass[j] = m;
      }
    }
  return r;
}

void MassRescaling::attach_body_loads(std::vector<BodyLoad>& loads, const ElementBlocks& blocks, const NodeSlots& slots) {
  loads_ = &loads;
  load_masses_.assign(loads.size(), LoadMasses{});
  // The slot ranges of the rescaled blocks, with their parts.
  struct Range {
    Index begin, end;
    Id part;
  };
  std::vector<Range> ranges;
  for (std::size_t k : blocks_)
    ranges.push_back({blocks[k]->force_slot_base(),
                      blocks[k]->force_slot_base() + static_cast<Index>(blocks[k]->connectivity().size()),
                      blocks[k]->part_id()});
  for (std::size_t l = 0; l < loads.size(); ++l) {
    const BodyLoad& bl = loads[l];
    LoadMasses& lm = load_masses_[l];
    lm.base = bl.mass;
    lm.offset.assign(1, 0);
    lm.slot.clear();
    for (Index i : bl.nodes) {
      for (Index k = slots.offset[i]; k < slots.offset[i + 1]; ++k) {
        const Index s = slots.slot[k];
        for (const Range& r : ranges)
          if (s >= r.begin && s < r.end &&
              (bl.parts.empty() || std::find(bl.parts.begin(), bl.parts.end(), r.part) != bl.parts.end()))
            lm.slot.push_back(s);
      }
      lm.offset.push_back(static_cast<Index>(lm.slot.size()));
    }
  }
  // The loads' masses with the mass added so far.
  for (std::size_t l = 0; l < load_masses_.size(); ++l)
    for (std::size_t j = 0; j < loads[l].mass.size(); ++j)
      for (Index s = load_masses_[l].offset[j]; s < load_masses_[l].offset[j + 1]; ++s)
        loads[l].mass[j] += corner_added_[static_cast<std::size_t>(load_masses_[l].slot[s])];
}

}  // namespace slideline
