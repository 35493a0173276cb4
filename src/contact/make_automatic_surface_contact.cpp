// The LS-DYNA automatic cards, penalty (contact/automatic_surface_contact.hpp): the automatic pass
// over both sides restricted to the cross pairs (*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE), or one way,
// the slave side's nodes on the master side's segments (*CONTACT_AUTOMATIC_NODES_TO_SURFACE,
// *CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE), and the pass that takes over the tie of
// *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK after failure (automatic_tiebreak_contact.hpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "slideline/contact/automatic_surface_contact.hpp"
#include "slideline/contact/automatic_tiebreak_contact.hpp"
#include "slideline/contact/make_contact_interface.hpp"
#include "slideline/contact/search/fcl_broad_phase.hpp"
#include "slideline/contact/segment_contact.hpp"
#include "slideline/contact/sticking_tiebreak_contact.hpp"
#include "slideline/contact/penalty_factory.hpp"
#include "slideline/core/error.hpp"
#include "slideline/mesh/surface_builder.hpp"

namespace slideline {

namespace {

/// The union of two sides' surfaces: the slave side's segments, then the master side's that are
/// not already there (same element, same kind, same nodes), with adjacency built. `sides` gets
/// one mask per segment (bit 1 slave side, bit 2 master side); `from_a` the index in the union of
/// each segment of `a`, and `from_b` (when given) of each segment of `b`.
Surface merge_sides(const Surface& a, const Surface& b, std::vector<std::uint8_t>& sides, std::vector<Index>& from_a,
                    std::vector<Index>* from_b = nullptr) {
  using Key = std::tuple<Index, Index, SegmentKind, std::array<Index, 4>>;
  const auto key = [](const Surface& s, Index k) {
    std::array<Index, 4> n{};
    std::copy_n(&s.conn[4 * static_cast<std::size_t>(k)], 4, n.begin());
    std::sort(n.begin(), n.end());
    const auto u = static_cast<std::size_t>(k);
    return Key{s.block[u], s.element[u], s.kind[u], n};
  };
  Surface out;
  std::map<Key, Index> seen;
  sides.clear();
  from_a.assign(static_cast<std::size_t>(a.segment_count()), -1);
  if (from_b) from_b->assign(static_cast<std::size_t>(b.segment_count()), -1);
  const auto append = [&](const Surface& s, std::uint8_t bit) {
    for (Index k = 0; k < s.segment_count(); ++k) {
      const auto [it, fresh] = seen.emplace(key(s, k), out.segment_count());
      if (bit == 1) from_a[static_cast<std::size_t>(k)] = it->second;
      if (bit == 2 && from_b) (*from_b)[static_cast<std::size_t>(k)] = it->second;
      if (!fresh) {
        sides[static_cast<std::size_t>(it->second)] |= bit;
        continue;
      }
      const auto u = static_cast<std::size_t>(k);
      out.conn.insert(out.conn.end(), &s.conn[4 * u], &s.conn[4 * u] + 4);
      out.block.push_back(s.block[u]);
      out.element.push_back(s.element[u]);
      out.part.push_back(s.part[u]);
      out.kind.push_back(s.kind[u]);
      out.thickness.push_back(s.thickness[u]);
      sides.push_back(bit);
    }
  };
  append(a, 1);
  append(b, 2);
  build_surface_adjacency(out);
  return out;
}

/// Each node's side mask (bit 1: on `slave`, bit 2: on `master`) and offset: the largest of its
/// sides' offsets, each side by its own rule (SST/SFST, MST/SFMT; a node-set slave side: the
/// nodal radius).
struct NodeSides {
  std::vector<std::uint8_t> mask;
  std::vector<Real> offset;
};
NodeSides node_sides(const std::vector<Index>& nodes, const InterfaceSpec& spec) {
  const ContactSide& slave = spec.slave;
  const ContactSide& master = spec.master;
  // SST/SFST offset shells only; a node set's nodes take it as their radius (Type 5's rule).
  const std::vector<Real> on_slave =
      slave_node_offsets(slave, spec.slave_shells, spec.node_set_slaves ? spec.nodal_radius : 0.0);
  const std::vector<Real> on_master = slave_node_offsets(master, spec.master_shells, 0.0);
  NodeSides out{std::vector<std::uint8_t>(nodes.size(), 0), std::vector<Real>(nodes.size(), 0.0)};
  const auto add = [&](std::size_t i, const std::vector<Index>& side, const std::vector<Real>& offsets,
                       std::uint8_t bit) {
    const auto it = std::lower_bound(side.begin(), side.end(), nodes[i]);
    if (it == side.end() || *it != nodes[i]) return;
    out.mask[i] |= bit;
    out.offset[i] = std::max(out.offset[i], offsets[static_cast<std::size_t>(it - side.begin())]);
  };
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    add(i, slave.nodes, on_slave, 1);
    add(i, master.nodes, on_master, 2);
  }
  return out;
}

/// Offset of each segment of `surface` (length) by the rule of its side (`sides`, bit 1 slave,
/// bit 2 master; the larger on both).
std::vector<Real> segment_offsets(const Surface& surface, const std::vector<std::uint8_t>& sides,
                                  const InterfaceSpec& spec) {
  std::vector<Real> out(sides.size(), 0.0);
  for (Index s = 0; s < surface.segment_count(); ++s) {
    const auto u = static_cast<std::size_t>(s);
    if (sides[u] & 1) out[u] = segment_offset(surface, s, spec.slave_shells);
    if (sides[u] & 2) out[u] = std::max(out[u], segment_offset(surface, s, spec.master_shells));
  }
  return out;
}

/// THKCHG = 1 (InterfaceSpec::follow_thickness): node_sides' and segment_offsets' rules as
/// offsets that follow the shells' current thickness (FollowedOffsets, shell_offset.hpp).
FollowedOffsets followed_node_sides(const std::vector<Index>& nodes, const InterfaceSpec& spec) {
  const auto on = [](const std::vector<Index>& side, Index n) {
    return std::binary_search(side.begin(), side.end(), n);
  };
  FollowedOffsets f;
  for (const Index n : nodes) {
    Real floor = 0.0;
    if (on(spec.slave.nodes, n)) {
      floor = spec.node_set_slaves ? spec.nodal_radius : 0.0;
      f.add_node_of(spec.slave.surface, n, spec.slave_shells, floor);
    }
    if (on(spec.master.nodes, n)) f.add_node_of(spec.master.surface, n, spec.master_shells, floor);
    f.close(floor);
  }
  return f;
}
FollowedOffsets followed_segment_offsets(const Surface& surface, const std::vector<std::uint8_t>& sides,
                                         const InterfaceSpec& spec) {
  FollowedOffsets f;
  for (Index s = 0; s < surface.segment_count(); ++s) {
    Real floor = 0.0;
    if (sides[static_cast<std::size_t>(s)] & 1) f.add_segment(surface, s, spec.slave_shells, floor);
    if (sides[static_cast<std::size_t>(s)] & 2) f.add_segment(surface, s, spec.master_shells, floor);
    f.close(floor);
  }
  return f;
}

/// The automatic pass of an automatic card and what its interface needs besides.
struct AutomaticPass {
  std::unique_ptr<PenaltyPass> pass;
  std::vector<std::uint8_t> sides;  ///< per segment of the pass's surface (bit 1 slave, bit 2 master side)
  std::vector<Index> from_slave;    ///< two-sided: per slave-side segment, its index in the pass's surface
  std::vector<Index> from_master;   ///< two-sided: per master-side segment, its index in the pass's surface
};

AutomaticPass make_automatic_pass(InterfaceSpec& spec, const ContactBuildContext& ctx) {
  const bool two_sided = spec.form == model::ContactForm::automatic_surface_to_surface;
  // Two-sided: every node and segment of both sides, cross pairs only. One way: the slave side's
  // nodes against the master side's segments (every pair is a cross pair).
  ContactSide pass_side;  // the pass's slaves (nodes) and, for the mortar coupling, their surface
  Surface master;
  AutomaticPass out;
  if (two_sided) {
    master = merge_sides(spec.slave.surface, spec.master.surface, out.sides, out.from_slave, &out.from_master);
    pass_side.surface = master;
    pass_side.nodes = master.nodes;
  } else {
    master = spec.master.surface;
    out.sides.assign(static_cast<std::size_t>(master.segment_count()), 2);
    pass_side = spec.slave;
  }
  NodeSides nodes = node_sides(pass_side.nodes, spec);
  std::vector<Real> offsets = segment_offsets(master, out.sides, spec);
  // Orientation of a solid node: its own faces (the union, the slave surface, or for a node set
  // the faces of the parts it lies on).
  // With eroding parts a node set's own faces include the interior faces of its erodible solids
  // (eroding_node_set_faces), so that the faces a deletion lays bare orient it.
  const Surface own = two_sided ? master
                      : spec.node_set_slaves
                          ? (spec.eroding ? eroding_node_set_faces(pass_side.nodes, ctx, spec.where + ": SSID")
                                          : node_set_faces(pass_side.nodes, ctx, spec.where + ": SSID"))
                          : spec.slave.surface;
  // The automatic pass (skip incident segments and a shell part's own segments, orientation of
  // solid faces, re-pick among the candidates between searches) at SLSFAC x SFS (the reader
  // refuses SFM != SFS for a one-pass interface).
  out.pass = make_penalty_pass(pass_side, std::move(nodes.offset), master,
                               penalty_pass_options(spec, spec.slave_stiffness, spec.master_shells));
  out.pass->slave_part() = node_parts(pass_side);
  out.pass->set_slave_orientation(SlaveOrientation(own, pass_side.nodes));
  out.pass->set_sides(std::move(nodes.mask), out.sides, std::move(offsets));
  if (spec.follow_thickness)
    out.pass->set_followed_offsets(followed_node_sides(pass_side.nodes, spec),
                                   followed_segment_offsets(master, out.sides, spec));
  // Eroding parts (docs/contact_erosion.md): two-sided, the slaves lie on the pass's surface; one
  // way, on their own side's.
  // A node set's slaves stay while an element holds them (set_node_set_slave_elements).
  if (spec.eroding) {
    ContactErosion erosion(master, two_sided ? nullptr : &own, pass_side.nodes);
    if (spec.node_set_slaves && !two_sided) set_node_set_slave_elements(erosion, pass_side.nodes, ctx);
    set_retained_slave_nodes(erosion, pass_side.nodes, ctx, spec.enmass);
    out.pass->set_erosion(std::move(erosion));
  }
  return out;
}

}  // namespace

std::unique_ptr<ContactAlgorithm> make_segment_contact(InterfaceSpec& spec) {
  if (spec.eroding)
    throw NotImplementedError(spec.where + ": SOFT = 2 (segment-based contact, optional card A) with eroding parts "
                                           "is not implemented");
  std::vector<std::uint8_t> sides;
  Surface surface;
  if (spec.single_surface) {  // *CONTACT_AUTOMATIC_SINGLE_SURFACE: every segment on both sides
    surface = spec.slave.surface;
    build_surface_adjacency(surface);
    sides.assign(static_cast<std::size_t>(surface.segment_count()), 3);
  } else {
    std::vector<Index> from_slave;
    surface = merge_sides(spec.slave.surface, spec.master.surface, sides, from_slave);
  }
  std::vector<Id> parts = surface.part;  // the single surface's parts: of its segments
  std::sort(parts.begin(), parts.end());
  parts.erase(std::unique(parts.begin(), parts.end()), parts.end());
  // Shells: half the contact thickness off the mid-surface, by each side's rule (SST x SFST,
  // MST x SFMT, else the section's thickness), as the automatic pass offsets them.
  std::vector<Real> offsets = segment_offsets(surface, sides, spec);
  auto contact = std::make_unique<SegmentContact>(spec.title, std::move(surface), std::move(sides),
                                                  std::make_unique<FclBroadPhase>(), spec.slave_stiffness);
  contact->set_offsets(std::move(offsets));
  contact->set_friction(spec.friction, spec.viscous_damping);
  contact->set_search_interval(spec.search_interval);
  if (spec.single_surface) contact->set_single_surface(std::move(parts));
  return contact;
}

std::unique_ptr<ContactAlgorithm> make_automatic_surface_contact(InterfaceSpec& spec, const ContactBuildContext& ctx) {
  if (spec.segment_based) return make_segment_contact(spec);
  AutomaticPass a = make_automatic_pass(spec, ctx);
  return make_penalty_interface<AutomaticSurfaceContact>(spec, std::move(a.pass), std::move(a.sides));
}

namespace {

/// OPTION 1 (blank, 0) and 3: ties formed at t = 0 and at each slave node's first touch
/// (sticking_tiebreak_contact.hpp), over the card *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE's pass.
std::unique_ptr<ContactAlgorithm> make_sticking_tiebreak_contact(InterfaceSpec& spec, const ContactBuildContext& ctx) {
  if (spec.node_set_slaves)
    throw NotImplementedError(spec.where + ": a node-set slave side on *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK "
                                           "OPTION 1 or 3 is not implemented (the tie's stresses need the slave segments)");
  InterfaceSpec contact_spec = spec;
  contact_spec.type = model::ContactType::automatic;
  contact_spec.keep_initial_penetrations = true;
  AutomaticPass a = make_automatic_pass(contact_spec, ctx);
  std::vector<std::uint8_t> held_nodes(ctx.nodes.size(), 0);
  std::vector<std::uint8_t> held_segments(a.sides.size(), 0);
  a.pass->set_held(held_nodes, held_segments);  // views; the vectors' buffers move with them
  const PenaltyPass* pass = a.pass.get();        // owned by the interface from here on
  std::vector<std::uint8_t> sides = a.sides;
  auto contact = make_penalty_interface<AutomaticSurfaceContact>(contact_spec, std::move(a.pass), std::move(a.sides));
  StickingTieParameters p;
  p.fails = spec.cohesive.option == 3;
  p.normal_failure = p.fails ? spec.failure.normal : 0.0;
  p.shear_failure = p.fails ? spec.failure.shear : 0.0;
  return std::make_unique<StickingTiebreakContact>(spec.title, std::move(contact), pass, std::move(sides),
                                                   std::move(spec.slave.nodes), std::move(spec.master.nodes),
                                                   std::move(spec.slave.surface), std::move(a.from_slave),
                                                   std::move(spec.master.surface),
                                                   std::move(a.from_master), std::move(held_nodes),
                                                   std::move(held_segments), p);
}

}  // namespace

std::unique_ptr<ContactAlgorithm> make_automatic_tiebreak_contact(InterfaceSpec& spec, const ContactBuildContext& ctx) {
  const int option = spec.cohesive.option;
  // OPTION 8 is OPTION 6 on offset shells (the tie and the pass offset by SST / MST x SFST / SFMT,
  // shell_offset.hpp); every other OPTION ties solid faces only.
  const bool shells = option == 8;
  if (!shells)
    for (const Surface* side : {&spec.slave.surface, &spec.master.surface})
      for (Index s = 0; s < side->segment_count(); ++s)
        if (side->kind[static_cast<std::size_t>(s)] == SegmentKind::shell)
          throw NotImplementedError(spec.where + ": shell segments on *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK "
                                                 "OPTION " + std::to_string(option) + " are not implemented (its tie has "
                                                 "no thickness offsets; OPTION 8 has them); solid faces only");
  if (option == 0 || option == 1 || option == 3) return make_sticking_tiebreak_contact(spec, ctx);
  if (option != 2 && option != 4 && option != 6 && option != 8 && option != 9)
    throw NotImplementedError(spec.where + ": OPTION = " + std::to_string(option) +
                              " of *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK is not implemented");
  if (shells) {  // the automatic card's offsets, always on (SHLTHK aside), following THKCHG = 1 alike
    spec.slave_shells.on = spec.master_shells.on = true;
    spec.follow_thickness = ctx.model.control_contact.thkchg == 1;
  }
  // The contact after failure: the card *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE's pass, each node's
  // penetration at t = 0 its spring's zero (IGNORE = 1; the tie keeps its stand-off alike).
  InterfaceSpec contact_spec = spec;
  contact_spec.type = model::ContactType::automatic;
  contact_spec.keep_initial_penetrations = true;
  AutomaticPass a = make_automatic_pass(contact_spec, ctx);
  std::vector<std::uint8_t> held_nodes(ctx.nodes.size(), 0);
  std::vector<std::uint8_t> held_segments(a.sides.size(), 0);
  a.pass->set_held(held_nodes, held_segments);  // views; the vectors' buffers move with them
  auto contact = make_penalty_interface<AutomaticSurfaceContact>(contact_spec, std::move(a.pass), std::move(a.sides));
  // The tie: Type 9's (failure per slave segment, NFLS / SFLS stresses, exponents 2), handing a
  // released node to the pass.
  TiebreakParameters p;
  p.unit = TiebreakParameters::FailureUnit::segment;
  p.penalty_factor = spec.slave_stiffness;
  p.normal_failure = spec.failure.normal;
  p.shear_failure = spec.failure.shear;
  p.friction = spec.friction;
  p.release_to_owner = true;
  p.two_sided_contact = true;
  if (spec.cohesive.option == 9) {  // the mixed-mode traction-separation law instead of the criterion
    const TiebreakCohesive& c = spec.cohesive;
    p.mixed_mode = true;
    p.cohesive = MixedModeCohesiveLaw{c.cn, 0.0, spec.failure.normal, spec.failure.shear, c.eraten, c.erates,
                                      c.param != 0.0 ? std::abs(c.param) : 1.0, c.param < 0.0};
    p.ct2cn = c.ct2cn > 0.0 ? c.ct2cn : 1.0;
  } else if (spec.cohesive.option == 4) {
    // The tie holds the normal direction (failure by NFLS, tension only); tied nodes slide with the
    // card's friction (FS, FD, DC) on the compressive part of their tie force.
    p.normal_only = true;
    p.shear_failure = 0.0;
  } else if (spec.cohesive.option == 6 || shells) {
    // The stress criterion as the onset of a linear softening to zero at PARAM = CCRIT, per tied
    // node, on the tie's own isotropic spring (EN = ET = kappa): the bilinear law with a fixed
    // final separation (mixed_mode_cohesive_law.hpp).
    p.mixed_mode = true;
    p.cohesive = MixedModeCohesiveLaw{0.0, 0.0, spec.failure.normal, spec.failure.shear, 0.0, 0.0, 1.0, false,
                                      spec.cohesive.param};
    p.ct2cn = 1.0;
    if (shells) {
      p.slave_shells = spec.slave_shells;
      p.master_shells = spec.master_shells;
    }
  }
  auto tie = std::make_unique<TiebreakContact>(spec.title, std::move(spec.slave.nodes), std::move(spec.slave.surface),
                                               std::move(spec.master.surface), p);
  return std::make_unique<AutomaticTiebreakContact>(std::move(tie), std::move(contact), std::move(a.from_slave),
                                                    std::move(held_nodes), std::move(held_segments));
}

}  // namespace slideline
