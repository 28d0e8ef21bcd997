// The checkpoint's one writing path and one reading path: named datasets in a group of an
// HDF5 file, the group carrying the format version. Every value of a solver state is saved
// under its own name (no positional scalars), so a reader can say which one is missing or
// wrong, and a new value is a new name. The reader is the one place where a checkpoint's
// datasets are checked on their way in (shape now; ranges and finiteness belong here too).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "mpm/particles.hpp"  // CpdiParticleDomain
#include "mpm/real.hpp"

namespace latmpm {
class Hdf5File;
}

namespace latmpm::mpm {

// 1: positional scalars (before issue 13); 2: named datasets.
// 3: plastic_dissipation, cpdi_domain; 4: contact_energy, friction_dissipation.
inline constexpr int64_t checkpoint_format_version = 4;

// How a value type is stored: its components per row and the dataset element type.
template <class T>
struct CheckpointCodec;
template <>
struct CheckpointCodec<Real> { static constexpr int components = 1; };
template <>
struct CheckpointCodec<Vec3> { static constexpr int components = 3; };
template <>
struct CheckpointCodec<Mat3> { static constexpr int components = 9; };
template <>
struct CheckpointCodec<SymTensor> { static constexpr int components = 6; };
template <>
struct CheckpointCodec<CpdiParticleDomain> { static constexpr int components = 56; };

class CheckpointWriter {
 public:
  // Writes the format version as an attribute of `group` (created).
  CheckpointWriter(Hdf5File& file, std::string group);
  void scalar(const std::string& name, double value);
  void integer(const std::string& name, int64_t value);
  void strings(const std::string& name, const std::vector<std::string>& values);
  void integers(const std::string& name, const std::vector<int64_t>& values, size_t columns);
  // One row per element: Real, Vec3, Mat3 (column-major), SymTensor (Voigt) as doubles;
  // int32, uint8 as they are; uint32 as int64.
  template <class T>
  void rows(const std::string& name, const std::vector<T>& values);
  // The same writer for a sub-group (its datasets under group/sub).
  CheckpointWriter sub(const std::string& sub) const;

 private:
  CheckpointWriter(Hdf5File& file, std::string group, bool);
  std::string path(const std::string& name) const { return group_ + "/" + name; }
  Hdf5File& file_;
  std::string group_;
};

class CheckpointReader {
 public:
  // Throws InputError(file, group, ...) when the group has no format version or another one.
  CheckpointReader(const Hdf5File& file, std::string group);
  bool has(const std::string& name) const;
  double scalar(const std::string& name) const;
  int64_t integer(const std::string& name) const;
  std::vector<std::string> strings(const std::string& name) const;
  // A table of `columns` integers per row, any number of rows.
  std::vector<int64_t> integers(const std::string& name, size_t columns) const;
  // Exactly `count` rows of T (see CheckpointWriter::rows); InputError naming the dataset
  // and the row counts when they differ ("another scene or point set").
  template <class T>
  std::vector<T> rows(const std::string& name, size_t count) const;
  CheckpointReader sub(const std::string& sub) const;
  const std::string& file_path() const;

 private:
  CheckpointReader(const Hdf5File& file, std::string group, bool);
  std::string path(const std::string& name) const { return group_ + "/" + name; }
  // The dataset's dims, checked against count rows of `components` values.
  void expect_shape(const std::string& name, size_t count, int components) const;
  std::vector<double> finite_values(const std::string& name, std::vector<double> values) const;
  const Hdf5File& file_;
  std::string group_;
};

}  // namespace latmpm::mpm
