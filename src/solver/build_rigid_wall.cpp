// The builder's part for *RIGIDWALL_PLANAR[_FINITE]: slave nodes, their fixed components and the
// wall's geometry, with located errors for what cannot be built (validate_model refused the
// fields not honoured).
#include <algorithm>
#include <cmath>
#include <iterator>

#include "build_support.hpp"
#include "slideline/solver/rigid_wall.hpp"

namespace slideline {

namespace {

/// Every node, or the set's; less NSIDEX's; sorted.
std::vector<Index> wall_nodes(const model::RigidWallPlanar& w, const RigidWallContext& ctx, const std::string& card) {
  std::vector<Index> nodes;
  if (w.nsid == 0) {
    nodes.resize(ctx.node_ids.size());
    for (std::size_t i = 0; i < nodes.size(); ++i) nodes[i] = static_cast<Index>(i);
  } else {
    nodes = ctx.sets.node_set(w.nsid, card + ": NSID");
    std::sort(nodes.begin(), nodes.end());
  }
  if (w.nsidex != 0) {
    auto ex = ctx.sets.node_set(w.nsidex, card + ": NSIDEX");
    std::sort(ex.begin(), ex.end());
    std::vector<Index> kept;
    std::set_difference(nodes.begin(), nodes.end(), ex.begin(), ex.end(), std::back_inserter(kept));
    nodes = std::move(kept);
  }
  return nodes;
}

}  // namespace

std::unique_ptr<NodalConstraint> make_rigid_wall(const model::RigidWallPlanar& w, std::size_t k,
                                                 const RigidWallContext& ctx) {
  const std::string card = describe(w.src) + ": *RIGIDWALL_PLANAR";
  RigidWallSpec s;
  s.name = !w.title.empty() ? w.title : "rw_" + std::to_string(w.id != 0 ? w.id : static_cast<Id>(k));
  const Vec3 n = w.head - w.tail;
  if (!(n.norm() > 0.0))
    throw InputError(card + ": the head XH YH ZH equals the tail XT YT ZT (no normal)");
  s.point = w.tail;
  s.normal = n / n.norm();
  if (w.finite) {
    Vec3 l = w.edge_head - w.tail;
    l -= l.dot(s.normal) * s.normal;  // LS-DYNA: the l edge lies in the plane
    if (!(l.norm() > 1e-12 * n.norm()) || !(w.lenl > 0.0) || !(w.lenm > 0.0))
      throw InputError(card + "_FINITE: XHEV YHEV ZHEV must give an edge direction in the plane and LENL, LENM "
                              "must be positive");
    s.finite = true;
    s.l_axis = l / l.norm();
    s.m_axis = s.normal.cross(s.l_axis);
    s.lenl = w.lenl;
    s.lenm = w.lenm;
  }
  s.friction = w.fric;
  s.birth = w.birth;
  s.death = w.death > 0.0 ? w.death : 1e20;
  s.nodes = wall_nodes(w, ctx, card);
  std::vector<std::uint8_t> fixed(ctx.node_ids.size(), 0);
  for (const auto& g : ctx.supports)
    for (const auto& sp : g.supports)
      if (!sp.rotational)
        for (Index i : sp.nodes) fixed[static_cast<std::size_t>(i)] |= static_cast<std::uint8_t>(1u << static_cast<int>(sp.axis));
  for (Index i : s.nodes) {
    if (const auto r = ctx.rigid_node_part.find(i); r != ctx.rigid_node_part.end())
      throw NotImplementedError(card + ": node " + std::to_string(ctx.node_ids[static_cast<std::size_t>(i)]) +
                                " belongs to rigid part " +
                                std::to_string(r->second) +
                                "; a rigid wall on rigid-body nodes is not implemented (exclude them with NSIDEX)");
    const std::uint8_t f = fixed[static_cast<std::size_t>(i)];
    for (int c = 0; c < 3; ++c)
      if ((f & (1u << c)) && std::abs(s.normal[c]) > 1e-12)
        throw NotImplementedError(card + ": a slave node is held in direction " + std::to_string(c + 1) +
                                  " by a support and the wall's normal has a component along it; not implemented");
    s.fixed.push_back(f);
  }
  return std::make_unique<RigidWall>(std::move(s));
}

}  // namespace slideline
