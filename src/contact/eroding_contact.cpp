// Contact with eroding parts (docs/contact_erosion.md): the interfaces that update their surfaces
// as elements are deleted get every face of their sides' eroding solids (contact/search/
// contact_erosion.hpp says which are active when); the others refuse an eroding part.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "slideline/contact/make_contact_interface.hpp"
#include "slideline/contact/search/contact_erosion.hpp"
#include "slideline/core/error.hpp"
#include "slideline/element/element_block.hpp"
#include "slideline/element/element_erosion.hpp"
#include "slideline/mesh/block_topology.hpp"
#include "slideline/mesh/surface_builder.hpp"

namespace slideline {

namespace {

constexpr const char* kSupported =
    "contact with eroding parts runs on *CONTACT_AUTOMATIC_SINGLE_SURFACE, *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE, "
    "*CONTACT_AUTOMATIC_NODES_TO_SURFACE and *CONTACT_ERODING_SINGLE_SURFACE / _SURFACE_TO_SURFACE / "
    "_NODES_TO_SURFACE (penalty; docs/contact_erosion.md)";

bool block_erodes(const ContactBuildContext& ctx, Index b) {
  const ElementErosion* er = std::as_const(*ctx.blocks[static_cast<std::size_t>(b)]).erosion();
  return er && er->active();
}

/// Appends to side.surface the interior faces of its parts' solids where one of the two elements
/// that own a face can erode (each face once per owner, oriented out of it; `between_parts`: only
/// faces whose two elements belong to different parts, IADJ = 1), rebuilds the adjacency and the
/// side's nodes.
void add_interior_faces(ContactSide& side, const ContactBuildContext& ctx, const std::string& where,
                        bool between_parts) {
  if (side.parts.empty()) return;  // a segment set: its segments only
  const Surface inner = interior_faces_of_parts(ctx.blocks, ctx.nodes, side.parts, where);
  using Key = std::pair<std::array<Index, 4>, Index>;
  std::vector<Key> keys;
  for (Index k = 0; k < inner.segment_count(); ++k) {
    std::array<Index, 4> a{};
    std::copy_n(&inner.conn[4 * static_cast<std::size_t>(k)], 4, a.begin());
    if (a[2] == a[3]) a[3] = -1;
    std::sort(a.begin(), a.end());
    keys.push_back({a, k});
  }
  std::sort(keys.begin(), keys.end());
  std::vector<char> keep(static_cast<std::size_t>(inner.segment_count()), 0);
  for (std::size_t i = 0; i < keys.size();) {
    std::size_t j = i;
    bool erodes = false, two_parts = false;
    const Id part = ctx.blocks[static_cast<std::size_t>(inner.block[static_cast<std::size_t>(keys[i].second)])]->part_id();
    for (; j < keys.size() && keys[j].first == keys[i].first; ++j) {
      const Index b = inner.block[static_cast<std::size_t>(keys[j].second)];
      erodes = erodes || block_erodes(ctx, b);
      two_parts = two_parts || ctx.blocks[static_cast<std::size_t>(b)]->part_id() != part;
    }
    const bool wanted = erodes && (!between_parts || two_parts);
    for (std::size_t k = i; k < j; ++k) keep[static_cast<std::size_t>(keys[k].second)] = wanted ? 1 : 0;
    i = j;
  }
  Surface& s = side.surface;
  for (Index k = 0; k < inner.segment_count(); ++k) {
    const auto u = static_cast<std::size_t>(k);
    if (keep[u]) s.append_segment(inner, k);
  }
  build_surface_adjacency(s);
  side.nodes = s.nodes;
}

/// ISYM = 1: leaves out of side.surface the solid faces on a symmetry plane: faces whose unit
/// normal (reference geometry) is a global axis to 1e-6 and whose nodes are all held in that
/// direction by a support without a curve acting for the whole run (*BOUNDARY_SPC_..., *NODE TC;
/// ContactBuildContext::held_axes).
/// Such faces are exterior only because the model is cut there; as contact segments they would
/// catch the other half's nodes that do not exist.
void drop_symmetry_faces(ContactSide& side, const ContactBuildContext& ctx) {
  Surface& s = side.surface;
  const std::span<const std::uint8_t> held = ctx.held_axes;
  if (held.empty() || s.segment_count() == 0) return;
  Surface kept;
  for (Index k = 0; k < s.segment_count(); ++k) {
    const auto u = static_cast<std::size_t>(k);
    const Index* c = &s.conn[4 * u];
    bool on_plane = false;
    if (s.kind[u] == SegmentKind::solid_face) {
      const Vec3Field& x0 = ctx.nodes.x0;
      const Vec3 n = (x0.get(c[2]) - x0.get(c[0])).cross(x0.get(c[3]) - x0.get(c[1]));
      const Real len = n.norm();
      for (int a = 0; a < 3 && len > 0.0; ++a) {
        if (std::abs(n[a]) < (1.0 - 1e-6) * len) continue;
        on_plane = true;
        for (int j = 0; j < 4; ++j) on_plane = on_plane && (held[static_cast<std::size_t>(c[j])] >> a & 1u);
      }
    }
    if (!on_plane) kept.append_segment(s, k);
  }
  if (kept.segment_count() == s.segment_count()) return;
  s = std::move(kept);
  build_surface_adjacency(s);
  side.nodes = s.nodes;
}

}  // namespace

Surface eroding_node_set_faces(const std::vector<Index>& nodes, const ContactBuildContext& ctx, const std::string& where) {
  ContactSide side;
  side.surface = node_set_faces(nodes, ctx, where);
  for (const auto& [pid, part_nodes] : ctx.sets.part_nodes)
    if (std::any_of(nodes.begin(), nodes.end(),
                    [&](Index n) { return std::binary_search(part_nodes.begin(), part_nodes.end(), n); }))
      side.parts.push_back(pid);
  add_interior_faces(side, ctx, where, false);
  return std::move(side.surface);
}

namespace {

/// Per node: the erodible elements that hold it ({block, element}), whether one of them is a
/// solid, and whether an element that cannot erode holds it. Read from every block's connectivity.
struct NodeElements {
  std::vector<std::uint8_t> fixed, solid;
  std::vector<std::vector<std::array<Index, 2>>> held;
};

NodeElements node_elements(const ContactBuildContext& ctx) {
  const std::size_t n_nodes = ctx.nodes.size();
  NodeElements out;
  out.fixed.assign(n_nodes, 0);
  out.solid.assign(n_nodes, 0);
  out.held.resize(n_nodes);
  for (std::size_t b = 0; b < ctx.blocks.size(); ++b) {
    const ElementBlock& block = *ctx.blocks[b];
    const Index count = block.element_count();
    const std::span<const Index> conn = block.connectivity();
    if (count == 0) continue;
    const BlockTopology topology = block.topology();
    const bool erodes = block_erodes(ctx, static_cast<Index>(b));
    for (Index e = 0; e < count; ++e) {
      const BlockTopology::Element el = topology.element(e);
      for (int a = 0; a < el.topology().nodes; ++a) {
        const auto n = static_cast<std::size_t>(conn[el.node_offset + static_cast<std::size_t>(a)]);
        if (!erodes) {
          out.fixed[n] = 1;
          continue;
        }
        if (el.topology().is_solid()) out.solid[n] = 1;
        auto& h = out.held[n];
        if (h.empty() || h.back() != std::array<Index, 2>{static_cast<Index>(b), e})
          h.push_back({static_cast<Index>(b), e});  // a degenerate element repeats a node
      }
    }
  }
  return out;
}

}  // namespace

void set_node_set_slave_elements(ContactErosion& erosion, std::span<const Index> slaves, const ContactBuildContext& ctx) {
  const NodeElements ne = node_elements(ctx);
  std::vector<Index> row(slaves.size() + 1, 0);
  std::vector<std::array<Index, 2>> elements;
  for (std::size_t i = 0; i < slaves.size(); ++i) {
    const auto n = static_cast<std::size_t>(slaves[i]);
    if (!ne.fixed[n]) elements.insert(elements.end(), ne.held[n].begin(), ne.held[n].end());
    row[i + 1] = static_cast<Index>(elements.size());
  }
  erosion.set_slave_elements(std::move(row), std::move(elements));
}

void set_retained_slave_nodes(ContactErosion& erosion, std::span<const Index> slaves, const ContactBuildContext& ctx,
                              int enmass) {
  if (enmass != 1 && enmass != 2) return;  // ENMASS 0: a freed node leaves the contact
  const NodeElements ne = node_elements(ctx);
  std::vector<Index> row(slaves.size() + 1, 0);
  std::vector<std::array<Index, 2>> elements;
  for (std::size_t i = 0; i < slaves.size(); ++i) {
    const auto n = static_cast<std::size_t>(slaves[i]);
    if (!ne.fixed[n] && (enmass == 2 || ne.solid[n]))
      elements.insert(elements.end(), ne.held[n].begin(), ne.held[n].end());
    row[i + 1] = static_cast<Index>(elements.size());
  }
  erosion.set_retained_nodes(std::move(row), std::move(elements));
}

void prepare_eroding_contact(InterfaceSpec& spec, const ContactBuildContext& ctx, const std::vector<Id>& eroding_part) {
  if (spec.symmetry_faces_out) {
    // ISYM = 1, eroding parts or not: the exterior faces now, the interior ones as they are added.
    drop_symmetry_faces(spec.slave, ctx);
    if (spec.single_surface)
      spec.master = spec.slave;
    else
      drop_symmetry_faces(spec.master, ctx);
  }
  if (eroding_part.empty()) return;
  Id pid = 0;
  const ContactSide* on = nullptr;
  for (const ContactSide* side : {&spec.slave, &spec.master})
    for (Index n : side->nodes)
      if (pid == 0 && eroding_part[static_cast<std::size_t>(n)] != 0) {
        pid = eroding_part[static_cast<std::size_t>(n)];
        on = side;
      }
  if (pid == 0) return;
  const std::string part = "part " + std::to_string(pid) + " can erode (its material's failure strain) and is on "
                           "this contact's " + (on == &spec.slave ? "slave" : "master") + " side: ";
  using F = model::ContactForm;
  const bool automatic = spec.type == model::ContactType::automatic &&
                         spec.enforcement == model::Enforcement::penalty &&
                         (spec.form == F::dyna3d || spec.form == F::automatic_surface_to_surface ||
                          spec.form == F::automatic_nodes_to_surface);
  if (!automatic) throw NotImplementedError(spec.where + ": " + part + "not implemented for this card; " + kSupported);
  if (spec.snlog != 0)
    throw NotImplementedError(spec.where + ": " + part + "optional card B: SNLOG = " + std::to_string(spec.snlog) +
                              " turns off the shooting-node logic, which a contact with eroding parts always has "
                              "here (sudden penetrations kept as the springs' zero; docs/contact_erosion.md): "
                              "not implemented");
  if (spec.mortar_coupling)
    throw NotImplementedError(spec.where + ": " + part + "the mortar coupling (_MORTAR) with eroding parts is not "
                                                         "implemented (the slave surface's weights would not follow "
                                                         "the erosion)");
  if (spec.node_set_slaves && spec.form != F::automatic_nodes_to_surface)
    for (Index n : spec.slave.nodes)
      if (eroding_part[static_cast<std::size_t>(n)] != 0)
        throw NotImplementedError(spec.where + ": part " + std::to_string(eroding_part[static_cast<std::size_t>(n)]) +
                                  " can erode and holds slave nodes of a node set (SSTYP 4): not implemented on this "
                                  "card (a node-set slave side with eroding parts runs on "
                                  "*CONTACT_ERODING_NODES_TO_SURFACE and *CONTACT_AUTOMATIC_NODES_TO_SURFACE); "
                                  "select the slave side by part (SSTYP 2 or 3)");
  if (spec.interior_faces) {
    add_interior_faces(spec.slave, ctx, spec.where + ": SSID", spec.interior_faces_between_parts_only);
    if (spec.symmetry_faces_out) drop_symmetry_faces(spec.slave, ctx);
    if (spec.single_surface) {
      spec.master = spec.slave;
    } else {
      add_interior_faces(spec.master, ctx, spec.where + ": MSID", spec.interior_faces_between_parts_only);
      if (spec.symmetry_faces_out) drop_symmetry_faces(spec.master, ctx);
    }
  }
  spec.eroding = true;
}

}  // namespace slideline
