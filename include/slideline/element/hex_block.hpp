#pragma once
/// A block of one-point hexahedra of one part and one material.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "slideline/core/error.hpp"
#include "slideline/core/parallel.hpp"
#include "slideline/element/element_block.hpp"
#include "slideline/element/hex8.hpp"

namespace slideline {

/// Hourglass control of a hexahedron block.
struct HexHourglass {
  enum class Kind : std::uint8_t {
    viscous,            ///< Flanagan-Belytschko viscous (LS-DYNA/DYNA3D types 1-3)
    physical_stiffness  ///< total-displacement stiffness scaled to the element's bending stiffness (type 10)
  };
  Kind kind = Kind::viscous;
  Real coefficient = 0.1;
};

/// Linear and quadratic bulk viscosity coefficients.
struct BulkViscosity {
  Real quadratic = 1.5;
  Real linear = 0.06;
};

/// Hexahedra with material law `Material` (MooneyRivlin, ElasticSolid): a class with
/// density(), wave_speed(), youngs_modulus() and cauchy_stress(F).
template <class Material>
class HexBlock final : public ElementBlock {
 public:
  HexBlock(Id part_id, Material material, HexHourglass hourglass, BulkViscosity bulk,
           std::vector<Index> connectivity, std::vector<Id> element_ids)
      : part_id_(part_id),
        mat_(std::move(material)),
        hg_(hourglass),
        bulk_(bulk),
        conn_(std::move(connectivity)),
        ids_(std::move(element_ids)) {
    const Index ne = element_count();
    chunk_dt_.assign(chunk_count(ne), 0.0);
    chunk_hg_.assign(chunk_count(ne), 0.0);
    chunk_visc_.assign(chunk_count(ne), 0.0);
    chunk_bad_.assign(chunk_count(ne), -1);
    volume0_.assign(ne, 0.0);
  }

  std::string kind() const override { return "hex8"; }
  Id part_id() const override { return part_id_; }
  Index element_count() const override { return static_cast<Index>(ids_.size()); }
  int nodes_per_element() const override { return 8; }
  std::span<const Index> connectivity() const override { return conn_; }
  Id element_id(Index e) const override { return ids_[e]; }
  const Material& material() const { return mat_; }

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
      const Real m = mat_.density() * v0 / 8.0;
      for (int k = 0; k < 8; ++k) nodes.mass[conn_[8 * e + k]] += m;
    }
  }

  Real compute_forces(const NodalFields& nodes, Real /*dt*/, CornerBuffer& corners,
                      BlockEnergy& energy) override {
    const Index ne = element_count();
    const Real c = mat_.wave_speed();
    const Real rho0 = mat_.density();
    const Real e_mod = mat_.youngs_modulus();
    const Index base = force_slot_base();
    const Index* conn = conn_.data();
    parallel_for_chunks(ne, [&](Index b, Index end, Index chunk) {
      using hex8::Col8;
      Real dtmin = std::numeric_limits<Real>::max();
      Real p_hg = 0.0, p_visc = 0.0;
      Index bad = -1;
      for (Index e = b; e < end; ++e) {
        const Index* n = conn + 8 * static_cast<std::size_t>(e);
        Col8 x, y, z, vx, vy, vz, x0, y0, z0;
        for (int k = 0; k < 8; ++k) {
          const Index i = n[k];
          x[k] = nodes.x.x[i];
          y[k] = nodes.x.y[i];
          z[k] = nodes.x.z[i];
          vx[k] = nodes.v.x[i];
          vy[k] = nodes.v.y[i];
          vz[k] = nodes.v.z[i];
          x0[k] = nodes.x0.x[i];
          y0[k] = nodes.x0.y[i];
          z0[k] = nodes.x0.z[i];
        }
        Col8 bx, by, bz;
        hex8::volume_gradient(x, y, z, bx, by, bz);
        const Real vol = (x * bx + y * by + z * bz).sum() / 3.0;
        if (!(vol > 0.0)) {
          if (bad < 0) bad = e;
          continue;
        }
        const Real inv_vol = 1.0 / vol;
        bx *= inv_vol;
        by *= inv_vol;
        bz *= inv_vol;
        // dX/dx = sum_I X_I (x) B_I, exact for linear fields; F is its inverse.
        Mat3 finv;
        finv << (x0 * bx).sum(), (x0 * by).sum(), (x0 * bz).sum(),  //
            (y0 * bx).sum(), (y0 * by).sum(), (y0 * bz).sum(),      //
            (z0 * bx).sum(), (z0 * by).sum(), (z0 * bz).sum();
        const Mat3 F = finv.inverse();
        Mat3 sigma = mat_.cauchy_stress(F);
        const Real trd = (vx * bx + vy * by + vz * bz).sum();
        const Real len = vol / hex8::max_face_area(x, y, z);
        Real qdt = 0.0;
        if (trd < 0.0) {
          const Real rho = rho0 * volume0_[e] * inv_vol;
          const Real q = rho * len * (bulk_.quadratic * len * trd * trd - bulk_.linear * c * trd);
          sigma.diagonal().array() -= q;
          p_visc += -q * trd * vol;
          qdt = bulk_.linear * c + bulk_.quadratic * len * (-trd);
        }
        // Stress divergence: f_I = -V sigma B_I (residual form).
        Col8 fx = -vol * (bx * sigma(0, 0) + by * sigma(0, 1) + bz * sigma(0, 2));
        Col8 fy = -vol * (bx * sigma(1, 0) + by * sigma(1, 1) + bz * sigma(1, 2));
        Col8 fz = -vol * (bx * sigma(2, 0) + by * sigma(2, 1) + bz * sigma(2, 2));
        // Hourglass: gamma_a = Gamma_a - (Gamma_a . x) B, then f = -k sum_a gamma_a (gamma_a . w)
        // with w the velocities (viscous) or the total displacements (physical stiffness).
        const bool viscous = hg_.kind == HexHourglass::Kind::viscous;
        const Col8 wx = viscous ? vx : Col8(x - x0);
        const Col8 wy = viscous ? vy : Col8(y - y0);
        const Col8 wz = viscous ? vz : Col8(z - z0);
        Col8 hx = Col8::Zero(), hy = Col8::Zero(), hz = Col8::Zero();
        for (int a = 0; a < 4; ++a) {
          const Col8 g = hex8::hourglass_base().row(a).transpose().array();
          const Col8 gam = g - ((g * x).sum() * bx + (g * y).sum() * by + (g * z).sum() * bz);
          hx += gam * (gam * wx).sum();
          hy += gam * (gam * wy).sum();
          hz += gam * (gam * wz).sum();
        }
        const Real k = viscous ? hg_.coefficient * rho0 * volume0_[e] * inv_vol * c *
                                     std::cbrt(vol * vol) / 4.0
                               : hg_.coefficient * e_mod * vol *
                                     (bx.square() + by.square() + bz.square()).sum() / 72.0;
        hx *= -k;
        hy *= -k;
        hz *= -k;
        p_hg += -(hx * vx + hy * vy + hz * vz).sum();
        fx += hx;
        fy += hy;
        fz += hz;
        if (!std::isfinite(fx.sum() + fy.sum() + fz.sum()) && bad < 0) bad = e;
        dtmin = std::min(dtmin, len / (qdt + std::sqrt(qdt * qdt + c * c)));
        const Index s0 = base + 8 * e;
        for (int kk = 0; kk < 8; ++kk) {
          corners.force.x[s0 + kk] = fx[kk];
          corners.force.y[s0 + kk] = fy[kk];
          corners.force.z[s0 + kk] = fz[kk];
        }
      }
      chunk_dt_[chunk] = dtmin;
      chunk_hg_[chunk] = p_hg;
      chunk_visc_[chunk] = p_visc;
      chunk_bad_[chunk] = bad;
    });
    for (Index bad : chunk_bad_)
      if (bad >= 0)
        throw InstabilityError("solid element " + std::to_string(ids_[bad]) + " of part " +
                                   std::to_string(part_id_) +
                                   " inverted (non-positive volume or non-finite force)",
                               0.0, 0);
    energy.hourglass_power += ordered_sum(chunk_hg_, 0.0);
    energy.viscous_power += ordered_sum(chunk_visc_, 0.0);
    Real dtmin = std::numeric_limits<Real>::max();
    for (Real d : chunk_dt_) dtmin = std::min(dtmin, d);
    return dtmin;
  }

 private:
  hex8::NodeMat gather(const Vec3Field& f, Index e) const {
    hex8::NodeMat m;
    const Index* n = conn_.data() + 8 * static_cast<std::size_t>(e);
    for (int k = 0; k < 8; ++k) {
      m(k, 0) = f.x[n[k]];
      m(k, 1) = f.y[n[k]];
      m(k, 2) = f.z[n[k]];
    }
    return m;
  }

  Id part_id_;
  Material mat_;
  HexHourglass hg_;
  BulkViscosity bulk_;
  std::vector<Index> conn_;
  std::vector<Id> ids_;
  std::vector<Real> volume0_;
  std::vector<Real> chunk_dt_, chunk_hg_, chunk_visc_;
  std::vector<Index> chunk_bad_;
};

}  // namespace slideline
