#pragma once
/// Factory of the penalty ties with failure (DYNA3D Types 8 and 9), TiebreakContact.
#include <memory>
#include <string>

#include "slideline/contact/make_contact_interface.hpp"

namespace slideline {

/// Type 8 (nodes spotwelded: SSID a node set or a surface's nodes, failure per node, NFLF/SFLF
/// forces, NEN/MES exponents) and Type 9 (tied surfaces with failure: SSID a surface, failure
/// per slave segment, NFLF/SFLF stresses). Penalty factor SLSFAC x SFS; friction FS, FD, DC after
/// failure. Throws InputError (naming the card's file:line) for a missing slave or master surface,
/// NotImplementedError for Lagrange enforcement.
std::unique_ptr<ContactAlgorithm> make_tiebreak_contact(const model::Contact& card, const std::string& title,
                                                        const ContactBuildContext& ctx);

}  // namespace slideline
