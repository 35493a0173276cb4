#include "slideline/io/csv_writer.hpp"

#include <charconv>

#include "slideline/core/error.hpp"

namespace slideline {

CsvWriter::CsvWriter(const std::string& path) : path_(path), out_(path, std::ios::binary | std::ios::trunc) {
  if (!out_) throw Error(path + ": cannot open the CSV file for writing");
}

std::vector<std::string> CsvWriter::column_names(const std::vector<HistoryChannel>& channels) {
  static const char* const axes[] = {"_x", "_y", "_z"};
  std::vector<std::string> names;
  for (const auto& c : channels) {
    if (c.components == 1) {
      names.push_back(c.path);
    } else {
      for (int k = 0; k < c.components; ++k) {
        std::string name = c.path;
        if (c.components == 3) {
          name += axes[k];
        } else {
          name += '_';
          name += std::to_string(k);
        }
        names.push_back(std::move(name));
      }
    }
  }
  return names;
}

void CsvWriter::begin(const std::vector<HistoryChannel>& channels, const MeshDescription&) {
  const auto names = column_names(channels);
  width_ = names.size();
  out_ << "time";
  for (const auto& n : names) out_ << ',' << n;
  out_ << '\n';
}

void CsvWriter::write_history(Real t, std::span<const Real> values) {
  if (values.size() != width_)
    throw Error(path_ + ": history record has " + std::to_string(values.size()) + " values, expected " +
                std::to_string(width_));
  // Shortest exact form: the CSV holds the same doubles as the HDF5 file.
  char buf[32];
  auto put = [&](Real v) {
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    out_.write(buf, r.ptr - buf);
  };
  put(t);
  for (Real v : values) {
    out_ << ',';
    put(v);
  }
  out_ << '\n';
}

void CsvWriter::flush() {
  out_.flush();
  if (!out_) throw Error(path_ + ": write failed");
}

}  // namespace slideline
