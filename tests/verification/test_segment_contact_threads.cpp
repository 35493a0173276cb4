// SOFT = 2 results do not depend on the thread count: two blocks of 10^4 surface segments (above
// the parallel threshold of 4096, so the segments are evaluated in parallel chunks), the upper
// pressed 1e-3 into the lower and sliding, 40 contact evaluations on 1, 2 and 3 threads: every
// contact force and the step vote bitwise identical. Slow (4 s of CPU in Release, 3 runs). The
// same for two shell plates of one part (4901 segments) on *CONTACT_AUTOMATIC_SINGLE_SURFACE with
// friction and VDC, pressed 1e-3 into their thickness offsets and sliding (side memory, offsets,
// stick springs in the parallel loop).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "slideline/core/parallel.hpp"
#include "slideline/solver/build.hpp"
#include "test_support/mesh_fixtures.hpp"

namespace slideline {
namespace {

/// Lower block n x 1 x n (part 1), upper block (n-1) x 1 x (n-1) on it (part 2, offset so that no
/// node lies over a node), one frictionless *CONTACT_AUTOMATIC_SURFACE_TO_SURFACE with SOFT = 2.
model::Model two_blocks(int n) {
  model::Model m = test_support::hex_grid_model(n, 1, n, 1);
  const Id first = static_cast<Id>(m.nodes.size()) + 1;
  const int u = n - 1;
  const auto id = [&](int i, int j, int k) { return first + i + (u + 1) * (j + 2 * k); };
  for (int k = 0; k <= u; ++k)
    for (int j = 0; j <= 1; ++j)
      for (int i = 0; i <= u; ++i) m.nodes.push_back({id(i, j, k), Vec3(0.37 + i, 1.0 + j, 0.41 + k), 0, 0});
  Id eid = static_cast<Id>(m.solids.size()) + 1;
  for (int k = 0; k < u; ++k)
    for (int i = 0; i < u; ++i)
      m.solids.push_back({eid++, 2, {id(i, 0, k), id(i + 1, 0, k), id(i + 1, 1, k), id(i, 1, k), id(i, 0, k + 1),
                                     id(i + 1, 0, k + 1), id(i + 1, 1, k + 1), id(i, 1, k + 1)}});
  m.parts.push_back({2, "upper", 1, 1, 0, 0, {}});
  model::Contact c;
  c.keyword = "*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE";
  c.type = model::ContactType::automatic;
  c.form = model::ContactForm::automatic_surface_to_surface;
  c.ssid = 2;
  c.sstyp = 3;
  c.msid = 1;
  c.mstyp = 3;
  c.soft = 2;
  m.contacts.push_back(c);
  return m;
}

/// Two shell plates of part 1 (thickness 0.1): n x n at y = 0 and (n-1) x (n-1) on it at y = 0.1
/// (its nodes over no node), one *CONTACT_AUTOMATIC_SINGLE_SURFACE with SOFT = 2 on every part,
/// FS 0.3, FD 0.2, DC 1, VDC 20.
model::Model two_plates(int n) {
  model::Model m;
  m.materials.push_back(model::MatElastic{1, 1.0, 1e4, 0.3, "plates", {}});
  model::SectionShell sec;
  sec.secid = 1;
  sec.t = {0.1, 0.1, 0.1, 0.1};
  m.shell_sections.push_back(sec);
  m.parts.push_back({1, "plates", 1, 1, 0, 0, {}});
  m.termination.endtim = 1.0;
  Id eid = 1;
  for (const int u : {n, n - 1}) {
    const Id first = static_cast<Id>(m.nodes.size()) + 1;
    const Real x0 = u == n ? 0.0 : 0.37, y = u == n ? 0.0 : 0.1, z0 = u == n ? 0.0 : 0.41;
    for (int k = 0; k <= u; ++k)
      for (int i = 0; i <= u; ++i) m.nodes.push_back({first + i + (u + 1) * k, Vec3(x0 + i, y, z0 + k), 0, 0});
    for (int k = 0; k < u; ++k)
      for (int i = 0; i < u; ++i) {
        const Id a = first + i + (u + 1) * k;
        m.shells.push_back({eid++, 1, {a, a + u + 1, a + u + 2, a + 1}, {}});
      }
  }
  model::Contact c;
  c.keyword = "*CONTACT_AUTOMATIC_SINGLE_SURFACE";
  c.type = model::ContactType::automatic;
  c.sstyp = 5;
  c.soft = 2;
  c.fs = 0.3;  // friction and VDC in the parallel loop too
  c.fd = 0.2;
  c.dc = 1.0;
  c.vdc = 20.0;
  m.contacts.push_back(c);
  return m;
}

/// FNV-1a over the bits of every contact force and step vote of 40 evaluations.
std::uint64_t run_on(int threads, Real& total, bool shells = false) {
  const int before = max_threads();
  set_threads(threads);
  const int n = 50;
  SimulationSetup setup = build_setup(shells ? two_plates(n) : two_blocks(n));
  NodalFields& nodes = setup.nodes;
  for (auto& b : setup.blocks) b->initialize(nodes);
  const std::vector<std::uint8_t> rigid(nodes.size(), 0);
  setup.contacts.initialize(ContactContext{nodes, setup.blocks, &setup.sets, rigid});
  const Index first_upper = static_cast<Index>(shells ? (n + 1) * (n + 1) : (n + 1) * 2 * (n + 1));
  const Index count = static_cast<Index>(nodes.size());
  for (Index i = first_upper; i < count; ++i) {
    nodes.x.y[i] -= 1e-3;
    nodes.v.x[i] = 13.0;  // the slide below, 0.013 per step of 1e-3 (the friction's slip speed)
  }
  StepTimes t;
  t.dt_prev = t.dt_avg = t.dt_next = t.dt_initial = 1e-3;
  std::uint64_t h = 1469598103934665603ull;
  const auto mix = [&h](Real v) {
    std::uint64_t u;
    std::memcpy(&u, &v, sizeof u);
    h = (h ^ u) * 1099511628211ull;
  };
  total = 0.0;
  for (int step = 0; step < 40; ++step) {
    for (Index i = first_upper; i < count; ++i) {
      nodes.x.x[i] += 0.013;
      nodes.x.z[i] += 0.007 * (step % 3);
    }
    nodes.f_contact.fill(0.0);
    nodes.m_contact.fill(0.0);
    mix(setup.contacts.apply_forces(nodes, t, ContactForceView{nodes.f_contact, nodes.m_contact}));
    for (Index i = 0; i < count; ++i) {
      const Vec3 f = nodes.f_contact.get(i);
      for (int c = 0; c < 3; ++c) mix(f[c]);
      total += f.norm();
    }
  }
  set_threads(before);
  return h;
}

TEST(SegmentContactSlow, ForcesBitwiseIdenticalOn1To3Threads) {
  Real total1 = 0.0, total = 0.0;
  const std::uint64_t h1 = run_on(1, total1);
  EXPECT_GT(total1, 0.0);  // the blocks are in contact
  for (int threads : {2, 3}) EXPECT_EQ(run_on(threads, total), h1) << threads << " threads";
}

TEST(SegmentContactSlow, ShellSingleSurfaceForcesBitwiseIdenticalOn1To3Threads) {
  Real total1 = 0.0, total = 0.0;
  const std::uint64_t h1 = run_on(1, total1, true);
  EXPECT_GT(total1, 0.0);  // the plates are in contact
  for (int threads : {2, 3}) EXPECT_EQ(run_on(threads, total, true), h1) << threads << " threads";
}

}  // namespace
}  // namespace slideline
