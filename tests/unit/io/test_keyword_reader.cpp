#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>

#include "slideline/core/error.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/solver/validate_model.hpp"

namespace slideline {
namespace {

std::string deck_path(const std::string& name) {
  return std::string(SLIDELINE_SOURCE_DIR) + "/tests/data/decks/" + name;
}

TEST(KeywordReader, ReadsSolidSeedDeck) {
  std::vector<Diagnostic> warnings;
  const auto m = read_keyword_file(deck_path("solid_on_solid_type3.k"), &warnings);
  EXPECT_TRUE(warnings.empty()) << to_string(warnings.front());
  EXPECT_EQ(m.title, "sslide3p seed: solid block on solid block (type 3 penalty)");
  ASSERT_EQ(m.nodes.size(), 16u);
  EXPECT_EQ(m.nodes[9].id, 10);
  EXPECT_DOUBLE_EQ(m.nodes[9].x[0], 1.51);
  EXPECT_DOUBLE_EQ(m.nodes[9].x[2], -0.01);
  ASSERT_EQ(m.solids.size(), 2u);
  EXPECT_EQ(m.solids[1].pid, 2);
  EXPECT_EQ(m.solids[1].n[7], 14);  // N1-N4 counter-clockwise seen from N5-N8 (positive volume)
  ASSERT_EQ(m.parts.size(), 2u);
  EXPECT_EQ(m.parts[1].title, "lower block");
  EXPECT_EQ(m.parts[1].hgid, 1);
  EXPECT_GT(m.parts[1].src.line, 0);
  ASSERT_EQ(m.materials.size(), 1u);
  const auto& mr = std::get<model::MatMooneyRivlin>(m.materials[0]);
  EXPECT_DOUBLE_EQ(mr.a, 909.091);
  EXPECT_EQ(mr.title, "rubber");
  EXPECT_DOUBLE_EQ(m.timestep.tssfac, 0.9);
  EXPECT_EQ(m.timestep.isdo, 0);  // blank keeps the default
  EXPECT_EQ(m.control_hourglass.ihq, 10);
  EXPECT_EQ(m.control_contact.shlthk, 1);
  EXPECT_DOUBLE_EQ(m.termination.endtim, 0.5);
  EXPECT_DOUBLE_EQ(m.database.d3plot, 0.05);
  EXPECT_EQ(m.database.history_nodes, (std::vector<Id>{5, 13}));
  ASSERT_EQ(m.hourglasses.size(), 1u);
  EXPECT_EQ(m.hourglasses[0].ihq, 10);
  EXPECT_DOUBLE_EQ(m.hourglasses[0].q2, 0.06);
  ASSERT_EQ(m.node_sets.size(), 2u);
  EXPECT_EQ(m.node_sets[0].title, "lower bottom");
  EXPECT_EQ(m.node_sets[0].nodes, (std::vector<Id>{9, 10, 11, 12}));
  ASSERT_EQ(m.segment_sets.size(), 2u);
  EXPECT_EQ(m.segment_sets[1].segments[0], (std::array<Id, 4>{13, 14, 15, 16}));
  ASSERT_EQ(m.spcs.size(), 2u);
  EXPECT_EQ(m.spcs[0].id, 1);
  EXPECT_EQ(m.spcs[0].title, "lower bottom");
  EXPECT_EQ(m.spcs[0].dof, (std::array<int, 6>{0, 1, 0, 0, 0, 0}));
  EXPECT_EQ(m.spcs[1].dof, (std::array<int, 6>{1, 0, 0, 0, 0, 0}));
  ASSERT_EQ(m.body_loads.size(), 2u);
  EXPECT_EQ(m.body_loads[0].axis, Axis::y);
  EXPECT_DOUBLE_EQ(m.body_loads[1].sf, -3.1);
  ASSERT_TRUE(m.body_load_parts.has_value());
  EXPECT_EQ(m.body_load_parts->psid, 1);
  ASSERT_EQ(m.curves.size(), 2u);
  EXPECT_EQ(m.curves[0].title, "y load");
  EXPECT_EQ(m.curves[1].points.size(), 4u);
  EXPECT_DOUBLE_EQ(m.curves[1].points[2].first, 0.4);
  ASSERT_TRUE(m.damping_global.has_value());
  EXPECT_DOUBLE_EQ(m.damping_global->valdmp, 15.0);
  ASSERT_EQ(m.contacts.size(), 1u);
  const auto& c = m.contacts[0];
  EXPECT_EQ(c.type, model::ContactType::surface_to_surface);
  EXPECT_EQ(c.enforcement, model::Enforcement::penalty);
  EXPECT_EQ(c.title, "solid_on_solid");
  EXPECT_DOUBLE_EQ(c.fs, 0.3);
  EXPECT_DOUBLE_EQ(c.dc, 2.0);
  EXPECT_DOUBLE_EQ(c.sfm, 10.0);
  EXPECT_DOUBLE_EQ(c.dt, 1e20);  // blank death time keeps the default
  EXPECT_EQ(c.src.file, deck_path("solid_on_solid_type3.k"));
  const auto problems = check_references(m);
  EXPECT_TRUE(problems.empty()) << to_string(problems.front());
}

TEST(KeywordReader, ReadsEveryContactCard) {
  std::vector<Diagnostic> warnings;
  const auto m = read_keyword_file(deck_path("shells_all_contacts.k"), &warnings);
  for (const auto& w : warnings) ADD_FAILURE() << to_string(w);
  using model::ContactType;
  using model::Enforcement;
  ASSERT_EQ(m.contacts.size(), 13u);
  const auto& c = m.contacts;
  EXPECT_EQ(c[0].type, ContactType::sliding_only);
  EXPECT_EQ(c[0].enforcement, Enforcement::kinematic);
  EXPECT_EQ(c[1].type, ContactType::tied_surface);
  EXPECT_EQ(c[1].cid, 2);
  EXPECT_EQ(c[1].title, "tied");
  EXPECT_EQ(c[2].type, ContactType::surface_to_surface);
  EXPECT_EQ(c[2].enforcement, Enforcement::lagrange);
  EXPECT_EQ(c[2].title, "lagrange sliding");
  EXPECT_DOUBLE_EQ(c[2].dc, 1.3);
  EXPECT_EQ(c[3].type, ContactType::nodes_to_surface);
  EXPECT_DOUBLE_EQ(c[3].radius, 0.05);  // SST with a node set is the nodal radius
  EXPECT_DOUBLE_EQ(c[3].mst, 0.1);
  EXPECT_EQ(c[4].enforcement, Enforcement::lagrange);
  EXPECT_EQ(c[5].type, ContactType::tied_nodes);
  EXPECT_EQ(c[5].enforcement, Enforcement::kinematic);
  EXPECT_EQ(c[6].type, ContactType::tied_shell_edge);
  EXPECT_EQ(c[6].cid, 7);
  EXPECT_EQ(c[7].type, ContactType::tiebreak_nodes);
  EXPECT_EQ(c[7].enforcement, Enforcement::penalty);
  EXPECT_DOUBLE_EQ(c[7].nflf, 1.0);
  EXPECT_DOUBLE_EQ(c[7].sflf, 1e4);
  EXPECT_DOUBLE_EQ(c[7].nen, 2.0);
  EXPECT_EQ(c[8].type, ContactType::tiebreak_surface);
  EXPECT_EQ(c[8].option, 0);
  EXPECT_DOUBLE_EQ(c[8].nfls, 9.0);
  EXPECT_DOUBLE_EQ(c[8].nflf, 9.0);  // NFLS/SFLS are mirrored into nflf/sflf for type 9
  EXPECT_DOUBLE_EQ(c[8].sflf, 1e4);
  EXPECT_DOUBLE_EQ(c[8].sfs, 100.0);
  EXPECT_EQ(c[9].type, ContactType::one_way);
  EXPECT_TRUE(c[9].sliding_only_option);
  EXPECT_EQ(c[9].title, "one way sliding");
  EXPECT_EQ(c[10].type, ContactType::one_way);
  EXPECT_FALSE(c[10].sliding_only_option);
  EXPECT_EQ(c[10].enforcement, Enforcement::lagrange);
  EXPECT_EQ(c[11].type, ContactType::automatic);
  EXPECT_FALSE(c[11].automatic_general);
  EXPECT_EQ(c[12].type, ContactType::automatic);
  EXPECT_TRUE(c[12].automatic_general);
  EXPECT_DOUBLE_EQ(c[12].fs, 0.1);

  ASSERT_EQ(m.parts.size(), 3u);
  EXPECT_EQ(m.parts[2].title, "");  // a blank *PART heading
  EXPECT_EQ(m.parts[2].mid, 3);
  ASSERT_EQ(m.shell_sections.size(), 1u);
  EXPECT_DOUBLE_EQ(m.shell_sections[0].shrf, 0.8333);
  EXPECT_EQ(m.shell_sections[0].nip, 5);
  EXPECT_DOUBLE_EQ(m.shell_sections[0].t[3], 0.1);
  ASSERT_EQ(m.materials.size(), 3u);
  EXPECT_EQ(std::get<model::MatElastic>(m.materials[1]).title, "stiff");
  EXPECT_DOUBLE_EQ(std::get<model::MatElastic>(m.materials[1]).e, 4000.0);
  const auto& rigid = std::get<model::MatRigid>(m.materials[2]);
  EXPECT_DOUBLE_EQ(rigid.cmo, 1.0);
  EXPECT_EQ(rigid.con2, 7);
  ASSERT_EQ(m.prescribed_motions.size(), 2u);
  EXPECT_EQ(m.prescribed_motions[0].id, 11);
  EXPECT_EQ(m.prescribed_motions[0].title, "pull");
  EXPECT_EQ(m.prescribed_motions[1].vad, 0);
  EXPECT_DOUBLE_EQ(m.prescribed_motions[1].sf, 0.5);
  EXPECT_DOUBLE_EQ(m.prescribed_motions[1].death, 1e28);
  EXPECT_EQ(m.node_sets[0].nodes.size(), 9u);
  EXPECT_EQ(m.nodes.size(), 14u);
  EXPECT_EQ(m.shells.size(), 5u);
  EXPECT_EQ(m.damping_parts.size(), 1u);
  ASSERT_EQ(m.damping_stiffness.size(), 2u);
  EXPECT_EQ(m.damping_stiffness[0].pid, 1);
  EXPECT_DOUBLE_EQ(m.damping_stiffness[0].coef, -2.5e-4);
  EXPECT_FALSE(m.damping_stiffness[0].set);
  EXPECT_EQ(m.damping_stiffness[1].pid, 2);  // a part set
  EXPECT_DOUBLE_EQ(m.damping_stiffness[1].coef, -1e-5);
  EXPECT_TRUE(m.damping_stiffness[1].set);
  const auto problems = check_references(m);
  EXPECT_TRUE(problems.empty()) << to_string(problems.front());
}

TEST(KeywordReader, PrescribedMotionNodeAndRigidForms) {
  // The first field is NID (_NODE) or PID (_RIGID); the _ID heading comes first, as for _SET.
  const auto m = read_keyword_string(
      "*KEYWORD\n"
      "*BOUNDARY_PRESCRIBED_MOTION_NODE\n"
      "        12         3         0         5      -2.0\n"
      "*BOUNDARY_PRESCRIBED_MOTION_RIGID_ID\n"
      "         7punch drive\n"
      "         4         1         2         6       0.5                 0.8       0.1\n"
      "*NODE\n"
      "1,0.0,0.0,0.0\n"
      "*ELEMENT_SHELL\n"
      "1,1,1,1,1,1\n"
      "*END\n",
      "motions.k", nullptr);
  ASSERT_EQ(m.prescribed_motions.size(), 2u);
  const auto& n = m.prescribed_motions[0];
  EXPECT_EQ(n.target, model::PrescribedMotion::Target::node);
  EXPECT_EQ(n.nsid, 12);
  EXPECT_EQ(n.dof, 3);
  EXPECT_EQ(n.vad, 0);
  EXPECT_EQ(n.lcid, 5);
  EXPECT_DOUBLE_EQ(n.sf, -2.0);
  EXPECT_EQ(n.src.line, 3);
  EXPECT_STREQ(n.keyword(), "*BOUNDARY_PRESCRIBED_MOTION_NODE");
  const auto& r = m.prescribed_motions[1];
  EXPECT_EQ(r.target, model::PrescribedMotion::Target::rigid);
  EXPECT_EQ(r.id, 7);
  EXPECT_EQ(r.title, "punch drive");
  EXPECT_EQ(r.nsid, 4);
  EXPECT_EQ(r.vad, 2);
  EXPECT_DOUBLE_EQ(r.death, 0.8);
  EXPECT_DOUBLE_EQ(r.birth, 0.1);
  // References are checked against nodes and parts respectively.
  std::string all;
  for (const auto& d : check_references(m)) all += to_string(d) + "\n";
  EXPECT_NE(all.find("motions.k:3: *BOUNDARY_PRESCRIBED_MOTION_NODE refers to undefined node 12"), std::string::npos) << all;
  EXPECT_NE(all.find("motions.k:6: *BOUNDARY_PRESCRIBED_MOTION_RIGID refers to undefined part 4"), std::string::npos) << all;
}

TEST(KeywordReader, FreeFormatTwoCardSolidAndUnknownKeyword) {
  std::vector<Diagnostic> warnings;
  const auto m = read_keyword_file(deck_path("free_format_cube.k"), &warnings);
  ASSERT_EQ(m.nodes.size(), 8u);
  EXPECT_DOUBLE_EQ(m.nodes[6].x[1], 1.0);
  ASSERT_EQ(m.solids.size(), 1u);
  EXPECT_EQ(m.solids[0].n, (std::array<Id, 8>{1, 2, 3, 4, 5, 6, 7, 8}));
  const auto& e = std::get<model::MatElastic>(m.materials.at(0));
  EXPECT_DOUBLE_EQ(e.e, 2.1e5);  // Fortran D exponent
  EXPECT_DOUBLE_EQ(e.ro, 7.8e-9);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].line, 21);
  EXPECT_NE(warnings[0].message.find("*DATABASE_EXTENT_BINARY"), std::string::npos);
  EXPECT_TRUE(check_references(m).empty());
}

TEST(KeywordReader, MalformedFieldNamesFileLineColumnsFieldAndCard) {
  const std::string deck = "*KEYWORD\n*MAT_ELASTIC\n         1      0.01       xyz       0.1\n*END\n";
  try {
    read_keyword_string(deck, "bad.k", nullptr);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "bad.k:3: columns 21-30 (field E of *MAT_ELASTIC): expected a real number, got 'xyz'");
  }
  try {
    read_keyword_string("*NODE\n1,0.0,abc,0\n", "free.k", nullptr);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "free.k:2: free-format field 3 (field Y of *NODE): expected a real number, got 'abc'");
  }
  EXPECT_THROW(read_keyword_string("*ELEMENT_SOLID\n       1     1.5\n", "x.k", nullptr), InputError);
  EXPECT_THROW(read_keyword_string("*NODE\n1,nan,0,0\n", "x.k", nullptr), InputError);
  EXPECT_THROW(read_keyword_file("/nonexistent/deck.k"), InputError);
}

// A fixed-format number wider than its 10 columns runs into the next field: "0.123456789" as
// ENDTIM would be read as ENDTIM 0.12345678 and ENDCYC 9 by a column reader. Refused, naming the
// columns, the field and the whole text; full-width neighbours and right-justified fields still read.
TEST(KeywordReader, NumberWrittenAcrossAFixedFieldBoundaryIsAnError) {
  try {
    read_keyword_string("*KEYWORD\n*CONTROL_TERMINATION\n0.123456789\n*END\n", "t.k", nullptr);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("t.k:3: columns 1-10 (field ENDTIM of *CONTROL_TERMINATION): '0.123456789' is written "
                        "across the field's end"),
              std::string::npos)
        << what;
  }
  // An integer run into the next field: ENDCYC "100.5" would be ENDCYC 10 and DTMIN 0.5.
  EXPECT_THROW(read_keyword_string("*CONTROL_TERMINATION\n       1.0        100.5\n", "t.k", nullptr),
               InputError);
  // Two full-width numbers side by side, and right-justified fields, are plain fixed format.
  const auto m = read_keyword_string("*CONTROL_TERMINATION\n1.2500E-01         01.0000E-02\n", "t.k", nullptr);
  EXPECT_EQ(m.termination.endtim, 0.125);
  EXPECT_EQ(m.termination.endcyc, 0);
  EXPECT_EQ(m.termination.dtmin, 0.01);
  const auto n = read_keyword_string("*CONTROL_TERMINATION\n       1.0       100\n", "t.k", nullptr);
  EXPECT_EQ(n.termination.endtim, 1.0);
  EXPECT_EQ(n.termination.endcyc, 100);
}

TEST(KeywordReader, UnknownKeywordsAreErrorsNamingCardAndLine) {
  const std::string deck =
      "*KEYWORD\n*FOO_BAR\n1,2\n*CONTACT_SPOTWELD\n1\n*CONTACT_SURFACE_TO_SURFACE\n1,2\n*END\n";
  std::vector<Diagnostic> warnings;
  try {
    read_keyword_string(deck, "w.k", &warnings);
    FAIL() << "no exception";
  } catch (const NotImplementedError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("w.k:2: *FOO_BAR (keyword not in slideline's tables) is not supported\n", 0), 0u) << what;
    EXPECT_NE(what.find("w.k:4: *CONTACT_SPOTWELD (contact type) is not supported"), std::string::npos)
        << what;
  }
  EXPECT_TRUE(warnings.empty());

  warnings.clear();
  ReadOptions ignore;
  ignore.ignore_unsupported = true;
  const auto m = read_keyword_string(deck, "w.k", &warnings, ignore);
  ASSERT_EQ(m.contacts.size(), 1u);
  EXPECT_FALSE(m.contacts[0].sliding_only_option);
  ASSERT_EQ(m.unsupported.size(), 2u);
  EXPECT_EQ(m.unsupported[0].keyword, "*FOO_BAR");
  EXPECT_EQ(m.unsupported[0].id, 1);
  EXPECT_EQ(m.unsupported[1].src.line, 4);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(to_string(warnings[0]).find("w.k:2: *FOO_BAR (keyword not in slideline's tables) dropped"), std::string::npos)
      << to_string(warnings[0]);
  const auto dropped = describe_dropped(m);
  ASSERT_EQ(dropped.size(), 2u);
  EXPECT_EQ(to_string(dropped[1]), "w.k:4: *CONTACT_SPOTWELD (id 1) dropped, 1 card(s)");
}

// _SLIDING_ONLY (no separation) changes the physics: where it means nothing it is an error naming
// the line, never a warning and a run without it.
TEST(KeywordReader, SlidingOnlyOptionOutsideTypeTenIsAnError) {
  try {
    read_keyword_string("*KEYWORD\n*CONTACT_SURFACE_TO_SURFACE_SLIDING_ONLY\n1,2\n*END\n", "w.k");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("w.k:2: *CONTACT_SURFACE_TO_SURFACE_SLIDING_ONLY: _SLIDING_ONLY", 0), 0u)
        << e.what();
  }
  const auto m = read_keyword_string("*KEYWORD\n*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_SLIDING_ONLY\n1,2\n*END\n", "w.k");
  ASSERT_EQ(m.contacts.size(), 1u);
  EXPECT_TRUE(m.contacts[0].sliding_only_option);
}

// *DAMPING_PART_MASS: FLAG = 1 reads the card of per-direction factors; _SET takes a part set.
TEST(KeywordReader, PartMassDampingFactorCardAndSet) {
  const auto m = read_keyword_string(
      "*KEYWORD\n*DAMPING_PART_MASS\n1,2,0.5,1\n0.5,0.5,0.5,0.5,0.5,0.5\n3,2,1.0\n"
      "*DAMPING_PART_MASS_SET\n4,2,2.0\n*END\n", "w.k");
  ASSERT_EQ(m.damping_parts.size(), 3u);
  EXPECT_EQ(m.damping_parts[0].flag, 1);
  EXPECT_DOUBLE_EQ(m.damping_parts[0].stf[2], 0.5);
  EXPECT_DOUBLE_EQ(m.damping_parts[0].stf[5], 0.5);
  EXPECT_EQ(m.damping_parts[1].pid, 3);  // the card after the factor card is the next record
  EXPECT_FALSE(m.damping_parts[1].set);
  EXPECT_EQ(m.damping_parts[2].pid, 4);
  EXPECT_TRUE(m.damping_parts[2].set);
  EXPECT_THROW(read_keyword_string("*KEYWORD\n*DAMPING_PART_MASS\n1,2,0.5,1\n*END\n", "w.k"), InputError);
  EXPECT_THROW(read_keyword_string("*KEYWORD\n*DAMPING_PART_MASS\n1,2,0.5,2\n*END\n", "w.k"), InputError);
}

// A free-format list line longer than a card's 8 fields is an error, not a silently short set.
TEST(KeywordReader, OverlongFreeFormatListLineIsAnError) {
  try {
    read_keyword_string("*KEYWORD\n*SET_NODE_LIST\n1\n1,2,3,4,5,6,7,8,9\n*END\n", "w.k");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("w.k:4: *SET_NODE_LIST: a list card holds at most 8 NID", 0), 0u) << e.what();
  }
  const auto m = read_keyword_string("*KEYWORD\n*SET_NODE_LIST\n1\n1,2,3,4,5,6,7,8,\n9\n*END\n", "w.k");
  ASSERT_EQ(m.node_sets.size(), 1u);
  EXPECT_EQ(m.node_sets[0].nodes.size(), 9u);  // a trailing comma is a blank field
}

TEST(KeywordReader, CheckReferencesNamesEveryMissingId) {
  const std::string deck =
      "*NODE\n1,0,0,0\n2,1,0,0\n"
      "*ELEMENT_SHELL\n1,7,1,2,3,4\n"
      "*PART\np\n1,5,6,0,9\n"
      "*SET_NODE_LIST\n1\n1,2,42\n"
      "*BOUNDARY_SPC_SET\n3,0,1\n"
      "*LOAD_BODY_Y\n8,1.0\n"
      "*CONTACT_SURFACE_TO_SURFACE\n4,5,0,3\n";
  const auto m = read_keyword_string(deck, "refs.k", nullptr);
  const auto problems = check_references(m);
  std::string all;
  for (const auto& p : problems) all += to_string(p) + "\n";
  for (const char* expected :
       {"*ELEMENT_SHELL 1 refers to undefined part 7", "*ELEMENT_SHELL 1 refers to undefined node 3",
        "*ELEMENT_SHELL 1 refers to undefined node 4", "refs.k:8: *PART 1 refers to undefined section 5",
        "*PART 1 refers to undefined material 6", "*PART 1 refers to undefined hourglass 9",
        "refs.k:10: *SET_NODE_LIST 1 refers to undefined node 42",
        "*BOUNDARY_SPC_SET refers to undefined node set 3", "*LOAD_BODY_Y refers to undefined curve 8",
        "SSID refers to undefined segment set 4", "MSID refers to undefined part 5"})
    EXPECT_NE(all.find(expected), std::string::npos) << "missing: " << expected << "\nin:\n" << all;
  EXPECT_EQ(problems.size(), 11u) << all;
}

TEST(KeywordReader, DefineBoxAndContactBoxReferences) {
  const std::string deck =
      "*NODE\n1,0,0,0\n2,1,0,0\n"
      "*ELEMENT_SHELL\n1,2,1,2,2,1\n"
      "*DEFINE_BOX_TITLE\nupper\n"
      "1,-1.0,2.0,0.5,1.5,-1.0,2.0\n"
      "*DEFINE_BOX\n"
      "$ BOXID XMN XMX YMN YMX ZMN ZMX\n"
      "2,0.0,1.5,0.0,1.0,0.0,1.02\n"
      "*CONTACT_SURFACE_TO_SURFACE\n1,2,3,3,1,7\n";
  const auto m = read_keyword_string(deck, "boxes.k", nullptr);
  ASSERT_EQ(m.boxes.size(), 2u);
  EXPECT_EQ(m.boxes[0].boxid, 1);
  EXPECT_EQ(m.boxes[0].title, "upper");
  EXPECT_EQ(m.boxes[0].min, (std::array<Real, 3>{-1.0, 0.5, -1.0}));
  EXPECT_EQ(m.boxes[0].max, (std::array<Real, 3>{2.0, 1.5, 2.0}));
  EXPECT_EQ(m.boxes[1].boxid, 2);
  EXPECT_EQ(m.boxes[1].src.line, 11);
  EXPECT_EQ(m.boxes[1].max, (std::array<Real, 3>{1.5, 1.0, 1.02}));
  ASSERT_EQ(m.contacts.size(), 1u);
  EXPECT_EQ(m.contacts[0].sboxid, 1);
  EXPECT_EQ(m.contacts[0].mboxid, 7);
  const auto problems = check_references(m);
  std::string all;
  for (const auto& p : problems) all += to_string(p) + "\n";
  // Box 1 exists; box 7 does not: named with the contact card's file and line.
  EXPECT_EQ(all.find("SBOXID"), std::string::npos) << all;
  EXPECT_NE(all.find("boxes.k:13: *CONTACT_SURFACE_TO_SURFACE MBOXID refers to undefined box 7"), std::string::npos)
      << all;
}

}  // namespace
}  // namespace slideline
