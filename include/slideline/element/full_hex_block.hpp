#pragma once
/// A block of fully integrated selective-reduced hexahedra (LS-DYNA *SECTION_SOLID ELFORM 2, the
/// "constant pressure" solid): 2x2x2 Gauss points for the deviatoric part, the element's mean
/// dilatation for the volumetric part (B-bar, Hughes 1980). No hourglass modes, so no hourglass
/// control; no volumetric locking (one pressure per element).
///
/// At Gauss point g the law sees F_g scaled to the element's mean volume ratio,
/// Fbar_g = (J_mean / det F_g)^(1/3) F_g with J_mean = V / V0, and the rate of deformation whose
/// trace is the element's mean dilatation rate, Dbar_g = D_g + (tr Dbar - tr D_g) I / 3. The
/// nodal forces are the B-bar ones: f_I = -sum_g detJ_g (s_g B_gI + p_g bbar_I), s_g and p_g the
/// deviator and the mean of the point's stress, bbar_I = (1/V) sum_g detJ_g B_gI. Lumped mass
/// rho V0 / 8 per node; stable step from L = V / (largest face area), as the one-point hexahedron.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "slideline/core/error.hpp"
#include "slideline/core/parallel.hpp"
#include "slideline/core/tensor3.hpp"
#include "slideline/element/block_options.hpp"
#include "slideline/element/cell_output.hpp"
#include "slideline/element/element_block.hpp"
#include "slideline/element/element_by_element_solid.hpp"
#include "slideline/element/solid_erosion.hpp"
#include "slideline/element/hex8.hpp"
#include "slideline/element/solid_point_terms.hpp"
#include "slideline/material/solid_material.hpp"
#include "slideline/mesh/element_topology.hpp"

namespace slideline {

namespace hex8_gauss {

/// Derivatives dN_I / d(xi, eta, zeta) of the trilinear shape functions at the 8 Gauss points
/// (+-1/sqrt 3 in each direction, weight 1), one 8x3 matrix per point; node order LS-DYNA's.
inline const std::array<hex8::NodeMat, 8>& shape_derivatives() {
  static const std::array<hex8::NodeMat, 8> d = [] {
    static constexpr int corner[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                         {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    const Real g = 1.0 / std::sqrt(3.0);
    std::array<hex8::NodeMat, 8> out;
    for (int p = 0; p < 8; ++p) {
      const Real q[3] = {corner[p][0] * g, corner[p][1] * g, corner[p][2] * g};
      for (int n = 0; n < 8; ++n) {
        Real f[3];
        for (int i = 0; i < 3; ++i) f[i] = 1.0 + corner[n][i] * q[i];
        out[p](n, 0) = 0.125 * corner[n][0] * f[1] * f[2];
        out[p](n, 1) = 0.125 * corner[n][1] * f[0] * f[2];
        out[p](n, 2) = 0.125 * corner[n][2] * f[0] * f[1];
      }
    }
    return out;
  }();
  return d;
}

/// The Jacobian dx/dxi = X^T dN (3x3) at point p of an element with nodal coordinates X (8x3).
inline Mat3 jacobian(const hex8::NodeMat& X, int p) { return X.transpose() * shape_derivatives()[p]; }

}  // namespace hex8_gauss

/// Fully integrated hexahedra with the law `Material`, one Material::State<Real> per Gauss point
/// (element e, point p at 8 e + p). Connectivity as the one-point hexahedron's.
template <SolidMaterial Material>
class FullHexBlock final : public ElementBlock {
 public:
  using State = typename Material::template State<Real>;

  FullHexBlock(Id part_id, Material material, BulkViscosity bulk, std::vector<Index> connectivity,
               std::vector<Id> element_ids, StiffnessDamping damping = {})
      : part_id_(part_id),
        mat_(std::move(material)),
        k_{mat_.wave_speed(), mat_.density(), mat_.lame_lambda(), mat_.shear_modulus(), bulk, damping.beta},
        conn_(std::move(connectivity)),
        ids_(std::move(element_ids)),
        common_(static_cast<Index>(ids_.size())) {
    if (!(damping.beta >= 0.0))
      throw InputError("solid part " + std::to_string(part_id_) +
                       ": the stiffness damping coefficient beta must not be negative");
    state_.assign(8 * ids_.size(), State{});
  }

  std::string kind() const override { return "hex8_full"; }
  Id part_id() const override { return part_id_; }
  Index element_count() const override { return static_cast<Index>(ids_.size()); }
  BlockTopology topology() const override { return {hex8_topology, element_count()}; }
  std::span<const Index> connectivity() const override { return conn_; }
  Id element_id(Index e) const override { return ids_[static_cast<std::size_t>(e)]; }
  Real bulk_modulus() const override { return mat_.bulk_modulus(); }
  const Material& material() const { return mat_; }
  /// The law's state of every Gauss point (element e, point p at 8 e + p).
  std::span<const State> states() const { return state_; }

  /// Reference inverse Jacobians and volumes; adds rho V0 / 8 to each node.
  void initialize(NodalFields& nodes) override {
    const Index ne = element_count();
    jacobian0_inverse_.resize(8 * static_cast<std::size_t>(ne));
    volume0_.resize(static_cast<std::size_t>(ne));
    for (Index e = 0; e < ne; ++e) {
      const hex8::NodeMat X = gather(nodes.x0, e);
      Real v0 = 0.0;
      bool positive = true;
      for (int p = 0; p < 8; ++p) {
        const Mat3 j = hex8_gauss::jacobian(X, p);
        positive = positive && j.determinant() > 0.0;
        v0 += j.determinant();
        jacobian0_inverse_[8 * e + p] = j.inverse();
      }
      if (!positive)
        throw InputError("solid element " + std::to_string(ids_[e]) + " of part " + std::to_string(part_id_) +
                         " has a non-positive Jacobian at a Gauss point (volume " + std::to_string(v0) +
                         "; check the node order)");
      volume0_[e] = v0;
      for (int k = 0; k < 8; ++k) nodes.mass[conn_[8 * e + k]] += mat_.density() * v0 / 8.0;
    }
  }

  Real compute_forces(const NodalFields& nodes, Real dt, CornerBuffer& corners, BlockEnergy& energy) override {
    const std::array<Real*, 3> out{corners.force.x.data() + force_slot_base(),
                                   corners.force.y.data() + force_slot_base(),
                                   corners.force.z.data() + force_slot_base()};
    // Erosion (element_erosion.hpp) by a failure strain at the mean plastic strain of the 8 points
    // (the cell output's), by the thresholds at each point (element_forces).
    return common_.template forces<Sums>(
        element_count(), dt, out, energy, "solid", ids_, part_id_,
        "inverted (non-positive Jacobian at a Gauss point or non-finite force)",
        [&](Index k) { return element_forces(nodes, k, dt, out); }, [&](Index k) { return mean_plastic_strain(k); });
  }

  /// ElementBlock::reference_steps: the element loop's step at the reference geometry at rest,
  /// L = V0 / A_max, with the stiffness-damping term (no bulk viscosity at rest).
  void reference_steps(const NodalFields& nodes, std::span<Real> out) const override {
    for (Index e = 0; e < element_count(); ++e) {
      const Real len = volume0_[e] / hex8::max_face_area(gather(nodes.x0, e));
      out[static_cast<std::size_t>(e)] = solid_terms::stable_step(len, k_.beta * k_.c * k_.c / len, k_.c);
    }
  }

  /// ElementBlock::scale_element_masses (MS1ST = 1): element e's rho V0 / 8 per corner times factor[e].
  Real scale_element_masses(std::span<const Real> factor, NodalFields& nodes) override {
    return common_.scale_masses(factor, conn_.data(), mat_.density(), volume0_, nodes);
  }

  /// ElementBlock::enable_mass_rescaling: the element loop keeps its steps before the factors.
  void enable_mass_rescaling() override { common_.enable_rescaling(element_count()); }
  /// ElementBlock::rescale_element_masses (MS1ST = 0): element e's physical mass rho V0 over its
  /// 8 corners.
  RescaledBlock rescale_element_masses(Real dt2ms, bool at_reference, const NodalFields& nodes,
                                       std::span<Real> corner_added, std::span<Real> /*corner_inertia*/) override {
    if (at_reference) reference_steps(nodes, common_.raw_steps(element_count()));
    return common_.rescale(dt2ms, mat_.density(), volume0_, corner_added);
  }

  Id smallest_step_element() const override { return common_.smallest_step_element(ids_); }

  /// ElementBlock::enable_erosion (refusals: solid_erosion::check_element_by_element).
  void enable_erosion(const ErosionCriteria& criteria) override {
    solid_erosion::check_element_by_element<State>(criteria, part_id(), "fully integrated hexahedra (ELFORM 2)", 8);
    common_.erosion().enable(criteria, element_count(), element_count());
  }
  const ElementErosion* erosion() const override {
    return common_.erosion().active() ? &common_.erosion() : nullptr;
  }

  /// The mean of element e's 8 points' plastic strains.
  Real mean_plastic_strain(Index e) const {
    Real eps = 0.0;
    for (int p = 0; p < 8; ++p) eps += plastic_strain_of(state_[8 * e + p]) / 8.0;
    return eps;
  }

  /// The mean over the Gauss points of the law's stress at the current geometry (each state
  /// advanced over a zero step on a copy), of the plastic strain and, for a law with W(F), of W.
  void cell_outputs(const NodalFields& nodes, std::span<CellOutput> out) const override {
    const Tensor3<Real> no_rate{};
    for (Index e = 0; e < element_count(); ++e) {
      const Geometry g = geometry(gather(nodes.x, e), e);
      CellOutput& c = out[static_cast<std::size_t>(e)];
      c = CellOutput{};
      for (int p = 0; p < 8; ++p) {
        State copy = state_[8 * e + p];
        const Tensor3<Real> s = mat_.update(copy, g.fbar[p], no_rate, 0.0);
        const SymTensor6 s6{s[0][0], s[1][1], s[2][2], s[0][1], s[1][2], s[0][2]};
        for (int k = 0; k < 6; ++k) c.stress[k] += s6[k] / 8.0;
        if constexpr (requires { { mat_.energy_density(g.fbar[p]) } -> std::convertible_to<Real>; })
          c.energy_density += mat_.energy_density(g.fbar[p]) / 8.0;
      }
      c.plastic_strain = mean_plastic_strain(e);
      c.deleted = common_.erosion().active() && common_.erosion().deleted(e);
      if (c.deleted) c.stress = SymTensor6{}, c.energy_density = 0.0;
      c.stress_bottom = c.stress_top = c.stress;
    }
  }

  bool has_plasticity() const override { return PlasticState<State>; }

  /// ElementBlock::plasticity_totals: each Gauss point's `eps`, and its `work` (per unit reference
  /// volume, j2_return.hpp) times its reference volume detJ0 (unit weights).
  PlasticityTotals plasticity_totals(const NodalFields& nodes) const override {
    PlasticityTotals t;
    if constexpr (PlasticState<State>) {
      for (Index e = 0; e < element_count(); ++e) {
        const Geometry g = geometry(gather(nodes.x0, e), e);
        for (int p = 0; p < 8; ++p) {
          const State& s = state_[8 * e + p];
          t.max_plastic_strain = std::max(t.max_plastic_strain, plastic_strain_of(s));
          t.plastic_work += plastic_work_density_of(s) * g.detj[p];
        }
      }
    }
    return t;
  }

 private:
  /// One element's step, powers and failure.
  struct Sums {
    Real dt = 0.0, visc = 0.0, damp = 0.0, power = 0.0;
    Real power_prev = 0.0;  ///< of the forces its corner slots held before, at this step's rates
    bool failed = false;
    bool erodes = false;  ///< NUMFIP of the 8 points fail the *MAT_ADD_EROSION thresholds, or TEROD / CEROD
  };

  /// The current geometry of an element at its Gauss points: the gradient operators B_g (8x3,
  /// 1/length), detJ_g, the mean gradient bbar (8x3), the volume and the scaled Fbar_g.
  struct Geometry {
    std::array<hex8::NodeMat, 8> b;
    std::array<Real, 8> detj;
    std::array<Tensor3<Real>, 8> fbar;
    hex8::NodeMat bbar;
    Real vol;
    bool positive;
  };

  Geometry geometry(const hex8::NodeMat& x, Index e) const {
    Geometry g;
    g.bbar.setZero();
    g.vol = 0.0;
    g.positive = true;
    std::array<Real, 8> detf;
    for (int p = 0; p < 8; ++p) {
      const Mat3 j = hex8_gauss::jacobian(x, p);
      g.detj[p] = j.determinant();
      g.positive = g.positive && g.detj[p] > 0.0;
      g.b[p] = hex8_gauss::shape_derivatives()[p] * j.inverse();
      g.bbar += g.detj[p] * g.b[p];
      g.vol += g.detj[p];
      const Mat3 f = j * jacobian0_inverse_[8 * static_cast<std::size_t>(e) + p];
      detf[p] = f.determinant();
      g.fbar[p] = to_tensor3(f);
    }
    g.bbar /= g.vol;
    const Real jmean = g.vol / volume0_[e];
    for (int p = 0; p < 8; ++p) {
      const Real s = std::cbrt(jmean / detf[p]);
      for (auto& row : g.fbar[p])
        for (Real& v : row) v *= s;
    }
    return g;
  }

  /// Stresses of element e at its 8 points, its B-bar nodal forces into its corner slots, its
  /// step and powers.
  Sums element_forces(const NodalFields& nodes, Index e, Real dt, const std::array<Real*, 3>& out) {
    const hex8::NodeMat x = gather(nodes.x, e), v = gather(nodes.v, e);
    const Geometry g = geometry(x, e);
    const Real trd_mean = (v.cwiseProduct(g.bbar)).sum();
    const Real len = g.vol / hex8::max_face_area(x);
    const Real rho = k_.rho0 * volume0_[e] / g.vol;
    Sums s;
    Real qdt = 0.0;
    hex8::NodeMat f = hex8::NodeMat::Zero();
    const ElementErosion& er = common_.erosion();
    const ErosionCriteria* crit = er.active() ? &er.criteria() : nullptr;
    int failed_points = 0;
    for (int p = 0; p < 8; ++p) {
      const Mat3 l = v.transpose() * g.b[p];  // L_ij = sum_I v_Ii B_Ij
      Tensor3<Real> d = solid_terms::symmetric_part(to_tensor3(l));
      const Real shift = (trd_mean - l.trace()) / 3.0;
      for (int i = 0; i < 3; ++i) d[i][i] += shift;
      Tensor3<Real> sigma = mat_.update(state_[8 * e + p], g.fbar[p], d, dt);
      if (crit && solid_erosion::point_verdict(*crit, sigma, g.fbar[p], er.time())) ++failed_points;
      const solid_terms::Added a = solid_terms::add_viscous_stress(sigma, d, trd_mean, g.detj[p], rho, len, k_);
      s.visc += a.visc;
      s.damp += a.damp;
      qdt = a.qdt;
      Mat3 dev = to_mat3(sigma);
      const Real pm = dev.trace() / 3.0;
      dev.diagonal().array() -= pm;
      f -= g.detj[p] * (g.b[p] * dev + pm * g.bbar);  // row I: (s B_I + p bbar_I)^T
    }
    const std::size_t s0 = 8 * static_cast<std::size_t>(e);
    for (int k = 0; k < 8; ++k)
      for (int i = 0; i < 3; ++i) {
        s.power_prev -= out[i][s0 + k] * v(k, i);
        out[i][s0 + k] = f(k, i);
      }
    s.power = -(f.cwiseProduct(v)).sum();
    s.dt = solid_terms::stable_step(len, qdt, k_.c);
    s.failed = !g.positive || !std::isfinite(f.sum());
    if (crit)
      s.erodes = (crit->has_thresholds() && failed_points >= crit->points_needed(8)) ||
                 solid_erosion::volume_fails(*crit, g.vol / volume0_[e]);
    return s;
  }

  hex8::NodeMat gather(const Vec3Field& f, Index e) const {
    return gather_rows<8>(f, conn_.data() + 8 * static_cast<std::size_t>(e));
  }

  Id part_id_;
  Material mat_;
  solid_terms::Constants k_;
  std::vector<Index> conn_;
  std::vector<Id> ids_;
  std::vector<Mat3> jacobian0_inverse_;  ///< per Gauss point (8 e + p), the reference dX/dxi inverted
  std::vector<Real> volume0_;
  std::vector<State> state_;  ///< the law's state, per Gauss point (8 e + p)
  ElementByElementSolid<8> common_;  ///< the element loop, erosion and mass scaling
};

}  // namespace slideline
