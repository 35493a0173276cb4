// The sslide generator: geometry of every pairing of the 19 problems against the spec, and the
// committed decks under examples/sslide/ against the generator.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <unordered_map>

#include "slideline/core/error.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/io/keyword_writer.hpp"
#include "slideline/scenarios/sslide.hpp"
#include "slideline/solver/validate_model.hpp"
#include "unit/io/model_equal.hpp"

namespace slideline::scenarios {
namespace {

using model::ContactType;

std::unordered_map<Id, Vec3> coordinates(const model::Model& m) {
  std::unordered_map<Id, Vec3> x;
  for (const auto& n : m.nodes) x[n.id] = n.x;
  return x;
}

std::set<Id> part_nodes(const model::Model& m, Id pid) {
  std::set<Id> s;
  for (const auto& e : m.solids)
    if (e.pid == pid) s.insert(e.n.begin(), e.n.end());
  for (const auto& e : m.shells)
    if (e.pid == pid) s.insert(e.n.begin(), e.n.end());
  return s;
}

/// Mass of a part from its elements (hexahedra are boxes here; shells flat quads).
Real part_mass(const model::Model& m, Id pid) {
  const auto x = coordinates(m);
  const model::Part* part = nullptr;
  for (const auto& p : m.parts)
    if (p.pid == pid) part = &p;
  Real rho = 0.0, t = 0.0;
  for (const auto& mat : m.materials)
    if (model::material_id(mat) == part->mid) std::visit([&](const auto& mm) { rho = mm.ro; }, mat);
  for (const auto& s : m.shell_sections)
    if (s.secid == part->secid) t = s.t[0];
  Real mass = 0.0;
  for (const auto& e : m.solids) {
    if (e.pid != pid) continue;
    Vec3 lo = x.at(e.n[0]), hi = lo;
    for (Id n : e.n) lo = lo.cwiseMin(x.at(n)), hi = hi.cwiseMax(x.at(n));
    mass += rho * (hi - lo).prod();
  }
  for (const auto& e : m.shells) {
    if (e.pid != pid) continue;
    const Vec3 d1 = x.at(e.n[2]) - x.at(e.n[0]), d2 = x.at(e.n[3]) - x.at(e.n[1]);
    mass += rho * t * 0.5 * d1.cross(d2).norm();
  }
  return mass;
}

/// The gap the spec asks for (README "Offsets"; report 3.1): the shell thickness is accounted for
/// by types 3, 5, 10 and 12 only.
Real spec_gap(ContactType type, const std::string& pairing) {
  const bool offset = type == ContactType::surface_to_surface || type == ContactType::nodes_to_surface ||
                      type == ContactType::one_way || type == ContactType::automatic;
  if (!offset || pairing == "solid_on_solid") return 0.0;
  return pairing == "shell_on_shell" || pairing == "node_on_shell" ? 0.10 : 0.05;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string deck_path(const std::string& name) {
  return std::string(SLIDELINE_SOURCE_DIR) + "/examples/sslide/" + name + ".k";
}

TEST(Sslide, NineteenProblemsWithTheirPairings) {
  const auto names = sslide_problem_names();
  ASSERT_EQ(names.size(), 19u);
  for (const auto& name : names) {
    SCOPED_TRACE(name);
    const auto p = make_sslide_problem(name);
    EXPECT_EQ(p.name, name);
    EXPECT_EQ(p.model.contacts.size(), p.pairings.size());
    std::set<std::string> pairings;
    for (const auto& pr : p.pairings) pairings.insert(pr.name);
    std::set<std::string> expected;
    switch (p.type) {
      case ContactType::nodes_to_surface:
      case ContactType::tied_nodes:
      case ContactType::tiebreak_nodes: expected = {"node_on_solid", "node_on_shell"}; break;
      case ContactType::tied_shell_edge: expected = {"node_on_shell"}; break;
      case ContactType::tiebreak_surface: expected = {"solid_on_solid"}; break;
      default: expected = {"solid_on_solid", "shell_on_solid", "shell_on_shell"};
    }
    EXPECT_EQ(pairings, expected);
    EXPECT_EQ(p.model.termination.endtim, 0.5);
    EXPECT_EQ(p.model.timestep.tssfac, p.type == ContactType::automatic ? 0.6 : 0.9);
    ASSERT_TRUE(p.model.damping_global.has_value());
    EXPECT_DOUBLE_EQ(p.model.damping_global->valdmp, 2 * 0.05 * 150);
  }
  EXPECT_THROW(make_sslide_problem("sslide4"), InputError);
}

TEST(Sslide, GeometryOfEveryPairing) {
  for (const auto& name : sslide_problem_names()) {
    const auto p = make_sslide_problem(name);
    const auto x = coordinates(p.model);
    const int cells = static_cast<int>(p.cells);
    for (const auto& pr : p.pairings) {
      SCOPED_TRACE(name + " " + pr.name);
      // Node counts: lower block 4 x 3 x (2 per unit length in z + 1); upper body 3 per unit length.
      const auto lower = part_nodes(p.model, pr.lower_part);
      const auto upper = part_nodes(p.model, pr.upper_part);
      EXPECT_EQ(lower.size(), 4u * 3u * (2u * cells + 1u));
      const bool solid_upper = pr.name == "solid_on_solid";
      EXPECT_EQ(upper.size(), (solid_upper ? 12u : 4u) * (3u * cells + 1u));
      // Upper mass 0.01 per unit cell, from the elements.
      EXPECT_NEAR(part_mass(p.model, pr.upper_part), 0.01 * p.cells, 1e-12);
      EXPECT_NEAR(pr.upper_mass, 0.01 * p.cells, 1e-15);
      // The master surface: the lower block's top face (y = 1), its grid lines in x and z.
      std::set<Real> mx, mz;
      for (Id n : lower)
        if (x.at(n).y() == 1.0) mx.insert(x.at(n).x()), mz.insert(x.at(n).z());
      ASSERT_EQ(mx.size(), 4u);
      // Contact nodes of the upper body: its lowest nodes. Gap per the spec.
      Real ymin = 1e9;
      for (Id n : upper) ymin = std::min(ymin, x.at(n).y());
      EXPECT_NEAR(ymin - 1.0, spec_gap(p.type, pr.name), 1e-12);
      EXPECT_NEAR(pr.gap, spec_gap(p.type, pr.name), 1e-12);
      Real xlo = 1e9, xhi = -1e9, zlo = 1e9, zhi = -1e9;
      for (Id n : upper) {
        const Vec3 v = x.at(n);
        xlo = std::min(xlo, v.x()), xhi = std::max(xhi, v.x()), zlo = std::min(zlo, v.z()), zhi = std::max(zhi, v.z());
        if (v.y() != ymin) continue;
        // Not on a master node or edge: off every grid line of the master face in x and in z.
        for (Real l : mx) EXPECT_GT(std::abs(v.x() - l), 1e-3) << "slave node " << n << " on master line x=" << l;
        for (Real l : mz) EXPECT_GT(std::abs(v.z() - l), 1e-3) << "slave node " << n << " on master line z=" << l;
      }
      // Seated, and able to slide 0.45 in +x without leaving the lower block.
      EXPECT_GE(xlo, *mx.begin());
      EXPECT_LE(xhi + 0.45, *mx.rbegin());
      EXPECT_GT(zlo, *mz.begin());
      EXPECT_LT(zhi, *mz.rbegin());
      // Monitor: a contact node near the centre, the segment under it, exact interpolation weights.
      const auto& mon = pr.monitor;
      EXPECT_EQ(x.at(mon.slave_node).y(), ymin);
      EXPECT_LT(std::abs(x.at(mon.slave_node).x() - 0.5 * (xlo + xhi)), 0.34);
      EXPECT_LT(std::abs(x.at(mon.slave_node).z() - 0.5 * (zlo + zhi)), 0.34);
      Vec3 under = Vec3::Zero();
      Real wsum = 0.0;
      for (int k = 0; k < 4; ++k) {
        EXPECT_GE(mon.weights[k], 0.0);
        EXPECT_TRUE(lower.count(mon.master_nodes[k]));
        under += mon.weights[k] * x.at(mon.master_nodes[k]);
        wsum += mon.weights[k];
      }
      EXPECT_NEAR(wsum, 1.0, 1e-14);
      EXPECT_NEAR(under.x(), x.at(mon.slave_node).x(), 1e-12);
      EXPECT_NEAR(under.z(), x.at(mon.slave_node).z(), 1e-12);
      // Segment normal (x2 - x0) x (x3 - x1) points up, towards the slave.
      const Vec3 nrm = (x.at(mon.master_nodes[2]) - x.at(mon.master_nodes[0]))
                           .cross(x.at(mon.master_nodes[3]) - x.at(mon.master_nodes[1]));
      EXPECT_GT(nrm.y(), 0.0);
      const auto& hist = p.model.database.history_nodes;
      EXPECT_NE(std::find(hist.begin(), hist.end(), mon.slave_node), hist.end());
      for (Id n : mon.master_nodes) EXPECT_NE(std::find(hist.begin(), hist.end(), n), hist.end());
      // The path: a row of top-face segments along x that holds the t = 0 segment and reaches
      // past where the slave can slide (0.45), every node recorded, coordinates as in the model.
      EXPECT_EQ((mon.slave_x0 - x.at(mon.slave_node)).norm(), 0.0);
      ASSERT_FALSE(mon.path.empty());
      bool holds_start = false;
      for (const auto& seg : mon.path) {
        holds_start = holds_start || seg.nodes == mon.master_nodes;
        for (int k = 0; k < 4; ++k) {
          EXPECT_NE(std::find(hist.begin(), hist.end(), seg.nodes[k]), hist.end());
          EXPECT_EQ((seg.x0[k] - x.at(seg.nodes[k])).norm(), 0.0);
        }
      }
      EXPECT_TRUE(holds_start);
      EXPECT_GE(mon.path.back().x0[2].x(), mon.slave_x0.x() + 0.45);
      // The leading edge: a recorded contact node at the upper body's largest x, in the slave's z.
      EXPECT_NE(std::find(hist.begin(), hist.end(), mon.leading_node), hist.end());
      EXPECT_EQ((mon.leading_x0 - x.at(mon.leading_node)).norm(), 0.0);
      EXPECT_EQ(mon.leading_x0.x(), xhi);
      EXPECT_EQ(mon.leading_x0.y(), ymin);
      EXPECT_EQ(mon.leading_x0.z(), mon.slave_x0.z());
      // Named contact and supports.
      const auto c = std::find_if(p.model.contacts.begin(), p.model.contacts.end(),
                                  [&](const model::Contact& cc) { return cc.title == pr.name; });
      ASSERT_NE(c, p.model.contacts.end());
      EXPECT_EQ(c->type, p.type);
      EXPECT_EQ(c->enforcement, p.enforcement);
      EXPECT_EQ(pr.bottom_support, pr.name + "_bottom");
      int spcs = 0;
      for (const auto& s : p.model.spcs) spcs += (s.title == pr.bottom_support && s.dof[1] == 1) ||
                                                (s.title == pr.right_support && s.dof[0] == 1);
      EXPECT_EQ(spcs, 2);
    }
  }
}

TEST(Sslide, ContactParametersFollowTheSpec) {
  for (const auto& name : sslide_problem_names()) {
    SCOPED_TRACE(name);
    const auto p = make_sslide_problem(name);
    for (const auto& c : p.model.contacts) {
      if (p.enforcement == model::Enforcement::penalty) {
        EXPECT_EQ(c.sfs, name == "sslide9pt" ? 100.0 : 10.0);
        EXPECT_EQ(c.sfm, c.sfs);
      }
      const bool frictional = p.idealization == SslideIdealization::frictional;
      if (frictional) {
        EXPECT_EQ(c.fs, 0.30);
        EXPECT_EQ(c.fd, 0.25);
        EXPECT_EQ(c.dc, p.enforcement == model::Enforcement::lagrange ? 1.3 : 2.0);
      }
      if (p.idealization == SslideIdealization::frictionless || p.idealization == SslideIdealization::tied)
        EXPECT_EQ(c.fs, 0.0);
      if (c.type == ContactType::nodes_to_surface) EXPECT_EQ(c.radius, 0.05);
      if (c.type == ContactType::one_way) EXPECT_EQ(c.sliding_only_option, name == "sslide10psl");
    }
  }
  const auto rigid = make_sslide_problem("sslide10lr");
  const auto& skin = rigid.pairings.back();
  ASSERT_EQ(skin.name, "shell_on_shell");
  ASSERT_NE(skin.skin_part, 0);
  for (const auto& part : rigid.model.parts)
    if (part.pid == skin.skin_part)
      for (const auto& mat : rigid.model.materials)
        if (model::material_id(mat) == part.mid) EXPECT_TRUE(std::holds_alternative<model::MatRigid>(mat));
  // No support on a rigid-body node (LS-DYNA ignores them): the right support skips the skin.
  const auto skin_nodes = part_nodes(rigid.model, skin.skin_part);
  for (const auto& set : rigid.model.node_sets)
    if (set.title == skin.right_support) {
      EXPECT_FALSE(set.nodes.empty());
      for (Id n : set.nodes) EXPECT_FALSE(skin_nodes.count(n)) << "node " << n;
    }
}

TEST(Sslide, RelativeDisplacementRemovesCommonMotion) {
  const auto p = make_sslide_problem("sslide3p");
  const auto& mon = p.pairings.front().monitor;
  const Vec3 shift(0.3, -0.2, 0.1);
  EXPECT_NEAR(relative_displacement(mon, shift, {shift, shift, shift, shift}).norm(), 0.0, 1e-15);
  const Vec3 d(1e-3, -2e-4, 0.0);
  EXPECT_NEAR((relative_displacement(mon, shift + d, {shift, shift, shift, shift}) - d).norm(), 0.0, 1e-15);
}

TEST(Sslide, TrackedRelativeDisplacementReprojectsOntoTheCurrentSegment) {
  const auto p = make_sslide_problem("sslide1k");
  const auto& mon = p.pairings.front().monitor;
  ASSERT_GE(mon.path.size(), 2u);
  std::vector<std::array<Vec3, 4>> u(mon.path.size());
  const Vec3 shift(0.3, -0.2, 0.1);
  for (auto& s : u) s.fill(shift);
  // Common motion only: nothing relative.
  EXPECT_NEAR(tracked_relative_displacement(mon, shift, u).norm(), 0.0, 1e-14);
  // The slave slides 0.6 in x (onto the next segment) on a translating master: the slip, no gap change.
  const Vec3 slide(0.6, 0.0, 0.0);
  EXPECT_NEAR((tracked_relative_displacement(mon, shift + slide, u) - slide).norm(), 0.0, 1e-12);
  // The master surface tilts about z through the slave's start (u_y = s (x - x_s)); the slave
  // slides 0.6 and stays ON the tilted surface: no gap change, whereas the t = 0 weights
  // (extrapolating the first segment) report the tilt times the distance slid.
  const Real slope = 1e-3;
  for (std::size_t s = 0; s < mon.path.size(); ++s)
    for (int k = 0; k < 4; ++k) u[s][k] = Vec3(0.0, slope * (mon.path[s].x0[k].x() - mon.slave_x0.x()), 0.0);
  const Vec3 on_surface(0.6, slope * 0.6, 0.0);
  EXPECT_NEAR(tracked_relative_displacement(mon, on_surface, u).y(), 0.0, 1e-6 * slope);
  std::array<Vec3, 4> first{};
  for (std::size_t s = 0; s < mon.path.size(); ++s)
    if (mon.path[s].nodes == mon.master_nodes) first = u[s];
  EXPECT_NEAR(relative_displacement(mon, on_surface, first).y(), slope * 0.6, 1e-9);
}

TEST(Sslide, CommittedDecksMatchTheGenerator) {
  for (const auto& name : sslide_problem_names()) {
    SCOPED_TRACE(name);
    const auto path = deck_path(name);
    ASSERT_TRUE(std::filesystem::exists(path)) << path << " is missing: blockcontact generate --all -o examples/sslide";
    EXPECT_TRUE(read_text(path) == write_keyword_string(make_sslide_problem(name).model))
        << path << " differs from the generator: blockcontact generate --all -o examples/sslide";
  }
}

TEST(Sslide, CommittedDecksReadBackAndCheck) {
  for (const auto& name : sslide_problem_names()) {
    SCOPED_TRACE(name);
    std::vector<Diagnostic> warnings;
    const auto m = read_keyword_file(deck_path(name), &warnings);
    EXPECT_TRUE(warnings.empty());
    for (const auto& w : warnings) ADD_FAILURE() << to_string(w);
    const auto problems = check_references(m);
    for (const auto& d : problems) ADD_FAILURE() << to_string(d);
    EXPECT_EQ(test::model_difference(make_sslide_problem(name).model, m), "");
  }
}

}  // namespace
}  // namespace slideline::scenarios
