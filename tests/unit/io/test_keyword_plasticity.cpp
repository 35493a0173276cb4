// The plasticity cards (*MAT_PLASTIC_KINEMATIC, *MAT_PIECEWISE_LINEAR_PLASTICITY): every field
// read, what is not built refused with file, line and field, the registry's law from the card.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "slideline/core/error.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/io/keyword_writer.hpp"
#include "slideline/solver/material_registry.hpp"

using namespace slideline;

namespace {

std::string thrown(const std::string& deck) {
  try {
    read_keyword_string(deck, "p.k", nullptr);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST(KeywordPlasticity, PlasticKinematicFields) {
  const auto m = read_keyword_string(
      "*MAT_PLASTIC_KINEMATIC_TITLE\nsteel\n"
      "         5    7.8e-9    2.0e+5       0.3     250.0    2000.0       0.5\n"
      "      40.4       5.0\n",
      "p.k", nullptr);
  const auto& k = std::get<model::MatPlasticKinematic>(m.materials.at(0));
  EXPECT_EQ(k.mid, 5);
  EXPECT_EQ(k.title, "steel");
  EXPECT_DOUBLE_EQ(k.sigy, 250.0);
  EXPECT_DOUBLE_EQ(k.etan, 2000.0);
  EXPECT_DOUBLE_EQ(k.beta, 0.5);
  EXPECT_DOUBLE_EQ(k.src_c, 40.4);
  EXPECT_DOUBLE_EQ(k.srp, 5.0);
  const std::string card1 = "*MAT_003\n         5    7.8e-9    2.0e+5       0.3     250.0\n";
  // FS: the failure strain (element erosion, docs/solver.md); 0 and 1e21 (LS-DYNA's default):
  // none; negative (a user subroutine): refused.
  const auto fs = read_keyword_string(card1 + ",,0.3\n", "p.k", nullptr);
  EXPECT_EQ(std::get<model::MatPlasticKinematic>(fs.materials.at(0)).fs, 0.3);
  EXPECT_EQ(material_laws(fs.materials.at(0)).failure_strain, 0.3);
  const auto never = read_keyword_string(card1 + ",,1.0e+21\n", "p.k", nullptr);
  EXPECT_EQ(std::get<model::MatPlasticKinematic>(never.materials.at(0)).fs, 0.0);
  EXPECT_EQ(material_laws(never.materials.at(0)).failure_strain, 0.0);
  EXPECT_EQ(thrown(card1 + ",,-0.3\n"),
            "p.k:3: *MAT_003: field FS = -0.3 (a user failure subroutine) is not implemented; give the failure "
            "strain (> 0), or leave it blank, 0 or 1e21 (no failure)");
  // The writer keeps FS.
  EXPECT_EQ(std::get<model::MatPlasticKinematic>(read_keyword_string(write_keyword_string(fs), "w.k", nullptr)
                                                     .materials.at(0))
                .fs,
            0.3);
  EXPECT_NE(thrown(card1 + ",,,1.0\n").find("p.k:3: *MAT_003: field VP = 1.0"),
            std::string::npos);
}

TEST(KeywordPlasticity, PiecewiseLinearTableCurveAndRefusals) {
  const auto m = read_keyword_string(
      "*MAT_PIECEWISE_LINEAR_PLASTICITY\n"
      "         7    7.8e-9    2.0e+5       0.3     200.0    1000.0\n"
      ",,,,1.0\n"
      "0.0,0.01,0.1\n"
      "     200.0     220.0     300.0\n"
      "*MAT_024\n"
      "         8    7.8e-9    2.0e+5       0.3\n"
      "0.0,0.0,3,4\n"
      "*DEFINE_CURVE\n3,,2.0,0.5\n0.0, 100.0\n1.0, 200.0\n"
      "*DEFINE_CURVE\n4\n0.0, 1.0\n100.0, 2.0\n",
      "p.k", nullptr);
  const auto& t = std::get<model::MatPiecewiseLinearPlasticity>(m.materials.at(0));
  EXPECT_EQ(t.vp, 1.0);
  EXPECT_DOUBLE_EQ(t.eps[2], 0.1);
  EXPECT_DOUBLE_EQ(t.es[2], 300.0);
  const MaterialLaws table_laws = material_laws(m.materials.at(0), m.curves);
  const auto& law = std::get<PiecewisePlasticity>(*table_laws.solid);
  ASSERT_EQ(law.constants().hardening.size(), 3u);  // the table to its last non-zero ES
  EXPECT_DOUBLE_EQ(law.yield_stress(0.055), 260.0);
  EXPECT_TRUE(law.constants().viscoplastic);
  // LCSS with SFA = 2, SFO = 0.5: the yield curve (0, 50) - (2, 100); LCSR the factor curve.
  const MaterialLaws curve_laws = material_laws(m.materials.at(1), m.curves);
  const auto& c = std::get<PiecewisePlasticity>(*curve_laws.solid);
  EXPECT_DOUBLE_EQ(c.yield_stress(1.0), 75.0);
  EXPECT_DOUBLE_EQ(c.rate_factor(50.0), 1.5);
  EXPECT_FALSE(c.constants().viscoplastic);
  // Without curve or table: SIGY and the hardening modulus E ETAN / (E - ETAN).
  const auto e = read_keyword_string("*MAT_024\n1,1.0,1000.0,0.3,2.0,10.0\n", "p.k", nullptr);
  const MaterialLaws etan_laws = material_laws(e.materials.at(0));
  const auto& b = std::get<PiecewisePlasticity>(*etan_laws.solid);
  EXPECT_DOUBLE_EQ(b.yield_stress(0.1), 2.0 + 0.1 * 1000.0 * 10.0 / 990.0);

  const std::string card1 = "*MAT_024\n         8    7.8e-9    2.0e+5       0.3     200.0\n";
  const auto failing = read_keyword_string("*MAT_024\n8,7.8e-9,2.0e+5,0.3,200.0,0.0,0.2\n", "p.k", nullptr);
  EXPECT_EQ(std::get<model::MatPiecewiseLinearPlasticity>(failing.materials.at(0)).fail, 0.2);
  EXPECT_EQ(material_laws(failing.materials.at(0)).failure_strain, 0.2);
  EXPECT_EQ(std::get<model::MatPiecewiseLinearPlasticity>(
                read_keyword_string(write_keyword_string(failing), "w.k", nullptr).materials.at(0))
                .fail,
            0.2);
  EXPECT_NE(thrown("*MAT_024\n8,7.8e-9,2.0e+5,0.3,200.0,0.0,-1.0\n").find("field FAIL = -1.0"), std::string::npos);
  // TDEL: the smallest element step kept (docs/solver.md, "Failure and erosion"); read, written
  // back, handed to the laws; negative refused naming the field and value.
  const auto tdel = read_keyword_string("*MAT_024\n8,7.8e-9,2.0e+5,0.3,200.0,0.0,,1e-7\n", "p.k", nullptr);
  EXPECT_EQ(std::get<model::MatPiecewiseLinearPlasticity>(tdel.materials.at(0)).tdel, 1e-7);
  EXPECT_EQ(material_laws(tdel.materials.at(0)).min_step, 1e-7);
  EXPECT_EQ(std::get<model::MatPiecewiseLinearPlasticity>(
                read_keyword_string(write_keyword_string(tdel), "w.k", nullptr).materials.at(0))
                .tdel,
            1e-7);
  EXPECT_NE(thrown("*MAT_024\n8,7.8e-9,2.0e+5,0.3,200.0,0.0,,-1e-7\n").find("p.k:2: *MAT_024: card 1 field TDEL = -1e-7"),
            std::string::npos);
  // LS-DYNA's default FAIL (1e21, as deck writers print it) and 0 both mean no failure: read as
  // the blank card.
  const auto blank = read_keyword_string("*MAT_024\n8,7.8e-9,2.0e+5,0.3,200.0,10.0\n", "p.k", nullptr);
  for (const char* fail : {"1.00000E21", "0.0", "1e20"}) {
    const auto d = read_keyword_string(std::string("*MAT_024\n8,7.8e-9,2.0e+5,0.3,200.0,10.0,") + fail + "\n", "p.k",
                                       nullptr);
    const auto& a = std::get<model::MatPiecewiseLinearPlasticity>(d.materials.at(0));
    const auto& z = std::get<model::MatPiecewiseLinearPlasticity>(blank.materials.at(0));
    EXPECT_EQ(a.sigy, z.sigy) << fail;
    EXPECT_EQ(a.etan, z.etan) << fail;
    EXPECT_EQ(a.fail, 0.0) << fail;
  }
  EXPECT_NE(thrown(card1 + ",,,,-1.0\n").find("p.k:3: *MAT_024: field VP = -1.0"),
            std::string::npos);
  EXPECT_NE(thrown(card1 + "40.0,5.0,,4\n").find("p.k:3:"), std::string::npos);
  EXPECT_NE(thrown(card1 + ",,,,,9\n").find("field LCF"),
            std::string::npos);
}

TEST(KeywordPlasticity, NullMaterialFieldsAndRefusals) {
  const auto m = read_keyword_string("*MAT_NULL\n4,0.1,,,,,1000.0,0.1\n", "p.k", nullptr);
  const auto& n = std::get<model::MatNull>(m.materials.at(0));
  EXPECT_EQ(n.mid, 4);
  EXPECT_DOUBLE_EQ(n.ym, 1000.0);
  EXPECT_DOUBLE_EQ(n.pr, 0.1);
  const MaterialLaws laws = material_laws(m.materials.at(0));
  EXPECT_FALSE(laws.solid);
  ASSERT_TRUE(laws.shell);
  const auto& law = std::get<NullShell>(*laws.shell);
  NullShell::State s;
  for (Real v : law.update(s, ShellRate{1.0, 2.0, 3.0, 4.0, 5.0}, 0.1, 1.0)) EXPECT_EQ(v, 0.0);
  EXPECT_DOUBLE_EQ(law.wave_speed(), std::sqrt(1000.0 / (0.1 * 0.99)));
  EXPECT_TRUE(law.problem().empty());
  // PC, MU, TEROD, CEROD are read for solids (tests/unit/solver/test_null_solid_model.cpp: refused on shells).
  const auto solid = read_keyword_string("*MAT_009\n4,0.1,-5.0,0.5,2.0,0.5\n", "p.k", nullptr);
  const auto& ns = std::get<model::MatNull>(solid.materials.at(0));
  EXPECT_EQ(ns.pc, -5.0);
  EXPECT_EQ(ns.mu, 0.5);
  EXPECT_EQ(ns.terod, 2.0);
  EXPECT_EQ(ns.cerod, 0.5);
}

// The writer gives the cards back: read -> write -> read keeps every field.
TEST(KeywordPlasticity, CardsRoundTrip) {
  const auto m = read_keyword_string(
      "*MAT_PLASTIC_KINEMATIC\n5,7.8e-9,2.0e+5,0.3,250.0,2000.0,0.5\n40.4,5.0\n"
      "*MAT_PIECEWISE_LINEAR_PLASTICITY_TITLE\nsteel\n7,7.8e-9,2.0e+5,0.3,200.0,1000.0\n2.0,3.0,0,0,1.0\n"
      "0.0,0.01,0.1\n200.0,220.0,300.0\n"
      "*MAT_NULL\n4,0.1,,,,,1000.0,0.1\n",
      "p.k", nullptr);
  const auto again = read_keyword_string(write_keyword_string(m), "again.k", nullptr);
  ASSERT_EQ(again.materials.size(), 3u);
  EXPECT_EQ(std::get<model::MatPlasticKinematic>(again.materials[0]).srp, 5.0);
  EXPECT_EQ(std::get<model::MatPiecewiseLinearPlasticity>(again.materials[1]).es[2], 300.0);
  EXPECT_EQ(std::get<model::MatPiecewiseLinearPlasticity>(again.materials[1]).title, "steel");
  EXPECT_EQ(std::get<model::MatNull>(again.materials[2]).ym, 1000.0);
  for (std::size_t i = 0; i < 3; ++i) {
    auto a = m.materials[i], b = again.materials[i];
    std::visit([](auto& x) { x.src = {}; }, a);
    std::visit([](auto& x) { x.src = {}; }, b);
    EXPECT_TRUE(a == b) << i;
  }
}

TEST(KeywordPlasticity, BothCardsGiveAShellLaw) {
  // The registry makes the plane-stress law from the same card (docs/solver.md, "On
  // Belytschko-Tsay shells"): its yield stress is the hexahedron law's.
  const auto m = read_keyword_string(
      "*MAT_PLASTIC_KINEMATIC\n1,7.8e-9,2.0e+5,0.3,250.0,2000.0,0.5\n"
      "*MAT_PIECEWISE_LINEAR_PLASTICITY\n2,7.8e-9,2.0e+5,0.3,200.0,1000.0\n",
      "p.k", nullptr);
  const MaterialLaws pk = material_laws(m.materials.at(0), m.curves);
  ASSERT_TRUE(pk.shell);
  const auto& shell3 = std::get<ShellPlasticity<J2Plasticity>>(*pk.shell);
  EXPECT_DOUBLE_EQ(shell3.law().flow_stress(0.0, 0.0, 0.0, 1.0), 250.0);
  EXPECT_DOUBLE_EQ(shell3.youngs_modulus(), 2.0e5);
  EXPECT_TRUE(shell3.problem().empty());
  const MaterialLaws pw = material_laws(m.materials.at(1), m.curves);
  ASSERT_TRUE(pw.shell);
  const auto& shell24 = std::get<ShellPlasticity<PiecewisePlasticity>>(*pw.shell);
  EXPECT_DOUBLE_EQ(shell24.law().flow_stress(0.0, 0.0, 0.0, 1.0), 200.0);
  EXPECT_DOUBLE_EQ(shell24.law().flow_stress(0.0, 0.01, 0.0, 1.0), 200.0 + 0.01 * 2.0e5 * 1000.0 / (2.0e5 - 1000.0));
}
