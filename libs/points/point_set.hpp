// Material points: what the voxelizer writes, the imperfection tool perturbs and the solver
// reads. Structure of arrays, SI units. Layout on disk in docs/formats.md ("Point-set file").
//
// Grid alignment rule: the solver's background grid has nodes at x = i·h (integer i, the
// global origin is a node) for the cell size h recorded here. The voxelizer places ppc³
// points per cell at x = (i + (k + 1/2)/ppc)·h, k = 0..ppc-1, so points sit symmetrically
// inside their cell for any solver run with the same h.
#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "points/hexahedron.hpp"

namespace latmpm {

struct PointSet {
  std::vector<Eigen::Vector3d> position;   // m
  std::vector<double> volume;              // m³ (surface points carry their inside fraction)
  std::vector<int32_t> body;               // index into body_names
  std::vector<Eigen::Vector3d> half_size;  // m, GIMP particle-domain half-lengths
  // CPDI1 domains (paper B Sec. 2.2): the eight vertices of each point's hexahedron in the
  // reference configuration, gmsh order, m. Empty for sets without them (voxelized sets);
  // position is then each domain's centroid and volume its exact volume.
  std::vector<HexVertices> domain_vertices;
  std::vector<std::string> body_names;     // "lattice", "bottom_plate", "top_plate", "column"...
  // Regions scenes need, one 0/1 mask per point: "record" (bottom layer of the base, the
  // paper's reaction measure), "top_layer", "bottom_layer"...
  std::map<std::string, std::vector<uint8_t>> tags;
  // Parameters of the geometry the points came from, copied from the geometry file
  // ("layer_height" -> "0.00933 m", "cells" -> "5x5x5"...): lets later tools find cell
  // layers without the geometry file. Values carry units, parse with parse_quantity.
  std::map<std::string, std::string> parameters;
  double cell_size = 0;  // m, the grid cell h the points were made for
  int ppc = 0;           // points per cell per direction

  size_t size() const { return position.size(); }
  // Index of a body by name, or -1.
  int body_index(const std::string& name) const;
  // Point p's GIMP domain half-lengths (m): half_size[p], each axis without one (zero) given
  // the voxelizer's, half a point spacing h/(2 ppc). The explicit and the static solver both
  // take it from here.
  Eigen::Vector3d domain_half_size(size_t p) const;
  // Throws InputError(where, field, problem) if arrays disagree in length, values are not
  // finite, volumes are not positive, or body indices are out of range.
  void validate(const std::string& where) const;
};

class Hdf5File;
void write_point_set(Hdf5File& file, const PointSet& points);
PointSet read_point_set(const Hdf5File& file);
bool holds_point_set(const Hdf5File& file);

}  // namespace latmpm
