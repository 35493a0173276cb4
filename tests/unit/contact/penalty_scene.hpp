#pragma once
// A flat master plate of nx x nx unit segments (normal +z) and a slave grid of nx x nx nodes
// slightly pressed into it (offset so that no slave node sits over a master node), with masses,
// for the penalty-pass tests and the contact benchmark. No element blocks: the segment stiffness
// is given.
#include <memory>
#include <vector>

#include "plate_surface.hpp"
#include "slideline/contact/enforcement/penalty.hpp"
#include "slideline/contact/search/fcl_broad_phase.hpp"

namespace slideline::test {

struct PenaltyScene {
  NodalFields nodes;
  std::unique_ptr<PenaltyPass> pass;
  std::vector<Index> slaves;
  ExponentialCoulomb friction;  ///< the law passed to compute() (mu = 0: no tangential force)
};

/// nx x nx master segments of size 1 at z = 0, nx x nx slave nodes at z = -penetration, unit
/// masses, segment stiffness k, friction law `friction`. Initialised (initial penetrations off:
/// the slaves are placed after initialize()). broad_phase: the pass's broad phase (null: FCL; the
/// benchmark passes the brute-force one to compare).
inline std::unique_ptr<PenaltyScene> make_penalty_scene(Index nx, Real penetration, Real k,
                                                        const ExponentialCoulomb& friction,
                                                        std::unique_ptr<BroadPhase> broad_phase = nullptr,
                                                        const PenaltyPassOptions& o = {}) {
  auto s = std::make_unique<PenaltyScene>();
  Vec3Field x;
  Surface master = make_plate(x, nx, nx, 1.0, Vec3::Zero());
  for (Index j = 0; j < nx; ++j) {
    for (Index i = 0; i < nx; ++i) {
      s->slaves.push_back(static_cast<Index>(x.size()));
      x.x.push_back(0.37 + i);
      x.y.push_back(0.41 + j);
      x.z.push_back(1.0);  // above the plate at initialize(); lowered afterwards
    }
  }
  s->nodes.resize(x.size());
  s->nodes.x = x;
  s->nodes.x0 = x;
  s->nodes.mass.assign(x.size(), 1.0);
  s->friction = friction;
  s->pass = std::make_unique<PenaltyPass>(s->slaves, std::vector<Real>(s->slaves.size(), 0.0), std::move(master),
                                          broad_phase ? std::move(broad_phase) : std::make_unique<FclBroadPhase>(), o);
  s->pass->initialize(s->nodes, std::vector<Real>(static_cast<std::size_t>(nx * nx), k));
  for (Index n : s->slaves) s->nodes.x.z[n] = -penetration;
  return s;
}

/// Moves every slave node by d (length) and sets its velocity to d / dt (the master is at rest).
inline void move_slaves(PenaltyScene& s, const Vec3& d, Real dt) {
  for (Index n : s.slaves) {
    s.nodes.x.add(n, d);
    s.nodes.v.set(n, d / dt);
  }
}

}  // namespace slideline::test
