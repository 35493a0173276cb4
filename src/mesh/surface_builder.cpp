#include "slideline/mesh/surface_builder.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <utility>

#include "slideline/core/error.hpp"

namespace slideline {

namespace {

/// Sorted distinct nodes of a face, padded with -1 for a triangle: equal for two faces exactly
/// when they have the same node set, whatever their order or which node a triangle repeats.
using FaceKey = std::array<Index, 4>;

/// A face or shell of some element, with its nodes in outward (shell: own) order.
struct Candidate {
  FaceKey key;
  SegmentNodes conn;
  Index block;
  Index element;
  SegmentKind kind;
  Real thickness;  ///< the shell's section thickness; 0 for a solid face
};

/// Removes cyclically repeated neighbours (a wedge's collapsed corner) and writes the face in
/// segment form: 4 distinct nodes, or 3 with the third repeated. Returns false when fewer than 3
/// distinct nodes remain or a node repeats non-adjacently (a face of no area).
bool normalize_face(const SegmentNodes& in, SegmentNodes& out) {
  Index d[4];
  int n = 0;
  for (int k = 0; k < 4; ++k)
    if (n == 0 || in[k] != d[n - 1]) d[n++] = in[k];
  if (n > 1 && d[n - 1] == d[0]) --n;
  if (n < 3) return false;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (d[i] == d[j]) return false;
  out = {d[0], d[1], d[2], n == 3 ? d[2] : d[3]};
  return true;
}

FaceKey face_key(const SegmentNodes& c) {
  FaceKey k = c;
  if (c[2] == c[3]) k[3] = -1;
  std::sort(k.begin(), k.begin() + (c[2] == c[3] ? 3 : 4));
  return k;
}

int corner_count(const SegmentNodes& c) { return c[2] == c[3] ? 3 : 4; }

/// True when `b` (normalised) runs through the nodes of `a` (normalised) in the same cyclic order.
bool same_cycle(const SegmentNodes& a, const SegmentNodes& b) {
  const int n = corner_count(a);
  if (corner_count(b) != n) return false;
  for (int shift = 0; shift < n; ++shift) {
    bool ok = true;
    for (int k = 0; k < n && ok; ++k) ok = a[(k + shift) % n] == b[k];
    if (ok) return true;
  }
  return false;
}

/// The same corners in the opposite cyclic order, keeping the first.
SegmentNodes reversed(const SegmentNodes& c) {
  if (corner_count(c) == 3) return {c[0], c[2], c[1], c[1]};
  return {c[0], c[3], c[2], c[1]};
}

std::string node_ids(const NodalFields& nodes, const SegmentNodes& c) {
  std::string s;
  for (int k = 0; k < 4; ++k) {
    if (k) s += ' ';
    s += (c[k] >= 0 && static_cast<std::size_t>(c[k]) < nodes.size()) ? std::to_string(nodes.ids[c[k]])
                                                                      : "?";
  }
  return s;
}

/// The nodes of local face f of the element whose connectivity starts at c.
SegmentNodes face_nodes(const Index* c, const LocalFace& f) { return {c[f[0]], c[f[1]], c[f[2]], c[f[3]]}; }

/// Appends the outward faces of solid element e of `block` (block index b; nodes from c) to
/// `out`. An element of zero volume has no outward side: an error when `strict`, else skipped (a
/// segment set only looks at the elements its segments name, so an unrelated bad element must not
/// stop it).
void append_solid_faces(const MeshBlock& block, Index b, const ElementTopology& topo, Index e,
                        const Index* c, const NodalFields& nodes, const std::string& context,
                        bool strict, std::vector<Candidate>& out) {
  const Real v = topo.measure(nodes.x0, c);
  if (!(std::abs(v) > 0.0)) {
    if (!strict) return;
    throw InputError(context + ": solid element " + std::to_string(block.element_id(e)) +
                     " of part " + std::to_string(block.part_id()) +
                     " has zero volume, so its faces have no outward side");
  }
  for (const LocalFace& f : topo.faces) {
    SegmentNodes raw = face_nodes(c, f);
    if (v < 0.0) raw = reversed(raw);  // a mirrored element: the table points in
    SegmentNodes face;
    if (!normalize_face(raw, face)) continue;
    out.push_back({face_key(face), face, b, e, SegmentKind::solid_face, 0.0});
  }
}

/// Appends surface element e (a shell: its one face, in its own order) of a run to `out`.
void append_surface_element(Index b, const TopologyRun& run, Index e, const Index* c,
                            std::vector<Candidate>& out) {
  for (const LocalFace& f : run.topology->faces) {
    SegmentNodes face;
    if (!normalize_face(face_nodes(c, f), face)) continue;
    out.push_back({face_key(face), face, b, e, SegmentKind::shell, run.thickness});
  }
}

/// Every solid face and shell of the blocks for which `use(block)` is true, ordered by block,
/// element, face. A topology without faces cannot carry a surface: an error when `strict`, else
/// its elements are skipped.
template <class Use>
std::vector<Candidate> collect(MeshBlocks blocks, const NodalFields& nodes,
                               const std::string& context, bool strict, Use use) {
  std::vector<Candidate> out;
  for (Index b = 0; b < static_cast<Index>(blocks.size()); ++b) {
    const MeshBlock& block = *blocks[b];
    if (!use(block)) continue;
    const Index* conn = block.connectivity().data();
    block.topology().for_each_element([&](const TopologyRun& run, Index e, std::size_t offset) {
      const ElementTopology& topo = *run.topology;
      if (topo.faces.empty()) {
        if (!strict) return;
        throw NotImplementedError("element block '" + block.kind() + "' of part " +
                                  std::to_string(block.part_id()) + ": " + std::string(topo.name) +
                                  " elements have no faces, so they cannot carry a contact surface");
      }
      if (topo.is_solid())
        append_solid_faces(block, b, topo, e, conn + offset, nodes, context, strict, out);
      else
        append_surface_element(b, run, e, conn + offset, out);
    });
  }
  return out;
}

void push_segment(Surface& surf, MeshBlocks blocks, const Candidate& c, const SegmentNodes& conn) {
  surf.conn.insert(surf.conn.end(), conn.begin(), conn.end());
  surf.block.push_back(c.block);
  surf.element.push_back(c.element);
  surf.part.push_back(blocks[c.block]->part_id());
  surf.kind.push_back(c.kind);
  surf.thickness.push_back(c.thickness);
}

/// A candidate's key next to its index: sorting these contiguous pairs, rather than indices that
/// point into the candidates, keeps the sort in cache (it dominates the build time).
struct KeyRef {
  FaceKey key;
  Index i;
  bool operator<(const KeyRef& o) const { return key != o.key ? key < o.key : i < o.i; }
};

/// Candidates sorted by key, ties in generation order (so lookups are deterministic).
std::vector<KeyRef> sorted_by_key(const std::vector<Candidate>& cand) {
  std::vector<KeyRef> order(cand.size());
  for (std::size_t i = 0; i < cand.size(); ++i) order[i] = {cand[i].key, static_cast<Index>(i)};
  std::sort(order.begin(), order.end());
  return order;
}

/// Per candidate, 1 when it is a solid face whose nodes another solid face among the candidates
/// also has (an interior face of the solids), else 0.
std::vector<char> interior_solid_faces(const std::vector<Candidate>& cand) {
  std::vector<char> interior(cand.size(), 0);
  const std::vector<KeyRef> order = sorted_by_key(cand);
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    int solids = 0;
    for (; j < order.size() && order[j].key == order[i].key; ++j)
      solids += cand[order[j].i].kind == SegmentKind::solid_face;
    if (solids > 1)
      for (std::size_t k = i; k < j; ++k)
        if (cand[order[k].i].kind == SegmentKind::solid_face) interior[order[k].i] = 1;
    i = j;
  }
  return interior;
}

}  // namespace

Surface build_surface_from_parts(MeshBlocks blocks, const NodalFields& nodes,
                                 std::span<const Id> parts, const std::string& context) {
  const std::set<Id> wanted(parts.begin(), parts.end());
  std::set<Id> found;
  for (const auto& b : blocks)
    if (wanted.count(b->part_id())) found.insert(b->part_id());
  for (Id p : wanted)
    if (!found.count(p))
      throw InputError(context + ": part " + std::to_string(p) +
                       " has no elements, so it has no surface");

  const std::vector<Candidate> cand =
      collect(blocks, nodes, context, true,
              [&](const MeshBlock& b) { return wanted.count(b.part_id()) != 0; });

  // The exterior: every candidate but the interior solid faces (shells are never interior: a
  // shell on a solid's face is a surface of its own).
  const std::vector<char> interior = interior_solid_faces(cand);
  Surface surf;
  for (std::size_t i = 0; i < cand.size(); ++i)
    if (!interior[i]) push_segment(surf, blocks, cand[i], cand[i].conn);
  if (surf.segment_count() == 0)
    throw InputError(context + ": the parts have no exterior face or shell");
  build_surface_adjacency(surf);
  return surf;
}

Surface interior_faces_of_parts(MeshBlocks blocks, const NodalFields& nodes, std::span<const Id> parts,
                                const std::string& context) {
  const std::set<Id> wanted(parts.begin(), parts.end());
  const std::vector<Candidate> cand =
      collect(blocks, nodes, context, true, [&](const MeshBlock& b) { return wanted.count(b.part_id()) != 0; });
  // The complement of build_surface_from_parts' rule: the solid faces another solid face of
  // these parts shares, each kept with its own element and orientation.
  const std::vector<char> interior = interior_solid_faces(cand);
  Surface surf;
  for (std::size_t i = 0; i < cand.size(); ++i)
    if (interior[i]) push_segment(surf, blocks, cand[i], cand[i].conn);
  return surf;
}

Surface build_surface_from_segments(MeshBlocks blocks, const NodalFields& nodes,
                                    std::span<const SegmentNodes> segments,
                                    const std::string& context) {
  // Every block: a segment may name any element of the model.
  const std::vector<Candidate> cand =
      collect(blocks, nodes, context, false, [](const MeshBlock&) { return true; });
  const std::vector<KeyRef> order = sorted_by_key(cand);

  Surface surf;
  std::map<FaceKey, Index> seen;  // keys of accepted segments, for duplicates
  for (std::size_t s = 0; s < segments.size(); ++s) {
    const SegmentNodes& given = segments[s];
    auto where = [&] {
      return context + ": segment " + std::to_string(s + 1) + " (nodes " + node_ids(nodes, given) + ")";
    };
    for (Index n : given)
      if (n < 0 || static_cast<std::size_t>(n) >= nodes.size())
        throw InputError(where() + " has a node index out of range");
    SegmentNodes seg;
    if (!normalize_face(given, seg))
      throw InputError(where() + " has fewer than 3 distinct nodes");
    const FaceKey key = face_key(seg);

    const auto lo = std::lower_bound(order.begin(), order.end(), key,
                                     [](const KeyRef& a, const FaceKey& k) { return a.key < k; });
    const auto hi = std::upper_bound(lo, order.end(), key,
                                     [](const FaceKey& k, const KeyRef& a) { return k < a.key; });
    if (lo == hi)
      throw InputError(where() + " matches no hexahedron face or shell element");
    // Preference: a solid face the given order points out of, any solid face, a shell.
    const Candidate* pick = nullptr;
    for (auto it = lo; it != hi && pick == nullptr; ++it)
      if (cand[it->i].kind == SegmentKind::solid_face && same_cycle(cand[it->i].conn, seg))
        pick = &cand[it->i];
    for (auto it = lo; it != hi && pick == nullptr; ++it)
      if (cand[it->i].kind == SegmentKind::solid_face) pick = &cand[it->i];
    if (pick == nullptr) pick = &cand[lo->i];

    SegmentNodes conn = pick->conn;
    if (pick->kind == SegmentKind::solid_face) {
      if (same_cycle(pick->conn, seg))
        conn = seg;
      else if (same_cycle(pick->conn, reversed(seg)))
        conn = reversed(seg);  // the given order points into the element
    }
    if (const auto [it, fresh] = seen.emplace(key, static_cast<Index>(s)); !fresh)
      throw InputError(where() + " repeats segment " + std::to_string(it->second + 1));
    push_segment(surf, blocks, *pick, conn);
  }
  if (surf.segment_count() == 0) throw InputError(context + ": the segment set is empty");
  build_surface_adjacency(surf);
  return surf;
}

void build_surface_adjacency(Surface& surf) {
  const Index ns = static_cast<Index>(surf.conn.size() / 4);

  // Nodes, and node -> segments: (node, segment) pairs sorted, a triangle's repeat counted once.
  std::vector<std::pair<Index, Index>> ns_pairs;
  ns_pairs.reserve(surf.conn.size());
  for (Index s = 0; s < ns; ++s)
    for (int k = 0; k < 4; ++k) {
      const Index n = surf.conn[4 * s + k];
      if (k == 3 && n == surf.conn[4 * s + 2]) continue;
      ns_pairs.emplace_back(n, s);
    }
  std::sort(ns_pairs.begin(), ns_pairs.end());
  ns_pairs.erase(std::unique(ns_pairs.begin(), ns_pairs.end()), ns_pairs.end());
  surf.nodes.clear();
  surf.node_segments.offset.assign(1, 0);
  surf.node_segments.value.clear();
  for (const auto& [n, s] : ns_pairs) {
    if (surf.nodes.empty() || surf.nodes.back() != n) {
      surf.nodes.push_back(n);
      surf.node_segments.offset.push_back(surf.node_segments.offset.back());
    }
    surf.node_segments.value.push_back(s);
    ++surf.node_segments.offset.back();
  }

  // Segment -> neighbours: segments grouped by edge (min node, max node); every pair in a group
  // shares that edge. Groups are small (2 on a manifold surface, a few at T-junctions).
  struct EdgeRef {
    Index a, b, s;
    bool operator<(const EdgeRef& o) const {
      return a != o.a ? a < o.a : (b != o.b ? b < o.b : s < o.s);
    }
  };
  std::vector<EdgeRef> edges;
  edges.reserve(surf.conn.size());
  for (Index s = 0; s < ns; ++s) {
    const Index* c = surf.conn.data() + 4 * s;
    const int n = c[2] == c[3] ? 3 : 4;
    for (int k = 0; k < n; ++k) {
      const Index p = c[k], q = c[(k + 1) % n];
      edges.push_back({std::min(p, q), std::max(p, q), s});
    }
  }
  std::sort(edges.begin(), edges.end());
  std::vector<std::pair<Index, Index>> nb;  // (segment, neighbour)
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j].a == edges[i].a && edges[j].b == edges[i].b) ++j;
    for (std::size_t p = i; p < j; ++p)
      for (std::size_t q = i; q < j; ++q)
        if (edges[p].s != edges[q].s) nb.emplace_back(edges[p].s, edges[q].s);
    i = j;
  }
  std::sort(nb.begin(), nb.end());
  nb.erase(std::unique(nb.begin(), nb.end()), nb.end());
  surf.segment_neighbors.offset.assign(static_cast<std::size_t>(ns) + 1, 0);
  surf.segment_neighbors.value.resize(nb.size());
  for (std::size_t i = 0; i < nb.size(); ++i) {
    ++surf.segment_neighbors.offset[nb[i].first + 1];
    surf.segment_neighbors.value[i] = nb[i].second;
  }
  for (Index s = 0; s < ns; ++s) surf.segment_neighbors.offset[s + 1] += surf.segment_neighbors.offset[s];
}

}  // namespace slideline
