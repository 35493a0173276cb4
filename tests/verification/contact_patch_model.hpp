#pragma once
// The contact patch test (issue 18, part 3; docs/contact.md, "The contact patch test"), built in
// C++ with the model API: a 3 x 3 elastic block (1 x 0.5 x 1, 2 layers) pressed onto an n x n
// block (n = 4 or 5, 2 layers) whose footprint is `margin` wider on every side (non-matching
// meshes, edges not flush). Both blocks are squeezed between equal and opposite uniform
// pressures (consistent nodal forces on the upper block's top and the lower block's bottom, the
// same total), so no support is needed and the exact static state is uniform compression
// sigma_yy = -p on both sides of the interface (the lower block's p scaled by the footprint
// ratio). Mass-proportional damping brings the run to that static state. `rotation` turns the
// whole model (nodes and loads) about an oblique axis.
#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>
#include <vector>

#include "slideline/contact/lagrange_contact.hpp"
#include "slideline/element/hex8.hpp"
#include "slideline/material/elastic.hpp"
#include "slideline/model/model.hpp"
#include "slideline/solver/build.hpp"
#include "slideline/solver/simulation.hpp"

namespace slideline::patch_test {

struct PatchOptions {
  int lower_cells = 5;                       ///< n: the lower block is n x n in x-z
  model::ContactType type = model::ContactType::surface_to_surface;
  model::ContactForm form = model::ContactForm::dyna3d;  ///< Type 12's LS-DYNA card (two sides or one)
  model::Enforcement enforcement = model::Enforcement::penalty;
  Real sfs = 1.0;                            ///< SFS = SFM (x SLSFAC 0.1)
  Real margin = 1e-3;                        ///< lower footprint wider by this on each side
  Mat3 rotation = Mat3::Identity();
  Real pressure = 1.0;
  Real youngs = 1000.0, poisson = 0.3, density = 1.0;
  Real damping = 150.0;                      ///< *DAMPING_GLOBAL VALDMP (1 / time)
  Real end_time = 1.5;
  int ihq = 10;                              ///< hourglass: 10 stiffness, 1 viscous
  bool lower_is_slave = false;               ///< Types 3, 10: the finer (lower) block as slave
  int coupling = 0;                          ///< model::Contact::penalty_coupling (1: _MORTAR)
};

/// Ids of the nodes of an (nx, ny, nz)-cell grid created by PatchModel, i fastest, then j, k.
struct PatchGrid {
  Id first = 0;
  int nx = 0, ny = 0, nz = 0;
  Id node(int i, int j, int k) const { return first + i + (nx + 1) * (j + (ny + 1) * k); }
};

/// The model and where its pieces are.
struct PatchModel {
  model::Model model;
  PatchGrid upper, lower;
  std::vector<Id> upper_interface_elements;  ///< upper block's bottom layer (element ids)
  std::vector<Id> lower_interface_elements;  ///< lower block's top layer
  Real lower_pressure = 1.0;                 ///< p x (upper footprint / lower footprint)
};

namespace detail {

inline PatchGrid add_grid(model::Model& m, Id pid, const Vec3& origin, const Vec3& size, int nx, int ny, int nz,
                          const Mat3& r, std::vector<Id>* layer_elements, int layer) {
  PatchGrid g{static_cast<Id>(m.nodes.size()) + 1, nx, ny, nz};
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        const Vec3 x = origin + Vec3(size[0] * i / nx, size[1] * j / ny, size[2] * k / nz);
        m.nodes.push_back({g.node(i, j, k), Vec3(r * x), 0, 0});
      }
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const Id e = static_cast<Id>(m.solids.size()) + 1;
        // LS-DYNA order: nodes 1-4 counter-clockwise seen from 5-8 (the face above).
        m.solids.push_back({e, pid,
                            {g.node(i, j, k), g.node(i, j, k + 1), g.node(i + 1, j, k + 1), g.node(i + 1, j, k),
                             g.node(i, j + 1, k), g.node(i, j + 1, k + 1), g.node(i + 1, j + 1, k + 1),
                             g.node(i + 1, j + 1, k)}});
        if (j == layer && layer_elements) layer_elements->push_back(e);
      }
  return g;
}

/// Consistent nodal forces of a uniform traction `t` (force / area, a vector) on the layer j of g.
inline void add_traction(model::Model& m, const PatchGrid& g, int j, const Vec3& size, const Vec3& t) {
  const Real cell = size[0] / g.nx * size[2] / g.nz;
  for (int k = 0; k <= g.nz; ++k)
    for (int i = 0; i <= g.nx; ++i) {
      const Real wi = (i == 0 || i == g.nx) ? 0.5 : 1.0, wk = (k == 0 || k == g.nz) ? 0.5 : 1.0;
      for (int d = 0; d < 3; ++d)
        if (t[d] != 0.0) m.nodal_loads.push_back({false, g.node(i, j, k), d + 1, 1, wi * wk * cell * t[d], 0, {}, {}});
    }
}

}  // namespace detail

/// Builds the patch test's model (see the file comment).
inline PatchModel make_patch_model(const PatchOptions& o) {
  PatchModel p;
  model::Model& m = p.model;
  const Real h = 0.5;
  const Vec3 up_size(1.0, h, 1.0), lo_size(1.0 + 2 * o.margin, h, 1.0 + 2 * o.margin);
  p.lower = detail::add_grid(m, 2, Vec3(-o.margin, 0.0, -o.margin), lo_size, o.lower_cells, 2, o.lower_cells,
                             o.rotation, &p.lower_interface_elements, 1);
  p.upper = detail::add_grid(m, 1, Vec3(0.0, h, 0.0), up_size, 3, 2, 3, o.rotation, &p.upper_interface_elements, 0);
  m.parts.push_back({1, "upper", 1, 1, 0, 1, {}});
  m.parts.push_back({2, "lower", 1, 1, 0, 1, {}});
  m.solid_sections.push_back({1, 1, {}});
  m.materials.push_back(model::MatElastic{1, o.density, o.youngs, o.poisson, "", {}});
  m.hourglasses.push_back({1, o.ihq, o.ihq == 10 ? 1.0 : 0.1, 1.5, 0.06, {}});
  m.curves.push_back({1, "ramp", 0, 1.0, 1.0, 0.0, 0.0, 0, {{0.0, 0.0}, {0.3, 1.0}, {100.0, 1.0}}, {}});
  p.lower_pressure = o.pressure * (up_size[0] * up_size[2]) / (lo_size[0] * lo_size[2]);
  detail::add_traction(m, p.upper, 2, up_size, o.rotation * Vec3(0.0, -o.pressure, 0.0));
  detail::add_traction(m, p.lower, 0, lo_size, o.rotation * Vec3(0.0, p.lower_pressure, 0.0));
  model::DampingGlobal d;
  d.valdmp = o.damping;
  m.damping_global = d;
  m.termination.endtim = o.end_time;

  model::Contact c;
  c.title = "patch";
  c.type = o.type;
  c.form = o.form;
  c.enforcement = o.enforcement;
  c.sfs = c.sfm = o.sfs;
  if (o.type == model::ContactType::automatic && o.form == model::ContactForm::dyna3d) {
    m.part_sets.push_back({1, "both", {1, 2}, {}});
    c.ssid = 1;
    c.sstyp = 2;
  } else if (o.type == model::ContactType::nodes_to_surface) {
    model::NodeSet ns{1, "upper bottom", {}, {}};
    for (int k = 0; k <= 3; ++k)
      for (int i = 0; i <= 3; ++i) ns.nodes.push_back(p.upper.node(i, 0, k));
    m.node_sets.push_back(ns);
    c.ssid = 1;
    c.sstyp = 4;
    c.msid = 2;
    c.mstyp = 3;
  } else {
    c.ssid = o.lower_is_slave ? 2 : 1;
    c.sstyp = 3;
    c.msid = o.lower_is_slave ? 1 : 2;
    c.mstyp = 3;
  }
  c.penalty_coupling = o.coupling;
  m.contacts.push_back(c);
  return p;
}

/// sigma_yy (in the unrotated frame, R^T sigma R) of each listed element at the current
/// configuration: one-point mean deformation gradient, the material's Cauchy stress.
inline std::vector<Real> normal_stresses(const Simulation& sim, const model::Model& m, const std::vector<Id>& elements,
                                         const Mat3& rotation, const ElasticSolid& law) {
  std::unordered_map<Id, Index> index;
  for (std::size_t i = 0; i < sim.nodes().ids.size(); ++i) index[sim.nodes().ids[i]] = static_cast<Index>(i);
  std::vector<Real> out;
  for (Id e : elements) {
    const model::SolidElement& el = m.solids[static_cast<std::size_t>(e - 1)];
    hex8::NodeMat X, x;
    for (int a = 0; a < 8; ++a) {
      const Index n = index.at(el.n[static_cast<std::size_t>(a)]);
      X.row(a) = sim.nodes().x0.get(n).transpose();
      x.row(a) = sim.nodes().x.get(n).transpose();
    }
    const hex8::NodeMat dv = hex8::volume_gradient(X);
    const Real v = hex8::volume(X, dv);
    Mat3 f = Mat3::Zero();
    for (int a = 0; a < 8; ++a) f += x.row(a).transpose() * (dv.row(a) / v);
    const Mat3 s = rotation.transpose() * law.cauchy_stress(f) * rotation;
    out.push_back(s(1, 1));
  }
  return out;
}

/// Range of sigma_yy / (-p) over the elements next to the interface, per side.
struct PatchResult {
  Real upper_min = 1e30, upper_max = -1e30, lower_min = 1e30, lower_max = -1e30;
  Real drift = 0.0;  ///< largest |ratio change| over the last third of the run (static check)
  LagrangeSolveStats solves;  ///< the Gauss-Seidel solves of a Lagrange interface (else zeros)
  Real worst() const {
    return std::max({std::abs(upper_min - 1.0), std::abs(upper_max - 1.0), std::abs(lower_min - 1.0),
                     std::abs(lower_max - 1.0)});
  }
};

/// Runs the patch test `p` (made by make_patch_model(o), or that model written as a deck and read
/// back) to o.end_time; the spread at the end and its drift over the last third.
inline PatchResult run_patch(const PatchModel& p, const PatchOptions& o) {
  auto sim = build_simulation(p.model);
  sim->initialize();
  const ElasticSolid law(o.density, o.youngs, o.poisson);
  const auto ratios = [&](PatchResult& r) {
    r = PatchResult{};
    for (Real s : normal_stresses(*sim, p.model, p.upper_interface_elements, o.rotation, law)) {
      r.upper_min = std::min(r.upper_min, -s / o.pressure);
      r.upper_max = std::max(r.upper_max, -s / o.pressure);
    }
    for (Real s : normal_stresses(*sim, p.model, p.lower_interface_elements, o.rotation, law)) {
      r.lower_min = std::min(r.lower_min, -s / p.lower_pressure);
      r.lower_max = std::max(r.lower_max, -s / p.lower_pressure);
    }
  };
  PatchResult before;
  bool sampled = false;
  while (sim->step()) {
    if (!sampled && sim->time() >= o.end_time * 2.0 / 3.0) {
      ratios(before);
      sampled = true;
    }
  }
  PatchResult r;
  ratios(r);
  if (const auto* lagrange = dynamic_cast<const LagrangeContact*>(&sim->contacts()[0])) r.solves = lagrange->solve_stats();
  r.drift = std::max({std::abs(r.upper_min - before.upper_min), std::abs(r.upper_max - before.upper_max),
                      std::abs(r.lower_min - before.lower_min), std::abs(r.lower_max - before.lower_max)});
  return r;
}

/// Runs the patch test of `o` built with the model API.
inline PatchResult run_patch(const PatchOptions& o) { return run_patch(make_patch_model(o), o); }

}  // namespace slideline::patch_test
