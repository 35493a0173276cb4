// Hertz contact (issue 18): a rigid sphere (R = 4) driven quasi-statically into an elastic block,
// force against F = 4/3 E* R^1/2 d^3/2, Type 3 penalty (default stiffness and SFS = 10) and
// Lagrange, each also in a copy rotated about an oblique axis. Model and closed form in
// hertz_model.hpp; figures and their explanation in docs/verification.md, "Hertz".
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "hertz_model.hpp"

namespace slideline {
namespace {

using hertz_test::HertzOptions;
using model::ContactType;
using model::Enforcement;

/// One sample at an indentation d.
struct HertzSample {
  Real d = 0.0;          ///< indenter travel since first touch (length)
  Real force = 0.0;      ///< contact force on the block along the drive (force)
  Real d_rel = 0.0;      ///< d less the block's displacement on the axis at the probe depth
  Real ratio = 0.0;      ///< force / Hertz force at d_rel (the measure the test asserts)
  Real ratio_far = 0.0;  ///< force / Hertz force at d (a finite block is stiffer: not asserted)
  Real sink = 0.0;       ///< (d - displacement of the block's top on the axis) / d
  Real ratio_sunk = 0.0; ///< force / Hertz force at d_rel less the sinking on the axis
};

/// The contact force on the block (part 1): Type 12's transmitted force on its first part, else
/// the slave side's total (the block is the slave).
Vec3 force_on_block(const ContactAlgorithm& c) {
  std::vector<std::string> names;
  c.append_output_names(names);
  const auto it = std::find(names.begin(), names.end(), "transmitted_force");
  if (it == names.end()) return c.slave_force();
  std::vector<Real> out(3 * names.size(), 0.0);
  c.write_output_values(out);
  const std::size_t k = static_cast<std::size_t>(it - names.begin());
  return {out[3 * k], out[3 * k + 1], out[3 * k + 2]};
}

/// Runs the model and samples it when the travel first passes each of `fractions` x o.travel.
std::vector<HertzSample> run_hertz(const HertzOptions& o, const std::vector<Real>& fractions) {
  const hertz_test::HertzModel hm = hertz_test::make_hertz_model(o);
  test_support::Run run(hm.model);
  const Vec3 down = o.frame.map(Vec3(0.0, -1.0, 0.0));
  Id cap_node = 0;  // any node of the rigid cap tracks the drive (no rotation)
  for (const auto& e : hm.model.solids)
    if (e.pid == hm.sphere_pid) cap_node = e.n[0];
  const Vec3 cap0 = run.x(cap_node);
  std::vector<HertzSample> out;
  std::size_t next = 0;
  while (next < fractions.size() && run.sim->step()) {
    const Real d = (run.x(cap_node) - cap0).dot(down) - o.gap;
    if (d < fractions[next] * o.travel) continue;
    HertzSample s;
    s.d = d;
    s.force = force_on_block(run.sim->contacts()[0]).dot(down);
    const Real u_probe = (run.x(hm.axis_depth) - run.sim->nodes().x0.get(run.index.at(hm.axis_depth))).dot(down);
    const Real u_top = (run.x(hm.axis_top) - run.sim->nodes().x0.get(run.index.at(hm.axis_top))).dot(down);
    s.d_rel = d - u_probe;
    s.ratio = s.force / hertz_test::hertz_force_at_relative_approach(s.d_rel, hm.probe_depth, o.radius, o.youngs,
                                                                      o.poisson);
    const Real a_far = std::sqrt(o.radius * d);
    s.ratio_far = s.force / hertz_test::hertz_force(a_far, o.radius, o.youngs, o.poisson);
    s.sink = (d - u_top) / d;
    s.ratio_sunk = s.force / hertz_test::hertz_force_at_relative_approach(s.d_rel - (d - u_top), hm.probe_depth,
                                                                           o.radius, o.youngs, o.poisson);
    out.push_back(s);
    ++next;
  }
  std::printf("hertz run: %ld cycles, dt %.3e, elements %.1f s, contact %.1f s\n", run.sim->cycle(), run.sim->dt(),
              run.sim->element_seconds(), run.sim->contact_seconds());
  return out;
}

struct HertzCase {
  const char* name;
  ContactType type;
  Enforcement enforcement;
  Real sfs;
};

void print(const HertzCase& c, const char* frame, const std::vector<HertzSample>& s) {
  for (const HertzSample& x : s)
    std::printf("hertz %-22s %-7s d %.5f F %.5f ratio %.4f (less the sinking: %.4f; far-field d: %.4f) sink %.3f\n",
                c.name, frame, x.d, x.force, x.ratio, x.ratio_sunk, x.ratio_far, x.sink);
}

// The closed form used by the test: u(0) is the Hertz approach, far down the axis the Hertz load
// acts as a point load (Boussinesq), and the inverse is consistent.
TEST(HertzClosedForm, AxisDisplacementAndInverse) {
  const Real r = 1.0, e = 1000.0, nu = 0.3, a = 0.1;
  EXPECT_NEAR(hertz_test::axis_displacement(0.0, a, r, e, nu), a * a / r, 1e-15);
  const Real z = 100.0 * a, f = hertz_test::hertz_force(a, r, e, nu);
  EXPECT_NEAR(hertz_test::axis_displacement(z, a, r, e, nu) / (f * (1 + nu) * (3 - 2 * nu) / (2 * M_PI * e * z)), 1.0,
              1e-3);
  const Real d_rel = a * a / r - hertz_test::axis_displacement(0.2, a, r, e, nu);
  EXPECT_NEAR(hertz_test::hertz_force_at_relative_approach(d_rel, 0.2, r, e, nu) / f, 1.0, 1e-12);
}

const std::vector<Real> kFractions{0.2, 0.4, 0.6, 0.8, 1.0};

/// Runs a case in the global frame and in the rotated copy; checks that the copy gives the same
/// figures (1e-3: the two runs' sample times differ by the steps' round-off) and that the force
/// grows with d. Returns the global frame's samples.
std::vector<HertzSample> run_both_frames(const HertzCase& c) {
  HertzOptions o;
  o.type = c.type;
  o.enforcement = c.enforcement;
  o.sfs = c.sfs;
  const std::vector<HertzSample> g = run_hertz(o, kFractions);
  print(c, "global", g);
  o.frame = test_support::oblique_frame();
  const std::vector<HertzSample> r = run_hertz(o, kFractions);
  print(c, "rotated", r);
  EXPECT_EQ(g.size(), kFractions.size());
  EXPECT_EQ(r.size(), kFractions.size());
  for (std::size_t k = 0; k < std::min(g.size(), r.size()); ++k) {
    EXPECT_NEAR(r[k].ratio, g[k].ratio, 1e-3 * g[k].ratio) << "rotated copy, d = " << g[k].d;
    if (k > 0) EXPECT_GT(g[k].force, g[k - 1].force);
  }
  return g;
}

constexpr ContactType T3 = ContactType::surface_to_surface;
constexpr Enforcement P = Enforcement::penalty, L = Enforcement::lagrange;
constexpr HertzCase kLagrange{"t3_lagrange", T3, L, 1.0};

/// Type 3 Lagrange in the global frame, run once per process (the penalty cases' reference).
const std::vector<HertzSample>& lagrange_reference() {
  static const std::vector<HertzSample> g = [] {
    HertzOptions o;
    o.enforcement = L;
    const std::vector<HertzSample> s = run_hertz(o, kFractions);
    print(kLagrange, "global", s);
    return s;
  }();
  return g;
}

// Exact contact (Type 3 Lagrange: no penetration, 2e-3 of d on the axis). Known limit, the mesh:
// force / Hertz 0.957-0.964 with h = 0.02 (a / h = 2.2-5), 0.930-0.946 with h = 0.03; the
// sequence extrapolates to 0.97-0.98 as h -> 0, the rest the elastic law's finite strain
// (p0 / E* up to 1.6 %) and the finite block (docs/verification.md, "Hertz"). The bound is the
// issue's 2 % above and the h = 0.02 mesh's figure rounded down below, so that a change that makes
// it worse is seen.
TEST(HertzContactSlow, Type3LagrangeFollowsHertzToTheMeshsAccuracy) {
  const std::vector<HertzSample> g = run_both_frames(kLagrange);
  for (const HertzSample& s : g) {
    if (s.d < 0.3 * HertzOptions{}.travel) continue;  // a < 2.8 h: fewer than 3 elements across
    EXPECT_GE(s.ratio, 0.95) << "d = " << s.d;
    EXPECT_LE(s.ratio, 1.02) << "d = " << s.d;
    EXPECT_LT(std::abs(s.sink), 5e-3) << "d = " << s.d;
  }
}

class HertzPenaltySlow : public ::testing::TestWithParam<HertzCase> {};

// Penalty: the indenter sinks into the block by p on the axis, less towards the contact's edge, so
// the block's elastic approach lies between d_rel - p and d_rel, and the force between the mesh's
// exact-contact figures (Type 3 Lagrange, same mesh, same d) at those two approaches:
// force / Hertz(d_rel) <= m and force / Hertz(d_rel - p) >= m, each within 2 % (the issue's
// target), m = Lagrange's force / Hertz at that d.
TEST_P(HertzPenaltySlow, ForceLiesBetweenTheExactContactFiguresOfItsApproaches) {
  const std::vector<HertzSample>& lag = lagrange_reference();
  const std::vector<HertzSample> g = run_both_frames(GetParam());
  ASSERT_EQ(g.size(), lag.size());
  for (std::size_t k = 0; k < g.size(); ++k) {
    EXPECT_LE(g[k].ratio / lag[k].ratio, 1.02) << "d = " << g[k].d;
    EXPECT_GE(g[k].ratio_sunk / lag[k].ratio, 0.98) << "d = " << g[k].d;
  }
}

constexpr HertzCase kPenaltyCases[] = {
    {"t3_penalty_sfs10", T3, P, 10.0},
    {"t3_penalty_default", T3, P, 1.0},
    // Type 12 (penalty and Lagrange) is not here: known limits, docs/verification.md "Hertz".
};

INSTANTIATE_TEST_SUITE_P(Cases, HertzPenaltySlow, ::testing::ValuesIn(kPenaltyCases),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace slideline
