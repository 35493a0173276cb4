// SegmentContact (SOFT = 2): the search cadence (BSORT) and the side memory across shell segments.
// 1. Cadence. Between two searches the candidates of an inflated search serve, narrowed each cycle
//    by the every-cycle search's own box test, so the forces must equal the every-cycle search's
//    bit for bit as long as no pair is missed. Two 4 x 4 grids (solid faces facing each other, or
//    shells with offsets) slide across each other and press in under prescribed motion; half way
//    the upper grid jumps by more than the allowance (no step could do that, the test can), which
//    must trigger an early search. Every cycle the forces and step votes of BSORT 10 and 0 equal
//    those of BSORT 1 exactly; searches: one per BSORT cycles plus the early one.
// 2. Side memory. A shell square (offset o_u) pressed past the mid-surface of a shell (offset o_l)
//    by e keeps the side it came from while within o_u + o_l: the force on it is
//      F = 0.5 k (o_u + o_l + e)   (0.5: only the square's Gauss points lie over the shell)
//    upwards, k = 0.5 x 0.1 x m_a m_b / (m_a + m_b) / dt_c^2. Slid onto the neighbouring shell
//    segment (sharing an edge; its normal the same way, or reversed), the side carries over: the
//    same F, upwards (read afresh it would be 0.5 k (o_u + o_l - e), downwards). Also rotated.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <vector>

#include "slideline/contact/search/brute_force_broad_phase.hpp"
#include "slideline/contact/segment_contact.hpp"
#include "slideline/element/element_block.hpp"

namespace slideline {
namespace {

using Mat3 = Eigen::Matrix<Real, 3, 3>;

Mat3 oblique() {
  return (Eigen::AngleAxis<Real>(0.7, Vec3(1, 2, 3).normalized()) * Eigen::AngleAxis<Real>(-0.4, Vec3::UnitX()))
      .toRotationMatrix();
}

constexpr int kN = 4;             // quads per side of each grid
constexpr Real kH = 0.25;         // their size
constexpr Real kDt = 0.01;        // the step (and dt_c)
constexpr int kCycles = 200;
constexpr int kJumpCycle = 125;   // not a scheduled search of BSORT 10 (1, 11, ..., 121, 131)
const Vec3 kVelocity(0.15, 0.05, -0.02);  // the upper grid's (length / time)

Index lower_node(int i, int j) { return i + (kN + 1) * j; }
Index upper_node(int i, int j) { return (kN + 1) * (kN + 1) + i + (kN + 1) * j; }

/// Lower grid at z = 0 (normal +z), upper at z0 (normal -z); solid faces of one element each, or
/// shells (offsets 0.03, thickness 0.06).
struct Grids {
  NodalFields nodes;
  std::vector<std::unique_ptr<ElementBlock>> blocks;
  std::unique_ptr<SegmentContact> contact;

  Grids(bool shells, int bsort, const Mat3& r) {
    const Index n = 2 * (kN + 1) * (kN + 1);
    nodes.resize(n);
    for (Index i = 0; i < n; ++i) nodes.mass[static_cast<std::size_t>(i)] = 1.0;
    Surface s;
    for (int j = 0; j < kN; ++j)
      for (int i = 0; i < kN; ++i) {
        s.conn.insert(s.conn.end(), {lower_node(i, j), lower_node(i + 1, j), lower_node(i + 1, j + 1),
                                     lower_node(i, j + 1)});
        s.block.push_back(0);
        s.element.push_back(i + kN * j);
        s.part.push_back(1);
      }
    for (int j = 0; j < kN; ++j)
      for (int i = 0; i < kN; ++i) {
        s.conn.insert(s.conn.end(), {upper_node(i, j), upper_node(i, j + 1), upper_node(i + 1, j + 1),
                                     upper_node(i + 1, j)});
        s.block.push_back(1);
        s.element.push_back(i + kN * j);
        s.part.push_back(2);
      }
    const std::size_t ns = s.block.size();
    s.kind.assign(ns, shells ? SegmentKind::shell : SegmentKind::solid_face);
    s.thickness.assign(ns, shells ? 0.06 : 0.0);
    for (Index i = 0; i < n; ++i) s.nodes.push_back(i);
    std::vector<std::uint8_t> sides(ns, 2);
    for (std::size_t k = ns / 2; k < ns; ++k) sides[k] = 1;
    contact = std::make_unique<SegmentContact>("grids", s, sides, std::make_unique<BruteForceBroadPhase>(), 0.1);
    if (shells) contact->set_offsets(std::vector<Real>(ns, 0.03));
    contact->set_search_interval(bsort);
    place(r, 0.0);
    contact->initialize(ContactContext{nodes, blocks, nullptr, {}, nullptr});
  }

  /// The upper grid moved by kVelocity t plus `jump` (length, along x), r applied to all.
  void place(const Mat3& r, Real t, Real jump = 0.0) {
    const Vec3 start(0.1, 0.05, 0.005);
    for (int j = 0; j <= kN; ++j)
      for (int i = 0; i <= kN; ++i) {
        const Vec3 p(kH * i, kH * j, 0.0);
        nodes.x.set(lower_node(i, j), r * p);
        nodes.v.set(lower_node(i, j), Vec3::Zero());
        nodes.x.set(upper_node(i, j), r * (p + start + t * kVelocity + Vec3(jump, 0.0, 0.0)));
        nodes.v.set(upper_node(i, j), r * kVelocity);
      }
  }

  void cycle() {
    nodes.f_contact.fill(0.0);
    StepTimes t;
    t.dt_prev = kDt;
    t.dt_initial = kDt;
    contact->apply_forces(nodes, t, ContactForceView{nodes.f_contact, nodes.m_contact});
  }
};

bool same_bits(const Vec3Field& a, const Vec3Field& b) {
  const auto eq = [](const std::vector<Real>& u, const std::vector<Real>& v) {
    return u.size() == v.size() && std::memcmp(u.data(), v.data(), u.size() * sizeof(Real)) == 0;
  };
  return eq(a.x, b.x) && eq(a.y, b.y) && eq(a.z, b.z);
}

TEST(SegmentContactCadence, ForcesEqualTheEveryCycleSearchBitForBitAndAJumpSearchesEarly) {
  for (const bool shells : {false, true})
    for (const bool rotated : {false, true}) {
      const Mat3 r = rotated ? oblique() : Mat3::Identity();
      Grids every(shells, 1, r), ten(shells, 10, r), dflt(shells, 0, r);
      int touching = 0;
      bool early = false;
      for (int c = 1; c <= kCycles; ++c) {
        const Real jump = c >= kJumpCycle ? 0.2 : 0.0;  // 0.2 > a = 1.5 |v| dt 10 = 0.024
        for (Grids* g : {&every, &ten, &dflt}) g->place(r, c * kDt, jump);
        const Index before = ten.contact->search_count();
        for (Grids* g : {&every, &ten, &dflt}) g->cycle();
        if (c == kJumpCycle) early = ten.contact->search_count() == before + 1;
        ASSERT_TRUE(same_bits(every.nodes.f_contact, ten.nodes.f_contact)) << "cycle " << c;
        ASSERT_TRUE(same_bits(every.nodes.f_contact, dflt.nodes.f_contact)) << "cycle " << c;
        ASSERT_EQ(every.contact->stable_dt(), ten.contact->stable_dt()) << "cycle " << c;
        if (every.contact->slave_force().norm() > 0.0) ++touching;
      }
      std::printf("%s %s: %d of %d cycles in contact; searches: every cycle %ld, BSORT 10 %ld, BSORT 0 %ld\n",
                  shells ? "shells" : "solids", rotated ? "rotated" : "aligned", touching, kCycles,
                  static_cast<long>(every.contact->search_count()), static_cast<long>(ten.contact->search_count()),
                  static_cast<long>(dflt.contact->search_count()));
      EXPECT_GT(touching, kCycles / 2);  // the comparison is not of zeros
      EXPECT_TRUE(early);
      EXPECT_EQ(every.contact->search_count(), kCycles + 1);
      // initialize's, cycles 1, 11, ..., 121, the jump's at 125, then 135, ..., 195.
      EXPECT_EQ(ten.contact->search_count(), 1 + 13 + 1 + 7);
      EXPECT_EQ(dflt.contact->search_count(), ten.contact->search_count());  // the default is 10
      EXPECT_NEAR(ten.contact->search_allowance(), 1.5 * kVelocity.norm() * kDt * 10, 1e-15);
    }
}

// ---- side memory across shell segments -----------------------------------------------------

constexpr Real kOu = 0.03, kOl = 0.05, kPast = 0.02, kMu = 3.0, kMl = 1.0;

struct Slide {
  NodalFields nodes;
  std::vector<std::unique_ptr<ElementBlock>> blocks;
  std::unique_ptr<SegmentContact> contact;
  Mat3 r;

  /// Lower shell: two unit squares side by side along x (nodes 0-5, masses kMl), the second
  /// reversed when `flip`; upper: a 0.2 x 0.2 shell square (nodes 6-9, masses kMu).
  Slide(const Mat3& rotation, bool flip) : r(rotation) {
    nodes.resize(10);
    for (Index i = 0; i < 10; ++i) nodes.mass[static_cast<std::size_t>(i)] = i < 6 ? kMl : kMu;
    const Vec3 lower[6] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}};
    for (Index i = 0; i < 6; ++i) nodes.x.set(i, r * lower[i]);
    place(0.4, 0.5);
    Surface s;
    s.conn = {0, 1, 4, 3};
    if (flip)
      s.conn.insert(s.conn.end(), {1, 4, 5, 2});
    else
      s.conn.insert(s.conn.end(), {1, 2, 5, 4});
    s.conn.insert(s.conn.end(), {6, 7, 8, 9});
    s.block = {0, 0, 1};
    s.element = {0, 1, 0};
    s.part = {1, 1, 2};
    s.kind.assign(3, SegmentKind::shell);
    s.thickness = {2 * kOl, 2 * kOl, 2 * kOu};
    s.nodes = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
    contact = std::make_unique<SegmentContact>("slide", s, std::vector<std::uint8_t>{2, 2, 1},
                                               std::make_unique<BruteForceBroadPhase>(), 0.1);
    contact->set_offsets({kOl, kOl, kOu});
    contact->initialize(ContactContext{nodes, blocks, nullptr, {}, nullptr});
  }

  /// The upper square's corner at (x0, 0.4) at height z.
  void place(Real x0, Real z) {
    const Vec3 sq[4] = {{0, 0, 0}, {0.2, 0, 0}, {0.2, 0.2, 0}, {0, 0.2, 0}};
    for (Index i = 0; i < 4; ++i) nodes.x.set(6 + i, r * (sq[i] + Vec3(x0, 0.4, z)));
  }

  /// The force on the upper square along +z (rotated).
  Real press(Real x0, Real z) {
    place(x0, z);
    nodes.f_contact.fill(0.0);
    StepTimes t;
    t.dt_prev = 0.01;
    t.dt_initial = 0.01;
    contact->apply_forces(nodes, t, ContactForceView{nodes.f_contact, nodes.m_contact});
    Vec3 up = Vec3::Zero();
    for (Index i = 6; i < 10; ++i) up += nodes.f_contact.get(i);
    return up.dot(r * Vec3::UnitZ());
  }
};

TEST(SegmentContactCadence, ShellSideIsKeptWhenThePointSlidesOntoTheNeighbouringSegment) {
  const Real k = 0.5 * 0.1 * (4 * kMu) * (4 * kMl) / (4 * kMu + 4 * kMl) / (0.01 * 0.01);  // 1500
  const Real o = kOu + kOl;
  for (const bool rotated : {false, true})
    for (const bool flip : {false, true}) {
      Slide s(rotated ? oblique() : Mat3::Identity(), flip);
      const Real tol = 1e-9 * k * o;
      EXPECT_NEAR(s.press(0.4, 0.5 * o), 0.5 * k * 0.5 * o, tol);  // from above, over segment 0
      EXPECT_NEAR(s.press(0.4, -kPast), 0.5 * k * (o + kPast), tol) << "pushed past: the side kept";
      EXPECT_NEAR(s.press(1.4, -kPast), 0.5 * k * (o + kPast), tol)
          << "slid onto the neighbour" << (flip ? " (reversed)" : "") << ": the side carried over";
      EXPECT_NEAR(s.press(1.4, 0.5 * o), 0.5 * k * 0.5 * o, tol);  // back above, over segment 1
      EXPECT_NEAR(s.press(1.4, 2.0 * o), 0.0, tol);                 // out of contact: forgotten
      EXPECT_NEAR(s.press(1.4, -0.5 * o), -0.5 * k * 0.5 * o, tol);  // from below: read afresh
    }
}

}  // namespace
}  // namespace slideline
