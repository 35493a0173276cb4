// Penalty ties with failure (DYNA3D Types 8 and 9): issue 9.
#include "slideline/contact/make_tiebreak_contact.hpp"

#include "slideline/contact/tiebreak_contact.hpp"
#include "slideline/core/error.hpp"
#include "slideline/solver/build.hpp"

namespace slideline {

std::unique_ptr<ContactAlgorithm> make_tiebreak_contact(const model::Contact& card, const std::string& title,
                                                        const ContactBuildContext& ctx) {
  if (card.enforcement == model::Enforcement::lagrange)
    throw_contact_not_implemented(card, "tiebreak interfaces are penalty only");
  const bool by_segment = card.type == model::ContactType::tiebreak_surface;
  ContactSide slave = resolve_contact_side(card, true, ctx);
  ContactSide master = resolve_contact_side(card, false, ctx);
  if (master.surface.segment_count() == 0)
    throw InputError(describe(card.src) + ": MSID of " + card.keyword + " selects no master segments");
  if (by_segment && slave.surface.segment_count() == 0)
    throw InputError(describe(card.src) + ": SSID of " + card.keyword +
                     " (DYNA3D type 9) must select slave segments (SSTYP 0, 2, 3 or 5), not a node set");
  if (card.sfs <= 0.0)
    throw InputError(describe(card.src) + ": SFS of " + card.keyword + " must be positive");
  TiebreakParameters p;
  p.unit = by_segment ? TiebreakParameters::FailureUnit::segment : TiebreakParameters::FailureUnit::node;
  p.penalty_factor = ctx.model.control_contact.slsfac * card.sfs;
  p.normal_failure = card.nflf;
  p.shear_failure = card.sflf;
  p.normal_exponent = by_segment ? 2.0 : card.nen;
  p.shear_exponent = by_segment ? 2.0 : card.mes;
  p.friction.mu_s = card.fs;
  p.friction.mu_k = card.fd;
  p.friction.beta = card.dc;
  return std::make_unique<TiebreakContact>(title, std::move(slave.nodes),
                                           by_segment ? std::move(slave.surface) : Surface{},
                                           std::move(master.surface), p);
}

}  // namespace slideline
