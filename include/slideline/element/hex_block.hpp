#pragma once
/// A block of one-point hexahedra of one part and one material.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "slideline/core/error.hpp"
#include "slideline/core/lanes.hpp"
#include "slideline/core/tensor3.hpp"
#include "slideline/core/parallel.hpp"
#include "slideline/element/block_options.hpp"
#include "slideline/element/element_block.hpp"
#include "slideline/element/solid_erosion.hpp"
#include "slideline/element/state_speed.hpp"
#include "slideline/element/hex8.hpp"
#include "slideline/element/mass_scaling_once.hpp"
#include "slideline/element/hex_hourglass_stiffness.hpp"
#include "slideline/material/solid_material.hpp"

namespace slideline {

/// Hexahedra with the law `Material` (material/solid_material.hpp). The block owns the law's state
/// of every element, one Material::State<Lanes> per batch of kLanes elements (batch e / kLanes,
/// lane e % kLanes; the spare lanes of a last partial batch follow its last element).
template <SolidMaterial Material>
class HexBlock final : public ElementBlock {
 public:
  /// The law's state of one batch of kLanes elements.
  using State = typename Material::template State<Lanes>;
  /// Whether the law's state carries each element's sound speed (a null solid's EOS): the bulk
  /// viscosity and the step then read it instead of the law's constant wave speed.
  static constexpr bool kStateSpeed = requires(const State& s) { s.sound_speed; };

  /// `damping.beta` > 0 adds the stiffness-proportional damping stress
  /// beta (lambda tr(D) I + 2 mu D) with the material's small-strain Lame constants.
  HexBlock(Id part_id, Material material, HexHourglass hourglass, BulkViscosity bulk,
           std::vector<Index> connectivity, std::vector<Id> element_ids,
           StiffnessDamping damping = {})
      : part_id_(part_id),
        mat_(std::move(material)),
        hg_(hourglass),
        bulk_(bulk),
        damping_(damping),
        conn_(std::move(connectivity)),
        ids_(std::move(element_ids)) {
    if (!(damping_.beta >= 0.0))
      throw InputError("solid part " + std::to_string(part_id_) +
                       ": the stiffness damping coefficient beta must not be negative");
    const Index ne = element_count();
    chunk_dt_.assign(chunk_count(ne), 0.0);
    chunk_dt_element_.assign(chunk_count(ne), 0);
    chunk_hg_.assign(chunk_count(ne), 0.0);
    chunk_visc_.assign(chunk_count(ne), 0.0);
    chunk_damp_.assign(chunk_count(ne), 0.0);
    chunk_power_.assign(chunk_count(ne), 0.0);
    chunk_bad_.assign(chunk_count(ne), -1);
    // The generalised hourglass forces of the last evaluation (every form), its bulk-viscosity
    // pressure times volume and (damped) its damping stress times volume: the trapezoidal works.
    const std::size_t nb = static_cast<std::size_t>(padded(ne) / kLanes);
    hg_force_.assign(12 * nb, Lanes::Zero());
    visc_prev_.assign(nb, Lanes::Zero());
    if (damping_.beta > 0.0) damp_prev_.assign(6 * nb, Lanes::Zero());
    volume0_.assign(padded(ne), 0.0);
    state_.assign(static_cast<std::size_t>(padded(ne) / kLanes), State{});
    // Lane-major connectivity: batch j, node k, lane l at 64 j + 8 k + l, the spare lanes of a
    // last partial batch repeating its last element.
    conn_lanes_.assign(8 * static_cast<std::size_t>(padded(ne)), 0);
    for (Index e = 0; e < padded(ne); ++e) {
      const Index src = std::min(e, ne - 1);
      const Index j = e / kLanes, l = e % kLanes;
      for (int k = 0; k < 8; ++k)
        conn_lanes_[64 * static_cast<std::size_t>(j) + kLanes * k + l] = conn_[8 * src + k];
    }
  }

  std::string kind() const override { return "hex8"; }
  bool stiffness_hourglass() const override { return hg_.kind != HexHourglass::Kind::viscous; }
  Id part_id() const override { return part_id_; }
  Index element_count() const override { return static_cast<Index>(ids_.size()); }
  BlockTopology topology() const override { return {hex8_topology, element_count()}; }
  std::span<const Index> connectivity() const override { return conn_; }
  Id element_id(Index e) const override { return ids_[e]; }
  const Material& material() const { return mat_; }
  /// The law's small-strain bulk modulus (force/length^2).
  Real bulk_modulus() const override { return mat_.bulk_modulus(); }
  /// The law's state of every element, by batch (see the class comment).
  std::span<const State> states() const { return state_; }
  const StiffnessDamping& stiffness_damping() const { return damping_; }

  /// ElementBlock::enable_erosion (refusals: solid_erosion::check).
  void enable_erosion(const ErosionCriteria& criteria) override {
    solid_erosion::check<State>(criteria, part_id_);
    erosion_.enable(criteria, element_count(), padded(element_count()));
    needs_stress_ = criteria.needs_stress();
  }
  const ElementErosion* erosion() const override { return erosion_.active() ? &erosion_ : nullptr; }

  /// ElementBlock::cell_outputs: the law's stress at the current geometry (its state advanced
  /// over a zero step on a copy, so the output never moves the law), the state's effective plastic
  /// strain and, for a law with a strain energy W(F) (`energy_density`), W per reference volume; for a
  /// law with a state energy (`energy_density(state)`: the J2 laws' elastic energy plus plastic work), that.
  void cell_outputs(const NodalFields& nodes, std::span<CellOutput> out) const override {
    const Index ne = element_count();
    Tensor3<Lanes> no_rate;
    for (auto& row : no_rate)
      for (Lanes& v : row) v = Lanes::Zero();
    for (Index e0 = 0; e0 < ne; e0 += kLanes) {
      Batch bt;
      gather_batch(nodes, e0, bt);
      const Tensor3<Lanes> F = inverse(inverse_deformation_gradient(bt));
      const State& held = state_[e0 / kLanes];
      State copy = held;
      Tensor3<Lanes> sigma;
      if constexpr (kStateSpeed) sigma = mat_.update_volume(copy, Lanes(bt.vol / Lanes::Map(volume0_.data() + e0)), no_rate, 0.0);
      else sigma = mat_.update(copy, F, no_rate, 0.0);
      Lanes w = Lanes::Zero();
      if constexpr (requires { { mat_.energy_density(F) } -> std::convertible_to<Lanes>; }) w = mat_.energy_density(F);
      else if constexpr (requires { { mat_.energy_density(held) } -> std::convertible_to<Lanes>; }) w = mat_.energy_density(held);
      const int valid = static_cast<int>(std::min<Index>(kLanes, ne - e0));
      for (int l = 0; l < valid; ++l) {
        CellOutput& c = out[static_cast<std::size_t>(e0 + l)];
        c.deleted = erosion_.active() && erosion_.deleted(e0 + l);
        c.stress = c.deleted ? SymTensor6{} : sym6(sigma, l);
        c.stress_bottom = c.stress_top = c.stress;
        c.plastic_strain = plastic_strain_of(held, l);
        c.energy_density = c.deleted ? 0.0 : w[l];
      }
    }
  }

  bool has_plasticity() const override { return PlasticState<State>; }

  /// ElementBlock::plasticity_totals: each element's `eps`, and its `work` (per unit reference
  /// volume, j2_return.hpp) times its reference volume.
  PlasticityTotals plasticity_totals(const NodalFields& /*nodes*/) const override {
    PlasticityTotals t;
    if constexpr (PlasticState<State>) {
      const Index ne = element_count();
      for (Index e0 = 0; e0 < ne; e0 += kLanes) {
        const State& s = state_[e0 / kLanes];
        for (int l = 0; l < static_cast<int>(std::min<Index>(kLanes, ne - e0)); ++l) {
          t.max_plastic_strain = std::max(t.max_plastic_strain, plastic_strain_of(s, l));
          t.plastic_work += plastic_work_density_of(s, l) * volume0_[static_cast<std::size_t>(e0 + l)];
        }
      }
    }
    return t;
  }

  void initialize(NodalFields& nodes) override {
    const Index ne = element_count();
    for (Index e = 0; e < ne; ++e) {
      const hex8::NodeMat X0 = gather(nodes.x0, e);
      const Real v0 = hex8::volume(X0, hex8::volume_gradient(X0));
      if (!(v0 > 0.0))
        throw InputError("solid element " + std::to_string(ids_[e]) + " of part " +
                         std::to_string(part_id_) + " has non-positive volume " +
                         std::to_string(v0) + " (check the node order)");
      volume0_[e] = v0;
      if (e == ne - 1)  // the spare lanes of a last partial batch repeat the last element
        std::fill(volume0_.begin() + ne, volume0_.end(), v0);
      const Real m = mat_.density() * v0 / 8.0;
      for (int k = 0; k < 8; ++k) nodes.mass[conn_[8 * e + k]] += m;
    }
  }

  /// ElementBlock::reference_steps: len / (q + sqrt(q^2 + c^2)), len = V / (largest face area) at
  /// the reference geometry, q the stiffness-damping term only (no bulk viscosity at rest).
  void reference_steps(const NodalFields& nodes, std::span<Real> out) const override {
    const Real c = mat_.wave_speed();
    for (Index e = 0; e < element_count(); ++e) {
      const hex8::NodeMat X0 = gather(nodes.x0, e);
      const Real len = hex8::volume(X0, hex8::volume_gradient(X0)) / hex8::max_face_area(X0);
      const Real q = damping_.beta * c * c / len;
      out[static_cast<std::size_t>(e)] = len / (q + std::sqrt(q * q + c * c));
    }
  }

  /// ElementBlock::scale_element_masses: element e's rho V0 / 8 per corner times factor[e].
  Real scale_element_masses(std::span<const Real> factor, NodalFields& nodes) override {
    const Index ne = element_count();
    step_factor_.assign(padded(ne), 1.0);
    const Real rho = mat_.density();
    const Real added = scale_corner_masses(
        ne, factor, conn_.data(),
        [&](Index e) { return ElementMassScaling::CornerShare{rho * volume0_[e] / 8.0, 0.0, 8 * e, 8}; }, nodes,
        step_factor_.data());
    std::fill(step_factor_.begin() + ne, step_factor_.end(), step_factor_[ne - 1]);  // spare lanes
    return added;
  }

  /// ElementBlock::enable_mass_rescaling: the element loop keeps its steps before the factors.
  void enable_mass_rescaling() override {
    rescaling_.enable(element_count(), padded(element_count()));
    step_factor_.assign(padded(element_count()), 1.0);
  }
  /// ElementBlock::rescale_element_masses: element e's physical mass rho V0 over its 8 corners.
  RescaledBlock rescale_element_masses(Real dt2ms, bool at_reference, const NodalFields& nodes,
                                       std::span<Real> corner_added, std::span<Real> /*corner_inertia*/) override {
    if (at_reference) reference_steps(nodes, rescaling_.raw_steps_span(element_count()));
    const Real rho = mat_.density();
    return rescaling_.rescale(element_count(), 8, dt2ms, [&](Index e) { return rho * volume0_[e]; },
                              step_factor_.data(), corner_added);
  }

  /// Internal forces of all elements into their corner slots of `corners` (residual form), the
  /// hourglass, bulk-viscosity and stiffness-damping powers into `energy`; returns the smallest
  /// element time step. Throws InstabilityError naming the first element (of the first chunk)
  /// that inverted or produced a non-finite force.
  /// `dt` (time) is the step the law integrates its state over; velocities are at t^{n-1/2}, the
  /// geometry at x^n, so the rate of deformation the law sees is sym(v^{n-1/2} (x) B(x^n)).
  Real compute_forces(const NodalFields& nodes, Real dt, CornerBuffer& corners,
                      BlockEnergy& energy) override {
    // One branch per block: a block without stiffness damping runs the kernel without it.
    const bool viscous = hg_.kind == HexHourglass::Kind::viscous;
    const bool damped = damping_.beta > 0.0;
    if (viscous && !damped)
      compute_chunks<true, false>(nodes, dt, corners);
    else if (!damped)
      compute_chunks<false, false>(nodes, dt, corners);
    else if (viscous)
      compute_chunks<true, true>(nodes, dt, corners);
    else
      compute_chunks<false, true>(nodes, dt, corners);
    if (erosion_.active())
      energy.eroded_elements += erosion_.reduce(energy.eroded_internal, energy.eroded_hourglass);
    return reduce_element_chunks(chunk_dt_, chunk_hg_, chunk_visc_, chunk_damp_, chunk_power_, chunk_bad_, energy,
                                 "solid", ids_, part_id_,
                                 "inverted (non-positive volume or non-finite force)");
  }

 private:
  /// The element loop, vectorised across elements: each chunk (a multiple of kLanes elements, so
  /// chunk boundaries and hence the results do not depend on the thread count) is processed in
  /// batches of kLanes elements, one per lane; a last partial batch repeats its last element in
  /// the spare lanes and discards them.
  template <bool viscous, bool damped>
  void compute_chunks(const NodalFields& nodes, Real dt_law, CornerBuffer& corners) {
    static_assert(kChunkSize % kLanes == 0, "batches must not straddle chunks");
    const Real c = mat_.wave_speed();
    const KernelConstants kc{c, mat_.density(), mat_.youngs_modulus(), damping_.beta * mat_.lame_lambda(),
                             2.0 * damping_.beta * mat_.shear_modulus(), damping_.beta * c * c,
                             mat_.shear_modulus()};
    const std::array<Real*, 3> out{corners.force.x.data() + force_slot_base(),
                                   corners.force.y.data() + force_slot_base(),
                                   corners.force.z.data() + force_slot_base()};
    parallel_for_chunks(element_count(), [&](Index b, Index end, Index chunk) {
      ChunkSums sums;
      for (Index e0 = b; e0 < end; e0 += kLanes) {
        const int valid = static_cast<int>(std::min<Index>(kLanes, end - e0));
        Batch bt;
        gather_batch(nodes, e0, bt);
        BatchStress st = batch_stress<damped>(bt, e0, dt_law, kc);
        BatchForces f = batch_forces<viscous>(bt, st.sigma, e0, dt_law, kc);
        if (erosion_.active()) erode_batch(bt, st, f, e0, valid, dt_law, chunk, kc.c, out);
        accumulate<damped>(sums, bt, st, f, e0, valid, kc.c, step_factor_.empty() ? nullptr : step_factor_.data(),
                           rescaling_.raw_steps());
        store_forces(f, e0, valid, out);
      }
      Index lane = 0;
      chunk_dt_[chunk] = sums.dtmin.minCoeff(&lane);
      chunk_dt_element_[chunk] = static_cast<Index>(sums.dtarg[lane]);
      chunk_hg_[chunk] = sums.p_hg.sum();
      chunk_visc_[chunk] = sums.p_visc.sum();
      chunk_damp_[chunk] = sums.p_damp.sum();
      chunk_power_[chunk] = sums.p_all.sum();
      chunk_bad_[chunk] = sums.bad;
    });
  }

  /// The block's constants the kernel reads: wave speed, density, Young's modulus, and the
  /// stiffness-damping factors beta lambda, 2 beta mu, beta c^2, and the shear modulus.
  struct KernelConstants {
    Real c, rho0, e_mod, beta_lambda, beta_2mu, beta_c2, mu;
  };

  /// One batch of kLanes elements: current, velocity and reference nodal components, the gradient
  /// operator B = (1/V) dV/dx (1/length), the volume and its inverse.
  struct Batch {
    hex8::NodeLanes x, y, z, vx, vy, vz, x0, y0, z0, bx, by, bz;
    Lanes vol, inv_vol;
  };

  /// The stress of a batch (law, bulk viscosity, stiffness damping), the viscous and damping
  /// powers, the characteristic length and the viscous term of the step.
  struct BatchStress {
    Tensor3<Lanes> sigma;
    Tensor3<Lanes> law;  ///< the law's stress alone: set only when an erosion criterion reads it
    Lanes visc, damp, qdt, len, c;  ///< c: the elements' sound speeds, set when kStateSpeed
    /// The powers of the last evaluation's bulk-viscosity and damping stresses at this step's rates.
    Lanes visc_prev, damp_prev;
  };

  /// Nodal forces of a batch (residual form), hourglass power, sum of the force components (to
  /// detect a non-finite force) and total internal power.
  struct BatchForces {
    hex8::NodeLanes fx, fy, fz;
    Lanes hg, fsum, all;
    Lanes hg_prev;  ///< the power of the last evaluation's hourglass forces at this step's rates
  };

  /// A chunk's running minimum step (and its element), powers and first failed element.
  struct ChunkSums {
    Lanes dtmin = Lanes::Constant(std::numeric_limits<Real>::max());
    Lanes dtarg = Lanes::Zero();  ///< per lane, the element (as a Real) with the smallest step so far
    Lanes p_hg = Lanes::Zero(), p_visc = Lanes::Zero(), p_damp = Lanes::Zero(), p_all = Lanes::Zero();
    Index bad = -1;
  };

  /// Gathers the batch starting at element e0 and computes its gradient operator and volume.
  void gather_batch(const NodalFields& nodes, Index e0, Batch& bt) const {
    const Index* idx = conn_lanes_.data() + 8 * static_cast<std::size_t>(e0);
    for (int k = 0; k < 8; ++k) {
      const Index* ik = idx + kLanes * k;
      bt.x[k] = gather_lanes(nodes.x.x.data(), ik);
      bt.y[k] = gather_lanes(nodes.x.y.data(), ik);
      bt.z[k] = gather_lanes(nodes.x.z.data(), ik);
      bt.vx[k] = gather_lanes(nodes.v.x.data(), ik);
      bt.vy[k] = gather_lanes(nodes.v.y.data(), ik);
      bt.vz[k] = gather_lanes(nodes.v.z.data(), ik);
      bt.x0[k] = gather_lanes(nodes.x0.x.data(), ik);
      bt.y0[k] = gather_lanes(nodes.x0.y.data(), ik);
      bt.z0[k] = gather_lanes(nodes.x0.z.data(), ik);
    }
    if (erosion_.active()) solid_erosion::freeze_deleted(bt, e0, erosion_, element_count());
    hex8::volume_gradient(bt.x, bt.y, bt.z, bt.bx, bt.by, bt.bz);
    bt.vol = Lanes::Zero();
    for (int k = 0; k < 8; ++k) bt.vol += bt.x[k] * bt.bx[k] + bt.y[k] * bt.by[k] + bt.z[k] * bt.bz[k];
    bt.vol /= 3.0;
    bt.inv_vol = 1.0 / bt.vol;
    for (int k = 0; k < 8; ++k) {
      bt.bx[k] *= bt.inv_vol;
      bt.by[k] *= bt.inv_vol;
      bt.bz[k] *= bt.inv_vol;
    }
  }

  /// Erosion of a batch's elements after the law's update (solid_erosion::fails, the step as
  /// accumulate() computes it with wave speed `c`): a deleted element's forces and powers are
  /// zeroed and its step is +inf (it votes none). The strains: of F at x^n (solid_erosion.hpp).
  /// Each element's held works are trapezoidal, as the block's (accumulate()): the first half from
  /// its last forces, still in its corner slots (`out`), and the last powers at this step's rates.
  void erode_batch(const Batch& bt, BatchStress& st, BatchForces& f, Index e0, int valid, Real dt, Index chunk, Real c,
                   const std::array<Real*, 3>& out) {
    const State& s = state_[e0 / kLanes];
    const ErosionCriteria& crit = erosion_.criteria();
    Tensor3<Lanes> F;
    if (crit.needs_strain()) F = inverse(inverse_deformation_gradient(bt));
    for (int l = 0; l < valid; ++l) {
      const std::size_t s0 = 8 * static_cast<std::size_t>(e0 + l);
      Real all_prev = 0.0;
      for (int k = 0; k < 8; ++k)
        all_prev -= out[0][s0 + k] * bt.vx[k][l] + out[1][s0 + k] * bt.vy[k][l] + out[2][s0 + k] * bt.vz[k][l];
      const Real internal_prev = 0.5 * (all_prev - st.visc_prev[l] - st.damp_prev[l] - f.hg_prev[l]);
      const Real internal = 0.5 * (f.all[l] - st.visc[l] - st.damp[l] - f.hg[l]);
      const Real q = st.qdt[l];
      const Real c_l = kStateSpeed ? st.c[l] : c;
      Real dt_e = crit.min_step > 0.0 ? st.len[l] / (q + std::sqrt(q * q + c_l * c_l)) : 0.0;
      if (!step_factor_.empty()) dt_e *= step_factor_[static_cast<std::size_t>(e0 + l)];
      const SymTensor6 law = needs_stress_ ? sym6(st.law, l) : SymTensor6{};
      const bool fails = solid_erosion::fails(crit, plastic_strain_of(s, l), law, erosion_.time(), dt_e,
                                              crit.needs_strain() ? solid_erosion::log_strains(F, l) : std::array<Real, 3>{}) ||
                         solid_erosion::volume_fails(crit, bt.vol[l] / volume0_[static_cast<std::size_t>(e0 + l)]);
      if (!erosion_.update_failed(e0 + l, chunk, fails, internal, 0.5 * f.hg[l], dt, internal_prev, 0.5 * f.hg_prev[l]))
        continue;
      for (int k = 0; k < 8; ++k) f.fx[k][l] = f.fy[k][l] = f.fz[k][l] = 0.0;
      f.hg[l] = f.all[l] = f.fsum[l] = st.visc[l] = st.damp[l] = 0.0;  // the first halves stay booked
      st.len[l] = std::numeric_limits<Real>::infinity();
    }
  }

  /// F^-1 = dX/dx = sum_I X_I (x) B_I, exact for linear fields.
  static Tensor3<Lanes> inverse_deformation_gradient(const Batch& bt) {
    Tensor3<Lanes> finv;
    for (auto& row : finv)
      for (Lanes& v : row) v = Lanes::Zero();
    for (int k = 0; k < 8; ++k) {
      finv[0][0] += bt.x0[k] * bt.bx[k];
      finv[0][1] += bt.x0[k] * bt.by[k];
      finv[0][2] += bt.x0[k] * bt.bz[k];
      finv[1][0] += bt.y0[k] * bt.bx[k];
      finv[1][1] += bt.y0[k] * bt.by[k];
      finv[1][2] += bt.y0[k] * bt.bz[k];
      finv[2][0] += bt.z0[k] * bt.bx[k];
      finv[2][1] += bt.z0[k] * bt.by[k];
      finv[2][2] += bt.z0[k] * bt.bz[k];
    }
    return finv;
  }

  /// The law's stress (its state advanced over dt_law), bulk viscosity in compression only
  /// (tr D < 0) and, when damped, the stiffness-damping stress.
  template <bool damped>
  BatchStress batch_stress(const Batch& bt, Index e0, Real dt_law, const KernelConstants& kc) {
    const Tensor3<Lanes> d = hex8::rate_of_deformation(bt.vx, bt.vy, bt.vz, bt.bx, bt.by, bt.bz);
    BatchStress st;
    if constexpr (kStateSpeed)  // an EOS reads the element's volume ratio
      st.sigma = mat_.update_volume(state_[e0 / kLanes], Lanes(bt.vol / Lanes::Map(volume0_.data() + e0)), d, dt_law);
    else
      st.sigma = mat_.update(state_[e0 / kLanes], inverse(inverse_deformation_gradient(bt)), d, dt_law);
    if (needs_stress_) st.law = st.sigma;  // the law's stress, for *MAT_ADD_EROSION's thresholds
    Lanes trd = Lanes::Zero();
    for (int k = 0; k < 8; ++k) trd += bt.vx[k] * bt.bx[k] + bt.vy[k] * bt.by[k] + bt.vz[k] * bt.bz[k];
    st.len = bt.vol / hex8::max_face_area(bt.x, bt.y, bt.z);
    const Lanes& len = st.len;
    const Lanes vol0 = Lanes::Map(volume0_.data() + e0);
    const LaneMask compressing = trd < 0.0;
    const Lanes rho = kc.rho0 * vol0 * bt.inv_vol;
    Lanes q;
    if constexpr (kStateSpeed) {  // the elements' own sound speeds (state_speed.hpp)
      q = state_speed::bulk_viscosity(state_[e0 / kLanes], mat_.viscosity(), bulk_, rho, len, trd, compressing, bt.vol / vol0, dt_law, st.qdt, st.c);
    } else {
      q = compressing.select(rho * len * (bulk_.quadratic * len * trd * trd - bulk_.linear * kc.c * trd), 0.0);
      st.qdt = compressing.select(bulk_.linear * kc.c + bulk_.quadratic * len * (-trd), 0.0);
    }
    for (int i = 0; i < 3; ++i) st.sigma[i][i] -= q;
    st.visc = -q * trd * bt.vol;
    Lanes& qv_prev = visc_prev_[static_cast<std::size_t>(e0 / kLanes)];
    st.visc_prev = -qv_prev * trd;
    qv_prev = q * bt.vol;
    st.damp = st.damp_prev = Lanes::Zero();
    if constexpr (damped) add_damping(st, d, trd, bt.vol, kc, damp_prev_.data() + 6 * static_cast<std::size_t>(e0 / kLanes));
    return st;
  }

  /// Rayleigh stiffness damping: sigma_d = beta (lambda tr(D) I + 2 mu D), its power, and the
  /// step of a damped element: (2 / w)(sqrt(1 + xi^2) - xi) with w = 2 c / len and xi = beta w / 2
  /// adds beta c^2 / len to the bulk-viscosity term.
  /// `prev`: the element's damping stress times volume of the last evaluation (xx, yy, zz, xy, yz,
  /// xz), whose power at this step's rates is st.damp_prev; replaced by this evaluation's.
  static void add_damping(BatchStress& st, const Tensor3<Lanes>& d, const Lanes& trd, const Lanes& vol,
                          const KernelConstants& kc, Lanes* prev) {
    const Lanes &dxx = d[0][0], &dyy = d[1][1], &dzz = d[2][2];
    const Lanes &dxy = d[0][1], &dyz = d[1][2], &dxz = d[0][2];
    const Lanes lt = kc.beta_lambda * trd;
    const Lanes sxx = lt + kc.beta_2mu * dxx, syy = lt + kc.beta_2mu * dyy, szz = lt + kc.beta_2mu * dzz;
    const Lanes sxy = kc.beta_2mu * dxy, syz = kc.beta_2mu * dyz, sxz = kc.beta_2mu * dxz;
    Tensor3<Lanes>& sigma = st.sigma;
    sigma[0][0] += sxx;
    sigma[1][1] += syy;
    sigma[2][2] += szz;
    sigma[0][1] += sxy;
    sigma[1][0] += sxy;
    sigma[1][2] += syz;
    sigma[2][1] += syz;
    sigma[0][2] += sxz;
    sigma[2][0] += sxz;
    st.damp = vol * (sxx * dxx + syy * dyy + szz * dzz + 2.0 * (sxy * dxy + syz * dyz + sxz * dxz));
    st.damp_prev = prev[0] * dxx + prev[1] * dyy + prev[2] * dzz + 2.0 * (prev[3] * dxy + prev[4] * dyz + prev[5] * dxz);
    prev[0] = vol * sxx;
    prev[1] = vol * syy;
    prev[2] = vol * szz;
    prev[3] = vol * sxy;
    prev[4] = vol * syz;
    prev[5] = vol * sxz;
    st.qdt += kc.beta_c2 / st.len;
  }

  /// Stress divergence f_I = -V sigma B_I (residual form) plus the hourglass forces
  /// f = -k sum_a gamma_a (gamma_a . w), w the velocities (viscous) or the total displacements
  /// (physical stiffness); the incremental stiffness forms (IHQ 4, 5, 6) in
  /// hex8::stiffness_hourglass_forces.
  template <bool viscous>
  BatchForces batch_forces(const Batch& bt, const Tensor3<Lanes>& sigma, Index e0, Real dt,
                           const KernelConstants& kc) {
    BatchForces f;
    for (int k = 0; k < 8; ++k) {
      f.fx[k] = -bt.vol * (bt.bx[k] * sigma[0][0] + bt.by[k] * sigma[0][1] + bt.bz[k] * sigma[0][2]);
      f.fy[k] = -bt.vol * (bt.bx[k] * sigma[1][0] + bt.by[k] * sigma[1][1] + bt.bz[k] * sigma[1][2]);
      f.fz[k] = -bt.vol * (bt.bx[k] * sigma[2][0] + bt.by[k] * sigma[2][1] + bt.bz[k] * sigma[2][2]);
    }
    hex8::NodeLanes hx, hy, hz;
    Lanes k_hg;
    Lanes* const q_prev = hg_force_.data() + 12 * static_cast<std::size_t>(e0 / kLanes);
    if constexpr (viscous) {
      hex8::ModeVectors rates;  // gamma_a . v
      hex8::hourglass_resistance(bt.x, bt.y, bt.z, bt.bx, bt.by, bt.bz, bt.vx, bt.vy, bt.vz, hx, hy, hz, &rates);
      const Lanes v23 = (bt.vol * bt.vol).unaryExpr([](Real v) { return std::cbrt(v); });
      const Lanes vol0 = Lanes::Map(volume0_.data() + e0);
      k_hg = hg_.coefficient * kc.rho0 * vol0 * bt.inv_vol * kc.c * v23 / 4.0;
      f.hg_prev = exchange_generalised_forces(q_prev, k_hg, rates, rates);
    } else if (hg_.kind != HexHourglass::Kind::physical_stiffness) {
      hex8::stiffness_hourglass_forces(hg_.kind == HexHourglass::Kind::assumed_strain, bt.x, bt.y, bt.z, bt.bx,
                                       bt.by, bt.bz, bt.vx, bt.vy, bt.vz, bt.vol, dt,
                                       hg_.coefficient * kc.rho0 * kc.c * kc.c / 72.0, kc.e_mod, kc.mu,
                                       hg_.coefficient, q_prev, hx, hy, hz, f.hg_prev);
      k_hg = Lanes::Constant(-1.0);  // hx, hy, hz are already the forces
    } else {
      hex8::NodeLanes ux, uy, uz;
      for (int k = 0; k < 8; ++k) {
        ux[k] = bt.x[k] - bt.x0[k];
        uy[k] = bt.y[k] - bt.y0[k];
        uz[k] = bt.z[k] - bt.z0[k];
      }
      hex8::ModeVectors disp;  // gamma_a . u
      hex8::hourglass_resistance(bt.x, bt.y, bt.z, bt.bx, bt.by, bt.bz, ux, uy, uz, hx, hy, hz, &disp);
      Lanes b2 = Lanes::Zero();
      for (int k = 0; k < 8; ++k) b2 += bt.bx[k] * bt.bx[k] + bt.by[k] * bt.by[k] + bt.bz[k] * bt.bz[k];
      k_hg = hg_.coefficient * kc.e_mod * bt.vol * b2 / 72.0;
      hex8::ModeShapes gam;
      hex8::hourglass_shapes(bt.x, bt.y, bt.z, bt.bx, bt.by, bt.bz, gam);
      f.hg_prev = exchange_generalised_forces(q_prev, k_hg, disp, hex8::hourglass_project(gam, bt.vx, bt.vy, bt.vz));
    }
    f.hg = Lanes::Zero();
    f.fsum = Lanes::Zero();
    f.all = Lanes::Zero();
    for (int k = 0; k < 8; ++k) {
      hx[k] *= -k_hg;
      hy[k] *= -k_hg;
      hz[k] *= -k_hg;
      f.hg -= hx[k] * bt.vx[k] + hy[k] * bt.vy[k] + hz[k] * bt.vz[k];
      f.fx[k] += hx[k];
      f.fy[k] += hy[k];
      f.fz[k] += hz[k];
      f.fsum += f.fx[k] + f.fy[k] + f.fz[k];
      f.all -= f.fx[k] * bt.vx[k] + f.fy[k] * bt.vy[k] + f.fz[k] * bt.vz[k];
    }
    return f;
  }

  /// The power of the stored generalised hourglass forces `q` (12, mode-major) at the rates
  /// `rates`, sum_a Q_a . qdot_a; then stores this evaluation's, Q_a = k w_a (the forces are
  /// -k sum_a gamma_a w_a: w the rates, viscous, or the displacements, IHQ 10).
  static Lanes exchange_generalised_forces(Lanes* q, const Lanes& k, const hex8::ModeVectors& w,
                                           const hex8::ModeVectors& rates) {
    Lanes p = Lanes::Zero();
    for (int a = 0; a < 4; ++a)
      for (int i = 0; i < 3; ++i) {
        p += q[3 * a + i] * rates[a][i];
        q[3 * a + i] = k * w[a][i];
      }
    return p;
  }

  /// Adds a batch's step (times `step_factor`, per element, when the masses are scaled; before it
  /// into `raw_steps`, when not null, for mass scaling every cycle), powers and
  /// failure to the chunk's sums; the spare lanes of a last partial batch (lanes valid..kLanes-1)
  /// count for nothing.
  template <bool damped>
  static void accumulate(ChunkSums& s, const Batch& bt, BatchStress& st, BatchForces& f, Index e0,
                         int valid, Real c, const Real* step_factor, Real* raw_steps) {
    Lanes dt;
    if constexpr (kStateSpeed) dt = st.len / (st.qdt + lane_sqrt(st.qdt * st.qdt + st.c * st.c));
    else dt = st.len / (st.qdt + lane_sqrt(st.qdt * st.qdt + c * c));
    if (raw_steps) Lanes::Map(raw_steps + e0) = dt;  // mass scaling every cycle (enable_mass_rescaling)
    if (step_factor) dt *= Lanes::Map(step_factor + e0);  // mass scaling (scale_element_masses)
    const LaneMask failed = !(bt.vol > 0.0) || !f.fsum.isFinite();
    if (valid < kLanes) {
      for (int l = valid; l < kLanes; ++l) {
        f.hg[l] = st.visc[l] = st.damp[l] = f.all[l] = 0.0;
        f.hg_prev[l] = st.visc_prev[l] = st.damp_prev[l] = 0.0;
        dt[l] = std::numeric_limits<Real>::max();
      }
    }
    if (s.bad < 0 && failed.head(valid).any())
      for (int l = 0; l < valid; ++l)
        if (failed[l]) {
          s.bad = e0 + l;
          break;
        }
    // The hourglass, bulk-viscosity and damping works are trapezoidal over the step that ends
    // here, as the ledger's nodal works are (docs/solver.md, "Energy"): the mean of the power of
    // the last evaluation's forces and of this one's, both at this step's rates.
    s.p_hg += 0.5 * (f.hg_prev + f.hg);
    s.p_visc += 0.5 * (st.visc_prev + st.visc);
    s.p_all += f.all;
    if constexpr (damped) s.p_damp += 0.5 * (st.damp_prev + st.damp);
    s.dtarg = (dt < s.dtmin).select(kLaneOffsets + static_cast<Real>(e0), s.dtarg);
    s.dtmin = s.dtmin.min(dt);
  }

  /// Writes a batch's forces into its elements' corner slots (`out`: x, y, z slot arrays).
  static void store_forces(const BatchForces& f, Index e0, int valid, const std::array<Real*, 3>& out) {
    const std::size_t s0 = 8 * static_cast<std::size_t>(e0);
    if (valid == kLanes) {
      store_transposed(f.fx, out[0] + s0);
      store_transposed(f.fy, out[1] + s0);
      store_transposed(f.fz, out[2] + s0);
      return;
    }
    for (int l = 0; l < valid; ++l)
      for (int k = 0; k < 8; ++k) {
        out[0][s0 + 8 * l + k] = f.fx[k][l];
        out[1][s0 + 8 * l + k] = f.fy[k][l];
        out[2][s0 + 8 * l + k] = f.fz[k][l];
      }
  }

  static Index padded(Index n) { return (n + kLanes - 1) / kLanes * kLanes; }

  hex8::NodeMat gather(const Vec3Field& f, Index e) const {
    return gather_rows<8>(f, conn_.data() + 8 * static_cast<std::size_t>(e));
  }

  Id part_id_;
  Material mat_;
  HexHourglass hg_;
  BulkViscosity bulk_;
  StiffnessDamping damping_;
  std::vector<Index> conn_;
  std::vector<Id> ids_;
  std::vector<Index> conn_lanes_;  ///< connectivity by batch, node and lane (see the constructor)
  std::vector<Real> volume0_;      ///< padded to whole batches
  std::vector<Real> step_factor_;  ///< sqrt of the mass-scaling factor, padded; empty: no scaling
  ElementMassScaling rescaling_;   ///< MS1ST = 0: the steps before the factors (inactive otherwise)
  std::vector<State> state_;       ///< the law's state, one per batch
  /// Generalised hourglass forces, 12 per batch: IHQ 4-6 the forces themselves (corotational
  /// frame), the other forms the last evaluation's (global frame), for the trapezoidal work.
  std::vector<Lanes> hg_force_;
  std::vector<Lanes> visc_prev_;   ///< per batch, the last evaluation's bulk-viscosity q V
  std::vector<Lanes> damp_prev_;   ///< damped: 6 per batch, the last evaluation's damping stress x V
  std::vector<Real> chunk_dt_, chunk_hg_, chunk_visc_, chunk_damp_, chunk_power_;
  std::vector<Index> chunk_dt_element_;  ///< per chunk, the element with the smallest step
  std::vector<Index> chunk_bad_;
  ElementErosion erosion_;  ///< inactive unless enable_erosion
  bool needs_stress_ = false;  ///< an erosion criterion reads the law's stress (BatchStress::law)
  inline static const Lanes kLaneOffsets = Lanes::LinSpaced(kLanes, 0.0, kLanes - 1.0);

 public:
  Id smallest_step_element() const override {
    return ids_.empty() ? Id{-1} : ids_[static_cast<std::size_t>(chunk_dt_element_[argmin_chunk(chunk_dt_)])];
  }
};

}  // namespace slideline
