#include "slideline/scenarios/two_block.hpp"

#include "block_mesh.hpp"

#include <algorithm>

namespace slideline::scenarios {

using detail::Grid;
using detail::lines;
using detail::merge_lines;
using detail::MeshWriter;

namespace {

/// The cards every pair shares, written by the first call: material, section, hourglass, the load
/// curves and body loads, damping, termination and output.
void add_common_cards(model::Model& m, const TwoBlockOptions& o) {
  const Id mat_id = o.first_id, sec_id = o.first_id, hg_id = o.first_id;
  const Id curve_y = o.first_id, curve_x = o.first_id + 1;
  m.title = "slideline two-block problem (LLNL DYNA3D contact verification, scenario 1)";
  m.materials.push_back(model::MatMooneyRivlin{mat_id, 0.01, 0.1, 909.091, 0.0, "rubber", {}});
  m.solid_sections.push_back({sec_id, 1, {}});
  m.hourglasses.push_back({hg_id, 10, 1.0, 1.5, 0.06, {}});
  m.bulk_viscosity = {1.5, 0.06};
  m.curves.push_back({curve_y, "load_y", 0, 1.0, 1.0, 0.0, 0.0, 0,
                      {{0.0, 0.0}, {0.1, 1.0}, {1000.0, 1.0}}, {}});
  m.curves.push_back({curve_x, "load_x", 0, 1.0, 1.0, 0.0, 0.0, 0,
                      {{0.0, 0.0}, {0.3, 0.0}, {0.4, 1.0}, {1000.0, 1.0}}, {}});
  // Body loads: LS-DYNA base accelerations, so the sign is opposite to the force. The upper block
  // has mass 0.01 (density 0.01, volume 1).
  const Real upper_mass = 0.01;
  m.body_loads.push_back({Axis::y, curve_y, o.py / upper_mass, 0, 0, 0, 0, 0, {}});
  m.body_loads.push_back({Axis::x, curve_x, -o.px / upper_mass, 0, 0, 0, 0, 0, {}});
  m.damping_global = model::DampingGlobal{0, 2.0 * 0.05 * 150.0, {0, 0, 0, 0, 0, 0}, {}};
  m.termination.endtim = o.end_time;
  m.timestep.tssfac = 0.9;
  m.database.rcforc = m.database.spcforc = m.database.nodout = m.database.glstat = o.history_interval;
  m.database.d3plot = o.state_interval;
}

}  // namespace

TwoBlockIds add_solid_pair(model::Model& m, const TwoBlockOptions& o) {
  if (m.materials.empty()) add_common_cards(m, o);
  const Id id = o.first_id;
  TwoBlockIds ids;
  Id next_part = 1, next_set = 1;
  for (const auto& p : m.parts) next_part = std::max(next_part, p.pid + 1);
  for (const auto& s : m.node_sets) next_set = std::max(next_set, s.sid + 1);
  for (const auto& s : m.part_sets) next_set = std::max(next_set, s.sid + 1);
  Id next_node = id, next_elem = id;
  for (const auto& n : m.nodes) next_node = std::max(next_node, n.id + 1);
  for (const auto& e : m.solids) next_elem = std::max(next_elem, e.id + 1);

  const Real x0 = o.origin_x;
  const Real xu = x0 + o.x_offset;
  std::vector<Real> ux = lines(xu, 1.0, 3), uy = lines(1.0, 1.0, 2), uz = lines(0.01, 1.0, 3);
  std::vector<Real> lx = lines(x0, 1.51, 3), ly = lines(0.0, 1.0, 2), lz = lines(0.0, 1.02, 2);
  if (o.merged) {
    lx = merge_lines(lx, ux, x0, x0 + 1.51);
    lz = merge_lines(lz, uz, 0.0, 1.02);
  }
  ids.lower_part = next_part++;
  ids.upper_part = next_part++;
  m.parts.push_back({ids.lower_part, "lower_block", m.solid_sections.front().secid,
                     model::material_id(m.materials.front()), 0, m.hourglasses.front().hgid, {}});
  m.parts.push_back({ids.upper_part, "upper_block", m.solid_sections.front().secid,
                     model::material_id(m.materials.front()), 0, m.hourglasses.front().hgid, {}});

  MeshWriter w(m, next_node, next_elem);
  const Grid lower = w.add_grid(lx, ly, lz, ids.lower_part, false);
  const Grid upper = w.add_grid(ux, uy, uz, ids.upper_part, o.merged);

  auto add_set = [&](const std::string& title, std::vector<Id> nodes) {
    m.node_sets.push_back({next_set, title, std::move(nodes), {}});
    return next_set++;
  };
  std::vector<Id> bottom, right, ltop, ubot;
  for (std::size_t k = 0; k < lower.zs.size(); ++k)
    for (std::size_t i = 0; i < lower.xs.size(); ++i) {
      bottom.push_back(lower.at(i, 0, k));
      ltop.push_back(lower.at(i, lower.ys.size() - 1, k));
    }
  for (std::size_t k = 0; k < lower.zs.size(); ++k)
    for (std::size_t j = 0; j < lower.ys.size(); ++j) right.push_back(lower.at(lower.xs.size() - 1, j, k));
  for (std::size_t k = 0; k < upper.zs.size(); ++k)
    for (std::size_t i = 0; i < upper.xs.size(); ++i) ubot.push_back(upper.at(i, 0, k));
  ids.bottom_set = add_set("bottom", bottom);
  ids.right_set = add_set("right", right);
  ids.lower_top_nodes = add_set("lower_top", ltop);
  ids.upper_bottom_nodes = add_set("upper_bottom", ubot);
  m.spcs.push_back({ids.bottom_set, "bottom_y", ids.bottom_set, 0, {0, 1, 0, 0, 0, 0}, {}});
  m.spcs.push_back({ids.right_set, "right_x", ids.right_set, 0, {1, 0, 0, 0, 0, 0}, {}});

  // Body loads act on the upper blocks of every pair: one part set, extended on each call.
  if (!m.body_load_parts) {
    m.part_sets.push_back({next_set, "loaded_parts", {}, {}});
    m.body_load_parts = model::LoadBodyParts{next_set++, {}};
  }
  for (auto& ps : m.part_sets)
    if (ps.sid == m.body_load_parts->psid) ps.parts.push_back(ids.upper_part);

  ids.monitor_upper = detail::nearest_in_layer(upper, 0, xu + 0.5, 0.51);
  ids.monitor_lower = detail::nearest_in_layer(lower, lower.ys.size() - 1, xu + 0.5, 0.51);
  m.database.history_nodes.push_back(ids.monitor_upper);
  if (ids.monitor_lower != ids.monitor_upper) m.database.history_nodes.push_back(ids.monitor_lower);
  return ids;
}

model::Model make_solid_pair_model(const TwoBlockOptions& options) {
  model::Model m;
  add_solid_pair(m, options);
  return m;
}

}  // namespace slideline::scenarios
