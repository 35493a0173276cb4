#pragma once
/// The 19 problems of the DYNA3D basic-contact verification report (../shared/spec, Appendix A),
/// generated as models: every element pairing of a problem side by side in one deck, each with its
/// own interface and supports, named after the pairing so that the output channels read
/// `interfaces/solid_on_solid/slave_force`, `supports/solid_on_solid_bottom/reaction`, ...
///
/// Geometry (per pairing, shifted by `kPairingSpacing` in x): lower block x in [x0, x0 + 1.51],
/// y in [0, 1], z in [0, 1.02] (2 elements per unit length in x and z, 2 through y); upper block
/// x in [x0 + 0.03, x0 + 1.03], z in [0.01, 1.01] (3 per unit length), y from 1 + gap. The shell
/// plate (3 x 3 shells, thickness 0.1, density 0.1) replaces the upper block in the shell and node
/// pairings; shell-on-shell and node-on-shell add a skin of shells on the lower block's top-face
/// nodes as the master surface. The "vec" problems stack 17 unit cells in z. docs/verification.md
/// lists every choice.
#include <array>
#include <string>
#include <vector>

#include "slideline/model/model.hpp"

namespace slideline::scenarios {

/// How the spec expects the interface to behave (report section 5), which selects the criteria.
enum class SslideIdealization : std::uint8_t {
  frictionless,     ///< Type 1: F_x = 0
  tied,             ///< Types 2, 6, 7: F = -P, no relative motion
  frictional,       ///< Types 3, 5, 10, 12: F_x to -f_s, then -f_k
  tension_failure,  ///< Types 8, 9 in tension: F_y follows the load to the failure force, then 0
  shear_failure,    ///< Type 9 in shear: tied to the shear failure force, then frictional
};

/// A slave node and the master segment under it at t = 0, with the bilinear shape-function
/// weights of the node's projection: the master surface point's displacement is
/// sum_k weights[k] * u(master_nodes[k]), and the relative displacement u_slave - that.
///
/// The slave node slides (type 1 throughout, frictional types after t ~ 0.37), so the criteria do
/// not use that fixed segment: `path` holds the row of lower top-face segments along x under the
/// slave (their nodes are history nodes), and at each output the slave node's current position is
/// re-projected onto the current master surface (closest point on the segment that holds it, see
/// relative_displacement below).
struct SslideMonitorSegment {
  std::array<Id, 4> nodes{};  ///< counter-clockwise seen from +y
  std::array<Vec3, 4> x0{};   ///< initial coordinates
};
struct SslideMonitor {
  Id slave_node = 0;
  std::array<Id, 4> master_nodes{};  ///< the segment at t = 0, counter-clockwise seen from +y
  Real xi = 0.0, eta = 0.0;          ///< projection in the segment's (-1, 1)^2 parameters
  std::array<Real, 4> weights{};     ///< N_k(xi, eta), summing to 1
  Vec3 slave_x0 = Vec3::Zero();      ///< the slave node's initial coordinates
  std::vector<SslideMonitorSegment> path;  ///< the master segments along the slave's path (+x)
  /// The upper body's leading contact node (largest x, nearest the slave's z) and its initial
  /// coordinates: the criteria judge sliding rows only until it passes the lower block's edge.
  Id leading_node = 0;
  Vec3 leading_x0 = Vec3::Zero();
};

/// One element pairing of a problem.
struct SslidePairing {
  std::string name;            ///< solid_on_solid, shell_on_solid, shell_on_shell, node_on_solid, node_on_shell
  std::string contact_title;   ///< the contact's heading: interfaces/<contact_title>/...
  std::string bottom_support;  ///< support titles: supports/<bottom_support>/reaction (y)
  std::string right_support;   ///<                  supports/<right_support>/reaction (x)
  Id upper_part = 0;           ///< the loaded (slave) body
  Id lower_part = 0;           ///< the supported solid block
  Id skin_part = 0;            ///< shells on the lower block's top face (0 when absent)
  Real gap = 0.0;              ///< initial distance between the upper body's contact surface
                               ///< (shell mid-surface or solid face) and the master mid-surface
  Real upper_mass = 0.0;       ///< mass of the upper body
  Real px = 0.0, py = 0.0;     ///< applied load magnitudes (x17 for the vec problems)
  SslideMonitor monitor;
};

/// One of the 19 problems.
struct SslideProblem {
  std::string name;         ///< deck name, e.g. "sslide3p"
  std::string description;  ///< Appendix A's one-line description
  model::ContactType type = model::ContactType::surface_to_surface;
  model::Enforcement enforcement = model::Enforcement::penalty;
  SslideIdealization idealization = SslideIdealization::frictional;
  Real px = 0.0;            ///< applied force along +x on each upper body (spec P_x)
  Real py = 0.0;            ///< applied force along -y on each upper body (compression > 0)
  Real cells = 1.0;         ///< unit cells stacked in z (17 for the vec problems); loads scale with it
  Real mu_s = 0.0, mu_k = 0.0, beta = 0.0;  ///< friction (0 when frictionless or tied)
  Real penalty_scale = 0.0;  ///< DYNA3D's interface penalty factor (SFS = SFM), 0 if not penalty
  Real failure_force = 0.0;  ///< expected macro failure force (types 8, 9), 0 otherwise
  Real failure_time = 0.0;   ///< time the load reaches it
  model::Model model;
  std::vector<SslidePairing> pairings;
};

/// Distance in x between the origins of two neighbouring pairings.
inline constexpr Real kPairingSpacing = 3.0;

/// The 19 problem names in the order of the spec's table (sslide1k ... sslide12l_vec).
std::vector<std::string> sslide_problem_names();

/// Builds one problem. Throws InputError for an unknown name (listing the known ones).
SslideProblem make_sslide_problem(const std::string& name);

/// u_slave - sum_k N_k u_master_k, from the displacement of the monitor's slave node and of its
/// master nodes (same order as `monitor.master_nodes`).
Vec3 relative_displacement(const SslideMonitor& monitor, const Vec3& u_slave,
                           const std::array<Vec3, 4>& u_master);

/// The relative displacement against the master surface point under the slave node NOW: the slave
/// node's current position x0 + u_slave is projected onto every segment of `monitor.path` at its
/// current position (x0 + u_path[s][k]); the closest one holds it, and the result is
/// u_slave - sum_k N_k(xi, eta) u_k with that segment's shape functions at the projection. Its y
/// is the change of the normal gap (shell offsets cancel: they are in both x0's), its x the slip.
Vec3 tracked_relative_displacement(const SslideMonitor& monitor, const Vec3& u_slave,
                                   const std::vector<std::array<Vec3, 4>>& u_path);

}  // namespace slideline::scenarios
