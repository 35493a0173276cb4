// *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK (OPTION 2): Type 9's tie, then the automatic
// surface-to-surface pass. See include/slideline/contact/automatic_tiebreak_contact.hpp.
#include "slideline/contact/automatic_tiebreak_contact.hpp"

namespace slideline {

void AutomaticTiebreakContact::initialize(const ContactContext& c) {
  tie_->initialize(c);
  // The pass first sees every pair (nothing held yet): each node's penetration at t = 0 becomes
  // its spring's zero (IGNORE = 1), a tied node's included, so that a released node starts from
  // where it was tied.
  std::fill(held_node_.begin(), held_node_.end(), std::uint8_t{0});
  std::fill(held_segment_.begin(), held_segment_.end(), std::uint8_t{0});
  contact_->initialize(c);
  refresh_held();
}

void AutomaticTiebreakContact::refresh_held() {
  const std::vector<TiePoint>& links = tie_->links();
  const std::vector<std::uint8_t>& released = tie_->released();
  for (std::size_t k = 0; k < links.size(); ++k)
    held_node_[static_cast<std::size_t>(links[k].slave)] = released[k] ? 0 : 1;
  const std::vector<std::uint8_t>& failed = tie_->failed_segments();
  for (std::size_t j = 0; j < failed.size(); ++j)
    held_segment_[static_cast<std::size_t>(contact_segment_[j])] = failed[j] ? 0 : 1;
}

void AutomaticTiebreakContact::apply_forces(const NodalFields& nodes, const StepTimes& times, ContactForceView out) {
  // The failures found last cycle hand their nodes over now (the tie applies them from this cycle).
  refresh_held();
  contact_->phases().forces->apply_forces(nodes, times, out);
  tie_->apply_forces(nodes, times, out);
}

}  // namespace slideline
