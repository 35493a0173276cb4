// Read-back of HDF5 output with the C API (see hdf5_reader.hpp).
#include "slideline/io/hdf5_reader.hpp"

#include <hdf5.h>

#include <sstream>

#include "slideline/core/error.hpp"

namespace slideline {
namespace {

/// Opens a file read-only with HDF5's error printing off (the Error thrown says what failed).
class File {
 public:
  explicit File(const std::string& path) {
    H5E_auto2_t func = nullptr;
    void* data = nullptr;
    H5Eget_auto2(H5E_DEFAULT, &func, &data);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    id_ = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    H5Eset_auto2(H5E_DEFAULT, func, data);
    if (id_ < 0) throw Error(path + ": cannot open the HDF5 file");
  }
  ~File() { H5Fclose(id_); }
  File(const File&) = delete;
  File& operator=(const File&) = delete;
  hid_t id() const { return id_; }

 private:
  hid_t id_ = -1;
};

bool exists_in(hid_t file, const std::string& object) {
  // Walk the path: H5Lexists fails (rather than returning false) on a missing intermediate group.
  std::string partial;
  std::stringstream ss(object);
  std::string piece;
  while (std::getline(ss, piece, '/')) {
    if (piece.empty()) continue;
    partial += "/" + piece;
    if (H5Lexists(file, partial.c_str(), H5P_DEFAULT) <= 0) return false;
  }
  return true;
}

}  // namespace

Hdf5Dataset read_hdf5_dataset(const std::string& path, const std::string& dataset) {
  File f(path);
  if (!exists_in(f.id(), dataset)) throw Error(path + ": no dataset " + dataset);
  const hid_t d = H5Dopen2(f.id(), dataset.c_str(), H5P_DEFAULT);
  if (d < 0) throw Error(path + ": cannot open dataset " + dataset);
  const hid_t s = H5Dget_space(d);
  const int rank = H5Sget_simple_extent_ndims(s);
  Hdf5Dataset out;
  std::vector<hsize_t> dims(static_cast<std::size_t>(std::max(rank, 0)));
  if (rank > 0) H5Sget_simple_extent_dims(s, dims.data(), nullptr);
  std::size_t n = 1;
  for (auto x : dims) {
    out.dims.push_back(static_cast<std::size_t>(x));
    n *= static_cast<std::size_t>(x);
  }
  out.values.resize(n);
  herr_t status = 0;
  if (n > 0) status = H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.values.data());
  H5Sclose(s);
  H5Dclose(d);
  if (status < 0) throw Error(path + ": cannot read dataset " + dataset);
  return out;
}

bool hdf5_exists(const std::string& path, const std::string& object) {
  File f(path);
  return exists_in(f.id(), object);
}

std::string read_hdf5_root_attribute(const std::string& path, const std::string& name) {
  File f(path);
  if (H5Aexists(f.id(), name.c_str()) <= 0) return {};
  const hid_t a = H5Aopen(f.id(), name.c_str(), H5P_DEFAULT);
  const hid_t t = H5Aget_type(a);
  std::string value(H5Tget_size(t), '\0');
  const hid_t mem = H5Tcopy(t);
  H5Aread(a, mem, value.data());
  H5Tclose(mem);
  H5Tclose(t);
  H5Aclose(a);
  while (!value.empty() && value.back() == '\0') value.pop_back();
  return value;
}

}  // namespace slideline
