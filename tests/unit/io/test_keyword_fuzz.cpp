// Property test: whatever a deck holds, the reader either returns a model or throws a
// slideline::Error (in practice InputError) — never another exception, never a crash.
// Mutations of the seed decks in tests/data/decks with a fixed seed, so failures reproduce.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "slideline/core/error.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/solver/validate_model.hpp"

namespace slideline {
namespace {

std::vector<std::string> seed_decks() {
  std::vector<std::string> decks;
  for (const auto& e : std::filesystem::directory_iterator(std::string(SLIDELINE_SOURCE_DIR) + "/tests/data/decks")) {
    if (e.path().extension() != ".k") continue;
    std::ifstream in(e.path(), std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    decks.push_back(ss.str());
  }
  std::sort(decks.begin(), decks.end());  // directory order is not deterministic
  return decks;
}

std::vector<std::string> split_lines(const std::string& s) {
  std::vector<std::string> lines;
  std::stringstream ss(s);
  std::string l;
  while (std::getline(ss, l)) lines.push_back(l);
  return lines;
}

std::string join_lines(const std::vector<std::string>& lines) {
  std::string s;
  for (const auto& l : lines) s += l + "\n";
  return s;
}

/// One random mutation of a deck.
std::string mutate(std::string deck, std::mt19937_64& rng) {
  static const char* const garbage[] = {"xyz", "1e999", "-", "+", ".", "1.2.3", "nan", "inf", "1d", "e5",
                                        ",", ",,,,,,,,,,", "*", "$", "99999999999999999999", "-2147483649",
                                        "0x10", " 1 2 ", "\t", "\r", "*NODE", "*END", "*PART", "1e308",
                                        "-1", "0", "\x01\xff", "_ID"};
  auto pick = [&](std::size_t n) { return n == 0 ? std::size_t{0} : std::size_t(rng() % n); };
  switch (rng() % 7) {
    case 0: {  // byte flips
      const int flips = 1 + int(rng() % 4);
      for (int k = 0; k < flips && !deck.empty(); ++k) deck[pick(deck.size())] = char(rng() % 256);
      return deck;
    }
    case 1:  // truncation
      return deck.substr(0, pick(deck.size() + 1));
    case 2: {  // delete lines
      auto lines = split_lines(deck);
      const int n = 1 + int(rng() % 3);
      for (int k = 0; k < n && !lines.empty(); ++k) lines.erase(lines.begin() + long(pick(lines.size())));
      return join_lines(lines);
    }
    case 3: {  // duplicate a line
      auto lines = split_lines(deck);
      if (!lines.empty()) {
        const auto i = pick(lines.size());
        lines.insert(lines.begin() + long(i), lines[i]);
      }
      return join_lines(lines);
    }
    case 4: {  // garbage in a fixed field position
      auto lines = split_lines(deck);
      if (lines.empty()) return deck;
      auto& l = lines[pick(lines.size())];
      const std::size_t col = 10 * pick(8);
      if (l.size() < col + 10) l.resize(col + 10, ' ');
      std::string g = garbage[pick(std::size(garbage))];
      g.resize(10, ' ');
      l.replace(col, 10, g);
      return join_lines(lines);
    }
    case 5: {  // garbage inserted anywhere
      const auto at = pick(deck.size() + 1);
      return deck.insert(at, garbage[pick(std::size(garbage))]);
    }
    default: {  // swap two lines
      auto lines = split_lines(deck);
      if (lines.size() > 1) std::swap(lines[pick(lines.size())], lines[pick(lines.size())]);
      return join_lines(lines);
    }
  }
}

TEST(KeywordFuzz, MutatedDecksOnlyEverThrowSlidelineErrors) {
  const auto seeds = seed_decks();
  ASSERT_GE(seeds.size(), 3u);
  std::mt19937_64 rng(20261122);
  const int mutations = 20000;
  int accepted = 0;
  int rejected = 0;
  for (int k = 0; k < mutations; ++k) {
    std::string deck = seeds[std::size_t(k) % seeds.size()];
    const int rounds = 1 + int(rng() % 3);
    for (int r = 0; r < rounds; ++r) deck = mutate(std::move(deck), rng);
    std::vector<Diagnostic> warnings;
    try {
      const auto m = read_keyword_string(deck, "mutant.k", &warnings);
      (void)check_references(m);  // must not crash either
      ++accepted;
    } catch (const Error&) {
      ++rejected;
    } catch (const std::exception& e) {
      ADD_FAILURE() << "mutation " << k << " threw a non-slideline exception: " << e.what() << "\n--- deck ---\n"
                    << deck;
      return;
    }
  }
  EXPECT_EQ(accepted + rejected, mutations);
  // Both outcomes must occur, else the mutations are too weak or too destructive to test anything.
  EXPECT_GT(accepted, mutations / 20);
  EXPECT_GT(rejected, mutations / 20);
  RecordProperty("accepted", accepted);
  RecordProperty("rejected", rejected);
}

}  // namespace
}  // namespace slideline
