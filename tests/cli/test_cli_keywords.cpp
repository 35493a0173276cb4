// `blockcontact keywords`: it lists every keyword of the reader's table (checked against the table
// itself, slideline::supported_keywords(), not against a copy), each of which the reader reads;
// `--unsupported` lists the classes the reader refuses or skips.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "slideline/core/error.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/io/keyword_table.hpp"
#include "slideline/model/contact_keywords.hpp"

namespace {

/// stdout of `blockcontact <args>`, and its exit status.
std::string run(const std::string& args, int& status) {
  const std::string cmd = std::string(SLIDELINE_BLOCKCONTACT) + " " + args;
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return {};
  std::string out;
  std::array<char, 4096> buf{};
  while (const std::size_t n = std::fread(buf.data(), 1, buf.size(), p)) out.append(buf.data(), n);
  status = pclose(p);
  return out;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

/// The listed line that starts with `name` followed by an option or a space, or "".
std::string line_for(const std::vector<std::string>& lines, const std::string& name) {
  for (const auto& l : lines)
    if (l.rfind(name, 0) == 0 && l.size() > name.size() && (l[name.size()] == ' ' || l[name.size()] == '['))
      return l;
  return {};
}

TEST(CliKeywords, ListsEveryKeywordOfTheReadersTable) {
  int status = -1;
  const auto lines = lines_of(run("keywords", status));
  ASSERT_EQ(status, 0);
  const auto& table = slideline::supported_keywords();
  ASSERT_GT(table.size(), 40u);
  EXPECT_EQ(lines.size(), table.size());
  for (const auto& k : table) {
    const std::string line = line_for(lines, k.name);
    ASSERT_FALSE(line.empty()) << k.name << " is read but not listed";
    EXPECT_NE(line.find(k.options), std::string::npos) << line;
    EXPECT_NE(line.find(k.description), std::string::npos) << line;
    EXPECT_FALSE(k.description.empty()) << k.name;
  }
  EXPECT_NE(line_for(lines, "*CONTACT_SURFACE_TO_SURFACE").find("[_LAGRANGE][_ID|_TITLE]"), std::string::npos);
  EXPECT_NE(line_for(lines, "*CONTACT_SURFACE_TO_SURFACE").find("type 3"), std::string::npos);
  EXPECT_NE(line_for(lines, "*MAT_ELASTIC").find("[_TITLE]"), std::string::npos);
}

// Every contact card of the contact keyword table is in the reader's table.
TEST(CliKeywords, ListsEveryContactCard) {
  const auto& table = slideline::supported_keywords();
  for (const auto& c : slideline::model::kContactKeywords) {
    bool found = false;
    for (const auto& k : table) found = found || k.name == c.keyword;
    EXPECT_TRUE(found) << c.keyword;
  }
}

/// Each spelling a listed line offers: the name, and the name with each option of its "[...]"
/// groups (one group at a time).
std::vector<std::string> spellings(const slideline::KeywordInfo& k) {
  std::vector<std::string> out{k.name};
  std::string_view o = k.options;
  while (!o.empty() && o.front() == '[') {
    const auto close = o.find(']');
    std::string_view group = o.substr(1, close - 1);
    while (true) {
      const auto bar = group.find('|');
      out.push_back(k.name + std::string(group.substr(0, bar)));
      if (bar == std::string_view::npos) break;
      group.remove_prefix(bar + 1);
    }
    o.remove_prefix(close + 1);
  }
  return out;
}

// What is listed is what the reader reads: each spelling of each listed keyword, alone in a deck,
// is read (it may lack cards: an input error) and never refused as an unsupported card.
TEST(CliKeywords, EveryListedSpellingIsRead) {
  int checked = 0;
  for (const auto& k : slideline::supported_keywords())
    for (const auto& kw : spellings(k)) {
      EXPECT_TRUE(slideline::reads_keyword(kw)) << kw;
      try {
        slideline::read_keyword_string("*KEYWORD\n" + kw + "\n*END\n", "k.k");
      } catch (const slideline::NotImplementedError& e) {
        EXPECT_EQ(std::string(e.what()).find("not supported"), std::string::npos) << kw << ": " << e.what();
      } catch (const slideline::InputError&) {
        // A card the keyword must have is missing: it was read.
      }
      ++checked;
    }
  EXPECT_GT(checked, 100);
  EXPECT_FALSE(slideline::reads_keyword("*MAT_JOHNSON_COOK"));
  EXPECT_FALSE(slideline::reads_keyword("*CONTACT_SURFACE_TO_SURFACE_ID_LAGRANGE"));
}

TEST(CliKeywords, UnsupportedListsTheClassesWithWhy) {
  int status = -1;
  const std::string out = run("keywords --unsupported", status);
  ASSERT_EQ(status, 0);
  const auto lines = lines_of(out);
  const auto line_of = [&](const std::string& start) {
    for (const auto& l : lines)
      if (l.rfind(start, 0) == 0) return l;
    return std::string();
  };
  for (const auto& c : slideline::unsupported_keyword_classes()) {
    const std::string line = line_of(std::string(c.prefix) + "... ");
    ASSERT_FALSE(line.empty()) << c.prefix;
    EXPECT_NE(line.find(std::string(c.what) + (c.physics ? ": refused" : ": skipped with a warning")),
              std::string::npos)
        << line;
  }
  EXPECT_NE(line_of("*MAT_... ").find("material: refused, it carries physics"), std::string::npos) << out;
  EXPECT_NE(line_of("*DATABASE_... ").find("output request: skipped with a warning"), std::string::npos) << out;
}

}  // namespace
