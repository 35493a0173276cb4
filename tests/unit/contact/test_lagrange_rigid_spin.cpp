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

Result solve_on_box(const Mat3& q) {
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
  groups.setup(top, ctx, {}, {}, true);
  ConstraintView view{nodes, mass, damping, {free_, free_, free_}, rigid, a, force, fc};
  const StepTimes times{0.0, dt, dt, dt, 10, dt};
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
  const Vec3 sn = (nodes.x.get(8) - c).cross(n);
  out.closed_form = g / (1.0 / m[8] + 1.0 / mt + sn.dot(inertia.inverse() * sn));
  // The solve's x^{n+1} of the box against the rigid-body update under the same forces.
  std::array<Vec3, 8> predicted{};
  for (Index i = 0; i < 8; ++i) predicted[static_cast<std::size_t>(i)] = predicted_position(view, times, groups.groups(), i);
  const Vec3 slave_next = predicted_position(view, times, groups.groups(), 8);
  Vec3 point_next = Vec3::Zero();
  for (int j = 0; j < 4; ++j) point_next += k.shape[static_cast<std::size_t>(j)] * predicted[static_cast<std::size_t>(j)];
  out.gap = n.dot(slave_next - point_next);
  RigidBody body(1, {0, 1, 2, 3, 4, 5, 6, 7}, {0, 0, 0, 0, 0, 0});
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

}  // namespace
}  // namespace slideline
