// HDF5 + XDMF output sink (C API: extendible chunked datasets appended in blocks).
#include "slideline/io/hdf5_writer.hpp"

#include <hdf5.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "slideline/core/error.hpp"

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
  std::vector<Real> disp;    // one state's displacements

  /// The group holding state s's own (nodes x 3) datasets.
  static std::string state_group(std::size_t s) { return "/states/state_" + std::to_string(s); }
  std::vector<Real> state_times;  // for the XDMF file
  std::size_t nodes = 0;
  /// One XDMF grid per topology the mesh has cells of (the topologies in the description's order).
  struct CellGrid {
    const ElementTopology* topology;
    std::size_t count;
  };
  std::vector<CellGrid> grids;
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

  void write_xdmf() const {
    const std::string h5 = std::filesystem::path(path).filename().string();
    std::ostringstream x;
    x.precision(17);
    x << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n  <Domain>\n"
      << "    <Grid Name=\"states\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (std::size_t s = 0; s < state_times.size(); ++s) {
      // Per-state (nodes x 3) datasets, referenced directly: ParaView 5.11's Xdmf3 readers crash on
      // HyperSlab and Function items, so the geometry is the stored deformed coordinates.
      const auto slab = [&](const char* name) {
        std::ostringstream d;
        d << "          <DataItem Dimensions=\"" << nodes
          << " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << h5 << ":" << state_group(s)
          << "/" << name << "</DataItem>\n";
        return d.str();
      };
      const auto grid = [&](const CellGrid& g, const std::string& time_tag) {
        const ElementTopology& t = *g.topology;
        x << "      <Grid Name=\"" << t.cell_set << "\" GridType=\"Uniform\">\n" << time_tag
          << "        <Topology TopologyType=\"" << t.xdmf_cell << "\" NumberOfElements=\"" << g.count
          << "\">\n"
          << "          <DataItem Dimensions=\"" << g.count << " " << t.nodes
          << "\" NumberType=\"Int\" Precision=\"4\" Format=\"HDF\">" << h5 << ":/mesh/" << t.cell_set
          << "</DataItem>\n"
          << "        </Topology>\n"
          << "        <Geometry GeometryType=\"XYZ\">\n"
          << slab("coordinates") << "        </Geometry>\n"
          << "        <Attribute Name=\"displacement\" AttributeType=\"Vector\" Center=\"Node\">\n"
          << slab("displacement") << "        </Attribute>\n"
          << "      </Grid>\n";
      };
      if (grids.size() > 1) {
        // Several topologies: a spatial collection of one grid each per state.
        x << "     <Grid Name=\"state " << s << "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
          << "      <Time Value=\"" << state_times[s] << "\"/>\n";
        for (const CellGrid& g : grids) grid(g, "");
        x << "     </Grid>\n";
      } else if (grids.size() == 1) {
        // One topology: the grid itself is the state (the layout every XDMF reader takes).
        std::ostringstream tv;
        tv.precision(17);
        tv << "        <Time Value=\"" << state_times[s] << "\"/>\n";
        grid(grids.front(), tv.str());
      }
    }
    x << "    </Grid>\n  </Domain>\n</Xdmf>\n";
    // Write then rename, so that a reader never sees a half-written file.
    const std::string target = xdmf_path();
    const std::string tmp = target + ".tmp";
    {
      std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
      out << x.str();
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

  d.nodes = mesh.node_ids.size();
  write_fixed(f, "/mesh/node_ids", H5T_NATIVE_INT64, H5T_STD_I64LE, mesh.node_ids, 1);
  write_fixed(f, "/mesh/coordinates", H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, mesh.x0, 3);
  for (const TopologyCells& c : mesh.cells) {
    write_fixed(f, "/mesh/" + std::string(c.topology->cell_set), H5T_NATIVE_INT32, H5T_STD_I32LE,
                c.connectivity, static_cast<hsize_t>(c.topology->nodes));
    if (c.count() > 0) d.grids.push_back({c.topology, c.count()});
  }
  d.state_time.create(f, "/states/time", {}, 64);
  if (d.nodes > 0) {
    d.state_disp.create(f, "/states/displacement", {hsize_t(d.nodes), 3}, 1);
  }
  d.x0 = mesh.x0;
  d.coords.assign(mesh.x0.size(), 0.0);
  d.disp.assign(mesh.x0.size(), 0.0);
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

void Hdf5Writer::write_state(Real t, std::span<const Real> displacements) {
  auto& d = *impl_;
  if (displacements.size() != 3 * d.nodes)
    throw Error(d.path + ": state has " + std::to_string(displacements.size()) + " values, expected " +
                std::to_string(3 * d.nodes));
  d.state_time.append(&t, 1);
  if (d.nodes > 0) {
    d.state_disp.append(displacements.data(), 1);
    for (std::size_t i = 0; i < d.coords.size(); ++i) {
      d.disp[i] = displacements[i];
      d.coords[i] = d.x0[i] + displacements[i];
    }
    const std::string g = Impl::state_group(d.state_times.size());
    write_fixed(d.file, g + "/coordinates", H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, d.coords, 3);
    write_fixed(d.file, g + "/displacement", H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, d.disp, 3);
  }
  d.state_times.push_back(t);
}

void Hdf5Writer::flush() {
  auto& d = *impl_;
  if (d.file < 0) return;
  d.write_buffer();
  check(H5Fflush(d.file, H5F_SCOPE_GLOBAL), "flushing " + d.path);
  if (d.begun) d.write_xdmf();
}

}  // namespace slideline
