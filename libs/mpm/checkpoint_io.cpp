#include "mpm/checkpoint_io.hpp"

#include <algorithm>
#include <cmath>

#include "core/checked_read.hpp"
#include "core/errors.hpp"
#include "core/hdf5_file.hpp"

namespace latmpm::mpm {

namespace {
constexpr const char* version_attribute = "format_version";
// The build's particle precision (real.hpp): a mixed build's float fields resumed by a double
// build (or the reverse) would not continue the run bit for bit. Missing: written as double.
constexpr const char* precision_attribute = "precision";

template <class T>
std::vector<double> flatten(const std::vector<T>& v) {
  constexpr int n = CheckpointCodec<T>::components;
  std::vector<double> out;
  out.reserve(v.size() * n);
  for (const auto& x : v)
    if constexpr (n == 1)
      out.push_back(x);
    else
      for (int i = 0; i < n; ++i) out.push_back(x.data()[i]);
  return out;
}

template <class T>
std::vector<T> unflatten(const std::vector<double>& d) {
  constexpr int n = CheckpointCodec<T>::components;
  if constexpr (n == 1) {
    return std::vector<T>(d.begin(), d.end());
  } else {
    std::vector<T> out(d.size() / n);
    for (size_t p = 0; p < out.size(); ++p)
      for (int i = 0; i < n; ++i) out[p].data()[i] = d[p * n + i];
    return out;
  }
}
}  // namespace

CheckpointWriter::CheckpointWriter(Hdf5File& file, std::string group) : file_(file), group_(std::move(group)) {
  file_.create_group(group_);
  file_.set_attribute(group_, version_attribute, checkpoint_format_version);
  file_.set_attribute(group_, precision_attribute, precision_name);
}

CheckpointWriter::CheckpointWriter(Hdf5File& file, std::string group, bool) : file_(file), group_(std::move(group)) {}

CheckpointWriter CheckpointWriter::sub(const std::string& sub) const { return {file_, path(sub), true}; }

void CheckpointWriter::scalar(const std::string& name, double value) { file_.write(path(name), std::vector<double>{value}, {1}); }

void CheckpointWriter::integer(const std::string& name, int64_t value) {
  file_.write(path(name), std::vector<int64_t>{value}, {1});
}

void CheckpointWriter::strings(const std::string& name, const std::vector<std::string>& values) {
  file_.write_strings(path(name), values);
}

void CheckpointWriter::integers(const std::string& name, const std::vector<int64_t>& values, size_t columns) {
  file_.write(path(name), values, {values.size() / columns, columns});
}

namespace {
// How a row type is stored: int32, uint8, int64 as they are; uint32 as int64; reals and
// fixed-size Eigen matrices as doubles, `components` per row.
template <class T>
auto stored(const std::vector<T>& values) {
  if constexpr (std::is_same_v<T, int32_t> || std::is_same_v<T, uint8_t> || std::is_same_v<T, int64_t>)
    return values;
  else if constexpr (std::is_same_v<T, uint32_t>)
    return std::vector<int64_t>(values.begin(), values.end());
  else if constexpr (CheckpointCodec<T>::components == 1)
    return std::vector<double>(values.begin(), values.end());
  else
    return flatten(values);
}
template <class T>
using Stored = typename decltype(stored(std::vector<T>{}))::value_type;

template <class T>
std::vector<size_t> row_shape(size_t rows) {
  constexpr int n = CheckpointCodec<T>::components;
  return n == 1 ? std::vector<size_t>{rows} : std::vector<size_t>{rows, size_t(n)};
}
}  // namespace

template <class T>
void CheckpointWriter::rows(const std::string& name, const std::vector<T>& values) {
  file_.write(path(name), stored(values), row_shape<T>(values.size()));
}

template <class T>
void CheckpointWriter::reserve_rows(const std::string& name, size_t total) {
  file_.reserve<Stored<T>>(path(name), row_shape<T>(total));
}

template <class T>
void CheckpointWriter::write_rows(const std::string& name, const std::vector<T>& values,
                                  const std::vector<RowBlock>& blocks) {
  file_.write_rows(path(name), stored(values), blocks);
}

void CheckpointWriter::reserve_integers(const std::string& name, size_t rows, size_t columns) {
  file_.reserve<int64_t>(path(name), {rows, columns});
}

CheckpointReader::CheckpointReader(const Hdf5File& file, std::string group) : file_(file), group_(std::move(group)) {
  if (!file_.exists(group_) || !file_.has_attribute(group_, version_attribute))
    throw InputError(file_.path(), group_,
                     "is not a latmpm checkpoint of format " + std::to_string(checkpoint_format_version) +
                         " (no format_version: written by an older latmpm; rerun from the start)");
  const int64_t version = file_.int_attribute(group_, version_attribute);
  if (version != checkpoint_format_version)
    throw InputError(file_.path(), group_,
                     "has checkpoint format " + std::to_string(version) + ", this latmpm reads format " +
                         std::to_string(checkpoint_format_version));
  const std::string precision =
      file_.has_attribute(group_, precision_attribute) ? file_.string_attribute(group_, precision_attribute) : "double";
  if (precision != precision_name)
    throw InputError(file_.path(), group_,
                     "was written by the " + precision + "-precision build and this latmpm is the " +
                         std::string(precision_name) +
                         "-precision one: resume with the build that wrote it (status.toml names it), or rerun "
                         "from the start");
}

CheckpointReader::CheckpointReader(const Hdf5File& file, std::string group, bool)
    : file_(file), group_(std::move(group)) {}

CheckpointReader CheckpointReader::sub(const std::string& sub) const { return {file_, path(sub), true}; }
CheckpointReader CheckpointReader::group(const std::string& group) const { return {file_, group, true}; }

const std::string& CheckpointReader::file_path() const { return file_.path(); }

bool CheckpointReader::has(const std::string& name) const { return file_.exists(path(name)); }

void CheckpointReader::expect_shape(const std::string& name, size_t count, int components) const {
  if (!has(name)) throw InputError(file_.path(), path(name), "missing from the checkpoint");
  const auto dims = file_.shape(path(name));
  const size_t rows = dims.empty() ? 0 : dims[0];
  if (rows != count)
    throw InputError(file_.path(), path(name),
                     "has " + std::to_string(rows) + " rows where the scene gives " + std::to_string(count) +
                         ": the checkpoint belongs to another scene or point set");
  const size_t cols = dims.size() > 1 ? dims[1] : 1;
  if (dims.size() > 2 || cols != size_t(components))
    throw InputError(file_.path(), path(name),
                     "has " + std::to_string(cols) + " values per row, expected " + std::to_string(components));
}

// Every real number of a checkpoint is a state the solver reached, so finite: a NaN or an
// infinity is a corrupted file, refused with the dataset named (read_checked_doubles).
double CheckpointReader::scalar(const std::string& name, ValueRange range) const {
  expect_shape(name, 1, 1);
  return read_checked_doubles(file_, path(name), {1}, range)[0];
}

int64_t CheckpointReader::integer(const std::string& name, int64_t min, int64_t max) const {
  expect_shape(name, 1, 1);
  return read_checked_integers(file_, path(name), {1}, min, max)[0];
}

std::vector<std::string> CheckpointReader::strings(const std::string& name) const {
  if (!has(name)) throw InputError(file_.path(), path(name), "missing from the checkpoint");
  return read_checked_strings(file_, path(name));
}

std::vector<int64_t> CheckpointReader::integers(const std::string& name, size_t columns, int64_t min,
                                                int64_t max) const {
  if (!has(name)) throw InputError(file_.path(), path(name), "missing from the checkpoint");
  const auto dims = file_.shape(path(name));
  expect_shape(name, dims.empty() ? 0 : dims[0], int(columns));
  return read_checked_integers(file_, path(name), {any_extent, columns}, min, max);
}

bool CheckpointReader::has_attribute(const std::string& name) const { return file_.has_attribute(group_, name); }

double CheckpointReader::attribute(const std::string& name, ValueRange range) const {
  return read_checked_double_attribute(file_, group_, name, range);
}

template <class T>
std::vector<T> CheckpointReader::rows(const std::string& name, size_t count, ValueRange range) const {
  if constexpr (std::is_integral_v<T>) {
    expect_shape(name, count, 1);
    // The range as integers, clamped to T's: an unsigned field cannot hold a negative value.
    const double lo = std::max(range.min, double(std::numeric_limits<T>::min()));
    const double hi = std::min(range.max, double(std::numeric_limits<T>::max()));
    const auto v = read_checked_integers(file_, path(name), {count}, int64_t(lo),
                                         hi >= 9.2e18 ? std::numeric_limits<int64_t>::max() : int64_t(hi));
    return std::vector<T>(v.begin(), v.end());
  } else {
    constexpr size_t n = size_t(CheckpointCodec<T>::components);
    expect_shape(name, count, int(n));
    return unflatten<T>(read_checked_doubles(file_, path(name), n == 1 ? std::vector<size_t>{count}
                                                                        : std::vector<size_t>{count, n},
                                             range));
  }
}

#define LATMPM_CHECKPOINT_ROWS(T)                                                                        \
  template void CheckpointWriter::rows<T>(const std::string&, const std::vector<T>&);                   \
  template void CheckpointWriter::reserve_rows<T>(const std::string&, size_t);                          \
  template void CheckpointWriter::write_rows<T>(const std::string&, const std::vector<T>&,              \
                                                const std::vector<RowBlock>&);                          \
  template std::vector<T> CheckpointReader::rows<T>(const std::string&, size_t, ValueRange) const;
LATMPM_CHECKPOINT_ROWS(Real)
LATMPM_CHECKPOINT_ROWS(Vec3)
LATMPM_CHECKPOINT_ROWS(Mat3)
LATMPM_CHECKPOINT_ROWS(SymTensor)
LATMPM_CHECKPOINT_ROWS(CpdiParticleDomain)
#if defined(LATMPM_MIXED_PRECISION)
LATMPM_CHECKPOINT_ROWS(ParticleReal)
LATMPM_CHECKPOINT_ROWS(ParticleVec3)
LATMPM_CHECKPOINT_ROWS(ParticleMat3)
LATMPM_CHECKPOINT_ROWS(ParticleSymTensor)
#endif
LATMPM_CHECKPOINT_ROWS(int32_t)
LATMPM_CHECKPOINT_ROWS(uint32_t)
LATMPM_CHECKPOINT_ROWS(uint8_t)
LATMPM_CHECKPOINT_ROWS(int64_t)
#undef LATMPM_CHECKPOINT_ROWS

}  // namespace latmpm::mpm
