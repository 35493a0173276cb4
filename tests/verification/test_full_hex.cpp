// Verification of the fully integrated selective-reduced hexahedron (*SECTION_SOLID ELFORM 2),
// read from a deck: a beam of a few elements through the depth in pure bending against
// Euler-Bernoulli (straight and rotated deck), the one-point hexahedron on the same mesh, and no
// volumetric locking in plane strain at nu = 0.499.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>
#include <string>

#include <Eigen/Geometry>

#include "slideline/io/keyword_reader.hpp"
#include "slideline/solver/build.hpp"

namespace slideline {
namespace {

constexpr Real kE = 1000.0, kRho = 1.0;
constexpr int kNy = 4, kNz = 1;  ///< elements through the depth, across
constexpr Real kH = 1.0, kW = 1.0, kDx = 0.25;

/// The beam's mesh: nx elements of kDx along x, and its supports.
struct Beam {
  int nx;
  bool plane_strain;  ///< false: clamped at x = 0; true: see beam_deck
  int node_id(int i, int j, int k) const { return 1 + i + (nx + 1) * (j + (kNy + 1) * k); }
  Real length() const { return nx * kDx; }
};

/// The beam [0, L] x [0, H] x [0, W], bent by an end moment: at x = L the x-forces of the linear
/// traction s y' (y' = y - H/2 from the neutral axis), as consistent nodal loads, ramped over
/// t_ramp; mass damping alpha. Moment M = s I. Supports: clamped at x = 0 (every component; exact
/// for nu = 0), or, for `plane_strain`, z fixed everywhere, x = 0 a symmetry plane (x fixed) with
/// y fixed on its neutral-axis nodes. The deck (nodes, loads) may be turned by R.
std::string beam_deck(const Beam& b, int elform, Real nu, Real s, Real t_ramp, Real t_end, Real alpha,
                      const Mat3& R = Mat3::Identity()) {
  std::ostringstream o;
  o << std::setprecision(17) << "*KEYWORD\n*CONTROL_TERMINATION\n" << t_end << ",0\n*SECTION_SOLID\n1," << elform
    << "\n*MAT_ELASTIC\n1," << kRho << "," << kE << "," << nu << "\n*PART\nbeam\n1,1,1\n*NODE\n";
  const Real dy = kH / kNy, dz = kW / kNz;
  for (int k = 0; k <= kNz; ++k)
    for (int j = 0; j <= kNy; ++j)
      for (int i = 0; i <= b.nx; ++i) {
        const Vec3 x = R * Vec3(i * kDx, j * dy, k * dz);
        o << b.node_id(i, j, k) << "," << x[0] << "," << x[1] << "," << x[2] << "\n";
      }
  o << "*ELEMENT_SOLID\n";
  int eid = 1;
  for (int k = 0; k < kNz; ++k)
    for (int j = 0; j < kNy; ++j)
      for (int i = 0; i < b.nx; ++i)
        o << eid++ << ",1," << b.node_id(i, j, k) << "," << b.node_id(i + 1, j, k) << ","
          << b.node_id(i + 1, j + 1, k) << "," << b.node_id(i, j + 1, k) << "," << b.node_id(i, j, k + 1) << ","
          << b.node_id(i + 1, j, k + 1) << "," << b.node_id(i + 1, j + 1, k + 1) << "," << b.node_id(i, j + 1, k + 1)
          << "\n";
  if (b.plane_strain)
    for (int k = 0; k <= kNz; ++k)
      for (int j = 0; j <= kNy; ++j)
        for (int i = 1; i <= b.nx; ++i) o << "*BOUNDARY_SPC_NODE\n" << b.node_id(i, j, k) << ",0,0,0,1\n";
  const int mid = kNy / 2;
  for (int k = 0; k <= kNz; ++k)
    for (int j = 0; j <= kNy; ++j) {
      o << "*BOUNDARY_SPC_NODE\n" << b.node_id(0, j, k) << ",0,1," << (!b.plane_strain || j == mid) << ",1\n";
      // Consistent load of the linear traction s y' on node (j, k) of the end face.
      const auto yp = [&](int jj) { return jj * dy - 0.5 * kH; };
      const Real fy = (j == 0 || j == kNy) ? dy / 6.0 * (2.0 * yp(j) + yp(j == 0 ? 1 : kNy - 1))
                                           : dy / 6.0 * (yp(j - 1) + 4.0 * yp(j) + yp(j + 1));
      const Real wz = (k == 0 || k == kNz) ? 0.5 * dz : dz;
      const Vec3 f = R * Vec3(s * fy * wz, 0.0, 0.0);
      for (int d = 0; d < 3; ++d)
        if (f[d] != 0.0) o << "*LOAD_NODE_POINT\n" << b.node_id(b.nx, j, k) << "," << d + 1 << ",1," << f[d] << "\n";
    }
  o << "*DEFINE_CURVE\n1\n0,0\n" << t_ramp << ",1\n" << 10.0 * t_end << ",1\n*DAMPING_GLOBAL\n0," << alpha
    << "\n*END\n";
  return o.str();
}

/// Tip deflection along -R e_y of the neutral axis relative to the root's, mean over z, over
/// Euler-Bernoulli's M L^2 / (2 E' I) (E' = E, or E / (1 - nu^2) in plane strain).
Real bend(const Beam& b, int elform, Real nu, const Mat3& R = Mat3::Identity()) {
  const Real inertia = kW * kH * kH * kH / 12.0, length = b.length();
  const Real e_eff = b.plane_strain ? kE / (1.0 - nu * nu) : kE;
  const Real omega1 = 3.516 * std::sqrt(e_eff * inertia / (kRho * kW * kH * std::pow(length, 4)));
  const Real period = 2.0 * std::acos(-1.0) / omega1;
  const Real s = 1e-3 * kE;
  auto sim = build_simulation(
      read_keyword_string(beam_deck(b, elform, nu, s, 2.0 * period, 7.0 * period, 1.4 * omega1, R), "beam.k"));
  while (sim->step()) {
  }
  const auto v = [&](int i, int k) {
    const Index n = b.node_id(i, kNy / 2, k) - 1;  // *NODE lists the ids in order
    EXPECT_EQ(sim->nodes().ids[n], b.node_id(i, kNy / 2, k));
    return (R.transpose() * (sim->nodes().x.get(n) - sim->nodes().x0.get(n)))[1];
  };
  Real d = 0.0;
  for (int k = 0; k <= kNz; ++k) d -= (v(b.nx, k) - v(0, k)) / (kNz + 1);
  return d / (s / e_eff * length * length / 2.0);  // kappa L^2 / 2, kappa = M / (E' I) = s / E'
}

/// The deflection ratio a fully integrated selective-reduced element should give in pure bending,
/// estimated on the exact nodal field of N = kNy elements through the depth. The moment is carried
/// by the element-mean strains (exact) plus, within each element, the bending pattern u = -kappa x y'
/// (what a trilinear element can represent: no lateral strain inside it). Of that in-element part the
/// B-bar element keeps only the deviatoric energy, (4 G / 3) / E' of the exact one (E' = E, or
/// E / (1 - nu^2) in plane strain), and the in-element part is 1 / N^2 of the bending energy: the
/// stiffness loses (1 - 4 G / (3 E')) / N^2. Parasitic shear (dv/dx linear in the element while
/// the nodes follow x^2 / 2) adds (G / E')(dx / H)^2. Ratio = 1 / (1 - loss + parasitic).
Real expected_bbar_ratio(Real nu, bool plane_strain) {
  const Real g_over_e = plane_strain ? (1.0 - nu) / 2.0 : 1.0 / (2.0 * (1.0 + nu));
  const Real loss = (1.0 - 4.0 / 3.0 * g_over_e) / (kNy * kNy);
  return 1.0 / (1.0 - loss + g_over_e * (kDx / kH) * (kDx / kH));
}

}  // namespace

// 8 x 4 x 1 elements (0.25 x 0.25 x 1), pure bending, nu = 0: expected_bbar_ratio gives 0.9897
// (-2.1% stiffness lost in the elements, +3.1% parasitic shear). The one-point hexahedron with
// viscous hourglass control has no stiffness in the in-element bending (hourglass) pattern: only
// the element-mean strains carry the moment, 1 - 1 / N^2 of the exact stiffness, 6.7% too soft
// (with one element through the depth it would have no bending stiffness at all). Both within 1%
// of their estimates, and the ELFORM 2 beam within 3% of Euler-Bernoulli; the same deck turned
// gives the same deflection.
TEST(FullHexahedron, BeamInPureBendingMatchesEulerBernoulli) {
  const Beam beam{8, false};
  const Real full = bend(beam, 2, 0.0);
  const Real one_point = bend(beam, 1, 0.0);
  std::printf("pure bending, tip deflection / Euler-Bernoulli: ELFORM 2 %.4f (estimate %.4f), ELFORM 1 (viscous "
              "hourglass) %.4f (estimate %.4f)\n",
              full, expected_bbar_ratio(0.0, false), one_point, 1.0 / (1.0 - 1.0 / (kNy * kNy)));
  RecordProperty("elform2_over_euler_bernoulli", std::to_string(full));
  EXPECT_NEAR(full, 1.0, 0.03);
  EXPECT_NEAR(full, expected_bbar_ratio(0.0, false), 0.01);
  EXPECT_NEAR(one_point, 1.0 / (1.0 - 1.0 / (kNy * kNy)), 0.01);
  const Mat3 R = Eigen::AngleAxis<Real>(0.7, Vec3(0.3, 1.0, -0.6).normalized()).toRotationMatrix();
  EXPECT_NEAR(bend(beam, 2, 0.0, R), full, 1e-9 * full);
}

// Plane strain (z fixed everywhere) at nu = 0.499, K = 500 G: the classic volumetric-locking test.
// One pressure per element leaves the beam free to bend at constant volume: the deflection stays
// at Euler-Bernoulli's with E' = E / (1 - nu^2) up to the in-element errors of
// expected_bbar_ratio (1.0267: -4.2% stiffness lost, +1.6% parasitic shear); a fully integrated
// volumetric part would lock (deflection down by orders of magnitude). A beam of 4 x 4 x 1
// elements (L = H: pure bending needs no slenderness) keeps the run short at this wave speed.
TEST(FullHexahedron, NoVolumetricLockingInPlaneStrainAtNu0499) {
  const Real r = bend(Beam{4, true}, 2, 0.499);
  std::printf("plane-strain pure bending at nu = 0.499, ELFORM 2: tip deflection / Euler-Bernoulli %.4f "
              "(estimate %.4f)\n",
              r, expected_bbar_ratio(0.499, true));
  RecordProperty("elform2_nu0499_over_euler_bernoulli", std::to_string(r));
  EXPECT_NEAR(r, 1.0, 0.04);
  EXPECT_NEAR(r, expected_bbar_ratio(0.499, true), 0.01);
}

}  // namespace slideline
