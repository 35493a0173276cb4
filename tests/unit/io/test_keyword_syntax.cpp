// Real-world deck syntax: *INCLUDE, *PARAMETER / *PARAMETER_EXPRESSION, Fortran reals without an
// exponent letter, long and I10 formats, CR-only line endings, and large junk input.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <string>

#include "slideline/core/error.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/solver/validate_model.hpp"

namespace slideline {
namespace {

std::string reader_deck(const std::string& name) {
  return std::string(SLIDELINE_SOURCE_DIR) + "/tests/data/decks/reader/" + name;
}

std::string message_of(const std::string& path) {
  try {
    read_keyword_file(path);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(KeywordSyntax, NestedIncludesAreRelativeToTheIncludingFile) {
  std::vector<Diagnostic> warnings;
  const auto m = read_keyword_file(reader_deck("include_main.k"), &warnings);
  EXPECT_TRUE(warnings.empty()) << to_string(warnings.front());
  EXPECT_EQ(m.nodes.size(), 8u);
  ASSERT_EQ(m.solids.size(), 1u);
  ASSERT_EQ(m.materials.size(), 1u);
  EXPECT_DOUBLE_EQ(m.termination.endtim, 0.01);
  // Cards remember the file they came from: the element is in the innermost include.
  ASSERT_EQ(m.files.size(), 3u);
  EXPECT_NE(model::element_source(m, m.solids[0]).file.find("include/cube_mesh.k"), std::string::npos);
  EXPECT_EQ(model::element_source(m, m.solids[0]).line, 13);
  EXPECT_NE(m.parts[0].src.file.find("include/materials.k"), std::string::npos);
  EXPECT_TRUE(check_references(m).empty());
}

TEST(KeywordSyntax, IncludeErrorsNameTheFileAndLine) {
  const std::string missing = message_of(reader_deck("include_missing.k"));
  EXPECT_NE(missing.find("include_missing.k:5: *INCLUDE: cannot open 'include/no_such_file.k'"), std::string::npos)
      << missing;
  const std::string cycle = message_of(reader_deck("include_cycle.k"));
  EXPECT_NE(cycle.find("include/cycle_b.k:3: *INCLUDE of '../include_cycle.k' makes a cycle"), std::string::npos)
      << cycle;
  const std::string bad = message_of(reader_deck("include_bad_field.k"));
  EXPECT_NE(bad.find("include/bad_field.k:3: columns 21-30 (field E of *MAT_ELASTIC): expected a real number"),
            std::string::npos)
      << bad;
}

TEST(KeywordSyntax, ParametersAndExpressionsAreSubstituted) {
  std::vector<Diagnostic> warnings;
  const auto m = read_keyword_file(reader_deck("parameters.k"), &warnings);
  EXPECT_TRUE(warnings.empty()) << to_string(warnings.front());
  EXPECT_DOUBLE_EQ(m.termination.endtim, 0.01);  // "1.00000-2": Fortran real without 'E'
  ASSERT_EQ(m.solids.size(), 1u);
  EXPECT_EQ(m.solids[0].pid, 1);
  EXPECT_EQ(m.parts.at(0).pid, 1);
  const auto& e = std::get<model::MatElastic>(m.materials.at(0));
  EXPECT_DOUBLE_EQ(e.ro, 0.01);
  EXPECT_DOUBLE_EQ(e.e, 1000.0);
  EXPECT_DOUBLE_EQ(e.pr, 0.1);  // 0.5*(0.3 - 0.1)
  ASSERT_EQ(m.body_loads.size(), 1u);
  EXPECT_DOUBLE_EQ(m.body_loads[0].sf, 0.5);  // -&gload, gload = -2*sqrt(max(4, 1+3)) + 1.5+2
  EXPECT_TRUE(check_references(m).empty());
}

TEST(KeywordSyntax, ParameterErrorsAreLocated) {
  try {
    read_keyword_string("*KEYWORD\n*MAT_ELASTIC\n         1      &rho\n", "p.k");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "p.k:3: columns 11-20 of *MAT_ELASTIC: parameter &RHO is not defined (a *PARAMETER must come "
                 "before the cards that use it)");
  }
  try {
    read_keyword_string("*KEYWORD\n*PARAMETER_EXPRESSION\nR x       2*(3+\n", "p.k");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("p.k:3: *PARAMETER_EXPRESSION X: expression '2*(3+': a value is missing", 0),
              0u)
        << e.what();
  }
  EXPECT_THROW(read_keyword_string("*PARAMETER_EXPRESSION\nR x       1/0\n", "p.k"), InputError);
  EXPECT_THROW(read_keyword_string("*PARAMETER_EXPRESSION\nR x       foo(1)\n", "p.k"), InputError);
  EXPECT_THROW(read_keyword_string("*PARAMETER\nX x            1\n", "p.k"), InputError);
  EXPECT_THROW(read_keyword_string("*PARAMETER\nI n          1.5\n", "p.k"), InputError);
  // Free format and character parameters.
  const auto m = read_keyword_string(
      "*PARAMETER\nR e, 2.5e3, C t, hello\n*PARAMETER_EXPRESSION\nI n, int(7/2) + 2**3\n"
      "*MAT_ELASTIC\n&n,1.0,&e,0.25\n",
      "f.k");
  const auto& e = std::get<model::MatElastic>(m.materials.at(0));
  EXPECT_EQ(e.mid, 11);
  EXPECT_DOUBLE_EQ(e.e, 2500.0);
}

TEST(KeywordSyntax, GarbageParametersExpressionsAndIncludesOnlyThrowSlidelineErrors) {
  // The seed-deck fuzz test never writes these cards: random expressions, names and include paths.
  const std::string alphabet = "()+-*/^&,.eEdD0123456789 abxyzpi_sqrtmaxR\t\x01\xff";
  std::uint64_t x = 0x9E3779B97F4A7C15ull;
  const auto next = [&] {
    x ^= x << 13, x ^= x >> 7, x ^= x << 17;
    return x;
  };
  int rejected = 0;
  for (int k = 0; k < 3000; ++k) {
    std::string junk;
    const std::size_t n = next() % 40;
    for (std::size_t i = 0; i < n; ++i) junk += alphabet[next() % alphabet.size()];
    const std::string decks[] = {
        "*PARAMETER\nR a            2\n*PARAMETER_EXPRESSION\nR x       " + junk + "\n",
        "*PARAMETER\n" + junk + "\n*NODE\n1,&a,0,0\n",
        "*INCLUDE\n" + junk + "\n",
        "*KEYWORD " + junk + "\n*NODE" + junk.substr(0, 2) + "\n1,0,0,0\n",
    };
    for (const auto& d : decks) {
      try {
        read_keyword_string(d, "g.k");
      } catch (const Error&) {
        ++rejected;
      } catch (const std::exception& e) {
        ADD_FAILURE() << "non-slideline exception " << e.what() << " on:\n" << d;
        return;
      }
    }
  }
  EXPECT_GT(rejected, 3000);
  // A pathological expression is refused, not a stack overflow.
  EXPECT_THROW(read_keyword_string("*PARAMETER_EXPRESSION\nR x       " + std::string(100000, '(') + "1\n", "d.k"),
               InputError);
  EXPECT_THROW(read_keyword_string("*PARAMETER_EXPRESSION\nR x       " + std::string(100000, '-') + "1\n", "d.k"),
               InputError);
}

TEST(KeywordSyntax, FortranRealsWithoutExponentLetter) {
  const auto m = read_keyword_string("*NODE\n1,2.00000-3,1.5+2,-4.-1\n2,1.5e+2,1.5D-2,+3.0\n", "f.k");
  ASSERT_EQ(m.nodes.size(), 2u);
  EXPECT_DOUBLE_EQ(m.nodes[0].x[0], 2.0e-3);
  EXPECT_DOUBLE_EQ(m.nodes[0].x[1], 150.0);
  EXPECT_DOUBLE_EQ(m.nodes[0].x[2], -0.4);
  EXPECT_DOUBLE_EQ(m.nodes[1].x[0], 150.0);
  EXPECT_DOUBLE_EQ(m.nodes[1].x[1], 0.015);
  EXPECT_DOUBLE_EQ(m.nodes[1].x[2], 3.0);
  EXPECT_THROW(read_keyword_string("*NODE\n1,1.5-,0,0\n", "f.k"), InputError);
  EXPECT_THROW(read_keyword_string("*NODE\n1,1-2-3,0,0\n", "f.k"), InputError);
}

TEST(KeywordSyntax, LongAndI10Formats) {
  std::vector<Diagnostic> warnings;
  const auto m = read_keyword_file(reader_deck("long_format.k"), &warnings);
  EXPECT_TRUE(warnings.empty()) << to_string(warnings.front());
  ASSERT_EQ(m.nodes.size(), 8u);
  EXPECT_DOUBLE_EQ(m.nodes[6].x[1], 1.0);
  ASSERT_EQ(m.solids.size(), 1u);
  EXPECT_EQ(m.solids[0].n[7], 8);
  EXPECT_EQ(m.solid_sections.at(0).secid, 1);  // "*SECTION_SOLID-": standard format for one keyword
  EXPECT_DOUBLE_EQ(std::get<model::MatElastic>(m.materials.at(0)).e, 1000.0);
  // One keyword in long format with the '+' suffix, I10 with '%'.
  const auto n = read_keyword_string(
      "*NODE +\n                   7                 1.5                 2.5                 3.5\n"
      "*ELEMENT_SHELL%\n         1         2         1         2         3         4\n",
      "l.k");
  ASSERT_EQ(n.nodes.size(), 1u);
  EXPECT_EQ(n.nodes[0].id, 7);
  EXPECT_DOUBLE_EQ(n.nodes[0].x[2], 3.5);
  ASSERT_EQ(n.shells.size(), 1u);
  EXPECT_EQ(n.shells[0].pid, 2);
  EXPECT_EQ(n.shells[0].n[3], 4);
}

TEST(KeywordSyntax, CrOnlyAndCrLfLineEndings) {
  const auto cr = read_keyword_file(reader_deck("cr_only.k"));
  EXPECT_EQ(cr.nodes.size(), 8u);
  EXPECT_EQ(cr.solids.size(), 1u);
  EXPECT_EQ(cr.title.find('\r'), std::string::npos);
  const auto crlf = read_keyword_string("*NODE\r\n1,0,0,0\r\n2,1,0,0\r\n", "w.k");
  EXPECT_EQ(crlf.nodes.size(), 2u);
}

TEST(KeywordSyntax, FilesWithoutKeywordsAreRefused) {
  EXPECT_NE(message_of(reader_deck("empty.k")).find("no keyword cards"), std::string::npos);
  EXPECT_NE(message_of(reader_deck("comments_only.k")).find("comments_only.k:3: no keyword cards"), std::string::npos);
  std::string bytes;
  std::uint64_t x = 88172645463325252ull;
  for (int i = 0; i < 100000; ++i) {
    x ^= x << 13, x ^= x >> 7, x ^= x << 17;
    bytes.push_back(static_cast<char>(x & 0xff));
  }
  EXPECT_THROW(read_keyword_string(bytes, "random.bin"), Error);
  try {
    read_keyword_string("*KEYWORD\n*NO\x01" "DE\n", "bin.k");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "bin.k:2: '*NO\\x01DE' is not a keyword (non-text bytes): the file is not a keyword "
                           "deck, or it is corrupted");
  }
}

long max_rss_kb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss;
}

TEST(KeywordSyntax, SixMegabytesOfJunkStayCheap) {
  // Junk lines under an unknown card, blank lines under *NODE, junk under an output card.
  std::string junk = "*KEYWORD\n*FOO_JUNK\n";
  while (junk.size() < 2'000'000) junk += "x 1 2 3 junk junk\n";
  junk += "*NODE\n1,0,0,0\n";
  junk.append(2'000'000, '\n');
  junk += "*DATABASE_JUNK\n";
  while (junk.size() < 6'000'000) junk += "0.1\n";
  const long before = max_rss_kb();
  std::vector<Diagnostic> warnings;
  ReadOptions ignore;
  ignore.ignore_unsupported = true;
  const auto m = read_keyword_string(junk, "junk.k", &warnings, ignore);
  const long grown_mb = (max_rss_kb() - before) / 1024;
  EXPECT_LT(grown_mb, 40) << "reading 6 MB of junk grew the peak memory by " << grown_mb << " MB";
  EXPECT_EQ(m.nodes.size(), 1u);
  ASSERT_EQ(m.unsupported.size(), 1u);
  EXPECT_EQ(m.unsupported[0].keyword, "*FOO_JUNK");
  EXPECT_GT(m.unsupported[0].cards, 100000);
  ASSERT_EQ(warnings.size(), 2u);  // one per card kind
}

}  // namespace
}  // namespace slideline
