// Types 3, 5, 10 and 12 with Lagrange-multiplier enforcement (the _LAGRANGE keyword suffix):
// the resolved card (InterfaceSpec) becomes a LagrangeContact (contact/lagrange_contact.hpp).
#include <variant>

#include "slideline/contact/lagrange_contact.hpp"
#include "slideline/contact/make_contact_interface.hpp"

namespace slideline {

namespace {

/// Translations (rotations = false: CON1) or rotations (CON2) held by the *MAT_RIGID constraints
/// (CMO = +1, codes as in LS-DYNA: 1 x, 2 y, 3 z, 4 xy, 5 yz, 6 zx, 7 xyz) of every rigid part;
/// the builder has validated the codes.
std::vector<std::pair<Id, std::array<int, 3>>> rigid_fixed_dofs(const model::Model& model, bool rotations) {
  static constexpr std::array<std::array<int, 3>, 8> codes{
      {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}, {1, 1, 1}}};
  std::vector<std::pair<Id, std::array<int, 3>>> out;
  for (const auto& part : model.parts)
    for (const auto& mat : model.materials)
      if (const auto* r = std::get_if<model::MatRigid>(&mat); r && r->mid == part.mid && r->cmo == 1.0) {
        const int code = rotations ? r->con2 : r->con1;
        if (code >= 0 && code <= 7) out.emplace_back(part.pid, codes[static_cast<std::size_t>(code)]);
      }
  return out;
}

/// The dofs of rigid parts that *BOUNDARY_PRESCRIBED_MOTION_RIGID drives (validate_model: PID a
/// *MAT_RIGID part, DOF 1-3 or 5-7), with their birth and death times.
std::vector<RigidMasterDrive> rigid_drives(const model::Model& model) {
  std::vector<RigidMasterDrive> out;
  for (const auto& pm : model.prescribed_motions)
    if (pm.target == model::PrescribedMotion::Target::rigid && ((pm.dof >= 1 && pm.dof <= 3) || (pm.dof >= 5 && pm.dof <= 7)))
      out.push_back({pm.nsid, pm.dof <= 3 ? pm.dof - 1 : pm.dof - 2, pm.birth, pm.death});
  return out;
}

}  // namespace

void set_rigid_master_constraints(LagrangeContactSettings& s, const model::Model& model) {
  s.rigid_fixed_translations = rigid_fixed_dofs(model, false);
  s.rigid_fixed_rotations = rigid_fixed_dofs(model, true);
  s.rigid_drives = rigid_drives(model);
}

std::unique_ptr<ContactAlgorithm> make_lagrange_contact(InterfaceSpec& spec, const ContactBuildContext& ctx) {
  const bool automatic = spec.type == model::ContactType::automatic;
  LagrangeContactSettings s;
  s.title = spec.title;
  s.friction = spec.friction;
  s.shell_offsets = spec.slave_shells.on;
  s.slave_thickness = spec.slave_shells.thickness;
  s.master_thickness = spec.master_shells.thickness;
  s.slave_thickness_scale = spec.slave_shells.scale;
  s.master_thickness_scale = spec.master_shells.scale;
  // Node-set slaves stand off by the nodal radius; surface slaves by their shell offsets only
  // (penalty Type 5 takes the larger of the two: docs/contact.md, "Offsets").
  if (spec.node_set_slaves) s.nodal_radius = spec.nodal_radius;
  s.skip_incident = automatic;
  s.one_constraint_per_mutual_pair = automatic;  // no over-constrained pairs (lagrange_contact.hpp)
  set_rigid_master_constraints(s, ctx.model);
  s.transmitted_output = spec.transmitted_output;
  s.mortar = spec.mortar_coupling;  // _MORTAR (check_runs refuses it on Type 12 and node sets)
  std::vector<Index> first;
  if (automatic && !spec.slave.parts.empty())
    first = ctx.sets.nodes_of_part(spec.slave.parts.front(), spec.where + ": SSID");
  // Node-set slaves (Type 5) are oriented by the faces of the parts they lie on
  // (search/slave_orientation.hpp); a slave surface orients its own nodes.
  Surface faces;
  if (spec.node_set_slaves) faces = node_set_faces(spec.slave.nodes, ctx, spec.where + ": SSID");
  auto contact = std::make_unique<LagrangeContact>(std::move(s), std::move(spec.master.surface),
                                                   std::move(spec.slave.nodes), std::move(spec.slave.surface),
                                                   std::move(first));
  contact->set_orientation_surface(std::move(faces));
  return contact;
}

}  // namespace slideline
