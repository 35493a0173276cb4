#pragma once
/// The step vote of a contact spring on nodes that also carry elements (docs/solver.md, "The step
/// of a node with elements and a contact spring").
///
/// A node held by its elements and pushed by a contact spring vibrates with both stiffnesses: the
/// squared frequencies add, omega^2 = omega_e^2 + omega_c^2. With dt = 2 / omega for each, the
/// bound on the step is
///
///     1 / dt^2 = 1 / dt_e^2 + 1 / dt_c^2,
///
/// dt_e the elements' stable step at the node (their vote, before TSSFAC), dt_c the spring's own
/// (2 / omega_c, omega_c^2 = k (1/m_s + sum N_a^2 / m_a), before TSSFAC). Each spring alone allows
/// its own step; together they allow less (by 1/sqrt(2) when the two are equal). Every contact
/// family that votes (penalty passes, SOFT = 2 segment pairs, tiebreak ties) forms its pairs'
/// 1 / dt^2 with combined_step_inv2(), from the largest element term of the nodes the pair joins
/// (ElementStepsView::pair, ::largest), and votes 1 / sqrt of the largest over its pairs.
#include <algorithm>
#include <cstddef>
#include <span>

#include "slideline/core/types.hpp"

namespace slideline {

/// Per node, 1 / dt_e^2 (1 / time^2) of the elements on it at this cycle's force evaluation: the
/// solver fills it (solver/nodal_element_steps.hpp) and hands it to the interfaces in StepTimes.
/// Empty (the default, and with SimulationControls::contact_step_with_elements off): 0 everywhere,
/// the springs vote alone.
class ElementStepsView {
 public:
  ElementStepsView() = default;
  /// `group`: per node, the index of its group (the set of element blocks it belongs to);
  /// `group_inv2`: per group, 1 / dt_e^2 (0: no element of the group bounds the step).
  ElementStepsView(std::span<const Index> group, std::span<const Real> group_inv2)
      : group_(group), group_inv2_(group_inv2) {}

  bool empty() const { return group_.empty(); }
  /// 1 / dt_e^2 at `node` (1 / time^2); 0 when no element bounds its step or the view is empty.
  Real at(Index node) const {
    return group_.empty() ? 0.0 : group_inv2_[static_cast<std::size_t>(group_[static_cast<std::size_t>(node)])];
  }
  /// The largest 1 / dt_e^2 of nodes[a] over the a < count whose weight[a] is not 0 (the master
  /// nodes a pair is coupled to); 0 for an empty view.
  template <class Weights>
  Real largest(const Index* nodes, const Weights& weight, int count) const {
    Real w = 0.0;
    if (group_.empty()) return w;
    for (int a = 0; a < count; ++a)
      if (weight[static_cast<std::size_t>(a)] != 0.0) w = std::max(w, at(nodes[a]));
    return w;
  }
  /// The element term of a pair: the largest 1 / dt_e^2 of its `slave` node and of the master
  /// nodes it is coupled to (weights not 0).
  template <class Weights>
  Real pair(Index slave, const Index* masters, const Weights& weight, int count) const {
    return group_.empty() ? 0.0 : std::max(at(slave), largest(masters, weight, count));
  }

 private:
  std::span<const Index> group_;
  std::span<const Real> group_inv2_;
};

/// 1 / dt^2 (1 / time^2) of a spring whose own bound is `spring_inv2` = 1 / dt_c^2 = omega_c^2 / 4
/// on nodes whose elements' bound is `element_inv2` = 1 / dt_e^2 (the largest over the nodes it
/// joins): their sum. A spring that does not vote (spring_inv2 = 0) stays 0: a node without a
/// spring is the elements' business. With element_inv2 = 0 the result is spring_inv2 exactly.
inline Real combined_step_inv2(Real spring_inv2, Real element_inv2) {
  return spring_inv2 > 0.0 ? spring_inv2 + element_inv2 : spring_inv2;
}

}  // namespace slideline
