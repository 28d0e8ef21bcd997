// Checked reads of HDF5 datasets: what a file claims is checked before it is used. A reader
// states the shape it expects (rows tied to a count it already knows), that values are
// finite and within a range, or that indices lie within a table; anything else is refused
// with one InputError naming the file and the dataset ("run/checkpoint.h5: /state/body:
// value 7 at row 12 is outside [0, 2]"). A corrupted but well-formed file (a few rows short,
// an index out of range, a NaN time) stops here instead of crashing the reader or running on.
#pragma once
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace latmpm {

class Hdf5File;

// One entry per axis; any_extent where the extent is free (an N×3 table of N unknown rows:
// {any_extent, 3}).
inline constexpr size_t any_extent = std::numeric_limits<size_t>::max();

struct ValueRange {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
};

// Finite doubles of the given shape within [range.min, range.max].
std::vector<double> read_checked_doubles(const Hdf5File& file, const std::string& dataset,
                                         const std::vector<size_t>& shape, ValueRange range = {});

// Integers (stored as an integer type) of the given shape within [min, max].
std::vector<int64_t> read_checked_integers(const Hdf5File& file, const std::string& dataset,
                                           const std::vector<size_t>& shape, int64_t min, int64_t max);

// Strings of the given count (any_extent: any).
std::vector<std::string> read_checked_strings(const Hdf5File& file, const std::string& dataset,
                                              size_t count = any_extent);

// Scalar attributes: finite and within range.
double read_checked_double_attribute(const Hdf5File& file, const std::string& object, const std::string& name,
                                     ValueRange range = {});
int64_t read_checked_integer_attribute(const Hdf5File& file, const std::string& object, const std::string& name,
                                       int64_t min, int64_t max);

// "3x7" for messages; any_extent as "N".
std::string shape_text(const std::vector<size_t>& shape);

}  // namespace latmpm
