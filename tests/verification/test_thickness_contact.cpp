// *CONTROL_CONTACT THKCHG = 1 (docs/contact.md, "Shell thickness change"): the offsets of an
// automatic card follow the shells' current thickness (*CONTROL_SHELL ISTUPD). Plate A (2 x 2, one
// shell of *MAT_PLASTIC_KINEMATIC, t0 = 0.1) is stretched equibiaxially by 20 % over [0, 1] by
// prescribed motion of its nodes, which thins it to t_A (perfectly plastic equibiaxial, the closed
// form of test_shell_thickness_update.cpp: t_A = t0 exp((1 - 2 nu) 2 SIGY / E) / 1.44); then plate B
// (1 x 1, elastic, t_B = 0.1, parallel at the distance 0.5, every node prescribed) moves towards it
// at v. Each pair is a node of B on A's
// segment (*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE, B the slave side), so contact begins when the
// mid-surface distance falls below (t_A + t_B) / 2 with THKCHG = 1, and below the first cycle's
// (t0 + t_B) / 2 with THKCHG = 0 (LS-DYNA's automatic cards); to the distance B moves in a step. The
// same in a copy turned about an oblique axis.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>
#include <string>

#include "slideline/element/element_block.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/solver/build.hpp"
#include "slideline/solver/simulation.hpp"

namespace slideline {
namespace {

constexpr Real kT1 = 1.0, kV = 0.5, kGap0 = 0.5;

std::string deck(int thkchg, const Mat3& r, Real end_time) {
  std::ostringstream o;
  o << std::setprecision(17) << "*KEYWORD\n*CONTROL_TERMINATION\n" << end_time << ",\n*CONTROL_SHELL\n0,0,0,1\n"
    << "*CONTROL_CONTACT\n0.1,0,1,0,1," << thkchg << "\n*SECTION_SHELL\n1,2,1.0,3\n0.1,0.1,0.1,0.1\n"
    << "*SECTION_SHELL\n2,2,1.0,3\n0.1,0.1,0.1,0.1\n*MAT_PLASTIC_KINEMATIC\n1,1e-2,1e4,0.3,10.0,0.0,1.0\n"
    << "*MAT_ELASTIC\n2,1e-2,1e4,0.3\n*PART\nplate A\n1,1,1\n*PART\nplate B\n2,2,2\n*NODE\n";
  const Real a[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (int k = 0; k < 8; ++k) {
    const Real s = k < 4 ? 1.0 : 0.5;
    const Vec3 x = r * Vec3(s * a[k % 4][0], s * a[k % 4][1], k < 4 ? 0.0 : kGap0);
    o << k + 1 << "," << x.x() << "," << x.y() << "," << x.z() << "\n";
  }
  o << "*ELEMENT_SHELL\n1,1,1,2,3,4\n2,2,5,6,7,8\n";
  for (int k = 1; k <= 8; ++k) o << "*BOUNDARY_SPC_NODE\n" << k << ",0,0,0,0,1,1,1\n";
  o << "*BOUNDARY_PRESCRIBED_MOTION_NODE\n";
  for (int k = 0; k < 8; ++k) {
    // A: x = X (1 + 0.2 c1(t)) in its plane; B: moved by c2(t) along -normal.
    const Vec3 d = k < 4 ? Vec3(r * Vec3(a[k][0], a[k][1], 0.0)) : Vec3(r * Vec3(0.0, 0.0, -1.0));
    // A zero component is held by the zero curve 3 (SF = 0 would read as its default, 1).
    for (int c = 0; c < 3; ++c)
      o << k + 1 << "," << c + 1 << ",2," << (d[c] == 0.0 ? 3 : k < 4 ? 1 : 2) << "," << (d[c] == 0.0 ? 1.0 : d[c])
        << "\n";
  }
  o << "*DEFINE_CURVE\n1\n0,0\n" << kT1 << ",0.2\n100,0.2\n*DEFINE_CURVE\n2\n0,0\n" << kT1 << ",0\n100,"
    << kV * (100.0 - kT1) << "\n*DEFINE_CURVE\n3\n0,0\n100,0\n*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE\n2,1,3,3\n*END\n";
  return o.str();
}

struct Touch {
  Real distance = -1.0, step = 0.0, thickness_a = 0.0;
};

/// The mid-surface distance of B from A when the interface first carries a force, the distance B
/// moves in that step, and A's thickness then.
Touch first_touch(int thkchg, const Mat3& r) {
  const Real end = kT1 + (kGap0 - 0.06) / kV;
  auto sim = build_simulation(read_keyword_string(deck(thkchg, r, end), "thk.k"));
  Real t_prev = 0.0;
  Touch out;
  while (sim->step()) {
    const Real t = sim->time();
    if (sim->contacts()[0].slave_force().norm() > 0.0) {
      out.distance = kGap0 - kV * (t - kT1);
      out.step = kV * (t - t_prev);
      const auto th = sim->blocks().at(0)->current_thickness();
      out.thickness_a = th.empty() ? -1.0 : th[0];
      break;
    }
    t_prev = t;
  }
  return out;
}

}  // namespace

TEST(ThicknessContact, OffsetFollowsTheCurrentThickness) {
  const Mat3 tilt = Eigen::AngleAxis<Real>(0.6, Vec3(1, -2, 3).normalized()).toRotationMatrix();
  for (const Mat3& r : {Mat3(Mat3::Identity()), tilt})
    for (int thkchg : {1, 0}) {
      const Touch c = first_touch(thkchg, r);
      const Real t_a = c.thickness_a, expected = 0.5 * ((thkchg == 1 ? t_a : 0.1) + 0.1);
      std::printf("%s THKCHG %d: t_A %.6f (t0 / 1.44 = %.6f); contact at distance %.6f, closed form %.6f (%.2f of a "
                  "step of %.2e)\n",
                  r.isIdentity() ? "flat" : "tilted", thkchg, t_a, 0.1 / 1.44, c.distance, expected,
                  (expected - c.distance) / c.step, c.step);
      ASSERT_GT(c.distance, 0.0);
      // Perfectly plastic equibiaxial (sigma = SIGY = 10): ln(1.44 t_A / t0) = (1 - 2 nu) 2 SIGY / E.
      EXPECT_NEAR(t_a / (0.1 * std::exp(0.4 * 20.0 / 1e4) / 1.44), 1.0, 1e-5);
      EXPECT_LE(c.distance, expected + 1e-12);
      EXPECT_GT(c.distance, expected - c.step - 1e-12);
    }
}

}  // namespace slideline
