#pragma once
// Hertz contact (issue 18, "Also measured"; docs/verification.md, "Hertz"): a rigid sphere of
// radius R driven at a constant speed into an elastic block, built in C++ with the model API.
//
// The indenter is the bottom cap of the sphere, one layer of *MAT_RIGID hexahedra whose lower
// faces are the sphere (a square grid of `cap_cells` x `cap_cells` mapped onto it: rigid is
// supported for any surface here, so no stiff elastic stand-in is needed). The block is
// [-W, W] x [-H, 0] x [-W, W] (top face y = 0), its bottom fixed in x, y and z, meshed with cells
// of size h around the axis (|x|, |z| <= fine_half, depth <= fine_depth) growing geometrically
// outside. Everything is placed by a Frame (identity or an oblique rotation), the drive included
// (three *BOUNDARY_PRESCRIBED_MOTION_RIGID cards, one per global axis, scaled by the components
// of the indentation direction; the rotations held at zero).
//
// Closed form. Hertz for a rigid sphere on a half-space: contact radius a, F = 4 E* a^3 / (3 R),
// approach d = a^2 / R (so F = 4/3 E* R^1/2 d^3/2), E* = E / (1 - nu^2), maximum pressure
// p0 = 2 a E* / (pi R). Hertz's d is measured against points far away; a block of finite size
// (fixed bottom at depth H) is stiffer than the half-space by a compliance of order
// F / (E H), which is several per cent of d at a / H = 0.05. So the test measures the approach
// between the indenter and the block's node on the axis at depth D instead: d_rel = d - u_z(D),
// u_z(D) the half-space displacement on the axis under the Hertz pressure (Johnson, Contact
// Mechanics, eq. 3.45 integrated from D to infinity):
//   u_z(D) = p0 a (1 + nu) / E [I1(s) - 2 nu I2(s)], s = D / a,
//   I1 = pi/2 - atan(s),  I2 = pi/4 - s/2 + s^2/2 atan(1/s) - atan(s)/2
// (u_z(0) = pi p0 a (1 - nu^2) / (2 E) = a^2 / R: the Hertz approach). The finite block changes
// d_rel only through the gradient of its correction field over D, about (D / H) of the above.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "general_contact_models.hpp"

namespace slideline::hertz_test {

using test_support::Frame;

struct HertzOptions {
  model::ContactType type = model::ContactType::surface_to_surface;
  model::Enforcement enforcement = model::Enforcement::penalty;
  Real sfs = 1.0;                ///< SFS = SFM (x SLSFAC 0.1): 1 the default, 10 the spec's
  Frame frame;
  Real radius = 4.0;             ///< R
  Real youngs = 1000.0, poisson = 0.3, density = 1.0;
  Real half_width = 1.0, depth = 1.0;  ///< W, H
  Real h = 0.02;                 ///< cell size near the axis
  Real fine_half = 0.14, fine_depth = 0.24;
  Real growth = 1.5;             ///< ratio of successive cells outside the fine region
  Real cap_half = 0.2;           ///< the cap covers |x|, |z| <= cap_half (in its grid)
  int cap_cells = 40;            ///< cap grid cells per side (0.01 each by default)
  Real cap_thickness = 0.01;
  Real cap_density = 10.0;       ///< nodal masses comparable to the block's fine nodes
  Real gap = 5e-4;               ///< initial gap between the sphere and the block
  Real speed = 0.0125;           ///< indentation speed, reached by t_ramp, constant after
  Real t_ramp = 0.04;
  Real travel = 0.0025;          ///< largest indentation d (a = 0.1 at R = 4)
  Real damping = 10.0;           ///< *DAMPING_GLOBAL VALDMP
  int ihq = 10;
  Real probe = 0.2;              ///< depth of the block's axis node the approach is measured to
};

/// Where the pieces of the model are.
struct HertzModel {
  model::Model model;
  Id block_pid = 1, sphere_pid = 2;
  Id axis_top = 0;     ///< block node at the top of the axis (0, 0, 0)
  Id axis_depth = 0;   ///< block node on the axis at depth `probe_depth`
  Real probe_depth = 0.0;
  Real t_contact = 0.0;  ///< time the sphere reaches the block
};

namespace detail {

/// Node coordinates from -half to half: cells of h over |s| <= fine, growing by `ratio` outside,
/// the outer cells scaled so that the last lands on `half`. Symmetric about 0.
inline std::vector<Real> graded_coordinates(Real half, Real fine, Real h, Real ratio) {
  const int nf = static_cast<int>(std::lround(fine / h));
  std::vector<Real> outer;  // distances of the outer nodes from the fine edge
  Real s = 0.0, c = h * ratio;
  while (s + 0.5 * c < half - nf * h) {
    s += c;
    outer.push_back(s);
    c *= ratio;
  }
  const Real scale = (half - nf * h) / outer.back();
  std::vector<Real> side;  // 0 .. half
  for (int i = 0; i <= nf; ++i) side.push_back(i * h);
  for (Real o : outer) side.push_back(nf * h + o * scale);
  std::vector<Real> out;
  for (std::size_t i = side.size(); i-- > 1;) out.push_back(-side[i]);
  out.insert(out.end(), side.begin(), side.end());
  return out;
}

/// The same, one-sided: 0 down to -depth (returned ascending, -depth first).
inline std::vector<Real> graded_depths(Real depth, Real fine, Real h, Real ratio) {
  std::vector<Real> two = graded_coordinates(depth, fine, h, ratio);
  return {two.begin(), two.begin() + static_cast<std::ptrdiff_t>(two.size() / 2 + 1)};
}

/// Hexahedra on a structured grid of node ids `at(i, j, k)`, LS-DYNA order, positive volume when
/// i, j, k run along a right-handed triple.
template <class At>
void add_grid_elements(model::Model& m, Id pid, int ni, int nj, int nk, At at) {
  Id next = 1;
  for (const auto& e : m.solids) next = std::max(next, e.id + 1);
  for (int k = 0; k < nk; ++k)
    for (int j = 0; j < nj; ++j)
      for (int i = 0; i < ni; ++i)
        m.solids.push_back({next++, pid,
                            {at(i, j, k), at(i + 1, j, k), at(i + 1, j + 1, k), at(i, j + 1, k), at(i, j, k + 1),
                             at(i + 1, j, k + 1), at(i + 1, j + 1, k + 1), at(i, j + 1, k + 1)},
                            0, 0});
}

inline Id next_node_id(const model::Model& m) {
  Id next = 1;
  for (const auto& nd : m.nodes) next = std::max(next, nd.id + 1);
  return next;
}

/// The block (part pid); returns its bottom nodes and fills the axis nodes of `hm`.
inline std::vector<Id> add_block(model::Model& m, Id pid, const HertzOptions& o, HertzModel& hm) {
  const std::vector<Real> xs = graded_coordinates(o.half_width, o.fine_half, o.h, o.growth);
  const std::vector<Real> ys = graded_depths(o.depth, o.fine_depth, o.h, o.growth);
  const int n = static_cast<int>(xs.size()), ny = static_cast<int>(ys.size());
  const Id first = next_node_id(m);
  auto at = [&](int i, int j, int k) { return first + i + n * (j + ny * k); };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < n; ++i) m.nodes.push_back({at(i, j, k), o.frame.map(Vec3(xs[i], ys[j], xs[k])), 0, 0});
  add_grid_elements(m, pid, n - 1, ny - 1, n - 1, at);
  const int mid = n / 2, top = ny - 1, probe = top - static_cast<int>(std::lround(o.probe / o.h));
  hm.axis_top = at(mid, top, mid);
  hm.axis_depth = at(mid, probe, mid);
  hm.probe_depth = -ys[static_cast<std::size_t>(probe)];
  std::vector<Id> bottom;
  for (int k = 0; k < n; ++k)
    for (int i = 0; i < n; ++i) bottom.push_back(at(i, 0, k));
  return bottom;
}

/// The rigid cap: the square grid mapped onto the sphere of centre c (layer 0, the contact
/// surface) and onto the sphere of radius R - t (layer 1, inside).
inline void add_cap(model::Model& m, Id pid, const HertzOptions& o, const Vec3& c) {
  const int n = o.cap_cells;
  const Id first = next_node_id(m);
  auto at = [&](int i, int j, int k) { return first + i + (n + 1) * (j + 2 * k); };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= 1; ++j)
      for (int i = 0; i <= n; ++i) {
        const Real u = o.cap_half * (2.0 * i / n - 1.0), w = o.cap_half * (2.0 * k / n - 1.0);
        const Vec3 dir = Vec3(u, -std::sqrt(o.radius * o.radius - u * u - w * w), w) / o.radius;
        const Real r = o.radius - j * o.cap_thickness;
        m.nodes.push_back({at(i, j, k), o.frame.map(c + r * dir), 0, 0});
      }
  add_grid_elements(m, pid, n, 1, n, at);
}

}  // namespace detail

/// The model of the file comment.
inline HertzModel make_hertz_model(const HertzOptions& o) {
  HertzModel hm;
  model::Model& m = hm.model;
  test_support::add_elastic_part(m, hm.block_pid, o.density, o.youngs, o.poisson, o.ihq);
  const std::vector<Id> bottom = detail::add_block(m, hm.block_pid, o, hm);
  m.node_sets.push_back({1, "bottom", bottom, {}});
  m.spcs.push_back({0, "", 1, 0, {1, 1, 1, 0, 0, 0}, {}});
  model::DampingGlobal damp;
  damp.valdmp = o.damping;
  m.damping_global = damp;
  detail::add_cap(m, hm.sphere_pid, o, Vec3(0.0, o.radius + o.gap, 0.0));
  m.materials.push_back(model::MatRigid{hm.sphere_pid, o.cap_density, o.youngs, o.poisson, 0.0, 0, 0, "", {}});
  m.solid_sections.push_back({hm.sphere_pid, 1, {}});
  m.parts.push_back({hm.sphere_pid, "sphere", hm.sphere_pid, hm.sphere_pid, 0, 0, {}});

  // Velocity drive: 0 -> speed over t_ramp, then constant; the gap closes at t_contact.
  hm.t_contact = 0.5 * o.t_ramp + o.gap / o.speed;
  m.curves.push_back({1, "speed", 0, 1.0, 1.0, 0.0, 0.0, 0, {{0.0, 0.0}, {o.t_ramp, o.speed}, {100.0, o.speed}}, {}});
  m.curves.push_back({2, "zero", 0, 1.0, 1.0, 0.0, 0.0, 0, {{0.0, 0.0}, {100.0, 0.0}}, {}});
  const Vec3 down = o.frame.map(Vec3(0.0, -1.0, 0.0));
  for (int d = 0; d < 3; ++d) {
    model::PrescribedMotion p;
    p.target = model::PrescribedMotion::Target::rigid;
    p.nsid = hm.sphere_pid;
    p.dof = d + 1;
    p.vad = 0;
    p.lcid = 1;
    p.sf = down[d];
    m.prescribed_motions.push_back(p);
    p.dof = d + 5;  // no rotation
    p.lcid = 2;
    p.sf = 1.0;
    m.prescribed_motions.push_back(p);
  }
  m.termination.endtim = hm.t_contact + 1.02 * o.travel / o.speed;

  model::Contact c;
  c.type = o.type;
  c.enforcement = o.enforcement;
  c.keyword = "*CONTACT (hertz)";
  c.title = "hertz";
  c.ssid = hm.block_pid;
  c.sstyp = 3;
  c.msid = hm.sphere_pid;
  c.mstyp = 3;
  if (o.type == model::ContactType::automatic) {
    m.part_sets.push_back({1, "both", {hm.block_pid, hm.sphere_pid}, {}});
    c.ssid = 1;
    c.sstyp = 2;
    c.msid = 0;
    c.mstyp = 0;
  }
  c.sfs = c.sfm = o.sfs;
  m.contacts.push_back(c);
  return hm;
}

/// Hertz: force of a rigid sphere of radius R at contact radius a on a half-space (E, nu).
inline Real hertz_force(Real a, Real r, Real e, Real nu) { return 4.0 * e / (1.0 - nu * nu) * a * a * a / (3.0 * r); }

/// Half-space displacement on the axis at depth z under the Hertz pressure of contact radius a
/// (into the body; u(0) = a^2 / R). See the file comment.
inline Real axis_displacement(Real z, Real a, Real r, Real e, Real nu) {
  const Real s = z / a;
  const Real i1 = 0.5 * M_PI - std::atan(s);
  const Real i2 = 0.25 * M_PI - 0.5 * s + (s > 0.0 ? 0.5 * s * s * std::atan(1.0 / s) : 0.0) - 0.5 * std::atan(s);
  const Real p0 = 2.0 * a * e / ((1.0 - nu * nu) * M_PI * r);
  return p0 * a * (1.0 + nu) / e * (i1 - 2.0 * nu * i2);
}

/// The Hertz force at which the approach between the indenter and the axis point at depth z is
/// d_rel (bisection on a; d_rel grows monotonically with a).
inline Real hertz_force_at_relative_approach(Real d_rel, Real z, Real r, Real e, Real nu) {
  Real lo = 0.0, hi = 10.0 * std::sqrt(r * std::max(d_rel, 0.0)) + 10.0 * z;
  for (int it = 0; it < 200; ++it) {
    const Real a = 0.5 * (lo + hi);
    (a * a / r - axis_displacement(z, a, r, e, nu) < d_rel ? lo : hi) = a;
  }
  return hertz_force(0.5 * (lo + hi), r, e, nu);
}

}  // namespace slideline::hertz_test
