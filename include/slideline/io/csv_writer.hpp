#pragma once
/// CSV output of the history channels: one row per history record, columns
/// `time,<path>` for one-component channels and `<path>_x,<path>_y,<path>_z` for three-component
/// channels (e.g. interfaces/solid_on_solid/slave_force_x). Nodal states are not written.
#include <fstream>
#include <string>

#include "slideline/solver/output_sink.hpp"

namespace slideline {

class CsvWriter final : public OutputSink {
 public:
  /// Creates (or truncates) `path`. Throws Error when it cannot be opened.
  explicit CsvWriter(const std::string& path);

  void begin(const std::vector<HistoryChannel>& channels, const MeshDescription& mesh) override;
  void write_history(Real t, std::span<const Real> values) override;
  void write_state(Real, const StateFields&) override {}
  void flush() override;

  /// The header columns for a channel list (without the leading "time").
  static std::vector<std::string> column_names(const std::vector<HistoryChannel>& channels);

 private:
  std::string path_;
  std::ofstream out_;
  std::size_t width_ = 0;
};

}  // namespace slideline
