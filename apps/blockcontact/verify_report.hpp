#pragma once
// The outputs of `blockcontact verify`: the console table, DIR/report.md and the manifest
// (DIR/sslide_plots.json) that scripts/plot_sslide.py reads.
#include <string>
#include <vector>

#include "slideline/scenarios/sslide_criteria.hpp"

namespace blockcontact {

/// What happened to one problem.
struct ProblemOutcome {
  slideline::scenarios::SslideProblem problem;
  bool ran = false;     ///< the run reached its end time
  std::string status;   ///< "ran N cycles", "not run: <reason>", "instability at ..."
  std::string h5;       ///< the run's HDF5 file name (relative to the output directory), if any
  double seconds = 0.0; ///< wall time (build + run + evaluation)
  std::vector<slideline::scenarios::SslideCriterion> rows;
  /// Per pairing: the monitor's relative displacement at each output (tracked re-projection,
  /// sslide.hpp), for the plots; empty when it could not be measured.
  std::vector<std::vector<slideline::Vec3>> relative;
};

/// True when every problem ran and every criterion holds.
bool all_pass(const std::vector<ProblemOutcome>& outcomes);

/// Fixed-width table: problem, pairing, criterion, measured, bound, DYNA3D, result.
std::string format_table(const std::vector<ProblemOutcome>& outcomes);

/// The plot manifest: per problem its HDF5 file, channels, monitors and the expected curves.
void write_plot_manifest(const std::vector<ProblemOutcome>& outcomes, const std::string& path);

/// DIR/report.md: summary with wall times, the table, and the figures when `plots` is set.
void write_report(const std::vector<ProblemOutcome>& outcomes, const std::string& spec_dir, bool plots,
                  const std::string& path);

}  // namespace blockcontact
