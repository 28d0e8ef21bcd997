#include "mesh/stl_file.hpp"

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <unordered_map>
#include <vector>

#include <Eigen/Geometry>

#include "core/errors.hpp"
#include "core/file_transfer.hpp"

namespace latmpm {
namespace {

static_assert(sizeof(float) == 4, "STL stores IEEE single precision");

constexpr size_t header_bytes = 80;
constexpr size_t binary_prefix_bytes = 84;  // header + uint32 triangle count
constexpr size_t binary_triangle_bytes = 50;  // normal, 3 vertices (12 floats) + uint16

// Merges vertices with bit-identical single-precision coordinates, which is how STL files
// share a vertex between the triangles around it.
class VertexWelder {
 public:
  VertexWelder(TriangleMesh& mesh, double metres_per_unit) : mesh_(mesh), scale_(metres_per_unit) {}

  int32_t add(const float xyz[3]) {
    Key key;
    for (int i = 0; i < 3; ++i) {
      const float v = xyz[i] + 0.0f;  // -0 and +0 are the same point
      std::memcpy(&key.bits[i], &v, sizeof v);
    }
    auto [it, inserted] = index_.emplace(key, static_cast<int32_t>(mesh_.vertices.size()));
    if (inserted)
      mesh_.vertices.emplace_back(xyz[0] * scale_, xyz[1] * scale_, xyz[2] * scale_);
    return it->second;
  }
  void reserve(size_t n) { index_.reserve(n); }

 private:
  struct Key {
    uint32_t bits[3];
    bool operator==(const Key& o) const {
      return bits[0] == o.bits[0] && bits[1] == o.bits[1] && bits[2] == o.bits[2];
    }
  };
  struct KeyHash {
    size_t operator()(const Key& k) const {
      uint64_t h = k.bits[0];
      h = h * 0x9E3779B97F4A7C15ull ^ k.bits[1];
      h = h * 0x9E3779B97F4A7C15ull ^ k.bits[2];
      return static_cast<size_t>(h ^ (h >> 29));
    }
  };
  TriangleMesh& mesh_;
  double scale_;
  std::unordered_map<Key, int32_t, KeyHash> index_;
};

void check_finite(const std::string& path, size_t triangle, const float xyz[9]) {
  for (int i = 0; i < 9; ++i) {
    if (!std::isfinite(xyz[i])) {
      throw InputError(path, "triangle " + std::to_string(triangle),
                       "vertex " + std::to_string(i / 3 + 1) + " has a non-finite coordinate (" +
                           std::to_string(xyz[i]) + ")");
    }
  }
}

void add_triangle(VertexWelder& welder, TriangleMesh& mesh, const float xyz[9]) {
  mesh.triangles.push_back({welder.add(xyz), welder.add(xyz + 3), welder.add(xyz + 6)});
}

TriangleMesh parse_binary(const std::string& path, const std::string& bytes, double scale) {
  uint32_t count = 0;
  std::memcpy(&count, bytes.data() + header_bytes, sizeof count);
  TriangleMesh mesh;
  mesh.triangles.reserve(count);
  mesh.vertices.reserve(count / 2 + 3);
  VertexWelder welder(mesh, scale);
  welder.reserve(count / 2 + 3);
  const char* record = bytes.data() + binary_prefix_bytes;
  for (uint32_t t = 0; t < count; ++t, record += binary_triangle_bytes) {
    float xyz[9];
    std::memcpy(xyz, record + 12, sizeof xyz);  // skip the stored normal
    check_finite(path, t, xyz);
    add_triangle(welder, mesh, xyz);
  }
  return mesh;
}

// Token reader for ASCII STL that knows the line it is on, for error messages.
class AsciiTokens {
 public:
  AsciiTokens(const std::string& path, const std::string& text) : path_(path), text_(text) {}

  bool at_end() {
    skip_space();
    return pos_ >= text_.size();
  }
  std::string next() {
    skip_space();
    const size_t start = pos_;
    while (pos_ < text_.size() && !is_space(text_[pos_])) ++pos_;
    return text_.substr(start, pos_ - start);
  }
  void expect(const char* word) {
    const std::string got = next();
    if (got != word) fail("expected '" + std::string(word) + "', found " + quoted(got));
  }
  float number() {
    skip_space();
    const size_t start = pos_;
    while (pos_ < text_.size() && !is_space(text_[pos_])) ++pos_;
    double value = 0;
    const char* first = text_.data() + start;
    const char* last = text_.data() + pos_;
    if (*first == '+') ++first;  // from_chars does not accept a leading '+'
    auto [end, ec] = std::from_chars(first, last, value);
    if (first == last || end != last || (ec != std::errc() && ec != std::errc::result_out_of_range))
      fail("expected a number, found " + quoted(text_.substr(start, pos_ - start)));
    // from_chars leaves `value` untouched (0) when out of range: 1e999 would read as 0.
    if (ec == std::errc::result_out_of_range)
      fail("number " + quoted(text_.substr(start, pos_ - start)) + " is out of range");
    if (std::isfinite(value) && std::fabs(value) > std::numeric_limits<float>::max())
      fail("number " + quoted(text_.substr(start, pos_ - start)) +
           " is beyond single precision (STL coordinates are floats)");
    return static_cast<float>(value);
  }
  void skip_line() {
    while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
  }
  [[noreturn]] void fail(const std::string& problem) const {
    throw InputError(path_, "line " + std::to_string(line_), problem);
  }

 private:
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }
  static std::string quoted(const std::string& s) {
    if (s.empty()) return "end of file (truncated?)";
    bool printable = true;
    for (unsigned char c : s) printable = printable && c >= 32 && c < 127;
    if (!printable) return "binary data (a truncated or padded binary STL?)";
    return "'" + (s.size() > 40 ? s.substr(0, 40) + "..." : s) + "'";
  }
  void skip_space() {
    while (pos_ < text_.size() && is_space(text_[pos_])) {
      if (text_[pos_] == '\n') ++line_;
      ++pos_;
    }
  }
  const std::string& path_;
  const std::string& text_;
  size_t pos_ = 0;
  size_t line_ = 1;
};

TriangleMesh parse_ascii(const std::string& path, const std::string& text, double scale) {
  TriangleMesh mesh;
  VertexWelder welder(mesh, scale);
  AsciiTokens in(path, text);
  in.expect("solid");
  in.skip_line();  // the solid's name
  size_t triangle = 0;
  for (;;) {
    const std::string word = in.next();
    if (word == "endsolid") {
      in.skip_line();
      if (in.at_end()) break;
      in.expect("solid");  // some exporters write several solids into one file
      in.skip_line();
      continue;
    }
    if (word != "facet") {
      in.fail(word.empty() ? "file ends without 'endsolid' (truncated?)"
                           : "expected 'facet' or 'endsolid', found '" + word + "'");
    }
    in.expect("normal");
    for (int i = 0; i < 3; ++i) in.number();  // the stored normal is not trusted
    in.expect("outer");
    in.expect("loop");
    // A loop normally has three vertices; polygons with more are fanned into triangles.
    std::vector<float> loop;
    for (;;) {
      const std::string w = in.next();
      if (w == "endloop") break;
      if (w != "vertex") in.fail("expected 'vertex' or 'endloop', found '" + w + "'");
      for (int i = 0; i < 3; ++i) loop.push_back(in.number());
    }
    if (loop.size() < 9) in.fail("facet " + std::to_string(triangle) + " has fewer than 3 vertices");
    in.expect("endfacet");
    for (size_t k = 2; 3 * k < loop.size(); ++k) {
      float xyz[9];
      std::memcpy(xyz, loop.data(), 3 * sizeof(float));
      std::memcpy(xyz + 3, loop.data() + 3 * (k - 1), 3 * sizeof(float));
      std::memcpy(xyz + 6, loop.data() + 3 * k, 3 * sizeof(float));
      check_finite(path, triangle, xyz);
      add_triangle(welder, mesh, xyz);
      ++triangle;
    }
  }
  return mesh;
}

bool starts_with_solid(const std::string& bytes) {
  size_t i = 0;
  while (i < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[i]))) ++i;
  return bytes.compare(i, 5, "solid") == 0;
}

std::array<double, 3> unit_normal(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                  const Eigen::Vector3d& c) {
  const Eigen::Vector3d n = (b - a).cross(c - a);
  const double length = n.norm();
  if (!(length > 0)) return {0, 0, 0};
  return {n.x() / length, n.y() / length, n.z() / length};
}

void check_writable_mesh(const TriangleMesh& mesh, const std::string& path) {
  const auto nv = static_cast<int64_t>(mesh.vertices.size());
  for (size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (!mesh.vertices[v].allFinite())
      throw InputError(path, "vertex " + std::to_string(v), "non-finite coordinate");
  }
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int32_t i : mesh.triangles[t]) {
      if (i < 0 || i >= nv)
        throw InputError(path, "triangle " + std::to_string(t),
                         "vertex index " + std::to_string(i) + " out of range");
    }
  }
  if (mesh.triangles.size() > UINT32_MAX)
    throw InputError(path, "triangles", "more than 2^32 triangles do not fit a binary STL");
}

}  // namespace

void write_stl(const TriangleMesh& mesh, const std::string& path, double metres_per_unit,
               StlEncoding encoding) {
  if (!(metres_per_unit > 0) || !std::isfinite(metres_per_unit))
    throw InputError(path, "units", "metres per unit must be positive");
  check_writable_mesh(mesh, path);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw InputError(path, "", "cannot open for writing");
  const double inv = 1.0 / metres_per_unit;
  auto in_units = [&](int32_t v, int axis) { return static_cast<float>(mesh.vertices[v][axis] * inv); };

  if (encoding == StlEncoding::binary) {
    char header[header_bytes] = {};
    std::snprintf(header, sizeof header, "latmpm binary STL, 1 unit = %g m", metres_per_unit);
    out.write(header, header_bytes);
    const auto count = static_cast<uint32_t>(mesh.triangles.size());
    out.write(reinterpret_cast<const char*>(&count), sizeof count);
    std::vector<char> buffer;
    buffer.reserve(binary_triangle_bytes * 4096);
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
      const auto& tri = mesh.triangles[t];
      const auto n = unit_normal(mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]]);
      float record[12];
      for (int i = 0; i < 3; ++i) record[i] = static_cast<float>(n[i]);
      for (int k = 0; k < 3; ++k)
        for (int i = 0; i < 3; ++i) record[3 + 3 * k + i] = in_units(tri[k], i);
      const char* bytes = reinterpret_cast<const char*>(record);
      buffer.insert(buffer.end(), bytes, bytes + sizeof record);
      buffer.push_back(0);  // attribute byte count
      buffer.push_back(0);
      if (buffer.size() >= binary_triangle_bytes * 4096 || t + 1 == mesh.triangles.size()) {
        out.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
        buffer.clear();
      }
    }
  } else {
    // %.9g round-trips single precision exactly, so reading back gives the binary's floats.
    out << "solid latmpm\n";
    char line[160];
    for (const auto& tri : mesh.triangles) {
      const auto n = unit_normal(mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]]);
      std::snprintf(line, sizeof line, "  facet normal %.9g %.9g %.9g\n    outer loop\n", n[0], n[1], n[2]);
      out << line;
      for (int k = 0; k < 3; ++k) {
        std::snprintf(line, sizeof line, "      vertex %.9g %.9g %.9g\n", in_units(tri[k], 0),
                      in_units(tri[k], 1), in_units(tri[k], 2));
        out << line;
      }
      out << "    endloop\n  endfacet\n";
    }
    out << "endsolid latmpm\n";
  }
  out.flush();
  if (!out) throw OutputError(shown_path(path), "write failed (disk full?)");
}

TriangleMesh read_stl(const std::string& path, double metres_per_unit) {
  return read_stl(path, metres_per_unit, nullptr);
}

TriangleMesh read_stl(const std::string& path, double metres_per_unit, StlEncoding* encoding) {
  if (!(metres_per_unit > 0) || !std::isfinite(metres_per_unit))
    throw InputError(path, "units", "metres per unit must be positive");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot open for reading");
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw InputError(path, "", "read failed");
  if (bytes.empty()) throw InputError(path, "", "empty file");

  TriangleMesh mesh;
  bool binary = false;
  if (bytes.size() >= binary_prefix_bytes) {
    uint32_t count = 0;
    std::memcpy(&count, bytes.data() + header_bytes, sizeof count);
    binary = bytes.size() == binary_prefix_bytes + binary_triangle_bytes * uint64_t{count};
    if (!binary && !starts_with_solid(bytes)) {
      throw InputError(path, "size",
                       "binary STL header announces " + std::to_string(count) + " triangles (" +
                           std::to_string(binary_prefix_bytes + binary_triangle_bytes * uint64_t{count}) +
                           " bytes) but the file has " + std::to_string(bytes.size()) +
                           " bytes (truncated?)");
    }
  } else if (!starts_with_solid(bytes)) {
    throw InputError(path, "size", "only " + std::to_string(bytes.size()) +
                                       " bytes: too short for a binary STL and not ASCII STL");
  }
  mesh = binary ? parse_binary(path, bytes, metres_per_unit) : parse_ascii(path, bytes, metres_per_unit);
  if (mesh.triangles.empty()) throw InputError(path, "triangles", "the file holds no triangles");
  if (encoding) *encoding = binary ? StlEncoding::binary : StlEncoding::ascii;
  return mesh;
}

}  // namespace latmpm
