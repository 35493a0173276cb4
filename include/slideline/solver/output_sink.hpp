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

/// Per-cell values of one topology that do not change during a run.
struct TopologyCellInfo {
  std::vector<Id> part_ids;       ///< deck *PART id of each cell
  std::vector<Id> material_ids;   ///< deck material id (*PART MID) of each cell
  std::vector<Real> thickness;    ///< section thickness of each cell (length; 0 for solids)
};

/// What a sink needs to describe the mesh (reference configuration) for state output.
struct MeshDescription {
  std::vector<Id> node_ids;
  std::vector<Real> x0;              ///< reference coordinates, 3 per node
  /// The cells, grouped by topology (cells_by_topology: every declared topology, in
  /// all_topologies order, empty where the model has none). Writers write each group as its
  /// topology says (HDF5 /mesh/<cell_set>, XDMF TopologyType xdmf_cell).
  std::vector<TopologyCells> cells;
  /// Per-cell values fixed for the run, one entry per `cells` entry (same order), cells in the
  /// same order; empty when the producer has none.
  std::vector<TopologyCellInfo> cell_info;
};

/// One state's cell fields of one topology (an entry per MeshDescription::cells entry).
struct TopologyCellFields {
  std::vector<Real> stress;          ///< 6 per cell: Cauchy xx, yy, zz, xy, yz, xz (force/length^2)
  std::vector<Real> stress_bottom;   ///< 6 per cell (surface topologies): outermost point, -z side
  std::vector<Real> stress_top;      ///< 6 per cell (surface topologies): outermost point, +z side
  std::vector<Real> von_mises;       ///< 1 per cell (force/length^2)
  std::vector<Real> plastic_strain;  ///< 1 per cell (dimensionless)
  std::vector<Real> energy_density;  ///< 1 per cell (energy per reference volume)
  std::vector<Real> deleted;         ///< 1 per cell: 1 deleted by erosion, 0 not; empty: no part erodes
  /// 1 per cell (surface topologies, length): the shell's current thickness; empty unless a part
  /// changes its thickness (*CONTROL_SHELL ISTUPD; the others keep their section's).
  std::vector<Real> current_thickness;
};

/// One output state. Nodal vectors hold 3 values per node (x, y, z interleaved); an empty span
/// (or empty `cells`) means the producer does not record that field.
struct StateFields {
  std::span<const Real> displacement;   ///< u = x - x0 (length)
  std::span<const Real> velocity;       ///< length/time
  std::span<const Real> acceleration;   ///< length/time^2
  std::span<const Real> contact_force;  ///< the contact forces on each node (force)
  std::span<const TopologyCellFields> cells;
};

class OutputSink {
 public:
  virtual ~OutputSink() = default;
  /// Called once before any record.
  virtual void begin(const std::vector<HistoryChannel>& channels, const MeshDescription& mesh) = 0;
  /// One history record: values of every channel in order, components flattened.
  virtual void write_history(Real t, std::span<const Real> values) = 0;
  /// One state at time t (see StateFields).
  virtual void write_state(Real t, const StateFields& state) = 0;
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
  void write_state(Real, const StateFields&) override {}
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
