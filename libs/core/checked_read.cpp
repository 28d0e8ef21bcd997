#include "core/checked_read.hpp"

#include <cmath>
#include <cstdio>

#include "core/errors.hpp"
#include "core/hdf5_file.hpp"

namespace latmpm {
namespace {

std::string number(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.9g", v);
  return text;
}

// "row 12" for a table, "index 12" for a list.
std::string position(size_t flat, const std::vector<size_t>& shape) {
  if (shape.size() < 2) return "index " + std::to_string(flat);
  size_t per_row = 1;
  for (size_t a = 1; a < shape.size(); ++a) per_row *= shape[a];
  return "row " + std::to_string(flat / per_row);
}

std::string field(const std::string& object, const std::string& name) {
  return object == "/" ? name : object + "@" + name;
}

void check_shape(const Hdf5File& file, const std::string& dataset, const std::vector<size_t>& expected) {
  const std::vector<size_t> found = file.shape(dataset);
  bool matches = found.size() == expected.size();
  for (size_t a = 0; matches && a < found.size(); ++a) matches = expected[a] == any_extent || expected[a] == found[a];
  if (!matches)
    throw InputError(file.path(), dataset, "shape " + shape_text(found) + ", expected " + shape_text(expected));
}

}  // namespace

std::string shape_text(const std::vector<size_t>& shape) {
  if (shape.empty()) return "scalar";
  std::string out;
  for (size_t a = 0; a < shape.size(); ++a)
    out += (a ? "x" : "") + (shape[a] == any_extent ? std::string("N") : std::to_string(shape[a]));
  return out;
}

std::vector<double> read_checked_doubles(const Hdf5File& file, const std::string& dataset,
                                         const std::vector<size_t>& shape, ValueRange range) {
  check_shape(file, dataset, shape);
  std::vector<size_t> found;
  std::vector<double> values = file.read_doubles(dataset, &found);
  for (size_t i = 0; i < values.size(); ++i) {
    const double v = values[i];
    if (!std::isfinite(v))
      throw InputError(file.path(), dataset, number(v) + " at " + position(i, found) + " (values must be finite)");
    if (v < range.min || v > range.max)
      throw InputError(file.path(), dataset, "value " + number(v) + " at " + position(i, found) + " is outside [" +
                                                 number(range.min) + ", " + number(range.max) + "]");
  }
  return values;
}

std::vector<int64_t> read_checked_integers(const Hdf5File& file, const std::string& dataset,
                                           const std::vector<size_t>& shape, int64_t min, int64_t max) {
  check_shape(file, dataset, shape);
  if (!file.is_integer(dataset)) throw InputError(file.path(), dataset, "not an integer dataset");
  std::vector<size_t> found;
  std::vector<int64_t> values = file.read_int64(dataset, &found);
  for (size_t i = 0; i < values.size(); ++i)
    if (values[i] < min || values[i] > max)
      throw InputError(file.path(), dataset, "value " + std::to_string(values[i]) + " at " + position(i, found) +
                                                 " is outside [" + std::to_string(min) + ", " + std::to_string(max) + "]");
  return values;
}

std::vector<std::string> read_checked_strings(const Hdf5File& file, const std::string& dataset, size_t count) {
  std::vector<std::string> values = file.read_strings(dataset);
  if (count != any_extent && values.size() != count)
    throw InputError(file.path(), dataset, std::to_string(values.size()) + " entries, expected " + std::to_string(count));
  return values;
}

double read_checked_double_attribute(const Hdf5File& file, const std::string& object, const std::string& name,
                                     ValueRange range) {
  const double v = file.double_attribute(object, name);
  if (!std::isfinite(v) || v < range.min || v > range.max)
    throw InputError(file.path(), field(object, name), "value " + number(v) + " is not within [" +
                                                                 number(range.min) + ", " + number(range.max) + "]");
  return v;
}

int64_t read_checked_integer_attribute(const Hdf5File& file, const std::string& object, const std::string& name,
                                       int64_t min, int64_t max) {
  const int64_t v = file.int_attribute(object, name);
  if (v < min || v > max)
    throw InputError(file.path(), field(object, name), "value " + std::to_string(v) + " is not within [" +
                                                                 std::to_string(min) + ", " + std::to_string(max) + "]");
  return v;
}

}  // namespace latmpm
