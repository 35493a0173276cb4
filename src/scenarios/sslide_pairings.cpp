// One element pairing of an sslide problem: the lower solid block with its supports, the upper
// body (solid block, shell plate, or a plate in the y-z plane), the optional shell skin on the
// lower block's top face, the sets contacts refer to, and the monitored node and segment.
#include <algorithm>

#include "sslide_build.hpp"

namespace slideline::scenarios::detail {

namespace {

constexpr Real kUpperInset = 0.03;   // upper block's left face, from the lower block's left face
constexpr Real kLowerLength = 1.51;  // lower block in x
constexpr Real kUnitMass = 0.01;     // upper body mass per unit cell

/// The lower top-face cell under (x, z), its nodes counter-clockwise seen from +y, and the
/// bilinear weights of (x, z) in it. xi runs along edge 1-2 (z), eta along edge 1-4 (x).
SslideMonitor locate_on_top(const Grid& lower, Id slave, Real x, Real z) {
  const std::size_t top = lower.ys.size() - 1;
  const std::size_t i = cell_of(lower.xs, x), k = cell_of(lower.zs, z);
  SslideMonitor mon;
  mon.slave_node = slave;
  mon.master_nodes = {lower.at(i, top, k), lower.at(i, top, k + 1), lower.at(i + 1, top, k + 1),
                      lower.at(i + 1, top, k)};
  mon.xi = 2.0 * (z - lower.zs[k]) / (lower.zs[k + 1] - lower.zs[k]) - 1.0;
  mon.eta = 2.0 * (x - lower.xs[i]) / (lower.xs[i + 1] - lower.xs[i]) - 1.0;
  const Real a = mon.xi, b = mon.eta;
  mon.weights = {0.25 * (1 - a) * (1 - b), 0.25 * (1 + a) * (1 - b), 0.25 * (1 + a) * (1 + b),
                 0.25 * (1 - a) * (1 + b)};
  return mon;
}

Real coordinate(const model::Model& m, Id node, int axis) {
  for (auto it = m.nodes.rbegin(); it != m.nodes.rend(); ++it)
    if (it->id == node) return it->x[axis];
  return 0.0;
}

/// The pairing's parts: the lower block, the optional skin, the upper body.
void add_parts(model::Model& m, const SslideCommonIds& common, SslideIds& ids, const SslidePairingRequest& r,
               SslidePairing& p) {
  const bool upper_is_shell = r.upper_shell || r.upper_edge_plate;
  p.lower_part = ids.next_part++;
  m.parts.push_back({p.lower_part, r.name + "_lower", common.solid_section, common.solid_material, 0,
                     common.solid_hourglass, {}});
  if (r.skin) {
    p.skin_part = ids.next_part++;
    m.parts.push_back({p.skin_part, r.name + "_skin", common.shell_section,
                       r.rigid_skin ? common.rigid_material : common.shell_material, 0, common.shell_hourglass, {}});
  }
  p.upper_part = ids.next_part++;
  if (upper_is_shell)
    m.parts.push_back({p.upper_part, r.name + "_upper", common.shell_section, common.shell_material, 0,
                       common.shell_hourglass, {}});
  else
    m.parts.push_back({p.upper_part, r.name + "_upper", common.solid_section, common.solid_material, 0,
                       common.solid_hourglass, {}});
}

/// The pairing's meshes and where the upper body sits.
struct PairingMesh {
  Grid lower, upper;
  std::vector<Id> contact_nodes;  // the upper body's contact nodes
  Real xu = 0.0;                  // the upper body's left face
  Real z0 = 0.0;                  // the upper body's near face in z
};

PairingMesh add_meshes(SslideIds& ids, const SslidePairingRequest& r, const SslidePairing& p) {
  // Lower block: 2 elements per unit length in x and z, 2 through y. The upper body is centred in
  // z (0.01 margin per unit cell on each side) and inset 0.03 in x, so that none of its nodes lies
  // on a lower grid line and it can slide 0.45 in +x and stay seated.
  PairingMesh g;
  const Real depth = 1.02 * r.cells;
  g.z0 = 0.01 * r.cells;
  const int nz_upper = static_cast<int>(3 * r.cells), nz_lower = static_cast<int>(2 * r.cells);
  g.xu = r.x0 + kUpperInset;
  g.lower = ids.mesh.add_grid(lines(r.x0, kLowerLength, 3), lines(0.0, 1.0, 2), lines(0.0, depth, nz_lower),
                              p.lower_part, false);
  if (r.skin) {
    const Grid skin = ids.mesh.add_nodes(g.lower.xs, {g.lower.ys.back()}, g.lower.zs, true);
    ids.mesh.add_shells(skin, p.skin_part, true);
  }
  if (r.upper_edge_plate) {
    g.upper = ids.mesh.add_nodes({g.xu + 0.5}, lines(1.0 + r.gap, 1.0, 3), lines(g.z0, r.cells, nz_upper), false);
    ids.mesh.add_shells(g.upper, p.upper_part, false);
    g.contact_nodes = layer_nodes(g.upper, 0);  // the bottom edge
  } else if (r.upper_shell) {
    g.upper = ids.mesh.add_nodes(lines(g.xu, 1.0, 3), {1.0 + r.gap}, lines(g.z0, r.cells, nz_upper), false);
    ids.mesh.add_shells(g.upper, p.upper_part, true);
    g.contact_nodes = layer_nodes(g.upper, 0);
  } else {
    g.upper = ids.mesh.add_grid(lines(g.xu, 1.0, 3), lines(1.0 + r.gap, 1.0, 2), lines(g.z0, r.cells, nz_upper),
                                p.upper_part, false);
    g.contact_nodes = layer_nodes(g.upper, 0);
  }
  return g;
}

/// The supports and the node, segment and part sets the contacts refer to.
void add_sets(model::Model& m, const SslideCommonIds& common, SslideIds& ids, const SslidePairingRequest& r,
              const SslidePairing& p, const PairingMesh& g, SslidePairingSets& sets) {
  const Grid& lower = g.lower;
  auto add_node_set = [&](const std::string& title, std::vector<Id> nodes) {
    m.node_sets.push_back({ids.next_set, title, std::move(nodes), {}});
    return ids.next_set++;
  };
  const Id bottom = add_node_set(p.bottom_support, layer_nodes(lower, 0));
  // A rigid skin owns the top-face nodes; LS-DYNA ignores SPCs on rigid-body nodes, so the right
  // support leaves them out (the bricks below hold the skin).
  std::vector<Id> right_nodes = x_face_nodes(lower, lower.xs.size() - 1);
  if (r.rigid_skin) {
    const auto top = layer_nodes(lower, lower.ys.size() - 1);
    std::erase_if(right_nodes, [&](Id n) { return std::find(top.begin(), top.end(), n) != top.end(); });
  }
  const Id right = add_node_set(p.right_support, right_nodes);
  m.spcs.push_back({bottom, p.bottom_support, bottom, 0, {0, 1, 0, 0, 0, 0}, {}});
  m.spcs.push_back({right, p.right_support, right, 0, {1, 0, 0, 0, 0, 0}, {}});
  sets.upper_nodes = add_node_set(r.name + "_upper_contact_nodes", g.contact_nodes);
  if (!(r.upper_shell || r.upper_edge_plate)) {
    m.segment_sets.push_back({ids.next_set, r.name + "_upper_bottom", layer_segments(g.upper, 0, false), {}});
    sets.upper_segments = ids.next_set++;
  }
  m.segment_sets.push_back(
      {ids.next_set, r.name + "_lower_top", layer_segments(lower, lower.ys.size() - 1, true), {}});
  sets.lower_segments = ids.next_set++;
  m.part_sets.push_back({ids.next_set, r.name + "_contact_parts", {p.upper_part, r.skin ? p.skin_part : p.lower_part}, {}});
  sets.contact_parts = ids.next_set++;
  for (auto& ps : m.part_sets)
    if (ps.sid == common.loaded_parts) ps.parts.push_back(p.upper_part);
}

/// The monitor: the contact node nearest the centre of the contact area, the segment under it,
/// the row of segments it slides over and the leading edge, and their history nodes.
void add_monitor(model::Model& m, const SslidePairingRequest& r, const PairingMesh& g, SslidePairing& p) {
  const Grid& lower = g.lower;
  const Id slave = nearest_in_layer(g.upper, 0, g.xu + 0.5, g.z0 + 0.5 * r.cells);
  p.monitor = locate_on_top(lower, slave, coordinate(m, slave, 0), coordinate(m, slave, 2));
  p.monitor.slave_x0 = Vec3(coordinate(m, slave, 0), coordinate(m, slave, 1), coordinate(m, slave, 2));
  // The row of top-face segments under the slave's z, over the whole block length: the slave
  // slides along +x and the criteria re-project it onto the segment it is over at each output.
  const std::size_t top = lower.ys.size() - 1, k = cell_of(lower.zs, p.monitor.slave_x0.z());
  for (std::size_t i = 0; i + 1 < lower.xs.size(); ++i) {
    SslideMonitorSegment seg;
    const std::array<std::size_t, 4> ci{i, i, i + 1, i + 1}, ck{k, k + 1, k + 1, k};
    for (int c = 0; c < 4; ++c) {
      seg.nodes[c] = lower.at(ci[c], top, ck[c]);
      seg.x0[c] = lower.coord(ci[c], top, ck[c]);
    }
    p.monitor.path.push_back(seg);
  }
  // The leading edge: the contact node at the upper body's +x end in the slave's row (the edge
  // plate's own x: it is its own leading edge).
  p.monitor.leading_node = nearest_in_layer(g.upper, 0, g.xu + 1.0, p.monitor.slave_x0.z());
  p.monitor.leading_x0 = Vec3(coordinate(m, p.monitor.leading_node, 0), coordinate(m, p.monitor.leading_node, 1),
                              coordinate(m, p.monitor.leading_node, 2));
  m.database.history_nodes.push_back(slave);
  if (p.monitor.leading_node != slave) m.database.history_nodes.push_back(p.monitor.leading_node);
  for (Id n : p.monitor.master_nodes) m.database.history_nodes.push_back(n);
  for (const auto& seg : p.monitor.path)
    for (Id n : seg.nodes)
      if (std::find(m.database.history_nodes.begin(), m.database.history_nodes.end(), n) ==
          m.database.history_nodes.end())
        m.database.history_nodes.push_back(n);
}

}  // namespace

SslidePairing add_sslide_pairing(model::Model& m, const SslideCommonIds& common, SslideIds& ids,
                                 const SslidePairingRequest& r, SslidePairingSets& sets) {
  SslidePairing p;
  p.name = r.name;
  p.contact_title = r.name;
  p.bottom_support = r.name + "_bottom";
  p.right_support = r.name + "_right";
  p.gap = r.gap;
  p.upper_mass = kUnitMass * r.cells;
  p.px = r.px;
  p.py = r.py;
  add_parts(m, common, ids, r, p);
  const PairingMesh mesh = add_meshes(ids, r, p);
  add_sets(m, common, ids, r, p, mesh, sets);
  add_monitor(m, r, mesh, p);
  return p;
}

}  // namespace slideline::scenarios::detail
