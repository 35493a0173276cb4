#pragma once
/// The output recorder: the history channels of a run and the histories and nodal states it
/// writes to the sinks at the output times (exact multiples of the intervals; step_control.hpp
/// makes the step land on them).
#include <memory>
#include <span>
#include <vector>

#include "slideline/contact/contact_manager.hpp"
#include "slideline/core/types.hpp"
#include "slideline/element/element_block.hpp"
#include "slideline/solver/output_sink.hpp"
#include "slideline/mesh/nodal_fields.hpp"
#include "slideline/solver/boundary.hpp"
#include "slideline/solver/energy_ledger.hpp"
#include "slideline/solver/mass_scaling.hpp"
#include "slideline/solver/nodal_constraint.hpp"
#include "slideline/solver/part_energy_monitor.hpp"

namespace slideline {

/// What the recorder reads: interface forces and outputs, support reactions, constraint outputs,
/// the displacement of the history nodes and the energies; the nodal fields and the element
/// blocks' cell outputs for the states.
struct OutputSources {
  const NodalFields& nodes;
  const ElementBlocks& blocks;
  const ContactManager& contacts;
  const std::vector<SupportGroup>& supports;
  const std::vector<std::unique_ptr<NodalConstraint>>& constraints;
  std::span<const Index> history_nodes;  ///< internal indices
  const EnergyReport& energy;
  /// Mass scaling every cycle (MS1ST = 0): each block's added mass now (one entry per block);
  /// empty otherwise (then the history has no added-mass channels).
  std::span<const PartAddedMass> added_mass = {};
  /// The per-part energies (part_energy_monitor.hpp): channels parts/<id>/internal_energy,
  /// hourglass_energy, eroded_internal and eroded_hourglass where a part can erode (null: none).
  const PartEnergyMonitor* part_energy = nullptr;
};

/// Where an element goes in the output cells: its topology's entry in MeshDescription::cells and
/// its cell index there.
struct CellSlot {
  std::size_t topology = 0;
  Index cell = 0;
};

/// The slot of every element of every block (result[b][e]), for the cell groups `cells`
/// (cells_by_topology's order: a topology's cells in block then element order).
std::vector<std::vector<CellSlot>> output_cell_slots(const ElementBlocks& blocks,
                                                     std::span<const TopologyCells> cells);

/// The per-cell values fixed for the run (part, material, thickness), by topology as `cells`.
std::vector<TopologyCellInfo> output_cell_info(const ElementBlocks& blocks, std::span<const TopologyCells> cells);

class OutputRecorder {
 public:
  /// Once, after the interfaces and constraints initialised: the channel list and the buffers.
  /// Throws InputError for a history node index out of range.
  void build_channels(const OutputSources& src);
  const std::vector<HistoryChannel>& channels() const { return channels_; }

  /// The sinks written by record() until end() (begin() calls their begin()).
  /// Also sizes the state buffers for `blocks` (the blocks `mesh` describes).
  void begin(const std::vector<OutputSink*>& sinks, const MeshDescription& mesh, const ElementBlocks& blocks);
  /// Flushes the sinks and forgets them.
  void end();

  /// Writes the histories (every `history_interval`, or every call when it is 0) and the nodal
  /// states (every `state_interval` > 0) due at time t, or both when `force`. `tol`: the time
  /// tolerance within which t is on an output time. Without sinks it does nothing.
  void record(const OutputSources& src, Real t, Real history_interval, Real state_interval, Real tol, bool force);

 private:
  void collect_history(const OutputSources& src);
  void collect_state(const OutputSources& src);

  // State buffers, sized by begin(): nodal vectors (3 per node), the blocks' cell outputs and
  // their scatter into the topologies' cells.
  std::vector<Real> velocity_, acceleration_, contact_force_;
  std::vector<std::vector<CellOutput>> block_cells_;
  std::vector<std::vector<CellSlot>> slots_;
  std::vector<TopologyCellFields> cell_fields_;
  std::vector<HistoryChannel> channels_;
  std::vector<std::size_t> contact_outputs_;     // extra history values each interface writes
  std::vector<std::size_t> constraint_outputs_;  // history values each constraint writes
  // The parts with plasticity (ElementBlock::has_plasticity), in the order of their first block,
  // each with its blocks: the channels parts/<id>/max_plastic_strain and parts/<id>/plastic_work.
  struct PartBlocks {
    Id part = 0;
    std::vector<std::size_t> blocks;
  };
  std::vector<PartBlocks> plastic_parts_;
  // MS1ST = 0: the parts of the rescaled blocks, each with its blocks: parts/<id>/added_mass.
  std::vector<PartBlocks> mass_parts_;
  std::vector<Real> history_values_;
  std::vector<Real> state_values_;
  Real last_history_ = -1.0;
  Real last_state_ = -1.0;
  bool erodes_ = false;  ///< a block can erode: the history has energy/eroded
  bool energy_parts_ = false;  ///< and the per-part energies (OutputSources::part_energy)
  const std::vector<OutputSink*>* sinks_ = nullptr;
};

}  // namespace slideline
