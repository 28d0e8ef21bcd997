// A small RAII layer over the HDF5 C API: the one way latmpm files are read and written.
// Datasets are addressed by path ("/points/position"); missing groups are created on write.
// A failure to read throws InputError naming the file and the dataset or attribute; a failure
// to write (disk full, I/O error) throws OutputError. A file being written must be closed
// with close() before it is published: HDF5 keeps data in its cache until then, so a full
// disk is often only seen there (the destructor cannot report it).
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace latmpm {

// Rows [first, first + count) of a dataset's first dimension: the part of a file one
// process writes when several write one file (parallel HDF5, docs/cluster.md).
struct RowBlock {
  size_t first = 0, count = 0;
};

class Hdf5File {
 public:
  enum class Mode { read, read_write, create };
  Hdf5File(const std::string& path, Mode mode);
  ~Hdf5File();
  Hdf5File(const Hdf5File&) = delete;
  Hdf5File& operator=(const Hdf5File&) = delete;
  Hdf5File(Hdf5File&& other) noexcept;
  Hdf5File& operator=(Hdf5File&& other) noexcept;

  const std::string& path() const { return path_; }
  bool exists(const std::string& object) const;  // group or dataset
  bool is_integer(const std::string& dataset) const;  // stored as an integer type
  // Flushes and closes; throws OutputError when the data did not reach the disk.
  void close();

  // Datasets: `dims` is the shape, row-major (N×3 for positions). Overwrites an existing one.
  void write(const std::string& dataset, const std::vector<double>& data,
             const std::vector<size_t>& dims);
  void write(const std::string& dataset, const std::vector<float>& data,
             const std::vector<size_t>& dims);
  void write(const std::string& dataset, const std::vector<int32_t>& data,
             const std::vector<size_t>& dims);
  void write(const std::string& dataset, const std::vector<int64_t>& data,
             const std::vector<size_t>& dims);
  void write(const std::string& dataset, const std::vector<uint8_t>& data,
             const std::vector<size_t>& dims);
  void write_strings(const std::string& dataset, const std::vector<std::string>& data);

  // A dataset laid out now and filled later, part by part (write_rows): of shape `dims` and
  // T's type (double, float, int32_t, int64_t, uint8_t), its storage allocated at once and
  // never filled with a default value (the rows written later cover it). So one process
  // can lay a file out that several then fill at once (open_shared_hdf5, parallel HDF5).
  template <typename T>
  void reserve(const std::string& dataset, const std::vector<size_t>& dims);
  // Rows of a dataset (reserved or written): `data` holds the rows of `blocks` (ascending,
  // apart) one after the other, each row the dataset's trailing dimensions. On a file that
  // several processes opened together (open_shared_hdf5) every process calls it for every
  // dataset in the same order, with its own blocks (none: it writes nothing), and the rows
  // go to the file in one collective transfer.
  template <typename T>
  void write_rows(const std::string& dataset, const std::vector<T>& data, const std::vector<RowBlock>& blocks);

  // Reads convert from the stored numeric type, except reals into integers (refused: an index
  // stored as 0.5 is not an index). `dims`, when given, receives the shape.
  std::vector<double> read_doubles(const std::string& dataset, std::vector<size_t>* dims = nullptr) const;
  std::vector<float> read_floats(const std::string& dataset, std::vector<size_t>* dims = nullptr) const;
  std::vector<int32_t> read_int32(const std::string& dataset, std::vector<size_t>* dims = nullptr) const;
  std::vector<int64_t> read_int64(const std::string& dataset, std::vector<size_t>* dims = nullptr) const;
  std::vector<uint8_t> read_uint8(const std::string& dataset, std::vector<size_t>* dims = nullptr) const;
  std::vector<std::string> read_strings(const std::string& dataset) const;
  std::vector<size_t> shape(const std::string& dataset) const;

  // Attributes on a group or dataset ("/" for the file).
  void set_attribute(const std::string& object, const std::string& name, const std::string& value);
  void set_attribute(const std::string& object, const std::string& name, const char* value) {
    set_attribute(object, name, std::string(value));
  }
  void set_attribute(const std::string& object, const std::string& name, double value);
  void set_attribute(const std::string& object, const std::string& name, int64_t value);
  void set_attribute(const std::string& object, const std::string& name,
                     const std::vector<double>& value);
  bool has_attribute(const std::string& object, const std::string& name) const;
  std::string string_attribute(const std::string& object, const std::string& name) const;
  double double_attribute(const std::string& object, const std::string& name) const;
  int64_t int_attribute(const std::string& object, const std::string& name) const;
  std::vector<double> doubles_attribute(const std::string& object, const std::string& name) const;

  void create_group(const std::string& group);

 private:
  friend Hdf5File open_hdf5_with(const std::string& path, int64_t file_access, int64_t transfer);
  Hdf5File(std::string path, int64_t id, int64_t transfer) : path_(std::move(path)), id_(id), transfer_(transfer) {}
  template <typename T>
  void write_numeric(const std::string& dataset, const std::vector<T>& data,
                     const std::vector<size_t>& dims, int64_t mem_type);
  template <typename T>
  std::vector<T> read_numeric(const std::string& dataset, std::vector<size_t>* dims,
                              int64_t mem_type) const;
  [[noreturn]] void fail(const std::string& field, const std::string& problem) const;
  [[noreturn]] void fail_write(const std::string& field, const std::string& problem) const;
  bool close_quietly() noexcept;  // false when the flush or close failed

  std::string path_;
  int64_t id_ = -1;  // hid_t, kept as int64_t so the header stays free of hdf5.h
  int64_t transfer_ = 0;  // raw-data transfer properties (0: H5P_DEFAULT; collective on a shared file)
};

// Opens an existing file for writing with the given HDF5 file-access and data-transfer
// property lists (both taken over, closed with the file): how core/shared_hdf5_file opens a
// file on several MPI processes.
Hdf5File open_hdf5_with(const std::string& path, int64_t file_access, int64_t transfer);

}  // namespace latmpm
