#pragma once
// A flat punch driven at constant speed into a column of eroding hexahedra (docs/
// contact_erosion.md, "Verification"): the deck, and a run that records what the checks read.
//
// Column: three unit cubes stacked along the axis a (before rotation: z, from z = 0 to 3), the
// base nodes held. The top cube (part 1) is *MAT_PLASTIC_KINEMATIC E 100, nu 0.3, yield 1, Et 1,
// failure strain FS; the two below (part 2) yield at 3, so they stay elastic (the punch force
// never passes 1.6). Punch: one elastic hexahedron 2 x 2 x 1 (part 3), centred over the column, its face
// `gap` above the column's top, every node driven at the velocity -v a. The deck's geometry is
// the one above turned by `rotation`. Contact: `card` with SSID = part set {1, 2} (SSTYP 2),
// MSID = part 3, and for a *CONTACT_ERODING_... card its card 4 with EROSOP `erosop`.
#include <array>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "slideline/contact/contact_algorithm.hpp"
#include "slideline/core/types.hpp"
#include "slideline/element/element_erosion.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/solver/build.hpp"
#include "slideline/solver/simulation.hpp"

namespace slideline::eroding_punch {

// E / yield = 100 keeps the run short (about 1 / (v sqrt(rho / E)) steps per unit of travel) while
// the impact stress rho c v = 0.18 at v = 5 stays well below yield (quasi-static crushing).
constexpr Real kE = 100.0, kNu = 0.3, kRho = 1e-5, kEt = 1.0, kYield = 1.0, kStrongYield = 3.0;
constexpr Real kEp = kE * kEt / (kE - kEt);  ///< plastic hardening modulus of the bilinear curve

struct Deck {
  std::string card = "*CONTACT_ERODING_SURFACE_TO_SURFACE";
  std::string sides = "1,3,2,3";  ///< card 1: SSID MSID SSTYP MSTYP (single surface: ",,5", every part)
  int erosop = 1;
  int iadj = 0;  ///< card 4's IADJ (1: also the faces between parts: the top cube's bottom)
  std::string optional_cards;  ///< after card 4: optional cards A-F as written (blank: none)
  Real fail = 0.05;     ///< FS of both column parts (0: no erosion)
  Real v = 5.0;         ///< punch speed (length / time)
  Real gap = 0.01;      ///< initial gap between the punch face and the column top (length)
  Real end_time = 0.23;
  /// TSSFAC: the top nodes' penalty spring (0.4 K per node: the punch face is 4 times the column's)
  /// is as stiff as their element, and the two together are not stable at the default 0.9 (each
  /// step vote sees its own spring only); 0.6 is.
  Real tssfac = 0.6;
  Mat3 rotation = Mat3::Identity();

  Vec3 axis() const { return rotation * Vec3(0.0, 0.0, 1.0); }
  Vec3 at(Real x, Real y, Real z) const { return rotation * Vec3(x, y, z); }

  std::string text() const {
    std::ostringstream o;
    o << std::setprecision(17) << "*KEYWORD\n*CONTROL_TERMINATION\n" << end_time << ",\n*CONTROL_TIMESTEP\n0,"
      << tssfac << "\n*SECTION_SOLID\n1,1\n";
    for (int m = 1; m <= 2; ++m)
      o << "*MAT_PLASTIC_KINEMATIC\n" << m << "," << kRho << "," << kE << "," << kNu << ","
        << (m == 1 ? kYield : kStrongYield) << "," << kEt << ",1.0\n0,0," << fail << "\n*PART\ncolumn " << m << "\n"
        << m << ",1," << m << "\n";
    o << "*MAT_ELASTIC\n3," << kRho << "," << kE << "," << kNu << "\n*PART\npunch\n3,1,3\n*NODE\n";
    const auto node = [&](int id, Real x, Real y, Real z) {
      const Vec3 p = at(x, y, z);
      o << id << "," << p.x() << "," << p.y() << "," << p.z() << "\n";
    };
    for (int k = 0; k <= 3; ++k)
      for (int j = 0; j <= 1; ++j)
        for (int i = 0; i <= 1; ++i) node(column_node(i, j, k), i, j, k);
    for (int k = 0; k <= 1; ++k)
      for (int j = 0; j <= 1; ++j)
        for (int i = 0; i <= 1; ++i) node(punch_node(i, j, k), -0.5 + 2.0 * i, -0.5 + 2.0 * j, 3.0 + gap + k);
    o << "*ELEMENT_SOLID\n";
    for (int k = 0; k < 3; ++k) {
      const auto n = [&](int i, int j, int kk) { return column_node(i, j, kk); };
      o << k + 1 << "," << (k == 2 ? 1 : 2) << "," << n(0, 0, k) << "," << n(1, 0, k) << "," << n(1, 1, k) << ","
        << n(0, 1, k) << "," << n(0, 0, k + 1) << "," << n(1, 0, k + 1) << "," << n(1, 1, k + 1) << ","
        << n(0, 1, k + 1) << "\n";
    }
    const auto p = [&](int i, int j, int k) { return punch_node(i, j, k); };
    o << "101,3," << p(0, 0, 0) << "," << p(1, 0, 0) << "," << p(1, 1, 0) << "," << p(0, 1, 0) << "," << p(0, 0, 1)
      << "," << p(1, 0, 1) << "," << p(1, 1, 1) << "," << p(0, 1, 1) << "\n";
    // Node set 3: every node of the column (a node-set slave side, SSTYP 4).
    o << "*SET_NODE_LIST\n1\n1,2,3,4\n*SET_NODE_LIST\n2\n101,102,103,104,105,106,107,108\n"
      << "*SET_NODE_LIST_GENERATE\n3\n1,16\n"
      << "*BOUNDARY_SPC_SET\n1,0,1,1,1\n*SET_PART_LIST\n1\n1,2\n";
    // The punch's velocity -v a, one constant curve per component (VAD 0).
    const Vec3 vel = -v * axis();
    for (int c = 0; c < 3; ++c)
      o << "*BOUNDARY_PRESCRIBED_MOTION_SET\n2," << c + 1 << ",0," << c + 1 << "\n*DEFINE_CURVE\n" << c + 1
        << "\n0," << vel[c] << "\n1," << vel[c] << "\n";
    o << card << "\n" << sides << "\n\n\n";
    if (card.find("ERODING") != std::string::npos) o << "0," << erosop << "," << iadj << "\n";
    o << optional_cards;
    o << "*END\n";
    return o.str();
  }

  static int column_node(int i, int j, int k) { return 1 + i + 2 * j + 4 * k; }
  static int punch_node(int i, int j, int k) { return 101 + i + 2 * j + 4 * k; }
};

/// Per step: its end time, the contact force on the punch along a (the column's push back, > 0 in
/// compression; the punch touches only the column), the punch face's and the column's top face's positions along a (the mean
/// of their four nodes: the top cube's top while it lives, then the next cube's top); at the end,
/// the top cube's deletion time (-1: live), the energies and every node's final position.
struct PunchRun {
  std::vector<Real> t, force, punch, top;
  Real deleted_at = -1.0;
  EnergyReport energy;
  std::vector<Real> final_x;
  Real max_dt = 0.0;
};

inline PunchRun run(const Deck& deck) {
  auto sim = build_simulation(read_keyword_string(deck.text(), "punch.k"));
  const NodalFields& nodes = sim->nodes();
  const auto index = [&](int id) {
    for (std::size_t i = 0; i < nodes.size(); ++i)
      if (nodes.ids[i] == id) return static_cast<Index>(i);
    return Index{-1};
  };
  const auto face = [&](auto id_of) {
    std::array<Index, 4> f{};
    for (int j = 0; j <= 1; ++j)
      for (int i = 0; i <= 1; ++i) f[static_cast<std::size_t>(i + 2 * j)] = index(id_of(i, j));
    return f;
  };
  const auto top1 = face([](int i, int j) { return Deck::column_node(i, j, 3); });
  const auto top2 = face([](int i, int j) { return Deck::column_node(i, j, 2); });
  const auto punch = face([](int i, int j) { return Deck::punch_node(i, j, 0); });
  const Vec3 a = deck.axis();
  const auto mean = [&](const std::array<Index, 4>& f) {
    Real s = 0.0;
    for (Index n : f) s += nodes.x.get(n).dot(a);
    return 0.25 * s;
  };
  const ElementErosion* top_erosion = nullptr;
  for (const auto& b : sim->blocks())
    if (b->part_id() == 1) top_erosion = std::as_const(*b).erosion();
  PunchRun r;
  bool more = true;
  while (more) {
    const Real t0 = sim->time();
    more = sim->step();
    r.max_dt = std::max(r.max_dt, sim->time() - t0);
    r.t.push_back(sim->time());
    Vec3 f = Vec3::Zero();
    for (int j = 0; j <= 1; ++j)
      for (int i = 0; i <= 1; ++i)
        for (int kk = 0; kk <= 1; ++kk) f += nodes.f_contact.get(index(Deck::punch_node(i, j, kk)));
    r.force.push_back(f.dot(a));
    r.punch.push_back(mean(punch));
    const bool top_live = !top_erosion || !top_erosion->deleted(0);
    r.top.push_back(mean(top_live ? top1 : top2));
  }
  if (top_erosion) r.deleted_at = top_erosion->deletion_times()[0];
  r.energy = sim->energy();
  for (std::size_t i = 0; i < nodes.size(); ++i)
    for (int c = 0; c < 3; ++c) r.final_x.push_back(nodes.x.get(static_cast<Index>(i))[c]);
  return r;
}

}  // namespace slideline::eroding_punch
