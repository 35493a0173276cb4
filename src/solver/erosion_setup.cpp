#include "erosion_setup.hpp"

#include <variant>

#include "build_support.hpp"
#include "slideline/solver/build.hpp"
#include "slideline/core/error.hpp"

namespace slideline {

std::unordered_map<Id, const model::MatAddErosion*> add_erosions_by_material(
    const model::Model& m, const std::unordered_map<Id, const model::Material*>& materials) {
  std::unordered_map<Id, const model::MatAddErosion*> out;
  for (const auto& a : m.add_erosions) {
    const auto it = materials.find(a.mid);
    if (it == materials.end())
      throw InputError(describe(a.src) + ": *MAT_ADD_EROSION card 1 field MID = " + std::to_string(a.mid) +
                       " refers to a material the deck does not define");
    if (std::holds_alternative<model::MatRigid>(*it->second))
      throw InputError(describe(a.src) + ": *MAT_ADD_EROSION card 1 field MID = " + std::to_string(a.mid) +
                       " is a *MAT_RIGID material, whose elements have no stress to fail");
    if (!out.emplace(a.mid, &a).second)
      throw InputError(describe(a.src) + ": a second *MAT_ADD_EROSION for material " + std::to_string(a.mid) +
                       " (the first at " + describe(out.at(a.mid)->src) + ")");
  }
  return out;
}

ErosionCriteria erosion_criteria(const MaterialLaws& laws, const model::MatAddErosion* add) {
  ErosionCriteria k;
  k.plastic_strain = laws.failure_strain;
  k.min_step = laws.min_step;
  k.max_relative_volume = laws.max_relative_volume;
  k.min_relative_volume = laws.min_relative_volume;
  if (!add) return k;
  const auto set = [](ErosionCriteria::Threshold& t, const std::optional<Real>& v) {
    t.on = v.has_value();
    t.value = v.value_or(0.0);
  };
  set(k.mxpres, add->mxpres);
  set(k.mnpres, add->mnpres);
  set(k.sigp1, add->sigp1);
  set(k.sigvm, add->sigvm);
  set(k.failtm, add->failtm);
  set(k.mneps, add->mneps);
  set(k.effeps, add->effeps);
  set(k.voleps, add->voleps);
  set(k.mxeps, add->mxeps);
  set(k.epssh, add->epssh);
  k.ncs = add->ncs;
  k.numfip = add->numfip;
  return k;
}

std::string erosion_description(const MaterialLaws& laws, const model::MatAddErosion* add) {
  std::string s;
  if (laws.failure_strain > 0.0)
    s += std::string(laws.failure_field) + " = " + std::to_string(laws.failure_strain) + " of " + laws.keyword;
  if (laws.min_step > 0.0)
    s += (s.empty() ? "" : ", ") + std::string("TDEL = ") + std::to_string(laws.min_step) + " of " + laws.keyword;
  if (laws.max_relative_volume > 0.0)
    s += (s.empty() ? "" : ", ") + std::string("TEROD = ") + std::to_string(laws.max_relative_volume) + " of " +
         laws.keyword;
  if (laws.min_relative_volume > 0.0)
    s += (s.empty() ? "" : ", ") + std::string("CEROD = ") + std::to_string(laws.min_relative_volume) + " of " +
         laws.keyword;
  if (add) s += (s.empty() ? "" : ", ") + std::string("*MAT_ADD_EROSION (") + describe(add->src) + ")";
  return s;
}

}  // namespace slideline
