#pragma once
// Small models with closed-form answers beyond the spec's geometry (issue 18), built in C++ with
// the model API: boxes of hexahedra in a rotated frame, contact cards of every type, and a run
// loop that maps deck ids to internal nodes. Shared by test_general_contact.cpp (bars colliding
// end on) and test_incline_contact.cpp (a block sliding down an inclined plane).
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "slideline/model/model.hpp"
#include "slideline/solver/build.hpp"
#include "slideline/solver/simulation.hpp"

namespace slideline::test_support {

using Mat3 = Eigen::Matrix<Real, 3, 3>;

/// A rigid placement of a model: p -> R p (about the origin). Identity, or the oblique rotation.
struct Frame {
  Mat3 r = Mat3::Identity();
  Vec3 map(const Vec3& p) const { return r * p; }
};

/// 0.7 rad about the axis (1, 2, 3) / sqrt(14): no coordinate plane or axis stays put.
inline Frame oblique_frame() {
  Frame f;
  f.r = Eigen::AngleAxis<Real>(0.7, Vec3(1.0, 2.0, 3.0).normalized()).toRotationMatrix();
  return f;
}

/// Node ids of an (nx+1) x (ny+1) x (nz+1) grid, i fastest.
struct BoxIds {
  int nx = 1, ny = 1, nz = 1;
  std::vector<Id> node;
  Id at(int i, int j, int k) const {
    return node[static_cast<std::size_t>(i + (nx + 1) * (j + (ny + 1) * k))];
  }
  /// Nodes of the face i = const.
  std::vector<Id> face_i(int i) const {
    std::vector<Id> out;
    for (int k = 0; k <= nz; ++k)
      for (int j = 0; j <= ny; ++j) out.push_back(at(i, j, k));
    return out;
  }
  /// Nodes of the face j = const.
  std::vector<Id> face_j(int j) const {
    std::vector<Id> out;
    for (int k = 0; k <= nz; ++k)
      for (int i = 0; i <= nx; ++i) out.push_back(at(i, j, k));
    return out;
  }
};

/// Appends a box [origin, origin + size] of nx x ny x nz hexahedra of part `pid` (LS-DYNA node
/// order, positive volume), placed by `frame`.
inline BoxIds add_box(model::Model& m, Id pid, const Vec3& origin, const Vec3& size, std::array<int, 3> n,
                      const Frame& frame) {
  BoxIds b{n[0], n[1], n[2], {}};
  Id next_node = 1, next_elem = 1;
  for (const auto& nd : m.nodes) next_node = std::max(next_node, nd.id + 1);
  for (const auto& e : m.solids) next_elem = std::max(next_elem, e.id + 1);
  for (int k = 0; k <= n[2]; ++k)
    for (int j = 0; j <= n[1]; ++j)
      for (int i = 0; i <= n[0]; ++i) {
        const Vec3 p = origin + Vec3(size[0] * i / n[0], size[1] * j / n[1], size[2] * k / n[2]);
        m.nodes.push_back({next_node, frame.map(p), 0, 0});
        b.node.push_back(next_node++);
      }
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i)
        m.solids.push_back({next_elem++, pid,
                            {b.at(i, j, k), b.at(i + 1, j, k), b.at(i + 1, j + 1, k), b.at(i, j + 1, k),
                             b.at(i, j, k + 1), b.at(i + 1, j, k + 1), b.at(i + 1, j + 1, k + 1),
                             b.at(i, j + 1, k + 1)},
                            0, 0});
  return b;
}

/// An elastic part (material, section and part of id `pid`), hourglass control `ihq` (1: the
/// default viscous form; 10: total-displacement physical stiffness, the spec's).
inline void add_elastic_part(model::Model& m, Id pid, Real rho, Real e, Real nu, int ihq = 1) {
  m.materials.push_back(model::MatElastic{pid, rho, e, nu, "elastic", {}});
  m.solid_sections.push_back({pid, 1, {}});
  Id hgid = 0;
  if (ihq != 1) {
    hgid = pid;
    m.hourglasses.push_back({hgid, ihq, ihq == 10 ? 1.0 : 0.1, 1.5, 0.06, {}});
  }
  m.parts.push_back({pid, "part" + std::to_string(pid), pid, pid, 0, hgid, {}});
}

/// One interface of every type that applies (DYNA3D numbering) between a slave and a master part.
struct ContactChoice {
  model::ContactType type = model::ContactType::surface_to_surface;
  model::Enforcement enforcement = model::Enforcement::penalty;
  /// An LS-DYNA automatic card of the type family (e.g. *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE).
  model::ContactForm form = model::ContactForm::dyna3d;
  std::string name() const {
    if (form == model::ContactForm::automatic_surface_to_surface) return "auto_s2s_penalty";
    if (form == model::ContactForm::automatic_nodes_to_surface) return "auto_n2s_penalty";
    if (form == model::ContactForm::forming_one_way) return "forming_one_way_penalty";
    return "type" + std::to_string(static_cast<int>(type)) +
           (enforcement == model::Enforcement::lagrange ? "_lagrange" : "_penalty");
  }
};

/// The DYNA3D types (penalty and Lagrange), then the LS-DYNA automatic cards (penalty).
inline std::vector<ContactChoice> all_contact_choices() {
  using T = model::ContactType;
  using E = model::Enforcement;
  std::vector<ContactChoice> out;
  for (T t : {T::surface_to_surface, T::nodes_to_surface, T::one_way, T::automatic})
    for (E e : {E::penalty, E::lagrange}) out.push_back({t, e});
  for (model::ContactForm f : {model::ContactForm::automatic_surface_to_surface,
                               model::ContactForm::automatic_nodes_to_surface, model::ContactForm::forming_one_way})
    out.push_back({T::automatic, E::penalty, f});
  return out;
}

/// The card: slave part `slave_pid` (Type 5 and *CONTACT_AUTOMATIC_NODES_TO_SURFACE: node set
/// `slave_nodes` of that part's nodes; Type 12 single surface: part set `pair_set` of both parts),
/// master part `master_pid`, Coulomb friction mu (FS = FD,
/// DC 0), penalty factor SFS = SFM = 10 (f = 1 with SLSFAC 0.1, the spec's).
inline model::Contact contact_card(const ContactChoice& c, Id slave_pid, Id master_pid, Id slave_nodes, Id pair_set,
                                   Real mu) {
  model::Contact card;
  card.type = c.type;
  card.enforcement = c.enforcement;
  card.form = c.form;
  card.keyword = "*CONTACT (" + c.name() + ")";
  card.title = c.name();
  card.ssid = slave_pid;
  card.sstyp = 3;
  card.msid = master_pid;
  card.mstyp = 3;
  if (c.type == model::ContactType::nodes_to_surface || c.form == model::ContactForm::automatic_nodes_to_surface) {
    card.ssid = slave_nodes;
    card.sstyp = 4;
  } else if (c.type == model::ContactType::automatic && c.form == model::ContactForm::dyna3d) {
    card.ssid = pair_set;
    card.sstyp = 2;
    card.msid = 0;
    card.mstyp = 0;
  }
  card.fs = card.fd = mu;
  card.sfs = card.sfm = 10.0;
  return card;
}

/// A built simulation with deck id -> internal index lookup.
struct Run {
  std::unique_ptr<Simulation> sim;
  std::unordered_map<Id, Index> index;
  explicit Run(const model::Model& m) : sim(build_simulation(m)) {
    sim->initialize();
    for (std::size_t i = 0; i < sim->nodes().ids.size(); ++i) index[sim->nodes().ids[i]] = static_cast<Index>(i);
  }
  Vec3 x(Id id) const { return sim->nodes().x.get(index.at(id)); }
  Vec3 v(Id id) const { return sim->nodes().v.get(index.at(id)); }
  Real mass(Id id) const { return sim->nodes().mass[static_cast<std::size_t>(index.at(id))]; }
  /// Mass-weighted mean of `field` over `ids`.
  template <class F>
  Vec3 mean(const std::vector<Id>& ids, F field) const {
    Vec3 s = Vec3::Zero();
    Real m = 0.0;
    for (Id id : ids) {
      s += mass(id) * field(id);
      m += mass(id);
    }
    return s / m;
  }
};

}  // namespace slideline::test_support
