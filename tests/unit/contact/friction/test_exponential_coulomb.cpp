#include <gtest/gtest.h>

#include "slideline/contact/friction/exponential_coulomb.hpp"

using namespace slideline;

TEST(ExponentialCoulomb, DecayLawValues) {
  const ExponentialCoulomb law{0.30, 0.25, 2.0};  // spec Table 2, penalty
  EXPECT_DOUBLE_EQ(law.coefficient(0.0), 0.30);
  EXPECT_NEAR(law.coefficient(0.5), 0.25 + 0.05 * std::exp(-1.0), 1e-15);
  EXPECT_NEAR(law.coefficient(-0.5), law.coefficient(0.5), 1e-15);  // |v|
  EXPECT_NEAR(law.coefficient(Vec3(0.3, 0.0, 0.4)), law.coefficient(0.5), 1e-15);
  EXPECT_NEAR(law.coefficient(100.0), 0.25, 1e-15);
  const ExponentialCoulomb no_decay{0.3, 0.25, 0.0};
  EXPECT_DOUBLE_EQ(no_decay.coefficient(7.0), 0.30);
}

TEST(ExponentialCoulomb, StickBelowTheLimit) {
  const Vec3 trial(1.0, 0.0, 2.0);
  const TangentialReturn r = coulomb_return_map(trial, 10.0, 0.3);  // |trial| = 2.236 < 3
  EXPECT_FALSE(r.slipping);
  EXPECT_EQ(r.force, trial);
  EXPECT_DOUBLE_EQ(r.limit, 3.0);
}

TEST(ExponentialCoulomb, SlipAtTheLimitKeepsTheDirection) {
  const Vec3 trial(3.0, 0.0, -4.0);
  const TangentialReturn r = coulomb_return_map(trial, 10.0, 0.25);
  EXPECT_TRUE(r.slipping);
  EXPECT_NEAR(r.force.norm(), 2.5, 1e-15);
  EXPECT_NEAR((r.force.normalized() - trial.normalized()).norm(), 0.0, 1e-15);
  // No compression: no friction force.
  const TangentialReturn off = coulomb_return_map(trial, -1.0, 0.3);
  EXPECT_EQ(off.force, Vec3::Zero());
  EXPECT_TRUE(off.slipping);
}

TEST(ExponentialCoulomb, StickSpringDragsTheStickingPointOnSlip) {
  const Real k = 100.0, n = 10.0, mu = 0.3;
  // Stick: 0.01 elastic slip -> 1.0 force < 3.0, history unchanged.
  const StickSpringUpdate s = stick_spring_update(Vec3(0.01, 0.0, 0.0), k, n, mu);
  EXPECT_FALSE(s.slipping);
  EXPECT_NEAR((s.force - Vec3(-1.0, 0.0, 0.0)).norm(), 0.0, 1e-15);
  EXPECT_EQ(s.elastic_displacement, Vec3(0.01, 0.0, 0.0));
  // Slip: 0.05 -> trial 5.0 > 3.0; the history shrinks to mu N / k along the same direction.
  const StickSpringUpdate p = stick_spring_update(Vec3(0.0, 0.0, 0.05), k, n, mu);
  EXPECT_TRUE(p.slipping);
  EXPECT_NEAR((p.force - Vec3(0.0, 0.0, -3.0)).norm(), 0.0, 1e-14);
  EXPECT_NEAR((p.elastic_displacement - Vec3(0.0, 0.0, 0.03)).norm(), 0.0, 1e-15);
  // Continuing to slide in the same direction from the returned state stays at the limit.
  const StickSpringUpdate q = stick_spring_update(p.elastic_displacement + Vec3(0, 0, 0.01), k, n, mu);
  EXPECT_TRUE(q.slipping);
  EXPECT_NEAR(q.force.norm(), 3.0, 1e-14);
  // Reversing unloads elastically (stick) before slipping the other way.
  const StickSpringUpdate back = stick_spring_update(p.elastic_displacement - Vec3(0, 0, 0.02), k, n, mu);
  EXPECT_FALSE(back.slipping);
  EXPECT_NEAR(back.force[2], -1.0, 1e-14);
}

TEST(ExponentialCoulomb, IncrementalTrialRotatesTheHistoryIntoTheTangentPlane) {
  const Vec3 n(0.0, 1.0, 0.0);
  // Previous force had a small normal component after the normal rotated: magnitude kept.
  const Vec3 prev(3.0, 0.4, 0.0);
  const Vec3 trial = tangential_trial_force(prev, n, 50.0, Vec3(0.0, 0.7, 0.02));
  EXPECT_NEAR(trial[1], 0.0, 1e-15);               // in the tangent plane
  EXPECT_NEAR(trial[0], prev.norm(), 1e-14);       // history magnitude kept
  EXPECT_NEAR(trial[2], -1.0, 1e-14);              // -k du_t; the normal part of du ignored
  EXPECT_EQ(rotate_into_plane(Vec3(0.0, 2.0, 0.0), n), Vec3::Zero());
}
