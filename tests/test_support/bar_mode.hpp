#pragma once
// The first axial (quarter-wave) mode of a free-clamped bar, run from a deck whose first four node
// ids are the free end x = 0: the time the free end's axial displacement returns to zero (half a
// period, 2 L / c for the continuum bar) and the worst energy balance error. Shared by the
// wave-speed checks of the tetrahedra, pentahedra and pyramids (tests/verification).
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <iomanip>
#include <sstream>
#include <string>

#include "slideline/io/keyword_reader.hpp"
#include "slideline/solver/build.hpp"

namespace test_support {

/// What a bar deck's cells are made of: `elements` writes the *ELEMENT_SOLID lines of cell i
/// (its eight corners in LS-DYNA order, N1-N2 along x, N1-N4 along y, N1-N5 along z; `eid` the
/// next element id, advanced by the writer); `centres`, when set, adds one node at each cell's
/// centre (id 4 (n + 1) + i + 1), with the mode's velocity.
struct BarCells {
  std::function<void(std::ostream&, int& eid, const std::array<int, 8>& corners, int centre)> elements;
  bool centres = false;
};

/// A deck of a bar along x of n cubic cells of side h (one through y and z), elastic (density
/// rho, modulus E, nu = 0, so the bar speed sqrt(E / rho) is also the dilatational speed), in a
/// *SECTION_SOLID of form `elform`, clamped at x = L, free at x = 0, started in its first axial
/// (quarter-wave) mode v = v0 cos(pi x / 2L) e_x; the whole deck turned by R. Node ids: 4 i + c + 1
/// at x = i h, c = dy + 2 dz (so the free end is nodes 1-4).
inline std::string bar_deck(int n, slideline::Real h, slideline::Real v0, slideline::Real t_end,
                            const slideline::Mat3& R, int elform, slideline::Real rho, slideline::Real E,
                            const BarCells& cells) {
  using slideline::Real;
  using slideline::Vec3;
  std::ostringstream s;
  s << std::setprecision(17) << "*KEYWORD\n*CONTROL_TERMINATION\n" << t_end << ",0\n*SECTION_SOLID\n1," << elform
    << "\n*MAT_ELASTIC\n1," << rho << "," << E << ",0.0\n*PART\nbar\n1,1,1\n*NODE\n";
  const Real length = n * h, pi = std::acos(-1.0);
  const auto id = [](int i, int c) { return 4 * i + c + 1; };
  const auto centre = [n](int i) { return 4 * (n + 1) + i + 1; };
  const auto node = [&](int nid, const Vec3& x) { s << nid << "," << x[0] << "," << x[1] << "," << x[2] << "\n"; };
  for (int i = 0; i <= n; ++i)
    for (int c = 0; c < 4; ++c) node(id(i, c), R * Vec3(i * h, (c & 1) * h, (c >> 1) * h));
  for (int i = 0; cells.centres && i < n; ++i) node(centre(i), R * Vec3((i + 0.5) * h, 0.5 * h, 0.5 * h));
  s << "*ELEMENT_SOLID\n";
  int eid = 1;
  for (int i = 0; i < n; ++i)
    cells.elements(s, eid,
                   {id(i, 0), id(i + 1, 0), id(i + 1, 1), id(i, 1), id(i, 2), id(i + 1, 2), id(i + 1, 3), id(i, 3)},
                   centre(i));
  s << "*SET_NODE_LIST\n1\n" << id(n, 0) << "," << id(n, 1) << "," << id(n, 2) << "," << id(n, 3)
    << "\n*BOUNDARY_SPC_SET\n1,0,1,1,1\n*INITIAL_VELOCITY_NODE\n";
  // cells from the free end at position xi (x = xi h)
  const auto velocity = [&](int nid, Real xi) { node(nid, R * Vec3(v0 * std::cos(pi * xi * h / (2.0 * length)), 0.0, 0.0)); };
  for (int i = 0; i < n; ++i)
    for (int c = 0; c < 4; ++c) velocity(id(i, c), i);
  for (int i = 0; cells.centres && i < n; ++i) velocity(centre(i), i + 0.5);
  s << "*END\n";
  return s.str();
}

struct BarRun {
  slideline::Real half_period = -1.0;  ///< first time the free end's axial displacement returns to zero
  slideline::Real balance = 0.0;       ///< largest |energy balance error| / initial kinetic energy
  long cycles = 0;
};

/// Runs the deck; the free end's axial displacement u = R^T (x - X) . e_x (mean of its 4 nodes,
/// the first four of the model). `name` names the deck in error messages.
inline BarRun run_bar(const std::string& deck, const std::string& name,
                      const slideline::Mat3& R = slideline::Mat3::Identity()) {
  using slideline::Index;
  using slideline::Real;
  auto sim = slideline::build_simulation(slideline::read_keyword_string(deck, name));
  BarRun r;
  Real u_prev = 0.0, t_prev = 0.0;
  bool rose = false;
  while (sim->step()) {
    Real u = 0.0;
    for (Index k = 0; k < 4; ++k) u += (R.transpose() * (sim->nodes().x.get(k) - sim->nodes().x0.get(k)))[0] / 4.0;
    rose = rose || u > 0.0;
    if (rose && r.half_period < 0.0 && u_prev > 0.0 && u <= 0.0)
      r.half_period = t_prev + (sim->time() - t_prev) * u_prev / (u_prev - u);
    u_prev = u;
    t_prev = sim->time();
    const auto& e = sim->energy();
    r.balance = std::max(r.balance, std::abs(e.balance_error()) / e.kinetic0);
  }
  r.cycles = sim->cycle();
  return r;
}

}  // namespace test_support
