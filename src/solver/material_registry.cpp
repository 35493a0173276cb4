#include "slideline/solver/material_registry.hpp"

#include <variant>

#include "build_support.hpp"
#include "slideline/core/error.hpp"
#include "slideline/core/overloaded.hpp"

namespace slideline {
namespace {

/// The points of curve `lcid` (scaled and offset as *DEFINE_CURVE says), for field `field` of `mat`.
std::vector<std::pair<Real, Real>> curve_points(std::span<const model::Curve> curves, Id lcid,
                                                const model::Source& src, const char* field) {
  for (const auto& c : curves)
    if (c.lcid == lcid) return make_curve(c).points();
  throw InputError(describe(src) + ": field " + field + " of *MAT_PIECEWISE_LINEAR_PLASTICITY refers to curve " +
                   std::to_string(lcid) + ", which is not defined");
}

/// The yield curve: LCSS, else the EPS/ES table (up to its last non-zero ES), else SIGY and the
/// hardening modulus E ETAN / (E - ETAN).
PiecewisePlasticity piecewise_law(const model::MatPiecewiseLinearPlasticity& m, std::span<const model::Curve> curves) {
  PiecewisePlasticityConstants k{m.ro, m.e, m.pr, {}, m.c, m.p, {}, m.vp == 1.0};
  if (m.lcss != 0) {
    k.hardening = curve_points(curves, m.lcss, m.src, "LCSS");
  } else if (m.es[0] != 0.0) {
    std::size_t n = 8;
    while (n > 1 && m.es[n - 1] == 0.0) --n;
    for (std::size_t i = 0; i < n; ++i) k.hardening.emplace_back(m.eps[i], m.es[i]);
  } else {
    k.hardening = {{0.0, m.sigy}};
    if (m.etan > 0.0) k.hardening.emplace_back(1.0, m.sigy + m.e * m.etan / (m.e - m.etan));
  }
  if (m.lcsr != 0) k.rate_curve = curve_points(curves, m.lcsr, m.src, "LCSR");
  return PiecewisePlasticity(std::move(k));
}

}  // namespace

EquationOfState equation_of_state(const model::Eos& eos, Real rho0) {
  return std::visit(
      Overloaded{
          [](const model::EosLinearPolynomial& e) { return EquationOfState::linear_polynomial(e.c, e.e0); },
          [&](const model::EosGruneisen& e) {
            return EquationOfState::gruneisen(rho0, e.c, e.s1, e.s2, e.s3, e.gamma0, e.a, e.e0);
          },
          [](const model::EosTabulated& e) { return EquationOfState::tabulated(e.ev, e.c, e.t, e.gama, e.e0); },
      },
      eos);
}

MaterialLaws material_laws(const model::Material& material, std::span<const model::Curve> curves,
                           const model::Eos* eos) {
  return std::visit(
      Overloaded{
          [](const model::MatElastic& m) {
            return MaterialLaws{ElasticSolid(m.ro, m.e, m.pr), ElasticShell(m.ro, m.e, m.pr), false,
                                "*MAT_ELASTIC"};
          },
          [](const model::MatMooneyRivlin& m) {
            return MaterialLaws{MooneyRivlin(m.ro, m.a, m.b, m.pr), std::nullopt, false,
                                "*MAT_MOONEY-RIVLIN_RUBBER"};
          },
          [](const model::MatPlasticKinematic& m) {
            const J2PlasticityConstants k{m.ro, m.e, m.pr, m.sigy, m.etan, m.beta, m.src_c, m.srp};
            return MaterialLaws{J2Plasticity(k), ShellPlasticity<J2Plasticity>(J2Plasticity(k)), false,
                                "*MAT_PLASTIC_KINEMATIC", m.fs, "FS"};
          },
          [&](const model::MatPiecewiseLinearPlasticity& m) {
            PiecewisePlasticity law = piecewise_law(m, curves);
            ShellPlasticity<PiecewisePlasticity> shell(law);
            return MaterialLaws{std::move(law), std::move(shell), false, "*MAT_PIECEWISE_LINEAR_PLASTICITY", m.fail,
                                "FAIL", m.tdel};
          },
          [&](const model::MatNull& m) {
            MaterialLaws laws{std::nullopt, NullShell(m.ro, m.ym, m.pr), false, "*MAT_NULL"};
            if (eos) laws.solid = NullSolid(m.ro, m.pc, m.mu, equation_of_state(*eos, m.ro));
            laws.max_relative_volume = m.terod;
            laws.min_relative_volume = m.cerod;
            return laws;
          },
          [](const model::MatRigid&) {
            return MaterialLaws{std::nullopt, std::nullopt, true, "*MAT_RIGID"};
          },
      },
      material);
}

}  // namespace slideline
