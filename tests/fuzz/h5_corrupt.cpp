// fuzz_h5_corrupt: makes a well-formed but corrupted copy of a latmpm HDF5 file in place,
// for the hostile-input suite (fuzz/run_fuzz.py). One edit per call:
//   fuzz_h5_corrupt FILE set DATASET INDEX VALUE     one element (flat index), type kept
//   fuzz_h5_corrupt FILE fill DATASET VALUE          every element
//   fuzz_h5_corrupt FILE drop-rows DATASET N         the last N rows removed
//   fuzz_h5_corrupt FILE delete DATASET              the dataset (or group) removed
//   fuzz_h5_corrupt FILE as-double DATASET           integers rewritten as doubles (+0.5)
//   fuzz_h5_corrupt FILE attr OBJECT NAME VALUE      a numeric attribute replaced
// VALUE may be nan, inf, -inf or any number. Exit status 0 done, 1 usage or a missing dataset.
#include <hdf5.h>

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/hdf5_file.hpp"

using latmpm::Hdf5File;

namespace {

double value_of(const std::string& text) { return std::strtod(text.c_str(), nullptr); }

size_t row_size(const std::vector<size_t>& dims) {
  size_t n = 1;
  for (size_t a = 1; a < dims.size(); ++a) n *= dims[a];
  return n;
}

template <class T>
void rewrite(Hdf5File& f, const std::string& dataset, std::vector<T> data, std::vector<size_t> dims,
             const std::string& op, const std::vector<std::string>& args) {
  if (op == "set") {
    const size_t i = std::stoul(args.at(0));
    if (i >= data.size()) throw std::runtime_error("index beyond the dataset");
    data[i] = T(value_of(args.at(1)));
  } else if (op == "fill") {
    for (auto& x : data) x = T(value_of(args.at(0)));
  } else if (op == "drop-rows") {
    const size_t drop = std::stoul(args.at(0));
    if (dims.empty() || drop > dims[0]) throw std::runtime_error("fewer rows than that");
    dims[0] -= drop;
    data.resize(dims[0] * row_size(dims));
  }
  f.write(dataset, data, dims);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: fuzz_h5_corrupt FILE OP DATASET|OBJECT ARGS...\n");
    return 1;
  }
  try {
    Hdf5File f(argv[1], Hdf5File::Mode::read_write);
    const std::string op = argv[2], target = argv[3];
    const std::vector<std::string> args(argv + 4, argv + argc);
    if (op == "attr") {
      const std::string name = args.at(0), text = args.at(1);
      if (text.find_first_of(".eEn") != std::string::npos || text.find("inf") != std::string::npos)
        f.set_attribute(target, name, value_of(text));
      else
        f.set_attribute(target, name, int64_t(std::stoll(text)));
    } else if (op == "delete") {
      f.close();
      const hid_t file = H5Fopen(argv[1], H5F_ACC_RDWR, H5P_DEFAULT);
      const bool removed = file >= 0 && H5Ldelete(file, target.c_str(), H5P_DEFAULT) >= 0;
      if (file >= 0) H5Fclose(file);
      return removed ? 0 : 1;
    } else if (op == "as-double") {
      std::vector<size_t> dims;
      auto data = f.read_doubles(target, &dims);
      for (auto& x : data) x += 0.5;
      f.write(target, data, dims);
    } else {
      std::vector<size_t> dims;
      if (f.is_integer(target)) {
        auto data = f.read_int64(target, &dims);
        rewrite(f, target, std::move(data), dims, op, args);
      } else {
        auto data = f.read_doubles(target, &dims);
        rewrite(f, target, std::move(data), dims, op, args);
      }
    }
    f.close();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz_h5_corrupt: %s\n", e.what());
    return 1;
  }
  return 0;
}
