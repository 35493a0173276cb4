#include "slideline/solver/rigid_wall.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "slideline/core/error.hpp"

namespace slideline {

RigidWall::RigidWall(RigidWallSpec spec) : spec_(std::move(spec)) {
  if (spec_.fixed.size() != spec_.nodes.size()) spec_.fixed.resize(spec_.nodes.size(), 0);
}

bool RigidWall::covers(const Vec3& x) const {
  if (!spec_.finite) return true;
  const Vec3 r = x - spec_.point;
  const Real s = r.dot(spec_.l_axis), q = r.dot(spec_.m_axis);
  return s >= 0.0 && s <= spec_.lenl && q >= 0.0 && q <= spec_.lenm;
}

void RigidWall::initialize(NodalFields& nodes, std::span<const Real>) {
  // A tolerance relative to the model's size: a node on the plane to round-off is on it.
  Real size = 0.0;
  for (Index i : spec_.nodes) size = std::max(size, (nodes.x0.get(i) - spec_.point).norm());
  for (Index i : spec_.nodes) {
    const Vec3 x = nodes.x.get(i);
    if ((x - spec_.point).dot(spec_.normal) < -1e-9 * size && covers(x))
      throw InputError("rigid wall " + spec_.name + ": node " + std::to_string(nodes.ids[i]) +
                       " starts behind the wall (the normal points from XT YT ZT to XH YH ZH, towards the "
                       "nodes)");
  }
}

Vec3 RigidWall::velocity_change(std::size_t k, const NodalFields& nodes, Real dt_avg, Real dt_next) const {
  const Index i = spec_.nodes[k];
  const Vec3& n = spec_.normal;
  const Vec3 x = nodes.x.get(i);
  const Vec3 vp = nodes.v.get(i) + dt_avg * nodes.a.get(i);  // v^{n+1/2} without the wall
  const Real d = (x - spec_.point).dot(n);
  const Real vn = vp.dot(n);
  if (d + dt_next * vn >= 0.0 || !covers(x)) return Vec3::Zero();
  // Land on the plane at t^{n+1} (a node already on or behind it stops there).
  const Real dvn = -std::max(d, 0.0) / dt_next - vn;
  Vec3 dv = dvn * n;
  if (spec_.friction > 0.0) {
    Vec3 vt = vp - vn * n;
    for (int c = 0; c < 3; ++c)
      if (spec_.fixed[k] & (1u << c)) vt[c] = 0.0;
    const Real speed = vt.norm();
    // Coulomb on the impulses: the tangential velocity change is at most FRIC times the normal one.
    if (speed > 0.0) dv -= (spec_.friction >= 1.0 ? 1.0 : std::min(1.0, spec_.friction * dvn / speed)) * vt;
  }
  return dv;
}

void RigidWall::constrain_accelerations(const ConstraintLoads& loads, NodalFields& nodes, Real t) {
  if (t != cycle_time_) {
    force_ = Vec3::Zero();
    in_contact_ = 0;
    cycle_time_ = t;
  }
  if (t < spec_.birth || t > spec_.death || !(loads.dt_avg > 0.0) || !(loads.dt_next > 0.0)) return;
  for (std::size_t k = 0; k < spec_.nodes.size(); ++k) {
    const Index i = spec_.nodes[k];
    const Real m = loads.mass[i];
    if (!(m > 0.0)) continue;
    const Vec3 dv = velocity_change(k, nodes, loads.dt_avg, loads.dt_next);
    if (dv.isZero(0.0)) continue;
    const Vec3 f = (m / loads.dt_avg) * dv;  // the wall's force on the node
    for (int c = 0; c < 3; ++c) {
      nodes.a[c][i] += dv[c] / loads.dt_avg;
      nodes.f_ext[c][i] += f[c];
    }
    force_ -= f;
    ++in_contact_;
  }
}

void RigidWall::append_output_names(std::vector<std::string>& names) const {
  names.push_back("rigidwalls/" + spec_.name + "/force");
  names.push_back("rigidwalls/" + spec_.name + "/normal_force");
}

void RigidWall::write_output_values(std::span<Real> out) const {
  if (out.size() < 6) return;
  const Real fn = -force_.dot(spec_.normal);  // the nodes push the wall against its normal
  const Vec3 ft = force_ + fn * spec_.normal;
  for (int c = 0; c < 3; ++c) out[static_cast<std::size_t>(c)] = force_[c];
  out[3] = fn;
  out[4] = ft.norm();
  out[5] = static_cast<Real>(in_contact_);
}

}  // namespace slideline
