#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "slideline/io/keyword_reader.hpp"
#include "slideline/io/keyword_writer.hpp"
#include "slideline/solver/validate_model.hpp"
#include "unit/io/model_equal.hpp"

namespace slideline {
namespace {

/// A model with every card the writer knows, every field away from its default, and reals that
/// do not fit 10 columns (thirds, tiny and huge exponents), so that lossless writing is exercised.
model::Model full_model() {
  using namespace model;
  Model m;
  m.title = "round trip, every card";
  for (int i = 0; i < 12; ++i)
    m.nodes.push_back({100 + i, Vec3(i / 3.0, -1.51 * i, 1e-17 * i), i % 3, i % 2});
  m.nodes.push_back({99999999, Vec3(123456789.125, -0.0, 7.0), 0, 0});  // id too wide for 8 columns
  m.solids.push_back({1, 1, {100, 101, 102, 103, 104, 105, 106, 107}});
  m.shells.push_back({2, 2, {108, 109, 110, 111}});
  m.parts.push_back({1, "upper block", 1, 1, 0, 1, {}});
  m.parts.push_back({2, "", 2, 2, 0, 0, {}});
  m.parts.push_back({3, "rigid", 2, 3, 0, 0, {}});
  m.solid_sections.push_back({1, 1, {}});
  m.shell_sections.push_back({2, 2, 5.0 / 6.0, 5, 1.0, {0.1, 0.2, 0.3, 0.4}, {}});  // PROPT other than 1 warns (output)
  m.materials.emplace_back(MatMooneyRivlin{1, 0.01, 0.1, 909.091, 0.5, "rubber", {}});
  m.materials.emplace_back(MatElastic{2, 0.1, 1000.0, 0.1, "", {}});
  m.materials.emplace_back(MatRigid{3, 0.1, 1000.0, 0.3, 1.0, 4, 7, "master shells", {}});
  m.hourglasses.push_back({1, 10, 0.15, 1.4, 0.07, {}});
  m.control_hourglass = {2, 0.05};
  m.bulk_viscosity = {1.25, 0.05};
  m.node_sets.push_back({1, "bottom", {100, 101, 102, 103, 104, 105, 106, 107, 108}, {}});
  m.node_sets.push_back({2, "", {109}, {}});
  m.segment_sets.push_back({1, "top", {{100, 101, 102, 103}, {104, 105, 106, 106}}, {}});
  m.part_sets.push_back({1, "loaded", {1, 2}, {}});
  m.spcs.push_back({0, "", 1, 0, {0, 1, 0, 0, 0, 0}, {}});
  m.spcs.push_back({7, "right face", 2, 0, {1, 0, 0, 1, 1, 1}, {}});
  m.spcs.push_back({0, "", 103, 0, {1, 1, 1, 0, 0, 0}, {}, true});  // *BOUNDARY_SPC_NODE
  m.spcs.push_back({9, "one node", 104, 0, {0, 0, 1, 0, 0, 0}, {}, true});
  m.nodal_loads.push_back({false, 105, 2, 1, -2.5, 0, {}, {}});
  m.nodal_loads.push_back({true, 1, 6, 2, 0.125, 0, {}, {}});
  m.prescribed_motions.push_back({3, "pull", 2, 3, 0, 1, 2.5, 0, 0.45, 0.01, {}});
  m.prescribed_motions.push_back({0, "", 1, 1, 2, 2, 1.0, 0, 1e28, 0.0, {}});
  // The _NODE and _RIGID forms (NID, PID in the first field), with and without _ID.
  m.prescribed_motions.push_back({0, "", 100, 2, 0, 1, -0.5, 0, 1e28, 0.0, {}, PrescribedMotion::Target::node});
  m.prescribed_motions.push_back({4, "node drive", 101, 3, 1, 2, 2.0, 0, 0.3, 0.1, {}, PrescribedMotion::Target::node});
  m.prescribed_motions.push_back({0, "", 3, 3, 0, 1, 1.5, 0, 1e28, 0.0, {}, PrescribedMotion::Target::rigid});
  m.prescribed_motions.push_back({9, "punch", 3, 1, 2, 2, 0.25, 0, 0.4, 0.05, {}, PrescribedMotion::Target::rigid});
  m.body_loads.push_back({Axis::y, 1, 10.0, 0, 0.0, 0.0, 0.0, 0, {}});
  m.body_loads.push_back({Axis::x, 2, -3.1, 0, 0.5, 0.25, 1.0 / 7.0, 0, {}});
  m.body_loads.push_back({Axis::z, 2, 1e-300, 0, 0.0, 0.0, 0.0, 0, {}});
  m.body_load_parts = LoadBodyParts{1, {}};
  m.curves.push_back({1, "y ramp", 0, 1.0, 1.0, 0.0, 0.0, 0, {{0.0, 0.0}, {0.1, 1.0}, {1.0 / 3.0, 1.0}}, {}});
  m.curves.push_back({2, "", 1, 2.0, 0.5, 0.01, -0.02, 0, {{0.0, 0.0}, {0.3, 0.0}, {0.4, 1.0}}, {}});
  m.boxes.push_back({1, "upper half", {-1.0, 0.5, -1.0}, {2.0, 1.0 / 3.0 + 1.0, 2.0}, {}});
  m.boxes.push_back({2, "", {0.0, -1e-3, 0.0}, {1.5, 1.0, 1.02}, {}});
  {
    InitialVelocity iv;  // every field, the exempted card included
    iv.nsid = 1;
    iv.nsidex = 2;
    iv.boxid = 1;
    iv.irigid = -1;
    iv.icid = 4;
    iv.v = Vec3(1.0 / 3.0, -2.5, 1e-9);
    iv.vr = Vec3(0.0, 0.0, 12.5);
    iv.ve = Vec3(-1.0, 0.0, 0.125);
    iv.vre = Vec3(3.0, 0.0, 0.0);
    m.initial_velocities.push_back(iv);
    iv = InitialVelocity{};
    iv.v = Vec3(0.0, -7.0, 0.0);  // NSID = 0 (all nodes), no exempted card
    m.initial_velocities.push_back(iv);
    InitialVelocityGeneration g;
    g.id = 2;
    g.styp = 2;
    g.omega = 100.0 / 7.0;
    g.v = Vec3(1.0, -2.0, 3.0);
    g.ivatn = 1;
    g.icid = 3;
    g.xc = Vec3(0.5, 0.25, -1.0);
    g.n = Vec3(0.0, 0.6, 0.8);
    g.phase = 1;
    g.irigid = 1;
    m.initial_velocity_generations.push_back(g);
    m.initial_velocity_nodes.push_back({105, Vec3(0.0, 0.0, -1.0), Vec3::Zero()});
    m.initial_velocity_nodes.push_back({99999999, Vec3(1e20, 2.0, 0.1), Vec3(0.5, -0.5, 1.0 / 3.0)});
  }
  m.damping_global = DampingGlobal{0, 15.0, {1, 1, 1, 0, 0, 0}, {}};
  m.damping_parts.push_back({1, 2, 0.5, 0, false, {}, {}});
  m.damping_parts.push_back({1, 2, 0.25, 1, true, {0.5, 0.5, 0.5, 1.0, 1.0, 1.0}, {}});
  m.damping_stiffness.push_back({2, -1.0 / 3.0e4, false, {}});
  m.damping_stiffness.push_back({1, -2.5e-5, true, {}});
  m.termination = {0.5, 100000, 2e-4, 7.5, 12.5, {}};
  m.timestep = {1e-5, 0.6, 1, 0.0, -1e-6, 2, 1, {}};  // MS1ST = 1: mass scaled once; TSLIMT != 0 is refused
  // Values the reader accepts (0 in ISLCHK / ORIEN would read back as their default 1; THKCHG 1 is
  // read and written back, other values are refused, RWPNAL warns, ENMASS 0, 1, 2 are read and
  // written back: docs/contact.md, "Contact card fields").
  m.control_contact = {0.2, 0.0, 1, 1, 2, 1, 1, 2};
  m.shell_esort = 1;  // *CONTROL_SHELL: ESORT, ISTUPD, INTGRD are stored and written back
  m.shell_istupd = 4;
  m.shell_intgrd = 1;
  m.database = {0.001, 0.002, 0.003, 0.004, 0.05, {100, 105, 109}};

  // One contact per DYNA3D type, every enforcement and option.
  const auto contact = [](ContactType t, Enforcement e) {
    Contact c;
    c.type = t;
    c.enforcement = e;
    c.ssid = 1;
    c.msid = 1;
    c.sstyp = 0;
    c.mstyp = 0;
    c.bt = 0.01;
    c.dt = 0.49;
    // What the reader accepts for this type (docs/contact.md, "Contact card fields"): friction
    // where the interface slides, penalty scales where it has springs (SFM apart from SFS on the
    // two-pass types only), thickness where it offsets; VDC, PENCHK, FSF and VSF stay at their
    // defaults (refused otherwise: test_keyword_zero_defaults.cpp); SOFT, SOFSCL and VC below.
    const bool tied = t == ContactType::tied_surface || t == ContactType::tied_nodes ||
                      t == ContactType::tied_shell_edge;
    const bool tiebreak = t == ContactType::tiebreak_nodes || t == ContactType::tiebreak_surface;
    const bool slides = !tied && t != ContactType::sliding_only;
    if (slides) {
      c.fs = 0.3;
      c.fd = 0.25;
      c.dc = 2.0;
    }
    if (e == Enforcement::penalty && !tied) {
      c.sfs = 10.0;
      c.sfm = t == ContactType::surface_to_surface || t == ContactType::one_way ? 100.0 : 10.0;
    }
    if (slides && !tiebreak) {
      const bool single = t == ContactType::automatic;
      c.sst = 0.05;
      c.mst = single ? 0.0 : 0.1;
      c.sfst = 1.5;
      c.sfmt = single ? 1.0 : 0.5;
    }
    return c;
  };
  m.contacts.push_back(contact(ContactType::sliding_only, Enforcement::kinematic));
  m.contacts.push_back(contact(ContactType::tied_surface, Enforcement::kinematic));
  m.contacts.back().cid = 2;
  m.contacts.push_back(contact(ContactType::surface_to_surface, Enforcement::penalty));
  m.contacts.back().title = "solid_on_solid";
  m.contacts.back().penalty_coupling = 1;  // _MORTAR
  m.contacts.back().soft = 1;  // optional card A (SOFT, SOFSCL) and VC, honoured on penalty Type 3
  m.contacts.back().sofscl = 0.2;
  m.contacts.back().vc = 0.5;
  m.contacts.push_back(contact(ContactType::surface_to_surface, Enforcement::lagrange));
  m.contacts.back().cid = 33;
  m.contacts.back().title = "lagrange, with a comma";
  auto c5 = contact(ContactType::nodes_to_surface, Enforcement::penalty);
  c5.sstyp = 4;
  c5.radius = c5.sst;
  m.contacts.push_back(c5);
  m.contacts.push_back(contact(ContactType::tied_nodes, Enforcement::kinematic));
  m.contacts.push_back(contact(ContactType::tied_shell_edge, Enforcement::kinematic));
  auto c8 = contact(ContactType::tiebreak_nodes, Enforcement::penalty);
  c8.nflf = 1.0;
  c8.sflf = 1e4;
  c8.nen = 3.0;
  c8.mes = 1.5;
  m.contacts.push_back(c8);
  auto c9 = contact(ContactType::tiebreak_surface, Enforcement::penalty);
  c9.nfls = c9.nflf = 9.0;
  c9.sfls = c9.sflf = 1e4;
  m.contacts.push_back(c9);
  auto c10 = contact(ContactType::one_way, Enforcement::penalty);
  c10.sliding_only_option = true;
  c10.penalty_coupling = 1;
  m.contacts.push_back(c10);
  m.contacts.push_back(contact(ContactType::one_way, Enforcement::lagrange));
  m.contacts.push_back(contact(ContactType::automatic, Enforcement::penalty));
  auto c12 = contact(ContactType::automatic, Enforcement::penalty);
  c12.automatic_general = true;
  c12.sboxid = 1;  // domain limiting (*DEFINE_BOX)
  c12.mboxid = 2;
  m.contacts.push_back(c12);
  return m;
}

void expect_same(const model::Model& a, const model::Model& b) {
  const std::string diff = test::model_difference(a, b);
  EXPECT_TRUE(diff.empty()) << diff;
}

TEST(KeywordRoundTrip, WrittenModelReadsBackIdentical) {
  const auto m = full_model();
  const std::string text = write_keyword_string(m);
  std::vector<Diagnostic> warnings;
  const auto back = read_keyword_string(text, "written.k", &warnings);
  // full_model() sets every *CONTROL_TIMESTEP field; the reader warns for the three that only
  // choose the step and are not honoured (DTINIT, ISDO; DT2MS and LCTM are the builder's).
  // Anything else is unexpected.
  int not_honoured = 0;
  for (const auto& w : warnings) {
    if (w.message.find("is read but not honoured") != std::string::npos)
      ++not_honoured;
    else
      ADD_FAILURE() << to_string(w);
  }
  EXPECT_EQ(not_honoured, 2);
  expect_same(m, back);
  EXPECT_EQ(back.contacts.size(), 13u);
  EXPECT_TRUE(check_references(back).empty()) << to_string(check_references(back).front());
  // Every card is located.
  EXPECT_GT(back.parts[0].src.line, 0);
  EXPECT_GT(back.contacts[12].src.line, back.contacts[11].src.line);
}

TEST(KeywordRoundTrip, ComparisonSeesAChangedField) {
  const auto m = full_model();
  EXPECT_TRUE(m == full_model());
  auto radius = m;
  radius.contacts[4].radius = 0.06;
  EXPECT_FALSE(m == radius);
  auto coordinate = m;  // one ulp of one coordinate: the comparison is exact
  coordinate.nodes[3].x[1] = std::nextafter(coordinate.nodes[3].x[1], 1.0);
  EXPECT_FALSE(m == coordinate);
  auto material = m;  // a field of one alternative of the material variant
  std::get<model::MatRigid>(material.materials[2]).con2 = 6;
  EXPECT_FALSE(m == material);
  auto coupling = m;  // the mortar coupling is the keyword's _MORTAR
  coupling.contacts[2].penalty_coupling = 0;
  EXPECT_FALSE(m == coupling);
  const std::string mortar = test::model_difference(m, coupling);
  EXPECT_NE(mortar.find("*CONTACT_SURFACE_TO_SURFACE_MORTAR_ID\n  *CONTACT_SURFACE_TO_SURFACE_ID"), std::string::npos)
      << mortar;
  // The difference is named by the line of the written deck that holds the field.
  const std::string d = test::model_difference(m, radius);
  EXPECT_NE(d.find("written, at line"), std::string::npos) << d;
  // Where a card was read (file, line) and a contact keyword's spelling are not content.
  auto located = m;
  located.parts[0].src = {"elsewhere.k", 42};
  located.solids[0].at = {7, 1};
  located.contacts[0].keyword = "*CONTACT_SLIDING_ONLY_ID";
  located.files = {"elsewhere.k"};
  EXPECT_EQ(test::model_difference(m, located), "");
}

TEST(KeywordRoundTrip, FileWriteAndRead) {
  const auto m = full_model();
  const auto path = (std::filesystem::temp_directory_path() / "slideline_roundtrip_test.k").string();
  write_keyword_file(m, path);
  expect_same(m, read_keyword_file(path));
  std::remove(path.c_str());
}

TEST(KeywordRoundTrip, SeedDecksReadWriteReadIdentical) {
  int decks = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(SLIDELINE_SOURCE_DIR) + "/tests/data/decks")) {
    if (entry.path().extension() != ".k") continue;
    SCOPED_TRACE(entry.path().string());
    const auto first = read_keyword_file(entry.path().string());
    const auto text = write_keyword_string(first);
    const auto second = read_keyword_string(text, "rewritten.k", nullptr);
    expect_same(first, second);
    // Writing is a fixed point: the rewritten deck writes out to the same text.
    EXPECT_EQ(text, write_keyword_string(second));
    ++decks;
  }
  EXPECT_GE(decks, 3);
}

}  // namespace
}  // namespace slideline
