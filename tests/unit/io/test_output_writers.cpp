#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "slideline/core/error.hpp"
#include "slideline/io/csv_writer.hpp"
#include "slideline/io/hdf5_reader.hpp"
#include "slideline/io/hdf5_writer.hpp"

namespace slideline {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const auto dir = fs::temp_directory_path() / "slideline_io_tests";
  fs::create_directories(dir);
  return dir / name;
}

std::vector<HistoryChannel> fake_channels() {
  return {{"interfaces/solid_on_solid/slave_force", 3},
          {"interfaces/solid_on_solid/master_force", 3},
          {"supports/lower bottom/reaction", 3},
          {"nodes/5/displacement", 3},
          {"energy/kinetic", 1},
          {"energy/internal", 1}};
}

/// 16 nodes and the given cells, listed for every declared topology as mesh_description does.
MeshDescription fake_mesh(std::vector<Index> hexes, std::vector<Index> tets, std::vector<Index> quads,
                          std::vector<Index> triangles) {
  MeshDescription m;
  for (int k = 0; k < 16; ++k) {
    m.node_ids.push_back(100 + k);
    m.x0.insert(m.x0.end(), {Real(k % 3), Real(k / 3), 0.5 * k});
  }
  m.cells = {{&hex8_topology, std::move(hexes)},
             {&tet4_topology, std::move(tets)},
             {&quad4_topology, std::move(quads)},
             {&tri3_topology, std::move(triangles)}};
  return m;
}

/// Two hexahedra sharing a face plus one quadrilateral: 12 + 4 nodes.
MeshDescription fake_mesh() {
  return fake_mesh({0, 1, 2, 3, 4, 5, 6, 7, 4, 5, 6, 7, 8, 9, 10, 11}, {}, {12, 13, 14, 15}, {});
}

/// The XDMF text written next to `h5`.
std::string xdmf_text(const Hdf5Writer& w) {
  std::ifstream in(w.xdmf_path());
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

Real value_of(int record, int column) { return 0.25 * record - 1.5 * column + (column == 3 ? 1e-9 : 0.0); }

std::vector<Real> record(int r, std::size_t width) {
  std::vector<Real> v(width);
  for (std::size_t c = 0; c < width; ++c) v[c] = value_of(r, int(c));
  return v;
}

/// Reads a whole dataset as doubles (HDF5 C API inside the library: the test executable does not
/// link HDF5 itself).
std::vector<double> read_doubles(const fs::path& file, const std::string& path, std::vector<std::size_t>* dims = nullptr) {
  auto d = read_hdf5_dataset(file.string(), path);
  if (dims) *dims = d.dims;
  return d.values;
}

constexpr int kRecords = 1300;  // more than two append blocks plus a partial one
constexpr int kStates = 3;

void write_run(OutputSink& sink, const MeshDescription& mesh) {
  const auto channels = fake_channels();
  sink.begin(channels, mesh);
  const std::size_t width = 3 * 4 + 2;
  for (int r = 0; r < kRecords; ++r) {
    sink.write_history(0.001 * r, record(r, width));
    if (r % 500 == 0) {
      std::vector<Real> u(3 * mesh.node_ids.size());
      for (std::size_t k = 0; k < u.size(); ++k) u[k] = 0.01 * r + 1e-3 * k;
      sink.write_state(0.001 * r, StateFields{.displacement = u});
    }
  }
}

TEST(Hdf5Writer, HistoriesStatesAndMeshReadBack) {
  const auto path = scratch("histories.h5");
  const auto mesh = fake_mesh();
  Hdf5Writer w(path.string());
  write_run(w, mesh);
  w.flush();

  // Read while the writer is still open: flush() must have made everything durable.
  const auto& f = path;
  std::vector<std::size_t> dims;
  const auto t = read_doubles(f, "/time", &dims);
  ASSERT_EQ(dims, (std::vector<std::size_t>{kRecords}));
  EXPECT_DOUBLE_EQ(t[1234], 1.234);
  const auto slave = read_doubles(f, "/interfaces/solid_on_solid/slave_force", &dims);
  ASSERT_EQ(dims, (std::vector<std::size_t>{kRecords, 3}));
  const auto node = read_doubles(f, "/nodes/5/displacement");
  const auto reaction = read_doubles(f, "/supports/lower bottom/reaction");
  const auto ke = read_doubles(f, "/energy/kinetic", &dims);
  ASSERT_EQ(dims, (std::vector<std::size_t>{kRecords}));
  const auto ie = read_doubles(f, "/energy/internal");
  for (int r : {0, 1, 511, 512, 1023, 1024, kRecords - 1}) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(slave[std::size_t(3 * r + k)], value_of(r, k));
      EXPECT_EQ(reaction[std::size_t(3 * r + k)], value_of(r, 6 + k));
      EXPECT_EQ(node[std::size_t(3 * r + k)], value_of(r, 9 + k));
    }
    EXPECT_EQ(ke[std::size_t(r)], value_of(r, 12));
    EXPECT_EQ(ie[std::size_t(r)], value_of(r, 13));
  }
  const auto st = read_doubles(f, "/states/time", &dims);
  ASSERT_EQ(dims, (std::vector<std::size_t>{kStates}));
  EXPECT_DOUBLE_EQ(st[2], 1.0);
  const auto u = read_doubles(f, "/states/displacement", &dims);
  ASSERT_EQ(dims, (std::vector<std::size_t>{kStates, 16, 3}));
  EXPECT_DOUBLE_EQ(u[48 + 3 * 15 + 2], 0.01 * 500 + 1e-3 * 47);
  const auto x0 = read_doubles(f, "/mesh/coordinates", &dims);
  ASSERT_EQ(dims, (std::vector<std::size_t>{16, 3}));
  EXPECT_EQ(x0, mesh.x0);
  const auto hex = read_doubles(f, "/mesh/hexahedra", &dims);  // converted on read
  ASSERT_EQ(dims, (std::vector<std::size_t>{2, 8}));
  EXPECT_EQ(hex[15], 11.0);
  read_doubles(f, "/mesh/quadrilaterals", &dims);
  EXPECT_EQ(dims, (std::vector<std::size_t>{1, 4}));
  // Every declared topology has its dataset, empty where the mesh has none.
  EXPECT_TRUE(read_doubles(f, "/mesh/tetrahedra", &dims).empty());
  EXPECT_EQ(dims, (std::vector<std::size_t>{0, 4}));
  EXPECT_TRUE(read_doubles(f, "/mesh/triangles", &dims).empty());
  EXPECT_EQ(dims, (std::vector<std::size_t>{0, 3}));
  const auto ids = read_doubles(f, "/mesh/node_ids");
  EXPECT_EQ(ids[15], 115.0);
  EXPECT_EQ(read_hdf5_root_attribute(path.string(), "units"), "consistent units of the deck");
}

TEST(Hdf5Writer, UnflushedTailIsWrittenByTheDestructorAndBadRecordsThrow) {
  const auto path = scratch("destructor.h5");
  {
    Hdf5Writer w(path.string());
    write_run(w, fake_mesh());
    EXPECT_THROW(w.write_history(1.0, std::vector<Real>(3)), Error);
    EXPECT_THROW(w.write_state(1.0, StateFields{.displacement = std::vector<Real>(5)}), Error);
  }
  std::vector<std::size_t> dims;
  read_doubles(path, "/energy/internal", &dims);
  EXPECT_EQ(dims, (std::vector<std::size_t>{kRecords}));
  EXPECT_THROW(read_hdf5_dataset(path.string(), "/energy/missing"), Error);
  EXPECT_THROW(Hdf5Writer("/nonexistent-dir/x.h5"), Error);
}

TEST(Xdmf, EveryDatasetItRefersToExistsInTheHdf5File) {
  const auto path = scratch("paraview.h5");
  Hdf5Writer w(path.string());
  write_run(w, fake_mesh());
  w.flush();
  EXPECT_EQ(w.xdmf_path(), scratch("paraview.xdmf").string());
  const std::string xml = xdmf_text(w);
  EXPECT_NE(xml.find("CollectionType=\"Temporal\""), std::string::npos);
  EXPECT_NE(xml.find("TopologyType=\"Hexahedron\" NumberOfElements=\"2\""), std::string::npos);
  EXPECT_NE(xml.find("TopologyType=\"Quadrilateral\" NumberOfElements=\"1\""), std::string::npos);
  EXPECT_NE(xml.find("<Time Value=\"1\"/>"), std::string::npos);

  const std::regex ref(">([^<>:]+\\.h5):([^<]+)<");
  std::set<std::string> paths;
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), ref); it != std::sregex_iterator(); ++it) {
    EXPECT_EQ((*it)[1].str(), "paraview.h5");
    paths.insert((*it)[2].str());
  }
  // Geometry from the stored deformed coordinates (no XDMF Function: ParaView's Xdmf3 readers abort
  // on it), the attribute from the displacements.
  EXPECT_TRUE(paths.count("/mesh/hexahedra") && paths.count("/mesh/quadrilaterals"));
  EXPECT_TRUE(paths.count("/states/state_2/coordinates") && paths.count("/states/state_2/displacement"));
  // ParaView 5.11's Xdmf3 readers crash on Function and HyperSlab items: neither is used.
  EXPECT_EQ(xml.find("Function"), std::string::npos);
  EXPECT_EQ(xml.find("HyperSlab"), std::string::npos);
  for (const auto& p : paths) EXPECT_TRUE(hdf5_exists(path.string(), p)) << p;
  EXPECT_FALSE(hdf5_exists(path.string(), "/states/nothing"));
  // The geometry of a state is the reference coordinates plus that state's displacements.
  {
    std::vector<std::size_t> dims;
    const auto x0 = read_doubles(path.string(), "/mesh/coordinates", &dims);
    const auto u = read_doubles(path.string(), "/states/state_2/displacement", &dims);
    const auto x = read_doubles(path.string(), "/states/state_2/coordinates", &dims);
    ASSERT_EQ(x.size(), x0.size());
    ASSERT_EQ(u.size(), x0.size());
    for (std::size_t i = 0; i < x.size(); ++i) EXPECT_EQ(x[i], x0[i] + u[i]) << i;
  }
  // Balanced tags: every opening <Grid> and <DataItem> has its closing tag.
  const auto count = [&](const std::string& s) {
    std::size_t n = 0;
    for (auto p = xml.find(s); p != std::string::npos; p = xml.find(s, p + 1)) ++n;
    return n;
  };
  EXPECT_EQ(count("<Grid "), count("</Grid>"));
  EXPECT_EQ(count("<DataItem "), count("</DataItem>"));
  EXPECT_EQ(count("<Grid Name=\"state "), std::size_t(kStates));
}

TEST(Xdmf, CellTypesComeFromTheTopologies) {
  // Tetrahedra alone: one grid per state (no spatial collection), 4 nodes per cell.
  {
    const auto path = scratch("tets.h5");
    Hdf5Writer w(path.string());
    write_run(w, fake_mesh({}, {0, 1, 2, 3, 1, 2, 3, 4}, {}, {}));
    w.flush();
    const std::string xml = xdmf_text(w);
    EXPECT_NE(xml.find("<Grid Name=\"tetrahedra\" GridType=\"Uniform\">"), std::string::npos);
    EXPECT_NE(xml.find("TopologyType=\"Tetrahedron\" NumberOfElements=\"2\""), std::string::npos);
    EXPECT_NE(xml.find("Dimensions=\"2 4\""), std::string::npos);
    EXPECT_NE(xml.find("tets.h5:/mesh/tetrahedra<"), std::string::npos);
    EXPECT_EQ(xml.find("CollectionType=\"Spatial\""), std::string::npos);
    EXPECT_EQ(xml.find("Hexahedron"), std::string::npos);
    std::vector<std::size_t> dims;
    const auto tets = read_doubles(path, "/mesh/tetrahedra", &dims);
    ASSERT_EQ(dims, (std::vector<std::size_t>{2, 4}));
    EXPECT_EQ(tets[7], 4.0);
  }
  // Tetrahedra and triangles: a spatial collection of one grid per topology, solids first.
  {
    const auto path = scratch("tets_and_triangles.h5");
    Hdf5Writer w(path.string());
    write_run(w, fake_mesh({}, {0, 1, 2, 3}, {}, {5, 6, 7, 8, 9, 10}));
    w.flush();
    const std::string xml = xdmf_text(w);
    const auto tet = xml.find("TopologyType=\"Tetrahedron\" NumberOfElements=\"1\"");
    const auto tri = xml.find("TopologyType=\"Triangle\" NumberOfElements=\"2\"");
    ASSERT_NE(tet, std::string::npos);
    ASSERT_NE(tri, std::string::npos);
    EXPECT_LT(tet, tri);
    EXPECT_NE(xml.find("Dimensions=\"2 3\""), std::string::npos);
    EXPECT_NE(xml.find("CollectionType=\"Spatial\""), std::string::npos);
    std::vector<std::size_t> dims;
    read_doubles(path, "/mesh/triangles", &dims);
    EXPECT_EQ(dims, (std::vector<std::size_t>{2, 3}));
  }
}

TEST(CsvWriter, HeaderAndValues) {
  const auto path = scratch("histories.csv");
  {
    CsvWriter w(path.string());
    write_run(w, fake_mesh());
    w.flush();
  }
  std::ifstream in(path);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header.rfind("time,interfaces/solid_on_solid/slave_force_x,interfaces/solid_on_solid/slave_force_y,", 0), 0u);
  EXPECT_NE(header.find(",supports/lower bottom/reaction_z,nodes/5/displacement_x,"), std::string::npos);
  EXPECT_EQ(header.substr(header.size() - 31), ",energy/kinetic,energy/internal");
  std::string line;
  int rows = 0;
  std::string row7;
  while (std::getline(in, line)) {
    if (rows == 7) row7 = line;
    ++rows;
  }
  EXPECT_EQ(rows, kRecords);
  std::stringstream ss(row7);
  std::string cell;
  std::vector<double> v;
  while (std::getline(ss, cell, ',')) v.push_back(std::stod(cell));
  ASSERT_EQ(v.size(), 15u);
  EXPECT_DOUBLE_EQ(v[0], 0.007);
  for (int c = 0; c < 14; ++c) EXPECT_EQ(v[std::size_t(c + 1)], value_of(7, c)) << c;
}

}  // namespace
}  // namespace slideline
