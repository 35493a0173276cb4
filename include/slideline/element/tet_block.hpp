#pragma once
/// A block of one-point (constant-strain) 4-node tetrahedra of one part and one material:
/// LS-DYNA's *SECTION_SOLID ELFORM 10, written in a deck as a degenerate *ELEMENT_SOLID
/// (N1 N2 N3 N4 N4 N4 N4 N4). The strain is constant in the element, so one point integrates it
/// exactly and there are no hourglass modes. Lumped mass rho V / 4 per node; stable step from the
/// characteristic length L = min altitude = 3 V / (largest face area), as LS-DYNA's solid step.
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
#include "slideline/element/solid_point_terms.hpp"
#include "slideline/material/solid_material.hpp"
#include "slideline/mesh/element_topology.hpp"

namespace slideline {

namespace tet4 {

/// The edge matrix [x2 - x1, x3 - x1, x4 - x1] (columns) of a tetrahedron.
inline Mat3 edges(const std::array<Vec3, 4>& x) {
  Mat3 m;
  for (int a = 0; a < 3; ++a) m.col(a) = x[a + 1] - x[0];
  return m;
}

/// Gradients of the four linear shape functions (1/length), rows of a 4x3 matrix, from the
/// inverse of the edge matrix: grad N_{a+1} = row a of edges^-1, grad N_1 = -(sum of the others).
inline Eigen::Matrix<Real, 4, 3> shape_gradients(const Mat3& edges_inverse) {
  Eigen::Matrix<Real, 4, 3> b;
  b.bottomRows<3>() = edges_inverse;
  b.row(0) = -edges_inverse.colwise().sum();
  return b;
}

/// Largest face area (length^2), for the minimum altitude 3 V / A_max.
inline Real max_face_area(const std::array<Vec3, 4>& x) {
  Real a2 = 0.0;
  for (const auto& f : topology_detail::tet4_faces)
    a2 = std::max(a2, (x[f[1]] - x[f[0]]).cross(x[f[2]] - x[f[0]]).squaredNorm());
  return 0.5 * std::sqrt(a2);
}

}  // namespace tet4

/// Tetrahedra with the law `Material` (material/solid_material.hpp), one Material::State<Real>
/// per element. Connectivity: 4 internal node indices per element, N1-N3 counter-clockwise seen
/// from N4 (the order of a degenerate hexahedron N1 N2 N3 N4 N4 N4 N4 N4 of positive volume).
template <SolidMaterial Material>
class TetBlock final : public ElementBlock {
 public:
  using State = typename Material::template State<Real>;

  TetBlock(Id part_id, Material material, BulkViscosity bulk, std::vector<Index> connectivity,
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
    state_.assign(ids_.size(), State{});
  }

  std::string kind() const override { return "tet4"; }
  Id part_id() const override { return part_id_; }
  Index element_count() const override { return static_cast<Index>(ids_.size()); }
  BlockTopology topology() const override { return {tet4_topology, element_count()}; }
  std::span<const Index> connectivity() const override { return conn_; }
  Id element_id(Index e) const override { return ids_[static_cast<std::size_t>(e)]; }
  Real bulk_modulus() const override { return mat_.bulk_modulus(); }
  const Material& material() const { return mat_; }
  std::span<const State> states() const { return state_; }

  /// Reference inverse edge matrices and volumes; adds rho V / 4 to each node.
  void initialize(NodalFields& nodes) override {
    const Index ne = element_count();
    edges0_inverse_.resize(static_cast<std::size_t>(ne));
    volume0_.resize(static_cast<std::size_t>(ne));
    for (Index e = 0; e < ne; ++e) {
      const Mat3 m = tet4::edges(gather(nodes.x0, e));
      const Real v0 = m.determinant() / 6.0;
      if (!(v0 > 0.0))
        throw InputError("tetrahedron " + std::to_string(ids_[e]) + " of part " + std::to_string(part_id_) +
                         " has non-positive volume " + std::to_string(v0) +
                         " (N1 N2 N3 must run counter-clockwise seen from N4)");
      edges0_inverse_[e] = m.inverse();
      volume0_[e] = v0;
      for (int k = 0; k < 4; ++k) nodes.mass[conn_[4 * e + k]] += mat_.density() * v0 / 4.0;
    }
  }

  Real compute_forces(const NodalFields& nodes, Real dt, CornerBuffer& corners, BlockEnergy& energy) override {
    const std::array<Real*, 3> out{corners.force.x.data() + force_slot_base(),
                                   corners.force.y.data() + force_slot_base(),
                                   corners.force.z.data() + force_slot_base()};
    return common_.template forces<Point>(
        element_count(), dt, out, energy, "tetrahedron", ids_, part_id_,
        "inverted (non-positive volume or non-finite force)",
        [&](Index k) { return element_forces(nodes, k, dt, out); },
        [&](Index k) { return plastic_strain_of(state_[k]); });
  }

  /// ElementBlock::reference_steps: the element loop's step at the reference geometry at rest,
  /// L = 3 V0 / A_max, with the stiffness-damping term (no bulk viscosity at rest).
  void reference_steps(const NodalFields& nodes, std::span<Real> out) const override {
    for (Index e = 0; e < element_count(); ++e) {
      const std::array<Vec3, 4> x0 = gather(nodes.x0, e);
      const Real len = 3.0 * volume0_[e] / tet4::max_face_area(x0);
      out[static_cast<std::size_t>(e)] = solid_terms::stable_step(len, k_.beta * k_.c * k_.c / len, k_.c);
    }
  }

  /// ElementBlock::scale_element_masses (MS1ST = 1): element e's rho V0 / 4 per corner times factor[e].
  Real scale_element_masses(std::span<const Real> factor, NodalFields& nodes) override {
    return common_.scale_masses(factor, conn_.data(), mat_.density(), volume0_, nodes);
  }

  /// ElementBlock::enable_mass_rescaling: the element loop keeps its steps before the factors.
  void enable_mass_rescaling() override { common_.enable_rescaling(element_count()); }
  /// ElementBlock::rescale_element_masses (MS1ST = 0): element e's physical mass rho V0 over its
  /// 4 corners.
  RescaledBlock rescale_element_masses(Real dt2ms, bool at_reference, const NodalFields& nodes,
                                       std::span<Real> corner_added, std::span<Real> /*corner_inertia*/) override {
    if (at_reference) reference_steps(nodes, common_.raw_steps(element_count()));
    return common_.rescale(dt2ms, mat_.density(), volume0_, corner_added);
  }

  Id smallest_step_element() const override { return common_.smallest_step_element(ids_); }

  /// ElementBlock::enable_erosion (refusals: solid_erosion::check_element_by_element).
  void enable_erosion(const ErosionCriteria& criteria) override {
    solid_erosion::check_element_by_element<State>(criteria, part_id(), "tetrahedra (ELFORM 10)", 1);
    common_.erosion().enable(criteria, element_count(), element_count());
  }
  const ElementErosion* erosion() const override {
    return common_.erosion().active() ? &common_.erosion() : nullptr;
  }

  /// The law's stress at the current geometry (its state advanced over a zero step on a copy),
  /// the state's plastic strain and, for a law with W(F), W per reference volume.
  void cell_outputs(const NodalFields& nodes, std::span<CellOutput> out) const override {
    const Tensor3<Real> no_rate{};
    for (Index e = 0; e < element_count(); ++e) {
      const Tensor3<Real> F = to_tensor3(tet4::edges(gather(nodes.x, e)) * edges0_inverse_[e]);
      State copy = state_[e];
      const Tensor3<Real> s = mat_.update(copy, F, no_rate, 0.0);
      CellOutput& c = out[static_cast<std::size_t>(e)];
      c.stress = {s[0][0], s[1][1], s[2][2], s[0][1], s[1][2], s[0][2]};
      c.stress_bottom = c.stress_top = c.stress;
      c.plastic_strain = plastic_strain_of(state_[e]);
      if constexpr (requires { { mat_.energy_density(F) } -> std::convertible_to<Real>; })
        c.energy_density = mat_.energy_density(F);
      c.deleted = common_.erosion().active() && common_.erosion().deleted(e);
      if (c.deleted) c.stress = c.stress_bottom = c.stress_top = SymTensor6{}, c.energy_density = 0.0;
    }
  }

  bool has_plasticity() const override { return PlasticState<State>; }

  /// ElementBlock::plasticity_totals: each element's `eps`, and its `work` (per unit reference
  /// volume, j2_return.hpp) times its reference volume.
  PlasticityTotals plasticity_totals(const NodalFields& nodes) const override {
    PlasticityTotals t;
    if constexpr (PlasticState<State>) {
      for (Index e = 0; e < element_count(); ++e) {
        const State& s = state_[e];
        t.max_plastic_strain = std::max(t.max_plastic_strain, plastic_strain_of(s));
        t.plastic_work += plastic_work_density_of(s) * tet4::edges(gather(nodes.x0, e)).determinant() / 6.0;
      }
    }
    return t;
  }

 private:
  /// One element's step, powers and failure.
  struct Point {
    Real dt, visc, damp, power;
    bool failed;
    bool erodes = false;  ///< the point fails the *MAT_ADD_EROSION thresholds, or TEROD / CEROD
    Real power_prev = 0.0;  ///< of the forces its corner slots held before, at this step's rates
  };

  /// Stress of element e (law at F = edges(x) edges(X)^-1 with D = sym(sum v_I (x) grad N_I),
  /// plus bulk viscosity and damping), its nodal forces f_I = -V sigma grad N_I into its corner
  /// slots, its step (L = 3 V / A_max) and powers.
  Point element_forces(const NodalFields& nodes, Index e, Real dt, const std::array<Real*, 3>& out) {
    const std::array<Vec3, 4> x = gather(nodes.x, e), v = gather(nodes.v, e);
    const Mat3 ed = tet4::edges(x);
    const Real vol = ed.determinant() / 6.0;
    const Eigen::Matrix<Real, 4, 3> g = tet4::shape_gradients(ed.inverse());
    Mat3 l = Mat3::Zero();
    for (int k = 0; k < 4; ++k) l += v[k] * g.row(k);
    const Tensor3<Real> d = solid_terms::symmetric_part(to_tensor3(l));
    const Tensor3<Real> F = to_tensor3(ed * edges0_inverse_[e]);
    Tensor3<Real> sigma = mat_.update(state_[e], F, d, dt);
    const ElementErosion& er = common_.erosion();
    const bool erodes = er.active() && (solid_erosion::point_verdict(er.criteria(), sigma, F, er.time()) ||
                                        solid_erosion::volume_fails(er.criteria(), vol / volume0_[e]));
    const Real len = 3.0 * vol / tet4::max_face_area(x);
    const Real rho = k_.rho0 * volume0_[e] / vol;
    const solid_terms::Added a = solid_terms::add_viscous_stress(sigma, d, l.trace(), vol, rho, len, k_);
    const Mat3 s = to_mat3(sigma);
    Point p{solid_terms::stable_step(len, a.qdt, k_.c), a.visc, a.damp, 0.0, !(vol > 0.0), erodes};
    const std::size_t s0 = 4 * static_cast<std::size_t>(e);
    Real fsum = 0.0;
    for (int k = 0; k < 4; ++k) {
      const Vec3 f = -vol * (s * g.row(k).transpose());
      for (int i = 0; i < 3; ++i) {
        p.power_prev -= out[i][s0 + k] * v[k][i];
        out[i][s0 + k] = f[i];
      }
      fsum += f.sum();
      p.power -= f.dot(v[k]);
    }
    p.failed = p.failed || !std::isfinite(fsum);
    return p;
  }

  std::array<Vec3, 4> gather(const Vec3Field& f, Index e) const {
    std::array<Vec3, 4> x;
    for (int k = 0; k < 4; ++k) x[k] = f.get(conn_[4 * static_cast<std::size_t>(e) + k]);
    return x;
  }

  Id part_id_;
  Material mat_;
  solid_terms::Constants k_;
  std::vector<Index> conn_;
  std::vector<Id> ids_;
  std::vector<Mat3> edges0_inverse_;  ///< per element, the reference edge matrix inverted
  std::vector<Real> volume0_;
  std::vector<State> state_;          ///< the law's state, one per element
  ElementByElementSolid<4> common_;  ///< the element loop, erosion and mass scaling
};

}  // namespace slideline
