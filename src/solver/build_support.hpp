#pragma once
// Private to the builder (build.cpp): id lookups with located errors, the deck-to-solver
// conversions and the field checks it needs. Moved out of build.cpp unchanged.
#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "slideline/core/error.hpp"
#include "slideline/element/block_options.hpp"
#include "slideline/model/model.hpp"
#include "slideline/solver/build.hpp"
#include "slideline/mesh/mesh_sets.hpp"
#include "slideline/solver/boundary.hpp"
#include "slideline/solver/load_curve.hpp"
#include "slideline/solver/nodal_constraint.hpp"

namespace slideline {

/// Appends to `g` one zero-displacement support of `nodes` per nonzero flag of `dof` (x, y, z,
/// rx, ry, rz), the translation or rotation about global axis `axis_of[d % 3]` (a *BOUNDARY_SPC
/// CID whose axes are global axes permutes them; *NODE TC/RC codes do not).
void add_fixed_components(SupportGroup& g, const std::vector<Index>& nodes, const std::array<int, 6>& dof,
                          const std::array<int, 3>& axis_of = {0, 1, 2});

/// The one scale factor of LS-DYNA's per-direction damping factors STX..SRZ when they all agree
/// (all blank/0 means 1, as LS-DYNA reads them), else nothing: directions damped differently are
/// not implemented.
std::optional<Real> common_direction_factor(const std::array<Real, 6>& stf);

/// Id -> record lookups with errors that name the referring card.
template <class T>
class IdTable {
 public:
  IdTable(const std::vector<T>& items, Id (*key)(const T&), const char* what) : what_(what) {
    for (const auto& it : items) {
      const Id k = key(it);
      if (!map_.emplace(k, &it).second)
        throw InputError(describe(it.src) + ": duplicate " + what_ + " id " + std::to_string(k));
    }
  }
  const T& at(Id id, const model::Source& from, const char* field) const {
    const auto f = map_.find(id);
    if (f == map_.end())
      throw InputError(describe(from) + ": " + field + " refers to " + what_ + " " +
                       std::to_string(id) + ", which the deck does not define");
    return *f->second;
  }
  bool contains(Id id) const { return map_.count(id) != 0; }

 private:
  std::string what_;
  std::unordered_map<Id, const T*> map_;
};

/// A *DEFINE_CURVE with its scale factors and offsets applied.
LoadCurve make_curve(const model::Curve& c);

/// LS-DYNA *MAT_RIGID constraint codes (CMO = +1): 0 none, 1 x, 2 y, 3 z, 4 x+y, 5 y+z, 6 z+x, 7 all
/// (the fixed axes); nothing for another code (validate_model refuses it).
std::optional<std::array<int, 3>> rigid_constraint_code(int code);

/// NIP of a *SECTION_SHELL, 0 meaning LS-DYNA's default 2.
int shell_nip(const model::SectionShell& sec);

/// *DAMPING_PART_STIFFNESS[_SET] by part id. COEF < 0 is the classical (LS-DYNA 950) Rayleigh
/// coefficient beta = -COEF (validate_model refuses COEF > 0, LS-DYNA's later, unpublished formulation).
std::map<Id, StiffnessDamping> stiffness_damping(const model::Model& m, const IdTable<model::Part>& parts);

/// The hexahedron hourglass kind of an IHQ (1-3 viscous, 4-5 Flanagan-Belytschko stiffness, 6 assumed
/// strain, 10 physical stiffness; 0 means the default); nothing for the other types (validate_model refuses them, naming the part).
std::optional<HexHourglass::Kind> hex_hourglass_kind(int ihq);

/// What the builder knows when it resolves a *RIGIDWALL_PLANAR (build_rigid_wall.cpp).
struct RigidWallContext {
  const MeshSets& sets;
  const std::vector<SupportGroup>& supports;
  const std::unordered_map<Index, Id>& rigid_node_part;  ///< node -> the rigid part that moves it
  const std::vector<Id>& node_ids;                       ///< deck id of each node
};

/// The k-th (1-based) *RIGIDWALL_PLANAR card as a RigidWall (slave nodes, fixed components,
/// geometry); throws InputError naming the card for what cannot be built.
std::unique_ptr<NodalConstraint> make_rigid_wall(const model::RigidWallPlanar& card, std::size_t k,
                                                 const RigidWallContext& ctx);

/// The hexahedron hourglass control of a validated IHQ and its coefficient QM.
HexHourglass hex_hourglass(int ihq, Real qm);

}  // namespace slideline
