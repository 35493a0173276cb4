#pragma once
/// A block of 4-node Belytschko-Tsay shells of one part, one plane-stress law and one section,
/// and of its 3-node C0 triangles (N3 = N4 in the deck; element/shell_c0tri.hpp), which LS-DYNA
/// runs in a form-2 part: the block holds its quadrilaterals, then its triangles.
///
/// The law (material/shell_material.hpp) works in the element's co-rotational frame: its state,
/// stored per element and through-thickness point, turns with the element (Belytschko, Lin & Tsay
/// 1984). See docs/shells_and_rigid.md for the options.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "slideline/core/error.hpp"
#include "slideline/core/parallel.hpp"
#include "slideline/element/element_block.hpp"
#include "slideline/element/shell_erosion.hpp"
#include "slideline/element/block_options.hpp"
#include "slideline/element/mass_scaling_once.hpp"
#include "slideline/element/shell_bt.hpp"
#include "slideline/element/shell_c0tri.hpp"
#include "slideline/element/shell_bulk_viscosity.hpp"
#include "slideline/element/shell_hourglass.hpp"
#include "slideline/element/shell_thickness.hpp"
#include "slideline/material/elastic_shell.hpp"
#include "slideline/material/shell_material.hpp"

namespace slideline {

/// Shells with the plane-stress law `Law`; ShellBlock is the elastic one.
template <PlaneStressMaterial Law>
class BasicShellBlock final : public ElementBlock {
 public:
  /// The law's state of one through-thickness point.
  using State = typename Law::State;

  /// `connectivity`: 4 internal node indices per element (counter-clockwise seen from the side
  /// the normal points to; a triangle repeats its third node, N3 = N4); `damping.beta` > 0 adds the stiffness-proportional damping stress
  /// beta (C : strain rate) with the law's plane-stress and transverse-shear moduli.
  BasicShellBlock(Id part_id, Law material, ShellSection section,
                  std::vector<Index> connectivity, std::vector<Id> element_ids,
                  StiffnessDamping damping = {})
      : part_id_(part_id),
        mat_(material),
        sec_(section),
        qhg_(section.hourglass_coefficient),
        bulk_(section.bulk),
        damping_(damping),
        rule_(shell_bt::ThicknessRule::make(section.nip, section.rule)),
        conn_(std::move(connectivity)),
        ids_(std::move(element_ids)) {
    if (const std::string why = mat_.problem(); !why.empty())
      throw InputError("shell part " + std::to_string(part_id_) + ": " + why);
    if (!(sec_.thickness > 0.0))
      throw InputError("shell part " + std::to_string(part_id_) + ": thickness must be positive");
    if (!(sec_.shear_factor > 0.0))
      throw InputError("shell part " + std::to_string(part_id_) + ": shear factor must be positive");
    if (!(damping_.beta >= 0.0))
      throw InputError("shell part " + std::to_string(part_id_) +
                       ": the stiffness damping coefficient beta must not be negative");
    if (conn_.size() != 4 * ids_.size())
      throw InputError("shell part " + std::to_string(part_id_) + ": connectivity needs 4 nodes per element");
    nq_ = shell_c0tri::triangles_last(conn_, ids_);
    tri_c_.assign(ids_.size() - static_cast<std::size_t>(nq_), 0.0);
    const Index ne = element_count();
    const Index nc = chunk_count(ne);
    chunk_dt_.assign(nc, 0.0);
    chunk_dt_element_.assign(nc, 0);
    chunk_hg_.assign(nc, 0.0);
    chunk_visc_.assign(nc, 0.0);
    chunk_damp_.assign(nc, 0.0);
    chunk_power_.assign(nc, 0.0);
    chunk_bad_.assign(nc, -1);
    area0_.assign(ne, 0.0);
    hg_q_.assign(5 * static_cast<std::size_t>(nq_), 0.0);
    visc_prev_.assign(static_cast<std::size_t>(ne), 0.0);
    state_.assign(static_cast<std::size_t>(ne) * rule_.n, State{});
  }

  std::string kind() const override { return "shell_bt"; }
  Id part_id() const override { return part_id_; }
  Index element_count() const override { return static_cast<Index>(ids_.size()); }
  BlockTopology topology() const override {
    return BlockTopology(quad4_topology, nq_, sec_.thickness).add(tri3_topology, element_count() - nq_, sec_.thickness);
  }
  /// Number of quadrilaterals: elements 0 .. nq - 1; the triangles follow.
  Index quad_count() const { return nq_; }
  std::span<const Index> connectivity() const override { return conn_; }
  Id element_id(Index e) const override { return ids_[e]; }
  Id smallest_step_element() const override {
    return ids_.empty() ? Id{-1} : ids_[static_cast<std::size_t>(chunk_dt_element_[argmin_chunk(chunk_dt_)])];
  }
  bool has_moments() const override { return true; }
  bool stiffness_hourglass() const override { return qhg_ > 0.0 && sec_.hourglass_stiffness; }
  const Law& material() const { return mat_; }
  const ShellSection& section() const { return sec_; }
  /// The law's 3-D bulk modulus (force/length^2).
  Real bulk_modulus() const override { return mat_.bulk_modulus(); }
  const StiffnessDamping& stiffness_damping() const { return damping_; }

  /// ElementBlock::enable_erosion: quadrilaterals (erode(); refusals: shell_erosion::check).
  void enable_erosion(const ErosionCriteria& criteria) override {
    shell_erosion::check<State>(criteria, part_id_, nq_, element_count(), rule_.n);
    erosion_.enable(criteria, element_count(), element_count());
    if (criteria.needs_strain()) strain_.assign(static_cast<std::size_t>(element_count()) * rule_.n, {});
  }
  /// ElementBlock::enable_thickness_update (*CONTROL_SHELL ISTUPD; docs/solver.md, "Shell thickness
  /// change"): each element's thickness t follows the thickness average of its points' normal
  /// strain increments (shell_thickness::PointStrains), t <- t exp(mean), and makes the next step's
  /// resultants, hourglass and bulk viscosity (the mass stays). Mode 4 needs a plastic law.
  void enable_thickness_update(int mode) override {
    const std::string part = "part " + std::to_string(part_id_);
    if constexpr (!requires(const State& s) { s.sigma; })
      throw NotImplementedError(part + ": its material carries no stress, so the normal strain of plane stress is not "
                                       "defined: *CONTROL_SHELL ISTUPD is not implemented on it");
    if (mode != 1 && mode != 4)
      throw NotImplementedError(part + ": *CONTROL_SHELL ISTUPD = " + std::to_string(mode) + " is not implemented");
    if (mode == 4 && !PlasticState<State>)
      throw NotImplementedError(part + ": *CONTROL_SHELL ISTUPD = 4 (elastic strains left out) acts on elastic-plastic "
                                       "materials; this part's is elastic");
    thick_.assign(static_cast<std::size_t>(element_count()), sec_.thickness);
    thickness_mode_ = mode;
  }
  std::span<const Real> current_thickness() const override { return thick_; }
  /// Element e's thickness (length): the section's, or its current one under ISTUPD.
  Real thickness(Index e) const { return thick_.empty() ? sec_.thickness : thick_[static_cast<std::size_t>(e)]; }
  /// Element e's strain at point ip (xx, yy, zz, xy, yz, xz, element frame), accumulated where a
  /// strain criterion of *MAT_ADD_EROSION is set (zero otherwise).
  std::array<Real, 6> point_strain(Index e, int ip) const {
    return strain_.empty() ? std::array<Real, 6>{} : strain_[static_cast<std::size_t>(e) * rule_.n + ip];
  }
  const ElementErosion* erosion() const override { return erosion_.active() ? &erosion_ : nullptr; }
  const shell_bt::ThicknessRule& thickness_rule() const { return rule_; }

  /// Nodal mass rho A t / 4 and rotary inertia (rho A t / 4) max(t^2, A) / 12 per corner.
  /// The A/12 term is LS-DYNA's scaling of shell rotary inertia: with t^2/12 alone the
  /// transverse-shear rotation modes of thin shells would be far stiffer than the membrane modes
  /// and would set the time step; with it the rotational step is not below the translational one.
  void initialize(NodalFields& nodes) override {
    const Index ne = element_count();
    const Real t = sec_.thickness;
    for (Index e = nq_; e < ne; ++e) initialize_triangle(nodes, e);  // rho A t / 3 per node
    for (Index e = 0; e < nq_; ++e) {
      const shell_bt::LocalGeometry g = shell_bt::local_geometry(gather(nodes.x0, e), sec_.invariant_frame);
      if (!(g.area > 0.0))
        throw InputError("shell element " + std::to_string(ids_[e]) + " of part " +
                         std::to_string(part_id_) + " has non-positive area " +
                         std::to_string(g.area) + " (check the node order)");
      area0_[e] = g.area;
      const Real m = mat_.density() * g.area * t / 4.0;
      const Real j = m * std::max(t * t, g.area) / 12.0;
      for (int k = 0; k < 4; ++k) {
        const Index n = conn_[4 * e + k];
        nodes.mass[n] += m;
        nodes.rot_inertia[n] += j;
        nodes.has_rotation[n] = 1;
      }
    }
  }

  /// ElementBlock::reference_steps: len / (q + sqrt(q^2 + c^2)) at the reference geometry, q the
  /// stiffness-damping term only (no bulk viscosity at rest); a triangle's len as its element loop
  /// takes it (the smaller of its membrane length and its bending / shear bound).
  void reference_steps(const NodalFields& nodes, std::span<Real> out) const override {
    const Real c = mat_.wave_speed();
    for (Index e = 0; e < element_count(); ++e) {
      const Real len = e < nq_ ? shell_bt::characteristic_length(gather(nodes.x0, e), area0_[e])
                               : triangle_step_length(shell_c0tri::local_geometry(gather_triangle(nodes.x0, e)), e);
      const Real q = damping_.beta * c * c / len;
      out[static_cast<std::size_t>(e)] = len / (q + std::sqrt(q * q + c * c));
    }
  }

  /// Element e's lumped share per corner (LS-DYNA's rule, as initialize() lumps it): mass rho A0 t /
  /// 4 (a triangle: / 3) and rotary inertia that mass x max(t^2, A0) / 12; with its corner slots.
  ElementMassScaling::CornerShare corner_share(Index e) const {
    const Real t = sec_.thickness;
    const bool quad = e < nq_;
    const Real m = mat_.density() * area0_[e] * t / (quad ? 4.0 : 3.0);
    return {m, m * std::max(t * t, area0_[e]) / 12.0, quad ? 4 * e : 4 * nq_ + 3 * (e - nq_), quad ? 4 : 3};
  }

  /// ElementBlock::scale_element_masses: element e's mass and rotary inertia per corner
  /// (corner_share) times factor[e]: the rotary inertia is scaled with the mass, as LS-DYNA's
  /// lumping keeps it proportional to the mass.
  Real scale_element_masses(std::span<const Real> factor, NodalFields& nodes) override {
    step_factor_.assign(element_count(), 1.0);
    return scale_corner_masses(element_count(), factor, conn_.data(), [&](Index e) { return corner_share(e); }, nodes,
                               step_factor_.data());
  }

  /// ElementBlock::enable_mass_rescaling: the element loop keeps its steps before the factors.
  void enable_mass_rescaling() override {
    rescaling_.enable(element_count(), element_count());
    step_factor_.assign(static_cast<std::size_t>(element_count()), 1.0);
  }
  /// ElementBlock::rescale_element_masses: each corner gets corner_share's mass and rotary inertia
  /// times (f_e - 1) (the moment slots are laid out as the force slots).
  RescaledBlock rescale_element_masses(Real dt2ms, bool at_reference, const NodalFields& nodes,
                                       std::span<Real> corner_added, std::span<Real> corner_inertia) override {
    if (at_reference) reference_steps(nodes, rescaling_.raw_steps_span(element_count()));
    return rescaling_.rescale_corners(element_count(), dt2ms, [&](Index e) { return corner_share(e); },
                                      step_factor_.data(), corner_added, corner_inertia);
  }

  /// Forces and moments at x^n with velocities and angular velocities at t^{n-1/2}: the stress
  /// increment uses the strain rate on the mid-step geometry x^n - dt/2 v (exactly zero for a
  /// rigid rotation), the forces the geometry at x^n. Returns the smallest element step
  /// A / max(side, diagonal) / (plate wave speed, with bulk viscosity and stiffness damping),
  /// time.
  Real compute_forces(const NodalFields& nodes, Real dt, CornerBuffer& corners,
                      BlockEnergy& energy) override {
    // One branch per block: a block without stiffness damping runs the loop without it.
    if (damping_.beta > 0.0)
      compute_chunks<true>(nodes, dt, corners);
    else
      compute_chunks<false>(nodes, dt, corners);
    if (erosion_.active()) energy.eroded_elements += erosion_.reduce(energy.eroded_internal, energy.eroded_hourglass);
    return reduce_element_chunks(chunk_dt_, chunk_hg_, chunk_visc_, chunk_damp_, chunk_power_, chunk_bad_, energy,
                                 "shell", ids_, part_id_,
                                 "degenerated (non-positive area or non-finite force)");
  }

 private:
  template <bool damped>
  void compute_chunks(const NodalFields& nodes, Real dt, CornerBuffer& corners) {
    parallel_for_chunks(element_count(), [&](Index b, Index end, Index chunk) {
      Real dtmin = std::numeric_limits<Real>::max();
      Index dtarg = b;
      Real p_hg = 0.0, p_visc = 0.0, p_damp = 0.0, p_all = 0.0;
      Index bad = -1;
      for (Index e = b; e < end; ++e) {
        if (erosion_.active() && erosion_.deleted(e)) {  // no forces, no step; its nodes may be anywhere
          store_element(e, shell_bt::NodeMat::Zero(), shell_bt::NodeMat::Zero(), corners);
          if (Real* raw = rescaling_.raw_steps()) raw[e] = std::numeric_limits<Real>::max();  // adds no mass
          continue;
        }
        const ElementResult r = e >= nq_ ? triangle_forces<damped>(nodes, dt, e, corners)
                                         : quad_forces<damped>(nodes, dt, e, chunk, corners);
        if (r.bad && bad < 0) bad = e;
        if (r.bad) continue;
        p_hg += 0.5 * (r.p_hg_prev + r.p_hg);  // trapezoidal, as the ledger's nodal work
        p_visc += 0.5 * (r.p_visc_prev + r.p_visc);
        if (r.deleted) continue;  // the first halves only (its forces are zero from now on)
        p_damp += r.p_damp;
        p_all += r.p_all;
        if (r.dt < dtmin) {
          dtmin = r.dt;
          dtarg = e;
        }
      }
      chunk_dt_[chunk] = dtmin;
      chunk_dt_element_[chunk] = dtarg;
      chunk_hg_[chunk] = p_hg;
      chunk_visc_[chunk] = p_visc;
      chunk_damp_[chunk] = p_damp;
      chunk_power_[chunk] = p_all;
      chunk_bad_[chunk] = bad;
    });
  }

  /// What one element adds to its chunk's sums (hourglass power: quadrilaterals only; _prev: the
  /// last forces' powers at this step's rates); `bad`: it degenerated or its forces are not
  /// finite, `deleted`: erosion deleted it at this evaluation.
  struct ElementResult {
    Real dt = 0.0, p_visc = 0.0, p_damp = 0.0, p_all = 0.0, p_hg = 0.0, p_hg_prev = 0.0, p_visc_prev = 0.0;
    bool bad = false, deleted = false;
  };

  /// Forces and moments of quadrilateral e into its corner slots: the strain rates on the mid-step
  /// geometry x^n - dt/2 v (exactly zero for a rigid rotation), the forces on the geometry at x^n;
  /// then erosion (erode()): a quadrilateral deleted now stores no forces and adds nothing.
  template <bool damped>
  ElementResult quad_forces(const NodalFields& nodes, Real dt, Index e, Index chunk, CornerBuffer& corners) {
    ElementResult out;
    const Real c = mat_.wave_speed();
    const shell_bt::NodeMat X = gather(nodes.x, e);
    const shell_bt::NodeMat V = gather(nodes.v, e);
    const shell_bt::NodeMat W = gather(nodes.omega, e);
    const shell_bt::LocalGeometry g = shell_bt::local_geometry(X, sec_.invariant_frame);
    const shell_bt::NodeMat Xm = dt > 0.0 ? shell_bt::NodeMat(X - 0.5 * dt * V) : X;
    const bool inv = sec_.invariant_frame;
    const shell_bt::LocalGeometry gm = dt > 0.0 && g.area > 0.0 ? shell_bt::local_geometry(Xm, inv) : g;
    if (!(g.area > 0.0) || !(gm.area > 0.0)) {
      out.bad = true;
      return out;
    }
    const shell_bt::StrainRates sr = shell_bt::strain_rates(gm, V * gm.e, W * gm.e);
    shell_bt::Resultants r;
    const Real t = thickness(e);
    shell_thickness::PointStrains ps = point_strains(e);
    State* st = state_.data() + static_cast<std::size_t>(e) * rule_.n;
    shell_thickness::PointStrains* psp = tracks_strain() ? &ps : nullptr;
    [[maybe_unused]] const Real damp =
        shell_thickness::integrate<damped>(mat_, rule_, t, damping_.beta, st, sr, dt, r, sec_.shear_factor, psp);
    if (!thick_.empty()) thick_[e] = t * std::exp(ps.mean);  // ISTUPD: the next step's thickness
    // Bulk viscosity on the membrane dilatation rate (a pressure over the thickness).
    const Real len = shell_bt::characteristic_length(X, g.area);
    Real qdt = bulk_viscosity(e, sr, len, g.area, t, r, out.p_visc, out.p_visc_prev);
    if constexpr (damped) {
      out.p_damp = damp * g.area;
      qdt += damping_.beta * c * c / len;  // the damped step, as for the hexahedron
    }
    shell_bt::NodeMat fl, ml;
    shell_bt::resultant_forces(g, r, fl, ml);
    shell_bt::NodeMat f = fl * g.e.transpose();
    shell_bt::NodeMat m = ml * g.e.transpose();
    if (qhg_ > 0.0) {
      const Real m_node = mat_.density() * area0_[e] * sec_.thickness / 4.0;  // the mass stays
      const Real j_node = m_node * std::max(sec_.thickness * sec_.thickness, area0_[e]) / 12.0;
      Real* q = &hg_q_[5 * static_cast<std::size_t>(e)];
      out.p_hg = shell_hourglass::add(qhg_, mat_.youngs_modulus(), sec_.shear_factor * mat_.stiffness().g, t, m_node, j_node,
                                      gm, Xm, V, W, f, m, sec_.hourglass_stiffness ? q : nullptr, dt, &g, q, out.p_hg_prev);
    }
    out.bad = !f.allFinite() || !m.allFinite();
    out.p_all = -(f.cwiseProduct(V).sum() + m.cwiseProduct(W).sum());
    out.dt = len / (qdt + std::sqrt(qdt * qdt + c * c));
    Real* raw = rescaling_.raw_steps();
    if (raw) raw[e] = out.dt;  // mass scaling every cycle (enable_mass_rescaling)
    if (!step_factor_.empty()) out.dt *= step_factor_[e];  // mass scaling (scale_element_masses)
    if (erosion_.active() && !out.bad && erode(e, chunk, out, V, W, corners, dt)) {
      out.deleted = true;
      out.p_hg = out.p_visc = out.p_damp = out.p_all = 0.0;
      out.dt = 0.0;
      if (raw) raw[e] = std::numeric_limits<Real>::max();  // deleted: adds no mass from now on
      store_element(e, shell_bt::NodeMat::Zero(), shell_bt::NodeMat::Zero(), corners);
      return out;
    }
    store_element(e, f, m, corners);
    return out;
  }

  /// Bulk viscosity of element e (shell_bulk_viscosity.hpp), its last evaluation's q t A kept.
  Real bulk_viscosity(Index e, const shell_bt::StrainRates& sr, Real len, Real area, Real t, shell_bt::Resultants& r,
                      Real& p_visc, Real& p_prev) {
    return shell_bulk_viscosity::add(mat_.density(), mat_.wave_speed(), bulk_, sr.membrane[0] + sr.membrane[1], len,
                                     area, t, r, p_visc, p_prev, visc_prev_[static_cast<std::size_t>(e)]);
  }

  /// Forces and moments of triangle e (e >= nq_) into its corner slots, as compute_chunks does for
  /// a quad (mid-step geometry for the rates, the geometry at x^n for the forces), without
  /// hourglass control (the element has no spurious mode; shell_c0tri.hpp).
  template <bool damped>
  ElementResult triangle_forces(const NodalFields& nodes, Real dt, Index e, CornerBuffer& corners) {
    ElementResult out;
    const shell_c0tri::NodeMat X = gather_triangle(nodes.x, e);
    const shell_c0tri::NodeMat V = gather_triangle(nodes.v, e);
    const shell_c0tri::NodeMat W = gather_triangle(nodes.omega, e);
    const shell_c0tri::NodeMat X0 = sec_.invariant_triangles ? gather_triangle(nodes.x0, e) : X;
    const shell_c0tri::NodeMat* ref = sec_.invariant_triangles ? &X0 : nullptr;  // INN = 2, 4
    const shell_c0tri::LocalGeometry g = shell_c0tri::local_geometry(X, ref);
    const shell_c0tri::NodeMat Xm = dt > 0.0 ? shell_c0tri::NodeMat(X - 0.5 * dt * V) : X;
    const shell_c0tri::LocalGeometry gm = dt > 0.0 ? shell_c0tri::local_geometry(Xm, ref) : g;
    if (!(g.area > 0.0) || !(gm.area > 0.0)) {
      out.bad = true;
      return out;
    }
    const shell_c0tri::StrainRates sr = shell_c0tri::strain_rates(gm, V * gm.e, W * gm.e);
    shell_bt::Resultants r;
    const Real t = thickness(e);
    const Real kappa = shell_c0tri::stabilised_shear_factor(gm, sec_.shear_factor, t);
    shell_thickness::PointStrains ps = point_strains(e);
    [[maybe_unused]] const Real damp = shell_thickness::integrate<damped>(mat_, rule_, t, damping_.beta,
        state_.data() + static_cast<std::size_t>(e) * rule_.n, sr.s, dt, r, kappa, tracks_strain() ? &ps : nullptr);
    if (!thick_.empty()) thick_[e] = t * std::exp(ps.mean);  // ISTUPD: the next step's thickness
    // The shear's rotational part: elastic, kappa G t I_p / A per unit area (shell_c0tri.hpp).
    const Real kc = kappa * mat_.shear_modulus() * t * gm.polar;
    Real& c_int = tri_c_[static_cast<std::size_t>(e - nq_)];
    c_int += dt * sr.shear_c;
    Real qc = kc * c_int;
    const Real c = mat_.wave_speed();
    const PlaneStressStiffness cs = mat_.stiffness();
    const Real len = shell_c0tri::characteristic_length(g, cs.c11, cs.g);
    const Real len_dt = triangle_step_length(g, e, kappa, len, t);
    Real qdt = bulk_viscosity(e, sr.s, len, g.area, t, r, out.p_visc, out.p_visc_prev);
    if constexpr (damped) {
      const Real dc = damping_.beta * kc * sr.shear_c;
      qc += dc;
      out.p_damp = (damp + dc * sr.shear_c) * g.area;
      qdt += damping_.beta * c * c / len;
    }
    shell_c0tri::NodeMat fl, ml;
    shell_c0tri::resultant_forces(g, r, qc, fl, ml);
    const shell_c0tri::NodeMat f = fl * g.e.transpose();
    const shell_c0tri::NodeMat m = ml * g.e.transpose();
    out.bad = !f.allFinite() || !m.allFinite();
    out.p_all = -(f.cwiseProduct(V).sum() + m.cwiseProduct(W).sum());
    out.dt = len_dt / (qdt + std::sqrt(qdt * qdt + c * c));
    if (Real* raw = rescaling_.raw_steps()) raw[e] = out.dt;  // mass scaling every cycle
    if (!step_factor_.empty()) out.dt *= step_factor_[e];  // mass scaling (scale_element_masses)
    const Index s0 = force_slot_base() + 4 * nq_ + 3 * (e - nq_);
    const Index m0 = moment_slot_base() + 4 * nq_ + 3 * (e - nq_);
    for (int k = 0; k < 3; ++k) {
      corners.force.x[s0 + k] = f(k, 0);
      corners.force.y[s0 + k] = f(k, 1);
      corners.force.z[s0 + k] = f(k, 2);
      corners.moment.x[m0 + k] = m(k, 0);
      corners.moment.y[m0 + k] = m(k, 1);
      corners.moment.z[m0 + k] = m(k, 2);
    }
    return out;
  }

  /// The length triangle e's step formula takes at geometry `g`: the smaller of its membrane
  /// length `len` and its bending / shear modes' bound 2 c / omega (shear factor `kappa`, thickness
  /// `tk` of the stiffness; the mass is the section's).
  Real triangle_step_length(const shell_c0tri::LocalGeometry& g, Index e, Real kappa, Real len, Real tk) const {
    const PlaneStressStiffness cs = mat_.stiffness();
    const Real t = sec_.thickness;
    const Real m_node = mat_.density() * area0_[e] * t / 3.0;
    const Real w2 = shell_c0tri::bending_omega2_bound(g, cs.c11, cs.g, kappa, tk, m_node,
                                                      m_node * std::max(t * t, area0_[e]) / 12.0);
    return std::min(len, 2.0 * mat_.wave_speed() / std::sqrt(w2));
  }
  /// The same at rest (the reference step): the shear factor and membrane length of `g` itself.
  Real triangle_step_length(const shell_c0tri::LocalGeometry& g, Index e) const {
    const PlaneStressStiffness cs = mat_.stiffness();
    return triangle_step_length(g, e, shell_c0tri::stabilised_shear_factor(g, sec_.shear_factor, sec_.thickness),
                                shell_c0tri::characteristic_length(g, cs.c11, cs.g), sec_.thickness);
  }

  /// Triangle e's lumped mass rho A t / 3 per node and the quad's rotary inertia scaling.
  void initialize_triangle(NodalFields& nodes, Index e) {
    const Real t = sec_.thickness;
    const shell_c0tri::LocalGeometry g = shell_c0tri::local_geometry(gather_triangle(nodes.x0, e));
    if (!(g.area > 0.0))
      throw InputError("shell element " + std::to_string(ids_[e]) + " of part " + std::to_string(part_id_) +
                       " (a triangle, N3 = N4) has zero area (its three nodes are on a line)");
    area0_[e] = g.area;
    const Real m = mat_.density() * g.area * t / 3.0;
    const Real j = m * std::max(t * t, g.area) / 12.0;
    const Index* c = triangle_nodes(e);
    for (int k = 0; k < 3; ++k) {
      nodes.mass[c[k]] += m;
      nodes.rot_inertia[c[k]] += j;
      nodes.has_rotation[c[k]] = 1;
    }
  }

  /// Whether the elements integrate their points' normal strains (ISTUPD, or a strain criterion).
  bool tracks_strain() const { return !thick_.empty() || !strain_.empty(); }
  /// The normal-strain bookkeeping of element e (shell_thickness::PointStrains): nu = c12 / c11.
  shell_thickness::PointStrains point_strains(Index e) {
    shell_thickness::PointStrains ps;
    if (!tracks_strain()) return ps;
    const PlaneStressStiffness cs = mat_.stiffness();
    const Real nu = cs.c12 / cs.c11, young = mat_.youngs_modulus();
    ps.total_factor = (1.0 - 2.0 * nu) / young;
    ps.thickness_factor = thickness_mode_ == 4 ? (1.0 - nu) / young : ps.total_factor;
    if (!strain_.empty()) ps.strain = strain_.data() + static_cast<std::size_t>(e) * rule_.n;
    return ps;
  }

  /// Erosion (element_erosion.hpp) of quadrilateral e after its update (`internal`, `hourglass`: its
  /// powers; `dt_e` its stable step); the verdict is shell_erosion::fails.
  /// Its held works are trapezoidal, as the block's: the first half from its last forces and
  /// moments, still in its corner slots, at this step's velocities V, W.
  bool erode(Index e, Index chunk, const ElementResult& r, const shell_bt::NodeMat& V, const shell_bt::NodeMat& W,
             const CornerBuffer& corners, Real dt) {
    const State* st = state_.data() + static_cast<std::size_t>(e) * rule_.n;
    const std::array<Real, 6>* eps = strain_.empty() ? nullptr : strain_.data() + static_cast<std::size_t>(e) * rule_.n;
    const bool gone = shell_erosion::fails(erosion_.criteria(), st, rule_.n, erosion_.time(), r.dt, eps);
    const Real all_prev =
        shell_erosion::previous_corner_power(corners, force_slot_base() + 4 * e, moment_slot_base() + 4 * e, V, W);
    return erosion_.update_failed(e, chunk, gone, 0.5 * (r.p_all - r.p_visc - r.p_hg) - r.p_damp, 0.5 * r.p_hg, dt,
                                  0.5 * (all_prev - r.p_visc_prev - r.p_hg_prev), 0.5 * r.p_hg_prev);
  }

  /// Writes element e's forces f and moments m (4 x 3, global) into its corner slots.
  void store_element(Index e, const shell_bt::NodeMat& f, const shell_bt::NodeMat& m,
                     CornerBuffer& corners) const {
    const Index s0 = force_slot_base() + 4 * e;
    const Index m0 = moment_slot_base() + 4 * e;
    for (int k = 0; k < 4; ++k) {
      corners.force.x[s0 + k] = f(k, 0);
      corners.force.y[s0 + k] = f(k, 1);
      corners.force.z[s0 + k] = f(k, 2);
      corners.moment.x[m0 + k] = m(k, 0);
      corners.moment.y[m0 + k] = m(k, 1);
      corners.moment.z[m0 + k] = m(k, 2);
    }
  }

 public:
  /// Stress (force/length^2, local co-rotational frame: xx, yy, xy, yz, xz) of element e at
  /// through-thickness point ip (0 = bottom, z = xi * t / 2).
  Eigen::Matrix<Real, 5, 1> stress(Index e, int ip) const {
    const ShellStress s = mat_.stress(state_[static_cast<std::size_t>(e) * rule_.n + ip]);
    return Eigen::Matrix<Real, 5, 1>(s[0], s[1], s[2], s[3], s[4]);
  }

  /// In-plane stress (xx, yy, xy, local frame) on the top (z = +t/2) or bottom surface of element
  /// e, linearly extrapolated from the two outermost points (exact for an elastic shell, whose
  /// in-plane stress is linear through the thickness). Needs nip >= 2.
  Eigen::Matrix<Real, 3, 1> surface_stress(Index e, bool top) const {
    const int n = rule_.n;
    if (n < 2) return stress(e, 0).template head<3>();
    const int i1 = top ? n - 1 : 0, i2 = top ? n - 2 : 1;
    const Real z1 = rule_.xi[i1], z2 = rule_.xi[i2], zs = top ? 1.0 : -1.0;
    const Real a = (zs - z2) / (z1 - z2);
    return a * stress(e, i1).template head<3>() + (1.0 - a) * stress(e, i2).template head<3>();
  }

  /// ElementBlock::cell_outputs: global stress at the mid surface (the middle through-thickness
  /// point; the mean of the two middle points for an even count) and at the outermost points,
  /// the largest plastic strain of the through-thickness points (the law state's `eps`, where it
  /// has one: in bending the mid surface stays elastic) and the thickness average of the law's
  /// energy density (`energy_density(state, shear factor)`).
  void cell_outputs(const NodalFields& nodes, std::span<CellOutput> out) const override {
    const int n = rule_.n;
    const int lo = (n - 1) / 2, hi = n / 2;  // the middle point(s)
    for (Index e = 0; e < element_count(); ++e) {
      const Mat3 ge = frame(nodes, e);
      const State* st = state_.data() + static_cast<std::size_t>(e) * n;
      CellOutput& c = out[static_cast<std::size_t>(e)];
      c.stress_bottom = shell_bt::global_stress(ge, stress(e, 0));
      c.stress_top = shell_bt::global_stress(ge, stress(e, n - 1));
      const SymTensor6 a = shell_bt::global_stress(ge, stress(e, lo)), b = shell_bt::global_stress(ge, stress(e, hi));
      for (int k = 0; k < 6; ++k) c.stress[k] = 0.5 * (a[k] + b[k]);
      c.plastic_strain = 0.0;
      for (int ip = 0; ip < n; ++ip) c.plastic_strain = std::max(c.plastic_strain, plastic_strain_of(st[ip]));
      c.energy_density = 0.0;
      if constexpr (requires { { mat_.energy_density(st[0], sec_.shear_factor) } -> std::convertible_to<Real>; })
        for (int ip = 0; ip < n; ++ip) c.energy_density += 0.5 * rule_.w[ip] * mat_.energy_density(st[ip], sec_.shear_factor);
      c.deleted = erosion_.active() && erosion_.deleted(e);
      if (c.deleted) c.stress = c.stress_bottom = c.stress_top = SymTensor6{}, c.energy_density = 0.0;
    }
  }

  bool has_plasticity() const override { return PlasticState<State>; }

  /// ElementBlock::plasticity_totals: each through-thickness point's `eps`, and its `work` times
  /// its share w/2 of the current area times the thickness (the section's, or the current one
  /// under ISTUPD).
  PlasticityTotals plasticity_totals(const NodalFields& nodes) const override {
    PlasticityTotals t;
    if constexpr (PlasticState<State>) {
      const int n = rule_.n;
      for (Index e = 0; e < element_count(); ++e) {
        const Real area = e < nq_ ? shell_bt::local_geometry(gather(nodes.x, e), sec_.invariant_frame).area
                                  : shell_c0tri::local_geometry(gather_triangle(nodes.x, e)).area;
        const State* st = state_.data() + static_cast<std::size_t>(e) * n;
        for (int ip = 0; ip < n; ++ip) {
          t.max_plastic_strain = std::max(t.max_plastic_strain, plastic_strain_of(st[ip]));
          t.plastic_work += 0.5 * rule_.w[ip] * plastic_work_density_of(st[ip]) * area * thickness(e);
        }
      }
    }
    return t;
  }

 private:
  shell_bt::NodeMat gather(const Vec3Field& f, Index e) const {
    return gather_rows<4>(f, conn_.data() + 4 * static_cast<std::size_t>(e));
  }
  const Index* triangle_nodes(Index e) const {
    return conn_.data() + 4 * static_cast<std::size_t>(nq_) + 3 * static_cast<std::size_t>(e - nq_);
  }
  shell_c0tri::NodeMat gather_triangle(const Vec3Field& f, Index e) const {
    return gather_rows<3>(f, triangle_nodes(e));
  }
  /// Element e's co-rotational frame (columns e1, e2, e3) at the current coordinates.
  Mat3 frame(const NodalFields& nodes, Index e) const {
    if (e < nq_) return shell_bt::local_geometry(gather(nodes.x, e), sec_.invariant_frame).e;
    const shell_c0tri::NodeMat X0 = gather_triangle(nodes.x0, e);
    return shell_c0tri::local_geometry(gather_triangle(nodes.x, e), sec_.invariant_triangles ? &X0 : nullptr).e;
  }

  Id part_id_;
  Law mat_;
  ShellSection sec_;
  Real qhg_;
  BulkViscosity bulk_;
  StiffnessDamping damping_;
  shell_bt::ThicknessRule rule_;
  std::vector<Index> conn_;
  std::vector<Id> ids_;
  std::vector<Real> step_factor_;  ///< sqrt of the mass-scaling factor per element; empty: none
  ElementMassScaling rescaling_;   ///< MS1ST = 0: the steps before the factors (inactive otherwise)
  std::vector<Real> area0_;
  std::vector<Real> hg_q_;  ///< 5 generalised hourglass forces per quad (local; viscous: the last ones)
  std::vector<Real> visc_prev_;  ///< per element, the last evaluation's bulk-viscosity q t A
  Index nq_ = 0;              ///< quadrilaterals; the triangles follow them
  std::vector<Real> tri_c_;   ///< per triangle, the time integral of the shear's rotational part c
  std::vector<State> state_;  ///< the law's state, element-major, then point
  std::vector<Real> thick_;   ///< ISTUPD: per element, the current thickness (empty: the section's)
  int thickness_mode_ = 0;    ///< ISTUPD (1 or 4) when thick_ is not empty
  std::vector<std::array<Real, 6>> strain_;  ///< strain criteria: per element and point (empty: none)
  std::vector<Real> chunk_dt_, chunk_hg_, chunk_visc_, chunk_damp_, chunk_power_;
  std::vector<Index> chunk_dt_element_;  ///< per chunk, the element with the smallest step
  std::vector<Index> chunk_bad_;
  ElementErosion erosion_;  ///< inactive unless enable_erosion
};

/// The elastic shell block (*MAT_ELASTIC).
using ShellBlock = BasicShellBlock<ElasticShell>;

}  // namespace slideline
