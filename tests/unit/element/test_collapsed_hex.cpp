// Pentahedra and pyramids run as hexahedra with collapsed nodes (LS-DYNA's ELFORM 1 and 2 for
// *ELEMENT_SOLID N1 N2 N3 N4 N5 N5 N6 N6 and N1 N2 N3 N4 N5 N5 N5 N5): the patch test on a
// distorted mesh of hexahedra, pentahedra and pyramids, hourglass forces that vanish on linear
// fields, and the element's highest frequency against the step the block reports.
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <string>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "slideline/element/full_hex_block.hpp"
#include "slideline/element/hex_block.hpp"
#include "slideline/material/elastic.hpp"
#include "test_support/block_eval.hpp"
#include "test_support/collapsed_hex.hpp"
#include "test_support/patch_mesh.hpp"

using namespace slideline;

namespace {

using test_support::PatchMesh;
using HK = HexHourglass::Kind;

/// The distorted 2x2x2 patch (test_support::make_patch_mesh) with the column of cells i = j = 0
/// cut into pentahedra (two per cell, the shared face z = 0.5 cut the same way in both) and the
/// cell i = j = k = 1 cut into six pyramids about a new node 27 near its centre. Faces between a
/// hexahedron and a pentahedron or pyramid are whole (bilinear) faces of the cell, so the mesh is
/// conforming.
PatchMesh make_mixed_patch() {
  const PatchMesh hexes = test_support::make_patch_mesh();
  PatchMesh p;
  p.nodes.resize(28);
  for (Index i = 0; i < 27; ++i) {
    p.nodes.ids[i] = hexes.nodes.ids[i];
    p.nodes.x0.set(i, hexes.nodes.x0.get(i));
  }
  p.interior = hexes.interior;
  std::array<Index, 8> cell7;
  for (int k = 0; k < 8; ++k) cell7[k] = hexes.conn[56 + k];
  Vec3 centre = Vec3::Zero();
  for (Index n : cell7) centre += hexes.nodes.x0.get(n) / 8.0;
  p.nodes.ids[27] = 28;
  p.nodes.x0.set(27, centre + Vec3(0.03, -0.02, 0.04));
  p.interior.push_back(27);
  p.nodes.x = p.nodes.x0;
  auto add = [&](const std::array<Index, 8>& c) {
    p.conn.insert(p.conn.end(), c.begin(), c.end());
    p.ids.push_back(static_cast<Id>(p.ids.size() + 1));
  };
  for (int e = 0; e < 8; ++e) {
    std::array<Index, 8> c;
    for (int k = 0; k < 8; ++k) c[k] = hexes.conn[8 * e + k];
    if (e == 0 || e == 4)
      for (const auto& w : test_support::split_into_pentahedra(c)) add(w);
    else if (e == 7)
      for (const auto& y : test_support::split_into_pyramids(c, Index{27})) add(y);
    else
      add(c);
  }
  return p;
}

/// The block kinds under test: the one-point hexahedron with each hourglass form, and ELFORM 2.
struct Form {
  const char* name;
  bool full;
  HK kind;
};
constexpr Form kForms[] = {{"viscous", false, HK::viscous},
                           {"physical_stiffness", false, HK::physical_stiffness},
                           {"fb_stiffness", false, HK::fb_stiffness},
                           {"assumed_strain", false, HK::assumed_strain},
                           {"elform2", true, HK::viscous}};

std::unique_ptr<ElementBlock> make_block(const Form& f, const PatchMesh& p, const ElasticSolid& mat, Real qm,
                                         BulkViscosity bv = {0.0, 0.0}) {
  if (f.full) return std::make_unique<FullHexBlock<ElasticSolid>>(1, mat, bv, p.conn, p.ids);
  return std::make_unique<HexBlock<ElasticSolid>>(1, mat, HexHourglass{f.kind, qm}, bv, p.conn, p.ids);
}

Real max_force(const NodalFields& n) {
  Real f = 0.0;
  for (Index i = 0; i < static_cast<Index>(n.size()); ++i) f = std::max(f, n.f_int.get(i).norm());
  return f;
}

}  // namespace

class CollapsedHexPatch : public ::testing::TestWithParam<Form> {};

// Every element's gradient operator B_I = (1/V) dV/dx_I satisfies sum_I x_I (x) B_I = identity
// for any eight points, coincident ones included (V scales by det A under x -> A x), so a
// collapsed hexahedron is exact for linear fields: uniform strain gives every element the same
// stress, the interior nodes (the centre, shared by all three kinds, and the pyramids' apex)
// stay in equilibrium, and a face carries the traction sigma n times its area.
TEST_P(CollapsedHexPatch, ConstantStrainOnDistortedMixedMesh) {
  PatchMesh p = make_mixed_patch();
  ASSERT_EQ(p.ids.size(), 5u + 4u + 6u);  // hexahedra, pentahedra, pyramids
  const ElasticSolid mat(1.0, 1000.0, 0.3);
  auto block = make_block(GetParam(), p, mat, 0.1);
  CornerBuffer corners;
  test_support::prepare(*block, p.nodes, corners);
  Mat3 F;
  F << 1.02, 0.01, -0.005, 0.003, 0.985, 0.01, 0.0, 0.004, 1.01;
  for (Index i = 0; i < 28; ++i) p.nodes.x.set(i, F * p.nodes.x0.get(i));
  test_support::evaluate(*block, p.nodes, corners);
  for (int n : p.interior) EXPECT_LT(p.nodes.f_int.get(n).norm(), 1e-10) << "node " << n;
  const Mat3 sigma = mat.cauchy_stress(F);
  std::vector<CellOutput> out(p.ids.size());
  block->cell_outputs(p.nodes, out);
  const SymTensor6 exact{sigma(0, 0), sigma(1, 1), sigma(2, 2), sigma(0, 1), sigma(1, 2), sigma(0, 2)};
  for (const CellOutput& c : out)
    for (int k = 0; k < 6; ++k) EXPECT_NEAR(c.stress[k], exact[k], 1e-10);
  Vec3 face = Vec3::Zero();
  for (Index i = 0; i < 28; ++i)
    if (std::abs(p.nodes.x0.x[i] - 1.0) < 1e-12) face += p.nodes.f_int.get(i);
  const Vec3 expected = -(sigma * (F.determinant() * F.inverse().transpose() * Vec3(1, 0, 0)));
  EXPECT_LT((face - expected).norm(), 1e-10 * expected.norm());
  Real mass = 0.0;  // rho V / 8 per corner: the collapsed corners add up to the element's mass
  for (Real m : p.nodes.mass) mass += m;
  EXPECT_NEAR(mass, 1.0, 1e-14);
}

INSTANTIATE_TEST_SUITE_P(EveryHexForm, CollapsedHexPatch, ::testing::ValuesIn(kForms),
                         [](const auto& info) { return std::string(info.param.name); });

class CollapsedHexHourglass : public ::testing::TestWithParam<Form> {};

// Hourglass forces vanish on rigid motion and on linear velocity fields (gamma_a . x_i = 0 for
// the hourglass shape vectors, collapsed corners included): the forces equal those of the same
// block without hourglass control, to round-off. The mesh is turned rigidly (the stiffness forms
// see the displacement (R - I) X + t, a linear field) and moves with v = L x.
TEST_P(CollapsedHexHourglass, ForcesVanishOnLinearFields) {
  PatchMesh p = make_mixed_patch();
  const ElasticSolid mat(1.0, 1000.0, 0.3);
  auto with = make_block(GetParam(), p, mat, 1.0), without = make_block(GetParam(), p, mat, 0.0);
  CornerBuffer cw, co;
  test_support::prepare(*with, p.nodes, cw);
  test_support::prepare(*without, p.nodes, co);
  const Mat3 R = Eigen::AngleAxis<Real>(1.1, Vec3(1, 2, -0.5).normalized()).toRotationMatrix();
  Mat3 L;
  L << 0.3, -0.2, 0.1, 0.05, -0.4, 0.2, 0.1, 0.0, 0.25;
  for (Index i = 0; i < 28; ++i) {
    p.nodes.x.set(i, R * p.nodes.x0.get(i) + Vec3(3.0, -2.0, 1.0));
    p.nodes.v.set(i, L * p.nodes.x.get(i));
  }
  BlockEnergy e1, e2;
  with->compute_forces(p.nodes, 1e-3, cw, e1);
  with->compute_forces(p.nodes, 1e-3, cw, e1);  // the stiffness forms accumulate: twice
  cw.gather(p.nodes.f_int, p.nodes.m_int);
  const NodalFields a = p.nodes;
  without->compute_forces(p.nodes, 1e-3, co, e2);
  without->compute_forces(p.nodes, 1e-3, co, e2);
  co.gather(p.nodes.f_int, p.nodes.m_int);
  Real diff = 0.0;
  for (Index i = 0; i < 28; ++i) diff = std::max(diff, (a.f_int.get(i) - p.nodes.f_int.get(i)).norm());
  EXPECT_LT(diff, 1e-10 * std::max(1.0, max_force(p.nodes))) << "forces " << max_force(p.nodes);
}

INSTANTIATE_TEST_SUITE_P(OnePointForms, CollapsedHexHourglass, ::testing::ValuesIn(kForms, kForms + 4),
                         [](const auto& info) { return std::string(info.param.name); });

namespace {

/// The free element's highest circular frequency (1/time: the stiffness K by central
/// differences of the block's forces, the block's lumped masses M, omega^2 the largest
/// eigenvalue of M^-1/2 K M^-1/2), the step the block reports (len / c at rest), and the number
/// of zero-energy modes (eigenvalues of K below 1e-9 E h).
struct Frequency {
  Real omega_max = 0.0, dt_block = 0.0;
  int zero_modes = 0;
};

Frequency element_frequency(const std::vector<Vec3>& X, const std::array<Index, 8>& c, const ElasticSolid& mat,
                            Real qm, const Form& form = kForms[1]) {
  const Index n = static_cast<Index>(X.size());
  PatchMesh p;
  p.nodes.resize(n);
  for (Index i = 0; i < n; ++i) {
    p.nodes.ids[i] = i + 1;
    p.nodes.x0.set(i, X[static_cast<std::size_t>(i)]);
  }
  p.nodes.x = p.nodes.x0;
  p.conn.assign(c.begin(), c.end());
  p.ids = {1};
  const std::unique_ptr<ElementBlock> owned = make_block(form, p, mat, qm);
  ElementBlock& block = *owned;
  CornerBuffer corners;
  test_support::prepare(block, p.nodes, corners);
  Frequency out;
  out.dt_block = test_support::evaluate(block, p.nodes, corners);
  const int dofs = 3 * static_cast<int>(n);
  Eigen::MatrixXd K(dofs, dofs);
  const Real h = 1e-7;
  for (int j = 0; j < dofs; ++j) {
    Eigen::VectorXd fp(dofs), fm(dofs);
    for (const Real s : {h, -h}) {
      p.nodes.x = p.nodes.x0;
      Vec3 xi = p.nodes.x.get(j / 3);
      xi[j % 3] += s;
      p.nodes.x.set(j / 3, xi);
      test_support::evaluate(block, p.nodes, corners);
      Eigen::VectorXd& f = s > 0 ? fp : fm;
      for (Index i = 0; i < n; ++i) f.segment<3>(3 * i) = p.nodes.f_int.get(i);
    }
    K.col(j) = -(fp - fm) / (2.0 * h);
  }
  K = 0.5 * (K + K.transpose()).eval();
  Eigen::VectorXd d(dofs);
  for (int j = 0; j < dofs; ++j) d[j] = 1.0 / std::sqrt(p.nodes.mass[static_cast<std::size_t>(j / 3)]);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> modes(d.asDiagonal() * K * d.asDiagonal());
  out.omega_max = std::sqrt(modes.eigenvalues().maxCoeff());
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> stiff(K);
  for (int j = 0; j < dofs; ++j) out.zero_modes += std::abs(stiff.eigenvalues()[j]) < 1e-9 * mat.youngs_modulus();
  return out;
}

}  // namespace

// The step of a collapsed hexahedron: len = V / (largest face area), the collapsed face counting
// zero. Central differences are stable for dt <= 2 / omega_max. Measured on the free unit cube,
// its first pentahedron (a right prism of legs 1) and its pyramid on the face z = 0 with the apex
// at the centre (nu = 0.3; ELFORM 1 with the physical stiffness hourglass control at QM 0.1 and 1,
// and ELFORM 2): the free cube's step is 1.36 x its critical step (docs/solver.md, "Time-step
// margin of isolated elements": 0.73 is the limit of TSSFAC for it), the pentahedron's 0.64 and
// the pyramid's 0.38, in every form. The collapsed elements are stable at TSSFAC 1 on their own;
// that is asserted, and that their margin is no worse than the hexahedron's. Each has only the
// six rigid modes free (the hourglass stiffness holds the pentahedron's 6 and the pyramid's 3
// non-linear modes too; ELFORM 2 has none).
TEST(CollapsedHexStep, BlockStepIsBelowTheCriticalStepOfTheElement) {
  const ElasticSolid mat(1.0, 1000.0, 0.3);
  std::vector<Vec3> cube;
  for (int k = 0; k < 8; ++k) cube.emplace_back(((k + 1) >> 1) & 1, (k >> 1) & 1, k >> 2);
  const std::array<Index, 8> hex{0, 1, 2, 3, 4, 5, 6, 7};
  // The first pentahedron uses nodes 0 1 2 4 5 6 of the cube; renumbered 0..5.
  const std::array<Index, 8> cut = test_support::split_into_pentahedra(hex)[0];
  const std::vector<Vec3> prism{cube[0], cube[1], cube[2], cube[4], cube[5], cube[6]};
  const std::array<Index, 8> penta{1, 0, 3, 4, 2, 2, 5, 5};
  ASSERT_EQ(cut, (std::array<Index, 8>{1, 0, 4, 5, 2, 2, 6, 6}));
  std::vector<Vec3> pyr(cube.begin(), cube.begin() + 4);
  pyr.emplace_back(0.5, 0.5, 0.5);
  const std::array<Index, 8> pyramid = test_support::split_into_pyramids(std::array<Index, 8>{0, 1, 2, 3, 4, 5, 6, 7},
                                                                         Index{4})[0];
  // QM 0.1 and 1 with the physical stiffness form; ELFORM 2 (no hourglass control, QM unused).
  for (const auto& [qm, form] : {std::pair{0.1, kForms[1]}, std::pair{1.0, kForms[1]}, std::pair{0.0, kForms[4]}}) {
    const Frequency fh = element_frequency(cube, hex, mat, qm, form);
    const Frequency fw = element_frequency(prism, penta, mat, qm, form);
    const Frequency fp = element_frequency(pyr, pyramid, mat, qm, form);
    const std::pair<const char*, Frequency> shapes[] = {{"hexahedron", fh}, {"pentahedron", fw}, {"pyramid", fp}};
    for (const auto& [name, f] : shapes) {
      const Real ratio = f.dt_block * f.omega_max / 2.0;
      std::printf("%-18s QM %.1f %-11s omega_max %.5g  step %.5g  step/critical %.3f  zero modes %d\n", form.name, qm,
                  name, f.omega_max, f.dt_block, ratio, f.zero_modes);
      EXPECT_EQ(f.zero_modes, 6) << form.name << " " << name << " QM " << qm;
      if (&f == &shapes[0].second) continue;
      EXPECT_LE(ratio, 1.0) << form.name << " " << name << " QM " << qm;
      EXPECT_LE(ratio, fh.dt_block * fh.omega_max / 2.0) << form.name << " " << name << " QM " << qm;
    }
  }
}
