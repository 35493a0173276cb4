// One forward-increment solve against a free rigid box (RigidMasterGroups with rotation,
// enforcement/lagrange.hpp), checked in closed form and against the rigid-body update itself.
//
// A slave node of mass m_s rests (gap 0, at rest) on the box's top face at the point p, off the
// box's centre of mass c, and is pulled down by a force m_s g. The box (8 corner nodes of unequal
// mass, total M, inertia I about c) is free. With s = p - c and n the face normal, one step dt
// (dt_avg = dt_next = dt, no damping) moves the slave by dt^2 (-g + lambda / m_s) n and the
// contact point of the box by -dt^2 lambda (1 / M + (s x n) . I^-1 (s x n)) n, so the gap stays 0
// for
//   lambda = g / (1 / m_s + 1 / M + (s x n) . I^-1 (s x n)).
// The box's nodes as the solve predicts them at x^{n+1} must be where RigidBody (solver/
// rigid_body.hpp: the same forces, the simulation's velocity and position update, its exponential
// map) puts them, up to the curvature of one step's turn, |omega dt|^2 |s| (omega dt ~ 1e-6 here).
// Also in a rotated copy (every position and the load turned by Q): the same lambda.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "plate_surface.hpp"
#include "slideline/contact/enforcement/lagrange.hpp"
#include "slideline/contact/enforcement/rigid_master_groups.hpp"
#include "slideline/solver/rigid_body.hpp"

namespace slideline {
namespace {

struct Result {
  Real lambda = 0.0, closed_form = 0.0, worst_node = 0.0, increment = 0.0, gap = 0.0;
};

/// held: the rotations the box's body holds (CON2 style, global axes; the rigid-body update holds
/// them too); drives: prescribed motions of its part 1 (the solve only), at time t.
Result solve_on_box(const Mat3& q, std::array<int, 3> held = {0, 0, 0}, std::vector<RigidMasterDrive> drives = {},
                    Real t = 0.0) {
  // Box [0, 2] x [0, 0.5] x [0, 1]; nodes 0-3 its top face (y = 0.5), 4-7 the bottom; node 8 the
  // slave on the top face at (0.4, 0.5, 0.3).
  const std::array<Vec3, 9> x0{Vec3(0, 0.5, 0), Vec3(0, 0.5, 1), Vec3(2, 0.5, 1), Vec3(2, 0.5, 0),
                               Vec3(0, 0, 0),   Vec3(0, 0, 1),   Vec3(2, 0, 1),   Vec3(2, 0, 0),
                               Vec3(0.4, 0.5, 0.3)};
  const std::array<Real, 9> m{0.1, 0.2, 0.15, 0.12, 0.1, 0.3, 0.05, 0.2, 0.01};
  const Real g = 10.0, dt = 1e-3;
  const Vec3 n = q * Vec3::UnitY();
  NodalFields nodes;
  nodes.resize(9);
  std::vector<Real> mass(m.begin(), m.end()), damping(9, 0.0);
  for (Index i = 0; i < 9; ++i) {
    nodes.x.set(i, q * x0[static_cast<std::size_t>(i)]);
    nodes.x0.set(i, nodes.x.get(i));
    nodes.mass[static_cast<std::size_t>(i)] = m[static_cast<std::size_t>(i)];
  }
  std::vector<std::uint8_t> free_(9, 0), rigid(9, 1);
  rigid[8] = 0;
  Vec3Field a, force, fc;
  a.resize(9);
  force.resize(9);
  fc.resize(9);
  a.set(8, -g * n);
  force.set(8, -m[8] * g * n);
  Surface top;
  top.conn = {0, 1, 2, 3};  // counter-clockwise seen from +y
  test::finish_surface(top);
  MeshSets sets;
  sets.part_nodes[1] = {0, 1, 2, 3, 4, 5, 6, 7};
  const std::vector<std::unique_ptr<ElementBlock>> blocks;
  const ContactContext ctx{nodes, blocks, &sets, rigid};
  RigidMasterGroups groups;
  const std::vector<std::pair<Id, std::array<int, 3>>> held_rotations{{1, held}};
  groups.setup(top, ctx, {}, held_rotations, true, drives);
  ConstraintView view{nodes, mass, damping, {free_, free_, free_}, rigid, a, force, fc};
  const StepTimes times{t, dt, dt, dt, 10, dt};
  groups.update(view, times);
  LagrangeConstraint k;
  k.slave = 8;
  k.master = {0, 1, 2, 3};
  const Real u = 2 * 0.3 - 1, v = 2 * (0.4 / 2) - 1;  // (z, x) of the point in the face's corners' order
  k.shape = {0.25 * (1 - u) * (1 - v), 0.25 * (1 + u) * (1 - v), 0.25 * (1 + u) * (1 + v), 0.25 * (1 - u) * (1 + v)};
  k.normal = n;
  std::vector<LagrangeConstraint> cs{k};
  LagrangeSolveOptions opt;
  opt.tolerance = 1e-16;
  const LagrangeSolveResult r = solve_forward_increment(cs, view, times, opt, groups.groups());
  EXPECT_TRUE(r.converged);
  Result out;
  out.lambda = cs[0].lambda;
  // Closed form, from the box's own mass and inertia.
  Real mt = 0.0;
  Vec3 c = Vec3::Zero();
  for (int i = 0; i < 8; ++i) {
    mt += m[static_cast<std::size_t>(i)];
    c += m[static_cast<std::size_t>(i)] * nodes.x.get(i);
  }
  c /= mt;
  Mat3 inertia = Mat3::Zero();
  for (int i = 0; i < 8; ++i) {
    const Vec3 s = nodes.x.get(i) - c;
    inertia += m[static_cast<std::size_t>(i)] * (s.squaredNorm() * Mat3::Identity() - s * s.transpose());
  }
  // Held or driven rotations drop out: I^-1 over the free axes only (S (S I S + 1 - S)^-1 S).
  std::array<bool, 3> fixed{held[0] != 0, held[1] != 0, held[2] != 0};
  for (const RigidMasterDrive& d : drives)
    if (d.dof >= 3 && d.active(t)) fixed[static_cast<std::size_t>(d.dof - 3)] = true;
  Mat3 reduced = inertia;
  for (int k = 0; k < 3; ++k)
    if (fixed[static_cast<std::size_t>(k)]) {
      reduced.row(k).setZero();
      reduced.col(k).setZero();
      reduced(k, k) = 1.0;
    }
  Vec3 sn = (nodes.x.get(8) - c).cross(n);
  for (int k = 0; k < 3; ++k)
    if (fixed[static_cast<std::size_t>(k)]) sn[k] = 0.0;
  out.closed_form = g / (1.0 / m[8] + 1.0 / mt + sn.dot(reduced.inverse() * sn));
  // The solve's x^{n+1} of the box against the rigid-body update under the same forces.
  std::array<Vec3, 8> predicted{};
  for (Index i = 0; i < 8; ++i) predicted[static_cast<std::size_t>(i)] = predicted_position(view, times, groups.groups(), i);
  const Vec3 slave_next = predicted_position(view, times, groups.groups(), 8);
  Vec3 point_next = Vec3::Zero();
  for (int j = 0; j < 4; ++j) point_next += k.shape[static_cast<std::size_t>(j)] * predicted[static_cast<std::size_t>(j)];
  out.gap = n.dot(slave_next - point_next);
  RigidBody body(1, {0, 1, 2, 3, 4, 5, 6, 7}, {0, 0, 0, held[0], held[1], held[2]});
  body.initialize(nodes, mass);
  ConstraintLoads loads{mass, nodes, &fc, nullptr};
  loads.dt_avg = dt;
  loads.dt_next = dt;
  Vec3Field no_moment;
  no_moment.resize(9);
  loads.total_moment = &no_moment;
  body.constrain_accelerations(loads, nodes, 0.0);
  for (Index i = 0; i < 8; ++i) {
    nodes.v.set(i, nodes.v.get(i) + dt * nodes.a.get(i));
    nodes.x.set(i, nodes.x.get(i) + dt * nodes.v.get(i));
  }
  body.after_positions(mass, nodes, dt);
  for (Index i = 0; i < 8; ++i) {
    const Vec3 moved = nodes.x.get(i) - q * x0[static_cast<std::size_t>(i)];
    out.increment = std::max(out.increment, moved.norm());
    out.worst_node = std::max(out.worst_node, (nodes.x.get(i) - predicted[static_cast<std::size_t>(i)]).norm());
  }
  return out;
}

TEST(LagrangeRigidSpin, OneStepOnAFreeBoxMatchesTheClosedFormAndTheRigidBodyUpdate) {
  const Result a = solve_on_box(Mat3::Identity());
  const Mat3 q = Eigen::AngleAxis<Real>(1.1, Vec3(0.3, -1.0, 2.0).normalized()).toRotationMatrix();
  const Result b = solve_on_box(q);
  for (const Result* r : {&a, &b})
    std::printf("free box: lambda %.15f, closed form %.15f (rel %.2e); box nodes: solve vs rigid-body update %.3e "
                "(of an increment %.3e), gap at x^{n+1} %.3e\n",
                r->lambda, r->closed_form, std::abs(r->lambda / r->closed_form - 1.0), r->worst_node, r->increment,
                r->gap);
  // Round-off: lambda comes from a gap of positions of size ~1 closed by increments of
  // g dt^2 = 1e-5, so its relative error is ~ eps / 1e-5 ~ 2e-11.
  for (const Result* r : {&a, &b}) {
    EXPECT_NEAR(r->lambda, r->closed_form, 1e-10 * r->closed_form);
    EXPECT_LT(std::abs(r->gap), 1e-15);
    // One step's turn is ~1e-6 rad: its curvature moves a node by ~1e-12 |s| against ~1e-6 |s|.
    EXPECT_LT(r->worst_node, 1e-6 * r->increment);
  }
  EXPECT_NEAR(b.lambda, a.lambda, 1e-10 * a.lambda);
}

TEST(LagrangeRigidSpin, HeldAndDrivenRotationsDropOutOfTheSolve) {
  // Held about z (CON2 = 3): the box turns about x and y only, in the solve as in its update.
  const Result z = solve_on_box(Mat3::Identity(), {0, 0, 1});
  // Held about all three (CON2 = 7): lambda = g / (1/m_s + 1/M), the translation-only figure.
  const Result all = solve_on_box(Mat3::Identity(), {1, 1, 1});
  // Rotations about x, y, z driven (*BOUNDARY_PRESCRIBED_MOTION_RIGID DOF 5-7) over [0, 1]: held
  // while the drives act (t = 0.5), free after their death (t = 2).
  std::vector<RigidMasterDrive> drives;
  for (int d = 3; d < 6; ++d) drives.push_back({1, d, 0.0, 1.0});
  const Result driven = solve_on_box(Mat3::Identity(), {0, 0, 0}, drives, 0.5);
  const Result after = solve_on_box(Mat3::Identity(), {0, 0, 0}, drives, 2.0);
  const Result free = solve_on_box(Mat3::Identity());
  std::printf("held z: lambda %.12f (closed form %.12f), box nodes vs update %.3e; held xyz %.12f (%.12f); "
              "driven %.12f; after the drives %.12f (free %.12f)\n",
              z.lambda, z.closed_form, z.worst_node, all.lambda, all.closed_form, driven.lambda, after.lambda,
              free.lambda);
  for (const Result* r : {&z, &all, &driven, &after}) EXPECT_NEAR(r->lambda, r->closed_form, 1e-10 * r->closed_form);
  EXPECT_LT(z.worst_node, 1e-6 * z.increment);
  EXPECT_LT(all.worst_node, 1e-6 * all.increment);
  EXPECT_GT(all.lambda, z.lambda);  // a stiffer body: more of the slave's weight on it
  EXPECT_GT(z.lambda, free.lambda);
  EXPECT_NEAR(driven.lambda, all.lambda, 1e-12 * all.lambda);
  EXPECT_NEAR(after.lambda, free.lambda, 1e-12 * free.lambda);
}

}  // namespace
}  // namespace slideline
