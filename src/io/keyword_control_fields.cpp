#include "field_rules.hpp"
#include "keyword_card.hpp"
#include "slideline/core/error.hpp"

// The control cards whose fields change the physics (issue 21): *CONTROL_SHELL, *CONTROL_ACCURACY,
// and *CONTROL_SOLID (*CONTROL_BULK_VISCOSITY: keyword_controls.cpp). Same rules as above: a field at
// its manual default passes, one that would change the answer is refused, one that acts only on
// what this code refuses or lacks warns. docs/keywords.md, "Control and output", is the table.
namespace slideline::keyword {
namespace {

using detail::check_remaining;
using detail::OptionalCard;
using detail::Rule;
using detail::Use;

constexpr Rule kShell1[] = {
    {"WRPANG", 20, Use::output, "shell warpage angle above which a warning is printed"},
    {"ESORT", 0, Use::honoured, ""},  // stored (Model::shell_esort); 2 refused where triangles run
    {"IRNXX", -1, Use::inert, "shell normal update of Hughes-Liu shells; the shells here are Belytschko-Tsay"},
    {"ISTUPD", 0, Use::honoured, ""},  // stored (Model::shell_istupd): 1, 4; 2, 3 refused
    {"THEORY", 2, Use::refuse, "default shell formulation; 2 = Belytschko-Tsay is the one here"},
    {"BWC", 2, Use::refuse, "warping stiffness of Belytschko-Tsay shells: 1 = Belytschko-Wong-Chiang"},
    {"MITER", 1, Use::refuse, "plane-stress plasticity iteration"},
    {"PROJ", 0, Use::refuse, "projection of the warping stiffness"},
};
constexpr Rule kShell2[] = {
    {"ROTASCL", 1, Use::refuse, "rotary inertia scale factor of shells"},
    {"INTGRD", 0, Use::honoured, ""},  // stored (Model::shell_intgrd): 0 Gauss, 1 Lobatto
    {"LAMSHT", 0, Use::refuse, "laminated shell theory"},
    {"CSTYP6", 1, Use::inert, "coordinate system of shell formulation 6, which is refused"},
    {"TSHELL", 0, Use::inert, "thermal shell option; the run is not thermal"},
};
constexpr Rule kShell3[] = {
    {"PSSTUPD", 0, Use::refuse, "part set of the shell thickness update"},
    {"SIDT4TU", 0, Use::refuse, "part set of the type 4 thickness update"},
    {"CNTCO", 0, Use::refuse, "contact reference surface from the shell offset"},
    {"ITSFLG", 0, Use::refuse, "initial transverse shear stress"},
    {"IRQUAD", 0, Use::inert, "in-plane integration rule of quadratic shells (ELFORM 23, 24), which are refused"},
    {"W-MODE", 0, Use::refuse, "failure by the W-mode"},
    {"STRETCH", 0, Use::refuse, "failure by stretch"},
    {"ICRQ", 0, Use::refuse, "continuous thickness and strain across elements"},
};
constexpr Rule kShell4[] = {
    {"NFAIL1", 0, Use::refuse, "failure of badly shaped shells"},
    {"NFAIL4", 0, Use::refuse, "failure of badly shaped shells"},
    {"PSNFAIL", 0, Use::refuse, "part set of NFAIL1 / NFAIL4"},
    {"KEEPCS", 0, Use::refuse, "keep the contact segments of failed shells"},
    {"DELFR", 0, Use::refuse, "deletion of shells whose neighbours failed"},
    {"DRCPSID", 0, Use::refuse, "part set of the drilling rotation constraint"},
    {"DRCPRM", 1, Use::refuse, "drilling rotation constraint scale"},
    {"INTPERR", 0, Use::refuse, "error on bad integration points"},
};
constexpr OptionalCard kShellCards[] = {{"card 1", kShell1}, {"card 2", kShell2}, {"card 3", kShell3},
                                        {"card 4", kShell4}};

constexpr Rule kAccuracy1[] = {
    // OSU = 1 asks for objective (second-order) stress updates under large rotations; every update
    // here is objective to all orders already (hyperelastic laws from F, J2 on the Green-Naghdi rate
    // with R from the polar decomposition of F, shells in their co-rotational frame), for every part.
    {"OSU", 0, Use::honoured, ""},
    {"INN", 1, Use::honoured, ""},  // stored (Model::accuracy_inn)
    {"PIDOSU", 0, Use::honoured, ""},
    {"IACC", 0, Use::refuse, "implicit accuracy option (also changes some explicit materials)"},
    {"EXACC", 0, Use::refuse, "explicit accuracy parameter"},
};
constexpr OptionalCard kAccuracyCards[] = {{"card 1", kAccuracy1}};

constexpr Rule kSolid1[] = {
    {"ESORT", 0, Use::honoured, ""},  // stored (Model::solid_esort); 1 refused where it would sort
    {"FMATRX", 0, Use::refuse, "method of the deformation gradient"},
    {"NIPTETS", 4, Use::inert, "integration points of tetrahedra, which are refused"},
    {"SWLOCL", 1, Use::output, "output system of spot weld solids"},
    {"PSFAIL", 0, Use::refuse, "part set of solid failure"},
    {"T10JTOL", 0, Use::inert, "Jacobian tolerance of 10-node tetrahedra, which are refused"},
    {"ICOH", 0, Use::refuse, "cohesive element deletion"},
    {"TET13K", 0, Use::inert, "formulation 13 tetrahedra, which are refused"},
};
constexpr Rule kSolid2[] = {
    {"PM1", 0, Use::refuse, "solid element permutation"}, {"PM2", 0, Use::refuse, "solid element permutation"},
    {"PM3", 0, Use::refuse, "solid element permutation"}, {"PM4", 0, Use::refuse, "solid element permutation"},
    {"PM5", 0, Use::refuse, "solid element permutation"}, {"PM6", 0, Use::refuse, "solid element permutation"},
    {"PM7", 0, Use::refuse, "solid element permutation"}, {"PM8", 0, Use::refuse, "solid element permutation"},
};
constexpr OptionalCard kSolidCards[] = {{"card 1", kSolid1}, {"card 2", kSolid2}};

}  // namespace

void check_control_fields(const Context& ctx, Block& b) {
  const std::string_view kw = b.keyword;
  const std::span<const OptionalCard> cards = kw == "*CONTROL_SHELL"      ? std::span<const OptionalCard>(kShellCards)
                                              : kw == "*CONTROL_ACCURACY" ? std::span<const OptionalCard>(kAccuracyCards)
                                                                          : std::span<const OptionalCard>(kSolidCards);
  check_remaining(ctx, b, cards);
}

}  // namespace slideline::keyword
