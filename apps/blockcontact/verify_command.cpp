// blockcontact verify: runs the sslide problems in-process, checks every criterion per pairing,
// prints the table, writes DIR/report.md and the plots (docs/verification.md).
#include <fmt/core.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "slideline/core/error.hpp"
#include "slideline/core/parallel.hpp"
#include "slideline/io/csv_writer.hpp"
#include "slideline/io/hdf5_writer.hpp"
#include "slideline/io/keyword_writer.hpp"
#include "slideline/scenarios/sslide_criteria.hpp"
#include "slideline/solver/build.hpp"
#include "verify_report.hpp"

namespace blockcontact {
namespace {

namespace fs = std::filesystem;
namespace sc = slideline::scenarios;

/// Issue 11: all 19 problems in under a minute on the 2-core development machine.
constexpr double kSuiteBudgetSeconds = 60.0;

struct VerifyOptions {
  std::vector<std::string> names;
  bool all = false;
  std::string out_dir = "sslide_verify";
  std::string spec_dir;
  std::string histories_dir;  ///< evaluate DIR/NAME.h5 instead of running (--histories)
  std::string plot_script;
  std::string python;
  bool plots = true;
  bool drop_contacts = false;
  int threads = 0;
};

/// Where to look for repository files: the working directory and the executable's directory.
std::vector<fs::path> search_roots() {
  std::vector<fs::path> roots{fs::current_path()};
  std::error_code ec;
  const auto exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) roots.push_back(exe.parent_path());
  return roots;
}

/// `relative` under the first root or root ancestor that has it; empty if none.
std::string find_upwards(const std::string& relative) {
  std::error_code ec;
  for (auto dir : search_roots()) {
    for (;;) {
      if (fs::exists(dir / relative, ec)) return (dir / relative).string();
      if (!dir.has_parent_path() || dir.parent_path() == dir) break;
      dir = dir.parent_path();
    }
  }
  return {};
}

ProblemOutcome run_problem(const std::string& name, const VerifyOptions& o, const sc::Dyna3dReported& reported) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  ProblemOutcome out;
  out.problem = sc::make_sslide_problem(name);
  if (!o.histories_dir.empty()) {
    // The histories of an earlier run (or a perturbed copy: tests/cli/sslide.cmake), evaluated as is.
    const auto h5 = (fs::path(o.histories_dir) / (name + ".h5")).string();
    const auto histories = sc::sslide_histories_from_hdf5(h5, out.problem);
    out.ran = true;
    out.status = "evaluated " + h5;
    out.h5 = fs::absolute(h5).string();
    out.rows = sc::evaluate_sslide_criteria(out.problem, histories, reported);
    for (const auto& p : out.problem.pairings) out.relative.push_back(sc::sslide_relative_displacement(p, histories));
    out.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return out;
  }
  if (o.drop_contacts) out.problem.model.contacts.clear();
  const auto base = fs::path(o.out_dir) / name;
  slideline::write_keyword_file(out.problem.model, base.string() + ".k");
  StderrDiagnostics diagnostics;  // outlives sim
  slideline::BuildOptions build;
  build.diagnostics = &diagnostics;
  std::unique_ptr<slideline::Simulation> sim;
  try {
    sim = slideline::build_simulation(out.problem.model, build);
  } catch (const slideline::NotImplementedError& e) {
    out.status = std::string("not run: ") + e.what();
  } catch (const slideline::InputError& e) {
    out.status = std::string("not run (bad model): ") + e.what();
  }
  if (sim) {
    slideline::History history;
    slideline::Hdf5Writer h5(base.string() + ".h5");
    slideline::CsvWriter csv(base.string() + ".csv");
    try {
      sim->run({&history, &h5, &csv});
      out.ran = true;
      out.status = fmt::format("ran {} cycles", sim->cycle());
    } catch (const slideline::InstabilityError& e) {
      out.status = fmt::format("instability at t = {:g}: {}", e.time(), e.what());
    }
    out.h5 = base.filename().string() + ".h5";
    const auto histories = sc::sslide_histories(history, out.problem);
    out.rows = sc::evaluate_sslide_criteria(out.problem, histories, reported);
    for (const auto& p : out.problem.pairings) out.relative.push_back(sc::sslide_relative_displacement(p, histories));
  }
  out.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return out;
}

int run_verify(const VerifyOptions& o) {
  const auto names = o.all ? sc::sslide_problem_names() : o.names;
  if (names.empty()) {
    fmt::print(stderr, "error: name problems (blockcontact generate --list) or pass --all\n");
    return kBadInput;
  }
  for (const auto& n : names) (void)sc::make_sslide_problem(n);  // unknown names fail before any run
  // DYNA3D's figures are compiled in; --spec reads another copy of the file instead.
  const auto& spec = o.spec_dir;
  if (!spec.empty() && !fs::exists(fs::path(spec) / "dyna3d_reported.json")) {
    fmt::print(stderr, "error: --spec {}: no dyna3d_reported.json there\n", spec);
    return kBadInput;
  }
  const auto reported = spec.empty() ? sc::Dyna3dReported::builtin()
                                     : sc::Dyna3dReported::load((fs::path(spec) / "dyna3d_reported.json").string());
  if (o.threads > 0) slideline::set_threads(o.threads);
  fs::create_directories(o.out_dir);

  std::vector<ProblemOutcome> outcomes;
  double total = 0.0;
  for (const auto& n : names) {
    outcomes.push_back(run_problem(n, o, reported));
    const auto& r = outcomes.back();
    total += r.seconds;
    int failed = 0;
    for (const auto& row : r.rows) failed += row.pass ? 0 : 1;
    fmt::print("{:<15} {:7.2f} s  {}  {}\n", n, r.seconds, r.ran && failed == 0 ? "PASS" : "FAIL",
               r.ran ? fmt::format("{} ({} of {} criteria failed)", r.status, failed, r.rows.size()) : r.status);
    std::fflush(stdout);
  }
  fmt::print("\n{}", format_table(outcomes));
  const bool ok = all_pass(outcomes);
  fmt::print("\n{} problem(s) in {:.2f} s: {}\n", outcomes.size(), total, ok ? "every criterion holds" : "FAILED");
  if (o.all && total > kSuiteBudgetSeconds)
    fmt::print("warning: the suite took {:.1f} s, over its {:g} s budget\n", total, kSuiteBudgetSeconds);

  write_plot_manifest(outcomes, (fs::path(o.out_dir) / "sslide_plots.json").string());
  bool plotted = false;
  if (o.plots) {
    const auto script = !o.plot_script.empty() ? o.plot_script : find_upwards("scripts/plot_sslide.py");
    if (script.empty()) {
      fmt::print(stderr, "warning: scripts/plot_sslide.py not found; no plots (pass --plot-script)\n");
    } else {
      // Debian's interpreter carries python3-matplotlib and python3-h5py; a python3 earlier on PATH
      // (pyenv, venv) usually does not.
      const std::string python = !o.python.empty() ? o.python : fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
      const auto cmd = fmt::format("'{}' '{}' '{}'", python, script, o.out_dir);
      std::fflush(stdout);
      plotted = std::system(cmd.c_str()) == 0;
      if (!plotted) fmt::print(stderr, "warning: '{}' failed; report.md has no plots\n", cmd);
    }
  }
  const auto report = (fs::path(o.out_dir) / "report.md").string();
  write_report(outcomes, spec, plotted, report);
  fmt::print("report: {}\n", report);
  return ok ? kOk : kFailure;
}

}  // namespace

void register_verify(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("verify", "Run the sslide problems and check every verification criterion");
  auto o = std::make_shared<VerifyOptions>();
  cmd->add_option("names", o->names, "Problem names (sslide1k ... sslide12l_vec)");
  cmd->add_flag("--all", o->all, "All 19 problems");
  cmd->add_option("-o,--output", o->out_dir, "Output directory (created if missing)")->capture_default_str();
  cmd->add_option("--spec", o->spec_dir,
                  "Directory of a dyna3d_reported.json to use instead of the copy compiled in");
  cmd->add_option("--histories", o->histories_dir,
                  "Evaluate DIR/NAME.h5 (histories of an earlier verify or run) instead of running the problems")
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--plot-script", o->plot_script, "Plot script (default: scripts/plot_sslide.py found upwards)");
  cmd->add_option("--python", o->python, "Python interpreter for the plots (default: /usr/bin/python3)");
  cmd->add_flag("!--no-plots", o->plots, "Do not call the plot script");
  cmd->add_flag("--drop-contacts", o->drop_contacts,
                "Run the models without their contacts (upper bodies fall freely): a smoke test of the "
                "run/report/plot pipeline; the interface criteria then fail");
  cmd->add_option("--threads", o->threads, "OpenMP threads (0 = OpenMP default)")->check(CLI::NonNegativeNumber);
  cmd->callback([o, &exit_code] { exit_code = run_verify(*o); });
}

}  // namespace blockcontact
