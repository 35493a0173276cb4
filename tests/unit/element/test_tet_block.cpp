// The one-point tetrahedron (TetBlock, *SECTION_SOLID ELFORM 10): rigid motion, the constant-strain
// patch test on a distorted mesh, lumped mass, the stable step rule, and the same laws as the
// hexahedron (a J2 law gives the hexahedron's stress under the same homogeneous history).
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "slideline/element/hex_block.hpp"
#include "slideline/element/tet_block.hpp"
#include "slideline/material/elastic.hpp"
#include "slideline/material/j2_plasticity.hpp"
#include "slideline/material/mooney_rivlin.hpp"
#include "test_support/block_eval.hpp"
#include "test_support/patch_mesh.hpp"

using namespace slideline;

namespace {

/// The distorted patch as 48 tetrahedra (no two alike).
struct TetPatch {
  NodalFields nodes;
  std::vector<Index> conn;
  std::vector<Id> ids;
  Index centre = 0;
};

TetPatch make_tet_patch() {
  test_support::PatchMesh hex = test_support::make_patch_mesh();
  TetPatch p{hex.nodes, test_support::patch_tets(), {}, hex.interior.front()};
  for (std::size_t e = 0; e < p.conn.size() / 4; ++e) p.ids.push_back(static_cast<Id>(e + 1));
  return p;
}

template <class Mat>
TetBlock<Mat> make_block(const TetPatch& p, Mat mat) {
  return TetBlock<Mat>(1, mat, BulkViscosity{}, p.conn, p.ids);
}

}  // namespace

TEST(TetBlock, RigidMotionGivesZeroInternalForce) {
  TetPatch p = make_tet_patch();
  auto block = make_block(p, MooneyRivlin(0.01, 909.091, 0.0, 0.1));
  CornerBuffer corners;
  test_support::prepare(block, p.nodes, corners);
  const Mat3 R = Eigen::AngleAxis<Real>(1.1, Vec3(1, 2, -0.5).normalized()).toRotationMatrix();
  const Vec3 w(0.3, -1.2, 0.7), v0(2.0, -1.0, 0.5);
  for (Index i = 0; i < 27; ++i) {
    const Vec3 x = R * p.nodes.x0.get(i) + Vec3(3.0, -2.0, 1.0);
    p.nodes.x.set(i, x);
    p.nodes.v.set(i, v0 + w.cross(x));
  }
  test_support::evaluate(block, p.nodes, corners);
  for (Index i = 0; i < 27; ++i) EXPECT_LT(p.nodes.f_int.get(i).norm(), 1e-10) << "node " << i;
}

TEST(TetBlock, ConstantStrainOnDistortedMeshGivesUniformStressAndInteriorEquilibrium) {
  TetPatch p = make_tet_patch();
  const ElasticSolid mat(1.0, 1000.0, 0.3);
  auto block = make_block(p, mat);
  CornerBuffer corners;
  test_support::prepare(block, p.nodes, corners);
  Mat3 F;
  F << 1.02, 0.01, -0.005, 0.003, 0.985, 0.01, 0.0, 0.004, 1.01;
  for (Index i = 0; i < 27; ++i) p.nodes.x.set(i, F * p.nodes.x0.get(i));
  test_support::evaluate(block, p.nodes, corners);
  // The centre node is shared by 24 tetrahedra of different shapes: its force vanishes only if
  // each of them has the exact homogeneous stress.
  EXPECT_LT(p.nodes.f_int.get(p.centre).norm(), 1e-12);
  const Mat3 sigma = mat.cauchy_stress(F);
  std::vector<CellOutput> out(p.ids.size());
  block.cell_outputs(p.nodes, out);
  for (const CellOutput& c : out) {
    EXPECT_NEAR(c.stress[0], sigma(0, 0), 1e-11 * sigma.norm());
    EXPECT_NEAR(c.stress[3], sigma(0, 1), 1e-11 * sigma.norm());
  }
  // The x = 1 face carries the traction sigma . n on its deformed area (Nanson).
  Vec3 face = Vec3::Zero();
  for (Index i = 0; i < 27; ++i)
    if (std::abs(p.nodes.x0.x[i] - 1.0) < 1e-12) face += p.nodes.f_int.get(i);
  const Vec3 expected = -(sigma * (F.determinant() * F.inverse().transpose() * Vec3(1, 0, 0)));
  EXPECT_LT((face - expected).norm(), 1e-12 * expected.norm());
}

// Uniaxial stress of the St. Venant-Kirchhoff law: stretch l along x, lateral stretch m with
// E22 = -nu E11 (Green strains), so S22 = 0 and S11 = E E11. The x = 1 face carries the force
// sigma11 m^2 = l S11 = l E (l^2 - 1) / 2 along x, and no node a force across x.
TEST(TetBlock, UniaxialStressMatchesTheClosedForm) {
  TetPatch p = make_tet_patch();
  const Real e = 1000.0, nu = 0.3, l = 1.05;
  const Real e11 = 0.5 * (l * l - 1.0), m = std::sqrt(1.0 - 2.0 * nu * e11);
  auto block = make_block(p, ElasticSolid(1.0, e, nu));
  CornerBuffer corners;
  test_support::prepare(block, p.nodes, corners);
  for (Index i = 0; i < 27; ++i) p.nodes.x.set(i, p.nodes.x0.get(i).cwiseProduct(Vec3(l, m, m)));
  test_support::evaluate(block, p.nodes, corners);
  const Real expected = l * e * e11;
  Vec3 fx = Vec3::Zero();
  for (Index i = 0; i < 27; ++i) {
    if (std::abs(p.nodes.x0.x[i] - 1.0) < 1e-12) fx += p.nodes.f_int.get(i);
    // sigma22 = sigma33 = 0 and no shear: every nodal force is along x.
    EXPECT_LT(p.nodes.f_int.get(i).tail<2>().norm(), 1e-12 * expected) << "node " << i;
  }
  EXPECT_NEAR(-fx[0], expected, 1e-12 * expected);  // residual form: the element pulls the face in
}

TEST(TetBlock, LumpedMassAddsUpToTheBodysMass) {
  TetPatch p = make_tet_patch();
  auto block = make_block(p, ElasticSolid(2.5, 1000.0, 0.3));
  CornerBuffer corners;
  test_support::prepare(block, p.nodes, corners);
  Real total = 0.0;
  for (Index i = 0; i < 27; ++i) total += p.nodes.mass[i];
  EXPECT_NEAR(total, 2.5 * 1.0, 1e-13);  // the distortion moves nodes inside the cube's faces
}

TEST(TetBlock, StableStepIsTheMinimumAltitudeOverTheWaveSpeed) {
  // The corner tetrahedron 0 (0,0,0) (1,0,0) (0,1,0) (0,0,1) scaled by h: V = h^3 / 6, largest face
  // the slanted one, sqrt(3) h^2 / 2: altitude 3 V / A = h / sqrt(3).
  const Real h = 0.2;
  NodalFields nodes;
  nodes.resize(4);
  const Vec3 x[4] = {Vec3(0, 0, 0), Vec3(h, 0, 0), Vec3(0, h, 0), Vec3(0, 0, h)};
  for (Index i = 0; i < 4; ++i) {
    nodes.ids[i] = i + 1;
    nodes.x0.set(i, x[i]);
    nodes.x.set(i, x[i]);
  }
  const ElasticSolid mat(1.0, 1000.0, 0.25);
  TetBlock<ElasticSolid> block(1, mat, BulkViscosity{}, {0, 1, 2, 3}, {7});
  CornerBuffer corners;
  test_support::prepare(block, nodes, corners);
  const Real dt = test_support::evaluate(block, nodes, corners);
  EXPECT_NEAR(dt, h / std::sqrt(3.0) / mat.wave_speed(), 1e-14);
  EXPECT_EQ(block.smallest_step_element(), 7);
  for (Index i = 0; i < 4; ++i) EXPECT_NEAR(nodes.mass[i], h * h * h / 24.0, 1e-16);
}

TEST(TetBlock, J2LawGivesTheHexahedronsStressUnderTheSameHomogeneousHistory) {
  // A stretch to 3x the yield strain in 30 steps, isochoric to first order (F = diag(l, m, m),
  // m = 1 - (l - 1) / 2), prescribed on every node: both meshes see the same F and D each step,
  // so each of their points must carry the same J2 state.
  TetPatch p = make_tet_patch();
  J2PlasticityConstants steel;
  steel.density = 7.8;
  steel.youngs = 2.0e5;
  steel.poisson = 0.3;
  steel.yield = 250.0;
  steel.tangent = 1.0e3;
  steel.beta = 1.0;
  const J2Plasticity law(steel);
  const test_support::PatchMesh hex_patch = test_support::make_patch_mesh();
  NodalFields hex_nodes = hex_patch.nodes;
  HexBlock<J2Plasticity> hexes(2, law, HexHourglass{}, BulkViscosity{0.0, 0.0}, hex_patch.conn, hex_patch.ids);
  TetBlock<J2Plasticity> tet_block(1, law, BulkViscosity{0.0, 0.0}, p.conn, p.ids);
  CornerBuffer ct, ch;
  test_support::prepare(tet_block, p.nodes, ct);
  test_support::prepare(hexes, hex_nodes, ch);
  const Real dt = 1e-3, rate = 3.0 * 250.0 / 2.0e5 / (30 * dt);
  for (int s = 1; s <= 30; ++s) {
    const Real l = 1.0 + rate * dt * s, lat = 1.0 - 0.5 * rate * dt * s;
    const Vec3 stretch(l, lat, lat), vel(rate, -0.5 * rate, -0.5 * rate);
    for (NodalFields* n : {&p.nodes, &hex_nodes})
      for (Index i = 0; i < 27; ++i) {
        n->x.set(i, stretch.cwiseProduct(n->x0.get(i)));
        n->v.set(i, vel.cwiseProduct(n->x0.get(i)));
      }
    BlockEnergy e;
    tet_block.compute_forces(p.nodes, dt, ct, e);
    hexes.compute_forces(hex_nodes, dt, ch, e);
  }
  std::vector<CellOutput> to(p.ids.size()), ho(8);
  tet_block.cell_outputs(p.nodes, to);
  hexes.cell_outputs(hex_nodes, ho);
  ASSERT_GT(ho[0].plastic_strain, 0.0);
  for (const CellOutput& c : to) {
    EXPECT_NEAR(c.plastic_strain, ho[0].plastic_strain, 1e-12);
    for (int k = 0; k < 6; ++k) EXPECT_NEAR(c.stress[k], ho[0].stress[k], 1e-9 * 250.0) << k;
  }
  // The history channels' totals (ElementBlock::plasticity_totals): the same state on the same
  // domain, so the same largest strain and the same plastic work from the two volume sums.
  ASSERT_TRUE(tet_block.has_plasticity());
  const PlasticityTotals tt = tet_block.plasticity_totals(p.nodes), th = hexes.plasticity_totals(hex_nodes);
  EXPECT_NEAR(tt.max_plastic_strain, to[0].plastic_strain, 1e-12);  // the elements differ by round-off
  EXPECT_NEAR(th.max_plastic_strain, tt.max_plastic_strain, 1e-12);
  EXPECT_GT(tt.plastic_work, 0.0);
  EXPECT_NEAR(tt.plastic_work, th.plastic_work, 1e-9 * th.plastic_work);
}
