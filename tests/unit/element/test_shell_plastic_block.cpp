// A Belytschko-Tsay shell of J2 plasticity (element/shell_block.hpp with
// material/shell_plasticity.hpp) under a prescribed homogeneous motion: equibiaxial stretch in the
// x-y plane and in a tilted copy of it (the same local stresses and plastic strain, against the
// closed form at every through-thickness point), then a rigid rotation that leaves them unchanged.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "slideline/element/shell_block.hpp"
#include "slideline/material/j2_plasticity.hpp"
#include "slideline/material/shell_plasticity.hpp"
#include "test_support/block_eval.hpp"

using namespace slideline;

namespace {

constexpr Real kE = 1000.0, kNu = 0.3, kSy = 1.0, kEt = 10.0;
using PlasticShellBlock = BasicShellBlock<ShellPlasticity<J2Plasticity>>;

struct Plate {
  NodalFields nodes;
  CornerBuffer corners;
  std::vector<Vec3> ref;  ///< reference positions relative to the centre (global)
  PlasticShellBlock block;

  explicit Plate(const Mat3& frame)
      : block(1, ShellPlasticity<J2Plasticity>(J2Plasticity({1e-3, kE, kNu, kSy, kEt, 1.0, 0.0, 0.0})),
              ShellSection{.thickness = 0.05, .bulk = {}}, {0, 1, 2, 3}, {1}) {
    nodes.resize(4);
    const Real xy[4][2] = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
    for (Index k = 0; k < 4; ++k) {
      ref.push_back(frame * Vec3(xy[k][0], xy[k][1], 0.0));
      nodes.ids[k] = k + 1;
      nodes.x0.set(k, ref.back());
      nodes.x.set(k, ref.back());
    }
    test_support::prepare(block, nodes, corners);
  }
  /// Moves the nodes to `x` with the velocities `v` (x - x_prev = dt v) and advances the block.
  void step(const std::vector<Vec3>& x, const std::vector<Vec3>& v, Real dt) {
    for (Index k = 0; k < 4; ++k) {
      nodes.x.set(k, x[k]);
      nodes.v.set(k, v[k]);
    }
    BlockEnergy e;
    block.compute_forces(nodes, dt, corners, e);
  }
  /// Equibiaxial stretch at the rate d (x = (1 + d t) X) over n steps of dt.
  void stretch(Real d, int n, Real dt) {
    std::vector<Vec3> x(4), v(4);
    for (int s = 1; s <= n; ++s) {
      for (Index k = 0; k < 4; ++k) {
        x[k] = (1.0 + d * s * dt) * ref[k];
        v[k] = d * ref[k];
      }
      step(x, v, dt);
    }
    for (Index k = 0; k < 4; ++k) ref[k] = x[k];
  }
  /// A rigid rotation about `axis` through the centre by `angle`, in n steps.
  void rotate(const Vec3& axis, Real angle, int n) {
    const Real dt = 1e-3, w = angle / (n * dt);
    std::vector<Vec3> x(4), v(4);
    // The chords' rotation rate about the mid-step geometry (Cayley: 2 tan(w dt / 2) / dt), so that
    // the nodal rotations turn with the chords and the transverse shear rate vanishes.
    const Real w_chord = 2.0 * std::tan(0.5 * w * dt) / dt;
    for (Index k = 0; k < 4; ++k) nodes.omega.set(k, w_chord * axis);
    for (int s = 1; s <= n; ++s) {
      // Chord velocities: x^s - x^{s-1} = dt v, so the mid-step geometry is the chord's midpoint.
      const Mat3 r1 = Eigen::AngleAxis<Real>(w * s * dt, axis).toRotationMatrix();
      const Mat3 r0 = Eigen::AngleAxis<Real>(w * (s - 1) * dt, axis).toRotationMatrix();
      for (Index k = 0; k < 4; ++k) {
        x[k] = r1 * ref[k];
        v[k] = (r1 * ref[k] - r0 * ref[k]) / dt;
      }
      step(x, v, dt);
    }
    for (Index k = 0; k < 4; ++k) nodes.omega.set(k, Vec3::Zero());
  }
};

/// Equibiaxial plane stress with isotropic bilinear hardening at the logarithmic strain eps.
Real equibiaxial(Real eps) {
  const Real ep = kE * kEt / (kE - kEt), el = kE / (1.0 - kNu) * eps;
  return el <= kSy ? el : (eps + kSy / (2.0 * ep)) / ((1.0 - kNu) / kE + 1.0 / (2.0 * ep));
}

}  // namespace

TEST(ShellPlasticBlock, EquibiaxialStretchClosedFormInAnyFrame) {
  const Real d = 0.1, dt = 1e-4;
  const int n = 500;  // to the logarithmic strain ln(1.005), ~7 times the yield strain
  const Real ref = equibiaxial(std::log1p(d * n * dt));
  const Mat3 tilt = Eigen::AngleAxis<Real>(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  Plate flat(Mat3::Identity()), tilted(tilt);
  flat.stretch(d, n, dt);
  tilted.stretch(d, n, dt);
  for (int ip = 0; ip < 5; ++ip) {
    const auto s = flat.block.stress(0, ip), st = tilted.block.stress(0, ip);
    EXPECT_NEAR(s[0] / ref, 1.0, 1e-5) << "point " << ip;  // the midpoint-rule rate: O((d dt)^2)
    EXPECT_NEAR(s[1] / ref, 1.0, 1e-5);
    EXPECT_NEAR(s[2], 0.0, 1e-12);
    for (int c = 0; c < 5; ++c) EXPECT_NEAR(st[c], s[c], 1e-10) << "component " << c;
  }
  std::vector<CellOutput> a(1), b(1);
  flat.block.cell_outputs(flat.nodes, a);
  tilted.block.cell_outputs(tilted.nodes, b);
  EXPECT_GT(a[0].plastic_strain, 0.005);
  EXPECT_NEAR(b[0].plastic_strain, a[0].plastic_strain, 1e-12);
  EXPECT_NEAR(b[0].energy_density, a[0].energy_density, 1e-10);
  EXPECT_GT(a[0].energy_density, kSy * a[0].plastic_strain);  // elastic energy plus plastic work
  // The history channels' totals (ElementBlock::plasticity_totals). Equibiaxial: sigma_vm = sigma,
  // so eps_p = (sigma - sigma_y) / Ep at every point, and the plastic work is the area under
  // sigma_vm(eps_p), sigma_y eps_p + Ep eps_p^2 / 2, times the current volume 1.005^2 x t.
  const Real ep = kE * kEt / (kE - kEt), eps_p = (ref - kSy) / ep;
  for (const Plate* plate : {&flat, &tilted}) {
    ASSERT_TRUE(plate->block.has_plasticity());
    const PlasticityTotals t = plate->block.plasticity_totals(plate->nodes);
    EXPECT_EQ(t.max_plastic_strain, plate == &flat ? a[0].plastic_strain : b[0].plastic_strain);
    EXPECT_NEAR(t.max_plastic_strain, eps_p, 1e-4 * eps_p);
    const Real volume = 1.005 * 1.005 * 0.05;
    EXPECT_NEAR(t.plastic_work, volume * (kSy * eps_p + 0.5 * ep * eps_p * eps_p), 1e-3 * volume * kSy * eps_p);
  }
}

TEST(ShellPlasticBlock, RigidRotationKeepsTheLocalStressAndPlasticStrain) {
  Plate p(Mat3::Identity());
  p.stretch(0.1, 300, 1e-4);
  const auto before = p.block.stress(0, 4);
  std::vector<CellOutput> a(1), b(1);
  p.block.cell_outputs(p.nodes, a);
  p.rotate(Vec3(1.0, -0.5, 0.3).normalized(), 1.2, 200);
  p.block.cell_outputs(p.nodes, b);
  const auto after = p.block.stress(0, 4);
  for (int c = 0; c < 5; ++c) EXPECT_NEAR(after[c], before[c], 1e-9 * std::abs(before[0])) << c;
  EXPECT_NEAR(b[0].plastic_strain, a[0].plastic_strain, 1e-12);
  // The global stress turned with the element: its von Mises value is unchanged.
  EXPECT_NEAR(von_mises(b[0].stress), von_mises(a[0].stress), 1e-9);
}
