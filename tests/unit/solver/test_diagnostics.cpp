// The library's warnings go to the DiagnosticSink its caller passes in (BuildOptions::diagnostics,
// handed on to the contact interfaces), never to stderr: the initial penetrations a penalty
// interface moves out, and the slaves a tied interface leaves free.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "slideline/core/diagnostics.hpp"
#include "slideline/scenarios/sslide.hpp"
#include "slideline/solver/build.hpp"

namespace slideline {
namespace {

using scenarios::make_sslide_problem;
using scenarios::SslideProblem;

/// Moves every node of pairing 0's upper (slave) body by d.
void move_upper_body(SslideProblem& p, const Vec3& d) {
  const Id upper = p.pairings[0].upper_part;
  std::set<Id> moved;
  for (const auto& e : p.model.solids)
    if (e.pid == upper) moved.insert(e.n.begin(), e.n.end());
  for (const auto& e : p.model.shells)
    if (e.pid == upper) moved.insert(e.n.begin(), e.n.end());
  for (auto& n : p.model.nodes)
    if (moved.count(n.id)) n.x += d;
}

/// Builds and initialises the model with `sink` (may be null); returns what went to stderr.
std::string build_and_initialize(const model::Model& m, DiagnosticSink* sink) {
  BuildOptions o;
  o.diagnostics = sink;
  testing::internal::CaptureStderr();
  auto sim = build_simulation(m, o);
  sim->initialize();
  return testing::internal::GetCapturedStderr();
}

TEST(Diagnostics, InitialPenetrationsGoToTheSinkNotToStderr) {
  SslideProblem p = make_sslide_problem("sslide10pv");
  move_upper_body(p, Vec3(0.0, -2e-3, 0.0));  // the 16 bottom nodes of the solid block 2e-3 deep
  DiagnosticList sink;
  EXPECT_EQ(build_and_initialize(p.model, &sink), "");
  ASSERT_EQ(sink.warnings.size(), 1u);
  const Diagnostic& w = sink.warnings[0];
  EXPECT_EQ(w.file, "");
  EXPECT_EQ(w.line, 0);
  EXPECT_EQ(w.message.rfind("contact '", 0), 0u) << w.message;
  EXPECT_NE(w.message.find("': 16 initial penetration(s), largest 0.002: 16 node(s) moved out to the surface, "
                           "largest move 0.002"),
            std::string::npos)
      << w.message;
  // Without a sink the warning is dropped: the library still prints nothing.
  EXPECT_EQ(build_and_initialize(p.model, nullptr), "");
}

TEST(Diagnostics, UntiedSlavesGoToTheSinkNotToStderr) {
  SslideProblem p = make_sslide_problem("sslide2kc");
  move_upper_body(p, Vec3(0.9, 0.0, 0.0));  // the block overhangs the master's x end
  DiagnosticList sink;
  EXPECT_EQ(build_and_initialize(p.model, &sink), "");
  ASSERT_EQ(sink.warnings.size(), 1u);
  const std::string& m = sink.warnings[0].message;
  EXPECT_EQ(m.rfind("contact ", 0), 0u) << m;
  EXPECT_NE(m.find(" slave node(s) project outside every master segment and are left free (first ids: "),
            std::string::npos)
      << m;
  EXPECT_EQ(build_and_initialize(p.model, nullptr), "");
}

TEST(Diagnostics, WarnFormatsOnlyWhenThereIsASink) {
  DiagnosticList sink;
  warn(&sink, "contact '%s': %ld item(s), largest %.6g", "a", 3L, 0.25);
  warn(nullptr, "never %s", "formatted");
  ASSERT_EQ(sink.warnings.size(), 1u);
  EXPECT_EQ(to_string(sink.warnings[0]), "contact 'a': 3 item(s), largest 0.25");
  EXPECT_EQ(to_string({"deck.k", 12, "m"}), "deck.k:12: m");
  EXPECT_EQ(to_string({"deck.k", 0, "m"}), "deck.k: m");
}

}  // namespace
}  // namespace slideline
