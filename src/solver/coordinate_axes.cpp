// The axes of a local coordinate system (coordinate_axes.hpp; docs/keywords.md, "Local coordinate
// systems").
#include "slideline/solver/coordinate_axes.hpp"

#include <algorithm>
#include <cmath>

#include "slideline/core/error.hpp"
#include "slideline/solver/build.hpp"

namespace slideline {
namespace {

using model::CoordinateSystem;

const char* keyword(CoordinateSystem::Kind k) {
  switch (k) {
    case CoordinateSystem::Kind::points: return "*DEFINE_COORDINATE_SYSTEM";
    case CoordinateSystem::Kind::nodes: return "*DEFINE_COORDINATE_NODES";
    case CoordinateSystem::Kind::vectors: return "*DEFINE_COORDINATE_VECTOR";
  }
  return "?";
}

std::string card(const CoordinateSystem& s) {
  return describe(s.src) + ": " + keyword(s.kind) + " " + std::to_string(s.cid);
}

/// Axis `d` (0 x, 1 y, 2 z) along `a`, the next axis (cyclic) in the plane of `a` and `b`, the
/// third their cross product: the columns of a proper rotation. Throws when `a` and `b` do not
/// span a plane.
Mat3 axes_from(const Vec3& a, const Vec3& b, int d, const std::string& where) {
  const Real la = a.norm(), lb = b.norm();
  const Vec3 n = a.cross(b);
  if (!(la > 0.0) || !(lb > 0.0) || !(n.norm() > 1e-10 * la * lb) || !n.allFinite())
    throw InputError(where + ": its axis and plane directions do not span a plane (a zero, coincident or "
                     "collinear point, node or vector); cannot build the system");
  Mat3 r;
  const int d1 = (d + 1) % 3, d2 = (d + 2) % 3;
  r.col(d) = a / la;
  r.col(d2) = n.normalized();
  r.col(d1) = r.col(d2).cross(r.col(d));
  return r;
}

Vec3 node_x(const model::Model& m, Id nid, const std::string& where, const char* field) {
  const auto n = std::find_if(m.nodes.begin(), m.nodes.end(), [&](const model::Node& x) { return x.id == nid; });
  if (n == m.nodes.end())
    throw InputError(where + ": field " + field + " refers to node " + std::to_string(nid) +
                     ", which the deck does not define");
  return n->x;
}

LocalAxes resolve(const model::Model& m, Id cid, const std::string& user, int depth) {
  const auto s = std::find_if(m.coordinate_systems.begin(), m.coordinate_systems.end(),
                              [&](const CoordinateSystem& c) { return c.cid == cid; });
  if (s == m.coordinate_systems.end())
    throw InputError(user + " refers to coordinate system " + std::to_string(cid) +
                     ", which the deck does not define (*DEFINE_COORDINATE_SYSTEM, _NODES or _VECTOR)");
  const std::string where = card(*s);
  LocalAxes out;
  out.system = &*s;
  switch (s->kind) {
    case CoordinateSystem::Kind::points: {
      Vec3 o = s->origin, l = s->axis, p = s->plane;
      if (s->cidl != 0) {
        if (depth > 16 || s->cidl == cid)
          throw InputError(where + ": field CIDL = " + std::to_string(s->cidl) + " makes the systems' CIDL refer "
                           "to each other in a loop");
        const LocalAxes base = resolve(m, s->cidl, where + " field CIDL", depth + 1);
        o = base.origin + base.r * o;
        l = base.origin + base.r * l;
        p = base.origin + base.r * p;
      }
      out.r = axes_from(l - o, p - o, 0, where);
      out.origin = o;
      break;
    }
    case CoordinateSystem::Kind::nodes: {
      const Vec3 x1 = node_x(m, s->nodes[0], where, "N1"), x2 = node_x(m, s->nodes[1], where, "N2"),
                 x3 = node_x(m, s->nodes[2], where, "N3");
      out.r = axes_from(x2 - x1, x3 - x1, s->dir, where);
      out.origin = x1;
      break;
    }
    case CoordinateSystem::Kind::vectors:
      out.r = axes_from(s->axis, s->plane, 0, where);
      out.origin = s->nodes[0] != 0 ? node_x(m, s->nodes[0], where, "NID") : Vec3::Zero();
      break;
  }
  return out;
}

}  // namespace

LocalAxes local_axes(const model::Model& m, Id cid, const std::string& user) { return resolve(m, cid, user, 0); }

std::vector<std::pair<Axis, Real>> global_components(const model::Model& m, Axis a, Id cid, const std::string& user) {
  if (cid == 0) return {{a, 1.0}};
  const Mat3 r = local_axes(m, cid, user).r;
  std::vector<std::pair<Axis, Real>> out;
  for (int k = 0; k < 3; ++k)
    if (const Real c = r(k, static_cast<int>(a)); c != 0.0) out.emplace_back(static_cast<Axis>(k), c);
  return out;
}

std::optional<std::array<int, 3>> axis_permutation(const Mat3& r) {
  std::array<int, 3> to{};
  for (int j = 0; j < 3; ++j) {
    int hit = -1;
    for (int i = 0; i < 3; ++i) {
      const Real a = std::abs(r(i, j));
      if (std::abs(a - 1.0) <= 1e-12) hit = i;
      else if (a > 1e-12) return std::nullopt;
    }
    if (hit < 0) return std::nullopt;
    to[static_cast<std::size_t>(j)] = hit;
  }
  return to;
}

}  // namespace slideline
