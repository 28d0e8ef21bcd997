// The checkpoint's one writing path and one reading path: named datasets in a group of an
// HDF5 file, the group carrying the format version. Every value of a solver state is saved
// under its own name (no positional scalars), so a reader can say which one is missing or
// wrong, and a new value is a new name. The reader is the one place where a checkpoint's
// datasets are checked on their way in, as they are read (the file is read once): shape
// against the counts the scene gives, integer type, finiteness of every real and the range
// the caller states (core/checked_read.hpp). A corrupted but well-formed file is refused with
// one InputError naming the file and the dataset before the solver state is changed.
#pragma once
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "core/checked_read.hpp"  // ValueRange
#include "mpm/particles.hpp"  // CpdiParticleDomain
#include "mpm/real.hpp"

#include "core/hdf5_file.hpp"  // RowBlock

namespace latmpm::mpm {

// 1: positional scalars (before issue 13); 2: named datasets.
// 3: plastic_dissipation, cpdi_domain; 4: contact_energy, friction_dissipation;
// 5: blend_dissipation; 6: grid_contact_dissipation; 7: transfer_dissipation.
inline constexpr int64_t checkpoint_format_version = 7;

// How a value type is stored: its components per row (a real: 1; a fixed-size Eigen matrix —
// Vec3, Mat3, SymTensor, CpdiParticleDomain and their ParticleReal forms — its coefficients).
template <class T, class = void>
struct CheckpointCodec {
  static constexpr int components = 1;
};
template <class T>
struct CheckpointCodec<T, std::void_t<decltype(T::SizeAtCompileTime)>> {
  static constexpr int components = int(T::SizeAtCompileTime);
};

class CheckpointWriter {
 public:
  // Writes the format version as an attribute of `group` (created).
  CheckpointWriter(Hdf5File& file, std::string group);
  void scalar(const std::string& name, double value);
  void integer(const std::string& name, int64_t value);
  void strings(const std::string& name, const std::vector<std::string>& values);
  void integers(const std::string& name, const std::vector<int64_t>& values, size_t columns);
  // One row per element: Real, Vec3, Mat3 (column-major), SymTensor (Voigt) and their
  // ParticleReal forms as doubles;
  // int32, uint8, int64 as they are; uint32 as int64.
  template <class T>
  void rows(const std::string& name, const std::vector<T>& values);
  // The same in two parts, for a file several processes write (docs/cluster.md, "Output"):
  // one process lays out `total` rows (reserve_rows, reserve_integers), then each process
  // writes its blocks of them (write_rows: `values` holds the blocks' rows one after the
  // other), the same dataset as rows() / integers() writes whole.
  template <class T>
  void reserve_rows(const std::string& name, size_t total);
  template <class T>
  void write_rows(const std::string& name, const std::vector<T>& values, const std::vector<RowBlock>& blocks);
  void reserve_integers(const std::string& name, size_t rows, size_t columns);
  // The same writer for a sub-group (its datasets under group/sub).
  CheckpointWriter sub(const std::string& sub) const;
  // A writer of rows into a group another process laid out (no attributes written).
  static CheckpointWriter existing(Hdf5File& file, std::string group) { return {file, std::move(group), true}; }

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
  // Every read below throws InputError(file, dataset, ...) when the dataset is missing, has
  // another shape, is not of an integer type where integers are read, holds a real that is
  // not finite, or a value outside `range` / [min, max].
  double scalar(const std::string& name, ValueRange range = {}) const;
  int64_t integer(const std::string& name, int64_t min = std::numeric_limits<int64_t>::min(),
                  int64_t max = std::numeric_limits<int64_t>::max()) const;
  std::vector<std::string> strings(const std::string& name) const;
  // A table of `columns` integers per row, any number of rows.
  std::vector<int64_t> integers(const std::string& name, size_t columns,
                                int64_t min = std::numeric_limits<int64_t>::min(),
                                int64_t max = std::numeric_limits<int64_t>::max()) const;
  // Exactly `count` rows of T (see CheckpointWriter::rows); InputError naming the dataset
  // and the row counts when they differ ("another scene or point set").
  template <class T>
  std::vector<T> rows(const std::string& name, size_t count, ValueRange range = {}) const;
  // Scalar attributes of the group.
  bool has_attribute(const std::string& name) const;
  double attribute(const std::string& name, ValueRange range = {}) const;
  CheckpointReader sub(const std::string& sub) const;
  // Another group of the same file, whose format version this reader has checked (e.g. the
  // run's /output beside /state).
  CheckpointReader group(const std::string& group) const;
  const std::string& file_path() const;

 private:
  CheckpointReader(const Hdf5File& file, std::string group, bool);
  std::string path(const std::string& name) const { return group_ + "/" + name; }
  // The dataset's dims, checked against count rows of `components` values.
  void expect_shape(const std::string& name, size_t count, int components) const;
  const Hdf5File& file_;
  std::string group_;
};

}  // namespace latmpm::mpm
