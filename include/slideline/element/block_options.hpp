#pragma once
/// The plain settings an element block is made from: hourglass control, bulk viscosity,
/// stiffness-proportional damping, the shell section. Kept apart from the kernels
/// (hex_block.hpp, shell_block.hpp) so that code which only builds blocks (block_factory.hpp,
/// src/solver/build.cpp) does not compile them.
#include <cstdint>

#include "slideline/core/types.hpp"

namespace slideline {

/// Hourglass control of a hexahedron block.
struct HexHourglass {
  enum class Kind : std::uint8_t {
    viscous,             ///< Flanagan-Belytschko viscous (LS-DYNA/DYNA3D types 1-3)
    physical_stiffness,  ///< total-displacement stiffness scaled to the element's bending stiffness (type 10)
    fb_stiffness,        ///< Flanagan-Belytschko stiffness on the velocity-integrated forces (types 4, 5)
    assumed_strain       ///< assumed-strain co-rotational stiffness after Belytschko-Bindeman (type 6)
  };
  Kind kind = Kind::viscous;
  Real coefficient = 0.1;
};

/// Linear and quadratic bulk viscosity coefficients.
struct BulkViscosity {
  Real quadratic = 1.5;
  Real linear = 0.06;
};

/// Stiffness-proportional (Rayleigh) damping of a block: the damping stress
/// beta (C : D) with C the material's small-strain elastic stiffness and D the rate of
/// deformation, added to the stress that makes the internal forces but never stored
/// (LS-DYNA *DAMPING_PART_STIFFNESS with COEF = -beta). A mode of circular frequency omega gets
/// the fraction of critical damping beta omega / 2. 0 = off (the kernel then does not evaluate
/// it at all).
struct StiffnessDamping {
  Real beta = 0.0;  ///< time
};

namespace shell_bt {
/// Through-thickness integration rule kind (shell_bt::ThicknessRule::Kind).
enum class ThicknessRuleKind : std::uint8_t {
  gauss,   ///< Gauss-Legendre (LS-DYNA default): interior points only
  lobatto  ///< Gauss-Lobatto: includes the two surfaces (2 points = trapezoid rule)
};
}  // namespace shell_bt

/// Shell section of a part: constant thickness, through-thickness rule, transverse shear factor,
/// and the part's viscous hourglass coefficient and membrane bulk viscosity.
struct ShellSection {
  Real thickness = 0.0;  ///< length
  int nip = 5;           ///< through-thickness points (Gauss 1..10, Lobatto 2..10)
  shell_bt::ThicknessRuleKind rule = shell_bt::ThicknessRuleKind::gauss;
  Real shear_factor = 5.0 / 6.0;  ///< SHRF: scales the transverse shear modulus
  /// The quadrilaterals' co-rotational frame: false, e1 along side 1-2 (LS-DYNA's default); true,
  /// invariant under a renumbering of the nodes (*CONTROL_ACCURACY INN; shell_bt::local_geometry).
  bool invariant_frame = false;
  /// The same for the triangles (N3 = N4): the reference side 1-2 carried by the polar rotation of
  /// the in-plane deformation (INN = 2, 4; shell_c0tri::invariant_e1); false, side 1-2.
  bool invariant_triangles = false;
  /// Hourglass coefficient (LS-DYNA QM; 0 = none): viscous, the fraction of the critical damping
  /// of each hourglass mode; stiffness (IHQ 4-6), the fraction of each mode's stiffness.
  Real hourglass_coefficient = 0.1;
  bool hourglass_stiffness = false;  ///< IHQ 4-6: the stiffness form (shell_hourglass::add)
  BulkViscosity bulk;  ///< on the membrane dilatation rate
};

}  // namespace slideline
