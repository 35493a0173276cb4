#include "slideline/solver/material_registry.hpp"

#include <variant>

#include "slideline/core/overloaded.hpp"

namespace slideline {

MaterialLaws material_laws(const model::Material& material) {
  return std::visit(
      Overloaded{
          [](const model::MatElastic& m) {
            return MaterialLaws{ElasticSolid(m.ro, m.e, m.pr), ElasticShell(m.ro, m.e, m.pr), false,
                                "*MAT_ELASTIC"};
          },
          [](const model::MatMooneyRivlin& m) {
            return MaterialLaws{MooneyRivlin(m.ro, m.a, m.b, m.pr), std::nullopt, false,
                                "*MAT_MOONEY-RIVLIN_RUBBER"};
          },
          [](const model::MatRigid&) {
            return MaterialLaws{std::nullopt, std::nullopt, true, "*MAT_RIGID"};
          },
      },
      material);
}

}  // namespace slideline
