#pragma once
/// ContactErosion: which segments and slave nodes of one contact pass are live while elements
/// erode (element/element_erosion.hpp). docs/contact_erosion.md.
///
/// The surfaces of an interface with an eroding part hold every face of its solids (the exterior
/// faces, and each interior face twice, once per element that owns it, each oriented out of its
/// own element; add_interior_faces(), src/contact/eroding_contact.cpp) and its shells. Rule:
/// - a segment is active while its own element is live and the element across it (its partner:
///   another solid face of the same surface with the same nodes) is deleted or absent; a shell,
///   while it is live. So an interior face becomes contact surface when the element in front of it
///   is deleted, and a face goes when its own element goes;
/// - a slave node is active while it lies on an active face of its own surface (the surface that
///   orients it), or when it has no face there at all (a node that no element of a tracked part
///   holds). A node freed of all its elements leaves the contact (LS-DYNA ENMASS = 0); so does a
///   node still inside the body (all its faces interior). A node-set slave side
///   (set_slave_elements) instead keeps every node of the set while an element holding it is
///   live: the set names its slaves; its own faces only orient them.
/// - ENMASS 1 and 2 (*CONTROL_CONTACT; set_retained_nodes): a slave freed of all its elements, when
///   one of them was a solid (1) or any (2), stays active as a free mass (slave_free() says which)
///   and meets any active segment: with no live face it has nothing to be oriented by.
/// update() re-reads the deletions once per cycle, before the search (the elements of the cycle
/// have run: src/solver/simulation_forces.cpp); it allocates nothing, and each flag is a pure
/// function of the deletion states, so nothing depends on the thread count.
#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "slideline/element/element_block.hpp"
#include "slideline/element/element_erosion.hpp"
#include "slideline/mesh/surface.hpp"

namespace slideline {

/// The activity of the segments of one Surface under erosion.
class SurfaceErosion {
 public:
  SurfaceErosion() = default;

  /// The segments of `s` (block, element and kind set); partners found by node set.
  explicit SurfaceErosion(const Surface& s) {
    const auto n = static_cast<std::size_t>(s.segment_count());
    block_.assign(s.block.begin(), s.block.end());
    element_.assign(s.element.begin(), s.element.end());
    partner_.assign(n, -1);
    using Key = std::pair<std::array<Index, 4>, Index>;
    std::vector<Key> keys;
    for (std::size_t k = 0; k < n; ++k) {
      if (s.kind[k] != SegmentKind::solid_face) continue;
      std::array<Index, 4> a{};
      std::copy_n(&s.conn[4 * k], 4, a.begin());
      if (a[2] == a[3]) a[3] = -1;
      std::sort(a.begin(), a.end());
      keys.push_back({a, static_cast<Index>(k)});
    }
    std::sort(keys.begin(), keys.end());
    for (std::size_t i = 0; i + 1 < keys.size(); ++i)
      if (keys[i].first == keys[i + 1].first) {
        partner_[static_cast<std::size_t>(keys[i].second)] = keys[i + 1].second;
        partner_[static_cast<std::size_t>(keys[i + 1].second)] = keys[i].second;
        ++i;
      }
    active_.assign(n, 0);
  }

  /// Reads the deletion states of `blocks` from now on (the blocks of the segments' block
  /// indices), and sets the flags. Allocates.
  void bind(const std::vector<std::unique_ptr<ElementBlock>>& blocks) {
    erosion_.assign(blocks.size(), nullptr);
    for (std::size_t b = 0; b < blocks.size(); ++b) erosion_[b] = std::as_const(*blocks[b]).erosion();
    update();
  }

  /// True when a block of the surface can erode (bind() first).
  bool tracked() const {
    for (Index b : block_)
      if (static_cast<std::size_t>(b) < erosion_.size() && erosion_[static_cast<std::size_t>(b)]) return true;
    return false;
  }

  /// Re-reads the deletions; true when a flag changed. No allocation.
  bool update() {
    bool changed = false;
    for (std::size_t k = 0; k < active_.size(); ++k) {
      const Index p = partner_[k];
      const bool a = live(k) && (p < 0 || !live(static_cast<std::size_t>(p)));
      changed = changed || (active_[k] != 0) != a;
      active_[k] = a ? 1 : 0;
    }
    return changed;
  }

  /// Per segment: 1 active, 0 not.
  std::span<const std::uint8_t> active() const { return active_; }
  /// The segment across segment k (same nodes, the other element), -1: none.
  Index partner(Index k) const { return partner_[static_cast<std::size_t>(k)]; }

 private:
  bool live(std::size_t k) const {
    const auto b = static_cast<std::size_t>(block_[k]);
    const ElementErosion* er = b < erosion_.size() ? erosion_[b] : nullptr;
    return !er || !er->active() || !er->deleted(element_[k]);
  }

  std::vector<Index> block_, element_, partner_;
  std::vector<const ElementErosion*> erosion_;  ///< per block; null: it does not erode
  std::vector<std::uint8_t> active_;
};

/// The erosion state of one pass: its master surface's segments, and its slaves from their own
/// surface (the same surface for a single-surface or two-sided automatic pass).
class ContactErosion {
 public:
  ContactErosion() = default;

  /// master: the pass's master surface; own: the surface its slaves lie on, or nullptr when it is
  /// `master`; slaves: internal node indices (the pass's order).
  ContactErosion(const Surface& master, const Surface* own, std::span<const Index> slaves)
      : master_(master), own_(own ? SurfaceErosion(*own) : SurfaceErosion()), same_(own == nullptr) {
    const Surface& o = own ? *own : master;
    row_.assign(slaves.size() + 1, 0);
    for (std::size_t i = 0; i < slaves.size(); ++i) {
      row_[i + 1] = row_[i];
      const auto it = std::lower_bound(o.nodes.begin(), o.nodes.end(), slaves[i]);
      if (it == o.nodes.end() || *it != slaves[i]) continue;
      const Index r = static_cast<Index>(it - o.nodes.begin());
      for (Index j = o.node_segments.begin(r); j < o.node_segments.end(r); ++j) {
        faces_.push_back(o.node_segments.value[static_cast<std::size_t>(j)]);
        ++row_[i + 1];
      }
    }
    slave_active_.assign(slaves.size(), 1);
  }

  /// Node-set slaves (SSTYP 4): slave i is active while one of the elements that hold it is live,
  /// faces or not (the set names its nodes; LS-DYNA ENMASS = 0 drops a node when its last element
  /// goes). `row` (per slave + 1) indexes `elements`, {block, element} of the erodible elements
  /// that hold slave i; a slave with none (held by an element that cannot erode, or by none) is
  /// always active. Before bind(); allocates.
  void set_slave_elements(std::vector<Index> row, std::vector<std::array<Index, 2>> elements) {
    by_element_ = true;
    element_row_ = std::move(row);
    elements_ = std::move(elements);
  }

  /// ENMASS 1, 2: slave i is kept, once every element of its row is deleted, as a free mass in
  /// contact (active, and slave_free()[i] = 1). `row` (per slave + 1) indexes `elements`, {block,
  /// element} of the erodible elements that hold slave i; an empty row: never kept (a node held by
  /// an element that cannot erode, or not by the elements ENMASS names). Before bind(); allocates.
  void set_retained_nodes(std::vector<Index> row, std::vector<std::array<Index, 2>> elements) {
    free_row_ = std::move(row);
    free_elements_ = std::move(elements);
    slave_free_.assign(free_row_.empty() ? 0 : free_row_.size() - 1, 0);
  }

  /// Binds both surfaces to the blocks' deletion states and sets the flags. Allocates.
  void bind(const std::vector<std::unique_ptr<ElementBlock>>& blocks) {
    master_.bind(blocks);
    if (!same_) own_.bind(blocks);
    erosion_.assign(blocks.size(), nullptr);
    for (std::size_t b = 0; b < blocks.size(); ++b) erosion_[b] = std::as_const(*blocks[b]).erosion();
    update_slaves();
  }
  /// True when a segment of either surface can erode.
  bool tracked() const { return master_.tracked() || (!same_ && own_.tracked()); }

  /// Once per cycle: re-reads the deletions; true when a segment or slave flag changed.
  bool update() {
    bool changed = master_.update();
    if (!same_) changed = own_.update() || changed;
    return update_slaves() || changed;
  }

  std::span<const std::uint8_t> segment_active() const { return master_.active(); }
  /// Per segment of the slaves' own surface (the master's when they are the same).
  std::span<const std::uint8_t> own_active() const { return same_ ? master_.active() : own_.active(); }
  std::span<const std::uint8_t> slave_active() const { return slave_active_; }
  /// Per slave: 1 while it is a free mass kept in contact (ENMASS 1, 2); empty without
  /// set_retained_nodes().
  std::span<const std::uint8_t> slave_free() const { return slave_free_; }

 private:
  bool element_live(const std::array<Index, 2>& be) const {
    const auto b = static_cast<std::size_t>(be[0]);
    const ElementErosion* er = b < erosion_.size() ? erosion_[b] : nullptr;
    return !er || !er->active() || !er->deleted(be[1]);
  }

  bool update_slaves() {
    const auto own = own_active();
    bool changed = false;
    for (std::size_t i = 0; i + 1 < row_.size(); ++i) {
      bool a;
      if (by_element_) {
        a = element_row_[i + 1] == element_row_[i];
        for (Index e = element_row_[i]; e < element_row_[i + 1] && !a; ++e)
          a = element_live(elements_[static_cast<std::size_t>(e)]);
      } else {
        a = row_[i + 1] == row_[i];
        for (Index f = row_[i]; f < row_[i + 1] && !a; ++f) a = own[static_cast<std::size_t>(faces_[static_cast<std::size_t>(f)])] != 0;
      }
      if (!slave_free_.empty()) {  // ENMASS 1, 2: a freed node stays, as a free mass
        bool f = free_row_[i + 1] > free_row_[i];
        for (Index e = free_row_[i]; e < free_row_[i + 1] && f; ++e)
          f = !element_live(free_elements_[static_cast<std::size_t>(e)]);
        changed = changed || (slave_free_[i] != 0) != f;
        slave_free_[i] = f ? 1 : 0;
        a = a || f;
      }
      changed = changed || (slave_active_[i] != 0) != a;
      slave_active_[i] = a ? 1 : 0;
    }
    return changed;
  }

  SurfaceErosion master_, own_;
  bool same_ = true;
  std::vector<Index> row_;    ///< per slave + 1: its own faces [row_[i], row_[i+1]) in faces_
  std::vector<Index> faces_;  ///< own-surface segment indices
  std::vector<std::uint8_t> slave_active_;
  bool by_element_ = false;                     ///< set_slave_elements(): the node-set rule
  std::vector<Index> element_row_;              ///< per slave + 1: its erodible elements in elements_
  std::vector<std::array<Index, 2>> elements_;  ///< {block, element}
  std::vector<const ElementErosion*> erosion_;  ///< per block; null: it does not erode
  std::vector<Index> free_row_;                 ///< set_retained_nodes(): per slave + 1
  std::vector<std::array<Index, 2>> free_elements_;
  std::vector<std::uint8_t> slave_free_;        ///< per slave (empty: ENMASS 0)
};

}  // namespace slideline
