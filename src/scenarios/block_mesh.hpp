#pragma once
// Structured-grid helpers shared by the scenario generators (two_block.cpp, sslide_*.cpp): coordinate
// lines, node grids (optionally sharing nodes by exact coordinates), hexahedra and quadrilateral
// shells on a grid, face node lists and segments. Private to src/scenarios.
#include <array>
#include <cstddef>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "slideline/model/model.hpp"

namespace slideline::scenarios::detail {

/// n + 1 equally spaced coordinates from `start` over `length`.
std::vector<Real> lines(Real start, Real length, int n);

/// `a` plus the values of `b` strictly inside (lo, hi), sorted, duplicates (1e-12) removed.
std::vector<Real> merge_lines(std::vector<Real> a, const std::vector<Real>& b, Real lo, Real hi);

/// Nodes on the tensor product of coordinate lines; (i, j, k) -> node id.
struct Grid {
  std::vector<Real> xs, ys, zs;
  std::vector<Id> node;

  Id at(std::size_t i, std::size_t j, std::size_t k) const {
    return node[i + xs.size() * (j + ys.size() * k)];
  }
  Vec3 coord(std::size_t i, std::size_t j, std::size_t k) const { return {xs[i], ys[j], zs[k]}; }
};

/// Appends nodes and elements to a model with increasing ids.
class MeshWriter {
 public:
  MeshWriter(model::Model& m, Id next_node, Id next_elem) : m_(m), next_node_(next_node), next_elem_(next_elem) {}

  /// Creates the grid's nodes. With `share`, a node at exactly the coordinates of a node this
  /// writer already created is reused (one body, no interface).
  Grid add_nodes(std::vector<Real> xs, std::vector<Real> ys, std::vector<Real> zs, bool share);
  /// Nodes plus one hexahedron per grid cell (LS-DYNA node order), all of part `pid`.
  Grid add_grid(std::vector<Real> xs, std::vector<Real> ys, std::vector<Real> zs, Id pid, bool share);
  /// One 4-node shell per cell of a grid that is flat in one direction (that direction has a single
  /// line). Node order (a, b), (a+1, b), (a+1, b+1), (a, b+1) over the two in-plane directions
  /// (x before y before z); `reverse` flips it, and with it the shell normal.
  void add_shells(const Grid& g, Id pid, bool reverse);

  Id next_node() const { return next_node_; }
  Id next_elem() const { return next_elem_; }

 private:
  model::Model& m_;
  Id next_node_, next_elem_;
  std::map<std::tuple<long long, long long, long long>, Id> shared_;
};

/// Node ids of the grid's face j = const (an x-z layer), k outer, i inner.
std::vector<Id> layer_nodes(const Grid& g, std::size_t j);
/// Node ids of the grid's face i = const (a y-z layer), k outer, j inner.
std::vector<Id> x_face_nodes(const Grid& g, std::size_t i);

/// The segments (4 node ids each) of the x-z layer j, counter-clockwise seen from +y when
/// `normal_up`, from -y otherwise.
std::vector<std::array<Id, 4>> layer_segments(const Grid& g, std::size_t j, bool normal_up);

/// The node of layer j nearest to (x, z) in the x-z plane (first one on a tie).
Id nearest_in_layer(const Grid& g, std::size_t j, Real x, Real z);

/// Index of the last grid line <= v (clamped to the cells), for locating a point in a grid.
std::size_t cell_of(const std::vector<Real>& lines, Real v);

}  // namespace slideline::scenarios::detail
