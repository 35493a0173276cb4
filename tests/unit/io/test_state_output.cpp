// The state output's fields (docs/output.md, "Nodal states and mesh"): small runs written through
// Hdf5Writer, read back, and checked against closed forms: a free body keeps its initial velocity
// with no acceleration, stress or energy; a homogeneously stretched hexahedron under uniaxial
// stress has sigma_xx = (1 + a) E E_xx / (1 + b)^2, von Mises |sigma_xx| and W = E E_xx^2 / 2; a
// stretched shell plate's mid-surface stress is the plane-stress closed form; part, material ids
// and thickness are the deck's; the XDMF file is well-formed and references every field.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "slideline/element/cell_output.hpp"
#include "slideline/io/hdf5_reader.hpp"
#include "slideline/io/hdf5_writer.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/solver/build.hpp"
#include "slideline/solver/simulation.hpp"
#include "test_support/mesh_fixtures.hpp"

namespace slideline {
namespace {

namespace fs = std::filesystem;
using test_support::grid_node;

fs::path scratch(const std::string& name) {
  const auto dir = fs::temp_directory_path() / "slideline_state_output_tests";
  fs::create_directories(dir);
  return dir / name;
}

/// A unit elastic cube (part 1, material 1: rho 1, E 1000, nu 0.3) and, beside it, the 3 x 3
/// shell plate of mesh_fixtures as part 2 (section 2, material 7, thickness 0.1), node ids + 100.
model::Model cube_and_plate() {
  model::Model m = test_support::hex_grid_model(1, 1, 1);
  model::Model p = test_support::shell_plate_model(2);
  for (auto n : p.nodes) {
    n.id += 100;
    n.x += Vec3(3.0, 0.0, 0.0);
    m.nodes.push_back(n);
  }
  for (auto e : p.shells) {
    e.id += 100;
    for (auto& n : e.n) n += 100;
    m.shells.push_back(e);
  }
  model::Part part = p.parts.front();
  part.secid = 2;
  part.mid = 7;
  m.parts.push_back(part);
  auto sec = p.shell_sections.front();
  sec.secid = 2;
  m.shell_sections.push_back(sec);
  m.materials.push_back(model::MatElastic{7, 0.1, 1000.0, 0.1, "", {}});
  return m;
}

/// Runs `m` with states every `d3plot` into `name`.h5; returns the HDF5 path.
fs::path run(model::Model m, Real d3plot, const std::string& name) {
  m.database.d3plot = d3plot;
  const fs::path h5 = scratch(name + ".h5");
  auto sim = build_simulation(m);
  Hdf5Writer w(h5.string());
  sim->run({&w});
  return h5;
}

std::vector<double> read(const fs::path& h5, const std::string& path, std::vector<std::size_t> dims) {
  const Hdf5Dataset d = read_hdf5_dataset(h5.string(), path);
  EXPECT_EQ(d.dims, dims) << path;
  return d.values;
}

std::size_t state_count(const fs::path& h5) { return read_hdf5_dataset(h5.string(), "/states/time").values.size(); }

/// Internal node order: the output's /mesh/node_ids.
std::vector<double> node_ids(const fs::path& h5) { return read_hdf5_dataset(h5.string(), "/mesh/node_ids").values; }

/// Checks that every start tag of `xml` is closed in order (a minimal well-formedness check:
/// the ParaView test opens the file with a real reader).
void expect_balanced_xml(const std::string& xml) {
  const std::regex tag(R"(<(/?)([A-Za-z]+)[^>]*?(/?)>)");
  std::vector<std::string> open;
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), tag); it != std::sregex_iterator(); ++it) {
    const auto& m = *it;
    if (m[1] == "/") {
      ASSERT_FALSE(open.empty()) << "close tag " << m[2] << " without an open one";
      ASSERT_EQ(open.back(), m[2]) << "tags closed out of order";
      open.pop_back();
    } else if (m[3] != "/") {
      open.push_back(m[2]);
    }
  }
  EXPECT_TRUE(open.empty());
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(StateOutput, FreeBodyKeepsItsVelocityWithoutStressAndIdsMatchTheDeck) {
  model::Model m = cube_and_plate();
  const Vec3 v0(1.0, 2.0, -0.5);
  for (const auto& n : m.nodes) m.initial_velocity_nodes.push_back({n.id, v0, Vec3::Zero()});
  m.termination.endtim = 0.02;
  const fs::path h5 = run(m, 0.01, "free_body");
  const std::size_t states = state_count(h5);
  ASSERT_EQ(states, 3u);
  const std::size_t n = m.nodes.size();
  const std::vector<double> t = read_hdf5_dataset(h5.string(), "/states/time").values;
  for (std::size_t s = 0; s < states; ++s) {
    const std::string g = "/states/state_" + std::to_string(s);
    const auto u = read(h5, g + "/displacement", {n, 3});
    const auto v = read(h5, g + "/velocity", {n, 3});
    const auto a = read(h5, g + "/acceleration", {n, 3});
    const auto fc = read(h5, g + "/contact_force", {n, 3});
    for (std::size_t i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(u[3 * i + c], v0[c] * t[s], 1e-12);
        EXPECT_NEAR(v[3 * i + c], v0[c], 1e-12);
        EXPECT_NEAR(a[3 * i + c], 0.0, 1e-9);
        EXPECT_EQ(fc[3 * i + c], 0.0);
      }
    for (const char* set : {"hexahedra", "quadrilaterals"}) {
      const std::size_t cells = std::string(set) == "hexahedra" ? 1 : 9;
      const auto sigma = read(h5, g + "/" + set + "/stress", {cells, 6});
      for (double x : sigma) EXPECT_NEAR(x, 0.0, 1e-9);
      for (const char* f : {"von_mises", "plastic_strain", "energy_density"})
        for (double x : read(h5, g + "/" + set + "/" + f, {cells})) EXPECT_NEAR(x, 0.0, 1e-9) << f;
    }
  }
  // Fixed fields, written once.
  EXPECT_EQ(read(h5, "/mesh/hexahedra_part_id", {1}), std::vector<double>{1.0});
  EXPECT_EQ(read(h5, "/mesh/hexahedra_material_id", {1}), std::vector<double>{1.0});
  EXPECT_EQ(read(h5, "/mesh/quadrilaterals_part_id", {9}), std::vector<double>(9, 2.0));
  EXPECT_EQ(read(h5, "/mesh/quadrilaterals_material_id", {9}), std::vector<double>(9, 7.0));
  EXPECT_EQ(read(h5, "/mesh/quadrilaterals_thickness", {9}), std::vector<double>(9, 0.1));
  EXPECT_FALSE(hdf5_exists(h5.string(), "/mesh/hexahedra_thickness"));
  EXPECT_FALSE(hdf5_exists(h5.string(), "/states/state_0/hexahedra/stress_top"));

  // The XDMF: well-formed, one Time per state, every field of each grid referenced, units stated.
  const std::string xml = slurp(fs::path(h5).replace_extension(".xdmf"));
  expect_balanced_xml(xml);
  const auto count = [&](const std::string& s) {
    std::size_t k = 0;
    for (auto p = xml.find(s); p != std::string::npos; p = xml.find(s, p + 1)) ++k;
    return k;
  };
  EXPECT_EQ(count("<Time Value="), states);
  EXPECT_EQ(count("<Attribute Name=\"velocity\" AttributeType=\"Vector\" Center=\"Node\">"), 2 * states);
  EXPECT_EQ(count("<Attribute Name=\"stress\" AttributeType=\"Tensor6\" Center=\"Cell\">"), 2 * states);
  EXPECT_EQ(count("<Attribute Name=\"stress_top\""), states);  // shells only
  EXPECT_EQ(count("<Attribute Name=\"thickness\""), states);
  EXPECT_EQ(count(":/mesh/quadrilaterals_part_id</DataItem>"), states);  // one dataset, referenced
  EXPECT_EQ(count("<Attribute ") + 1, count("<Information Name=\"units\""));  // + the domain's
}

TEST(StateOutput, UniaxialStressInAStretchedHexahedron) {
  // Every dof driven at constant velocity: x = X + (a X, b Y, b Z) t/T, a homogeneous stretch with
  // (1 + b)^2 = 1 - 2 nu E_xx at t = T, which makes the St. Venant-Kirchhoff stress uniaxial.
  model::Model m = test_support::hex_grid_model(1, 1, 1);
  const Real T = 0.1, E = 1000.0, nu = 0.3, a = 0.01;
  const Real exx = 0.5 * ((1 + a) * (1 + a) - 1.0);
  const Real b = std::sqrt(1.0 - 2.0 * nu * exx) - 1.0;
  model::Curve c;
  c.lcid = 1;
  c.points = {{0.0, 1.0}, {1.0, 1.0}};
  m.curves.push_back(c);
  for (const auto& n : m.nodes)
    for (int dof = 1; dof <= 3; ++dof) {
      model::PrescribedMotion p;
      p.target = model::PrescribedMotion::Target::node;
      p.id = static_cast<Id>(m.prescribed_motions.size() + 1);
      p.nsid = n.id;
      p.dof = dof;
      p.vad = 0;
      p.lcid = 1;
      p.sf = (dof == 1 ? a : b) * n.x[dof - 1] / T;
      p.src = {"stretch.k", 1};
      m.prescribed_motions.push_back(p);
    }
  m.termination.endtim = T;
  const fs::path h5 = run(m, T, "uniaxial");
  ASSERT_EQ(state_count(h5), 2u);
  const auto sigma = read(h5, "/states/state_1/hexahedra/stress", {1, 6});
  const Real sxx = (1 + a) * E * exx / ((1 + b) * (1 + b));
  EXPECT_NEAR(sigma[0], sxx, 1e-9 * sxx);
  for (int k = 1; k < 6; ++k) EXPECT_NEAR(sigma[k], 0.0, 1e-9 * sxx) << k;
  EXPECT_NEAR(read(h5, "/states/state_1/hexahedra/von_mises", {1})[0], std::abs(sxx), 1e-9 * sxx);
  EXPECT_NEAR(read(h5, "/states/state_1/hexahedra/energy_density", {1})[0], 0.5 * E * exx * exx,
              1e-9 * E * exx * exx);
  // The velocity is the driven one.
  const auto v = read(h5, "/states/state_1/velocity", {8, 3});
  for (std::size_t i = 0; i < 8; ++i) {
    EXPECT_NEAR(v[3 * i], a * m.nodes[i].x[0] / T, 1e-12);
    EXPECT_NEAR(v[3 * i + 1], b * m.nodes[i].x[1] / T, 1e-12);
  }
}

TEST(StateOutput, StretchedShellPlateHasThePlaneStressClosedForm) {
  // The plate (x-z plane) driven at vx = a X / T, vz = c Z / T, vy = 0: a membrane state, the same
  // at the mid surface and at the outer points; the hypoelastic law integrates the logarithmic
  // strains (midpoint rule, error ~ (a dt)^2), so sigma_xx = E/(1 - nu^2) (ln(1+a) + nu ln(1+c)).
  model::Model m = test_support::shell_plate_model(1);
  const Real T = 0.05, E = 1000.0, nu = 0.1, a = 1e-3, c = -4e-4;
  model::Curve curve;
  curve.lcid = 1;
  curve.points = {{0.0, 1.0}, {1.0, 1.0}};
  m.curves.push_back(curve);
  for (const auto& n : m.nodes)
    for (int dof = 1; dof <= 3; ++dof) {
      model::PrescribedMotion p;
      p.target = model::PrescribedMotion::Target::node;
      p.id = static_cast<Id>(m.prescribed_motions.size() + 1);
      p.nsid = n.id;
      p.dof = dof;
      p.lcid = 1;
      p.sf = (dof == 1 ? a * n.x[0] : dof == 3 ? c * n.x[2] : 0.0) / T;
      p.src = {"plate.k", 1};
      m.prescribed_motions.push_back(p);
    }
  m.termination.endtim = T;
  const fs::path h5 = run(m, T, "plate");
  const Real exx = std::log1p(a), ezz = std::log1p(c);
  const Real sxx = E / (1 - nu * nu) * (exx + nu * ezz), szz = E / (1 - nu * nu) * (ezz + nu * exx);
  const std::string g = "/states/state_1/quadrilaterals/";
  for (const char* f : {"stress", "stress_bottom", "stress_top"}) {
    const auto s = read(h5, g + f, {9, 6});
    for (std::size_t e = 0; e < 9; ++e) {
      EXPECT_NEAR(s[6 * e + 0], sxx, 1e-6 * sxx) << f;
      EXPECT_NEAR(s[6 * e + 2], szz, 1e-6 * sxx) << f;
      for (int k : {1, 3, 4, 5}) EXPECT_NEAR(s[6 * e + k], 0.0, 1e-6 * sxx) << f << " " << k;
    }
  }
  const Real vm = std::sqrt(sxx * sxx - sxx * szz + szz * szz);
  for (double x : read(h5, g + "von_mises", {9})) EXPECT_NEAR(x, vm, 1e-6 * vm);
  const Real w = 0.5 * (sxx * sxx - 2 * nu * sxx * szz + szz * szz) / E;  // sigma : C^-1 : sigma / 2
  for (double x : read(h5, g + "energy_density", {9})) EXPECT_NEAR(x, w, 1e-5 * w);
  // The thickness does not change here: no current_thickness field, the section's under /mesh.
  EXPECT_FALSE(hdf5_exists(h5.string(), g + "current_thickness"));

  // With *CONTROL_SHELL ISTUPD = 1 the elastic plane-stress thinning d ln t = -nu / (1 - nu)
  // (d_xx + d_zz) integrates to t = t0 exp(-nu / (1 - nu) (ln(1 + a) + ln(1 + c))) (the plate's
  // in-plane strains are uniform): each state's current_thickness holds it (to 1e-3 of the change,
  // the rate's midpoint integration), the section's t0 stays under /mesh, and the XDMF lists it.
  m.shell_istupd = 1;
  const fs::path h5u = run(m, T, "plate_istupd");
  const Real t0 = read(h5u, "/mesh/quadrilaterals_thickness", {9})[0];
  const Real t_cf = t0 * std::exp(-nu / (1.0 - nu) * (exx + ezz));
  const auto first = read(h5u, "/states/state_0/quadrilaterals/current_thickness", {9});
  const auto last = read(h5u, g + "current_thickness", {9});
  std::printf("thickness t0 %.12g, after %.12g (closed form %.12g, change %.3g)\n", t0, last[0], t_cf, t_cf - t0);
  for (std::size_t e = 0; e < 9; ++e) {
    EXPECT_EQ(first[e], t0);
    EXPECT_NEAR(last[e], t_cf, 1e-3 * std::abs(t_cf - t0));
  }
  for (double x : read(h5u, "/mesh/quadrilaterals_thickness", {9})) EXPECT_EQ(x, t0);
  const std::string xml = slurp(fs::path(h5u).replace_extension(".xdmf"));
  EXPECT_NE(xml.find("Name=\"current_thickness\""), std::string::npos);
}

TEST(StateOutput, NodalContactForcesAddUpToTheInterfaceForce) {
  // sslide3p to t = 0.2 (the normal load is on): on the upper solid block (part 2) the nodal
  // contact forces add up to the interface's slave force at the same time, and over the whole
  // model to zero (penalty forces act in equal and opposite pairs).
  model::Model m = read_keyword_file(std::string(SLIDELINE_SOURCE_DIR) + "/examples/sslide/sslide3p.k");
  m.termination.endtim = 0.2;
  const fs::path h5 = run(m, 0.1, "sslide3p");
  ASSERT_EQ(state_count(h5), 3u);
  const std::size_t n = node_ids(h5).size();
  const auto fc = read(h5, "/states/state_2/contact_force", {n, 3});
  const Hdf5Dataset hex = read_hdf5_dataset(h5.string(), "/mesh/hexahedra");
  const auto part = read_hdf5_dataset(h5.string(), "/mesh/hexahedra_part_id").values;
  std::vector<char> upper(n, 0);
  for (std::size_t e = 0; e < part.size(); ++e)
    if (part[e] == 2.0)
      for (int k = 0; k < 8; ++k) upper[static_cast<std::size_t>(hex.values[8 * e + k])] = 1;
  Vec3 on_upper = Vec3::Zero(), total = Vec3::Zero();
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) {
      total[c] += fc[3 * i + c];
      if (upper[i]) on_upper[c] += fc[3 * i + c];
    }
  const auto slave = read_hdf5_dataset(h5.string(), "/interfaces/solid_on_solid/slave_force").values;
  const Vec3 f(slave[slave.size() - 3], slave[slave.size() - 2], slave[slave.size() - 1]);
  EXPECT_GT(f[1], 5.0);  // the block is pressed down with a load of 10
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(on_upper[c], f[c], 1e-9 * f.norm()) << c;
    EXPECT_NEAR(total[c], 0.0, 1e-9 * f.norm()) << c;
  }
}

TEST(StateOutput, RepeatedSupportNamesGetUniqueChannels) {
  // Two *BOUNDARY_PRESCRIBED_MOTION_NODE cards without _ID on node 1 are both "motion_1": the
  // second channel is motion_1_2 (the HDF5 writer refused the repeated dataset before).
  model::Model m = test_support::hex_grid_model(1, 1, 1);
  model::Curve c;
  c.lcid = 1;
  c.points = {{0.0, 0.0}, {1.0, 0.0}};
  m.curves.push_back(c);
  for (int dof : {1, 2}) {
    model::PrescribedMotion p;
    p.target = model::PrescribedMotion::Target::node;
    p.nsid = 1;
    p.dof = dof;
    p.lcid = 1;
    p.src = {"motion.k", dof};
    m.prescribed_motions.push_back(p);
  }
  const fs::path h5 = run(m, 0.01, "repeated_names");
  EXPECT_TRUE(hdf5_exists(h5.string(), "/supports/motion_1/reaction"));
  EXPECT_TRUE(hdf5_exists(h5.string(), "/supports/motion_1_2/reaction"));
}

/// A stand-in law state with an effective plastic strain (as the J2 law's will have).
struct PlasticState {
  Real eps = 0.25;
};
struct ElasticState {};

TEST(StateOutput, PlasticStrainIsTheStatesEpsWhereItHasOne) {
  EXPECT_EQ(plastic_strain_of(PlasticState{}), 0.25);
  EXPECT_EQ(plastic_strain_of(ElasticState{}), 0.0);
  struct LaneState {
    Lanes eps = Lanes::LinSpaced(kLanes, 0.0, kLanes - 1.0);
  };
  EXPECT_EQ(plastic_strain_of(LaneState{}, 3), 3.0);
  EXPECT_DOUBLE_EQ(von_mises({1.0, 0.0, 0.0, 0.0, 0.0, 0.0}), 1.0);
  EXPECT_DOUBLE_EQ(von_mises({0.0, 0.0, 0.0, 1.0, 0.0, 0.0}), std::sqrt(3.0));
}

}  // namespace
}  // namespace slideline
