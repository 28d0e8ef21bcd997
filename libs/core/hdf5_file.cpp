#include "core/hdf5_file.hpp"

#include <hdf5.h>

#include <algorithm>
#include <type_traits>
#include <utility>

#include "core/errors.hpp"
#include "core/file_transfer.hpp"

namespace latmpm {
namespace {

static_assert(sizeof(hid_t) == sizeof(int64_t), "hid_t is stored as int64_t");

// HDF5 prints its own error stack by default; we report errors ourselves, once.
// No library shutdown at exit: a file whose close failed (a full disk) stays open inside
// HDF5, and shutting down retries the flush on freed state and crashes after our message.
// Every file we write is closed (and checked) explicitly before it is published.
struct SilenceHdf5 {
  SilenceHdf5() {
    H5dont_atexit();
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
};
const SilenceHdf5 silence_hdf5;

struct Handle {  // closes an HDF5 object id with the right function
  hid_t id;
  herr_t (*closer)(hid_t);
  Handle(hid_t i, herr_t (*c)(hid_t)) : id(i), closer(c) {}
  ~Handle() {
    if (id >= 0) closer(id);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  bool ok() const { return id >= 0; }
};

std::string parent_of(const std::string& path) {
  auto pos = path.find_last_of('/');
  if (pos == std::string::npos || pos == 0) return "/";
  return path.substr(0, pos);
}

bool link_exists(hid_t file, const std::string& path) {
  if (path == "/" || path.empty()) return true;
  // H5Lexists needs every intermediate link to exist: check from the root down.
  size_t pos = 0;
  while ((pos = path.find('/', pos + 1)) != std::string::npos) {
    if (H5Lexists(file, path.substr(0, pos).c_str(), H5P_DEFAULT) <= 0) return false;
  }
  return H5Lexists(file, path.c_str(), H5P_DEFAULT) > 0;
}

}  // namespace

Hdf5File::Hdf5File(const std::string& path, Mode mode) : path_(path) {
  switch (mode) {
    case Mode::create:
      id_ = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
      if (id_ < 0) fail_write("", "cannot create the file (is the directory writable?)");
      break;
    case Mode::read:
    case Mode::read_write: {
      if (H5Fis_hdf5(path.c_str()) <= 0) {
        FILE* f = std::fopen(path.c_str(), "rb");
        if (!f) fail("", "cannot open the file (missing or unreadable)");
        std::fclose(f);
        fail("", "not an HDF5 file");
      }
      id_ = H5Fopen(path.c_str(), mode == Mode::read ? H5F_ACC_RDONLY : H5F_ACC_RDWR, H5P_DEFAULT);
      if (id_ < 0) fail("", "cannot open the HDF5 file");
      break;
    }
  }
}

Hdf5File::~Hdf5File() { close_quietly(); }

Hdf5File::Hdf5File(Hdf5File&& other) noexcept
    : path_(std::move(other.path_)), id_(std::exchange(other.id_, -1)), transfer_(std::exchange(other.transfer_, 0)) {}

Hdf5File& Hdf5File::operator=(Hdf5File&& other) noexcept {
  if (this != &other) {
    close_quietly();
    path_ = std::move(other.path_);
    id_ = std::exchange(other.id_, -1);
    transfer_ = std::exchange(other.transfer_, 0);
  }
  return *this;
}

bool Hdf5File::close_quietly() noexcept {
  if (transfer_ > 0) H5Pclose(std::exchange(transfer_, 0));
  if (id_ < 0) return true;
  unsigned intent = 0;
  const bool writing = H5Fget_intent(id_, &intent) >= 0 && (intent & H5F_ACC_RDWR);
  bool ok = !writing || H5Fflush(id_, H5F_SCOPE_LOCAL) >= 0;
  ok = H5Fclose(id_) >= 0 && ok;
  id_ = -1;
  return ok;
}

void Hdf5File::close() {
  const std::string path = path_;
  if (!close_quietly()) throw OutputError(shown_path(path), "write failed when closing the file (disk full?)");
}

void Hdf5File::fail(const std::string& field, const std::string& problem) const {
  throw InputError(path_, field, problem);
}

void Hdf5File::fail_write(const std::string& field, const std::string& problem) const {
  throw OutputError(shown_path(path_) + (field.empty() ? "" : ": " + field), problem);
}

bool Hdf5File::is_integer(const std::string& dataset) const {
  if (!exists(dataset)) fail(dataset, "missing dataset");
  Handle set(H5Dopen2(id_, dataset.c_str(), H5P_DEFAULT), H5Dclose);
  if (!set.ok()) fail(dataset, "cannot open dataset");
  Handle type(H5Dget_type(set.id), H5Tclose);
  return H5Tget_class(type.id) == H5T_INTEGER;
}

bool Hdf5File::exists(const std::string& object) const { return link_exists(id_, object); }

void Hdf5File::create_group(const std::string& group) {
  if (exists(group)) return;
  Handle lcpl(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
  H5Pset_create_intermediate_group(lcpl.id, 1);
  Handle g(H5Gcreate2(id_, group.c_str(), lcpl.id, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  if (!g.ok()) fail_write(group, "cannot create group");
}

template <typename T>
void Hdf5File::write_numeric(const std::string& dataset, const std::vector<T>& data,
                             const std::vector<size_t>& dims, int64_t mem_type) {
  size_t count = 1;
  std::vector<hsize_t> hdims(dims.begin(), dims.end());
  for (size_t d : dims) count *= d;
  if (count != data.size()) fail(dataset, "internal: shape does not match the data size");
  create_group(parent_of(dataset));
  if (exists(dataset)) H5Ldelete(id_, dataset.c_str(), H5P_DEFAULT);
  Handle space(H5Screate_simple(static_cast<int>(hdims.size()), hdims.data(), nullptr), H5Sclose);
  Handle set(H5Dcreate2(id_, dataset.c_str(), mem_type, space.id, H5P_DEFAULT, H5P_DEFAULT,
                        H5P_DEFAULT),
             H5Dclose);
  if (!set.ok()) fail_write(dataset, "cannot create dataset");
  if (count > 0 && H5Dwrite(set.id, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()) < 0)
    fail_write(dataset, "write failed (disk full?)");
}

template <typename T>
std::vector<T> Hdf5File::read_numeric(const std::string& dataset, std::vector<size_t>* dims,
                                      int64_t mem_type) const {
  if (!exists(dataset)) fail(dataset, "missing dataset");
  Handle set(H5Dopen2(id_, dataset.c_str(), H5P_DEFAULT), H5Dclose);
  if (!set.ok()) fail(dataset, "cannot open dataset");
  Handle type(H5Dget_type(set.id), H5Tclose);
  H5T_class_t cls = H5Tget_class(type.id);
  if (cls != H5T_INTEGER && cls != H5T_FLOAT) fail(dataset, "not a numeric dataset");
  // Integers (indices, ids, flags) read from reals would be silently truncated: 0.5 -> 0.
  if (cls == H5T_FLOAT && H5Tget_class(static_cast<hid_t>(mem_type)) == H5T_INTEGER)
    fail(dataset, "stored as real numbers where integers are expected");
  std::vector<size_t> shape_out = shape(dataset);
  size_t count = 1;
  for (size_t d : shape_out) count *= d;
  std::vector<T> data(count);
  if (count > 0 && H5Dread(set.id, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()) < 0)
    fail(dataset, "read failed (truncated or corrupt file?)");
  if (dims) *dims = shape_out;
  return data;
}

std::vector<size_t> Hdf5File::shape(const std::string& dataset) const {
  if (!exists(dataset)) fail(dataset, "missing dataset");
  Handle set(H5Dopen2(id_, dataset.c_str(), H5P_DEFAULT), H5Dclose);
  if (!set.ok()) fail(dataset, "cannot open dataset");
  Handle space(H5Dget_space(set.id), H5Sclose);
  int rank = H5Sget_simple_extent_ndims(space.id);
  if (rank < 0) fail(dataset, "cannot read the shape");
  std::vector<hsize_t> hdims(static_cast<size_t>(rank));
  H5Sget_simple_extent_dims(space.id, hdims.data(), nullptr);
  return std::vector<size_t>(hdims.begin(), hdims.end());
}

void Hdf5File::write(const std::string& d, const std::vector<double>& v, const std::vector<size_t>& s) {
  write_numeric(d, v, s, H5T_NATIVE_DOUBLE);
}
void Hdf5File::write(const std::string& d, const std::vector<float>& v, const std::vector<size_t>& s) {
  write_numeric(d, v, s, H5T_NATIVE_FLOAT);
}
void Hdf5File::write(const std::string& d, const std::vector<int32_t>& v, const std::vector<size_t>& s) {
  write_numeric(d, v, s, H5T_NATIVE_INT32);
}
void Hdf5File::write(const std::string& d, const std::vector<int64_t>& v, const std::vector<size_t>& s) {
  write_numeric(d, v, s, H5T_NATIVE_INT64);
}
void Hdf5File::write(const std::string& d, const std::vector<uint8_t>& v, const std::vector<size_t>& s) {
  write_numeric(d, v, s, H5T_NATIVE_UINT8);
}
std::vector<double> Hdf5File::read_doubles(const std::string& d, std::vector<size_t>* s) const {
  return read_numeric<double>(d, s, H5T_NATIVE_DOUBLE);
}
std::vector<float> Hdf5File::read_floats(const std::string& d, std::vector<size_t>* s) const {
  return read_numeric<float>(d, s, H5T_NATIVE_FLOAT);
}
std::vector<int32_t> Hdf5File::read_int32(const std::string& d, std::vector<size_t>* s) const {
  return read_numeric<int32_t>(d, s, H5T_NATIVE_INT32);
}
std::vector<int64_t> Hdf5File::read_int64(const std::string& d, std::vector<size_t>* s) const {
  return read_numeric<int64_t>(d, s, H5T_NATIVE_INT64);
}
std::vector<uint8_t> Hdf5File::read_uint8(const std::string& d, std::vector<size_t>* s) const {
  return read_numeric<uint8_t>(d, s, H5T_NATIVE_UINT8);
}

namespace {
template <typename T>
hid_t native_type() {
  if constexpr (std::is_same_v<T, double>) return H5T_NATIVE_DOUBLE;
  else if constexpr (std::is_same_v<T, float>) return H5T_NATIVE_FLOAT;
  else if constexpr (std::is_same_v<T, int32_t>) return H5T_NATIVE_INT32;
  else if constexpr (std::is_same_v<T, int64_t>) return H5T_NATIVE_INT64;
  else return H5T_NATIVE_UINT8;
}
}  // namespace

template <typename T>
void Hdf5File::reserve(const std::string& dataset, const std::vector<size_t>& dims) {
  create_group(parent_of(dataset));
  if (exists(dataset)) H5Ldelete(id_, dataset.c_str(), H5P_DEFAULT);
  std::vector<hsize_t> hdims(dims.begin(), dims.end());
  Handle space(H5Screate_simple(static_cast<int>(hdims.size()), hdims.data(), nullptr), H5Sclose);
  // Contiguous, as write() lays a dataset out; allocated now so that the processes filling
  // it need not, and not filled: every row is written.
  Handle create(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  H5Pset_alloc_time(create.id, H5D_ALLOC_TIME_EARLY);
  H5Pset_fill_time(create.id, H5D_FILL_TIME_NEVER);
  Handle set(H5Dcreate2(id_, dataset.c_str(), native_type<T>(), space.id, H5P_DEFAULT, create.id, H5P_DEFAULT),
             H5Dclose);
  if (!set.ok()) fail_write(dataset, "cannot create dataset (disk full?)");
}

template <typename T>
void Hdf5File::write_rows(const std::string& dataset, const std::vector<T>& data, const std::vector<RowBlock>& blocks) {
  Handle set(H5Dopen2(id_, dataset.c_str(), H5P_DEFAULT), H5Dclose);
  if (!set.ok()) fail_write(dataset, "cannot open dataset");
  Handle file_space(H5Dget_space(set.id), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(file_space.id);
  std::vector<hsize_t> dims(static_cast<size_t>(std::max(rank, 0)));
  H5Sget_simple_extent_dims(file_space.id, dims.data(), nullptr);
  size_t row_size = 1, rows = 0;
  for (size_t d = 1; d < dims.size(); ++d) row_size *= dims[d];
  H5Sselect_none(file_space.id);
  std::vector<hsize_t> start(dims.size(), 0), count(dims);
  size_t end = 0;
  for (const RowBlock& b : blocks) {
    if (dims.empty() || b.first < end || b.first + b.count > dims[0])
      fail_write(dataset, "internal: rows [" + std::to_string(b.first) + ", " + std::to_string(b.first + b.count) +
                              ") out of order or beyond the dataset's " + std::to_string(dims.empty() ? 0 : dims[0]));
    end = b.first + b.count;
    if (b.count == 0) continue;
    start[0] = b.first, count[0] = b.count;
    H5Sselect_hyperslab(file_space.id, H5S_SELECT_OR, start.data(), nullptr, count.data(), nullptr);
    rows += b.count;
  }
  if (data.size() != rows * row_size) fail_write(dataset, "internal: the rows do not match the data size");
  // Rows arrive in file order (the selection's order), one after the other in memory.
  const hsize_t values = rows * row_size, extent = std::max<hsize_t>(values, 1);
  Handle memory_space(H5Screate_simple(1, &extent, nullptr), H5Sclose);
  if (values == 0) H5Sselect_none(memory_space.id);
  if (H5Dwrite(set.id, native_type<T>(), memory_space.id, file_space.id, transfer_, data.data()) < 0)
    fail_write(dataset, "write failed (disk full?)");
}

#define LATMPM_HDF5_ROWS(T)                                                                 \
  template void Hdf5File::reserve<T>(const std::string&, const std::vector<size_t>&);      \
  template void Hdf5File::write_rows<T>(const std::string&, const std::vector<T>&, const std::vector<RowBlock>&);
LATMPM_HDF5_ROWS(double)
LATMPM_HDF5_ROWS(float)
LATMPM_HDF5_ROWS(int32_t)
LATMPM_HDF5_ROWS(int64_t)
LATMPM_HDF5_ROWS(uint8_t)
#undef LATMPM_HDF5_ROWS

Hdf5File open_hdf5_with(const std::string& path, int64_t file_access, int64_t transfer) {
  const hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDWR, file_access);
  H5Pclose(file_access);
  Hdf5File file(path, id, transfer);  // closes the transfer list in any case
  if (id < 0) file.fail_write("", "cannot open the file to write its rows");
  return file;
}

void Hdf5File::write_strings(const std::string& dataset, const std::vector<std::string>& data) {
  create_group(parent_of(dataset));
  if (exists(dataset)) H5Ldelete(id_, dataset.c_str(), H5P_DEFAULT);
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.id, H5T_VARIABLE);
  H5Tset_cset(type.id, H5T_CSET_UTF8);
  hsize_t n = data.size();
  Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose);
  Handle set(H5Dcreate2(id_, dataset.c_str(), type.id, space.id, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
             H5Dclose);
  if (!set.ok()) fail_write(dataset, "cannot create dataset");
  std::vector<const char*> ptrs;
  for (const auto& s : data) ptrs.push_back(s.c_str());
  if (n > 0 && H5Dwrite(set.id, type.id, H5S_ALL, H5S_ALL, H5P_DEFAULT, ptrs.data()) < 0)
    fail_write(dataset, "write failed (disk full?)");
}

std::vector<std::string> Hdf5File::read_strings(const std::string& dataset) const {
  if (!exists(dataset)) fail(dataset, "missing dataset");
  Handle set(H5Dopen2(id_, dataset.c_str(), H5P_DEFAULT), H5Dclose);
  if (!set.ok()) fail(dataset, "cannot open dataset");
  Handle ftype(H5Dget_type(set.id), H5Tclose);
  if (H5Tget_class(ftype.id) != H5T_STRING || !H5Tis_variable_str(ftype.id))
    fail(dataset, "not a variable-length string dataset");
  if (shape(dataset).size() != 1) fail(dataset, "not a one-dimensional list of strings");
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.id, H5T_VARIABLE);
  H5Tset_cset(type.id, H5Tget_cset(ftype.id));
  size_t n = shape(dataset).at(0);
  std::vector<char*> ptrs(n, nullptr);
  if (n > 0 && H5Dread(set.id, type.id, H5S_ALL, H5S_ALL, H5P_DEFAULT, ptrs.data()) < 0)
    fail(dataset, "read failed");
  std::vector<std::string> out;
  for (char* p : ptrs) out.emplace_back(p ? p : "");
  if (n > 0) {
    Handle space(H5Dget_space(set.id), H5Sclose);
    H5Dvlen_reclaim(type.id, space.id, H5P_DEFAULT, ptrs.data());
  }
  return out;
}

namespace {
hid_t open_object(hid_t file, const std::string& object) {
  return H5Oopen(file, object.c_str(), H5P_DEFAULT);
}
}  // namespace

namespace {
// Replaces attribute `name` on `object` with one of the given type and shape.
bool replace_attribute(hid_t file, const std::string& object, const std::string& name,
                       hid_t type, hid_t space, const void* data) {
  Handle obj(open_object(file, object), H5Oclose);
  if (!obj.ok()) return false;
  if (H5Aexists(obj.id, name.c_str()) > 0) H5Adelete(obj.id, name.c_str());
  Handle attr(H5Acreate2(obj.id, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  return attr.ok() && H5Awrite(attr.id, type, data) >= 0;
}
}  // namespace

void Hdf5File::set_attribute(const std::string& object, const std::string& name,
                             const std::string& value) {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.id, H5T_VARIABLE);
  H5Tset_cset(type.id, H5T_CSET_UTF8);
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  const char* p = value.c_str();
  if (!replace_attribute(id_, object, name, type.id, space.id, &p))
    fail_write(object, "cannot write attribute '" + name + "'");
}

void Hdf5File::set_attribute(const std::string& object, const std::string& name,
                             const std::vector<double>& value) {
  hsize_t n = value.size();
  Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose);
  if (!replace_attribute(id_, object, name, H5T_NATIVE_DOUBLE, space.id, value.data()))
    fail_write(object, "cannot write attribute '" + name + "'");
}

void Hdf5File::set_attribute(const std::string& object, const std::string& name, double value) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  if (!replace_attribute(id_, object, name, H5T_NATIVE_DOUBLE, space.id, &value))
    fail_write(object, "cannot write attribute '" + name + "'");
}

void Hdf5File::set_attribute(const std::string& object, const std::string& name, int64_t value) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  if (!replace_attribute(id_, object, name, H5T_NATIVE_INT64, space.id, &value))
    fail_write(object, "cannot write attribute '" + name + "'");
}

bool Hdf5File::has_attribute(const std::string& object, const std::string& name) const {
  if (!exists(object)) return false;
  Handle obj(open_object(id_, object), H5Oclose);
  return obj.ok() && H5Aexists(obj.id, name.c_str()) > 0;
}

std::string Hdf5File::string_attribute(const std::string& object, const std::string& name) const {
  if (!has_attribute(object, name)) fail(object == "/" ? name : object + "@" + name, "missing attribute");
  Handle obj(open_object(id_, object), H5Oclose);
  Handle attr(H5Aopen(obj.id, name.c_str(), H5P_DEFAULT), H5Aclose);
  Handle ftype(H5Aget_type(attr.id), H5Tclose);
  if (H5Tget_class(ftype.id) != H5T_STRING) fail(object + "@" + name, "not a string attribute");
  if (H5Tis_variable_str(ftype.id)) {
    Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(type.id, H5T_VARIABLE);
    H5Tset_cset(type.id, H5Tget_cset(ftype.id));
    char* p = nullptr;
    if (H5Aread(attr.id, type.id, &p) < 0) fail(object + "@" + name, "read failed");
    std::string out = p ? p : "";
    H5free_memory(p);
    return out;
  }
  size_t size = H5Tget_size(ftype.id);
  std::string out(size, '\0');
  if (H5Aread(attr.id, ftype.id, out.data()) < 0) fail(object + "@" + name, "read failed");
  out.resize(out.find('\0') == std::string::npos ? size : out.find('\0'));
  return out;
}

double Hdf5File::double_attribute(const std::string& object, const std::string& name) const {
  if (!has_attribute(object, name)) fail(object == "/" ? name : object + "@" + name, "missing attribute");
  Handle obj(open_object(id_, object), H5Oclose);
  Handle attr(H5Aopen(obj.id, name.c_str(), H5P_DEFAULT), H5Aclose);
  double v = 0;
  if (H5Aread(attr.id, H5T_NATIVE_DOUBLE, &v) < 0) fail(object + "@" + name, "not a number");
  return v;
}

int64_t Hdf5File::int_attribute(const std::string& object, const std::string& name) const {
  if (!has_attribute(object, name)) fail(object == "/" ? name : object + "@" + name, "missing attribute");
  Handle obj(open_object(id_, object), H5Oclose);
  Handle attr(H5Aopen(obj.id, name.c_str(), H5P_DEFAULT), H5Aclose);
  int64_t v = 0;
  if (H5Aread(attr.id, H5T_NATIVE_INT64, &v) < 0) fail(object + "@" + name, "not an integer");
  return v;
}

std::vector<double> Hdf5File::doubles_attribute(const std::string& object, const std::string& name) const {
  if (!has_attribute(object, name)) fail(object == "/" ? name : object + "@" + name, "missing attribute");
  Handle obj(open_object(id_, object), H5Oclose);
  Handle attr(H5Aopen(obj.id, name.c_str(), H5P_DEFAULT), H5Aclose);
  Handle space(H5Aget_space(attr.id), H5Sclose);
  hssize_t n = H5Sget_simple_extent_npoints(space.id);
  std::vector<double> v(static_cast<size_t>(n > 0 ? n : 0));
  if (n > 0 && H5Aread(attr.id, H5T_NATIVE_DOUBLE, v.data()) < 0) fail(object + "@" + name, "not numbers");
  return v;
}

}  // namespace latmpm
