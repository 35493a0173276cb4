#pragma once
/// The material cards of the model description (model.hpp): each *MAT_... card the reader takes,
/// with LS-DYNA's field names, defaults and semantics, and *MAT_ADD_EROSION, which adds failure
/// criteria to one of them.
#include <array>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "slideline/core/types.hpp"
#include "slideline/model/source.hpp"

namespace slideline::model {

/// *MAT_ELASTIC (type 1)
struct MatElastic {
  Id mid = 0;
  Real ro = 0.0;  ///< density
  Real e = 0.0;   ///< Young's modulus
  Real pr = 0.0;  ///< Poisson ratio
  std::string title;
  Source src;
  bool operator==(const MatElastic&) const = default;
};

/// *MAT_MOONEY-RIVLIN_RUBBER (type 27): W = A(I1-3) + B(I2-3) + C(I3^-2 - 1) + D(I3-1)^2.
struct MatMooneyRivlin {
  Id mid = 0;
  Real ro = 0.0;
  Real pr = 0.0;
  Real a = 0.0;
  Real b = 0.0;
  std::string title;
  Source src;
  bool operator==(const MatMooneyRivlin&) const = default;
};

/// *MAT_RIGID (type 20). E and PR are used only for contact stiffness and the time step.
struct MatRigid {
  Id mid = 0;
  Real ro = 0.0;
  Real e = 0.0;
  Real pr = 0.0;
  Real cmo = 0.0;  ///< 0 = no constraints; +1 = constrain the body's global translations/rotations
  int con1 = 0;    ///< translational constraint code (with cmo = +1): 0 none, 1 x, 2 y, 3 z, 4 xy, 5 yz, 6 zx, 7 xyz
  int con2 = 0;    ///< rotational constraint code (with cmo = +1), same coding
  std::string title;
  Source src;
  bool operator==(const MatRigid&) const = default;
};

/// *MAT_PLASTIC_KINEMATIC (type 3): J2 plasticity, bilinear hardening mixed isotropic/kinematic by
/// BETA, Cowper-Symonds rate scaling (SRC, SRP). FS (failure strain) and VP = 1 are refused by
/// the reader.
struct MatPlasticKinematic {
  Id mid = 0;
  Real ro = 0.0;
  Real e = 0.0;
  Real pr = 0.0;
  Real sigy = 0.0;  ///< initial yield stress
  Real etan = 0.0;  ///< tangent modulus
  Real beta = 0.0;  ///< 0 kinematic, 1 isotropic hardening
  Real src_c = 0.0;  ///< SRC: Cowper-Symonds C (0: no rate effect)
  Real srp = 0.0;    ///< SRP: Cowper-Symonds P
  Real fs = 0.0;     ///< FS: failure strain, elements erode at this plastic strain (0: never)
  std::string title;
  Source src;
  bool operator==(const MatPlasticKinematic&) const = default;
};

/// *MAT_PIECEWISE_LINEAR_PLASTICITY (type 24): J2 plasticity, isotropic hardening by the curve
/// LCSS, the 8-point table EPS/ES or the tangent modulus ETAN; rate scaling by C/P or LCSR.
/// FAIL > 0 erodes elements at that plastic strain; TDEL > 0 erodes elements whose stable step
/// falls below it.
struct MatPiecewiseLinearPlasticity {
  Id mid = 0;
  Real ro = 0.0;
  Real e = 0.0;
  Real pr = 0.0;
  Real sigy = 0.0;
  Real etan = 0.0;
  Real c = 0.0;   ///< Cowper-Symonds C (0: no Cowper-Symonds scaling)
  Real p = 0.0;   ///< Cowper-Symonds P
  Id lcss = 0;    ///< curve: yield stress against effective plastic strain (0: table or ETAN)
  Id lcsr = 0;    ///< curve: yield-stress scale factor against strain rate
  Real vp = 0.0;  ///< 0: rate = total strain rate; 1: viscoplastic (rate = plastic strain rate)
  Real fail = 0.0;  ///< FAIL: failure strain, elements erode at this plastic strain (0: never)
  Real tdel = 0.0;  ///< TDEL: elements whose stable step (time) falls below it erode (0: never)
  std::array<Real, 8> eps{};  ///< EPS1..EPS8 effective plastic strains of the table
  std::array<Real, 8> es{};   ///< ES1..ES8 yield stresses of the table
  std::string title;
  Source src;
  bool operator==(const MatPiecewiseLinearPlasticity&) const = default;
};

/// *MAT_NULL (type 9): no deviatoric stiffness; on shells a surface with mass only (YM and PR set
/// the contact stiffness and time step of such shells); on solids a fluid-like material whose
/// pressure is the part's equation of state (*EOS_..., EosId of *PART) plus the viscous
/// deviatoric stress 2 MU dev(D).
struct MatNull {
  Id mid = 0;
  Real ro = 0.0;
  Real ym = 0.0;
  Real pr = 0.0;
  std::string title;
  Source src;
  // Solids only (after the title and source, so that the shells' aggregate initialisations hold):
  Real pc = 0.0;     ///< PC: pressure cutoff in tension (<= 0; the pressure never falls below it)
  Real mu = 0.0;     ///< MU: dynamic viscosity (force time/length^2)
  Real terod = 0.0;  ///< TEROD: erosion when V/V0 exceeds it (0: not used)
  Real cerod = 0.0;  ///< CEROD: erosion when V/V0 falls below it (0: not used)
  bool operator==(const MatNull&) const = default;
};

/// *MAT_ADD_EROSION: failure criteria added to material MID (docs/keywords.md). Each threshold
/// is empty when the deck excludes it (blank, 0 or EXCL); the reader refuses the criteria that are
/// not built (SIGTH / IMPULSE, curves, damage cards). Strains: principal logarithmic strains.
struct MatAddErosion {
  Id mid = 0;
  std::optional<Real> mxpres;  ///< MXPRES: fails when the pressure (positive in compression) >= it
  std::optional<Real> mnpres;  ///< MNPRES: fails when the pressure <= it
  std::optional<Real> sigp1;   ///< SIGP1: fails when the largest principal stress >= it
  std::optional<Real> sigvm;   ///< SIGVM: fails when the von Mises stress >= it
  std::optional<Real> failtm;  ///< FAILTM: fails when the time >= it
  std::optional<Real> mneps;   ///< MNEPS: fails when the smallest principal strain <= it
  std::optional<Real> effeps;  ///< EFFEPS: fails when the effective strain >= it (> 0)
  std::optional<Real> voleps;  ///< VOLEPS: fails when the volumetric strain >= it (> 0) or <= it (< 0)
  std::optional<Real> mxeps;   ///< MXEPS: fails when the largest principal strain >= it (> 0)
  std::optional<Real> epssh;   ///< EPSSH: fails when the tensorial shear strain >= it (> 0)
  Real numfip = 1.0;  ///< NUMFIP: failed points (> 0), a percentage of them (-100..0), |NUMFIP| - 100 points
  int ncs = 1;        ///< NCS: thresholds that must hold at once
  Real excl = 0.0;    ///< EXCL (kept for the writer)
  std::string title;
  Source src;
  bool operator==(const MatAddErosion&) const = default;
};

/// *EOS_LINEAR_POLYNOMIAL (form 1): p = C0 + C1 mu + C2 mu^2 + C3 mu^3 + (C4 + C5 mu + C6 mu^2) E,
/// mu = rho / rho0 - 1, E internal energy per unit reference volume; C2 mu^2 and C6 mu^2 are left
/// out in tension (mu < 0).
struct EosLinearPolynomial {
  Id eosid = 0;
  std::array<Real, 7> c{};  ///< C0..C6
  Real e0 = 0.0;            ///< E0: initial internal energy per unit reference volume
  Real v0 = 0.0;            ///< V0: initial relative volume (0 and blank: 1)
  Source src;
  bool operator==(const EosLinearPolynomial&) const = default;
};

/// *EOS_GRUNEISEN (form 4): the Mie-Gruneisen form on the shock Hugoniot Us = C + S1 up + S2 up^2/Us
/// + S3 up^3/Us^2 (compressed) and rho0 C^2 mu + (GAMAO + A mu) E (expanded).
struct EosGruneisen {
  Id eosid = 0;
  Real c = 0.0;       ///< C: the Hugoniot's intercept (velocity)
  Real s1 = 0.0, s2 = 0.0, s3 = 0.0;
  Real gamma0 = 0.0;  ///< GAMAO
  Real a = 0.0;       ///< A: first-order volume correction of GAMAO
  Real e0 = 0.0;
  Real v0 = 0.0;      ///< 0 and blank: 1
  Id lcid = 0;        ///< card 2 LCID (refused when given)
  Source src;
  bool operator==(const EosGruneisen&) const = default;
};

/// *EOS_TABULATED (form 9): p = C(eps_V) + GAMA T(eps_V) E, eps_V = ln(V/V0), C and T linear
/// between the 10 points EV1 > EV2 > ... > EV10 and extrapolated from the end segments.
struct EosTabulated {
  Id eosid = 0;
  Real gama = 0.0;
  Real e0 = 0.0;
  Real v0 = 0.0;  ///< 0 and blank: 1
  std::array<Real, 10> ev{}, c{}, t{};
  Source src;
  bool operator==(const EosTabulated&) const = default;
};

using Eos = std::variant<EosLinearPolynomial, EosGruneisen, EosTabulated>;

/// The id of an equation of state card.
inline Id eos_id(const Eos& e) {
  return std::visit([](const auto& x) { return x.eosid; }, e);
}

/// The keyword of an equation of state card, for messages.
inline const char* eos_keyword(const EosLinearPolynomial&) { return "*EOS_LINEAR_POLYNOMIAL"; }
inline const char* eos_keyword(const EosGruneisen&) { return "*EOS_GRUNEISEN"; }
inline const char* eos_keyword(const EosTabulated&) { return "*EOS_TABULATED"; }

/// The card of id `id` in `all`; null when none.
inline const Eos* find_eos(const std::vector<Eos>& all, Id id) {
  for (const Eos& e : all)
    if (eos_id(e) == id) return &e;
  return nullptr;
}

using Material = std::variant<MatElastic, MatMooneyRivlin, MatRigid, MatPlasticKinematic,
                              MatPiecewiseLinearPlasticity, MatNull>;

}  // namespace slideline::model
