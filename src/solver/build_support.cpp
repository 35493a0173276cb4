#include "build_support.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

#include "slideline/core/overloaded.hpp"

namespace slideline {

/// The one scale factor of LS-DYNA's per-direction damping factors STX..SRZ when they all agree
/// (all blank/0 means 1, as LS-DYNA reads them), else nothing: directions damped differently are
/// not implemented.
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

std::array<int, 3> rigid_constraint_code(int code, const model::Source& src, const char* field) {
  switch (code) {
    case 0: return {0, 0, 0};
    case 1: return {1, 0, 0};
    case 2: return {0, 1, 0};
    case 3: return {0, 0, 1};
    case 4: return {1, 1, 0};
    case 5: return {0, 1, 1};
    case 6: return {1, 0, 1};
    case 7: return {1, 1, 1};
    default:
      throw InputError(describe(src) + ": field " + field + " of *MAT_RIGID must be 0 to 7 (got " +
                       std::to_string(code) + ")");
  }
}

void check_positive(Real v, const char* field, const model::Source& src) {
  if (!(v > 0.0))
    throw InputError(describe(src) + ": field " + field + " must be positive (got " +
                     std::to_string(v) + ")");
}

void check_material_constants(const model::Material& material) {
  std::visit(Overloaded{[](const model::MatElastic& x) {
                          check_positive(x.ro, "RO", x.src);
                          check_positive(x.e, "E", x.src);
                        },
                        [](const model::MatMooneyRivlin& x) { check_positive(x.ro, "RO", x.src); },
                        [](const model::MatRigid& x) {
                          check_positive(x.ro, "RO", x.src);
                          check_positive(x.e, "E", x.src);  // sets the part's time step, as in LS-DYNA
                        }},
             material);
}

std::map<Id, StiffnessDamping> stiffness_damping(const model::Model& m, const IdTable<model::Part>& parts) {
  std::map<Id, StiffnessDamping> out;
  for (const auto& d : m.damping_stiffness) {
    if (d.coef > 0.0)
      throw NotImplementedError(
          describe(d.src) + ": *DAMPING_PART_STIFFNESS COEF = " + std::to_string(d.coef) +
          " > 0 selects LS-DYNA's approximate fraction of critical damping at high frequencies, "
          "whose formulation is not published; give COEF = -beta (beta in time units, the "
          "classical Rayleigh coefficient: fraction of critical damping beta * omega / 2)");
    if (!std::isfinite(d.coef))
      throw InputError(describe(d.src) + ": field COEF of *DAMPING_PART_STIFFNESS must be finite");
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

HexHourglass hex_hourglass(int ihq, Real qm, const model::Part& part) {
  HexHourglass hg;
  if (ihq == 0 || ihq == 1 || ihq == 2 || ihq == 3) {
    hg.kind = HexHourglass::Kind::viscous;
  } else if (ihq == 10) {
    hg.kind = HexHourglass::Kind::physical_stiffness;
  } else {
    throw NotImplementedError(describe(part.src) + ": hourglass type IHQ=" + std::to_string(ihq) +
                              " of part " + std::to_string(part.pid) +
                              " is not implemented (use 1-3 viscous or 10 physical stiffness)");
  }
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
