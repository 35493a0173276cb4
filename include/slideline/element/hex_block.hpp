#pragma once
/// A block of one-point hexahedra of one part and one material.
#include <algorithm>
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
#include "slideline/element/hex8.hpp"
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
  Id part_id() const override { return part_id_; }
  Index element_count() const override { return static_cast<Index>(ids_.size()); }
  int nodes_per_element() const override { return 8; }
  std::span<const Index> connectivity() const override { return conn_; }
  Id element_id(Index e) const override { return ids_[e]; }
  const Material& material() const { return mat_; }
  /// The law's small-strain bulk modulus (force/length^2).
  Real bulk_modulus() const override { return mat_.bulk_modulus(); }
  /// The law's state of every element, by batch (see the class comment).
  std::span<const State> states() const { return state_; }
  const StiffnessDamping& stiffness_damping() const { return damping_; }

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
    const Index ne = element_count();
    const Real c = mat_.wave_speed();
    const Real rho0 = mat_.density();
    const Real e_mod = mat_.youngs_modulus();
    [[maybe_unused]] const Real beta_lambda = damping_.beta * mat_.lame_lambda();
    [[maybe_unused]] const Real beta_2mu = 2.0 * damping_.beta * mat_.shear_modulus();
    [[maybe_unused]] const Real beta_c2 = damping_.beta * c * c;
    Real* fx_out = corners.force.x.data() + force_slot_base();
    Real* fy_out = corners.force.y.data() + force_slot_base();
    Real* fz_out = corners.force.z.data() + force_slot_base();
    parallel_for_chunks(ne, [&](Index b, Index end, Index chunk) {
      using hex8::NodeLanes;
      Lanes dtmin = Lanes::Constant(std::numeric_limits<Real>::max());
      Lanes dtarg = Lanes::Zero();  // per lane, the element (as a Real) with the smallest step so far
      Lanes p_hg = Lanes::Zero(), p_visc = Lanes::Zero(), p_damp = Lanes::Zero(), p_all = Lanes::Zero();
      Index bad = -1;
      for (Index e0 = b; e0 < end; e0 += kLanes) {
        const int valid = static_cast<int>(std::min<Index>(kLanes, end - e0));
        const Index* idx = conn_lanes_.data() + 8 * static_cast<std::size_t>(e0);
        NodeLanes x, y, z, vx, vy, vz, x0, y0, z0;
        for (int k = 0; k < 8; ++k) {
          const Index* ik = idx + kLanes * k;
          x[k] = gather_lanes(nodes.x.x.data(), ik);
          y[k] = gather_lanes(nodes.x.y.data(), ik);
          z[k] = gather_lanes(nodes.x.z.data(), ik);
          vx[k] = gather_lanes(nodes.v.x.data(), ik);
          vy[k] = gather_lanes(nodes.v.y.data(), ik);
          vz[k] = gather_lanes(nodes.v.z.data(), ik);
          x0[k] = gather_lanes(nodes.x0.x.data(), ik);
          y0[k] = gather_lanes(nodes.x0.y.data(), ik);
          z0[k] = gather_lanes(nodes.x0.z.data(), ik);
        }
        NodeLanes bx, by, bz;
        hex8::volume_gradient(x, y, z, bx, by, bz);
        Lanes vol = Lanes::Zero();
        for (int k = 0; k < 8; ++k) vol += x[k] * bx[k] + y[k] * by[k] + z[k] * bz[k];
        vol /= 3.0;
        const Lanes inv_vol = 1.0 / vol;
        for (int k = 0; k < 8; ++k) {
          bx[k] *= inv_vol;
          by[k] *= inv_vol;
          bz[k] *= inv_vol;
        }
        // dX/dx = sum_I X_I (x) B_I, exact for linear fields; F is its inverse.
        Tensor3<Lanes> finv;
        for (auto& row : finv)
          for (Lanes& v : row) v = Lanes::Zero();
        for (int k = 0; k < 8; ++k) {
          finv[0][0] += x0[k] * bx[k];
          finv[0][1] += x0[k] * by[k];
          finv[0][2] += x0[k] * bz[k];
          finv[1][0] += y0[k] * bx[k];
          finv[1][1] += y0[k] * by[k];
          finv[1][2] += y0[k] * bz[k];
          finv[2][0] += z0[k] * bx[k];
          finv[2][1] += z0[k] * by[k];
          finv[2][2] += z0[k] * bz[k];
        }
        const Tensor3<Lanes> d = rate_of_deformation(vx, vy, vz, bx, by, bz);
        Tensor3<Lanes> sigma = mat_.update(state_[e0 / kLanes], inverse(finv), d, dt_law);
        Lanes trd = Lanes::Zero();
        for (int k = 0; k < 8; ++k) trd += vx[k] * bx[k] + vy[k] * by[k] + vz[k] * bz[k];
        const Lanes len = vol / hex8::max_face_area(x, y, z);
        const Lanes vol0 = Lanes::Map(volume0_.data() + e0);
        // Bulk viscosity in compression only (tr D < 0).
        const LaneMask compressing = trd < 0.0;
        const Lanes rho = rho0 * vol0 * inv_vol;
        const Lanes q = compressing.select(
            rho * len * (bulk_.quadratic * len * trd * trd - bulk_.linear * c * trd), 0.0);
        for (int i = 0; i < 3; ++i) sigma[i][i] -= q;
        Lanes visc = -q * trd * vol;
        Lanes qdt = compressing.select(bulk_.linear * c + bulk_.quadratic * len * (-trd), 0.0);
        Lanes damp = Lanes::Zero();
        if constexpr (damped) {
          // Rayleigh stiffness damping: sigma_d = beta (lambda tr(D) I + 2 mu D).
          const Lanes &dxx = d[0][0], &dyy = d[1][1], &dzz = d[2][2];
          const Lanes &dxy = d[0][1], &dyz = d[1][2], &dxz = d[0][2];
          const Lanes lt = beta_lambda * trd;
          const Lanes sxx = lt + beta_2mu * dxx, syy = lt + beta_2mu * dyy, szz = lt + beta_2mu * dzz;
          const Lanes sxy = beta_2mu * dxy, syz = beta_2mu * dyz, sxz = beta_2mu * dxz;
          sigma[0][0] += sxx;
          sigma[1][1] += syy;
          sigma[2][2] += szz;
          sigma[0][1] += sxy;
          sigma[1][0] += sxy;
          sigma[1][2] += syz;
          sigma[2][1] += syz;
          sigma[0][2] += sxz;
          sigma[2][0] += sxz;
          damp = vol * (sxx * dxx + syy * dyy + szz * dzz + 2.0 * (sxy * dxy + syz * dyz + sxz * dxz));
          // The step of a damped element: (2 / w)(sqrt(1 + xi^2) - xi) with w = 2 c / len and
          // xi = beta w / 2 adds beta c^2 / len to the bulk-viscosity term.
          qdt += beta_c2 / len;
        }
        // Stress divergence: f_I = -V sigma B_I (residual form).
        NodeLanes fx, fy, fz;
        for (int k = 0; k < 8; ++k) {
          fx[k] = -vol * (bx[k] * sigma[0][0] + by[k] * sigma[0][1] + bz[k] * sigma[0][2]);
          fy[k] = -vol * (bx[k] * sigma[1][0] + by[k] * sigma[1][1] + bz[k] * sigma[1][2]);
          fz[k] = -vol * (bx[k] * sigma[2][0] + by[k] * sigma[2][1] + bz[k] * sigma[2][2]);
        }
        // Hourglass: f = -k sum_a gamma_a (gamma_a . w) with w the velocities (viscous) or the
        // total displacements (physical stiffness).
        NodeLanes hx, hy, hz;
        Lanes k_hg;
        if constexpr (viscous) {
          hex8::hourglass_resistance(x, y, z, bx, by, bz, vx, vy, vz, hx, hy, hz);
          const Lanes v23 = (vol * vol).unaryExpr([](Real v) { return std::cbrt(v); });
          k_hg = hg_.coefficient * rho0 * vol0 * inv_vol * c * v23 / 4.0;
        } else {
          NodeLanes ux, uy, uz;
          for (int k = 0; k < 8; ++k) {
            ux[k] = x[k] - x0[k];
            uy[k] = y[k] - y0[k];
            uz[k] = z[k] - z0[k];
          }
          hex8::hourglass_resistance(x, y, z, bx, by, bz, ux, uy, uz, hx, hy, hz);
          Lanes b2 = Lanes::Zero();
          for (int k = 0; k < 8; ++k) b2 += bx[k] * bx[k] + by[k] * by[k] + bz[k] * bz[k];
          k_hg = hg_.coefficient * e_mod * vol * b2 / 72.0;
        }
        Lanes hg = Lanes::Zero(), fsum = Lanes::Zero(), all = Lanes::Zero();
        for (int k = 0; k < 8; ++k) {
          hx[k] *= -k_hg;
          hy[k] *= -k_hg;
          hz[k] *= -k_hg;
          hg -= hx[k] * vx[k] + hy[k] * vy[k] + hz[k] * vz[k];
          fx[k] += hx[k];
          fy[k] += hy[k];
          fz[k] += hz[k];
          fsum += fx[k] + fy[k] + fz[k];
          all -= fx[k] * vx[k] + fy[k] * vy[k] + fz[k] * vz[k];
        }
        Lanes dt = len / (qdt + lane_sqrt(qdt * qdt + c * c));
        const LaneMask failed = !(vol > 0.0) || !fsum.isFinite();
        if (valid < kLanes) {  // the spare lanes of a last partial batch
          for (int l = valid; l < kLanes; ++l) {
            hg[l] = visc[l] = damp[l] = all[l] = 0.0;
            dt[l] = std::numeric_limits<Real>::max();
          }
        }
        if (bad < 0 && failed.head(valid).any())
          for (int l = 0; l < valid; ++l)
            if (failed[l]) {
              bad = e0 + l;
              break;
            }
        p_hg += hg;
        p_visc += visc;
        p_all += all;
        if constexpr (damped) p_damp += damp;
        dtarg = (dt < dtmin).select(kLaneOffsets + static_cast<Real>(e0), dtarg);
        dtmin = dtmin.min(dt);
        const std::size_t s0 = 8 * static_cast<std::size_t>(e0);
        if (valid == kLanes) {
          store_transposed(fx, fx_out + s0);
          store_transposed(fy, fy_out + s0);
          store_transposed(fz, fz_out + s0);
        } else {
          for (int l = 0; l < valid; ++l)
            for (int k = 0; k < 8; ++k) {
              fx_out[s0 + 8 * l + k] = fx[k][l];
              fy_out[s0 + 8 * l + k] = fy[k][l];
              fz_out[s0 + 8 * l + k] = fz[k][l];
            }
        }
      }
      Index lane = 0;
      chunk_dt_[chunk] = dtmin.minCoeff(&lane);
      chunk_dt_element_[chunk] = static_cast<Index>(dtarg[lane]);
      chunk_hg_[chunk] = p_hg.sum();
      chunk_visc_[chunk] = p_visc.sum();
      chunk_damp_[chunk] = p_damp.sum();
      chunk_power_[chunk] = p_all.sum();
      chunk_bad_[chunk] = bad;
    });
  }

  /// D = sym(v (x) B) of a batch (1/time), from the nodal velocities and the gradient operator.
  static Tensor3<Lanes> rate_of_deformation(const hex8::NodeLanes& vx, const hex8::NodeLanes& vy,
                                            const hex8::NodeLanes& vz, const hex8::NodeLanes& bx,
                                            const hex8::NodeLanes& by, const hex8::NodeLanes& bz) {
    Lanes dxx = Lanes::Zero(), dyy = Lanes::Zero(), dzz = Lanes::Zero();
    Lanes lxy = Lanes::Zero(), lyx = Lanes::Zero(), lyz = Lanes::Zero();
    Lanes lzy = Lanes::Zero(), lxz = Lanes::Zero(), lzx = Lanes::Zero();
    for (int k = 0; k < 8; ++k) {
      dxx += vx[k] * bx[k];
      dyy += vy[k] * by[k];
      dzz += vz[k] * bz[k];
      lxy += vx[k] * by[k];
      lyx += vy[k] * bx[k];
      lyz += vy[k] * bz[k];
      lzy += vz[k] * by[k];
      lxz += vx[k] * bz[k];
      lzx += vz[k] * bx[k];
    }
    const Lanes dxy = 0.5 * (lxy + lyx), dyz = 0.5 * (lyz + lzy), dxz = 0.5 * (lxz + lzx);
    return {{{dxx, dxy, dxz}, {dxy, dyy, dyz}, {dxz, dyz, dzz}}};
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
  std::vector<State> state_;       ///< the law's state, one per batch
  std::vector<Real> chunk_dt_, chunk_hg_, chunk_visc_, chunk_damp_, chunk_power_;
  std::vector<Index> chunk_dt_element_;  ///< per chunk, the element with the smallest step
  std::vector<Index> chunk_bad_;
  inline static const Lanes kLaneOffsets = Lanes::LinSpaced(kLanes, 0.0, kLanes - 1.0);

 public:
  Id smallest_step_element() const override {
    return ids_.empty() ? Id{-1} : ids_[static_cast<std::size_t>(chunk_dt_element_[argmin_chunk(chunk_dt_)])];
  }
};

}  // namespace slideline
