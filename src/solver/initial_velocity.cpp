// Initial velocities (see initial_velocity.hpp and docs/keywords.md for the semantics).
#include "initial_velocity.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "slideline/solver/coordinate_axes.hpp"
#include "slideline/core/error.hpp"
#include "slideline/solver/build.hpp"
#include "slideline/solver/rigid_body.hpp"

namespace slideline {
namespace {

/// "deck.k:12: *INITIAL_VELOCITY" for messages.
template <class Card>
std::string place(const model::Model& m, const Card& c, const char* keyword) {
  return describe(model::element_source(m, c)) + ": " + keyword;
}

/// The rotation from system `icid` to global (identity for 0): the card's velocities are given in
/// that system (LS-DYNA's ICID). The system at t = 0 (a moving system has not moved yet).
Mat3 velocity_frame(const model::Model& m, Id icid, const std::string& where) {
  return icid == 0 ? Mat3::Identity() : local_axes(m, icid, where + " field ICID").r;
}

std::string num(Real v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

/// The velocity each node receives and which card gave it.
class Assignment {
 public:
  Assignment(const NodalFields& nodes, std::vector<std::uint8_t> rotational)
      : nodes_(nodes), rotational_(std::move(rotational)), v_(nodes.size(), Vec3::Zero()),
        w_(nodes.size(), Vec3::Zero()), owner_(nodes.size(), -1) {}

  /// Starts a card; `where` is "file:line: *KEYWORD".
  void begin_card(std::string where, bool has_rotation) {
    cards_.push_back(std::move(where));
    card_rotation_.push_back(has_rotation);
    card_reaches_rotation_.push_back(false);
  }

  void set(Index i, const Vec3& v, const Vec3& w) {
    const int card = static_cast<int>(cards_.size()) - 1;
    const Vec3 wi = rotational_[i] ? w : Vec3::Zero();
    if (rotational_[i]) card_reaches_rotation_.back() = true;
    if (owner_[i] >= 0 && owner_[i] != card && (v_[i] != v || w_[i] != wi))
      throw InputError(cards_[card] + " gives node " + std::to_string(nodes_.ids[i]) +
                       " a velocity that differs from the one " + cards_[owner_[i]] +
                       " gives it; one node takes one initial velocity (cards do not override each "
                       "other: exempt the node, e.g. with NSIDEX of *INITIAL_VELOCITY)");
    v_[i] = v;
    w_[i] = wi;
    owner_[i] = card;
  }

  /// A rotational velocity that no node of the card can carry would be lost: refuse it.
  void end_card() const {
    if (card_rotation_.back() && !card_reaches_rotation_.back())
      throw InputError(cards_.back() +
                       ": rotational velocity given, but none of its nodes carries rotations (only "
                       "shell nodes do; a solid spins through the translational velocities, e.g. "
                       "*INITIAL_VELOCITY_GENERATION)");
  }

  bool assigned(Index i) const { return owner_[i] >= 0; }
  const std::string& card_of(Index i) const { return cards_[owner_[i]]; }
  const Vec3& v(Index i) const { return v_[i]; }
  const Vec3& w(Index i) const { return w_[i]; }
  Vec3& v(Index i) { return v_[i]; }
  Vec3& w(Index i) { return w_[i]; }
  bool rotational(Index i) const { return rotational_[i] != 0; }

 private:
  const NodalFields& nodes_;
  std::vector<std::uint8_t> rotational_;
  std::vector<Vec3> v_, w_;
  std::vector<int> owner_;
  std::vector<std::string> cards_;
  std::vector<bool> card_rotation_, card_reaches_rotation_;
};

std::vector<Index> all_nodes(std::size_t n) {
  std::vector<Index> out(n);
  for (std::size_t i = 0; i < n; ++i) out[i] = static_cast<Index>(i);
  return out;
}

void apply_set_cards(const InitialVelocityInputs& in, const NodalFields& nodes, Assignment& a) {
  const model::Model& m = in.model;
  for (const auto& iv : m.initial_velocities) {
    const std::string where = place(m, iv, "*INITIAL_VELOCITY");
    // validate_model refused negative NSID, NSIDEX, BOXID.
    const Mat3 r = velocity_frame(m, iv.icid, where);
    std::vector<Index> targets =
        iv.nsid == 0 ? all_nodes(nodes.size()) : in.sets.node_set(iv.nsid, where + ": NSID");
    std::vector<Index> exempt;
    if (iv.nsidex > 0) exempt = in.sets.node_set(iv.nsidex, where + ": NSIDEX");
    if (iv.boxid > 0) {
      const auto box = std::find_if(m.boxes.begin(), m.boxes.end(),
                                    [&](const model::Box& b) { return b.boxid == iv.boxid; });
      if (box == m.boxes.end())
        throw InputError(where + ": BOXID refers to *DEFINE_BOX " + std::to_string(iv.boxid) +
                         ", which the deck does not define");
      // LS-DYNA: only the nodes of NSID inside the box (at t = 0) are initialised.
      std::erase_if(targets, [&](Index i) {
        for (int c = 0; c < 3; ++c)
          if (nodes.x0[c][i] < box->min[c] || nodes.x0[c][i] > box->max[c]) return true;
        return false;
      });
    }
    a.begin_card(where, iv.vr != Vec3::Zero() || (iv.nsidex > 0 && iv.vre != Vec3::Zero()));
    for (Index i : targets)
      if (!std::binary_search(exempt.begin(), exempt.end(), i)) a.set(i, r * iv.v, r * iv.vr);
    for (Index i : exempt) a.set(i, r * iv.ve, r * iv.vre);
    a.end_card();
  }
}

void apply_generation_cards(const InitialVelocityInputs& in, const NodalFields& nodes, Assignment& a) {
  const model::Model& m = in.model;
  for (const auto& g : m.initial_velocity_generations) {
    const std::string where = place(m, g, "*INITIAL_VELOCITY_GENERATION");
    // validate_model refused IVATN, PHASE != 0, an STYP out of 1-3, OMEGA without an axis and OMEGA
    // with ICID (the manual gives VX VY VZ in the local system; the axis's frame it leaves open).
    std::vector<Index> targets;
    if (g.id == 0) {
      // ID = 0: every node, STYP ignored (our reading of the LS-DYNA manual: "if zero, STYP is
      // ignored and all velocities are set").
      targets = all_nodes(nodes.size());
    } else if (g.styp == 1) {
      std::vector<Index> all;
      for (Id pid : in.sets.part_set(g.id, where + ": ID (STYP = 1)")) {
        const auto& pn = in.sets.nodes_of_part(pid, where + ": a part of part set " + std::to_string(g.id));
        all.insert(all.end(), pn.begin(), pn.end());
      }
      std::sort(all.begin(), all.end());
      all.erase(std::unique(all.begin(), all.end()), all.end());
      targets = std::move(all);
    } else if (g.styp == 2) {
      targets = in.sets.nodes_of_part(g.id, where + ": ID (STYP = 2)");
    } else if (g.styp == 3) {
      targets = in.sets.node_set(g.id, where + ": ID (STYP = 3)");
    }
    const Vec3 axis = g.omega != 0.0 ? Vec3(g.n / g.n.norm()) : Vec3::Zero();
    const Vec3 spin = g.omega * axis;  // angular velocity vector
    const Vec3 v = velocity_frame(m, g.icid, where) * g.v;
    a.begin_card(where, false);        // the spin reaches rotational dofs only where they exist
    for (Index i : targets) a.set(i, v + spin.cross(nodes.x0.get(i) - g.xc), spin);
  }
}

void apply_node_cards(const InitialVelocityInputs& in, Assignment& a) {
  const model::Model& m = in.model;
  for (const auto& iv : m.initial_velocity_nodes) {
    const std::string where = place(m, iv, "*INITIAL_VELOCITY_NODE");
    const auto f = in.node_index.find(iv.nid);
    if (f == in.node_index.end())
      throw InputError(where + ": NID refers to node " + std::to_string(iv.nid) +
                       ", which the deck does not define");
    const Mat3 r = velocity_frame(m, iv.icid, where);
    a.begin_card(where, iv.vr != Vec3::Zero());
    a.set(f->second, r * iv.v, r * iv.vr);
    a.end_card();
  }
}


/// A rigid part moves as one body: RigidBody::initialize projects its nodes' velocities onto the
/// body's momentum and angular momentum, which reproduces them only if they already are one
/// rigid-body motion V + Omega x (x - c). Anything else (a velocity on some of its nodes only, a
/// spin without the matching translations) would be silently averaged away: refuse it.
void check_rigid_parts(const InitialVelocityInputs& in, const NodalFields& nodes, const Assignment& a) {
  std::map<Id, std::vector<Index>> parts;
  for (const auto& [i, pid] : in.rigid_node_part) parts[pid].push_back(i);
  for (auto& [pid, pn] : parts) {
    std::sort(pn.begin(), pn.end());
    const auto given = std::find_if(pn.begin(), pn.end(), [&](Index i) { return a.assigned(i); });
    if (given == pn.end()) continue;
    // Unit-weight least-squares fit about the centroid (weights do not matter for an exact fit).
    Vec3 c = Vec3::Zero(), vbar = Vec3::Zero();
    for (Index i : pn) {
      c += nodes.x0.get(i);
      vbar += a.v(i);
    }
    c /= static_cast<Real>(pn.size());
    vbar /= static_cast<Real>(pn.size());
    Mat3 j = Mat3::Zero();
    Vec3 l = Vec3::Zero();
    Real size = 0.0, speed = 0.0, spin = 0.0;
    for (Index i : pn) {
      const Vec3 r = nodes.x0.get(i) - c;
      j += r.squaredNorm() * Mat3::Identity() - r * r.transpose();
      l += r.cross(a.v(i) - vbar);
      size = std::max(size, r.norm());
      speed = std::max(speed, a.v(i).norm());
      spin = std::max(spin, a.w(i).norm());
    }
    const Vec3 omega = solve_psd(j, l);
    const Real tol = 1e-9 * (speed + (spin + omega.norm()) * size) + std::numeric_limits<Real>::min();
    for (Index i : pn) {
      const Real dv = (a.v(i) - vbar - omega.cross(nodes.x0.get(i) - c)).norm();
      const Real dw = a.rotational(i) ? (a.w(i) - omega).norm() * size : 0.0;
      if (dv <= tol && dw <= tol) continue;
      const std::string card = a.assigned(i) ? a.card_of(i) : a.card_of(*given);
      throw InputError(card + ": the initial velocities of the nodes of rigid part " + std::to_string(pid) +
                       " are not one rigid-body motion (node " + std::to_string(nodes.ids[i]) +
                       (a.assigned(i) ? "" : ", which no card gives a velocity,") + " is off by " +
                       num(std::max(dv, dw / std::max(size, std::numeric_limits<Real>::min()))) +
                       "); a *MAT_RIGID part moves as one body: give all its nodes one translation and "
                       "rotation, e.g. *INITIAL_VELOCITY_GENERATION with STYP = 2");
    }
  }
}

}  // namespace

void apply_initial_velocities(const InitialVelocityInputs& in, NodalFields& nodes) {
  const model::Model& m = in.model;
  if (m.initial_velocities.empty() && m.initial_velocity_generations.empty() &&
      m.initial_velocity_nodes.empty())
    return;
  // Shell nodes carry rotations (the blocks set has_rotation only when they initialise).
  std::vector<std::uint8_t> rotational(nodes.size(), 0);
  for (const auto& e : m.shells)
    for (Id nid : e.n)
      if (const auto f = in.node_index.find(nid); f != in.node_index.end()) rotational[f->second] = 1;
  Assignment a(nodes, std::move(rotational));
  apply_set_cards(in, nodes, a);
  apply_generation_cards(in, nodes, a);
  apply_node_cards(in, a);
  check_rigid_parts(in, nodes, a);

  // Supports active at t = 0 win over the initial velocity.
  for (const auto& g : in.supports)
    for (const auto& s : g.supports) {
      if (!s.active(0.0)) continue;
      const int c = static_cast<int>(s.axis);
      for (Index i : s.nodes) (s.rotational ? a.w(i) : a.v(i))[c] = 0.0;
    }
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const Index i = static_cast<Index>(k);
    if (!a.assigned(i)) continue;
    nodes.v.set(i, a.v(i));
    if (a.rotational(i)) nodes.omega.set(i, a.w(i));
  }
}

}  // namespace slideline
