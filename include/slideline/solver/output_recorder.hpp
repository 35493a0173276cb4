#pragma once
/// The output recorder: the history channels of a run and the histories and nodal states it
/// writes to the sinks at the output times (exact multiples of the intervals; step_control.hpp
/// makes the step land on them).
#include <memory>
#include <span>
#include <vector>

#include "slideline/contact/contact_manager.hpp"
#include "slideline/core/types.hpp"
#include "slideline/solver/output_sink.hpp"
#include "slideline/mesh/nodal_fields.hpp"
#include "slideline/solver/boundary.hpp"
#include "slideline/solver/energy_ledger.hpp"
#include "slideline/solver/nodal_constraint.hpp"

namespace slideline {

/// What the recorder reads: interface forces and outputs, support reactions, constraint outputs,
/// the displacement of the history nodes and the energies.
struct OutputSources {
  const NodalFields& nodes;
  const ContactManager& contacts;
  const std::vector<SupportGroup>& supports;
  const std::vector<std::unique_ptr<NodalConstraint>>& constraints;
  std::span<const Index> history_nodes;  ///< internal indices
  const EnergyReport& energy;
};

class OutputRecorder {
 public:
  /// Once, after the interfaces and constraints initialised: the channel list and the buffers.
  /// Throws InputError for a history node index out of range.
  void build_channels(const OutputSources& src);
  const std::vector<HistoryChannel>& channels() const { return channels_; }

  /// The sinks written by record() until end() (begin() calls their begin()).
  void begin(const std::vector<OutputSink*>& sinks, const MeshDescription& mesh);
  /// Flushes the sinks and forgets them.
  void end();

  /// Writes the histories (every `history_interval`, or every call when it is 0) and the nodal
  /// states (every `state_interval` > 0) due at time t, or both when `force`. `tol`: the time
  /// tolerance within which t is on an output time. Without sinks it does nothing.
  void record(const OutputSources& src, Real t, Real history_interval, Real state_interval, Real tol, bool force);

 private:
  void collect_history(const OutputSources& src);

  std::vector<HistoryChannel> channels_;
  std::vector<std::size_t> contact_outputs_;     // extra history values each interface writes
  std::vector<std::size_t> constraint_outputs_;  // history values each constraint writes
  std::vector<Real> history_values_;
  std::vector<Real> state_values_;
  Real last_history_ = -1.0;
  Real last_state_ = -1.0;
  const std::vector<OutputSink*>* sinks_ = nullptr;
};

}  // namespace slideline
