// HDF5 + XDMF output sink (C API: extendible chunked datasets appended in blocks).
#include "slideline/io/hdf5_writer.hpp"

#include <hdf5.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <type_traits>

#include "slideline/core/error.hpp"
#include "xdmf_document.hpp"

namespace slideline {
namespace {

/// History records buffered before an append: large enough that the per-dataset HDF5 calls are
/// amortised, small enough that little is lost if the process is killed between flushes.
constexpr std::size_t kHistoryBlock = 512;

/// Closes an HDF5 handle on scope exit.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  hid_t get() const { return id_; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

void check(herr_t status, const std::string& what) {
  if (status < 0) throw Error("HDF5: " + what + " failed");
}
hid_t check_id(hid_t id, const std::string& what) {
  if (id < 0) throw Error("HDF5: " + what + " failed");
  return id;
}

/// An extendible dataset whose first dimension grows; `row` is the shape of one record.
struct Series {
  hid_t dset = -1;
  std::vector<hsize_t> row;  // dims after the first
  hsize_t rows = 0;
  hid_t type = H5T_NATIVE_DOUBLE;

  hsize_t row_size() const {
    hsize_t n = 1;
    for (auto d : row) n *= d;
    return n;
  }

  void create(hid_t file, const std::string& path, std::vector<hsize_t> row_shape, hsize_t chunk_rows) {
    row = std::move(row_shape);
    std::vector<hsize_t> dims{0}, maxdims{H5S_UNLIMITED}, chunk{chunk_rows};
    for (auto d : row) {
      dims.push_back(d);
      maxdims.push_back(d);
      chunk.push_back(std::max<hsize_t>(d, 1));
    }
    Handle space(check_id(H5Screate_simple(int(dims.size()), dims.data(), maxdims.data()), "dataspace " + path), H5Sclose);
    Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
    check(H5Pset_chunk(dcpl.get(), int(chunk.size()), chunk.data()), "chunking " + path);
    Handle lcpl(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
    check(H5Pset_create_intermediate_group(lcpl.get(), 1), "link property");
    dset = check_id(H5Dcreate2(file, path.c_str(), type, space.get(), lcpl.get(), dcpl.get(), H5P_DEFAULT),
                    "creating dataset " + path);
  }

  /// Appends `count` rows held contiguously in `data`.
  void append(const Real* data, hsize_t count) {
    if (count == 0) return;
    std::vector<hsize_t> dims{rows + count}, start{rows}, extent{count};
    for (auto d : row) {
      dims.push_back(d);
      start.push_back(0);
      extent.push_back(d);
    }
    check(H5Dset_extent(dset, dims.data()), "extending a dataset");
    Handle file_space(H5Dget_space(dset), H5Sclose);
    check(H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start.data(), nullptr, extent.data(), nullptr),
          "selecting rows");
    Handle mem_space(H5Screate_simple(int(extent.size()), extent.data(), nullptr), H5Sclose);
    check(H5Dwrite(dset, H5T_NATIVE_DOUBLE, mem_space.get(), file_space.get(), H5P_DEFAULT, data), "writing rows");
    rows += count;
  }

  void close() {
    if (dset >= 0) H5Dclose(dset);
    dset = -1;
  }
};

template <class T>
void write_fixed(hid_t file, const std::string& path, hid_t mem_type, hid_t file_type, const std::vector<T>& data,
                 hsize_t cols) {
  const hsize_t rows = cols ? data.size() / cols : 0;
  std::vector<hsize_t> dims{rows};
  if (cols > 1) dims.push_back(cols);
  Handle space(check_id(H5Screate_simple(int(dims.size()), dims.data(), nullptr), "dataspace " + path), H5Sclose);
  Handle lcpl(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
  check(H5Pset_create_intermediate_group(lcpl.get(), 1), "link property");
  Handle dset(check_id(H5Dcreate2(file, path.c_str(), file_type, space.get(), lcpl.get(), H5P_DEFAULT, H5P_DEFAULT),
                       "creating dataset " + path),
              H5Dclose);
  if (!data.empty()) check(H5Dwrite(dset.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), "writing " + path);
}

void write_string_attribute(hid_t obj, const char* name, const std::string& value) {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), std::max<std::size_t>(value.size(), 1));
  H5Tset_strpad(type.get(), H5T_STR_NULLTERM);
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attr(check_id(H5Acreate2(obj, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), "attribute"), H5Aclose);
  check(H5Awrite(attr.get(), type.get(), value.c_str()), "writing attribute");
}

/// Writes a (rows x cols) dataset with a "units" attribute (an output field, xdmf_document.hpp).
template <class T>
void write_field(hid_t file, const std::string& path, const std::vector<T>& data, hsize_t cols,
                 std::string_view units) {
  if constexpr (std::is_integral_v<T>)
    write_fixed(file, path, H5T_NATIVE_INT64, H5T_STD_I64LE, data, cols);
  else
    write_fixed(file, path, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, data, cols);
  Handle dset(check_id(H5Dopen2(file, path.c_str(), H5P_DEFAULT), "opening " + path), H5Dclose);
  write_string_attribute(dset.get(), "units", std::string(units));
}

/// Index of the field called `name` in xdmf::kFields.
std::size_t field_index(std::string_view name) {
  std::size_t i = 0;
  while (i < xdmf::kFieldCount && xdmf::kFields[i].name != name) ++i;
  if (i == xdmf::kFieldCount) throw Error("HDF5 writer: no output field " + std::string(name));
  return i;
}

}  // namespace

struct Hdf5Writer::Impl {
  std::string path;
  hid_t file = -1;
  Series time;
  std::vector<Series> channels;
  std::vector<int> offsets;
  std::size_t width = 0;
  std::vector<Real> buffer_t;
  std::vector<Real> buffer;  // buffered records, width values each
  Series state_time;
  Series state_disp;
  std::vector<Real> x0;      // reference coordinates, 3 per node
  std::vector<Real> coords;  // one state's deformed coordinates x0 + u (the XDMF geometry)
  std::vector<Real> values;  // one field of one state, for writing
  xdmf::Layout layout;       // grids, state times and the fields each state holds (the XDMF file)
  std::vector<std::size_t> cell_group;  // per layout grid, its entry in MeshDescription::cells
  std::uint32_t fixed_fields = 0;       // the fixed cell fields written at begin()
  bool begun = false;

  void write_buffer() {
    const hsize_t n = buffer_t.size();
    if (n == 0) return;
    time.append(buffer_t.data(), n);
    std::vector<Real> column;
    for (std::size_t c = 0; c < channels.size(); ++c) {
      const auto comps = static_cast<std::size_t>(channels[c].row_size());
      column.resize(n * comps);
      for (std::size_t r = 0; r < n; ++r)
        for (std::size_t k = 0; k < comps; ++k)
          column[r * comps + k] = buffer[r * width + static_cast<std::size_t>(offsets[c]) + k];
      channels[c].append(column.data(), n);
    }
    buffer_t.clear();
    buffer.clear();
  }

  std::string xdmf_path() const { return std::filesystem::path(path).replace_extension(".xdmf").string(); }

  /// Writes field `name` of state s (nodal: `set` empty) when `data` is not empty, and marks it
  /// in `mask`.
  void state_field(std::string_view name, std::size_t s, std::string_view set, std::span<const Real> data,
                   std::uint32_t& mask) {
    if (data.empty()) return;
    const std::size_t i = field_index(name);
    const xdmf::Field& f = xdmf::kFields[i];
    values.assign(data.begin(), data.end());
    write_field(file, xdmf::field_path(f, s, set), values, static_cast<hsize_t>(f.components), f.units);
    mask |= 1u << i;
  }

  /// The cell fields of state s (`cells` indexed as MeshDescription::cells).
  void cell_fields(std::size_t s, std::span<const TopologyCellFields> cells, std::uint32_t& mask) {
    for (std::size_t g = 0; g < layout.grids.size(); ++g) {
      if (cell_group[g] >= cells.size()) continue;
      const TopologyCellFields& c = cells[cell_group[g]];
      const std::string_view set = layout.grids[g].topology->cell_set;
      state_field("stress", s, set, c.stress, mask);
      state_field("stress_bottom", s, set, c.stress_bottom, mask);
      state_field("stress_top", s, set, c.stress_top, mask);
      state_field("von_mises", s, set, c.von_mises, mask);
      state_field("plastic_strain", s, set, c.plastic_strain, mask);
      state_field("energy_density", s, set, c.energy_density, mask);
      state_field("deleted", s, set, c.deleted, mask);
      state_field("current_thickness", s, set, c.current_thickness, mask);
    }
  }

  /// The fixed cell fields (part, material, thickness) of every grid, once.
  void fixed_cell_fields(const MeshDescription& mesh) {
    for (std::size_t g = 0; g < layout.grids.size(); ++g) {
      if (cell_group[g] >= mesh.cell_info.size()) continue;
      const TopologyCellInfo& info = mesh.cell_info[cell_group[g]];
      const std::string_view set = layout.grids[g].topology->cell_set;
      const auto fixed = [&](std::string_view name, const auto& data) {
        const std::size_t i = field_index(name);
        write_field(file, xdmf::field_path(xdmf::kFields[i], 0, set), data, 1, xdmf::kFields[i].units);
        fixed_fields |= 1u << i;
      };
      fixed("part_id", info.part_ids);
      fixed("material_id", info.material_ids);
      if (layout.grids[g].topology->dimension == 2) fixed("thickness", info.thickness);
    }
  }

  void write_xdmf() const {
    // Write then rename, so that a reader never sees a half-written file.
    const std::string target = xdmf_path();
    const std::string tmp = target + ".tmp";
    {
      std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
      out << xdmf::document(layout);
      if (!out) throw Error(tmp + ": write failed");
    }
    std::filesystem::rename(tmp, target);
  }

  void close() {
    for (auto& c : channels) c.close();
    time.close();
    state_time.close();
    state_disp.close();
    if (file >= 0) H5Fclose(file);
    file = -1;
  }
};

Hdf5Writer::Hdf5Writer(const std::string& path) : impl_(std::make_unique<Impl>()) {
  impl_->path = path;
  impl_->layout.h5 = std::filesystem::path(path).filename().string();
  {
    // HDF5 prints its error stack on failure; the Error thrown below says it better.
    H5E_auto2_t func = nullptr;
    void* data = nullptr;
    H5Eget_auto2(H5E_DEFAULT, &func, &data);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    impl_->file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    H5Eset_auto2(H5E_DEFAULT, func, data);
  }
  if (impl_->file < 0) throw Error(path + ": cannot create the HDF5 output file");
  write_string_attribute(impl_->file, "units", "consistent units of the deck");
  write_string_attribute(impl_->file, "format", "slideline output 1 (docs/output.md)");
}

Hdf5Writer::~Hdf5Writer() {
  try {
    flush();
  } catch (...) {
    // A destructor must not throw; flush() reports errors to callers that want them.
  }
  impl_->close();
}

const std::string& Hdf5Writer::path() const { return impl_->path; }
std::string Hdf5Writer::xdmf_path() const { return impl_->xdmf_path(); }

void Hdf5Writer::begin(const std::vector<HistoryChannel>& channels, const MeshDescription& mesh) {
  auto& d = *impl_;
  if (d.begun) throw Error(d.path + ": begin() called twice");
  d.begun = true;
  const hid_t f = d.file;
  d.time.create(f, "/time", {}, kHistoryBlock);
  int off = 0;
  for (const auto& c : channels) {
    Series s;
    const std::string p = "/" + c.path;
    s.create(f, p, c.components == 1 ? std::vector<hsize_t>{} : std::vector<hsize_t>{hsize_t(c.components)}, kHistoryBlock);
    d.channels.push_back(s);
    d.offsets.push_back(off);
    off += c.components;
  }
  d.width = static_cast<std::size_t>(off);

  d.layout.nodes = mesh.node_ids.size();
  write_fixed(f, "/mesh/node_ids", H5T_NATIVE_INT64, H5T_STD_I64LE, mesh.node_ids, 1);
  write_fixed(f, "/mesh/coordinates", H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, mesh.x0, 3);
  for (std::size_t i = 0; i < mesh.cells.size(); ++i) {
    const TopologyCells& c = mesh.cells[i];
    write_fixed(f, "/mesh/" + std::string(c.topology->cell_set), H5T_NATIVE_INT32, H5T_STD_I32LE,
                c.connectivity, static_cast<hsize_t>(c.topology->nodes));
    if (c.count() > 0) {
      d.layout.grids.push_back({c.topology, c.count()});
      d.cell_group.push_back(i);
    }
  }
  d.fixed_cell_fields(mesh);
  d.state_time.create(f, "/states/time", {}, 64);
  if (d.layout.nodes > 0) {
    d.state_disp.create(f, "/states/displacement", {hsize_t(d.layout.nodes), 3}, 1);
  }
  d.x0 = mesh.x0;
  d.coords.assign(mesh.x0.size(), 0.0);
}

void Hdf5Writer::write_history(Real t, std::span<const Real> values) {
  auto& d = *impl_;
  if (values.size() != d.width)
    throw Error(d.path + ": history record has " + std::to_string(values.size()) + " values, expected " +
                std::to_string(d.width));
  d.buffer_t.push_back(t);
  d.buffer.insert(d.buffer.end(), values.begin(), values.end());
  if (d.buffer_t.size() >= kHistoryBlock) d.write_buffer();
}

void Hdf5Writer::write_state(Real t, const StateFields& state) {
  auto& d = *impl_;
  const std::size_t n3 = 3 * d.layout.nodes;
  const auto check_size = [&](std::span<const Real> v, const char* what) {
    if (!v.empty() && v.size() != n3)
      throw Error(d.path + ": state " + what + " has " + std::to_string(v.size()) + " values, expected " +
                  std::to_string(n3));
  };
  if (state.displacement.size() != n3)
    throw Error(d.path + ": state has " + std::to_string(state.displacement.size()) + " displacement values, expected " +
                std::to_string(n3));
  check_size(state.velocity, "velocity");
  check_size(state.acceleration, "acceleration");
  check_size(state.contact_force, "contact force");
  const std::size_t s = d.layout.times.size();
  d.state_time.append(&t, 1);
  std::uint32_t mask = d.fixed_fields;
  if (d.layout.nodes > 0) {
    d.state_disp.append(state.displacement.data(), 1);
    for (std::size_t i = 0; i < d.coords.size(); ++i) d.coords[i] = d.x0[i] + state.displacement[i];
    write_fixed(d.file, xdmf::state_group(s) + "/coordinates", H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, d.coords, 3);
    d.state_field("displacement", s, "", state.displacement, mask);
    d.state_field("velocity", s, "", state.velocity, mask);
    d.state_field("acceleration", s, "", state.acceleration, mask);
    d.state_field("contact_force", s, "", state.contact_force, mask);
    d.cell_fields(s, state.cells, mask);
  }
  d.layout.times.push_back(t);
  d.layout.fields.push_back(mask);
}

void Hdf5Writer::flush() {
  auto& d = *impl_;
  if (d.file < 0) return;
  d.write_buffer();
  check(H5Fflush(d.file, H5F_SCOPE_GLOBAL), "flushing " + d.path);
  if (d.begun) d.write_xdmf();
}

}  // namespace slideline
