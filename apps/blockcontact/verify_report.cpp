#include "verify_report.hpp"

#include <fmt/core.h>

#include <cmath>
#include <fstream>

#include "slideline/core/error.hpp"

namespace blockcontact {

namespace sc = slideline::scenarios;

namespace {

std::string number(double v) { return std::isnan(v) ? "-" : fmt::format("{:.4g}", v); }

std::string dyna(const sc::SslideCriterion& r) { return r.dyna3d ? fmt::format("{:.4g}", *r.dyna3d) : "-"; }

/// A Markdown table cell: '|' would end the cell.
std::string cell(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '|') o += '\\';
    o += c;
  }
  return o;
}

std::string json_string(const std::string& s) {
  std::string o = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') o += '\\';
    if (c == '\n') {
      o += "\\n";
      continue;
    }
    o += c;
  }
  return o + "\"";
}

std::string json_numbers(const std::vector<double>& v) {
  std::string o = "[";
  for (std::size_t k = 0; k < v.size(); ++k) {
    if (k) o += ',';
    o += fmt::format("{:.9g}", v[k]);
  }
  return o + "]";
}

void write_file(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  if (!out) throw slideline::Error("cannot write " + path);
}

}  // namespace

bool all_pass(const std::vector<ProblemOutcome>& outcomes) {
  for (const auto& o : outcomes) {
    if (!o.ran || o.rows.empty()) return false;
    for (const auto& r : o.rows)
      if (!r.pass) return false;
  }
  return true;
}

std::string format_table(const std::vector<ProblemOutcome>& outcomes) {
  std::string t = fmt::format("{:<14} {:<15} {:<30} {:>11} {:<30} {:>9}  {}\n", "problem", "pairing", "criterion",
                              "measured", "bound", "DYNA3D", "result");
  for (const auto& o : outcomes) {
    if (!o.ran && o.rows.empty()) {
      t += fmt::format("{:<14} {:<15} {}\n", o.problem.name, "-", o.status);
      continue;
    }
    for (const auto& r : o.rows) {
      t += fmt::format("{:<14} {:<15} {:<30} {:>11} {:<30} {:>9}  {}{}\n", r.problem, r.pairing, r.criterion,
                       number(r.measured), r.bound, dyna(r), r.pass ? "pass" : "FAIL",
                       r.note.empty() ? "" : "  (" + r.note + ")");
    }
    if (!o.ran) t += fmt::format("{:<14} {:<15} {}\n", o.problem.name, "-", o.status);
  }
  return t;
}

void write_plot_manifest(const std::vector<ProblemOutcome>& outcomes, const std::string& path) {
  std::string j = "{\"problems\": [\n";
  bool first = true;
  for (const auto& o : outcomes) {
    if (o.h5.empty()) continue;
    const auto& pr = o.problem;
    j += first ? "" : ",\n";
    first = false;
    j += fmt::format("{{\"name\": {}, \"description\": {}, \"h5\": {}, \"pairings\": [", json_string(pr.name),
                     json_string(pr.description), json_string(o.h5));
    for (std::size_t k = 0; k < pr.pairings.size(); ++k) {
      const auto& p = pr.pairings[k];
      std::vector<double> w(p.monitor.weights.begin(), p.monitor.weights.end());
      std::string masters;
      for (auto n : p.monitor.master_nodes) {
        if (!masters.empty()) masters += ',';
        masters += std::to_string(n);
      }
      // The relative displacement as the criteria measure it (re-projected at every output).
      std::vector<double> rx, ry;
      if (k < o.relative.size())
        for (const auto& r : o.relative[k]) rx.push_back(r.x()), ry.push_back(r.y());
      j += fmt::format(
          "{}\n  {{\"name\": {}, \"force\": {}, \"bottom\": {}, \"right\": {}, \"slave_node\": {}, "
          "\"master_nodes\": [{}], \"weights\": {}, \"relative_x\": {}, \"relative_y\": {}}}",
          k ? "," : "", json_string(p.name), json_string(fmt::format("/{}", sc::sslide_force_channel(pr, p))),
          json_string(fmt::format("/{}", sc::sslide_support_channel(p.bottom_support))),
          json_string(fmt::format("/{}", sc::sslide_support_channel(p.right_support))), p.monitor.slave_node, masters,
          json_numbers(w), json_numbers(rx), json_numbers(ry));
    }
    // The closed-form curves (identical for every pairing of a problem: same loads).
    std::vector<double> t, fx, fy, rx, ry;
    for (int k = 0; k <= 1000; ++k) {
      const double tt = 0.5 * k / 1000.0;
      const auto e = sc::sslide_expected(pr, pr.pairings.front(), tt);
      t.push_back(tt);
      fx.push_back(e.force.x());
      fy.push_back(e.force.y());
      rx.push_back(e.reaction.x());
      ry.push_back(e.reaction.y());
    }
    j += fmt::format("],\n \"expected\": {{\"time\": {}, \"F_x\": {}, \"F_y\": {}, \"R_x\": {}, \"R_y\": {}}}}}",
                     json_numbers(t), json_numbers(fx), json_numbers(fy), json_numbers(rx), json_numbers(ry));
  }
  j += "\n]}\n";
  write_file(path, j);
}

void write_report(const std::vector<ProblemOutcome>& outcomes, const std::string& spec_dir, bool plots,
                  const std::string& path) {
  std::string md = "# sslide verification report\n\n";
  md += "The 19 problems of the DYNA3D basic-contact verification report (McMichael 2006), run by "
        "`blockcontact verify`; criteria as in docs/verification.md. DYNA3D's figures from " +
        (spec_dir.empty() ? std::string("the copy compiled in (src/scenarios/dyna3d_reported.json)")
                          : "`" + spec_dir + "/dyna3d_reported.json`") +
        ".\n\n";
  md += all_pass(outcomes) ? "**Every criterion holds.**\n\n" : "**Some criteria fail or problems did not run.**\n\n";
  md += "| problem | status | wall time (s) | criteria failed |\n|---|---|---:|---:|\n";
  double total = 0.0;
  for (const auto& o : outcomes) {
    int failed = 0;
    for (const auto& r : o.rows) failed += r.pass ? 0 : 1;
    total += o.seconds;
    md += fmt::format("| {} | {} | {:.2f} | {} of {} |\n", o.problem.name, cell(o.status), o.seconds, failed,
                      o.rows.size());
  }
  md += fmt::format("| total | | {:.2f} | |\n\n(budget for the 19 problems: 60 s on the 2-core development machine)\n\n",
                    total);
  md += "## Criteria\n\n| problem | pairing | criterion | measured | bound | DYNA3D | result | note |\n"
        "|---|---|---|---:|---|---:|---|---|\n";
  for (const auto& o : outcomes)
    for (const auto& r : o.rows)
      md += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} |\n", r.problem, r.pairing, cell(r.criterion),
                        number(r.measured), cell(r.bound), dyna(r), r.pass ? "pass" : "**FAIL**", cell(r.note));
  if (plots) {
    md += "\n## Figures\n\nF = force on the upper body, R = force of the lower body on its supports, "
          "relative displacement = slave node - master surface point under it; the closed-form answer "
          "as a broad grey line.\n";
    for (const auto& o : outcomes) {
      if (o.h5.empty()) continue;
      md += fmt::format("\n### {}\n\n{}\n\n![{} forces]({}_forces.png)\n![{} relative displacement]({}_relative.png)\n",
                        o.problem.name, o.problem.description, o.problem.name, o.problem.name, o.problem.name,
                        o.problem.name);
    }
  }
  write_file(path, md);
}

}  // namespace blockcontact
