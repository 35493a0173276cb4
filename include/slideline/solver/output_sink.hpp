#pragma once
/// Where a run's results go. The simulation records named history channels at the history
/// interval and nodal states at the state interval; sinks (HDF5 + XDMF, CSV, in-memory) store them.
///
/// Channel paths follow the output contract (docs/output.md):
///   interfaces/<title>/slave_force, interfaces/<title>/master_force   (3 components)
///   supports/<title>/reaction                                          (3 components)
///   supports/rigid_<part id>/reaction, .../reaction_moment             (3 components)
///   nodes/<id>/displacement                                            (3 components)
///   energy/<name>                                                      (1 component)
#include <span>
#include <string>
#include <vector>

#include "slideline/core/types.hpp"
#include "slideline/mesh/mesh_block.hpp"

namespace slideline {

struct HistoryChannel {
  std::string path;
  int components = 1;
};

/// What a sink needs to describe the mesh (reference configuration) for state output.
struct MeshDescription {
  std::vector<Id> node_ids;
  std::vector<Real> x0;              ///< reference coordinates, 3 per node
  /// The cells, grouped by topology (cells_by_topology: every declared topology, in
  /// all_topologies order, empty where the model has none). Writers write each group as its
  /// topology says (HDF5 /mesh/<cell_set>, XDMF TopologyType xdmf_cell).
  std::vector<TopologyCells> cells;
};

class OutputSink {
 public:
  virtual ~OutputSink() = default;
  /// Called once before any record.
  virtual void begin(const std::vector<HistoryChannel>& channels, const MeshDescription& mesh) = 0;
  /// One history record: values of every channel in order, components flattened.
  virtual void write_history(Real t, std::span<const Real> values) = 0;
  /// One nodal state: displacements, 3 per node (x, y, z interleaved).
  virtual void write_state(Real t, std::span<const Real> displacements) = 0;
  /// Makes everything written so far durable (called at the end and when a run stops early).
  virtual void flush() = 0;
};

/// In-memory sink: keeps every history record, for tests, verification and reports.
class History final : public OutputSink {
 public:
  void begin(const std::vector<HistoryChannel>& channels, const MeshDescription&) override {
    channels_ = channels;
    offsets_.clear();
    int off = 0;
    for (const auto& c : channels_) {
      offsets_.push_back(off);
      off += c.components;
    }
    width_ = off;
  }
  void write_history(Real t, std::span<const Real> values) override {
    time_.push_back(t);
    data_.insert(data_.end(), values.begin(), values.end());
  }
  void write_state(Real, std::span<const Real>) override {}
  void flush() override {}

  const std::vector<Real>& time() const { return time_; }
  std::size_t records() const { return time_.size(); }
  const std::vector<HistoryChannel>& channels() const { return channels_; }
  /// Column index of a channel's first component, or -1.
  int find(const std::string& path) const {
    for (std::size_t i = 0; i < channels_.size(); ++i)
      if (channels_[i].path == path) return offsets_[i];
    return -1;
  }
  /// Component c of channel `path` at record r. Throws if the channel does not exist.
  Real value(const std::string& path, std::size_t r, int c = 0) const;
  /// The whole series of one component.
  std::vector<Real> series(const std::string& path, int c = 0) const;
  /// Mean of one component over records with t in [t0, t1].
  Real mean(const std::string& path, int c, Real t0, Real t1) const;

 private:
  std::vector<HistoryChannel> channels_;
  std::vector<int> offsets_;
  int width_ = 0;
  std::vector<Real> time_;
  std::vector<Real> data_;
};

}  // namespace slideline
