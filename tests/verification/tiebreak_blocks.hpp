#pragma once
// The pair of stacked unit blocks every *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK verification
// test ties (test_automatic_tiebreak*.cpp): parts 1 (upper, y in [0.5, 1]) and 2 (lower, y in
// [0, 0.5]), one hexahedron each (IHQ 10), in `frame`; segment set 1 the upper block's bottom face
// (slave, outward -y), 2 the lower block's top face (master, +y); node sets 3 (the upper block's
// top face, where the tests load or drive) and 4 (the lower block's bottom face, held by SPC 1);
// and the card between the two segment sets.
#include <string>

#include "general_contact_models.hpp"

namespace slideline::test_support {

struct TiebreakBlocks {
  BoxIds upper, lower;
};

inline TiebreakBlocks add_tiebreak_blocks(model::Model& m, const Frame& frame, Real rho, Real e, Real nu) {
  add_elastic_part(m, 1, rho, e, nu, 10);
  add_elastic_part(m, 2, rho, e, nu, 10);
  TiebreakBlocks b{add_box(m, 1, Vec3(0.0, 0.5, 0.0), Vec3(1.0, 0.5, 1.0), {1, 1, 1}, frame),
                   add_box(m, 2, Vec3(0.0, 0.0, 0.0), Vec3(1.0, 0.5, 1.0), {1, 1, 1}, frame)};
  const BoxIds& u = b.upper;
  const BoxIds& l = b.lower;
  m.segment_sets.push_back({1, "slave", {{u.at(0, 0, 0), u.at(1, 0, 0), u.at(1, 0, 1), u.at(0, 0, 1)}}, {}});
  m.segment_sets.push_back({2, "master", {{l.at(0, 1, 0), l.at(0, 1, 1), l.at(1, 1, 1), l.at(1, 1, 0)}}, {}});
  m.node_sets.push_back({3, "top", u.face_j(1), {}});
  m.node_sets.push_back({4, "bottom", l.face_j(0), {}});
  m.spcs.push_back({1, "fixed", 4, 0, {1, 1, 1, 1, 1, 1}, {}});
  return b;
}

/// Two blocks 1 x 0.5 x 1 of 2 x 1 x 2 hexahedra in `frame`: part 1 below, part 2 `gap` above it
/// (both parts already added); segment set 1 the lower block's top face (master), set 2 the upper
/// block's bottom face (slave).
inline TiebreakBlocks add_gapped_blocks(model::Model& m, const Frame& frame, Real gap) {
  TiebreakBlocks b;
  b.lower = add_box(m, 1, Vec3(0.0, 0.0, 0.0), Vec3(1.0, 0.5, 1.0), {2, 1, 2}, frame);  // the lower first
  b.upper = add_box(m, 2, Vec3(0.0, 0.5 + gap, 0.0), Vec3(1.0, 0.5, 1.0), {2, 1, 2}, frame);
  const BoxIds& l = b.lower;
  const BoxIds& u = b.upper;
  model::SegmentSet master{1, "master", {}, {}};
  model::SegmentSet slave{2, "slave", {}, {}};
  for (int k = 0; k < 2; ++k)
    for (int i = 0; i < 2; ++i) {
      master.segments.push_back({l.at(i, 1, k), l.at(i, 1, k + 1), l.at(i + 1, 1, k + 1), l.at(i + 1, 1, k)});
      slave.segments.push_back({u.at(i, 0, k), u.at(i + 1, 0, k), u.at(i + 1, 0, k + 1), u.at(i, 0, k + 1)});
    }
  m.segment_sets.push_back(master);
  m.segment_sets.push_back(slave);
  return b;
}

/// The tiebreak card between segment sets 1 (slave) and 2 (master), OPTION `option`, named
/// `what` in its keyword (for messages).
inline model::Contact tiebreak_card(const std::string& what, int option) {
  model::Contact card;
  card.keyword = "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK (" + what + ")";
  card.type = model::ContactType::tiebreak_surface;
  card.form = model::ContactForm::automatic_surface_to_surface;
  card.ssid = 1;
  card.msid = 2;
  card.sstyp = card.mstyp = 0;
  card.option = option;
  return card;
}

/// A nodal load of curve `lcid` along `dir` (a unit vector) on node set `nsid`, `scale` per node.
inline void add_node_load(model::Model& m, Id nsid, Id lcid, const Vec3& dir, Real scale) {
  for (int k = 0; k < 3; ++k)
    if (dir[k] != 0.0) m.nodal_loads.push_back({true, nsid, k + 1, lcid, scale * dir[k], 0, {0, 0, 0}, {}});
}

}  // namespace slideline::test_support
