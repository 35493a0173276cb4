// The per-part negative-energy stop with erosion (docs/solver.md, "Energy checks per part"): a
// part's remaining elements (its energy less what its deleted elements held) and its deleted
// elements are checked apart, so the positive energy deleted elements took away no longer hides
// remaining elements whose energy went negative (the total alone was checked before).
// The rule's arithmetic on given energies: the ledger and the powers behind them are tested where
// they are built.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "slideline/contact/contact_manager.hpp"
#include "slideline/core/error.hpp"
#include "slideline/element/hex_block.hpp"
#include "slideline/material/elastic.hpp"
#include "slideline/solver/stability_monitor.hpp"

using namespace slideline;

namespace {

std::vector<std::unique_ptr<ElementBlock>> one_block() {
  std::vector<std::unique_ptr<ElementBlock>> blocks;
  std::vector<Index> conn{0, 1, 2, 3, 4, 5, 6, 7};
  blocks.push_back(std::make_unique<HexBlock<ElasticSolid>>(7, ElasticSolid(1.0, 1.0, 0.3), HexHourglass{},
                                                            BulkViscosity{0.0, 0.0}, conn, std::vector<Id>{1}));
  return blocks;
}

/// A report whose balance closes: kinetic0 = 100, the rest as given, kinetic the remainder.
EnergyReport closed_report(Real internal, Real hourglass, Real bulk) {
  EnergyReport e;
  e.kinetic0 = 100.0;
  e.internal = internal;
  e.hourglass = hourglass;
  e.bulk_viscosity = bulk;
  e.kinetic = 100.0 - internal - hourglass - bulk;
  return e;
}

/// check_energy at cycle 200 (past the checks' start) with the balance limit off; returns the
/// InstabilityError's message, empty when the run goes on.
std::string check(const EnergyReport& e, PartEnergyMonitor& parts) {
  const auto blocks = one_block();
  NodalFields nodes;
  nodes.resize(8);
  ContactManager contacts;
  SimulationControls controls;
  controls.energy_error_limit = 0.0;
  StabilityMonitor monitor;
  try {
    monitor.check_energy(e, parts, MonitoredModel{nodes, blocks, contacts}, 1.0, 200, controls);
  } catch (const InstabilityError& err) {
    return err.what();
  }
  return {};
}

}  // namespace

// The largest energy in play is the initial kinetic energy, 100: the bound is -1.
TEST(ModelEnergyStops, ErodedEnergyNoLongerHidesNegativeRemainingElements) {
  const auto blocks = one_block();
  PartEnergyMonitor parts;
  parts.reset(blocks);
  parts.add(0, BlockEnergy{.element_power = 10.0}, 1.0);  // +10, then deleted elements take it away
  BlockEnergy deleting;
  deleting.element_power = -3.0;  // the remaining elements lose 3: their energy is -3
  deleting.eroded_internal = 10.0;
  deleting.eroded_elements = 1;
  parts.add(0, deleting, 1.0);
  EXPECT_DOUBLE_EQ(parts.internal_energy(0), 7.0);  // the total alone, +7, passed before
  EXPECT_DOUBLE_EQ(parts.eroded_internal_energy(0), 10.0);
  const std::string stop = check(closed_report(0.0, 0.0, 0.0), parts);
  EXPECT_NE(stop.find("internal (elements not eroded) energy of part 7 went negative (-3"), std::string::npos) << stop;
  // Within the bound (-1 of 100) the run goes on.
  PartEnergyMonitor small;
  small.reset(blocks);
  small.add(0, BlockEnergy{.element_power = 10.0}, 1.0);
  deleting.element_power = -0.5;
  small.add(0, deleting, 1.0);
  EXPECT_EQ(check(closed_report(0.0, 0.0, 0.0), small), "");
}
