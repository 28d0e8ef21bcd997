// The geometry every tool exchanges: a graph of cylindrical struts (capsules: cylinders with
// spherical caps of the same radius, so struts meeting at a node form a smooth, closed
// union) plus solid axis-aligned plates. Lengths in metres. The compression axis is z.
#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace latmpm {

struct Strut {
  int32_t a = 0, b = 0;  // node indices
  double radius = 0;     // m
};

// A solid box, e.g. the printed top and bottom plates. Each plate is its own body.
struct Plate {
  std::string name;  // "bottom_plate", "top_plate"
  Eigen::Vector3d min = Eigen::Vector3d::Zero(), max = Eigen::Vector3d::Zero();
};

// How strut ends are shaped. `round` (capsules) joins struts smoothly at nodes; `flat`
// (plain cylinders, exactly as long as the strut) is for a single column whose length must be
// exact, e.g. the buckling column of paper A Sec. 4 (see docs/geometry.md).
enum class StrutEnds { round, flat };

struct StrutGraph {
  std::string name;               // "T2P30", "column", "bcc"...
  std::string strut_body = "lattice";  // body name of the struts ("lattice", "column")
  StrutEnds strut_ends = StrutEnds::round;  // file: /geometry @strut_ends ("round" if absent)
  std::vector<Eigen::Vector3d> nodes;
  std::vector<Strut> struts;
  std::vector<Plate> plates;
  // How it was made, for humans and later tools: "cell" -> "tetrahedral",
  // "strut_length" -> "0.008 m"... (free-form key/value text).
  std::map<std::string, std::string> parameters;
};

class Hdf5File;
// Layout in docs/formats.md ("Geometry file").
void write_strut_graph(Hdf5File& file, const StrutGraph& graph);
StrutGraph read_strut_graph(const Hdf5File& file);
// True when the file holds a strut graph (as opposed to a point set).
bool holds_strut_graph(const Hdf5File& file);

}  // namespace latmpm
