// InterfaceSpec (contact/interface_spec.hpp): one resolution of a *CONTACT card for every family:
// the one shell offset rule, the one friction law, the one table of what runs.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "slideline/contact/interface_spec.hpp"
#include "slideline/contact/make_contact_interface.hpp"
#include "slideline/contact/segment_contact.hpp"
#include "slideline/mesh/mesh_sets.hpp"
#include "slideline/contact/shell_offset.hpp"
#include "slideline/core/error.hpp"
#include "slideline/scenarios/sslide.hpp"
#include "slideline/solver/build.hpp"
#include "unit/contact/plate_surface.hpp"

namespace slideline {
namespace {

/// Two quads side by side (nodes 0..5), the first a shell of thickness 0.1, the second a solid face.
Surface shell_and_solid() {
  Surface s;
  s.conn = {0, 1, 4, 3, 1, 2, 5, 4};
  test::finish_surface(s);
  s.kind[0] = SegmentKind::shell;
  s.thickness[0] = 0.1;
  return s;
}

TEST(ShellOffset, HalfThicknessOnShellsOnlyWhenOn) {
  const Surface s = shell_and_solid();
  EXPECT_EQ(segment_offset(s, 0, {false, 0.0, 1.0}), 0.0);
  EXPECT_EQ(segment_offset(s, 0, {true, 0.0, 1.0}), 0.05);
  EXPECT_EQ(segment_offset(s, 0, {true, 0.3, 0.5}), 0.5 * 0.3 * 0.5);  // SST/MST override, SFST/SFMT scale
  EXPECT_EQ(segment_offset(s, 1, {true, 0.3, 0.5}), 0.0);              // a solid face has none
}

TEST(ShellOffset, NodeTakesItsLargestSegmentOffset) {
  const Surface s = shell_and_solid();
  const ShellOffsetRule on{true, 0.0, 1.0};
  // Rows follow s.nodes (0..5): nodes 1 and 4 touch both segments, 2 and 5 the solid face only.
  EXPECT_EQ(node_offset(s, 1, on), 0.05);
  EXPECT_EQ(node_offset(s, 4, on), 0.05);
  EXPECT_EQ(node_offset(s, 2, on), 0.0);
  ContactSide side;
  side.surface = s;
  side.nodes = s.nodes;
  const auto o = slave_node_offsets(side, on, 0.02);  // the radius is a floor
  ASSERT_EQ(o.size(), 6u);
  EXPECT_EQ(o[0], 0.05);
  EXPECT_EQ(o[2], 0.02);
  ContactSide node_set;
  node_set.nodes = {7, 9};
  EXPECT_EQ(slave_node_offsets(node_set, on, 0.02), (std::vector<Real>{0.02, 0.02}));
}

TEST(InterfaceSpec, FrictionLawIsTheSameForEveryFamily) {
  model::Contact c;
  c.fs = 0.3;
  c.dc = 2.0;
  ExponentialCoulomb f = contact_friction(c);  // FD = 0: constant FS (penalty, Lagrange, tiebreak alike)
  EXPECT_EQ(f.mu_s, 0.3);
  EXPECT_EQ(f.mu_k, 0.3);
  EXPECT_EQ(f.beta, 2.0);
  c.fd = 0.25;
  EXPECT_EQ(contact_friction(c).mu_k, 0.25);
  c.fs = -0.1;
  c.keyword = "*CONTACT_SURFACE_TO_SURFACE";
  c.src = {"deck.k", 12};
  try {
    contact_friction(c);
    FAIL() << "negative FS accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "deck.k:12: *CONTACT_SURFACE_TO_SURFACE: FS, FD and DC must not be negative");
  }
}

/// The error build_simulation throws for `m` (empty when it builds).
template <class E>
std::string build_error(const model::Model& m) {
  try {
    build_simulation(m);
  } catch (const E& e) {
    return e.what();
  }
  return {};
}

TEST(InterfaceSpec, NegativeFrictionIsRefusedByPenaltyToo) {
  model::Model m = scenarios::make_sslide_problem("sslide3p").model;
  m.contacts.front().fd = -0.25;
  EXPECT_NE(build_error<InputError>(m).find("FS, FD and DC must not be negative"), std::string::npos);
}

TEST(InterfaceSpec, PenaltyAutomaticRefusesAMasterSide) {
  model::Model m = scenarios::make_sslide_problem("sslide12p").model;
  m.contacts.front().msid = m.contacts.front().ssid;
  m.contacts.front().mstyp = m.contacts.front().sstyp;
  EXPECT_NE(build_error<NotImplementedError>(m).find("MSID"), std::string::npos);
}

TEST(InterfaceSpec, TiedLagrangeIsRefusedBeforeTheSidesAreBuilt) {
  model::Model m = scenarios::make_sslide_problem("sslide2kc").model;
  m.contacts.front().enforcement = model::Enforcement::lagrange;
  m.contacts.front().ssid = 999;  // a bad side is not what the message is about
  EXPECT_NE(build_error<NotImplementedError>(m).find("tied interfaces are kinematic"), std::string::npos);
}

// The LS-DYNA automatic cards (model::ContactForm): penalty only, and the two-sided card needs
// surfaces on both sides; each refusal names the card's file and line.
TEST(InterfaceSpec, AutomaticCardsRefuseLagrangeAndANodeSetSurface) {
  model::Model m = scenarios::make_sslide_problem("sslide3p").model;
  model::Contact& c = m.contacts.front();
  c.type = model::ContactType::automatic;
  c.form = model::ContactForm::automatic_surface_to_surface;
  c.keyword = "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_LAGRANGE";
  c.src = {"deck.k", 40};
  c.enforcement = model::Enforcement::lagrange;
  const std::string lagrange = build_error<NotImplementedError>(m);
  EXPECT_NE(lagrange.find("deck.k:40: *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_LAGRANGE"), std::string::npos) << lagrange;
  EXPECT_NE(lagrange.find("penalty enforcement only"), std::string::npos) << lagrange;
  c.enforcement = model::Enforcement::penalty;
  c.keyword = "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE";
  c.sstyp = 4;
  const std::string node_set = build_error<InputError>(m);
  EXPECT_NE(node_set.find("deck.k:40: *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE: SSTYP = 4"), std::string::npos)
      << node_set;
}

// The mortar coupling (a deck's _MORTAR, penalty_coupling 1) runs on the penalty passes with slave
// segments; elsewhere the build refuses it, naming the card, instead of running without it.
TEST(InterfaceSpec, MortarCouplingIsRefusedWhereItIsNotBuilt) {
  const auto refusal = [](const char* problem, int coupling, auto error) {
    model::Model m = scenarios::make_sslide_problem(problem).model;
    m.contacts.front().penalty_coupling = coupling;
    m.contacts.front().src = {"deck.k", 9};
    const std::string what = build_error<decltype(error)>(m);
    EXPECT_NE(what.find("deck.k:9: "), std::string::npos) << what;
    return what;
  };
  EXPECT_NE(refusal("sslide12l", 1, NotImplementedError("")).find("_MORTAR with _LAGRANGE on a type 12"),
            std::string::npos);
  EXPECT_NE(refusal("sslide2kc", 1, NotImplementedError("")).find("tied, tiebreak or sliding-only"), std::string::npos);
  EXPECT_NE(refusal("sslide9ps", 1, NotImplementedError("")).find("tied, tiebreak or sliding-only"), std::string::npos);
  EXPECT_NE(refusal("sslide5p", 1, NotImplementedError("")).find("node-set slave side (SSTYP 4)"), std::string::npos);
  EXPECT_NE(refusal("sslide3p", 2, InputError("")).find("neither 0 (DYNA3D's rule) nor 1 (mortar)"), std::string::npos);
}

// SOFT = 2 (segment-based contact): built on the automatic single surface (Type 12 without MSID,
// here with friction and VDC: a SegmentContact) and on Type 3's solid faces; refused by name with
// VC, on _GENERAL, on Type 3's shell segments and on Type 10.
TEST(InterfaceSpec, SegmentBasedContactRunsOnTheSingleSurfaceAndIsRefusedElsewhere) {
  model::Model m = scenarios::make_sslide_problem("sslide12p").model;
  model::Contact& c = m.contacts.front();
  c.src = {"deck.k", 12};
  c.soft = 2;
  c.fs = 0.2;
  c.vdc = 10.0;
  const std::unique_ptr<Simulation> sim = build_simulation(m);
  int segment_based = 0;  // the card set to SOFT = 2, of the problem's interfaces
  for (std::size_t i = 0; i < sim->contacts().size(); ++i)
    segment_based += dynamic_cast<const SegmentContact*>(&sim->contacts()[i]) != nullptr;
  EXPECT_EQ(segment_based, 1);
  c.vc = 1.0;
  EXPECT_NE(build_error<NotImplementedError>(m).find("deck.k:12: "), std::string::npos);
  EXPECT_NE(build_error<NotImplementedError>(m).find("SOFT = 2 (segment-based contact) with VC"), std::string::npos);
  c.vc = 0.0;
  c.automatic_general = true;
  EXPECT_NE(build_error<NotImplementedError>(m).find("*CONTACT_AUTOMATIC_SINGLE_SURFACE and *CONTACT_SURFACE_TO_SURFACE "
                                                     "only"),
            std::string::npos);
  model::Model t3 = scenarios::make_sslide_problem("sslide3p").model;
  t3.contacts.front().soft = 2;  // solid on solid
  const std::unique_ptr<Simulation> s3 = build_simulation(t3);
  EXPECT_NE(dynamic_cast<const SegmentContact*>(&s3->contacts()[0]), nullptr);
  for (model::Contact& card : t3.contacts) card.soft = 2;  // the pairings with shells too
  EXPECT_NE(build_error<NotImplementedError>(t3).find("on *CONTACT_SURFACE_TO_SURFACE with shell segments"),
            std::string::npos);
  model::Model t10 = scenarios::make_sslide_problem("sslide10pv").model;
  t10.contacts.front().soft = 2;
  EXPECT_NE(build_error<NotImplementedError>(t10).find("SOFT = 2 (segment-based contact, optional card A)"),
            std::string::npos);
}

// *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK on shell segments (the tie has no thickness
// offsets): refused by name, with the card's location, before anything is built.
TEST(InterfaceSpec, AutomaticTiebreakRefusesShellSegments) {
  InterfaceSpec spec;
  spec.where = "deck.k:7: *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK";
  spec.type = model::ContactType::tiebreak_surface;
  spec.form = model::ContactForm::automatic_surface_to_surface;
  spec.slave.surface = shell_and_solid();
  spec.master.surface = shell_and_solid();
  const model::Model m;
  const std::vector<std::unique_ptr<ElementBlock>> blocks;
  const NodalFields nodes;
  const MeshSets sets;
  try {
    make_automatic_tiebreak_contact(spec, ContactBuildContext{m, blocks, nodes, sets});
    ADD_FAILURE() << "built";
  } catch (const NotImplementedError& e) {
    EXPECT_NE(std::string(e.what()).find("deck.k:7: *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK: shell segments"),
              std::string::npos)
        << e.what();
  }
}


// *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK built through the model API with an OPTION no
// class runs (the reader refuses it first): refused by the factory too, not run as another OPTION.
TEST(InterfaceSpec, AutomaticTiebreakRefusesAnUnbuiltOption) {
  InterfaceSpec spec;
  spec.where = "api: *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK";
  spec.type = model::ContactType::tiebreak_surface;
  spec.form = model::ContactForm::automatic_surface_to_surface;
  spec.cohesive.option = 5;
  const model::Model m;
  const std::vector<std::unique_ptr<ElementBlock>> blocks;
  const NodalFields nodes;
  const MeshSets sets;
  try {
    make_automatic_tiebreak_contact(spec, ContactBuildContext{m, blocks, nodes, sets});
    ADD_FAILURE() << "built";
  } catch (const NotImplementedError& e) {
    EXPECT_NE(std::string(e.what()).find("OPTION = 5"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace slideline
