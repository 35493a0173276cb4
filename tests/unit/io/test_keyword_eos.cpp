// *EOS_LINEAR_POLYNOMIAL, *EOS_GRUNEISEN, *EOS_TABULATED and the solid fields of *MAT_NULL
// (PC, MU, TEROD, CEROD): each field read, written back, and honoured or refused by name
// (docs/keywords.md, "Equations of state").
#include <gtest/gtest.h>

#include <string>
#include <variant>

#include "model_equal.hpp"
#include "slideline/core/error.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/io/keyword_writer.hpp"
#include "slideline/solver/material_registry.hpp"
#include "slideline/solver/validate_model.hpp"

namespace slideline {
namespace {

const std::string kEosCards =
    "*EOS_LINEAR_POLYNOMIAL\n1,0.1,2.0,3.0,4.0,0.4,0.5,0.6\n7.0,1.0\n"
    "*EOS_GRUNEISEN\n2,0.394,1.489,0.1,0.2,2.02,0.47,0.3\n0\n"
    // birdball.k's table (16-wide fields)
    "*EOS_TABULATED\n         3  1.00E+00  0.00E+00  1.00E+00\n"
    " 1.000000015E-01 0.000000000E+00-9.529999644E-02-1.043999940E-01-1.123999953E-01\n"
    "-1.177999973E-01-1.257999986E-01-1.310000122E-01-1.483999938E-01-2.326999903E-01\n"
    "-5.000000000E+03 0.000000000E+00 2.940000000E+02 1.470000000E+03 2.940000000E+03\n"
    " 4.410000000E+03 5.880000000E+03 7.350000000E+03 1.470000000E+04 7.350000000E+04\n"
    " 0.000000000E+00 0.000000000E+00 0.000000000E+00 0.000000000E+00 0.000000000E+00\n"
    " 0.000000000E+00 0.000000000E+00 0.000000000E+00 0.000000000E+00 0.000000000E+00\n";

TEST(KeywordEos, CardsReadAndRoundTrip) {
  const auto m = read_keyword_string("*KEYWORD\n" + kEosCards +
                                         "*MAT_NULL\n1,8.54E-05,-1.45E+01,4.00E-06,2.0,0.2\n*END\n",
                                     "e.k", nullptr);
  ASSERT_EQ(m.eos.size(), 3u);
  const auto& lp = std::get<model::EosLinearPolynomial>(m.eos[0]);
  EXPECT_EQ(lp.eosid, 1);
  EXPECT_EQ(lp.c[0], 0.1);
  EXPECT_EQ(lp.c[6], 0.6);
  EXPECT_EQ(lp.e0, 7.0);
  EXPECT_EQ(lp.v0, 1.0);
  const auto& gr = std::get<model::EosGruneisen>(m.eos[1]);
  EXPECT_EQ(gr.c, 0.394);
  EXPECT_EQ(gr.s1, 1.489);
  EXPECT_EQ(gr.s3, 0.2);
  EXPECT_EQ(gr.gamma0, 2.02);
  EXPECT_EQ(gr.a, 0.47);
  EXPECT_EQ(gr.e0, 0.3);
  const auto& tb = std::get<model::EosTabulated>(m.eos[2]);
  EXPECT_EQ(tb.gama, 1.0);
  EXPECT_EQ(tb.v0, 1.0);
  EXPECT_EQ(tb.ev[0], 1.000000015E-01);
  EXPECT_EQ(tb.ev[9], -2.326999903E-01);
  EXPECT_EQ(tb.c[0], -5000.0);
  EXPECT_EQ(tb.c[9], 73500.0);
  EXPECT_EQ(tb.t[4], 0.0);
  const auto& nl = std::get<model::MatNull>(m.materials.at(0));
  EXPECT_EQ(nl.pc, -14.5);
  EXPECT_EQ(nl.mu, 4e-6);
  EXPECT_EQ(nl.terod, 2.0);
  EXPECT_EQ(nl.cerod, 0.2);
  const auto again = read_keyword_string(write_keyword_string(m), "again.k", nullptr);
  EXPECT_EQ(test::model_difference(m, again), "");
  // The registry makes the null solid of each EOS (the part's EOSID picks it).
  for (const auto& eos : m.eos) {
    const MaterialLaws laws = material_laws(m.materials.at(0), {}, &eos);
    ASSERT_TRUE(laws.solid);
    EXPECT_TRUE(std::holds_alternative<NullSolid>(*laws.solid));
    EXPECT_EQ(laws.max_relative_volume, 2.0);
    EXPECT_EQ(laws.min_relative_volume, 0.2);
  }
  EXPECT_FALSE(material_laws(m.materials.at(0)).solid);
}

TEST(KeywordEos, ReaderRefusesFieldsItDoesNotRun) {
  const auto thrown = [](const std::string& text) -> std::string {
    try {
      read_keyword_string("*KEYWORD\n" + text + "*END\n", "e.k", nullptr);
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(thrown("*EOS_GRUNEISEN\n2,0.394,1.489\n0,,5\n").find("e.k:4: *EOS_GRUNEISEN: field LCID = 5"),
            std::string::npos);
  EXPECT_NE(thrown("*EOS_TABULATED\n3,1.0,0,1,7\n").find("e.k:3: *EOS_TABULATED: field 5 = 7"), std::string::npos);
  EXPECT_NE(thrown("*EOS_TABULATED\n3,1.0\n0.1,0,-0.1,-0.2,-0.3\n").find("missing EV6-10 card"), std::string::npos);
}

/// One unit cube of part 1 (`part` its *PART cards), with `cards` (material, EOS, section, hourglass).
std::string cube(const std::string& cards, const std::string& part = "*PART\ncube\n1,1,1,1\n") {
  std::string d = "*KEYWORD\n*CONTROL_TERMINATION\n1.0\n" + cards + part + "*NODE\n";
  for (int k = 0; k <= 1; ++k)
    for (int j = 0; j <= 1; ++j)
      for (int i = 0; i <= 1; ++i)
        d += std::to_string(1 + i + 2 * j + 4 * k) + "," + std::to_string(i) + "," + std::to_string(j) + "," +
             std::to_string(k) + "\n";
  return d + "*ELEMENT_SOLID\n1,1,1,2,4,3,5,6,8,7\n*END\n";
}

std::string validation(const std::string& text) {
  try {
    validate_model(read_keyword_string(text, "c.k", nullptr));
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(KeywordEos, ValidationRefusesByName) {
  const std::string lp = "*EOS_LINEAR_POLYNOMIAL\n1,0,1000.0\n", sec = "*SECTION_SOLID\n1,1\n";
  const std::string null = "*MAT_NULL\n1,1e-3\n";
  EXPECT_EQ(validation(cube(sec + null + lp)), "");
  const auto refuses = [&](const std::string& text, const std::string& what) {
    const std::string got = validation(text);
    EXPECT_NE(got.find(what), std::string::npos) << "expected: " << what << "\ngot: " << got;
  };
  refuses(cube(sec + "*MAT_ELASTIC\n1,1e-3,1000.0,0.3\n" + lp),
          "part 1: field EOSID = 1 of *PART: an equation of state goes with *MAT_NULL solids; material 1 has its own pressure");
  refuses(cube(sec + "*MAT_NULL\n1,1e-3,,,,,1000.0\n" + lp), "field YM = 1000 of *MAT_NULL is used for null shells");
  refuses(cube("*SECTION_SOLID\n1,2\n" + null + lp), "field ELFORM of *SECTION_SOLID: 2 with *MAT_NULL (part 1)");
  refuses(cube(sec + null + lp + "*HOURGLASS\n1,6\n", "*PART\ncube\n1,1,1,1,1\n"), "hourglass type IHQ=6 of *MAT_NULL");
  refuses(cube(sec + null + "*EOS_LINEAR_POLYNOMIAL\n1,0,1000.0\n0,0.9\n"),
          "field V0 = 0.9 of *EOS_LINEAR_POLYNOMIAL is not implemented");
  refuses(cube(sec + "*MAT_NULL\n1,1e-3,5.0\n" + lp), "field PC of *MAT_NULL is a pressure cutoff in tension");
  refuses(cube(sec + "*MAT_NULL\n1,1e-3,0,0,0.9\n" + lp), "field TEROD of *MAT_NULL");
  refuses(cube(sec + "*MAT_NULL\n1,1e-3,0,0,0,1.2\n" + lp), "field CEROD of *MAT_NULL");
  {
    std::string refs;
    for (const Diagnostic& d : check_references(read_keyword_string(cube(sec + null + lp, "*PART\ncube\n1,1,1,7\n"), "c.k")))
      refs += to_string(d) + "\n";
    EXPECT_NE(refs.find("*PART 1 refers to undefined equation of state 7"), std::string::npos) << refs;
  }
  refuses(cube(sec + null + "*EOS_LINEAR_POLYNOMIAL\n1,5.0\n"), "the sound speed at the reference state");
  refuses(cube(sec + null + "*EOS_TABULATED\n1\n0,0.1,-0.1,-0.2,-0.3\n-0.4,-0.5,-0.6,-0.7,-0.8\n"
                            "0,1,2,3,4\n5,6,7,8,9\n0,0,0,0,0\n0,0,0,0,0\n"),
          "*EOS_TABULATED: EV1 .. EV10 must descend strictly");
  refuses(cube(sec + null, "*PART\ncube\n1,1,1\n"), "combines solids with *MAT_NULL (a solid of it needs an equation of state");
}

TEST(KeywordEos, NullShellsRefuseTheSolidFields) {
  std::string d = "*KEYWORD\n*CONTROL_TERMINATION\n1.0\n*SECTION_SHELL\n1\n0.1\n*MAT_NULL\n1,1e-3,0,0.5,,,1000.0,0.3\n"
                  "*PART\nskin\n1,1,1\n*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n*ELEMENT_SHELL\n1,1,1,2,3,4\n*END\n";
  EXPECT_NE(validation(d).find("field MU = 0.5 of *MAT_NULL acts on solids"), std::string::npos) << validation(d);
}

}  // namespace
}  // namespace slideline
