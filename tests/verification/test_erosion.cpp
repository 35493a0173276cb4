// Element erosion from the material's failure strain (*MAT_PLASTIC_KINEMATIC FS,
// *MAT_PIECEWISE_LINEAR_PLASTICITY FAIL; element/element_erosion.hpp), read from a deck: a bar of
// hexahedra pulled in uniaxial stress, against the closed-form bilinear curve. The element is
// deleted when its plastic strain reaches the failure strain, at the time the curve gives (to the
// step); its forces vanish, the reaction with them; the energy it held is booked as eroded and the
// balance closes. A notched bar (one weaker element) breaks there; the same runs on 1 and 3
// threads give the same bits.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "slideline/core/error.hpp"
#include "slideline/core/parallel.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/solver/build.hpp"
#include "slideline/solver/simulation.hpp"
#include "test_support/kuhn_tets.hpp"

namespace slideline {
namespace {

constexpr Real kE = 1000.0, kNu = 0.3, kRho = 1e-5, kEt = 10.0, kFail = 0.02;
/// The plastic hardening modulus E Et / (E - Et) of the bilinear curve.
constexpr Real kEp = kE * kEt / (kE - kEt);

/// A bar of nx x ny x nz unit cubes along x: x = 0 held in x, y = 0 in y, z = 0 in z (uniaxial
/// stress: the lateral faces are free), the end x = nx pulled by the displacement u(t) (`u`:
/// points of a piecewise-linear curve). Every element is *MAT_PLASTIC_KINEMATIC (isotropic
/// hardening, yield 1.5) but those of x-layer `weak` (-1: none), which yield at 1; both fail at
/// plastic strain kFail.
struct BarDeck {
  int nx = 1, ny = 1, nz = 1;
  int weak = -1;
  int elform = 1;  ///< *SECTION_SOLID ELFORM: 1, 2, or 10 (six tetrahedra per cube)
  Real end_time = 1.0;
  std::vector<std::pair<Real, Real>> u;

  int node_id(int i, int j, int k) const { return 1 + i + (nx + 1) * (j + (ny + 1) * k); }
  int element_id(int i, int j, int k) const { return 1 + i + nx * (j + ny * k); }

  std::string text() const {
    std::ostringstream o;
    o << std::setprecision(17) << "*KEYWORD\n*CONTROL_TERMINATION\n" << end_time << ",\n*SECTION_SOLID\n1," << elform << "\n";
    for (int m = 1; m <= 2; ++m)
      o << "*MAT_PLASTIC_KINEMATIC\n" << m << "," << kRho << "," << kE << "," << kNu << "," << (m == 1 ? 1.5 : 1.0)
        << "," << kEt << ",1.0\n0,0," << kFail << "\n*PART\npart " << m << "\n" << m << ",1," << m << "\n";
    o << "*NODE\n";
    for (int k = 0; k <= nz; ++k)
      for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) o << node_id(i, j, k) << "," << i << "," << j << "," << k << "\n";
    o << "*ELEMENT_SOLID\n";
    if (elform == 10) {
      write_tets(o);
      return finish(o);
    }
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
          o << element_id(i, j, k) << "," << (i == weak ? 2 : 1) << "," << node_id(i, j, k) << ","
            << node_id(i + 1, j, k) << "," << node_id(i + 1, j + 1, k) << "," << node_id(i, j + 1, k) << ","
            << node_id(i, j, k + 1) << "," << node_id(i + 1, j, k + 1) << "," << node_id(i + 1, j + 1, k + 1) << ","
            << node_id(i, j + 1, k + 1) << "\n";
    return finish(o);
  }

  /// Six tetrahedra per cube (N5-N8 repeat N4), numbered 6 (cube id - 1) + 1..6.
  void write_tets(std::ostream& o) const {
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
          for (std::size_t t = 0; t < 6; ++t) {
            const auto corner = [&](int c) { return node_id(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1)); };
            const auto tet = test_support::kuhn_tets()[t];
            const int n4 = corner(tet[3]);
            o << 6 * (element_id(i, j, k) - 1) + static_cast<int>(t) + 1 << "," << (i == weak ? 2 : 1) << ","
              << corner(tet[0]) << "," << corner(tet[1]) << "," << corner(tet[2]) << "," << n4 << "," << n4 << ","
              << n4 << "," << n4 << "," << n4 << "\n";
          }
  }

  /// The node sets, supports and pull, after the elements.
  std::string finish(std::ostringstream& o) const {
    // Node sets 1-4: x = 0, y = 0, z = 0, x = nx.
    const auto set = [&](int sid, auto on) {
      o << "*SET_NODE_LIST\n" << sid << "\n";
      for (int k = 0; k <= nz; ++k)
        for (int j = 0; j <= ny; ++j)
          for (int i = 0; i <= nx; ++i)
            if (on(i, j, k)) o << node_id(i, j, k) << "\n";
    };
    set(1, [](int i, int, int) { return i == 0; });
    set(2, [](int, int j, int) { return j == 0; });
    set(3, [](int, int, int k) { return k == 0; });
    set(4, [&](int i, int, int) { return i == nx; });
    o << "*BOUNDARY_SPC_SET\n1,0,1,0,0\n*BOUNDARY_SPC_SET\n2,0,0,1,0\n*BOUNDARY_SPC_SET\n3,0,0,0,1\n"
      << "*BOUNDARY_PRESCRIBED_MOTION_SET\n4,1,2,1\n*DEFINE_CURVE\n1\n";
    for (const auto& [t, d] : u) o << t << "," << d << "\n";
    o << "*END\n";
    return o.str();
  }
};

/// The end displacement: the velocity ramps from 0 to v along a half cosine over [0, t_ramp] (no
/// kink to shake the bar), then holds to t_end; returned as (t, u) points and as a function.
struct Pull {
  Real v, t_ramp;
  Real at(Real t) const {
    const Real pi = std::acos(-1.0);
    if (t >= t_ramp) return v * (t - 0.5 * t_ramp);
    return 0.5 * v * (t - t_ramp / pi * std::sin(pi * t / t_ramp));
  }
  /// The time u reaches `d` after the ramp (u linear there).
  Real time_of(Real d) const { return d / v + 0.5 * t_ramp; }
  std::vector<std::pair<Real, Real>> points(Real t_end) const {
    std::vector<std::pair<Real, Real>> p;
    for (int i = 0; i <= 100; ++i) p.push_back({t_ramp * i / 100, at(t_ramp * i / 100)});
    p.push_back({t_end, at(t_end)});
    return p;
  }
};

/// The stress at which plastic strain kFail is reached, for initial yield `sy` (isotropic
/// hardening: sy + Ep eps_p), and the log strain there (elastic sigma / E plus plastic).
Real failure_stress(Real sy) { return sy + kEp * kFail; }
Real failure_log_strain(Real sy) { return failure_stress(sy) / kE + kFail; }

/// What a run records: the x reaction on the held end at each step, the step times, and the
/// deletion times of the first block's elements at the end.
struct RunResult {
  std::vector<Real> t, reaction, dt;  ///< per step: its end time, the reaction, the step
  std::vector<Real> deleted_at;  ///< per element of the bar (block order), -1: not deleted
  EnergyReport energy;
  /// The step at the first deletion (after it, with every element gone, nothing bounds the step).
  Real step_at_deletion() const {
    Real first = -1.0;
    for (Real d : deleted_at)
      if (d >= 0.0 && (first < 0.0 || d < first)) first = d;
    std::size_t k = 0;
    while (k + 1 < t.size() && t[k] < first) ++k;
    return dt[k];
  }
  /// Index of the first step whose forces were those at or after time `td` (the step that starts
  /// at td ends at t[k] > td).
  std::size_t first_step_after(Real td) const {
    std::size_t k = 0;
    while (k < t.size() && t[k] <= td) ++k;
    return k;
  }
};

/// Runs deck `text`; the reaction is the x sum over the support groups named `held`.
RunResult run(const std::string& text, const std::vector<std::string>& held = {"spc_1"}) {
  auto sim = build_simulation(read_keyword_string(text, "bar.k"));
  RunResult r;
  std::vector<const SupportGroup*> groups;
  for (const auto& g : sim->supports())
    if (std::find(held.begin(), held.end(), g.name) != held.end()) groups.push_back(&g);
  EXPECT_EQ(groups.size(), held.size());
  bool more = true;
  while (more) {
    more = sim->step();
    r.dt.push_back(sim->time() - (r.t.empty() ? 0.0 : r.t.back()));
    r.t.push_back(sim->time());
    Real f = 0.0;
    for (const SupportGroup* g : groups) f += g->reaction.x();
    r.reaction.push_back(f);
  }
  for (const auto& b : sim->blocks()) {
    const ElementErosion* er = std::as_const(*b).erosion();
    EXPECT_NE(er, nullptr) << "part " << b->part_id() << " erodes";
    if (!er) continue;
    for (std::size_t e = 0; e < er->deletion_times().size(); ++e) r.deleted_at.push_back(er->deletion_times()[e]);
  }
  r.energy = sim->energy();
  return r;
}

/// A 1 x 1 Belytschko-Tsay shell (thickness 0.1, 2 Gauss points) of the bar's stronger material
/// in the x-y plane: x = 0 held in x (node 1 in y too), z and the rotations held everywhere, the
/// edge x = 1 pulled by `u`: uniaxial membrane stress.
std::string shell_strip(Real end_time, const std::vector<std::pair<Real, Real>>& u) {
  std::ostringstream o;
  o << std::setprecision(17) << "*KEYWORD\n*CONTROL_TERMINATION\n" << end_time
    << ",\n*SECTION_SHELL\n1,2,1.0,2\n0.1,0.1,0.1,0.1\n*MAT_PLASTIC_KINEMATIC\n1," << kRho << "," << kE << ","
    << kNu << ",1.5," << kEt << ",1.0\n0,0," << kFail << "\n*PART\nstrip\n1,1,1\n*NODE\n1,0,0,0\n2,1,0,0\n"
    << "3,1,1,0\n4,0,1,0\n*ELEMENT_SHELL\n1,1,1,2,3,4\n*BOUNDARY_SPC_NODE\n1,0,1,1,1,1,1,1\n"
    << "*BOUNDARY_SPC_NODE\n4,0,1,0,1,1,1,1\n*BOUNDARY_SPC_NODE\n2,0,0,0,1,1,1,1\n*BOUNDARY_SPC_NODE\n"
    << "3,0,0,0,1,1,1,1\n*SET_NODE_LIST\n4\n2,3\n*BOUNDARY_PRESCRIBED_MOTION_SET\n4,1,2,1\n*DEFINE_CURVE\n1\n";
  for (const auto& [t, d] : u) o << t << "," << d << "\n";
  o << "*END\n";
  return o.str();
}

}  // namespace

// One element, yield 1.5: deleted at the log strain (1.5 + Ep FS) / E + FS, i.e. at the time the
// prescribed end displacement reaches it, to the step; the reaction is the closed-form failure
// stress just before and exactly 0 from then on (the held nodes belong to that element only). The
// energy the element held, booked as eroded, is the work of the curve to failure, and the balance
// closes with it.
TEST(Erosion, BarFailsAtTheClosedFormStrain) {
  const Pull pull{0.1, 0.05};
  const Real ef = failure_log_strain(1.5), t_fail = pull.time_of(std::exp(ef) - 1.0);
  BarDeck deck;
  deck.end_time = t_fail + 0.02;
  deck.u = pull.points(1.0);
  const RunResult r = run(deck.text());
  ASSERT_EQ(r.deleted_at.size(), 1u);
  const Real t_del = r.deleted_at[0], dt = r.step_at_deletion();
  std::printf("deleted at t = %.6f, closed form %.6f (step %.3g)\n", t_del, t_fail, dt);
  RecordProperty("deletion_time_error_in_steps", std::to_string((t_del - t_fail) / dt));
  EXPECT_NEAR(t_del, t_fail, 1.0 * dt);
  // The reaction: the failure stress times the current section at the last forces before the
  // deletion, exactly 0 from the deleting evaluation on.
  const std::size_t k = r.first_step_after(t_del);
  ASSERT_GT(k, 1u);
  ASSERT_LT(k + 1, r.t.size());
  const Real section = std::exp(-2.0 * kNu * failure_stress(1.5) / kE - kFail);  // elastic and isochoric plastic
  EXPECT_NEAR(r.reaction[k - 1], failure_stress(1.5) * section, 0.005 * failure_stress(1.5));
  for (std::size_t j = k; j < r.t.size(); ++j) ASSERT_EQ(r.reaction[j], 0.0) << "t = " << r.t[j];
  // Eroded energy: the work of the curve to failure per unit (reference) volume.
  const Real sf = failure_stress(1.5);
  const Real work = sf * sf / (2.0 * kE) + 1.5 * kFail + 0.5 * kEp * kFail * kFail;
  std::printf("eroded energy %.6g (internal %.6g, hourglass %.3g), closed form %.6g; balance error %.3g\n",
              r.energy.eroded(), r.energy.eroded_internal, r.energy.eroded_hourglass, work, r.energy.balance_error());
  EXPECT_NEAR(r.energy.eroded(), work, 0.01 * work);
  EXPECT_NEAR(r.energy.internal, 0.0, 1e-3 * work);  // nothing left in the model
  EXPECT_LT(std::abs(r.energy.balance_error()), 1e-3 * work);
}

// The same cube as fully integrated hexahedron (ELFORM 2: deleted at the mean plastic strain of
// its 8 points) and as six tetrahedra (ELFORM 10): under the uniform state the first deletion
// comes at the closed-form time (within a step), every element goes, and the held end is free
// of force from the last deletion on.
TEST(Erosion, FullyIntegratedHexahedronAndTetrahedraFailAtTheClosedFormStrain) {
  const Pull pull{0.1, 0.05};
  const Real t_fail = pull.time_of(std::exp(failure_log_strain(1.5)) - 1.0);
  for (int elform : {2, 10}) {
    BarDeck deck;
    deck.elform = elform;
    deck.end_time = t_fail + 0.01;
    deck.u = pull.points(1.0);
    const RunResult r = run(deck.text());
    ASSERT_EQ(r.deleted_at.size(), elform == 2 ? 1u : 6u);
    const auto [first, last] = std::minmax_element(r.deleted_at.begin(), r.deleted_at.end());
    ASSERT_GE(*first, 0.0) << "ELFORM " << elform << ": every element is deleted";
    const Real dt = r.step_at_deletion();
    std::printf("ELFORM %d: deleted at t = %.6f to %.6f, closed form %.6f (step %.3g)\n", elform, *first, *last,
                t_fail, dt);
    EXPECT_NEAR(*first, t_fail, 1.0 * dt) << "ELFORM " << elform;
    for (std::size_t j = r.first_step_after(*last); j < r.t.size(); ++j)
      ASSERT_EQ(r.reaction[j], 0.0) << "ELFORM " << elform << ", t = " << r.t[j];
    EXPECT_LT(std::abs(r.energy.balance_error()), 1e-3 * r.energy.eroded()) << "ELFORM " << elform;
  }
}

// Three elements, the middle one weaker (yield 1 against 1.5): it alone fails, when the end
// displacement reaches about its log strain at failure plus the other two's elastic stretch. Not
// to the step: the weak element's faces are shared with elastic neighbours that do not contract
// laterally as its plastic flow would (about 1% against 0.04%), so it is not quite in uniaxial
// stress; the end displacement at failure is within 1% of the uniaxial closed form.
TEST(Erosion, NotchedBarBreaksAtTheWeakElement) {
  const Pull pull{0.1, 0.05};
  const Real sf = failure_stress(1.0);
  const Real u_fail = 2.0 * (std::exp(sf / kE) - 1.0) + std::exp(failure_log_strain(1.0)) - 1.0;
  const Real t_fail = pull.time_of(u_fail);
  BarDeck deck;
  deck.nx = 3;
  deck.weak = 1;
  deck.end_time = t_fail + 0.02;
  deck.u = pull.points(1.0);
  const RunResult r = run(deck.text());
  // Blocks in part order: part 1 (elements 1 and 3), part 2 (element 2).
  ASSERT_EQ(r.deleted_at.size(), 3u);
  EXPECT_LT(r.deleted_at[0], 0.0);
  EXPECT_LT(r.deleted_at[1], 0.0);
  const Real u_del = pull.at(r.deleted_at[2]);
  std::printf("weak element deleted at t = %.6f (end displacement %.6g), uniaxial closed form %.6f (%.6g)\n",
              r.deleted_at[2], u_del, t_fail, u_fail);
  EXPECT_NEAR(u_del, u_fail, 0.01 * u_fail);
  // After the break the held piece rings elastically about 0: its mean reaction is near 0.
  Real mean = 0.0;
  int n = 0;
  for (std::size_t j = 0; j < r.t.size(); ++j)
    if (r.t[j] > r.deleted_at[2] + 0.005) {
      mean += r.reaction[j];
      ++n;
    }
  ASSERT_GT(n, 0);
  EXPECT_LT(std::abs(mean / n), 0.05 * sf);
  EXPECT_LT(std::abs(r.energy.balance_error()), 1e-3 * r.energy.eroded());
}

// A bar of 4 x 16 x 16 elements (two chunks), pulled fast so that elements fail within a few
// hundred steps: the histories of 1 and 3 threads are the same bits, deletions included.
TEST(Erosion, DeletionsDoNotDependOnTheThreadCount) {
  BarDeck deck;
  deck.nx = 4;
  deck.ny = deck.nz = 16;
  deck.weak = 2;
  const Pull pull{20.0, 0.002};
  deck.end_time = 0.006;
  deck.u = pull.points(1.0);
  const int before = max_threads();
  set_threads(1);
  const RunResult one = run(deck.text());
  set_threads(3);
  const RunResult three = run(deck.text());
  set_threads(before);
  const auto deleted = std::count_if(one.deleted_at.begin(), one.deleted_at.end(), [](Real t) { return t >= 0.0; });
  std::printf("%ld of %zu elements deleted\n", static_cast<long>(deleted), one.deleted_at.size());
  EXPECT_GT(deleted, 0);
  EXPECT_EQ(one.deleted_at, three.deleted_at);
  EXPECT_EQ(one.reaction, three.reaction);
  EXPECT_EQ(one.energy.values(), three.energy.values());
  EXPECT_EQ(one.energy.eroded(), three.energy.eroded());
}

// The same pull on a shell strip: deleted when both through-thickness points reach FS, at the
// closed-form time (within one step); no force after it; the eroded energy is the work of the
// curve to failure times the volume 0.1 (within 1%: the shell's thickness stays 0.1 while its
// area grows by the plastic flow, about 0.6% more volume on average), and the balance closes.
TEST(Erosion, ShellStripFailsAtTheClosedFormStrain) {
  const Pull pull{0.1, 0.05};
  const Real t_fail = pull.time_of(std::exp(failure_log_strain(1.5)) - 1.0);
  const RunResult r = run(shell_strip(t_fail + 0.02, pull.points(1.0)), {"spc_node_1", "spc_node_4"});
  ASSERT_EQ(r.deleted_at.size(), 1u);
  const Real dt = r.step_at_deletion();
  std::printf("shell deleted at t = %.6f, closed form %.6f (step %.3g)\n", r.deleted_at[0], t_fail, dt);
  EXPECT_NEAR(r.deleted_at[0], t_fail, 1.0 * dt);
  const std::size_t k = r.first_step_after(r.deleted_at[0]);
  ASSERT_GT(k, 1u);
  std::printf("shell force before deletion %.6g, failure stress x thickness %.6g\n", r.reaction[k - 1],
              0.1 * failure_stress(1.5));
  EXPECT_GT(r.reaction[k - 1], 0.1 * 0.95 * failure_stress(1.5));  // the strip carried its load
  for (std::size_t j = k; j < r.t.size(); ++j) ASSERT_EQ(r.reaction[j], 0.0) << "t = " << r.t[j];
  const Real sf = failure_stress(1.5);
  const Real work = 0.1 * (sf * sf / (2.0 * kE) + 1.5 * kFail + 0.5 * kEp * kFail * kFail);
  std::printf("shell eroded energy %.6g, closed form %.6g; balance error %.3g\n", r.energy.eroded(), work,
              r.energy.balance_error());
  EXPECT_NEAR(r.energy.eroded(), work, 0.01 * work);
  EXPECT_LT(std::abs(r.energy.balance_error()), 1e-3 * work);
}

// An eroding part on a contact surface is refused, naming the part and the card: the surfaces are
// not rebuilt as elements go.
TEST(Erosion, ContactWithAnErodingPartIsRefused) {
  BarDeck deck;
  deck.nx = 3;
  deck.weak = 1;
  deck.u = {{0.0, 0.0}, {1.0, 0.1}};
  std::string text = deck.text();
  text.insert(text.rfind("*END"), "*CONTACT_SURFACE_TO_SURFACE\n1,2,3,3\n\n\n");
  try {
    build_simulation(read_keyword_string(text, "bar.k"));
    FAIL() << "a contact on an eroding part ran";
  } catch (const NotImplementedError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("*CONTACT_SURFACE_TO_SURFACE"), std::string::npos) << what;
    EXPECT_NE(what.find("part 1 can erode"), std::string::npos) << what;
  }
}

}  // namespace slideline
