#include "points/xdmf.hpp"

#include <sstream>

namespace latmpm {
namespace {

std::string xml_escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// XDMF NumberType and Precision (bytes) of each stored type.
const char* number_type(XdmfAttribute::Type t) {
  switch (t) {
    case XdmfAttribute::Type::float64:
    case XdmfAttribute::Type::float32: return "Float";
    case XdmfAttribute::Type::int32:
    case XdmfAttribute::Type::int64: return "Int";
    case XdmfAttribute::Type::uint8: return "UChar";
  }
  return "Float";
}
int precision(XdmfAttribute::Type t) {
  switch (t) {
    case XdmfAttribute::Type::float64:
    case XdmfAttribute::Type::int64: return 8;
    case XdmfAttribute::Type::float32:
    case XdmfAttribute::Type::int32: return 4;
    case XdmfAttribute::Type::uint8: return 1;
  }
  return 8;
}

const char* attribute_type(int components) {
  switch (components) {
    case 1: return "Scalar";
    case 3: return "Vector";
    case 6: return "Tensor6";
    case 9: return "Tensor";
    default: return "Matrix";
  }
}

void data_item(std::ostringstream& s, size_t n, int components, XdmfAttribute::Type type,
               const std::string& reference) {
  s << "        <DataItem Dimensions=\"" << n;
  if (components > 1) s << " " << components;
  s << "\" NumberType=\"" << number_type(type) << "\" Precision=\"" << precision(type)
    << "\" Format=\"HDF\">" << xml_escaped(reference) << "</DataItem>\n";
}

}  // namespace

std::string xdmf_polyvertex(const std::string& hdf5_file, size_t points,
                            const std::string& position_dataset,
                            const std::vector<XdmfAttribute>& attributes,
                            const std::string& grid_name) {
  std::ostringstream s;
  s << "<?xml version=\"1.0\" ?>\n"
    << "<Xdmf Version=\"3.0\">\n  <Domain>\n"
    << "    <Grid Name=\"" << xml_escaped(grid_name) << "\" GridType=\"Uniform\">\n"
    << "      <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << points
    << "\" NodesPerElement=\"1\"/>\n"
    << "      <Geometry GeometryType=\"XYZ\">\n";
  data_item(s, points, 3, XdmfAttribute::Type::float64, hdf5_file + ":" + position_dataset);
  s << "      </Geometry>\n";
  for (const auto& a : attributes) {
    s << "      <Attribute Name=\"" << xml_escaped(a.name) << "\" AttributeType=\""
      << attribute_type(a.components) << "\" Center=\"Node\">\n";
    data_item(s, points, a.components, a.type, hdf5_file + ":" + a.dataset);
    s << "      </Attribute>\n";
  }
  s << "    </Grid>\n  </Domain>\n</Xdmf>\n";
  return s.str();
}

std::string xdmf_path_beside(const std::string& hdf5_path) {
  const size_t slash = hdf5_path.find_last_of('/');
  const size_t dot = hdf5_path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return hdf5_path + ".xmf";
  return hdf5_path.substr(0, dot) + ".xmf";
}

std::vector<XdmfAttribute> point_set_xdmf_attributes(const std::vector<std::string>& tag_names) {
  std::vector<XdmfAttribute> attributes = {
      {"volume", "/points/volume", 1, XdmfAttribute::Type::float64},
      {"body", "/points/body", 1, XdmfAttribute::Type::int32},
      {"half_size", "/points/half_size", 3, XdmfAttribute::Type::float64}};
  for (const auto& tag : tag_names)
    attributes.push_back({"tag_" + tag, "/points/tags/" + tag, 1, XdmfAttribute::Type::uint8});
  return attributes;
}

}  // namespace latmpm
