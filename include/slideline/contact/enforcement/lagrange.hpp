#pragma once
/// Forward-increment Lagrange multipliers (Carpenter, Taylor and Katona, IJNME 1991; Zywicz and
/// Puso, IJNME 1999): the multipliers at t^n make the constraints hold at the PREDICTED positions
/// x^{n+1}. The prediction is the simulation's damped central-difference update
/// (contact_algorithm.hpp, ConstraintView):
///   dx_i = x_i^{n+1} - x_i^n = dt_next ((1 - h_i) v_i^{n-1/2} + dt_avg a_i) / (1 + h_i),
///   h_i = damping_i dt_avg / 2,
/// so a force df on a movable component changes dx by c_i df with the compliance
///   c_i = dt_next dt_avg / ((1 + h_i) m_i)   (length / force; 0 for fixed or rigid components).
///
/// One constraint joins a slave node s to the point sum_a N_a x_a of a master segment, with unit
/// normal n (towards the slave) and target gap g0 (offsets: shell half thicknesses, nodal radius):
///   normal:      g = n . (x_s - sum N_a x_a)^{n+1} - g0 >= 0, lambda >= 0, lambda g = 0
///                (bilateral: g = 0, lambda free: Type 1 sliding only);
///   tangential:  stick  P_t (dx_s - sum N_a dx_a) = 0 while |tau| <= mu lambda, else slip with
///                |tau| = mu lambda (Coulomb; mu set per constraint by the caller).
/// The force on the slave is lambda n + tau, on master node a -N_a (lambda n + tau): the slave and
/// master totals are equal and opposite to round-off.
/// Mortar transfer (LagrangeConstraint::mortar_count > 0): the master point is sum_a w_a x_a over
/// the nodes of several master segments, w_a the slave node's mortar weights
/// (enforcement/mortar_weights.hpp), in place of one segment's N_a; everything above holds with
/// w_a for N_a, so a uniform pressure reaches the master as consistent nodal forces.
///
/// The coupled system (the constraints share master nodes, and in single-surface contact a node
/// may be slave and master at once) is solved by projected Gauss-Seidel over the constraints in
/// their given order: exact diagonal blocks (1 x 1 normal, 2 x 2 tangential from the component
/// compliances), projection on lambda >= 0 and on the friction disc after each block. The sweep
/// order is fixed, so the result does not depend on the thread count. Warm start: the caller may
/// set lambda and tau (e.g. the previous step's); they are applied before the first sweep.
/// Convergence: a sweep in which no block moves a predicted position by more than `tolerance`
/// (length). No allocation.
///
/// Rigid bodies: ConstraintView makes rigid nodes immovable, and the simulation moves the rigid
/// bodies with the contact load only after the solve. Against a light rigid master that lag makes
/// the contact chatter (the master moves away, the slave falls, the master is hit again: forces
/// alternating between 0 and twice the load). With `RigidGroups` the solve moves each rigid body
/// as ONE translating mass (its total mass; components where any of its nodes is fixed stay
/// immovable): a force df on a node of group g moves every node of g by c_g df,
/// c_g = dt_next dt_avg / ((1 + h) M_g). With `RigidGroups::spin` the group also turns about its
/// centre of mass c_g: the forces add the torque T_g = sum (x_i - c_g) x df_i and every node of g
/// moves by (J_g T_g) x (x_i - c_g) more, J_g = dt_next dt_avg / (1 + h) I_g^-1 (I_g the body's
/// inertia tensor about c_g; rows and columns of held rotations zero): the increment the rigid-body
/// update gives a node under those forces, to first order in the turn of one step. Without it the
/// turn is left to the update after the solve, and the next cycle corrects the gap it opened.
#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <vector>

#include "slideline/contact/contact_algorithm.hpp"
#include "slideline/core/types.hpp"

namespace slideline {

/// One slave-node / master-point constraint and its multipliers.
struct LagrangeConstraint {
  Index slave = -1;
  std::array<Index, 4> master{};   ///< segment nodes (a triangle repeats one with weight 0)
  std::array<Real, 4> shape{};     ///< master shape functions at the contact point (sum 1)
  Vec3 normal = Vec3::UnitY();     ///< unit normal towards the slave
  Real target = 0.0;               ///< gap the constraint keeps (length)
  Real mu = 0.0;                   ///< Coulomb coefficient this step (0: frictionless)
  bool bilateral = false;          ///< tension and compression (Type 1)
  Real lambda = 0.0;               ///< normal force on the slave (force; > 0 compression)
  Vec3 tau = Vec3::Zero();         ///< tangential (friction) force on the slave (force)
  Vec3 slip = Vec3::Zero();        ///< after the solve: predicted tangential relative increment (length)
  /// Mortar transfer (see the file comment): when mortar_count > 0 the master nodes and weights
  /// are these (storage the interface owns and keeps unchanged during the solve; at most
  /// max_masters), and master / shape are not used.
  static constexpr int max_masters = 48;
  const Index* mortar_node = nullptr;
  const Real* mortar_weight = nullptr;
  int mortar_count = 0;
};

/// Calls f(a, node, weight) for each master node of `k` with a nonzero weight, a its place in the
/// constraint's list (a < 4 for a segment's nodes).
template <class F>
inline void for_each_master(const LagrangeConstraint& k, F&& f) {
  if (k.mortar_count > 0) {
    for (int a = 0; a < k.mortar_count; ++a)
      if (k.mortar_weight[a] != 0.0) f(a, k.mortar_node[a], k.mortar_weight[a]);
    return;
  }
  for (int a = 0; a < 4; ++a)
    if (k.shape[static_cast<std::size_t>(a)] != 0.0)
      f(a, k.master[static_cast<std::size_t>(a)], k.shape[static_cast<std::size_t>(a)]);
}

struct LagrangeSolveOptions {
  Real tolerance = 1e-11;  ///< largest position correction in the last sweep (length)
  int max_sweeps = 300;
};

struct LagrangeSolveResult {
  int sweeps = 0;
  Real correction = 0.0;  ///< largest position correction of the last sweep (length)
  bool converged = true;
};

/// Scratch of the cached solve (see solve_forward_increment): the caller sizes `dx` to the node
/// count and reserves `rows` for its largest constraint count once, so the solve never allocates.
struct LagrangeWorkspace {
  struct Row {
    Vec3 c = Vec3::Zero();         ///< pair compliance (per component)
    Real wn = 0.0;                 ///< n . (c n)
    Real g0 = 0.0;                 ///< n . (x_s - sum N_a x_a)^n - target
    Vec3 t1 = Vec3::Zero(), t2 = Vec3::Zero();
    Real a11 = 0.0, a12 = 0.0, a22 = 0.0, det = 0.0;
    Vec3 cs = Vec3::Zero();        ///< the slave node's compliance
    std::array<Vec3, 4> cm{};      ///< the master nodes' compliances (a segment's; mortar: not cached)
    Vec3 applied = Vec3::Zero();   ///< force already in the view (the warm start)
  };
  std::vector<Vec3> dx;  ///< per node (global index): predicted increment x^{n+1} - x^n during the solve
  std::vector<Row> rows;
};

/// Rigid bodies taking part in a solve as translating (and, with `spin`, turning) masses (see the
/// file comment).
struct RigidGroups {
  std::span<const Index> group;    ///< per node (global index): group, or -1
  std::span<const Vec3> compliance;  ///< per group: c_g per component (length / force; 0 = immovable)
  std::span<Vec3> force;             ///< per group: force accumulated by the solve (scratch)
  /// Rotation (all empty: the groups only translate). Per group: the centre of mass at x^n
  /// (length), the rotational compliance J_g (1 / (force length)), the torque about the centre
  /// accumulated by the solve (force length; scratch).
  std::span<const Vec3> center = {};
  std::span<const Mat3> spin = {};
  std::span<Vec3> torque = {};
};

namespace detail {

/// The compliance and prediction of the nodes as ConstraintView describes them.
struct Predictor {
  ConstraintView& view;
  Real dt_next, dt_avg;
  const RigidGroups* rigid = nullptr;
  Vec3* master_added = nullptr;  ///< when set: sum of the forces added to master nodes

  Index group(Index i) const {
    return rigid && !rigid->group.empty() ? rigid->group[static_cast<std::size_t>(i)] : Index(-1);
  }
  /// True when the rigid groups turn in the solve (RigidGroups::spin).
  bool spinning() const { return rigid && !rigid->group.empty() && !rigid->spin.empty(); }
  /// Arm of node i about the centre of its group g (length).
  Vec3 arm(Index i, Index g) const {
    return view.nodes.x.get(i) - rigid->center[static_cast<std::size_t>(g)];
  }

  Real h(Index i) const { return 0.5 * view.damping[static_cast<std::size_t>(i)] * dt_avg; }
  bool movable(Index i, int c) const {
    return !view.rigid[static_cast<std::size_t>(i)] && !view.fixed[c][static_cast<std::size_t>(i)] &&
           view.mass[static_cast<std::size_t>(i)] > 0.0;
  }
  Vec3 compliance(Index i) const {
    const Real c = dt_next * dt_avg / ((1.0 + h(i)) * view.mass[static_cast<std::size_t>(i)]);
    return {movable(i, 0) ? c : 0.0, movable(i, 1) ? c : 0.0, movable(i, 2) ? c : 0.0};
  }
  /// x^{n+1} - x^n (length).
  Vec3 increment(Index i) const {
    const Real hi = h(i);
    Vec3 d = dt_next * ((1.0 - hi) * view.nodes.v.get(i) + dt_avg * view.a.get(i)) / (1.0 + hi);
    if (const Index g = group(i); g >= 0) {
      const auto gi = static_cast<std::size_t>(g);
      d += rigid->compliance[gi].cwiseProduct(rigid->force[gi]);
      if (!rigid->spin.empty()) d += (rigid->spin[gi] * rigid->torque[gi]).cross(arm(i, g));
    }
    return d;
  }
  void apply(Index i, const Vec3& df) const {
    view.f_contact.add(i, df);
    view.force.add(i, df);
    if (const Index g = group(i); g >= 0) {
      rigid->force[static_cast<std::size_t>(g)] += df;
      if (!rigid->spin.empty()) rigid->torque[static_cast<std::size_t>(g)] += arm(i, g).cross(df);
    }
    const Real m = view.mass[static_cast<std::size_t>(i)];
    for (int c = 0; c < 3; ++c)
      if (movable(i, c)) view.a[c][static_cast<std::size_t>(i)] += df[c] / m;
  }
  void apply(const LagrangeConstraint& k, const Vec3& df) const {
    apply(k.slave, df);
    for_each_master(k, [&](int, Index m, Real w) {
      const Vec3 fm = -w * df;
      apply(m, fm);
      if (master_added) *master_added += fm;
    });
  }
  /// Relative predicted increment of the slave against its master point (length).
  Vec3 relative_increment(const LagrangeConstraint& k) const {
    Vec3 r = increment(k.slave);
    for_each_master(k, [&](int, Index m, Real w) { r -= w * increment(m); });
    return r;
  }
  Vec3 relative_position(const LagrangeConstraint& k) const {
    Vec3 r = view.nodes.x.get(k.slave);
    for_each_master(k, [&](int, Index m, Real w) { r -= w * view.nodes.x.get(m); });
    return r;
  }
  /// Diagonal of the constraint's compliance (per component, length / force).
  Vec3 pair_compliance(const LagrangeConstraint& k) const {
    Vec3 c = compliance(k.slave);
    for_each_master(k, [&](int, Index m, Real w) { c += w * w * compliance(m); });
    if (rigid == nullptr || rigid->group.empty()) return c;
    // A rigid group moves as one: its share is (sum of the weights on its nodes)^2 c_g, the
    // slave counting +1 and the masters -N_a.
    std::array<Index, 1 + LagrangeConstraint::max_masters> gs{};
    std::array<Real, 1 + LagrangeConstraint::max_masters> ws{};
    int ng = 0;
    const auto add = [&](Index node, Real w) {
      const Index g = group(node);
      if (g < 0) return;
      for (int j = 0; j < ng; ++j)
        if (gs[j] == g) {
          ws[j] += w;
          return;
        }
      gs[ng] = g;
      ws[ng++] = w;
    };
    add(k.slave, 1.0);
    for_each_master(k, [&](int, Index m, Real w) { add(m, -w); });
    for (int j = 0; j < ng; ++j) c += ws[j] * ws[j] * rigid->compliance[static_cast<std::size_t>(gs[j])];
    return c;
  }
  /// The rotational part of the constraint's compliance (spinning() only; length / force): a
  /// force df on the constraint (+df on the slave, -N_a df on the masters) turns group g by
  /// J_g (rho_g x df), rho_g = sum of the weighted arms of the constraint's nodes in g, which moves
  /// the relative increment by (J_g (rho_g x df)) x rho_g = [rho_g]x^T J_g [rho_g]x df.
  Mat3 pair_rotation(const LagrangeConstraint& k) const {
    std::array<Index, 1 + LagrangeConstraint::max_masters> gs{};
    std::array<Vec3, 1 + LagrangeConstraint::max_masters> rho{};
    int ng = 0;
    const auto add = [&](Index node, Real w) {
      const Index g = group(node);
      if (g < 0) return;
      for (int j = 0; j < ng; ++j)
        if (gs[j] == g) {
          rho[j] += w * arm(node, g);
          return;
        }
      gs[ng] = g;
      rho[ng++] = w * arm(node, g);
    };
    add(k.slave, 1.0);
    for_each_master(k, [&](int, Index m, Real w) { add(m, -w); });
    Mat3 c = Mat3::Zero();
    for (int j = 0; j < ng; ++j) {
      Mat3 x;  // [rho]x: x v = rho x v
      x << 0.0, -rho[j][2], rho[j][1], rho[j][2], 0.0, -rho[j][0], -rho[j][1], rho[j][0], 0.0;
      c += x.transpose() * rigid->spin[static_cast<std::size_t>(gs[j])] * x;
    }
    return c;
  }
};

inline void tangent_basis(const Vec3& n, Vec3& t1, Vec3& t2) {
  const Vec3 e = std::abs(n[0]) < 0.6 ? Vec3::UnitX() : (std::abs(n[1]) < 0.6 ? Vec3::UnitY() : Vec3::UnitZ());
  t1 = (e - e.dot(n) * n).normalized();
  t2 = n.cross(t1);
}

/// Records sweep `sweep` (from 0) of a Gauss-Seidel solve with its largest correction `worst`
/// (length); true when that is within `tolerance` (converged: stop sweeping).
inline bool end_sweep(LagrangeSolveResult& result, int sweep, Real worst, Real tolerance) {
  result.sweeps = sweep + 1;
  result.correction = worst;
  result.converged = worst <= tolerance;
  return result.converged;
}

}  // namespace detail

/// x^{n+1} of node i as the last solve left it (length): the damped update of ConstraintView
/// plus, for a node of a rigid group, the group's translation (`rigid` as that solve had it).
inline Vec3 predicted_position(ConstraintView view, const StepTimes& times, const RigidGroups* rigid, Index i) {
  const detail::Predictor p{view, times.dt_next, times.dt_avg, rigid};
  return view.nodes.x.get(i) + p.increment(i);
}

/// Takes the forces lambda n + tau of `cs` out of `view` again (before the geometry of the
/// constraints is changed and they are solved once more).
/// `master_added`, when given, accumulates the forces added to (here: taken from) master nodes.
inline void withdraw_constraint_forces(std::span<const LagrangeConstraint> cs, ConstraintView view,
                                       const StepTimes& times, const RigidGroups* rigid = nullptr,
                                       Vec3* master_added = nullptr) {
  const detail::Predictor p{view, times.dt_next, times.dt_avg, rigid, master_added};
  for (const auto& k : cs)
    if (k.lambda != 0.0 || k.tau.squaredNorm() > 0.0) p.apply(k, -(k.lambda * k.normal + k.tau));
}

namespace detail {

/// The same projected Gauss-Seidel as solve_forward_increment's reference loop, on cached data:
/// per constraint the compliances, the tangent basis with its 2 x 2 block and the gap at x^n
/// (constant during a solve), per node the predicted increment dx (a force df on a node changes
/// it by compliance . df, exactly what the reference loop gets by updating the acceleration).
/// The view is written once at the end (final minus warm-start force per constraint), so the
/// result differs from the reference only by round-off in the order of the sums.
inline LagrangeSolveResult solve_cached(std::span<LagrangeConstraint> cs, const Predictor& p,
                                        const LagrangeSolveOptions& opt, LagrangeWorkspace& ws) {
  LagrangeSolveResult result;
  ws.rows.resize(cs.size());  // within the reserved capacity: no allocation
  auto& dx = ws.dx;
  for (std::size_t j = 0; j < cs.size(); ++j) {
    const LagrangeConstraint& k = cs[j];
    auto& w = ws.rows[j];
    w.c = p.pair_compliance(k);
    const Vec3& n = k.normal;
    w.wn = n[0] * n[0] * w.c[0] + n[1] * n[1] * w.c[1] + n[2] * n[2] * w.c[2];
    w.g0 = n.dot(p.relative_position(k)) - k.target;
    tangent_basis(n, w.t1, w.t2);
    w.a11 = w.t1.dot(w.c.cwiseProduct(w.t1));
    w.a12 = w.t1.dot(w.c.cwiseProduct(w.t2));
    w.a22 = w.t2.dot(w.c.cwiseProduct(w.t2));
    w.det = w.a11 * w.a22 - w.a12 * w.a12;
    w.cs = p.compliance(k.slave);
    dx[static_cast<std::size_t>(k.slave)] = p.increment(k.slave);
    if (k.mortar_count == 0)
      for (int a = 0; a < 4; ++a) w.cm[static_cast<std::size_t>(a)] = p.compliance(k.master[static_cast<std::size_t>(a)]);
    for_each_master(k, [&](int, Index m, Real) { dx[static_cast<std::size_t>(m)] = p.increment(m); });
    w.applied = k.lambda * k.normal + k.tau;
  }
  const auto rel = [&](const LagrangeConstraint& k) {
    Vec3 r = dx[static_cast<std::size_t>(k.slave)];
    for_each_master(k, [&](int, Index m, Real wt) { r -= wt * dx[static_cast<std::size_t>(m)]; });
    return r;
  };
  const auto move = [&](const LagrangeConstraint& k, const LagrangeWorkspace::Row& w, const Vec3& df) {
    dx[static_cast<std::size_t>(k.slave)] += w.cs.cwiseProduct(df);
    for_each_master(k, [&](int a, Index m, Real wt) {
      const Vec3 cm = k.mortar_count > 0 ? p.compliance(m) : w.cm[static_cast<std::size_t>(a)];
      dx[static_cast<std::size_t>(m)] -= wt * cm.cwiseProduct(df);
    });
  };
  for (int sweep = 0; sweep < opt.max_sweeps; ++sweep) {
    Real worst = 0.0;
    for (std::size_t j = 0; j < cs.size(); ++j) {
      LagrangeConstraint& k = cs[j];
      const auto& w = ws.rows[j];
      if (!(w.wn > 0.0)) continue;  // both sides immovable
      const Vec3& n = k.normal;
      Vec3 r = rel(k);
      const Real g = w.g0 + n.dot(r);
      Real lambda = k.lambda - g / w.wn;
      if (!k.bilateral) lambda = std::max(lambda, Real(0));
      const Real dl = lambda - k.lambda;
      if (dl != 0.0) {
        move(k, w, dl * n);
        r += dl * w.c.cwiseProduct(n);
        k.lambda = lambda;
        worst = std::max(worst, std::abs(dl) * w.wn);
      }
      if (k.mu <= 0.0 || !(w.det > 0.0)) continue;
      const Real u1 = w.t1.dot(r), u2 = w.t2.dot(r);
      const Real d1 = -(w.a22 * u1 - w.a12 * u2) / w.det, d2 = -(w.a11 * u2 - w.a12 * u1) / w.det;
      Vec3 trial = k.tau - k.tau.dot(n) * n + d1 * w.t1 + d2 * w.t2;
      const Real limit = k.mu * std::max(k.lambda, Real(0));
      const Real tn = trial.norm();
      if (tn > limit) trial *= (tn > 0.0 ? limit / tn : 0.0);
      const Vec3 dt = trial - k.tau;
      if (dt.squaredNorm() > 0.0) {
        move(k, w, dt);
        k.tau = trial;
        worst = std::max(worst, w.c.cwiseProduct(dt).norm());
      }
    }
    if (detail::end_sweep(result, sweep, worst, opt.tolerance)) break;
  }
  for (std::size_t j = 0; j < cs.size(); ++j) {
    const LagrangeConstraint& k = cs[j];
    const Vec3 df = k.lambda * k.normal + k.tau - ws.rows[j].applied;
    if (df.squaredNorm() > 0.0) p.apply(k, df);
  }
  for (auto& k : cs) {
    const Vec3 r = p.relative_increment(k);
    k.slip = r - r.dot(k.normal) * k.normal;
  }
  return result;
}

}  // namespace detail

/// Solves the constraints `cs` at the step `times` into `view` (accelerations, total and contact
/// forces of the nodes involved). On entry lambda and tau hold the warm start (0 for none); on
/// exit the converged multipliers and `slip`. Returns the sweep count and the last correction.
/// With a workspace (and no rigid groups) the sweeps run on cached data (detail::solve_cached):
/// the same iteration, several times cheaper per sweep. `master_added`, when given, accumulates
/// every force added to a master node (the interface's master_force: what the masters received).
inline LagrangeSolveResult solve_forward_increment(std::span<LagrangeConstraint> cs, ConstraintView view,
                                                   const StepTimes& times, const LagrangeSolveOptions& opt = {},
                                                   const RigidGroups* rigid = nullptr,
                                                   LagrangeWorkspace* workspace = nullptr,
                                                   Vec3* master_added = nullptr) {
  if (rigid) {
    for (Vec3& f : rigid->force) f.setZero();
    for (Vec3& t : rigid->torque) t.setZero();
  }
  const detail::Predictor p{view, times.dt_next, times.dt_avg, rigid, master_added};
  const bool spin = p.spinning();
  LagrangeSolveResult result;
  for (auto& k : cs) {
    if (!k.bilateral) k.lambda = std::max(k.lambda, Real(0));
    if (k.mu <= 0.0) k.tau.setZero();
    if (k.lambda != 0.0 || k.tau.squaredNorm() > 0.0) p.apply(k, k.lambda * k.normal + k.tau);
  }
  if (cs.empty()) return result;
  if (workspace && (rigid == nullptr || rigid->group.empty()) && workspace->rows.capacity() >= cs.size() &&
      workspace->dx.size() >= view.nodes.size())
    return detail::solve_cached(cs, p, opt, *workspace);
  for (int sweep = 0; sweep < opt.max_sweeps; ++sweep) {
    Real worst = 0.0;
    for (auto& k : cs) {
      const Vec3 c = p.pair_compliance(k);
      const Vec3& n = k.normal;
      // A turning rigid group couples the components (cr, RigidGroups::spin); the translation
      // and node parts stay the diagonal c, so without spin the arithmetic is the same as ever.
      const Mat3 cr = spin ? p.pair_rotation(k) : Mat3::Zero();
      Real wn = n[0] * n[0] * c[0] + n[1] * n[1] * c[1] + n[2] * n[2] * c[2];
      if (spin) wn += n.dot(cr * n);
      if (!(wn > 0.0)) continue;  // both sides immovable
      Vec3 r = p.relative_increment(k);
      const Real g = n.dot(p.relative_position(k) + r) - k.target;
      Real lambda = k.lambda - g / wn;
      if (!k.bilateral) lambda = std::max(lambda, Real(0));
      const Real dl = lambda - k.lambda;
      if (dl != 0.0) {
        p.apply(k, dl * n);
        r += dl * c.cwiseProduct(n);
        if (spin) r += dl * (cr * n);
        k.lambda = lambda;
        worst = std::max(worst, std::abs(dl) * wn);
      }
      if (k.mu <= 0.0) continue;
      // Stick: the 2 x 2 block of the compliance in the tangent plane, solved exactly.
      Vec3 t1, t2;
      detail::tangent_basis(n, t1, t2);
      Real a11 = t1.dot(c.cwiseProduct(t1)), a12 = t1.dot(c.cwiseProduct(t2)), a22 = t2.dot(c.cwiseProduct(t2));
      if (spin) {
        a11 += t1.dot(cr * t1);
        a12 += t1.dot(cr * t2);
        a22 += t2.dot(cr * t2);
      }
      const Real det = a11 * a22 - a12 * a12;
      if (!(det > 0.0)) continue;
      const Real u1 = t1.dot(r), u2 = t2.dot(r);
      const Real d1 = -(a22 * u1 - a12 * u2) / det, d2 = -(a11 * u2 - a12 * u1) / det;
      Vec3 trial = k.tau - k.tau.dot(n) * n + d1 * t1 + d2 * t2;
      const Real limit = k.mu * std::max(k.lambda, Real(0));
      const Real tn = trial.norm();
      if (tn > limit) trial *= (tn > 0.0 ? limit / tn : 0.0);
      const Vec3 dt = trial - k.tau;
      if (dt.squaredNorm() > 0.0) {
        p.apply(k, dt);
        k.tau = trial;
        worst = std::max(worst, spin ? Vec3(c.cwiseProduct(dt) + cr * dt).norm() : c.cwiseProduct(dt).norm());
      }
    }
    if (detail::end_sweep(result, sweep, worst, opt.tolerance)) break;
  }
  for (auto& k : cs) {
    const Vec3 r = p.relative_increment(k);
    k.slip = r - r.dot(k.normal) * k.normal;
  }
  return result;
}

}  // namespace slideline
