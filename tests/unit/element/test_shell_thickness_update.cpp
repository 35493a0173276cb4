// The shell thickness change of *CONTROL_SHELL ISTUPD (element/shell_block.hpp,
// shell_thickness.hpp; docs/solver.md, "Shell thickness change") and the strains the shell
// erosion criteria read, on one Belytschko-Tsay quadrilateral and one C0 triangle under a
// prescribed homogeneous in-plane stretch (stretches l1, l2 along two in-plane axes), flat and in a
// tilted copy. Closed forms (logarithmic strains e1 = ln l1, e2 = ln l2):
//  - elastic, plane stress: d eps_zz = -nu / (1 - nu) (d eps_xx + d eps_yy), so
//    t / t0 = exp(-nu / (1 - nu) (e1 + e2)) at every point and for the element;
//  - elastic-plastic (J2, plastic flow at constant volume): the volume changes only elastically,
//    ln(l1 l2 t / t0) = (1 - 2 nu) / E (sigma_xx + sigma_yy), so
//    t / t0 = exp((1 - 2 nu) / E (sigma_xx + sigma_yy) - e1 - e2); equibiaxial with ISTUPD = 4
//    (plastic part only) t / t0 = exp(-(eps_p,xx + eps_p,yy)) = exp(-eps_p), eps_p the effective
//    plastic strain (equibiaxial: eps_p,xx = eps_p,yy = eps_p / 2).
// The rates are taken on the mid-step geometry, so the integral of the rate matches the logarithm to
// O((d dt)^2) per unit strain.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "slideline/element/shell_block.hpp"
#include "slideline/material/j2_plasticity.hpp"
#include "slideline/material/shell_plasticity.hpp"
#include "test_support/block_eval.hpp"

using namespace slideline;

namespace {

constexpr Real kE = 1000.0, kNu = 0.3, kSy = 1.0, kEt = 10.0, kT = 0.05;
using PlasticShellBlock = BasicShellBlock<ShellPlasticity<J2Plasticity>>;

/// One element (a quadrilateral, or a triangle with N3 = N4) of law block `Block` in the plane of
/// `frame`'s first two columns, its nodes moved by hand.
template <class Block>
struct Element {
  NodalFields nodes;
  CornerBuffer corners;
  std::vector<Vec3> ref;  ///< reference positions (global)
  Mat3 frame;
  Block block;
  int corners_n;

  Element(Block b, const Mat3& f, bool triangle, int istupd, const ErosionCriteria* erosion = nullptr)
      : frame(f), block(std::move(b)), corners_n(triangle ? 3 : 4) {
    nodes.resize(corners_n);
    const Real xy[4][2] = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
    for (Index k = 0; k < corners_n; ++k) {
      ref.push_back(frame * Vec3(xy[k][0], xy[k][1], 0.0));
      nodes.ids[k] = k + 1;
      nodes.x0.set(k, ref.back());
      nodes.x.set(k, ref.back());
    }
    if (istupd != 0) block.enable_thickness_update(istupd);
    if (erosion) block.enable_erosion(*erosion);
    test_support::prepare(block, nodes, corners);
  }
  /// Stretch at the rates d1, d2 along the frame's first two axes (x = X + t (d1 (a.X) a + d2
  /// (b.X) b) over n steps of dt, with the chord velocities (the mid-step geometry is the chord's
  /// midpoint). Returns the stretches.
  std::pair<Real, Real> stretch(Real d1, Real d2, int n, Real dt) {
    const Vec3 a = frame.col(0), b = frame.col(1);
    for (int s = 1; s <= n; ++s) {
      for (Index k = 0; k < corners_n; ++k) {
        const Vec3& X = ref[static_cast<std::size_t>(k)];
        const Vec3 v = d1 * a.dot(X) * a + d2 * b.dot(X) * b;
        nodes.x.set(k, X + s * dt * v);
        nodes.v.set(k, v);
      }
      BlockEnergy e;
      block.compute_forces(nodes, dt, corners, e);
    }
    return {1.0 + d1 * n * dt, 1.0 + d2 * n * dt};
  }
};

template <class Block>
Block make_block(bool triangle, int nip = 5);

template <>
ShellBlock make_block<ShellBlock>(bool triangle, int nip) {
  return ShellBlock(1, ElasticShell(1e-3, kE, kNu), ShellSection{.thickness = kT, .nip = nip, .bulk = {}},
                    triangle ? std::vector<Index>{0, 1, 2, 2} : std::vector<Index>{0, 1, 2, 3}, {1});
}
template <>
PlasticShellBlock make_block<PlasticShellBlock>(bool triangle, int nip) {
  return PlasticShellBlock(1, ShellPlasticity<J2Plasticity>(J2Plasticity({1e-3, kE, kNu, kSy, kEt, 1.0, 0.0, 0.0})),
                           ShellSection{.thickness = kT, .nip = nip, .bulk = {}},
                           triangle ? std::vector<Index>{0, 1, 2, 2} : std::vector<Index>{0, 1, 2, 3}, {1});
}

const Mat3 kTilt = Eigen::AngleAxis<Real>(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();

}  // namespace

// Elastic, unequal stretches l1 = 1.02, l2 = 0.995, quadrilateral and triangle, flat and tilted:
// t / t0 = exp(-nu / (1 - nu) (ln l1 + ln l2)) to 1e-9 relative.
TEST(ShellThicknessUpdate, ElasticThicknessFollowsThePlaneStressNormalStrain) {
  for (bool triangle : {false, true})
    for (const Mat3& f : {Mat3(Mat3::Identity()), kTilt}) {
      Element<ShellBlock> el(make_block<ShellBlock>(triangle), f, triangle, 1);
      const auto [l1, l2] = el.stretch(0.2, -0.05, 1000, 1e-4);
      const Real expected = kT * std::exp(-kNu / (1.0 - kNu) * (std::log(l1) + std::log(l2)));
      const Real t = el.block.thickness(0);
      std::printf("%s %s: t = %.12g, closed form %.12g (rel %.2e)\n", triangle ? "triangle" : "quad",
                  f.isIdentity() ? "flat" : "tilted", t, expected, t / expected - 1.0);
      EXPECT_NEAR(t / expected, 1.0, 1e-9);
      EXPECT_EQ(el.block.current_thickness()[0], t);
    }
}

// Without ISTUPD the thickness is the section's, whatever the stretch (and nothing is tracked).
TEST(ShellThicknessUpdate, OffKeepsTheSectionThickness) {
  Element<ShellBlock> el(make_block<ShellBlock>(false), Mat3::Identity(), false, 0);
  el.stretch(0.2, 0.2, 200, 1e-4);
  EXPECT_EQ(el.block.thickness(0), kT);
  EXPECT_TRUE(el.block.current_thickness().empty());
}

// Elastic-plastic, equibiaxial stretch to ln(1.05) (~ 35 yield strains): ISTUPD = 1 gives
// t / t0 = exp((1 - 2 nu) / E 2 sigma - 2 ln l) (sigma the points' equibiaxial stress), ISTUPD = 4
// exp(-eps_p); flat and tilted, quadrilateral and triangle, to 1e-6 relative.
TEST(ShellThicknessUpdate, PlasticThicknessKeepsThePlasticVolume) {
  for (bool triangle : {false, true})
    for (const Mat3& f : {Mat3(Mat3::Identity()), kTilt})
      for (int mode : {1, 4}) {
        Element<PlasticShellBlock> el(make_block<PlasticShellBlock>(triangle), f, triangle, mode);
        const auto [l1, l2] = el.stretch(1.0, 1.0, 500, 1e-4);
        const auto s = el.block.stress(0, 2);
        std::vector<CellOutput> out(1);
        el.block.cell_outputs(el.nodes, out);
        const Real eps_p = out[0].plastic_strain;
        ASSERT_GT(eps_p, 0.03);
        const Real expected = mode == 1 ? kT * std::exp((1.0 - 2.0 * kNu) / kE * (s[0] + s[1]) - std::log(l1 * l2))
                                        : kT * std::exp(-eps_p);
        const Real t = el.block.thickness(0);
        std::printf("%s %s ISTUPD %d: t / t0 = %.10g, closed form %.10g (rel %.2e; exp(-eps_p) = %.6g)\n",
                    triangle ? "triangle" : "quad", f.isIdentity() ? "flat" : "tilted", mode, t / kT, expected / kT,
                    t / expected - 1.0, std::exp(-eps_p));
        EXPECT_NEAR(t / expected, 1.0, 1e-6);
      }
}

// The thinned section carries the stress: the membrane force per unit width is the points' stress
// times the current thickness. Elastic equibiaxial stretch l: sigma = E / (1 - nu) ln l, and the
// nodal force on a side of the square (current length l) is sigma l t, with t = t0 l^(-2 nu / (1 -
// nu)); read from the corner forces of two nodes of the side x = +l / 2.
TEST(ShellThicknessUpdate, MembraneForceFollowsTheCurrentThickness) {
  Element<ShellBlock> el(make_block<ShellBlock>(false), Mat3::Identity(), false, 1);
  const auto [l, l2] = el.stretch(0.2, 0.2, 1000, 1e-4);
  (void)l2;
  el.corners.gather(el.nodes.f_int, el.nodes.m_int);
  const Real sigma = kE / (1.0 - kNu) * std::log(l);
  const Real t = kT * std::pow(l, -2.0 * kNu / (1.0 - kNu));
  const Real fx = el.nodes.f_int.x[1] + el.nodes.f_int.x[2];  // nodes at x = +l/2
  std::printf("side force %.10g, closed form sigma l t %.10g (rel %.2e); with t0 %.10g\n", -fx, sigma * l * t,
              -fx / (sigma * l * t) - 1.0, sigma * l * kT);
  EXPECT_NEAR(-fx / (sigma * l * t), 1.0, 2e-4);  // the forces use the thickness at the step's start
}

// The strain a shell's erosion criteria read (ShellBlock::point_strain, with a strain criterion
// set): elastic stretches l1, l2 give xx = ln l1, yy = ln l2, zz = -nu / (1 - nu) (ln l1 + ln l2),
// no shear, at every point, in the element frame (flat and tilted alike).
TEST(ShellThicknessUpdate, PointStrainsAreTheLogarithmicStrains) {
  ErosionCriteria k;
  k.mxeps = {true, 10.0};
  for (const Mat3& f : {Mat3(Mat3::Identity()), kTilt}) {
    Element<ShellBlock> el(make_block<ShellBlock>(false), f, false, 0, &k);
    const auto [l1, l2] = el.stretch(0.2, -0.05, 1000, 1e-4);
    const Real e1 = std::log(l1), e2 = std::log(l2);
    for (int ip = 0; ip < 5; ++ip) {
      const auto e = el.block.point_strain(0, ip);
      EXPECT_NEAR(e[0], e1, 1e-9 * e1) << ip;
      EXPECT_NEAR(e[1], e2, 1e-8 * std::abs(e2)) << ip;
      EXPECT_NEAR(e[2], -kNu / (1.0 - kNu) * (e1 + e2), 1e-8 * e1) << ip;
      for (int c = 3; c < 6; ++c) EXPECT_NEAR(e[c], 0.0, 1e-12) << ip << " " << c;
    }
    EXPECT_EQ(el.block.thickness(0), kT);  // erosion alone does not change the thickness
  }
}
