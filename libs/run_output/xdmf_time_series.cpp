#include "run_output/xdmf_time_series.hpp"

#include <cstdio>
#include <sstream>

namespace latmpm {
namespace {

struct Field {
  const char* name;     // attribute name in ParaView
  const char* dataset;  // HDF5 dataset in the snapshot file
  const char* type;     // XDMF AttributeType
  int components;
  const char* number_type;
  int precision;
};

// What snapshot_writer.cpp writes; keep the two in step.
constexpr Field fields[] = {
    {"velocity", "/particles/velocity", "Vector", 3, "Float", 4},
    {"stress", "/particles/stress", "Tensor6", 6, "Float", 4},
    {"von_mises", "/particles/von_mises", "Scalar", 1, "Float", 4},
    {"J", "/particles/J", "Scalar", 1, "Float", 4},
    {"body", "/particles/body", "Scalar", 1, "Int", 4},
};

std::string dims(size_t n, int components) {
  return components == 1 ? std::to_string(n) : std::to_string(n) + " " + std::to_string(components);
}

}  // namespace

std::string xdmf_time_series(const std::vector<XdmfFrame>& frames) {
  std::ostringstream x;
  x << "<?xml version=\"1.0\" ?>\n"
    << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
    << "<Xdmf Version=\"3.0\">\n"
    << "  <Domain>\n"
    << "    <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const XdmfFrame& f : frames) {
    char time[32];
    std::snprintf(time, sizeof time, "%.17g", f.time);
    const std::string n = std::to_string(f.points);
    x << "      <Grid Name=\"step " << f.step << "\" GridType=\"Uniform\">\n"
      << "        <Time Value=\"" << time << "\"/>\n"
      << "        <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n
      << "\" NodesPerElement=\"1\"/>\n"
      << "        <Geometry GeometryType=\"XYZ\">\n"
      << "          <DataItem Dimensions=\"" << dims(f.points, 3)
      << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << f.hdf5_file
      << ":/particles/position</DataItem>\n"
      << "        </Geometry>\n";
    for (const Field& field : fields)
      x << "        <Attribute Name=\"" << field.name << "\" AttributeType=\"" << field.type
        << "\" Center=\"Node\">\n"
        << "          <DataItem Dimensions=\"" << dims(f.points, field.components)
        << "\" NumberType=\"" << field.number_type << "\" Precision=\"" << field.precision
        << "\" Format=\"HDF\">" << f.hdf5_file << ":" << field.dataset << "</DataItem>\n"
        << "        </Attribute>\n";
    for (const std::string& name : f.extra_scalars)
      x << "        <Attribute Name=\"" << name << "\" AttributeType=\"Scalar\" Center=\"Node\">\n"
        << "          <DataItem Dimensions=\"" << dims(f.points, 1) << "\" NumberType=\"Float\" Precision=\"4\" Format=\"HDF\">"
        << f.hdf5_file << ":/particles/" << name << "</DataItem>\n"
        << "        </Attribute>\n";
    x << "      </Grid>\n";
  }
  x << "    </Grid>\n  </Domain>\n</Xdmf>\n";
  return x.str();
}

}  // namespace latmpm
