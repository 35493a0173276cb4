#pragma once
// Pushed strips of every deformable element kind for the MS1ST = 0 mass-scaling tests
// (test_mass_rescaling_blocks.cpp, test_mass_rescaling_erosion.cpp), with the closed-form element
// steps and added masses.
//
// A strip: n cells of side h along the axis a = R e_x, held at one end (all translations) and
// pushed at the other along -a at v_p; nu = 0, so the wave speed is c = sqrt(E / rho) for the solids
// and for the shell (plane stress, c = sqrt(E / (rho (1 - nu^2)))), no bulk viscosity. A cell is
//   hex1, hex2: one hexahedron (ELFORM 1, ELFORM 2), the cube [0, h]^3;
//   tet:        six tetrahedra around the cube's diagonal from corner 0 to corner 6 (Kuhn), each of
//               volume h^3 / 6;
//   shell:      one Belytschko-Tsay quadrilateral h x h in the plane of a and R e_y, thickness kT.
// Element e's stable step from its nodes x (what the test checks against), each block's own formula:
//   hex1, hex2: V / A_max / c, V the trilinear volume (2 x 2 x 2 Gauss points integrate det J
//               exactly), A_max the largest face area 1/2 |d1 x d2| (d1, d2 the face's diagonals);
//   tet:        3 V / A_max / c (the smallest altitude), V = det[x2 - x1, x3 - x1, x4 - x1] / 6;
//   shell:      A / max(longest side, longest diagonal) / c, A = 1/2 |d13 x d24|.
// At rest: hex h / c; tet and shell h / (sqrt 2 c) (a Kuhn tetrahedron's largest face is
// h^2 / sqrt 2; the square's diagonal is sqrt 2 h).
// The element's physical mass m_e: rho h^3 (hexahedra), rho h^3 / 6 (tetrahedra), rho h^2 kT (shell);
// the shell's rotary inertia m_e max(kT^2, A0) / 12 (A0 = h^2 > kT^2), spread over its 4 corners.
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "slideline/element/full_hex_block.hpp"
#include "slideline/element/hex_block.hpp"
#include "slideline/element/shell_block.hpp"
#include "slideline/element/tet_block.hpp"
#include "slideline/material/elastic.hpp"
#include "slideline/material/elastic_shell.hpp"
#include "slideline/material/j2_plasticity.hpp"
#include "slideline/material/shell_plasticity.hpp"
#include "slideline/solver/simulation.hpp"
#include "test_support/staged_simulation.hpp"

namespace slideline::strips {

constexpr Real kRho = 1.0, kE = 1.0e4, kT = 0.08;

enum class Kind { hex1, hex2, tet, shell };

inline const char* name(Kind k) {
  switch (k) {
    case Kind::hex1: return "hex1";
    case Kind::hex2: return "hex2";
    case Kind::tet: return "tet4";
    case Kind::shell: return "shell";
  }
  return "?";
}

inline Real wave_speed() { return std::sqrt(kE / kRho); }

/// The element step at rest of a cell of side h.
inline Real reference_step(Kind k, Real h) {
  return (k == Kind::hex1 || k == Kind::hex2) ? h / wave_speed() : h / (std::sqrt(2.0) * wave_speed());
}

inline Eigen::Matrix3d rotation() {
  return (Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, -0.5).normalized()) * Eigen::AngleAxisd(-0.3, Vec3::UnitZ()))
      .toRotationMatrix();
}

/// One strip of a model.
struct StripSpec {
  Kind kind = Kind::hex1;
  int cells = 10;
  Real h = 0.1;
  Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
  Vec3 origin = Vec3::Zero();
  Real push_speed = 2.0;
  Id part = 1;
  /// > 0: J2 plasticity (yield 0.02 E, tangent 0.1 E) with elements deleted at this plastic strain.
  Real failure_strain = 0.0;
};

/// What the tests need of a built strip: its elements' nodes and physical masses, its block.
struct Strip {
  StripSpec spec;
  std::vector<std::vector<Index>> elements;  // node indices, in the block's order
  std::vector<Real> mass;                    // per element, physical mass
  std::size_t block = 0;                     // index in Simulation::blocks()
  Index first_node = 0, node_count = 0;
};

inline int nodes_per_plane(Kind k) { return k == Kind::shell ? 2 : 4; }

/// Element e's stable step (time) from the current nodes, as the header states it.
inline Real element_step(const Strip& s, const NodalFields& nodes, std::size_t e) {
  const auto& q = s.elements[e];
  const auto x = [&](int k) { return Vec3(nodes.x.get(q[static_cast<std::size_t>(k)])); };
  const Real c = wave_speed();
  switch (s.spec.kind) {
    case Kind::hex1:
    case Kind::hex2: {
      constexpr int sx[8] = {-1, 1, 1, -1, -1, 1, 1, -1}, sy[8] = {-1, -1, 1, 1, -1, -1, 1, 1},
                    sz[8] = {-1, -1, -1, -1, 1, 1, 1, 1};
      const Real g = 1.0 / std::sqrt(3.0);
      Real volume = 0.0;
      for (int p = 0; p < 8; ++p) {
        const Real xi = g * sx[p], eta = g * sy[p], zeta = g * sz[p];
        Eigen::Matrix3d jac = Eigen::Matrix3d::Zero();
        for (int k = 0; k < 8; ++k) {
          const Vec3 d(sx[k] * (1 + sy[k] * eta) * (1 + sz[k] * zeta), sy[k] * (1 + sx[k] * xi) * (1 + sz[k] * zeta),
                       sz[k] * (1 + sx[k] * xi) * (1 + sy[k] * eta));
          jac += x(k) * (d / 8.0).transpose();
        }
        volume += jac.determinant();
      }
      constexpr int faces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
      Real area = 0.0;
      for (const auto& f : faces) area = std::max(area, 0.5 * (x(f[2]) - x(f[0])).cross(x(f[3]) - x(f[1])).norm());
      return volume / area / c;
    }
    case Kind::tet: {
      Eigen::Matrix3d m;
      for (int a = 0; a < 3; ++a) m.col(a) = x(a + 1) - x(0);
      const Real volume = m.determinant() / 6.0;
      constexpr int faces[4][3] = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
      Real area = 0.0;
      for (const auto& f : faces) area = std::max(area, 0.5 * (x(f[1]) - x(f[0])).cross(x(f[2]) - x(f[0])).norm());
      return 3.0 * volume / area / c;
    }
    case Kind::shell: {
      const Real area = 0.5 * (x(2) - x(0)).cross(x(3) - x(1)).norm();
      Real longest = std::max((x(2) - x(0)).norm(), (x(3) - x(1)).norm());
      for (int k = 0; k < 4; ++k) longest = std::max(longest, (x((k + 1) % 4) - x(k)).norm());
      return area / longest / c;
    }
  }
  return 0.0;
}

/// The mass scaling factor (T / dt_e)^2 for DT2MS = `dt2ms` (< 0: only below T; > 0: every element).
inline Real factor(Real dt_e, Real dt2ms) {
  const Real t = std::abs(dt2ms);
  if (dt2ms < 0.0 && dt_e >= t) return 1.0;
  return (t / dt_e) * (t / dt_e);
}

/// Whether element e of the strip is deleted (erosion).
inline bool deleted(const Strip& s, const Simulation& sim, std::size_t e) {
  const ElementErosion* er = sim.blocks()[s.block]->erosion();
  return er && er->deleted(static_cast<Index>(e));
}

/// The closed-form added mass sum_e m_e (f_e - 1) over the strip's live elements.
inline Real closed_form_added(const Strip& s, const Simulation& sim, Real dt2ms) {
  Real added = 0.0;
  for (std::size_t e = 0; e < s.elements.size(); ++e)
    if (!deleted(s, sim, e)) added += s.mass[e] * (factor(element_step(s, sim.nodes(), e), dt2ms) - 1.0);
  return added;
}

/// The closed-form rotary inertia of a shell strip's elements, scaled: sum_e f_e m_e A0 / 12.
inline Real closed_form_inertia(const Strip& s, const Simulation& sim, Real dt2ms) {
  Real j = 0.0;
  const Real a0 = s.spec.h * s.spec.h;
  for (std::size_t e = 0; e < s.elements.size(); ++e) {
    const Real f = deleted(s, sim, e) ? 1.0 : factor(element_step(s, sim.nodes(), e), dt2ms);
    j += f * s.mass[e] * std::max(kT * kT, a0) / 12.0;
  }
  return j;
}

/// A model of strips (each its own part), built into `setup`.
struct StripModel : test_support::StagedSimulation {
  std::vector<Strip> strips;

  explicit StripModel(const std::vector<StripSpec>& specs) {
    Index total = 0;
    for (const StripSpec& sp : specs) total += nodes_per_plane(sp.kind) * (sp.cells + 1);
    setup.nodes.resize(total);
    Index base = 0;
    for (const StripSpec& sp : specs) {
      strips.push_back(build(sp, base));
      base += strips.back().node_count;
    }
    setup.controls.end_time = 0.0;
  }

  /// Total nodal mass and rotary inertia of the model now.
  Real total_mass() const {
    Real m = 0.0;
    for (Real v : sim().nodes().mass) m += v;
    return m;
  }
  Real total_inertia() const {
    Real j = 0.0;
    for (Real v : sim().nodes().rot_inertia) j += v;
    return j;
  }

 private:
  Strip build(const StripSpec& sp, Index base) {
    Strip s;
    s.spec = sp;
    s.first_node = base;
    s.block = setup.blocks.size();
    const int np = nodes_per_plane(sp.kind);
    s.node_count = np * (sp.cells + 1);
    const Real h = sp.h;
    for (int i = 0; i <= sp.cells; ++i)
      for (int c = 0; c < np; ++c) {
        const Index k = base + np * i + c;
        const Vec3 local = sp.kind == Kind::shell ? Vec3(i * h, c == 1 ? h : 0.0, 0.0)
                                                  : Vec3(i * h, (c == 1 || c == 2) ? h : 0.0, c >= 2 ? h : 0.0);
        const Vec3 p = sp.origin + sp.r * local;
        setup.nodes.ids[k] = k + 1;
        setup.nodes.x0.set(k, p);
        setup.nodes.x.set(k, p);
      }
    std::vector<Index> conn;
    std::vector<Id> ids;
    const auto add = [&](std::vector<Index> q, Real m) {
      conn.insert(conn.end(), q.begin(), q.end());
      ids.push_back(static_cast<Id>(1000 * sp.part + static_cast<Id>(ids.size()) + 1));
      s.elements.push_back(std::move(q));
      s.mass.push_back(m);
    };
    for (int i = 0; i < sp.cells; ++i) {
      const Index a = base + np * i, b = base + np * (i + 1);
      if (sp.kind == Kind::shell) {
        add({a, b, b + 1, a + 1}, kRho * h * h * kT);
        continue;
      }
      const std::array<Index, 8> q{a + 0, b + 0, b + 1, a + 1, a + 3, b + 3, b + 2, a + 2};
      if (sp.kind != Kind::tet) {
        add(std::vector<Index>(q.begin(), q.end()), kRho * h * h * h);
        continue;
      }
      // Kuhn: the six tetrahedra around the diagonal 0-6, ordered to a positive volume.
      constexpr int kuhn[6][2] = {{1, 2}, {2, 3}, {3, 7}, {7, 4}, {4, 5}, {5, 1}};
      for (const auto& k : kuhn) {
        std::vector<Index> t{q[0], q[static_cast<std::size_t>(k[0])], q[static_cast<std::size_t>(k[1])], q[6]};
        Eigen::Matrix3d m;
        for (int col = 0; col < 3; ++col)
          m.col(col) = setup.nodes.x0.get(t[static_cast<std::size_t>(col + 1)]) - setup.nodes.x0.get(t[0]);
        if (m.determinant() < 0.0) std::swap(t[1], t[2]);
        add(t, kRho * h * h * h / 6.0);
      }
    }
    const bool plastic = sp.failure_strain > 0.0;
    const J2Plasticity j2(J2PlasticityConstants{kRho, kE, 0.0, 0.02 * kE, 0.1 * kE, 1.0, 0.0, 0.0});
    const BulkViscosity none{0.0, 0.0};
    std::unique_ptr<ElementBlock> block;
    switch (sp.kind) {
      case Kind::hex1:
        if (plastic)
          block = std::make_unique<HexBlock<J2Plasticity>>(sp.part, j2, HexHourglass{}, none, conn, ids);
        else
          block = std::make_unique<HexBlock<ElasticSolid>>(sp.part, ElasticSolid(kRho, kE, 0.0), HexHourglass{}, none,
                                                           conn, ids);
        break;
      case Kind::hex2:
        if (plastic)
          block = std::make_unique<FullHexBlock<J2Plasticity>>(sp.part, j2, none, conn, ids);
        else
          block = std::make_unique<FullHexBlock<ElasticSolid>>(sp.part, ElasticSolid(kRho, kE, 0.0), none, conn, ids);
        break;
      case Kind::tet:
        if (plastic)
          block = std::make_unique<TetBlock<J2Plasticity>>(sp.part, j2, none, conn, ids);
        else
          block = std::make_unique<TetBlock<ElasticSolid>>(sp.part, ElasticSolid(kRho, kE, 0.0), none, conn, ids);
        break;
      case Kind::shell: {
        ShellSection sec;
        sec.thickness = kT;
        sec.bulk = none;
        if (plastic)
          block = std::make_unique<BasicShellBlock<ShellPlasticity<J2Plasticity>>>(
              sp.part, ShellPlasticity<J2Plasticity>(j2), sec, conn, ids);
        else
          block = std::make_unique<ShellBlock>(sp.part, ElasticShell(kRho, kE, 0.0), sec, conn, ids);
        break;
      }
    }
    if (plastic) {
      ErosionCriteria crit;
      crit.plastic_strain = sp.failure_strain;
      block->enable_erosion(crit);
    }
    setup.blocks.push_back(std::move(block));
    // End 0 held in every translation; the last plane pushed at v_p along -a (starting at v_p).
    SupportGroup held{"held_" + std::to_string(sp.part), {}, Vec3::Zero()};
    SupportGroup pushed{"pushed_" + std::to_string(sp.part), {}, Vec3::Zero()};
    const Vec3 dir = sp.r.col(0);
    std::vector<Index> first, last;
    for (int c = 0; c < np; ++c) {
      first.push_back(base + c);
      last.push_back(base + np * sp.cells + c);
    }
    for (int c = 0; c < 3; ++c) {
      Support fix;
      fix.axis = static_cast<Axis>(c);
      fix.nodes = first;
      held.supports.push_back(fix);
      Support push = fix;
      push.nodes = last;
      push.has_curve = true;
      push.kind = Prescribed::velocity;
      push.curve = LoadCurve::constant(1.0);
      push.scale = -sp.push_speed * dir[c];
      pushed.supports.push_back(push);
    }
    setup.supports.push_back(held);
    setup.supports.push_back(pushed);
    for (Index k : last) setup.nodes.v.set(k, -sp.push_speed * dir);
    return s;
  }
};

}  // namespace slideline::strips
