// XDMF 3 descriptions of point data stored in HDF5, so ParaView (the "Xdmf3 Reader") opens
// a point file directly: one Polyvertex grid whose geometry and attributes are references
// "<file>.h5:/dataset" into the HDF5 file. Generic: the voxelizer writes one for a point
// set, the solver can write one per particle snapshot.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace latmpm {

struct XdmfAttribute {
  enum class Type { float64, float32, int32, int64, uint8 };
  std::string name;     // as shown in ParaView, e.g. "volume"
  std::string dataset;  // HDF5 path, e.g. "/points/volume"
  int components = 1;   // 1 scalar, 3 vector, 9 tensor (N×components dataset)
  Type type = Type::float64;
};

// The .xmf text. `hdf5_file` is written into the references as given: pass the name
// relative to the .xmf file (normally just the file name, both side by side).
// `position_dataset` holds N×3 float64 coordinates.
std::string xdmf_polyvertex(const std::string& hdf5_file, size_t points,
                            const std::string& position_dataset,
                            const std::vector<XdmfAttribute>& attributes,
                            const std::string& grid_name = "points");

// "run/out.h5" -> "run/out.xmf" (any extension replaced; ".xmf" appended if none).
std::string xdmf_path_beside(const std::string& hdf5_path);

// The attributes of a point-set file (docs/formats.md): volume, body, half_size and one
// uint8 mask per tag.
std::vector<XdmfAttribute> point_set_xdmf_attributes(const std::vector<std::string>& tag_names);

}  // namespace latmpm
