#pragma once
/// HDF5 output of one run (the output contract, docs/output.md), with an XDMF file beside it so
/// that ParaView opens the deformed-mesh series directly.
///
/// Layout of `<name>.h5`:
///   /time                         (n)              history record times
///   /<channel path>               (n) or (n x 3)   one dataset per history channel
///   /mesh/node_ids                (N)              deck node ids, internal node order
///   /mesh/coordinates             (N x 3)          reference coordinates
///   /mesh/hexahedra               (E x 8)          internal node indices (0-based)
///   /mesh/quadrilaterals          (Q x 4)          internal node indices (0-based)
///   /states/time                  (S)              state times
///   /states/displacement          (S x N x 3)      nodal displacements
///   /states/state_<k>/<field>     (N x 3)          coordinates, displacement, velocity,
///                                                  acceleration, contact_force of state k
///   /states/state_<k>/<cells>/<f> (C x 6) or (C)   stress (+ stress_bottom, stress_top for
///                                                  shells), von_mises, plastic_strain,
///                                                  energy_density of state k
///   /mesh/<cells>_<f>             (C)              part_id, material_id (+ thickness, shells)
/// (the field table: src/io/xdmf_document.hpp; docs/output.md).
/// Histories are buffered and appended in blocks; flush() writes the buffer, flushes the file
/// and rewrites `<name>.xdmf`, so a run that stops early keeps everything up to its last flush.
#include <memory>
#include <string>

#include "slideline/solver/output_sink.hpp"

namespace slideline {

class Hdf5Writer final : public OutputSink {
 public:
  /// Creates (or truncates) the HDF5 file at `path`; the XDMF file gets the same name with the
  /// extension .xdmf. Throws Error when the file cannot be created.
  explicit Hdf5Writer(const std::string& path);
  /// Flushes and closes the file (errors are swallowed here: call flush() to see them).
  ~Hdf5Writer() override;
  Hdf5Writer(const Hdf5Writer&) = delete;
  Hdf5Writer& operator=(const Hdf5Writer&) = delete;

  void begin(const std::vector<HistoryChannel>& channels, const MeshDescription& mesh) override;
  void write_history(Real t, std::span<const Real> values) override;
  void write_state(Real t, const StateFields& state) override;
  void flush() override;

  const std::string& path() const;
  /// Path of the XDMF companion file.
  std::string xdmf_path() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace slideline
