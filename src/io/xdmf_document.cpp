// The XDMF companion of the HDF5 output: a temporal collection of the deformed states with every
// nodal and cell field (docs/output.md, "ParaView").
#include "xdmf_document.hpp"

#include <sstream>

namespace slideline::xdmf {

std::string state_group(std::size_t s) { return "/states/state_" + std::to_string(s); }

std::string field_path(const Field& f, std::size_t state, std::string_view cell_set) {
  const std::string name(f.name), set(cell_set);
  if (f.fixed) return "/mesh/" + set + "_" + name;
  const std::string group = state_group(state);
  return f.center == Center::node ? group + "/" + name : group + "/" + set + "/" + name;
}

namespace {

const char* attribute_type(int components) {
  return components == 1 ? "Scalar" : components == 3 ? "Vector" : "Tensor6";
}

/// One DataItem referencing an HDF5 dataset of `rows` x `cols` values.
void data_item(std::ostream& x, const std::string& h5, const std::string& path, std::size_t rows, int cols,
               bool integer) {
  x << "          <DataItem Dimensions=\"" << rows;
  if (cols > 1) x << " " << cols;
  x << "\" NumberType=\"" << (integer ? "Int" : "Float") << "\" Precision=\"8\" Format=\"HDF\">" << h5 << ":"
    << path << "</DataItem>\n";
}

/// The grid of topology g in state s: connectivity, deformed geometry and the fields it holds.
void grid(std::ostream& x, const Layout& l, std::size_t s, const Grid& g, const std::string& time_tag) {
  const ElementTopology& t = *g.topology;
  const std::string set(t.cell_set);
  x << "      <Grid Name=\"" << set << "\" GridType=\"Uniform\">\n" << time_tag
    << "        <Topology TopologyType=\"" << t.xdmf_cell << "\" NumberOfElements=\"" << g.count << "\">\n"
    << "          <DataItem Dimensions=\"" << g.count << " " << t.nodes
    << "\" NumberType=\"Int\" Precision=\"4\" Format=\"HDF\">" << l.h5 << ":/mesh/" << set << "</DataItem>\n"
    << "        </Topology>\n"
    << "        <Geometry GeometryType=\"XYZ\">\n";
  data_item(x, l.h5, state_group(s) + "/coordinates", l.nodes, 3, false);
  x << "        </Geometry>\n";
  for (std::size_t i = 0; i < kFieldCount; ++i) {
    const Field& f = kFields[i];
    if (!(l.fields[s] >> i & 1u) || (f.surface_only && t.dimension != 2)) continue;
    const bool node = f.center == Center::node;
    x << "        <Attribute Name=\"" << f.name << "\" AttributeType=\"" << attribute_type(f.components)
      << "\" Center=\"" << (node ? "Node" : "Cell") << "\">\n"
      << "          <Information Name=\"units\" Value=\"" << f.units << "\"/>\n";
    data_item(x, l.h5, field_path(f, s, set), node ? l.nodes : g.count, f.components, f.integer);
    x << "        </Attribute>\n";
  }
  x << "      </Grid>\n";
}

}  // namespace

std::string document(const Layout& l) {
  std::ostringstream x;
  x.precision(17);
  x << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n  <Domain>\n"
    << "    <Information Name=\"units\" Value=\"consistent units of the deck (docs/output.md)\"/>\n"
    << "    <Grid Name=\"states\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (std::size_t s = 0; s < l.times.size(); ++s) {
    std::ostringstream tv;
    tv.precision(17);
    tv << "      <Time Value=\"" << l.times[s] << "\"/>\n";
    if (l.grids.size() > 1) {
      // Several topologies: a spatial collection of one grid each per state.
      x << "     <Grid Name=\"state " << s << "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
        << tv.str();
      for (const Grid& g : l.grids) grid(x, l, s, g, "");
      x << "     </Grid>\n";
    } else if (l.grids.size() == 1) {
      // One topology: the grid itself is the state (the layout every XDMF reader takes).
      grid(x, l, s, l.grids.front(), "  " + tv.str());
    }
  }
  x << "    </Grid>\n  </Domain>\n</Xdmf>\n";
  return x.str();
}

}  // namespace slideline::xdmf
