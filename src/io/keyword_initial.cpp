// The *INITIAL_VELOCITY family (field orders from the LS-DYNA keyword manual, listed in
// docs/keywords.md). The reader only records the cards; build_simulation checks the references
// and refuses what the solver cannot do (IVATN, PHASE, a spin with a local system), naming the card's line.
#include <string>

#include "keyword_card.hpp"
#include "slideline/core/error.hpp"

namespace slideline::keyword {
namespace {

const char* const kVelocity[] = {"VX", "VY", "VZ", "VXR", "VYR", "VZR"};
const char* const kExempted[] = {"VXE", "VYE", "VZE", "VXRE", "VYRE", "VZRE"};

/// Six velocity fields from `first` on: three translational, three rotational.
void get_velocity(const Card& c, int first, const char* const names[6], Vec3& v, Vec3& vr) {
  for (int k = 0; k < 3; ++k) {
    c.get(first + k, names[k], v[k]);
    c.get(first + 3 + k, names[3 + k], vr[k]);
  }
}

const Line* next_nonblank(Block& b) {
  while (const Line* l = b.take())
    if (!trim(l->text).empty()) return l;
  return nullptr;
}

const Line& require_card(const Context& ctx, Block& b, const Line& first, const char* what) {
  const Line* l = b.take();
  if (!l)
    throw InputError(ctx.where(first.number) + b.keyword + ": missing " + what + " card");
  return *l;
}

}  // namespace

void read_initial_velocity_node(const Context& ctx, Block& b, model::Model& m) {
  while (const Line* l = next_nonblank(b)) {
    Card c(ctx, *l, b.keyword, kStandard);
    model::InitialVelocityNode iv;
    c.get(0, "NID", iv.nid);
    get_velocity(c, 1, kVelocity, iv.v, iv.vr);
    c.get(7, "ICID", iv.icid);
    iv.at.line = l->number;
    iv.at.file = ctx.file_index;
    m.initial_velocity_nodes.push_back(iv);
  }
}

void read_initial_velocity(const Context& ctx, Block& b, model::Model& m) {
  while (const Line* l = next_nonblank(b)) {
    Card c(ctx, *l, b.keyword, kStandard);
    model::InitialVelocity iv;
    c.get(0, "NSID", iv.nsid);
    c.get(1, "NSIDEX", iv.nsidex);
    c.get(2, "BOXID", iv.boxid);
    c.get(3, "IRIGID", iv.irigid);
    c.get(4, "ICID", iv.icid);
    Card c2(ctx, require_card(ctx, b, *l, "VX VY VZ VXR VYR VZR"), b.keyword, kStandard);
    get_velocity(c2, 0, kVelocity, iv.v, iv.vr);
    if (iv.nsidex > 0) {
      Card c3(ctx, require_card(ctx, b, *l, "exempted-node velocity (NSIDEX > 0)"), b.keyword, kStandard);
      get_velocity(c3, 0, kExempted, iv.ve, iv.vre);
    }
    iv.at.line = l->number;
    iv.at.file = ctx.file_index;
    m.initial_velocities.push_back(iv);
  }
}

void read_initial_velocity_generation(const Context& ctx, Block& b, model::Model& m) {
  while (const Line* l = next_nonblank(b)) {
    Card c(ctx, *l, b.keyword, kStandard);
    model::InitialVelocityGeneration g;
    c.get(0, "ID", g.id);
    c.get(1, "STYP", g.styp);
    c.get(2, "OMEGA", g.omega);
    c.get(3, "VX", g.v[0]);
    c.get(4, "VY", g.v[1]);
    c.get(5, "VZ", g.v[2]);
    c.get(6, "IVATN", g.ivatn);
    c.get(7, "ICID", g.icid);
    Card c2(ctx, require_card(ctx, b, *l, "XC YC ZC NX NY NZ PHASE IRIGID"), b.keyword, kStandard);
    static const char* const names[] = {"XC", "YC", "ZC", "NX", "NY", "NZ"};
    for (int k = 0; k < 3; ++k) {
      c2.get(k, names[k], g.xc[k]);
      c2.get(3 + k, names[3 + k], g.n[k]);
    }
    c2.get(6, "PHASE", g.phase);
    c2.get(7, "IRIGID", g.irigid);
    g.at.line = l->number;
    g.at.file = ctx.file_index;
    m.initial_velocity_generations.push_back(g);
  }
}

}  // namespace slideline::keyword
