#include "build_support.hpp"

#include <algorithm>
#include <cmath>
#include <variant>


namespace slideline {

/// The one scale factor of LS-DYNA's per-direction damping factors STX..SRZ when they all agree
/// (all blank/0 means 1, as LS-DYNA reads them), else nothing: directions damped differently are
/// not implemented.
void add_fixed_components(SupportGroup& g, const std::vector<Index>& nodes, const std::array<int, 6>& dof,
                          const std::array<int, 3>& axis_of) {
  for (int d = 0; d < 6; ++d) {
    if (dof[static_cast<std::size_t>(d)] == 0) continue;
    Support s;
    s.axis = static_cast<Axis>(axis_of[static_cast<std::size_t>(d % 3)]);
    s.rotational = d >= 3;
    s.nodes = nodes;
    g.supports.push_back(std::move(s));
  }
}

std::optional<Real> common_direction_factor(const std::array<Real, 6>& stf) {
  if (std::all_of(stf.begin(), stf.end(), [](Real s) { return s == 0.0; })) return 1.0;
  if (std::all_of(stf.begin(), stf.end(), [&](Real s) { return s == stf[0]; })) return stf[0];
  return std::nullopt;
}

LoadCurve make_curve(const model::Curve& c) {
  if (c.points.empty())
    throw InputError(describe(c.src) + ": *DEFINE_CURVE " + std::to_string(c.lcid) + " has no points");
  std::vector<std::pair<Real, Real>> pts;
  pts.reserve(c.points.size());
  const Real sfa = c.sfa == 0.0 ? 1.0 : c.sfa;
  const Real sfo = c.sfo == 0.0 ? 1.0 : c.sfo;
  for (const auto& [t, y] : c.points) pts.emplace_back(sfa * t + c.offa, sfo * y + c.offo);
  try {
    return LoadCurve(std::move(pts), "lcid " + std::to_string(c.lcid));
  } catch (const InputError& e) {
    throw InputError(describe(c.src) + ": " + e.what());
  }
}

std::optional<std::array<int, 3>> rigid_constraint_code(int code) {
  switch (code) {
    case 0: return std::array<int, 3>{0, 0, 0};
    case 1: return std::array<int, 3>{1, 0, 0};
    case 2: return std::array<int, 3>{0, 1, 0};
    case 3: return std::array<int, 3>{0, 0, 1};
    case 4: return std::array<int, 3>{1, 1, 0};
    case 5: return std::array<int, 3>{0, 1, 1};
    case 6: return std::array<int, 3>{1, 0, 1};
    case 7: return std::array<int, 3>{1, 1, 1};
    default: return std::nullopt;
  }
}

int shell_nip(const model::SectionShell& sec) { return sec.nip == 0 ? 2 : sec.nip; }

std::map<Id, StiffnessDamping> stiffness_damping(const model::Model& m, const IdTable<model::Part>& parts) {
  std::map<Id, StiffnessDamping> out;
  for (const auto& d : m.damping_stiffness) {
    // Before build_sets (which needs the parts' nodes): the part set straight from the deck.
    std::vector<Id> pids{d.pid};
    if (d.set) {
      const auto ps = std::find_if(m.part_sets.begin(), m.part_sets.end(),
                                   [&](const model::PartSet& p) { return p.sid == d.pid; });
      if (ps == m.part_sets.end())
        throw InputError(describe(d.src) + ": PSID refers to part set " + std::to_string(d.pid) +
                         ", which the deck does not define");
      pids = ps->parts;
    }
    for (Id pid : pids) {
      parts.at(pid, d.src, d.set ? "a part of PSID" : "PID");
      if (!out.emplace(pid, StiffnessDamping{-d.coef}).second)
        throw InputError(describe(d.src) + ": part " + std::to_string(pid) +
                         " has stiffness damping from two *DAMPING_PART_STIFFNESS cards");
    }
  }
  return out;
}

std::optional<HexHourglass::Kind> hex_hourglass_kind(int ihq) {
  if (ihq == 0 || ihq == 1 || ihq == 2 || ihq == 3) return HexHourglass::Kind::viscous;
  if (ihq == 4 || ihq == 5) return HexHourglass::Kind::fb_stiffness;  // 5: our B is already exact
  if (ihq == 6) return HexHourglass::Kind::assumed_strain;
  if (ihq == 10) return HexHourglass::Kind::physical_stiffness;
  return std::nullopt;
}

HexHourglass hex_hourglass(int ihq, Real qm) {
  HexHourglass hg;
  hg.kind = hex_hourglass_kind(ihq).value();  // validate_model refused the other types
  hg.coefficient = qm;
  return hg;
}

/// build_setup (build.cpp), then the simulation constructed from it.
std::unique_ptr<Simulation> build_simulation(const model::Model& model, const BuildOptions& options) {
  auto sim = std::make_unique<Simulation>(build_setup(model, options));
  sim->set_diagnostics(options.diagnostics);
  return sim;
}

}  // namespace slideline
