// The verification criteria, proven before contact runs: histories synthesised from the closed-form
// answers pass every criterion of every problem; each perturbation fails the criterion it targets.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <set>

#include "slideline/core/error.hpp"
#include "slideline/io/hdf5_writer.hpp"
#include "slideline/scenarios/sslide_criteria.hpp"

namespace slideline::scenarios {
namespace {

Dyna3dReported reported() { return Dyna3dReported::builtin(); }

/// Changes to the synthetic answer: F, master force, reaction and relative displacement at time t
/// for pairing p, applied after the closed form.
struct Perturbation {
  std::function<void(Real t, Vec3& force)> force;
  std::function<void(Real t, Vec3& master)> master;
  std::function<void(Real t, Vec3& reaction)> reaction;
  std::function<void(Real t, Vec3& rel)> relative;
};

/// A recorded History with the channels a real run reports, built from the closed form: slave
/// force F, master -F, reactions split between the bottom (y) and right (x) supports, master nodes
/// moving with a common elastic field and the slave node moving with it plus the relative
/// displacement (zero while stuck; sliding, or lifting off after a tensile failure).
History synthesise(const SslideProblem& pr, const Perturbation& dp = {}) {
  const auto channels = sslide_channels(pr);
  std::vector<HistoryChannel> hc;
  for (const auto& c : channels) hc.push_back({c, 3});
  History h;
  h.begin(hc, {});
  std::vector<Real> values(3 * hc.size());
  for (int k = 0; k <= 500; ++k) {
    const Real t = 0.001 * k;
    std::fill(values.begin(), values.end(), 0.0);
    auto put = [&](const std::string& path, const Vec3& v) {
      const auto it = std::find(channels.begin(), channels.end(), path);
      const auto c = static_cast<std::size_t>(it - channels.begin());
      for (int d = 0; d < 3; ++d) values[3 * c + d] += v[d];
    };
    for (const auto& p : pr.pairings) {
      const auto e = sslide_expected(pr, p, t);
      Vec3 f = e.force, r = e.reaction;
      if (pr.idealization == SslideIdealization::frictionless) {
        f.x() = -f.y() * (1.5e-3 + 2 * 2e-4 * 0.53);  // the tilt of the face under the block
        r.x() = -f.x();
      }
      if (dp.force) dp.force(t, f);
      Vec3 fm = -f;
      if (dp.master) dp.master(t, fm);
      if (dp.reaction) dp.reaction(t, r);
      put(sslide_force_channel(pr, p), f);
      if (pr.type != model::ContactType::automatic) put(sslide_master_channel(p), fm);
      put(sslide_support_channel(p.bottom_support), Vec3(0, r.y(), 0));
      put(sslide_support_channel(p.right_support), Vec3(r.x(), 0, 0));
      Vec3 rel = Vec3::Zero();
      if (f.x() != -p.px * std::clamp((t - 0.3) / 0.1, 0.0, 1.0) && pr.idealization != SslideIdealization::tied)
        rel.x() = 0.5 * (t - 0.39) * (t - 0.39);  // sliding after the static limit
      if (pr.idealization == SslideIdealization::tension_failure && t > pr.failure_time)
        rel.y() = 50.0 * (t - pr.failure_time) * (t - pr.failure_time);  // lifting off
      if (dp.relative) dp.relative(t, rel);
      const Vec3 common(1e-4 * t, -2e-3 * t, 3e-5 * t);
      // Frictionless: the lower block's top face tilts (u_y rising towards +x, slope 1.5e-3 to
      // 1.9e-3) and the force follows the normal, F_x = -F_y x the slope under the block's centre.
      const bool tilt = pr.idealization == SslideIdealization::frictionless;
      Real x_left = 1e300;
      for (const auto& seg : p.monitor.path)
        for (const auto& x : seg.x0) x_left = std::min(x_left, x.x());
      const auto face = [&](Real x) {
        const Real d = x - x_left;
        return tilt ? std::clamp(t / 0.1, 0.0, 1.0) * (1.5e-3 * d + 2e-4 * d * d) : 0.0;
      };
      std::set<Id> row;
      for (const auto& seg : p.monitor.path)
        for (std::size_t k = 0; k < 4; ++k)
          if (row.insert(seg.nodes[k]).second) put(sslide_node_channel(seg.nodes[k]), common + Vec3(0, face(seg.x0[k].x()), 0));
      for (Id n : p.monitor.master_nodes)
        if (!row.count(n)) put(sslide_node_channel(n), common);
      put(sslide_node_channel(p.monitor.slave_node),
          common + rel + Vec3(0, face(p.monitor.slave_x0.x() + common.x() + rel.x()), 0));
      if (p.monitor.leading_node != p.monitor.slave_node)  // the upper body moves as one
        put(sslide_node_channel(p.monitor.leading_node), common + rel);
      if (pr.type == model::ContactType::tiebreak_surface && t >= pr.failure_time)
        // The last record before the closed form drops is 8.9 (t = 0.089): a mean traction of 8.9
        // when the most loaded segment reaches 9.0.
        put(sslide_first_failure_channel(p), Vec3(9.0, 8.9, 9.0 / 8.9));
    }
    h.write_history(t, values);
  }
  return h;
}

std::vector<SslideCriterion> evaluate(const SslideProblem& pr, const Perturbation& dp = {}) {
  return evaluate_sslide_criteria(pr, sslide_histories(synthesise(pr, dp), pr), reported());
}

/// Rows that failed, as "pairing: criterion" strings.
std::vector<std::string> failures(const std::vector<SslideCriterion>& rows) {
  std::vector<std::string> f;
  for (const auto& r : rows)
    if (!r.pass) f.push_back(r.pairing + ": " + r.criterion + " = " + std::to_string(r.measured) + " (" + r.bound + ")");
  return f;
}

bool failed(const std::vector<SslideCriterion>& rows, const std::string& criterion) {
  return std::any_of(rows.begin(), rows.end(),
                     [&](const SslideCriterion& r) { return !r.pass && r.criterion.rfind(criterion, 0) == 0; });
}

TEST(SslideCriteria, ClosedFormPassesEveryCriterionOfEveryProblem) {
  for (const auto& name : sslide_problem_names()) {
    SCOPED_TRACE(name);
    const auto pr = make_sslide_problem(name);
    const auto rows = evaluate(pr);
    EXPECT_GE(rows.size(), 4u * pr.pairings.size());
    for (const auto& f : failures(rows)) ADD_FAILURE() << f;
    for (const auto& r : rows) EXPECT_EQ(r.problem, name);
  }
}

TEST(SslideCriteria, DyNA3DFiguresAppearBesideTheirRows) {
  const auto rows = evaluate(make_sslide_problem("sslide3p"));
  int with_figure = 0;
  for (const auto& r : rows)
    if (r.criterion.rfind("peak |F_x|", 0) == 0 && r.pairing == "shell_on_shell") {
      ASSERT_TRUE(r.dyna3d.has_value());
      EXPECT_EQ(*r.dyna3d, 2.90);  // report 6.3.1: 2.90 for shell-on-shell
      ++with_figure;
    }
  EXPECT_EQ(with_figure, 1);
}

TEST(SslideCriteria, PerturbedNormalForceFails) {
  const auto pr = make_sslide_problem("sslide3p");
  const auto rows = evaluate(pr, {.force = [](Real, Vec3& f) { f.y() *= 1.03; }});
  EXPECT_TRUE(failed(rows, "mean F_y"));
  EXPECT_TRUE(failed(rows, "mean R_y"));  // R no longer balances F
  EXPECT_FALSE(failed(rows, "peak |F_x|"));
}

TEST(SslideCriteria, ImbalancedMasterForceFails) {
  const auto pr = make_sslide_problem("sslide2kc");
  const auto rows = evaluate(pr, {.master = [](Real, Vec3& m) { m *= 1.0 + 1e-5; }});
  EXPECT_TRUE(failed(rows, "balance"));
  EXPECT_FALSE(failed(rows, "mean F_x"));
}

TEST(SslideCriteria, FrictionWithoutStaticPeakFails) {
  const auto pr = make_sslide_problem("sslide10pv");
  const auto rows = evaluate(pr, {.force = [](Real, Vec3& f) { f.x() = std::max(f.x(), -2.5); },
                                  .reaction = [](Real, Vec3& r) { r.x() = std::min(r.x(), 2.5); }});
  EXPECT_TRUE(failed(rows, "peak |F_x|"));
  EXPECT_TRUE(failed(rows, "peak |R_x|"));
  EXPECT_FALSE(failed(rows, "mean F_x"));
}

TEST(SslideCriteria, WrongKineticFrictionFails) {
  const auto pr = make_sslide_problem("sslide12p");
  const auto rows = evaluate(pr, {.force = [](Real t, Vec3& f) { if (t > 0.45) f.x() = -2.6; }});
  EXPECT_TRUE(failed(rows, "mean F_x [0.45,0.5]"));
  EXPECT_FALSE(failed(rows, "mean R_x"));
}

TEST(SslideCriteria, EarlySlipAndInterpenetrationFail) {
  const auto pr = make_sslide_problem("sslide5l");
  const auto rows = evaluate(pr, {.relative = [](Real t, Vec3& u) {
                                    if (t > 0.32) u.x() += 2e-3;
                                    u.y() = -1e-3;  // DYNA3D reached 3.5e-4 (report 6.4.2)
                                  }});
  EXPECT_TRUE(failed(rows, "no slip"));
  EXPECT_TRUE(failed(rows, "interpenetration"));
}

TEST(SslideCriteria, TiedInterfaceThatSlipsFails) {
  const auto pr = make_sslide_problem("sslide6k");
  const auto rows = evaluate(pr, {.relative = [](Real t, Vec3& u) { u.x() = t > 0.4 ? 2e-4 : 0.0; }});
  EXPECT_TRUE(failed(rows, "max |rel x|"));
  EXPECT_FALSE(failed(rows, "max |rel y|"));
}

TEST(SslideCriteria, FrictionlessInterfaceWithFrictionFails) {
  const auto pr = make_sslide_problem("sslide1k");
  const auto rows = evaluate(pr, {.force = [](Real t, Vec3& f) { f.x() = t > 0.3 ? -0.03 : f.x(); }});
  EXPECT_TRUE(failed(rows, "max |F_x|"));
  EXPECT_TRUE(failed(rows, "|mean R_x + mean F_x|"));  // R no longer carries F
  EXPECT_FALSE(failed(rows, "max |R_x|"));
  EXPECT_FALSE(failed(rows, "tilt"));  // [0.2, 0.3] untouched
}

TEST(SslideCriteria, FrictionlessForceOffTheMasterNormalFails) {
  const auto pr = make_sslide_problem("sslide1k");
  // Within max |F_x| <= 0.02 but not along the tilted face: -F_x / F_y = 1.0e-3, the slopes under
  // the block are 1.6e-3 to 1.8e-3.
  const auto rows = evaluate(pr, {.force = [](Real, Vec3& f) { f.x() = -1e-3 * f.y(); },
                                  .reaction = [](Real, Vec3& r) { r.x() = 1e-3 * -r.y(); }});
  EXPECT_TRUE(failed(rows, "tilt"));
  EXPECT_FALSE(failed(rows, "max |F_x|"));
  EXPECT_FALSE(failed(rows, "max |R_x|"));
}

TEST(SslideCriteria, ReactionVibrationBeyondOnePercentFails) {
  const auto pr = make_sslide_problem("sslide1k");
  const auto rows = evaluate(pr, {.reaction = [](Real t, Vec3& r) { r.x() += 0.12 * std::sin(500.0 * t); }});
  EXPECT_TRUE(failed(rows, "max |R_x|"));
  EXPECT_FALSE(failed(rows, "max |F_x|"));
}

TEST(SslideCriteria, ChatterFails) {
  const auto pr = make_sslide_problem("sslide10lr");
  // Standard deviation ~0.6 / sqrt(2) = 0.42 > 3% of 10, over [0.45, 0.5] only.
  const auto rows = evaluate(pr, {.force = [](Real t, Vec3& f) { if (t >= 0.45) f.y() += 0.6 * std::sin(2000.0 * t); }});
  EXPECT_TRUE(failed(rows, "std F_y [0.45,0.5]"));
  EXPECT_FALSE(failed(rows, "std F_y [0.2,0.3]"));
  EXPECT_FALSE(failed(rows, "mean F_y"));
}

TEST(SslideCriteria, TensileFailureHasNoChatterRowsAfterFailure) {
  for (const char* name : {"sslide8p", "sslide9pt"}) {
    const auto rows = evaluate(make_sslide_problem(name));
    for (const auto& r : rows) EXPECT_EQ(r.criterion.rfind("std F_y", 0), std::string::npos) << name;
  }
  const auto rows = evaluate(make_sslide_problem("sslide9ps"));  // shear failure: before and after
  EXPECT_EQ(std::count_if(rows.begin(), rows.end(), [](const auto& r) { return r.criterion.rfind("std F_y", 0) == 0; }), 2);
}

TEST(SslideCriteria, TypeNineTensionPeakMustMatchTheStressRatio) {
  const auto pr = make_sslide_problem("sslide9pt");
  // Peak 8.6 (inside [8.55, 9.36]) but the recorded max/mean traction 9.0 / 8.9 predicts 8.9.
  const auto rows = evaluate(pr, {.force = [](Real, Vec3& f) { f.y() = std::max(f.y(), -8.6); }});
  EXPECT_TRUE(failed(rows, "peak x max/mean stress"));
  EXPECT_FALSE(failed(rows, "peak |F_y|"));
  auto h = sslide_histories(synthesise(pr), pr);
  h.channels.erase(sslide_first_failure_channel(pr.pairings.front()));
  EXPECT_TRUE(failed(evaluate_sslide_criteria(pr, h, reported()), "peak x max/mean stress"));
}

TEST(SslideCriteria, TypeEightFailureTimeIsTheFirstRecordNearThePeak) {
  const auto pr = make_sslide_problem("sslide8p");
  // A rebound 0.8% above the first peak at t = 0.11 is allowed; one 2% above is not.
  const auto rebound = [](Real height) {
    return Perturbation{.force = [height](Real t, Vec3& f) {
      if (t >= 0.09 && t < 0.11) f.y() = -9.0;
      if (std::abs(t - 0.11) < 5e-4) f.y() = -9.0 * height;
    }};
  };
  EXPECT_FALSE(failed(evaluate(pr, rebound(1.008)), "failure time"));
  EXPECT_TRUE(failed(evaluate(pr, rebound(1.02)), "failure time"));
}

TEST(SslideCriteria, InterpenetrationIsJudgedWhileTheNodeIsOverTheMaster) {
  const auto pr = make_sslide_problem("sslide9ps");
  // The block jumps 2.0 past the lower block's end at t = 0.45 and sinks 0.01: judged up to the
  // time its leading edge passes the end, with the time in the note.
  const auto rows = evaluate(pr, {.relative = [](Real t, Vec3& u) {
                                    if (t >= 0.45) u.x() = 2.0, u.y() = -0.01;
                                  }});
  bool seen = false;
  for (const auto& r : rows)
    if (r.criterion.rfind("interpenetration", 0) == 0) {
      EXPECT_TRUE(r.pass) << r.measured;
      EXPECT_NE(r.note.find("passes the lower block's edge at t = 0.45"), std::string::npos) << r.note;
      seen = true;
    }
  EXPECT_TRUE(seen);
  EXPECT_TRUE(failed(evaluate(pr, {.relative = [](Real t, Vec3& u) { if (t >= 0.45) u.y() = -0.01; }}),
                     "interpenetration"));
}

/// Slides at 5 per unit time from t = 0.4: the leading edge (x0 + 1.03 from the lower block's left
/// end, which is 1.51 long) passes the end when the slide exceeds 0.48, at the record t = 0.497.
void slide_off_at_0497(Real t, Vec3& u) {
  if (t > 0.4) u.x() = 5.0 * (t - 0.4);
}

TEST(SslideCriteria, EdgeCrossingIsWhenTheLeadingNodePassesTheLowerBlocksEnd) {
  const auto pr = make_sslide_problem("sslide9ps");
  const auto h = sslide_histories(synthesise(pr, {.relative = slide_off_at_0497}), pr);
  for (const auto& p : pr.pairings) {
    const auto e = sslide_edge_crossing(p, h);
    EXPECT_TRUE(e.recorded);
    ASSERT_TRUE(e.time.has_value());
    EXPECT_NEAR(*e.time, 0.497, 1e-12);
    // The monitored (centre) node is still 0.5 inside at that time: the leading node, not the
    // monitor, tells when the body leaves its seat.
    EXPECT_TRUE(*sslide_monitor_over_master(p, h, 497));
  }
  // The closed form slides 6e-3 by t = 0.5: never passes.
  const auto h0 = sslide_histories(synthesise(pr), pr);
  for (const auto& p : pr.pairings) EXPECT_FALSE(sslide_edge_crossing(p, h0).time.has_value());
}

TEST(SslideCriteria, RowsAfterTheEdgeCrossingAreJudgedOnlyBeforeIt) {
  const auto pr = make_sslide_problem("sslide9ps");
  // After the edge: the block sinks 0.01 and F_y swings +-2 (tipping off the end).
  const auto after = [](Real t) { return t >= 0.497 - 1e-9; };
  const Perturbation tipping{.force = [&](Real t, Vec3& f) { if (after(t)) f.y() += (static_cast<int>(t * 1e3 + 0.5) % 2 ? 2.0 : -2.0); },
                             .relative = [&](Real t, Vec3& u) {
                               slide_off_at_0497(t, u);
                               if (after(t)) u.y() = -0.01;
                             }};
  const auto rows = evaluate(pr, tipping);
  for (const auto& f : failures(rows)) ADD_FAILURE() << f;
  int noted = 0;
  for (const auto& r : rows)
    if (r.note.find("passes the lower block's edge at t = 0.497") != std::string::npos) ++noted;
  // interpenetration, std F_y [0.45,0.5], mean F_x and mean R_x [0.45,0.5]
  EXPECT_EQ(noted, 4);
  // The same tipping while the block is still seated fails both rows.
  const Perturbation seated{.force = tipping.force, .relative = [&](Real t, Vec3& u) { if (after(t)) u.y() = -0.01; }};
  const auto bad = evaluate(pr, seated);
  EXPECT_TRUE(failed(bad, "interpenetration"));
  EXPECT_TRUE(failed(bad, "std F_y [0.45,0.5]"));
}

TEST(SslideCriteria, MissingLeadingEdgeChannelFails) {
  const auto pr = make_sslide_problem("sslide9ps");
  auto h = sslide_histories(synthesise(pr), pr);
  h.channels.erase(sslide_node_channel(pr.pairings.front().monitor.leading_node));
  const auto rows = evaluate_sslide_criteria(pr, h, reported());
  EXPECT_TRUE(failed(rows, "leading edge seated"));
}

TEST(SslideCriteria, EarlyTensileFailureFails) {
  const auto pr = make_sslide_problem("sslide8p");
  const auto rows = evaluate(pr, {.force = [](Real t, Vec3& f) { if (t >= 0.07) f.y() = 0.0; }});
  EXPECT_TRUE(failed(rows, "peak |F_y|"));
  EXPECT_TRUE(failed(rows, "failure time"));
  EXPECT_FALSE(failed(rows, "max |F| t>0.15"));
}

TEST(SslideCriteria, InterfaceThatHoldsAfterFailureFails) {
  const auto pr = make_sslide_problem("sslide9pt");
  const auto rows = evaluate(pr, {.force = [](Real t, Vec3& f) { if (t > 0.2) f.y() = -0.1; },
                                  .relative = [](Real t, Vec3& u) { if (t > 0.2) u.y() = 0.0; }});
  EXPECT_TRUE(failed(rows, "max |F| t>0.15"));
  EXPECT_TRUE(failed(rows, "separated"));
}

TEST(SslideCriteria, LateShearFailureFails) {
  const auto pr = make_sslide_problem("sslide9ps");
  // Holds to the full load 4.0 (t = 0.4) before sliding.
  const auto rows = evaluate(pr, {.force = [](Real t, Vec3& f) {
                                    if (t > 0.38 && t <= 0.4) f.x() = -4.0 * (t - 0.3) / 0.1;
                                  }});
  EXPECT_TRUE(failed(rows, "peak |F_x| (shear failure)"));
  EXPECT_TRUE(failed(rows, "time of peak |F_x|"));
}

TEST(SslideCriteria, MissingChannelsFailLoudly) {
  const auto pr = make_sslide_problem("sslide12l");
  auto h = sslide_histories(synthesise(pr), pr);
  h.channels.erase(sslide_force_channel(pr, pr.pairings.front()));
  const auto rows = evaluate_sslide_criteria(pr, h, reported());
  bool named = false;
  for (const auto& r : rows)
    if (r.pairing == pr.pairings.front().name && r.note.find("transmitted_force") != std::string::npos) {
      EXPECT_FALSE(r.pass);
      EXPECT_TRUE(std::isnan(r.measured));
      named = true;
    }
  EXPECT_TRUE(named);
}

/// The rows of `problem` named `criterion` (prefix) after `edit` changed its synthesised histories.
std::vector<SslideCriterion> rows_after(const std::string& problem, const std::string& criterion,
                                        const std::function<void(const SslideProblem&, SslideHistories&)>& edit) {
  const auto pr = make_sslide_problem(problem);
  auto h = sslide_histories(synthesise(pr), pr);
  edit(pr, h);
  std::vector<SslideCriterion> out;
  for (const auto& r : evaluate_sslide_criteria(pr, h, reported()))
    if (r.criterion.rfind(criterion, 0) == 0) out.push_back(r);
  return out;
}

void expect_failed_with(const std::vector<SslideCriterion>& rows, const std::string& why) {
  ASSERT_FALSE(rows.empty());
  for (const auto& r : rows) {
    EXPECT_FALSE(r.pass) << r.pairing << ": " << r.criterion;
    EXPECT_NE(r.note.find(why), std::string::npos) << r.pairing << ": " << r.criterion << ": " << r.note;
  }
}

TEST(SslideCriteria, EmptyWindowFails) {
  // A run that stopped at t = 0.14: no record after 0.15 (it used to pass "max |F| t>0.15").
  const auto truncate = [](const SslideProblem&, SslideHistories& h) {
    std::size_t keep = 0;
    while (keep < h.time.size() && h.time[keep] <= 0.14 + 1e-9) ++keep;
    h.time.resize(keep);
    for (auto& [k, v] : h.channels) v.resize(keep);
  };
  expect_failed_with(rows_after("sslide8p", "max |F| t>0.15", truncate), "no record in [0.15");
  expect_failed_with(rows_after("sslide3p", "mean F_x [0.45,0.5]", truncate), "no record in [0.45, 0.5]");
  expect_failed_with(rows_after("sslide3p", "std F_y [0.2,0.3]", truncate), "no record in [0.2, 0.3]");
}

TEST(SslideCriteria, EmptySeriesFailsTheBalance) {
  const auto empty = [](const SslideProblem&, SslideHistories& h) {
    h.time.clear();
    for (auto& [k, v] : h.channels) v.clear();
  };
  expect_failed_with(rows_after("sslide2kc", "balance", empty), "one record per output time");
  expect_failed_with(rows_after("sslide2kc", "mean F_y", empty), "no record");
}

constexpr Real kNaN = std::numeric_limits<Real>::quiet_NaN();

TEST(SslideCriteria, NaNRecordsFail) {
  // A NaN first record of the monitor used to give an interpenetration of 0.
  const auto nan_monitor = [](const SslideProblem& pr, SslideHistories& h) {
    for (const auto& p : pr.pairings) h.channels.at(sslide_node_channel(p.monitor.slave_node))[0].y() = kNaN;
  };
  expect_failed_with(rows_after("sslide3p", "interpenetration", nan_monitor), "NaN record at t = 0");
  const auto nan_force = [](const SslideProblem& pr, SslideHistories& h) {
    for (const auto& p : pr.pairings) h.channels.at(sslide_force_channel(pr, p))[250] = Vec3::Constant(kNaN);
  };
  expect_failed_with(rows_after("sslide2kc", "balance", nan_force), "NaN record at t = 0.25");
  expect_failed_with(rows_after("sslide2kc", "mean F_y", nan_force), "NaN record at t = 0.25");
}

TEST(SslideCriteria, ShortChannelFails) {
  const auto shorten = [](const SslideProblem& pr, SslideHistories& h) {
    for (const auto& p : pr.pairings) h.channels.at(sslide_force_channel(pr, p)).resize(100);
  };
  expect_failed_with(rows_after("sslide3p", "mean F_y", shorten), "fewer records");
  expect_failed_with(rows_after("sslide3p", "balance", shorten), "one record per output time");
}

TEST(SslideCriteria, Hdf5HistoriesMatchTheRecording) {
  const auto pr = make_sslide_problem("sslide2kt");
  const auto mem = synthesise(pr);
  const auto path = (std::filesystem::temp_directory_path() / "slideline_sslide_criteria.h5").string();
  {
    std::vector<HistoryChannel> hc = mem.channels();
    Hdf5Writer w(path);
    MeshDescription mesh;
    w.begin(hc, mesh);
    const auto width = 3 * hc.size();
    for (std::size_t r = 0; r < mem.records(); ++r) {
      std::vector<Real> v(width);
      for (std::size_t c = 0; c < hc.size(); ++c)
        for (int d = 0; d < 3; ++d) v[3 * c + d] = mem.value(hc[c].path, r, d);
      w.write_history(mem.time()[r], v);
    }
    w.flush();
  }
  const auto a = sslide_histories(mem, pr);
  const auto b = sslide_histories_from_hdf5(path, pr);
  EXPECT_EQ(a.time, b.time);
  ASSERT_EQ(a.channels.size(), b.channels.size());
  for (const auto& [k, v] : a.channels) EXPECT_EQ(v, b.channels.at(k)) << k;
  std::filesystem::remove(path);
}

TEST(Dyna3dReported, FiguresByPairingAllOrScalar) {
  const auto d = Dyna3dReported(parse_json(
      R"({"p": {"peak": {"solid_on_solid": 2.95, "all": 1.5}, "x": 3e-4, "s": "text", "n": null, "a": [1, 2]}})"));
  EXPECT_EQ(d.figure("p", "peak", "solid_on_solid"), 2.95);
  EXPECT_EQ(d.figure("p", "peak", "shell_on_shell"), 1.5);
  EXPECT_EQ(d.figure("p", "x", "anything"), 3e-4);
  EXPECT_FALSE(d.figure("p", "s").has_value());
  EXPECT_FALSE(d.figure("p", "n").has_value());
  EXPECT_FALSE(d.figure("q", "x").has_value());
  EXPECT_THROW(parse_json(R"({"p": {"x": 1,}})"), InputError);
  EXPECT_THROW(parse_json(R"({"p": 1} extra)"), InputError);
  EXPECT_THROW(parse_json(R"({"p": "open)"), InputError);
  EXPECT_EQ(reported().figure("sslide9pt", "peak_normal_force"), 8.43);
}

TEST(Dyna3dReported, EveryFigureCitesItsSection) {
  const auto root = parse_json(dyna3d_reported_json());
  int figures = 0;
  for (const auto& [problem, entry] : root.object) {
    if (problem.front() == '_') continue;
    const JsonValue* sections = entry.find("sections");
    ASSERT_NE(sections, nullptr) << problem;
    for (const auto& [key, value] : entry.object) {
      const bool figure = value.kind == JsonValue::Kind::number ||
                          (value.kind == JsonValue::Kind::object && key != "sections" &&
                           key.find("_wording") == std::string::npos);
      if (!figure) continue;
      EXPECT_FALSE(Dyna3dReported(root).section(problem, key).empty()) << problem << "." << key;
      ++figures;
    }
  }
  EXPECT_GT(figures, 50);
  // The issue-17 penalty bound applies where the report says "on the order of 1E-03".
  EXPECT_EQ(reported().text("sslide3p", "interpenetration_wording", "solid_on_solid"), "on the order of 1E-03");
  EXPECT_EQ(reported().section("sslide3p", "interpenetration"), "6.3.1, Figure 13 (b)");
}

}  // namespace
}  // namespace slideline::scenarios
