// blockcontact run <deck>: read, build and run a deck, writing DIR/<stem>.h5 (+ .xdmf, + .csv).
// SIGINT/SIGTERM stop the run at the end of the cycle with the files closed (exit code 5); the
// files are also flushed every few seconds of wall time, so that a killed run leaves them readable.
#include <fmt/core.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "commands.hpp"
#include "interrupt_guard.hpp"
#include "slideline/core/error.hpp"
#include "slideline/core/parallel.hpp"
#include "slideline/element/element_erosion.hpp"
#include "slideline/io/csv_writer.hpp"
#include "slideline/io/hdf5_writer.hpp"
#include "slideline/io/keyword_reader.hpp"
#include "slideline/solver/build.hpp"
#include "slideline/solver/validate_model.hpp"

namespace blockcontact {
namespace {

struct RunOptions {
  std::string deck;
  std::string out_dir = ".";
  bool csv = false;
  int threads = 0;
  double end_time = 0.0;
  bool ignore_unsupported = false;
  /// Stop when the energy balance error passes this fraction (0: never); negative: the deck's
  /// *CONTROL_TERMINATION ENDENG, else 5%.
  double energy_limit = -1.0;
  double flush_every = 5.0;  ///< wall-clock seconds between flushes of the output files (0: none)
  bool contact_step_with_elements = false;  ///< the default asked for explicitly (accepted, changes nothing)
  bool contact_springs_alone = false;       ///< SimulationControls::contact_step_with_elements off
};

using Clock = std::chrono::steady_clock;

/// The live progress line: silent for the first second, then rewritten in place (\r) on a
/// terminal, or printed as a new line every few seconds when stdout is a file or pipe.
class Progress {
 public:
  explicit Progress(double end_time) : end_time_(end_time), tty_(isatty(fileno(stdout)) != 0) {}

  void update(const slideline::Simulation& sim) {
    const auto now = Clock::now();
    const double elapsed = seconds(start_, now);
    if (elapsed < 1.0 || seconds(last_, now) < (tty_ ? 0.2 : 5.0)) return;
    last_ = now;
    const double t = sim.time();
    const double eta = t > 0.0 ? elapsed * (end_time_ - t) / t : 0.0;
    // The step the solver takes next (sim.dt() is the last step, which is often a short one that
    // landed on an output time).
    const double dt = sim.plan_step().dt_next;
    const std::string line =
        fmt::format("cycle {:>9}  t {:.5e} / {:.4g}  dt {:.3e}  energy error {:+.2e}  ETA {:.0f} s", sim.cycle(), t,
                    end_time_, dt, sim.energy().relative_balance_error(), eta);
    if (tty_) {
      fmt::print("\r{}", line);
      dirty_ = true;
    } else {
      fmt::print("{}\n", line);
    }
    std::fflush(stdout);
  }

  /// Ends a \r line so that the next output starts on a fresh line.
  void finish() {
    if (dirty_) fmt::print("\n");
    dirty_ = false;
  }

  double elapsed() const { return seconds(start_, Clock::now()); }

 private:
  static double seconds(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
  }
  double end_time_;
  bool tty_;
  bool dirty_ = false;
  Clock::time_point start_ = Clock::now();
  Clock::time_point last_ = Clock::time_point{};
};

/// Flushes the sinks (HDF5: buffered records, H5Fflush, the XDMF so far; CSV) every `every`
/// seconds of wall time, so that a run killed without warning (SIGKILL, power loss) leaves files
/// that open, holding everything up to the last flush.
class PeriodicFlush {
 public:
  PeriodicFlush(const std::vector<slideline::OutputSink*>& sinks, double every) : sinks_(sinks), every_(every) {}

  void update() {
    if (!(every_ > 0.0)) return;
    const auto now = Clock::now();
    if (std::chrono::duration<double>(now - last_).count() < every_) return;
    for (auto* s : sinks_) s->flush();
    last_ = now;
  }

 private:
  const std::vector<slideline::OutputSink*>& sinks_;
  double every_;
  Clock::time_point last_ = Clock::now();
};

/// Prints each hourglass warning of the run once, as it arises (stderr).
class HourglassWarnings {
 public:
  void print_new(const slideline::Simulation& sim, Progress& progress) {
    const auto& w = sim.hourglass_warnings();
    if (printed_ == w.size()) return;
    progress.finish();
    for (; printed_ < w.size(); ++printed_) fmt::print(stderr, "warning: {}\n", slideline::to_string(w[printed_]));
    std::fflush(stderr);
  }

 private:
  std::size_t printed_ = 0;
};

/// Cycles between reads of the clock (progress line, periodic flush); the signal flag is checked
/// every cycle.
constexpr long kClockEvery = 16;

/// Mass scaling (DT2MS): the total added mass and, at the start (`per_part`), each part's.
void print_added_mass(const slideline::Simulation& sim, const char* prefix, bool per_part = false) {
  const auto& parts = sim.added_mass();
  if (parts.empty()) return;
  double mass = 0.0, added = 0.0;
  for (const auto& p : parts) {
    mass += p.mass;
    added += p.added;
    if (per_part) fmt::print("{}{}\n", prefix, slideline::describe(p));
  }
  fmt::print("{}DT2MS = {:g}{}: added mass {:.6g} ({:.3g}% of {:.6g}); step TSSFAC x |DT2MS| = {:.6g}\n", prefix,
             sim.controls().dt2ms, sim.controls().mass_scaling_every_cycle ? " (MS1ST = 0, every cycle)" : " (MS1ST = 1, once)",
             added, mass > 0.0 ? 100.0 * added / mass : 0.0, mass, sim.controls().dt_scale * std::abs(sim.controls().dt2ms));
}

/// Element erosion (element/element_erosion.hpp): per eroding part, the elements deleted and when
/// (the first 20 by time), and the energy they held.
void print_erosion(const slideline::Simulation& sim) {
  bool any = false;
  for (const auto& b : sim.blocks()) {
    const slideline::ElementErosion* er = std::as_const(*b).erosion();
    if (!er) continue;
    any = true;
    std::vector<std::pair<double, slideline::Id>> deleted;
    const auto times = er->deletion_times();
    for (std::size_t e = 0; e < times.size(); ++e)
      if (times[e] >= 0.0) deleted.emplace_back(times[e], b->element_id(static_cast<slideline::Index>(e)));
    std::sort(deleted.begin(), deleted.end());
    fmt::print("erosion: part {}: {} of {} elements deleted (failure strain {:g})\n", b->part_id(), deleted.size(),
               times.size(), er->failure_strain());
    for (std::size_t k = 0; k < std::min<std::size_t>(deleted.size(), 20); ++k)
      fmt::print("  element {} deleted at t = {:.6g}\n", deleted[k].second, deleted[k].first);
    if (deleted.size() > 20) fmt::print("  ... and {} more (the state output's cell field \"deleted\")\n", deleted.size() - 20);
  }
  if (any)
    fmt::print("erosion: eroded energy {:.6g} (internal {:.6g}, hourglass {:.6g})\n", sim.energy().eroded(),
               sim.energy().eroded_internal, sim.energy().eroded_hourglass);
}

/// The end of a completed run: the energy warning if one was raised, the cost and the balance.
void print_run_end(const slideline::Simulation& sim, double wall) {
  if (const auto& w = sim.energy_warning())
    fmt::print(stderr, "warning: the energy balance error passed {:.1f}% at t = {:g} (cycle {}); it ended at {:.2f}% "
               "(the run stops at {:.1f}%: --energy-limit or *CONTROL_TERMINATION ENDENG)\n",
               100.0 * w->relative_error, w->time, w->cycle, 100.0 * sim.energy_error_fraction(),
               100.0 * sim.controls().energy_error_limit);
  if (const auto& w = sim.contact_energy_warning())
    fmt::print(stderr, "warning: the contact forces did {:.1f}% of the largest energy in play more work on the bodies "
               "than they took from them by t = {:g} (cycle {}, the first check): contact created energy (the energy balance cannot "
               "show it; a contact spring too stiff for the step, chatter, or initial penetrations pushed out); "
               "the contact energy ended at {:.4g}\n",
               100.0 * w->relative_error, w->time, w->cycle, sim.energy().contact);
  const double element_cycles = double(sim.element_count()) * double(std::max(1L, sim.cycle()));
  fmt::print("done: {} cycles to t = {:g} in {:.2f} s ({:.1f} ns per element-cycle, contact {:.0f}% of the time)\n",
             sim.cycle(), sim.time(), wall, element_cycles > 0 ? 1e9 * wall / element_cycles : 0.0,
             wall > 0 ? 100.0 * sim.contact_seconds() / wall : 0.0);
  fmt::print("energy balance error {:+.3e} (relative)\n", sim.energy().relative_balance_error());
  print_added_mass(sim, "mass scaling: ");
  print_erosion(sim);
}

int run_deck(const RunOptions& o) {
  std::size_t warning_count = 0;
  const auto model = read_deck(o.deck, o.ignore_unsupported, warning_count);
  print_dropped(model);
  const auto problems = slideline::check_references(model);
  if (!problems.empty()) {
    for (const auto& p : problems) fmt::print(stderr, "error: {}\n", slideline::to_string(p));
    fmt::print(stderr, "{}: {} problem(s); nothing was run\n", o.deck, problems.size());
    return kBadInput;
  }

  StderrDiagnostics diagnostics;  // outlives sim
  slideline::BuildOptions build;
  build.end_time = o.end_time;
  build.diagnostics = &diagnostics;
  slideline::SimulationSetup setup = slideline::build_setup(model, build);
  if (o.energy_limit >= 0.0) {  // the flag overrides the deck's ENDENG
    setup.controls.energy_error_limit = o.energy_limit;
    if (o.energy_limit > 0.0) setup.controls.energy_error_warning = std::min(0.01, 0.2 * o.energy_limit);
  }
  if (o.contact_springs_alone) setup.controls.contact_step_with_elements = false;
  const auto sim = std::make_unique<slideline::Simulation>(std::move(setup));
  sim->set_diagnostics(&diagnostics);
  if (o.threads > 0) slideline::set_threads(o.threads);
  sim->initialize();  // before any output file exists: a refused model leaves no stub .h5

  std::filesystem::create_directories(o.out_dir);
  const auto stem = std::filesystem::path(o.deck).stem().string();
  const auto h5_path = (std::filesystem::path(o.out_dir) / (stem + ".h5")).string();
  // From here on SIGINT/SIGTERM stop the run at the end of a cycle (checked in the callback below).
  const InterruptGuard interrupt_guard;
  slideline::Hdf5Writer h5(h5_path);
  std::unique_ptr<slideline::CsvWriter> csv;
  std::vector<slideline::OutputSink*> sinks{&h5};
  if (o.csv) {
    csv = std::make_unique<slideline::CsvWriter>((std::filesystem::path(o.out_dir) / (stem + ".csv")).string());
    sinks.push_back(csv.get());
  }

  fmt::print("{}: {} nodes, {} elements, {} contact interface(s), end time {:g}, {} thread(s)\n", o.deck,
             model.nodes.size(), sim->element_count(), sim->contacts().size(), sim->controls().end_time,
             slideline::max_threads());
  print_added_mass(*sim, "mass scaling: ", true);
  std::fflush(stdout);
  Progress progress(sim->controls().end_time);
  PeriodicFlush periodic_flush(sinks, o.flush_every);
  HourglassWarnings hourglass_warnings;
  try {
    sim->run(
        sinks,
        [&](const slideline::Simulation& s) {
          // Every cycle: a pending SIGINT/SIGTERM unwinds through run(), which flushes the sinks.
          InterruptGuard::throw_if_pending();
          hourglass_warnings.print_new(s, progress);
          if (s.cycle() % kClockEvery != 0) return;
          progress.update(s);
          periodic_flush.update();
        },
        1);
  } catch (const RunInterrupted& e) {
    hourglass_warnings.print_new(*sim, progress);
    progress.finish();
    fmt::print(stderr, "{} at t = {:g} (cycle {}): stopped at the end of the cycle\n", e.what(), sim->time(),
               sim->cycle());
    fmt::print(stderr, "the output recorded so far was kept in {} and {}{}\n", h5_path, h5.xdmf_path(),
               o.csv ? fmt::format(" and {}", (std::filesystem::path(o.out_dir) / (stem + ".csv")).string()) : "");
    return kInterrupted;
  } catch (const slideline::InstabilityError& e) {
    hourglass_warnings.print_new(*sim, progress);
    progress.finish();
    fmt::print(stderr, "instability at t = {:g} (cycle {}): {}\n", e.time(), e.cycle(), e.what());
    fmt::print(stderr, "output up to t = {:g} was kept in {}\n", e.time(), h5_path);
    return kInstability;
  }
  hourglass_warnings.print_new(*sim, progress);
  progress.finish();
  print_run_end(*sim, progress.elapsed());
  fmt::print("output: {} and {}{}\n", h5_path, h5.xdmf_path(),
             o.csv ? fmt::format(" and {}", (std::filesystem::path(o.out_dir) / (stem + ".csv")).string()) : "");
  return kOk;
}

}  // namespace

void register_run(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("run", "Run a keyword deck and write its histories and states");
  auto o = std::make_shared<RunOptions>();
  cmd->add_option("deck", o->deck, "Keyword deck (.k)")->required()->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", o->out_dir, "Output directory (created if missing)")->capture_default_str();
  cmd->add_flag("--csv", o->csv, "Also write the histories as <stem>.csv");
  cmd->add_option("--threads", o->threads, "OpenMP threads (0 = OpenMP default)")->check(CLI::NonNegativeNumber);
  cmd->add_option("--end-time", o->end_time, "Override *CONTROL_TERMINATION ENDTIM (> 0)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--ignore-unsupported", o->ignore_unsupported,
                "Run even though the deck holds unsupported physics cards: drop them and list them");
  cmd->add_option("--energy-limit", o->energy_limit,
                  "Stop (exit 4) when the energy balance error passes this fraction of the largest energy "
                  "(0: never; default: the deck's *CONTROL_TERMINATION ENDENG percent, else 0.05); a warning "
                  "at a fifth of it, 1% at most")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--flush-every", o->flush_every,
                  "Seconds of wall time between flushes of the output files (0: only at the end)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  auto* combined = cmd->add_flag("--contact-step-with-elements", o->contact_step_with_elements,
                                 "The default: a contact spring's step vote counts the elements on its nodes, "
                                 "1/dt^2 = 1/dt_e^2 + 1/dt_c^2 (stable where a node's spring is as stiff as its "
                                 "elements)");
  cmd->add_flag("--contact-step-springs-alone", o->contact_springs_alone,
                "Each contact spring votes its own step alone (LS-DYNA's rule: larger steps, unstable where a "
                "node's spring is as stiff as its elements)")
      ->excludes(combined);
  cmd->callback([o, &exit_code] { exit_code = run_deck(*o); });
}

}  // namespace blockcontact
