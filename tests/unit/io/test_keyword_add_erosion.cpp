// *MAT_ADD_EROSION (src/io/keyword_add_erosion.cpp, src/solver/erosion_setup.cpp): the fields
// built are read and written back; every criterion not built, when not excluded, and a negative
// EFFEPS / EPSSH / MXEPS is refused with the file, line, card, field and value; a MID that is not a
// deformable material of the deck, a second card for one MID, NUMFIP beyond a shell's points, the
// criteria on tetrahedra are refused when the model is built (the strain criteria on shells are
// built).
#include <gtest/gtest.h>

#include <string>

#include "slideline/core/error.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/io/keyword_writer.hpp"
#include "slideline/solver/build.hpp"

using namespace slideline;

namespace {

/// The error a deck raises when read (`build`: and built), or "(no error)".
std::string thrown(const std::string& deck, bool build = false) {
  try {
    auto m = read_keyword_string(deck, "p.k", nullptr);
    if (build) build_simulation(m);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

const std::string kMat = "*MAT_ELASTIC\n1,1.0,1000.0,0.3\n";  // lines 1-2

/// One cube of material 1, section ELFORM `elform` (`shell`: one shell, NIP 2, instead), the cards
/// `extra` first.
std::string deck(const std::string& extra, int elform = 1, bool shell = false) {
  std::string d = "*KEYWORD\n" + extra + kMat + "*PART\np\n1,1,1\n*NODE\n";
  for (int k = 0; k <= (shell ? 0 : 1); ++k)
    for (int j = 0; j <= 1; ++j)
      for (int i = 0; i <= 1; ++i)
        d += std::to_string(1 + i + 2 * j + 4 * k) + "," + std::to_string(i) + "," + std::to_string(j) + "," +
             std::to_string(k) + "\n";
  d += "*CONTROL_TERMINATION\n1.0\n";  // after `extra`, which the tests name by line
  if (shell) return d + "*SECTION_SHELL\n1,2,1.0,2\n0.1,0.1,0.1,0.1\n*ELEMENT_SHELL\n1,1,1,2,4,3\n*END\n";
  d += "*SECTION_SOLID\n1," + std::to_string(elform) + "\n*ELEMENT_SOLID\n";
  d += elform == 10 ? "1,1,1,2,4,5,5,5,5,5\n" : "1,1,1,2,4,3,5,6,8,7\n";
  return d + "*END\n";
}

}  // namespace

// The fields built, as the model keeps them: thresholds (absent when excluded: blank or 0 with
// EXCL blank, equal to EXCL, MXPRES at 0 always), NUMFIP and NCS (blank: 1), FAILTM < 0 as
// |FAILTM|; the optional cards at their defaults; written and read back the same.
TEST(KeywordAddErosion, ReadsTheCriteriaBuilt) {
  const auto m = read_keyword_string(kMat + "*MAT_ADD_EROSION_TITLE\nbrittle\n1,,5.0,-0.2,0.3,-0.1,-40,2\n"
                                            "-3.0,15.0,20.0,0.25,0.12,,,-0.5\n"
                                            "0,,,,1.0,,1.0\n,10\n,0.5\n",
                                     "p.k", nullptr);
  ASSERT_EQ(m.add_erosions.size(), 1u);
  const auto& a = m.add_erosions[0];
  EXPECT_EQ(a.mid, 1);
  EXPECT_EQ(a.title, "brittle");
  EXPECT_EQ(a.mxpres, 5.0);
  EXPECT_EQ(a.mnpres, -3.0);
  EXPECT_EQ(a.sigp1, 15.0);
  EXPECT_EQ(a.sigvm, 20.0);
  EXPECT_EQ(a.failtm, 0.5);
  EXPECT_EQ(a.mneps, -0.2);
  EXPECT_EQ(a.effeps, 0.3);
  EXPECT_EQ(a.voleps, -0.1);
  EXPECT_EQ(a.mxeps, 0.25);
  EXPECT_EQ(a.epssh, 0.12);
  EXPECT_EQ(a.numfip, -40.0);
  EXPECT_EQ(a.ncs, 2);
  const auto back = read_keyword_string(write_keyword_string(m), "w.k", nullptr);
  ASSERT_EQ(back.add_erosions.size(), 1u);
  auto b = back.add_erosions[0];
  b.src = a.src;
  EXPECT_EQ(b, a);
  // EXCL 1234: MNPRES = 0 is a threshold (fails in any tension), the fields set to 1234 are not,
  // MXPRES = 0 never is.
  const auto e = read_keyword_string(kMat + "*MAT_ADD_EROSION\n1,1234,0,1234,1234,1234\n0,1234,1234,1234,1234,1234,1234,1234\n",
                                     "p.k", nullptr);
  EXPECT_FALSE(e.add_erosions[0].mxpres);
  EXPECT_EQ(e.add_erosions[0].mnpres, 0.0);
  EXPECT_FALSE(e.add_erosions[0].sigvm);
  EXPECT_FALSE(e.add_erosions[0].failtm);
  EXPECT_FALSE(e.add_erosions[0].mneps);
  EXPECT_FALSE(e.add_erosions[0].effeps);
  EXPECT_FALSE(e.add_erosions[0].voleps);
  EXPECT_FALSE(e.add_erosions[0].mxeps);
  EXPECT_FALSE(e.add_erosions[0].epssh);
  // EXCL 9: a blank MXEPS or EPSSH is 0, not 9: a threshold (met at rest); MNEPS, EFFEPS, VOLEPS
  // (and MXPRES) at 0 are excluded whatever EXCL, and so is FAILTM (birdball.k's card 2 leaves it
  // blank with EXCL 888).
  const auto z = read_keyword_string(kMat + "*MAT_ADD_EROSION\n1,9,9,,,\n9,9,20,,,9,9\n", "p.k", nullptr);
  EXPECT_FALSE(z.add_erosions[0].failtm);
  EXPECT_EQ(z.add_erosions[0].mxeps, 0.0);
  EXPECT_EQ(z.add_erosions[0].epssh, 0.0);
  EXPECT_FALSE(z.add_erosions[0].mneps);
  EXPECT_FALSE(z.add_erosions[0].effeps);
  EXPECT_FALSE(z.add_erosions[0].voleps);
}

// Each criterion not built, when not excluded, is refused naming file, line, card, field and value.
TEST(KeywordAddErosion, RefusesWhatIsNotBuilt) {
  const auto refused = [](const std::string& cards, const std::string& expected) {
    const std::string what = thrown(kMat + "*MAT_ADD_EROSION\n" + cards);
    EXPECT_NE(what.find(expected), std::string::npos) << what << "\n  expected: " << expected;
  };
  refused("1,,,,-0.2\n,,20\n", "p.k:4: *MAT_ADD_EROSION: card 1 field EFFEPS = -0.2 must be positive");
  refused("1\n,,20,-4\n", "p.k:5: *MAT_ADD_EROSION: card 2 field MXEPS = -4 (a curve of the failure strain");
  refused("1\n,,20,,-0.5\n", "p.k:5: *MAT_ADD_EROSION: card 2 field EPSSH = -0.5 must be positive");
  refused("1\n,,20,,,100\n", "p.k:5: *MAT_ADD_EROSION: card 2 field SIGTH = 100");
  refused("1\n,,20,,,,3\n", "p.k:5: *MAT_ADD_EROSION: card 2 field IMPULSE = 3");
  refused("1\n,-7\n", "p.k:5: *MAT_ADD_EROSION: card 2 field SIGP1 = -7");
  refused("1\n,,-8\n", "p.k:5: *MAT_ADD_EROSION: card 2 field SIGVM = -8");
  // EXCL 9: a blank SIGTH is 0, not 9: a criterion, refused.
  refused("1,9,9,9,9,9\n9,9,20,9,9,,9,9\n", "p.k:5: *MAT_ADD_EROSION: card 2 field SIGTH = 0 (blank)");
  refused("1\n,,20\n-1\n", "p.k:6: *MAT_ADD_EROSION: card 3 field IDAM = -1");
  refused("1\n,,20\n\n5\n", "p.k:7: *MAT_ADD_EROSION: card 4 field LCFLD = 5");
  refused("1\n,,20\n\n\n,,,1e-6\n", "p.k:8: *MAT_ADD_EROSION: card 5 field DTMIN = 1e-6");
  refused("1,,,,,,,2.5\n,,20\n", "p.k:4: *MAT_ADD_EROSION: card 1 field NCS = 2.5");
  refused("1,,,,,,,3\n,15,20\n", "p.k:4: *MAT_ADD_EROSION: card 1 field NCS = 3 asks for more criteria");
  refused("1,,,,,,1.5\n,,20\n", "p.k:4: *MAT_ADD_EROSION: card 1 field NUMFIP = 1.5");
  refused("1\n\n", "p.k:4: *MAT_ADD_EROSION: no criterion is set");
  refused("1\n", "p.k:4: *MAT_ADD_EROSION: card 2");
}

// ERODE of *CONTROL_TIMESTEP: 1 is read and written back; another value is refused naming file,
// line, field and value.
TEST(KeywordAddErosion, ErodeFlagOfControlTimestep) {
  const auto m = read_keyword_string("*CONTROL_TIMESTEP\n,,,,,,1\n", "p.k", nullptr);
  EXPECT_EQ(m.timestep.erode, 1);
  EXPECT_EQ(read_keyword_string(write_keyword_string(m), "w.k", nullptr).timestep.erode, 1);
  const std::string what = thrown("*CONTROL_TIMESTEP\n,,,,,,2\n");
  EXPECT_NE(what.find("p.k:2: *CONTROL_TIMESTEP card 1: field ERODE = 2 must be 0 or 1"), std::string::npos) << what;
}

// At the build: a MID that the deck does not define or that is rigid, a second card for one MID,
// NUMFIP beyond a shell's points, the stress criteria on tetrahedra; the card's file and line named.
TEST(KeywordAddErosion, RefusedAtTheBuild) {
  EXPECT_EQ(thrown(deck("*MAT_ADD_EROSION\n1\n,,20\n"), true), "(no error)");
  EXPECT_EQ(thrown(deck("*MAT_ADD_EROSION\n1\n,,20\n", 1, true), true), "(no error)");
  std::string what = thrown(deck("*MAT_ADD_EROSION\n7\n,,20\n"), true);
  EXPECT_NE(what.find("p.k:3: *MAT_ADD_EROSION card 1 field MID = 7 refers to a material the deck does not define"),
            std::string::npos)
      << what;
  what = thrown(deck("*MAT_ADD_EROSION\n1\n,,20\n*MAT_ADD_EROSION\n1\n,15\n"), true);
  EXPECT_NE(what.find("p.k:6: a second *MAT_ADD_EROSION for material 1 (the first at p.k:3)"), std::string::npos)
      << what;
  what = thrown(deck("*MAT_RIGID\n2,1.0,1000.0,0.3\n*MAT_ADD_EROSION\n2\n,,20\n"), true);
  EXPECT_NE(what.find("p.k:5: *MAT_ADD_EROSION card 1 field MID = 2 is a *MAT_RIGID material"), std::string::npos)
      << what;
  what = thrown(deck("*MAT_ADD_EROSION\n1,,,,,,3\n,,20\n", 1, true), true);
  EXPECT_NE(what.find("NUMFIP of *MAT_ADD_EROSION asks for 3 failed through-thickness points, but its section has 2"),
            std::string::npos)
      << what;
  EXPECT_NE(what.find("*MAT_ADD_EROSION (p.k:3)"), std::string::npos) << what;
  what = thrown(deck("*MAT_ADD_EROSION\n1,,,,,,2\n,,20\n"), true);
  EXPECT_NE(what.find("NUMFIP of *MAT_ADD_EROSION asks for 2 failed points, but a one-point hexahedron has 1"),
            std::string::npos)
      << what;
  EXPECT_EQ(thrown(deck("*MAT_ADD_EROSION\n1,,,,,,-50\n,,20\n"), true), "(no error)");  // 50% of one point
  EXPECT_EQ(thrown(deck("*MAT_ADD_EROSION\n1,,,-0.1,0.2,0.1\n,,,0.3,0.2\n"), true), "(no error)");
  // The strain criteria on shells are built (element/shell_erosion.hpp).
  EXPECT_EQ(thrown(deck("*MAT_ADD_EROSION\n1\n,,20,0.3\n", 1, true), true), "(no error)");
  // The thresholds on tetrahedra (ELFORM 10, one point) and fully integrated hexahedra (ELFORM 2,
  // 8 points) are built (element/solid_erosion.hpp); NUMFIP beyond their points is refused.
  EXPECT_EQ(thrown(deck("*MAT_ADD_EROSION\n1\n,,20\n", 10), true), "(no error)");
  EXPECT_EQ(thrown(deck("*MAT_ADD_EROSION\n1,,,,,,8\n,,20\n", 2), true), "(no error)");
  what = thrown(deck("*MAT_ADD_EROSION\n1,,,,,,2\n,,20\n", 10), true);
  EXPECT_NE(what.find("NUMFIP of *MAT_ADD_EROSION asks for 2 failed points, but tetrahedra (ELFORM 10) have 1"),
            std::string::npos)
      << what;
  what = thrown(deck("*MAT_ADD_EROSION\n1,,,,,,9\n,,20\n", 2), true);
  EXPECT_NE(what.find("asks for 9 failed points, but fully integrated hexahedra (ELFORM 2) have 8"), std::string::npos)
      << what;
}
