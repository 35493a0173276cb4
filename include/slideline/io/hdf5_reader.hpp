#pragma once
/// Minimal read-back of slideline's HDF5 output (docs/output.md), for tests, verification and
/// post-processing in C++ without HDF5 types in the caller.
#include <cstddef>
#include <string>
#include <vector>

namespace slideline {

/// A whole dataset converted to double, row-major, with its dimensions.
struct Hdf5Dataset {
  std::vector<std::size_t> dims;
  std::vector<double> values;
};

/// Reads dataset `dataset` (e.g. "/interfaces/solid_on_solid/slave_force") of file `path`.
/// Integer datasets are converted. Throws Error when the file or dataset cannot be read.
Hdf5Dataset read_hdf5_dataset(const std::string& path, const std::string& dataset);

/// True when `object` (a dataset or group path) exists in the file. Throws Error when the file
/// cannot be opened.
bool hdf5_exists(const std::string& path, const std::string& object);

/// A string attribute of the root group ("units", "format"); empty when absent.
std::string read_hdf5_root_attribute(const std::string& path, const std::string& name);

}  // namespace slideline
