// The table of the 19 sslide problems (report Appendix A, sections 3 and 6) and the model each
// one becomes: shared cards, one pairing per element interaction, one contact per pairing.
#include <algorithm>

#include "slideline/contact/search/closest_point.hpp"
#include "slideline/core/error.hpp"
#include "sslide_build.hpp"

namespace slideline::scenarios {

namespace {

using model::ContactType;
using model::Enforcement;
using Ideal = SslideIdealization;

/// Which element interactions a problem holds (report section 3.1).
enum class Pairings : std::uint8_t {
  surfaces,    ///< solid_on_solid, shell_on_solid, shell_on_shell (types 1, 2, 3, 10, 12)
  nodes,       ///< node_on_solid, node_on_shell (types 5, 6, 8)
  shell_edge,  ///< node_on_shell with the plate in the y-z plane (type 7)
  solid_only,  ///< solid_on_solid (type 9)
};

struct ProblemSpec {
  const char* name;
  const char* description;
  ContactType type;
  Enforcement enforcement;
  Ideal idealization;
  Pairings pairings;
  Real px, py;
  Real penalty_scale;  // DYNA3D's interface penalty factor; 0 = not penalty
  Real cells = 1.0;
  bool sliding_only_option = false;
  bool rigid_skin = false;
};

constexpr Real kPenaltyScale = 10.0;  // report 6.3.1: factor 10 for every penalty problem

// clang-format off
const ProblemSpec kProblems[] = {
  {"sslide1k", "Type 1 interface with kinematic enforcement.", ContactType::sliding_only, Enforcement::kinematic, Ideal::frictionless, Pairings::surfaces, 0.31, 10.0, 0.0},
  {"sslide2kc", "Type 2 interface with kinematic enforcement and compression loading.", ContactType::tied_surface, Enforcement::kinematic, Ideal::tied, Pairings::surfaces, 3.1, 10.0, 0.0},
  {"sslide2kt", "Type 2 interface with kinematic enforcement and tension loading.", ContactType::tied_surface, Enforcement::kinematic, Ideal::tied, Pairings::surfaces, -3.1, -10.0, 0.0},
  {"sslide3p", "Type 3 interface with penalty enforcement.", ContactType::surface_to_surface, Enforcement::penalty, Ideal::frictional, Pairings::surfaces, 3.1, 10.0, kPenaltyScale},
  {"sslide3l", "Type 3 interface with Lagrange enforcement.", ContactType::surface_to_surface, Enforcement::lagrange, Ideal::frictional, Pairings::surfaces, 3.1, 10.0, 0.0},
  {"sslide5p", "Type 5 interface with penalty enforcement.", ContactType::nodes_to_surface, Enforcement::penalty, Ideal::frictional, Pairings::nodes, 3.1, 10.0, kPenaltyScale},
  {"sslide5l", "Type 5 interface with Lagrange enforcement.", ContactType::nodes_to_surface, Enforcement::lagrange, Ideal::frictional, Pairings::nodes, 3.1, 10.0, 0.0},
  {"sslide6k", "Type 6 interface with kinematic enforcement.", ContactType::tied_nodes, Enforcement::kinematic, Ideal::tied, Pairings::nodes, 3.1, -10.0, 0.0},
  {"sslide7k", "Type 7 interface with kinematic enforcement.", ContactType::tied_shell_edge, Enforcement::kinematic, Ideal::tied, Pairings::shell_edge, 0.0, -10.0, 0.0},
  {"sslide8p", "Type 8 interface with penalty enforcement.", ContactType::tiebreak_nodes, Enforcement::penalty, Ideal::tension_failure, Pairings::nodes, 0.0, -10.0, kPenaltyScale},
  {"sslide9pt", "Type 9 interface with penalty enforcement and tension failure.", ContactType::tiebreak_surface, Enforcement::penalty, Ideal::tension_failure, Pairings::solid_only, 0.0, -10.0, 100.0},
  {"sslide9ps", "Type 9 interface with penalty enforcement and shear failure.", ContactType::tiebreak_surface, Enforcement::penalty, Ideal::shear_failure, Pairings::solid_only, 4.0, 10.0, kPenaltyScale},
  {"sslide10psl", "Type 10 interface with penalty enforcement and sliding only.", ContactType::one_way, Enforcement::penalty, Ideal::frictional, Pairings::surfaces, 3.1, 10.0, kPenaltyScale, 1.0, true},
  {"sslide10pv", "Type 10 interface with penalty enforcement and sliding with voids.", ContactType::one_way, Enforcement::penalty, Ideal::frictional, Pairings::surfaces, 3.1, 10.0, kPenaltyScale},
  {"sslide10lr", "Type 10 interface with Lagrange enforcement.", ContactType::one_way, Enforcement::lagrange, Ideal::frictional, Pairings::surfaces, 3.1, 10.0, 0.0, 1.0, false, true},
  {"sslide12p", "Type 12 interface with penalty enforcement.", ContactType::automatic, Enforcement::penalty, Ideal::frictional, Pairings::surfaces, 3.1, 10.0, kPenaltyScale},
  {"sslide12l", "Type 12 interface with Lagrange enforcement.", ContactType::automatic, Enforcement::lagrange, Ideal::frictional, Pairings::surfaces, 3.1, 10.0, 0.0},
  {"sslide12p_vec", "Type 12 interface with penalty enforcement and multiple unit cells.", ContactType::automatic, Enforcement::penalty, Ideal::frictional, Pairings::surfaces, 3.1, 10.0, kPenaltyScale, 17.0},
  {"sslide12l_vec", "Type 12 interface with Lagrange enforcement and multiple unit cells.", ContactType::automatic, Enforcement::lagrange, Ideal::frictional, Pairings::surfaces, 3.1, 10.0, 0.0, 17.0},
};
// clang-format on

/// Types whose interface offsets shell surfaces by half their thickness (report 3.1: 3, 5, 10,
/// 12; type 5 through the nodal radius and the master thickness option). The upper body then
/// starts at that distance, so the bodies touch without load.
bool offsets_shells(ContactType t) {
  return t == ContactType::surface_to_surface || t == ContactType::nodes_to_surface || t == ContactType::one_way ||
         t == ContactType::automatic;
}

constexpr Real kShellThickness = 0.1;

struct PairingPlan {
  const char* name;
  bool upper_shell, edge_plate, skin;
  int half_thicknesses;  // gap in half shell thicknesses when the type offsets shells
};

std::vector<PairingPlan> plan(Pairings p) {
  switch (p) {
    case Pairings::surfaces:
      return {{"solid_on_solid", false, false, false, 0},
              {"shell_on_solid", true, false, false, 1},
              {"shell_on_shell", true, false, true, 2}};
    case Pairings::nodes:
      return {{"node_on_solid", true, false, false, 1}, {"node_on_shell", true, false, true, 2}};
    case Pairings::shell_edge:
      return {{"node_on_shell", false, true, true, 0}};
    case Pairings::solid_only:
      return {{"solid_on_solid", false, false, false, 0}};
  }
  return {};
}

void add_common_cards(model::Model& m, const ProblemSpec& s, bool shells, bool rigid, detail::SslideCommonIds& c,
                      detail::SslideIds& ids) {
  m.title = std::string(s.name) + ": " + s.description + " (LLNL DYNA3D contact verification, scenario 1)";
  c.solid_material = 1;
  m.materials.push_back(model::MatMooneyRivlin{1, 0.01, 0.1, 909.091, 0.0, "mooney_rivlin_block", {}});
  c.solid_section = 1;
  m.solid_sections.push_back({1, 1, {}});
  c.solid_hourglass = 1;
  m.hourglasses.push_back({1, 10, 1.0, 1.5, 0.06, {}});
  if (shells) {
    c.shell_material = 2;
    m.materials.push_back(model::MatElastic{2, 0.1, 1000.0, 0.1, "elastic_shell", {}});
    c.shell_section = 2;
    model::SectionShell sec;
    sec.secid = 2;
    sec.elform = 2;
    sec.nip = 5;
    sec.t = {kShellThickness, kShellThickness, kShellThickness, kShellThickness};
    m.shell_sections.push_back(sec);
    c.shell_hourglass = 2;
    m.hourglasses.push_back({2, 2, 0.1, 1.5, 0.06, {}});
  }
  if (rigid) {
    c.rigid_material = 3;
    m.materials.push_back(model::MatRigid{3, 0.1, 1000.0, 0.1, 0.0, 0, 0, "rigid_skin", {}});
  }
  m.bulk_viscosity = {1.5, 0.06};
  m.curves.push_back({1, "load_y", 0, 1.0, 1.0, 0.0, 0.0, 0, {{0.0, 0.0}, {0.1, 1.0}, {1000.0, 1.0}}, {}});
  m.curves.push_back({2, "load_x", 0, 1.0, 1.0, 0.0, 0.0, 0, {{0.0, 0.0}, {0.3, 0.0}, {0.4, 1.0}, {1000.0, 1.0}}, {}});
  // *LOAD_BODY is a base acceleration (docs/keywords.md): +SF pushes along -y; P / (mass 0.01 per
  // unit cell) is the same for every pairing and for the stacked bodies.
  const Real unit_mass = 0.01;
  m.body_loads.push_back({Axis::y, 1, s.py / unit_mass, 0, 0, 0, 0, 0, {}});
  if (s.px != 0.0) m.body_loads.push_back({Axis::x, 2, -s.px / unit_mass, 0, 0, 0, 0, 0, {}});
  c.loaded_parts = ids.next_set++;
  m.part_sets.push_back({c.loaded_parts, "upper_bodies", {}, {}});
  m.body_load_parts = model::LoadBodyParts{c.loaded_parts, {}};
  // 5 % of critical at 150 rad/s, mass proportional: alpha = 2 * 0.05 * 150 = 15 1/T.
  m.damping_global = model::DampingGlobal{0, 2.0 * 0.05 * 150.0, {0, 0, 0, 0, 0, 0}, {}};
  m.termination.endtim = 0.5;
  m.timestep.tssfac = s.type == ContactType::automatic ? 0.6 : 0.9;
  // Shell thickness in the non-automatic contacts that account for it (type 12 always does).
  m.control_contact.shlthk = (offsets_shells(s.type) && s.type != ContactType::automatic) ? 1 : 0;
  const Real history = 0.001;
  m.database.rcforc = m.database.spcforc = m.database.nodout = m.database.glstat = history;
  m.database.d3plot = 0.05;
}

model::Contact make_contact(const ProblemSpec& s, const SslidePairing& p, const PairingPlan& plan,
                            const detail::SslidePairingSets& sets, Id cid) {
  model::Contact c;
  c.cid = cid;
  c.title = p.contact_title;
  c.type = s.type;
  c.enforcement = s.enforcement;
  c.sliding_only_option = s.sliding_only_option;
  const bool node_slaves = s.type == ContactType::nodes_to_surface || s.type == ContactType::tied_nodes ||
                           s.type == ContactType::tiebreak_nodes || s.type == ContactType::tied_shell_edge;
  if (s.type == ContactType::automatic) {
    c.ssid = sets.contact_parts;  // every node a slave, every segment a master, within the pair
    c.sstyp = 2;
  } else {
    if (node_slaves) {
      c.ssid = sets.upper_nodes;
      c.sstyp = 4;
    } else if (plan.upper_shell) {
      c.ssid = p.upper_part;
      c.sstyp = 3;
    } else {
      c.ssid = sets.upper_segments;
      c.sstyp = 0;
    }
    if (plan.skin) {
      c.msid = p.skin_part;
      c.mstyp = 3;
    } else {
      c.msid = sets.lower_segments;
      c.mstyp = 0;
    }
  }
  // Friction (report Table 2) wherever the interface slides with friction, including after a
  // tiebreak fails (types 8 and 9 then behave as types 5 and 3).
  const bool friction = s.idealization == Ideal::frictional || s.idealization == Ideal::shear_failure ||
                        s.idealization == Ideal::tension_failure;
  if (friction) {
    c.fs = 0.30;
    c.fd = 0.25;
    c.dc = s.enforcement == Enforcement::lagrange ? 1.3 : 2.0;
  }
  // DYNA3D's interface penalty factor multiplies the default stiffness exactly as LS-DYNA's
  // SFS/SFM multiply SLSFAC (left at its default 0.1): factor 10 is SFS = SFM = 10.
  if (s.penalty_scale > 0.0) c.sfs = c.sfm = s.penalty_scale;
  if (s.type == ContactType::nodes_to_surface) c.radius = c.sst = 0.5 * kShellThickness;
  if (s.type == ContactType::tiebreak_nodes) {
    c.nflf = 1.0;  // report 6.7: F_nf = 1.0, F_sf = 1e4, m = n = 2
    c.sflf = 1.0e4;
    c.nen = c.mes = 2.0;
  }
  if (s.type == ContactType::tiebreak_surface) {
    const bool tension = s.idealization == Ideal::tension_failure;
    c.nfls = c.nflf = tension ? 9.0 : 1.0e4;  // report 6.8: stresses; slave area 1
    c.sfls = c.sflf = tension ? 1.0e4 : 3.5;
  }
  return c;
}

const ProblemSpec& find_spec(const std::string& name) {
  for (const auto& s : kProblems)
    if (name == s.name) return s;
  std::string known;
  for (const auto& s : kProblems) known += std::string(known.empty() ? "" : ", ") + s.name;
  throw InputError("unknown sslide problem '" + name + "' (known: " + known + ")");
}

}  // namespace

std::vector<std::string> sslide_problem_names() {
  std::vector<std::string> v;
  for (const auto& s : kProblems) v.emplace_back(s.name);
  return v;
}

SslideProblem make_sslide_problem(const std::string& name) {
  const ProblemSpec& s = find_spec(name);
  SslideProblem out;
  out.name = s.name;
  out.description = s.description;
  out.type = s.type;
  out.enforcement = s.enforcement;
  out.idealization = s.idealization;
  out.px = s.px;
  out.py = s.py;
  out.cells = s.cells;
  out.penalty_scale = s.penalty_scale;
  if (s.idealization == Ideal::frictional || s.idealization == Ideal::shear_failure ||
      s.idealization == Ideal::tension_failure) {
    out.mu_s = 0.30;
    out.mu_k = 0.25;
    out.beta = s.enforcement == Enforcement::lagrange ? 1.3 : 2.0;
  }
  if (s.idealization == Ideal::tension_failure) {
    out.failure_force = 9.0;  // reached by the y ramp (10 t / 0.1) at t = 0.09
    out.failure_time = 0.09;
  } else if (s.idealization == Ideal::shear_failure) {
    out.failure_force = 3.5;  // reached by the x ramp (4 (t - 0.3) / 0.1) at t = 0.3875
    out.failure_time = 0.3875;
  }

  const auto plans = plan(s.pairings);
  const bool shells = std::any_of(plans.begin(), plans.end(), [](const PairingPlan& p) {
    return p.upper_shell || p.edge_plate || p.skin;
  });
  model::Model& m = out.model;
  detail::SslideIds ids{detail::MeshWriter(m, 1, 1), 1, 1};
  detail::SslideCommonIds common;
  add_common_cards(m, s, shells, s.rigid_skin, common, ids);

  Id cid = 1;
  for (std::size_t k = 0; k < plans.size(); ++k) {
    const auto& pl = plans[k];
    detail::SslidePairingRequest r;
    r.name = pl.name;
    r.x0 = kPairingSpacing * static_cast<Real>(k);
    r.cells = s.cells;
    r.gap = offsets_shells(s.type) ? 0.5 * kShellThickness * pl.half_thicknesses : 0.0;
    r.upper_shell = pl.upper_shell;
    r.upper_edge_plate = pl.edge_plate;
    r.skin = pl.skin;
    r.rigid_skin = pl.skin && s.rigid_skin;
    r.px = s.px * s.cells;
    r.py = s.py * s.cells;
    detail::SslidePairingSets sets;
    out.pairings.push_back(detail::add_sslide_pairing(m, common, ids, r, sets));
    m.contacts.push_back(make_contact(s, out.pairings.back(), pl, sets, cid++));
  }
  return out;
}

Vec3 relative_displacement(const SslideMonitor& monitor, const Vec3& u_slave, const std::array<Vec3, 4>& u_master) {
  Vec3 u = u_slave;
  for (int k = 0; k < 4; ++k) u -= monitor.weights[k] * u_master[k];
  return u;
}

Vec3 tracked_relative_displacement(const SslideMonitor& monitor, const Vec3& u_slave,
                                   const std::vector<std::array<Vec3, 4>>& u_path) {
  const Vec3 x = monitor.slave_x0 + u_slave;
  Projection best;
  std::size_t best_s = 0;
  for (std::size_t s = 0; s < monitor.path.size() && s < u_path.size(); ++s) {
    SegmentCorners c;
    for (int k = 0; k < 4; ++k) c[k] = monitor.path[s].x0[k] + u_path[s][k];
    const Projection pr = project_point_to_quad(x, c);
    if (s == 0 || is_better_projection(pr, static_cast<Index>(s), best, static_cast<Index>(best_s))) {
      best = pr;
      best_s = s;
    }
  }
  Vec3 u = u_slave;
  for (int k = 0; k < 4; ++k) u -= best.shape[k] * u_path[best_s][k];
  return u;
}

}  // namespace slideline::scenarios
