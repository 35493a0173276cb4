#include "slideline/solver/mass_scaling.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace slideline {

PartAddedMass scale_block_mass(ElementBlock& block, NodalFields& nodes, Real block_mass, Real dt2ms) {
  PartAddedMass p;
  p.part = block.part_id();
  p.mass = block_mass;
  p.elements = block.element_count();
  // Set once at the start (no allocation in a step): the factors live only here.
  std::vector<Real> steps(static_cast<std::size_t>(p.elements), 0.0);
  block.reference_steps(nodes, steps);
  p.smallest_step = steps.empty() ? 0.0 : *std::min_element(steps.begin(), steps.end());
  std::vector<Real> factor(steps.size(), 1.0);
  for (std::size_t e = 0; e < steps.size(); ++e) {
    factor[e] = mass_scale_factor(steps[e], dt2ms);
    if (factor[e] != 1.0) ++p.scaled;
  }
  if (p.scaled > 0) p.added = block.scale_element_masses(factor, nodes);
  return p;
}

std::string describe(const PartAddedMass& p) {
  return fmt::format("part {}: mass {:.6g}, added {:.6g} ({:.3g}%), {} of {} elements scaled (smallest step {:.4g})",
                     p.part, p.mass, p.added, p.mass > 0.0 ? 100.0 * p.added / p.mass : 0.0, p.scaled, p.elements,
                     p.smallest_step);
}

}  // namespace slideline
