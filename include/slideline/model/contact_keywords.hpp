#pragma once
/// The one table of the *CONTACT_... keywords: for each supported base name, the DYNA3D interface
/// type it maps to, its default enforcement and the name `blockcontact check` prints. The keyword
/// reader parses names through it, the writer writes names from it, and the CLI prints from it:
/// adding a contact card is one row here (plus its physics; docs/architecture.md, "A contact
/// card").
#include <string_view>

#include "slideline/model/model.hpp"

namespace slideline::model {

struct ContactKeyword {
  std::string_view keyword;   ///< the base name, e.g. "*CONTACT_SURFACE_TO_SURFACE" (options follow it)
  ContactType type;
  bool automatic_general;     ///< the _GENERAL spelling of type 12 (Contact::automatic_general)
  int dyna3d_type;            ///< DYNA3D's interface type number (1 to 12)
  Enforcement enforcement;    ///< without the _LAGRANGE option (DYNA3D's enforcement of the type)
  bool sliding_option;        ///< takes the _SLIDING_ONLY option (Type 10's no-separation option)
  std::string_view name;      ///< what the CLI prints after "type N", e.g. "surface to surface"
  /// An LS-DYNA card with no DYNA3D number runs as the family `type` with this form
  /// (Contact::form); the DYNA3D cards leave it at dyna3d.
  ContactForm form = ContactForm::dyna3d;
  /// takes the _MORTAR option (Contact::penalty_coupling = 1, the mortar coupling of the penalty
  /// springs; docs/contact.md, "The contact patch test")
  bool mortar_option = false;
  /// *CONTACT_ERODING_...: the automatic card of `form` with its surfaces updated as elements
  /// erode, and the mandatory card 4 (ISYM EROSOP IADJ; Contact::eroding)
  bool eroding = false;
};

inline constexpr ContactKeyword kContactKeywords[] = {
    {"*CONTACT_SLIDING_ONLY", ContactType::sliding_only, false, 1, Enforcement::kinematic, false,
     "sliding only"},
    {"*CONTACT_TIED_SURFACE_TO_SURFACE", ContactType::tied_surface, false, 2, Enforcement::kinematic, false,
     "tied surface"},
    {"*CONTACT_SURFACE_TO_SURFACE", ContactType::surface_to_surface, false, 3, Enforcement::penalty, false,
     "surface to surface", ContactForm::dyna3d, true},
    {"*CONTACT_NODES_TO_SURFACE", ContactType::nodes_to_surface, false, 5, Enforcement::penalty, false,
     "nodes to surface"},
    {"*CONTACT_TIED_NODES_TO_SURFACE", ContactType::tied_nodes, false, 6, Enforcement::kinematic, false,
     "tied nodes"},
    {"*CONTACT_TIED_SHELL_EDGE_TO_SURFACE", ContactType::tied_shell_edge, false, 7, Enforcement::kinematic, false,
     "tied shell edge"},
    {"*CONTACT_TIEBREAK_NODES_TO_SURFACE", ContactType::tiebreak_nodes, false, 8, Enforcement::penalty, false,
     "tiebreak nodes"},
    {"*CONTACT_TIEBREAK_SURFACE_TO_SURFACE", ContactType::tiebreak_surface, false, 9, Enforcement::penalty, false,
     "tiebreak surface"},
    {"*CONTACT_ONE_WAY_SURFACE_TO_SURFACE", ContactType::one_way, false, 10, Enforcement::penalty, true,
     "one way", ContactForm::dyna3d, true},
    {"*CONTACT_AUTOMATIC_SINGLE_SURFACE", ContactType::automatic, false, 12, Enforcement::penalty, false,
     "automatic", ContactForm::dyna3d, true},
    {"*CONTACT_AUTOMATIC_GENERAL", ContactType::automatic, true, 12, Enforcement::penalty, false, "automatic"},
    {"*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE", ContactType::automatic, false, 12, Enforcement::penalty, false,
     "automatic surface to surface", ContactForm::automatic_surface_to_surface, true},
    {"*CONTACT_AUTOMATIC_NODES_TO_SURFACE", ContactType::automatic, false, 12, Enforcement::penalty, false,
     "automatic nodes to surface", ContactForm::automatic_nodes_to_surface},
    {"*CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE", ContactType::automatic, false, 12, Enforcement::penalty, false,
     "forming one way", ContactForm::forming_one_way},
    {"*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK", ContactType::tiebreak_surface, false, 9, Enforcement::penalty,
     false, "automatic surface to surface tiebreak", ContactForm::automatic_surface_to_surface},
    {"*CONTACT_ERODING_SINGLE_SURFACE", ContactType::automatic, false, 12, Enforcement::penalty, false,
     "eroding single surface", ContactForm::dyna3d, false, true},
    {"*CONTACT_ERODING_SURFACE_TO_SURFACE", ContactType::automatic, false, 12, Enforcement::penalty, false,
     "eroding surface to surface", ContactForm::automatic_surface_to_surface, false, true},
    {"*CONTACT_ERODING_NODES_TO_SURFACE", ContactType::automatic, false, 12, Enforcement::penalty, false,
     "eroding nodes to surface", ContactForm::automatic_nodes_to_surface, false, true},
    {"*CONTACT_FORCE_TRANSDUCER_PENALTY", ContactType::surface_to_surface, false, 3, Enforcement::penalty, false,
     "force transducer", ContactForm::force_transducer},
};

// ContactType's values are DYNA3D's type numbers: the table must agree.
static_assert([] {
  for (const auto& k : kContactKeywords)
    if (static_cast<int>(k.type) != k.dyna3d_type) return false;
  return true;
}());

/// The row of a contact card (its type and form, and for type 12 the _GENERAL spelling), or
/// nullptr for a type no row has.
constexpr const ContactKeyword* contact_keyword(const Contact& c) {
  const ContactKeyword* first = nullptr;
  for (const auto& k : kContactKeywords) {
    if (k.type != c.type || k.form != c.form || k.eroding != c.eroding) continue;
    if (k.automatic_general == c.automatic_general) return &k;
    if (!first) first = &k;
  }
  return first;
}

/// "kinematic", "penalty" or "Lagrange".
constexpr std::string_view enforcement_name(Enforcement e) {
  switch (e) {
    case Enforcement::kinematic: return "kinematic";
    case Enforcement::penalty: return "penalty";
    case Enforcement::lagrange: return "Lagrange";
  }
  return "?";
}

}  // namespace slideline::model
