// SegmentContact (SOFT = 2) with shell segments, against closed forms, also in a rotated frame.
// Two unit squares, the lower at z = 0 (node masses 1), the upper at z (node masses 3), as in
// test_segment_contact.cpp: k = 0.5 x 0.1 x m_a m_b / (m_a + m_b) / dt_c^2 = 1500 (m_a = 12,
// m_b = 4, dt_c = 0.01). A shell's contact surface lies its offset o off its mid-surface on
// either side, so two shells (offsets o_u, o_l) pressed to mid-surface distance g carry
// k (o_u + o_l - g), pushing them apart along the side the upper one came from; a solid face (no
// offset) on a shell carries k (o_l - g), from above or below (its outward normal towards the
// shell). The side is remembered while a point stays within o_u + o_l of the other
// mid-surface: pushed past it, the force still points back to where it came from.
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
constexpr Real kOu = 0.03, kOl = 0.05;  // offsets: half the upper's and the lower's contact thickness

struct Pair {
  NodalFields nodes;
  std::vector<std::unique_ptr<ElementBlock>> blocks;
  std::unique_ptr<SegmentContact> contact;
  Mat3 r = Mat3::Identity();
  bool upper_faces_up = false;  ///< the upper segment's normal +z (a solid face: its body below it)

  void place(Real z) {
    const Vec3 lower[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    const Vec3 down[4] = {{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}};
    for (Index i = 0; i < 4; ++i) {
      nodes.x.set(i, r * lower[i]);
      nodes.x.set(4 + i, r * ((upper_faces_up ? lower[i] : down[i]) + Vec3(0, 0, z)));
    }
  }

  /// upper: shell (offset kOu) or solid face (no offset); the lower is a shell (offset kOl).
  Pair(const Mat3& rotation, Real z0, bool upper_shell, bool faces_up = false) : r(rotation), upper_faces_up(faces_up) {
    nodes.resize(8);
    for (Index i = 0; i < 8; ++i) nodes.mass[static_cast<std::size_t>(i)] = i < 4 ? kMl : kMu;
    place(z0);
    Surface s;
    s.conn = {4, 5, 6, 7, 0, 1, 2, 3};
    s.block = {0, 1};
    s.element = {0, 0};
    s.part = {2, 1};
    s.kind = {upper_shell ? SegmentKind::shell : SegmentKind::solid_face, SegmentKind::shell};
    s.thickness = {upper_shell ? 2 * kOu : 0.0, 2 * kOl};
    s.nodes = {0, 1, 2, 3, 4, 5, 6, 7};
    contact = std::make_unique<SegmentContact>("pair", s, std::vector<std::uint8_t>{1, 2},
                                               std::make_unique<BruteForceBroadPhase>(), kScale);
    contact->set_offsets({upper_shell ? kOu : 0.0, kOl});
    contact->initialize(ContactContext{nodes, blocks, nullptr, {}, nullptr});
  }

  /// The force on the upper segment along +z (rotated) at mid-surface height z.
  Real press(Real z) {
    place(z);
    nodes.f_contact.fill(0.0);
    StepTimes t;
    t.dt_prev = kDtc;
    t.dt_initial = kDtc;
    contact->apply_forces(nodes, t, ContactForceView{nodes.f_contact, nodes.m_contact});
    Vec3 upper = Vec3::Zero(), lower = Vec3::Zero();
    for (Index i = 0; i < 4; ++i) {
      upper += nodes.f_contact.get(4 + i);
      lower += nodes.f_contact.get(i);
    }
    EXPECT_LT((upper + lower).norm(), 1e-12 * (1.0 + upper.norm()));  // equal and opposite
    EXPECT_LT((upper - (r * Vec3::UnitZ()) * upper.dot(r * Vec3::UnitZ())).norm(), 1e-12 * (1.0 + upper.norm()));
    return upper.dot(r * Vec3::UnitZ());
  }
};

Mat3 oblique() { return Eigen::AngleAxis<Real>(0.7, Vec3(1.0, 2.0, 3.0).normalized()).toRotationMatrix(); }

TEST(SegmentContactShells, ShellsMeetAtTheSumOfTheirOffsetsFromEitherSide) {
  const Real o = kOu + kOl;
  for (const Mat3& r : {Mat3(Mat3::Identity()), oblique()}) {
    Pair above(r, 0.2, true);
    EXPECT_EQ(above.press(o + 1e-3), 0.0);
    EXPECT_NEAR(above.press(o - 0.01), kK * 0.01, 1e-9);
    EXPECT_NEAR(above.press(0.02), kK * (o - 0.02), 1e-9);
    // Pushed 0.02 past the lower mid-surface: the side is remembered, the force still points up.
    EXPECT_NEAR(above.press(-0.02), kK * (o + 0.02), 1e-9);
    Pair below(r, -0.2, true);  // the mirror: the upper shell comes from below
    EXPECT_EQ(below.press(-o - 1e-3), 0.0);
    EXPECT_NEAR(below.press(-o + 0.01), -kK * 0.01, 1e-9);
    EXPECT_NEAR(below.press(0.02), -kK * (o + 0.02), 1e-9);
  }
}

TEST(SegmentContactShells, ASolidFaceMeetsAShellAtTheShellOffsetFromEitherSide) {
  for (const Mat3& r : {Mat3(Mat3::Identity()), oblique()}) {
    Pair faces(r, 0.2, false);  // the face's normal -z: the body above it, facing the shell
    EXPECT_EQ(faces.press(kOl + 1e-3), 0.0);
    EXPECT_NEAR(faces.press(kOl - 0.01), kK * 0.01, 1e-9);
    Pair below(r, -0.2, false, true);  // normal +z, below the shell: faces it from below
    EXPECT_NEAR(below.press(-kOl + 0.01), -kK * 0.01, 1e-9);
  }
}

}  // namespace
}  // namespace slideline
