// SegmentContact (SOFT = 2) on two unit square faces pressed together, against closed forms, also
// in a rotated frame. Upper face (slave side, node masses m_u = 3) on lower face (master side,
// m_l = 1): segment masses m_a = 4 m_u = 12, m_b = 4 m_l = 4, m* = 3; with SLSFAC x SFS = 0.1 and
// dt_c = 0.01, k = 0.5 x 0.1 x 3 / 1e-4 = 1500. Pressed by d the pair carries k d, a quarter on
// each node (the faces are matched and the Gauss points symmetric), equal and opposite. Each of the
// 8 Gauss-point springs (4 per face, weight 1/8) joins points where sum N^2 = 4/9 on both faces:
// omega^2 = k / 8 x 4/9 x (1/m_u + 1/m_l), step 2 / omega. An initial penetration d0 is the
// baseline: force k (d - d0), and the baseline follows a separation (d0 = min(d0, d)).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "slideline/contact/search/brute_force_broad_phase.hpp"
#include "slideline/contact/segment_contact.hpp"
#include "slideline/element/element_block.hpp"

namespace slideline {
namespace {

using Mat3 = Eigen::Matrix<Real, 3, 3>;

constexpr Real kMu = 3.0, kMl = 1.0, kDtc = 0.01, kScale = 0.1;
constexpr Real kK = 0.5 * kScale * (4 * kMu) * (4 * kMl) / (4 * kMu + 4 * kMl) / (kDtc * kDtc);  // 1500

struct Pair {
  NodalFields nodes;
  std::vector<std::unique_ptr<ElementBlock>> blocks;
  std::unique_ptr<SegmentContact> contact;
  Mat3 r = Mat3::Identity();

  /// Nodes 0-3 the lower face (normal +z) at z = 0, nodes 4-7 the upper face (normal -z) at `z`.
  void place(Real z) {
    const Vec3 lower[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    const Vec3 upper[4] = {{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}};
    for (Index i = 0; i < 4; ++i) {
      nodes.x.set(i, r * lower[i]);
      nodes.x.set(4 + i, r * (upper[i] + Vec3(0, 0, z)));
    }
  }

  explicit Pair(const Mat3& rotation, Real z0) : r(rotation) {
    nodes.resize(8);
    for (Index i = 0; i < 8; ++i) nodes.mass[static_cast<std::size_t>(i)] = i < 4 ? kMl : kMu;
    place(z0);
    Surface s;
    s.conn = {4, 5, 6, 7, 0, 1, 2, 3};  // segment 0: the upper face (slave side), 1: the lower
    s.block = {0, 0};
    s.element = {0, 1};
    s.part = {2, 1};
    s.kind = {SegmentKind::solid_face, SegmentKind::solid_face};
    s.thickness = {0.0, 0.0};
    s.nodes = {0, 1, 2, 3, 4, 5, 6, 7};
    contact = std::make_unique<SegmentContact>("pair", s, std::vector<std::uint8_t>{1, 2},
                                               std::make_unique<BruteForceBroadPhase>(), kScale);
    contact->initialize(ContactContext{nodes, blocks, nullptr, {}, nullptr});
  }

  /// Forces at upper-face height z, step just taken dt_prev.
  void press(Real z, Real dt_prev = kDtc) {
    place(z);
    nodes.f_contact.fill(0.0);
    StepTimes t;
    t.dt_prev = dt_prev;
    t.dt_initial = kDtc;
    contact->apply_forces(nodes, t, ContactForceView{nodes.f_contact, nodes.m_contact});
  }
  Vec3 up() const { return r * Vec3::UnitZ(); }
};

Mat3 oblique() { return Eigen::AngleAxis<Real>(0.7, Vec3(1.0, 2.0, 3.0).normalized()).toRotationMatrix(); }

TEST(SegmentContactPair, PressedFacesCarryKTimesTheDepthEqualAndOpposite) {
  for (const Mat3& r : {Mat3(Mat3::Identity()), oblique()}) {
    Pair p(r, 0.1);
    EXPECT_EQ(p.contact->initial_penetration_count(), 0);
    const Real d = 0.01;
    p.press(-d);
    const Vec3 f = kK * d * p.up();  // on the upper face
    for (Index i = 0; i < 4; ++i) {
      EXPECT_LT((p.nodes.f_contact.get(4 + i) - 0.25 * f).norm(), 1e-12 * f.norm()) << i;
      EXPECT_LT((p.nodes.f_contact.get(i) + 0.25 * f).norm(), 1e-12 * f.norm()) << i;
    }
    EXPECT_LT((p.contact->slave_force() - f).norm(), 1e-12 * f.norm());
    EXPECT_LT((p.contact->master_force() + f).norm(), 1e-12 * f.norm());
    const Real dt = 2.0 / std::sqrt(kK / 8.0 * 4.0 / 9.0 * (1.0 / kMu + 1.0 / kMl));
    EXPECT_NEAR(p.contact->stable_dt() / dt, 1.0, 1e-12);
    p.press(1e-3);  // apart: nothing
    EXPECT_EQ(p.contact->slave_force().norm(), 0.0);
  }
}

TEST(SegmentContactPair, InitialPenetrationIsTheBaselineAndFollowsASeparation) {
  for (const Mat3& r : {Mat3(Mat3::Identity()), oblique()}) {
    Pair p(r, -0.004);
    EXPECT_EQ(p.contact->initial_penetration_count(), 8);  // every Gauss point of both faces
    EXPECT_NEAR(p.contact->largest_initial_penetration(), 0.004, 1e-14);
    p.press(-0.004);
    EXPECT_LT(p.contact->slave_force().norm(), 1e-9);  // no force at the initial depth
    p.press(-0.01);
    EXPECT_NEAR(p.contact->slave_force().dot(p.up()), kK * 0.006, 1e-9);
    p.press(-0.002);  // out to 0.002: the baseline follows
    EXPECT_LT(p.contact->slave_force().norm(), 1e-9);
    p.press(-0.01);
    EXPECT_NEAR(p.contact->slave_force().dot(p.up()), kK * 0.008, 1e-9);
  }
}

TEST(SegmentContactPair, SpringsFollowAStepThatGrowsMoreThanFivePercent) {
  Pair p(Mat3::Identity(), 0.1);
  p.press(-0.01, 1.04 * kDtc);  // within 5 %: dt_c stays
  EXPECT_EQ(p.contact->sizing_step(), kDtc);
  EXPECT_NEAR(p.contact->slave_force().z(), kK * 0.01, 1e-9);
  p.press(-0.01, 1.1 * kDtc);  // 10 % above: k ~ 1 / dt^2
  EXPECT_EQ(p.contact->sizing_step(), 1.1 * kDtc);
  EXPECT_NEAR(p.contact->slave_force().z(), kK * 0.01 / (1.1 * 1.1), 1e-9);
}

}  // namespace
}  // namespace slideline
