// validate_model (run by build_simulation): every refusal names the card and file:line, and one
// problem over many elements is one line.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>

#include "slideline/core/error.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/solver/build.hpp"
#include "slideline/solver/validate_model.hpp"

using namespace slideline;

namespace {

std::string deck(const std::string& name) { return std::string(SLIDELINE_SOURCE_DIR) + "/tests/data/decks/" + name; }

/// The message of validate_model on a deck, "" when it passes; `not_implemented` tells which error.
std::string validation(const std::string& name, bool* not_implemented = nullptr) {
  const auto m = read_keyword_file(deck(name));
  try {
    validate_model(m);
  } catch (const NotImplementedError& e) {
    if (not_implemented) *not_implemented = true;
    return e.what();
  } catch (const InputError& e) {
    if (not_implemented) *not_implemented = false;
    return e.what();
  }
  return "";
}

TEST(ValidateModel, MaterialConstantsAreRangeCheckedWithCardAndLine) {
  EXPECT_EQ(validation("reader/poisson_half.k"),
            deck("reader/poisson_half.k") + ":33: field PR of *MAT_ELASTIC must be in (-1, 0.5) (got 0.5)");
  EXPECT_EQ(validation("reader/huge_modulus.k"),
            deck("reader/huge_modulus.k") + ":33: field E of *MAT_ELASTIC is 1e+308, beyond 1e+30 (check the units)");
  EXPECT_EQ(validation("reader/huge_density.k"),
            deck("reader/huge_density.k") + ":33: field RO of *MAT_ELASTIC is 1e+308, beyond 1e+30 (check the units)");
  model::Model m = read_keyword_file(deck("unit_cube.k"));
  m.materials[0] = model::MatMooneyRivlin{1, 0.01, 0.49, -1.0, 0.5, "", {"r.k", 9}};
  try {
    validate_model(m);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "r.k:9: fields A, B of *MAT_MOONEY-RIVLIN_RUBBER must give a positive shear modulus 2(A + B) (got A = "
              "-1, B = 0.5)");
  }
}

TEST(ValidateModel, ControlsNameTheirCards) {
  EXPECT_EQ(validation("reader/tssfac.k"),
            deck("reader/tssfac.k") +
                ":7: field TSSFAC of *CONTROL_TIMESTEP must be in (0, 1] (0 = the default 0.9; got 1.5)");
  EXPECT_EQ(validation("reader/zero_end_time.k"),
            deck("reader/zero_end_time.k") + ":5: field ENDTIM of *CONTROL_TERMINATION must be positive (got 0)");
  model::Model m = read_keyword_file(deck("unit_cube.k"));
  BuildOptions o;
  o.end_time = 1.0;
  m.termination = {};
  EXPECT_NO_THROW(validate_model(m, o));  // --end-time stands in for ENDTIM
  EXPECT_THROW(validate_model(m), InputError);
}

TEST(ValidateModel, EmptyModelsAreRefused) {
  const std::string what = validation("reader/no_nodes.k");
  EXPECT_NE(what.find("no_nodes.k: the model has no nodes (*NODE): nothing to run"), std::string::npos) << what;
  EXPECT_NE(what.find("no_nodes.k: the model has no elements"), std::string::npos) << what;
}

TEST(ValidateModel, InvertedHexahedraNameTheElementAndLine) {
  EXPECT_EQ(validation("reader/inverted_hex.k"),
            deck("reader/inverted_hex.k") +
                ":26: *ELEMENT_SOLID 1 has non-positive volume -1 (inverted: list N1-N4 counter-clockwise seen "
                "from the face N5-N8)");
}

TEST(ValidateModel, TetrahedralMeshIsOneLineNamingTheElementKind) {
  bool ni = false;
  const std::string what = validation("reader/tet_mesh.k", &ni);
  EXPECT_TRUE(ni);
  EXPECT_EQ(std::count(what.begin(), what.end(), '\n'), 0) << what;
  EXPECT_NE(what.find("*ELEMENT_SOLID: 4-node tetrahedra (written as degenerate *ELEMENT_SOLID"), std::string::npos)
      << what;
  EXPECT_NE(what.find(": 1080 elements (first: 1, 2, 3, ...)"), std::string::npos) << what;
  EXPECT_EQ(what.rfind(deck("reader/tet_mesh.k") + ":", 0), 0u) << what;
  // The reference check leaves the blank N5..N8 of those elements to this message.
  EXPECT_TRUE(check_references(read_keyword_file(deck("reader/tet_mesh.k"))).empty());
}

TEST(ValidateModel, ShellTrianglesAndMixedProblems) {
  model::Model m = read_keyword_file(deck("unit_cube.k"));
  // Triangles (N3 = N4) in an elastic shell part pass (they run as C0 triangles); a shell with
  // another repeated node does not.
  m.materials.push_back(model::MatElastic{2, 1.0, 1e5, 0.3, "plate", {}});
  model::SectionShell sec;
  sec.secid = 2;
  sec.t = {0.1, 0.1, 0.1, 0.1};
  sec.src = {"s.k", 30};
  m.shell_sections.push_back(sec);
  m.parts.push_back({2, "plate", 2, 2, 0, 0, {}});
  m.shells.push_back({7, 2, {1, 2, 3, 3}, 40, 0});
  m.shells.push_back({8, 2, {1, 3, 4, 4}, 41, 0});
  EXPECT_NO_THROW(validate_model(m));
  m.shells.push_back({9, 2, {1, 1, 3, 4}, 42, 0});
  try {
    validate_model(m);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), deck("unit_cube.k") + ":42: *ELEMENT_SHELL 9 repeats a node");
  }
  m.shells.pop_back();
  // ELFORM 4 (C0 triangle) on a part of triangles passes; on a part with a quadrilateral, and any
  // other form, are refused naming the section's line and field.
  m.shell_sections.back().elform = 4;
  EXPECT_NO_THROW(validate_model(m));
  for (int form : {4, 16}) {
    m.shell_sections.back().elform = form;
    if (form == 4) m.shells.push_back({9, 2, {1, 2, 3, 4}, 42, 0});
    try {
      validate_model(m);
      FAIL() << "no exception";
    } catch (const NotImplementedError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("s.k:30: field ELFORM of *SECTION_SHELL: " + std::to_string(form)), std::string::npos) << what;
    }
  }
  // Triangles in a rigid part are refused, naming the element and its line (the deck's SPC on
  // node 1, now a rigid part's node, is reported too, so the error is the input one).
  m.shells.pop_back();
  m.shell_sections.back().elform = 2;
  m.materials.back() = model::MatRigid{2, 1.0, 1e5, 0.3, 0.0, 0, 0, "rigid", {}};
  try {
    validate_model(m);
    FAIL() << "no exception";
  } catch (const std::exception& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(deck("unit_cube.k") + ":40: *ELEMENT_SHELL 7 of rigid part 2 is a triangle (N3 = N4)"),
              std::string::npos)
        << what;
  }
}

TEST(ValidateModel, PrescribedMotionFieldsNotRunAreRefused) {
  model::Model m = read_keyword_file(deck("unit_cube.k"));
  model::PrescribedMotion pm;
  pm.nsid = 1;
  pm.lcid = 1;
  pm.vid = 3;  // a motion along a vector
  pm.src = {"p.k", 12};
  m.prescribed_motions.push_back(pm);
  EXPECT_THROW(validate_model(m), NotImplementedError);
  // BIRTH and DEATH are honoured (SupportWindow test); a window that closes before it opens is not.
  m.prescribed_motions.back().vid = 0;
  m.prescribed_motions.back().birth = 0.2;
  m.prescribed_motions.back().death = 0.1;
  EXPECT_THROW(validate_model(m), InputError);
}

TEST(ValidateModel, SeedDeckHexahedraAreValid) {
  // solid_on_solid_type3.k once listed both blocks' bottom faces clockwise (inverted elements,
  // hidden behind its contact card, which build_simulation does not run yet).
  model::Model m = read_keyword_file(deck("solid_on_solid_type3.k"));
  EXPECT_NO_THROW(validate_model(m));
  m.contacts.clear();
  auto sim = build_simulation(m);
  EXPECT_NO_THROW(sim->initialize());
  EXPECT_GT(sim->stable_dt(), 0.0);
}

}  // namespace

TEST(ValidateModel, SolidHourglassTypesRunOrAreRefusedNamingThePart) {
  // 1-6 and 10 run on hexahedra (4/5 Flanagan-Belytschko stiffness, 6 assumed strain); the others
  // are refused naming the part's card and line.
  for (int ihq : {0, 1, 2, 3, 4, 5, 6, 10}) {
    model::Model m = read_keyword_file(deck("unit_cube.k"));
    m.control_hourglass.ihq = ihq;
    EXPECT_NO_THROW(validate_model(m)) << "IHQ " << ihq;
  }
  for (int ihq : {7, 8, 9}) {
    model::Model m = read_keyword_file(deck("unit_cube.k"));
    m.control_hourglass.ihq = ihq;
    try {
      validate_model(m);
      ADD_FAILURE() << "IHQ " << ihq << " accepted";
    } catch (const NotImplementedError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(deck("unit_cube.k") + ":", 0), 0u) << what;
      EXPECT_NE(what.find("hourglass type IHQ=" + std::to_string(ihq) + " of part 1 is not implemented"),
                std::string::npos)
          << what;
    }
  }
}

// Pentahedra (N1 N2 N3 N4 N5 N5 N6 N6) and pyramids (N1 N2 N3 N4 N5 N5 N5 N5) pass in ELFORM 1
// (0) and 2 parts, where they run as collapsed hexahedra; in an ELFORM 10 part they are refused,
// and so is any other repeated-node form in any part (each naming the element and line);
// ELFORM 15 (LS-DYNA's own pentahedron) is refused naming the field.
TEST(ValidateModel, PentahedraAndPyramidsPassInHexahedronParts) {
  const model::Model cube = read_keyword_file(deck("unit_cube.k"));
  auto message = [&](std::array<Id, 8> n, int elform) -> std::string {
    model::Model m = cube;
    m.solids[0].n = n;
    m.solid_sections[0].elform = elform;
    try {
      validate_model(m);
    } catch (const std::exception& e) {
      return e.what();
    }
    return "";
  };
  const std::array<Id, 8> penta{2, 1, 5, 6, 3, 3, 7, 7}, pyramid{1, 2, 3, 4, 5, 5, 5, 5};
  for (const int elform : {0, 1, 2}) {
    EXPECT_EQ(message(penta, elform), "") << elform;
    EXPECT_EQ(message(pyramid, elform), "") << elform;
    EXPECT_EQ(message({1, 2, 2, 4, 5, 6, 6, 8}, elform), deck("unit_cube.k") + ":26: *ELEMENT_SOLID 1 repeats a node")
        << elform;
  }
  // Reversed, the pentahedron is inverted: its volume is checked as the hexahedron's.
  EXPECT_NE(message({1, 2, 6, 5, 3, 3, 7, 7}, 1).find("*ELEMENT_SOLID 1 has non-positive volume"), std::string::npos);
  EXPECT_NE(message(penta, 10).find(":26: *ELEMENT_SOLID 1 is in a part of *SECTION_SOLID ELFORM 10 but is not a "
                                    "tetrahedron"),
            std::string::npos);
  EXPECT_NE(message(penta, 15).find("field ELFORM of *SECTION_SOLID: 15"), std::string::npos) << message(penta, 15);
}
