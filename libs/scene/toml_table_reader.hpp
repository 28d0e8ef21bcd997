// Reading a TOML document field by field, the way every scene key is read: each value is
// looked up by the schema, checked (type, unit, range) and marked as used; whatever the
// schema never asked for is an unknown key, which stops the run (catches typos such as
// 'strut_diamter'). Every error names the file and line (or the --set override) and the full
// key path: "scene.toml:12: bodies.lattice.material.E: '10' has no unit; ...".
// Defaults are written back into the document, so the document becomes the resolved scene.
//
// Private to libs/scene: only its .cpp files include toml++ (see scene/scene.hpp for the API).
#pragma once
#include <Eigen/Core>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <toml++/toml.h>
#include <vector>

#include "core/errors.hpp"
#include "core/units.hpp"

namespace latmpm::scene_toml {

// Where values came from: the scene file and the --set overrides applied on top of it.
class Origins {
 public:
  explicit Origins(std::string file) : file_(std::move(file)) {}
  const std::string& file() const { return file_; }
  void add_override(const std::string& key_path, const std::string& assignment);
  // "scene.toml:12", or "--set a.b=c" when the key (or a table above it) was overridden.
  std::string where(const std::string& key_path, const toml::node* node,
                    const toml::node* fallback) const;

 private:
  std::string file_;
  std::map<std::string, std::string> overrides_;  // key path -> "--set key=value"
};

// Applies "a.b.c=value" (value parsed as TOML, else taken as a string). Numeric path parts
// index arrays ("points.0.file"); index == size appends a table. Creates missing tables,
// so a misspelt key still reaches the unknown-key check with the override named.
void apply_override(toml::table& document, const std::string& assignment, Origins& origins);

class TableReader {
 public:
  TableReader(toml::table& table, std::string path, const Origins& origins);

  const std::string& path() const { return path_; }
  std::string key_path(const std::string& key) const;
  std::string where(const std::string& key) const;  // location of key, or of this table
  bool overridden(const std::string& key) const;    // the value came from --set
  [[noreturn]] void fail(const std::string& key, const std::string& problem) const;

  bool has(const std::string& key);  // also declares the key as known
  bool has_text(const std::string& key);  // present and a string; declares the key as known
  // Required values (missing -> error naming the table).
  double quantity(const std::string& key, const Dimension& dimension);
  double number(const std::string& key);
  std::string text(const std::string& key);
  // Values with a default, written back into the document when missing.
  double quantity(const std::string& key, const Dimension& dimension, const std::string& fallback);
  double number(const std::string& key, double fallback);
  long integer(const std::string& key, long fallback);
  std::string text(const std::string& key, const std::string& fallback);
  bool boolean(const std::string& key, bool fallback);
  // One of `allowed` (a string); the error lists them.
  std::string choice(const std::string& key, const std::vector<std::string>& allowed,
                     const std::string& fallback);
  // [x, y, z] of quantities with units.
  Eigen::Vector3d vector(const std::string& key, const Dimension& dimension);
  Eigen::Vector3d vector(const std::string& key, const Dimension& dimension,
                         const std::string& fallback_component);
  // Sub-tables ([a.b] or inline { ... }), and arrays of tables ([[points]]).
  TableReader table(const std::string& key);
  std::optional<TableReader> optional_table(const std::string& key);
  // An optional table whose keys all have defaults: created empty when missing, so the
  // resolved document lists the defaults too.
  TableReader table_or_empty(const std::string& key);
  std::vector<TableReader> tables(const std::string& key);
  // Keys of this table in document order (for tables whose keys are names, like [bodies]).
  std::vector<std::string> keys() const;

  // Overwrites a value (e.g. a path made absolute) in the resolved document.
  void replace_text(const std::string& key, const std::string& value);
  // Every key present but never asked for is an error (the first one, by line).
  void finish() const;
  int line() const;

 private:
  toml::node* find(const std::string& key);
  toml::node& require(const std::string& key);
  double quantity_of(const std::string& key, toml::node& node, const Dimension& dimension);
  std::string type_name(const toml::node& node) const;

  toml::table* table_;
  std::string path_;
  const Origins* origins_;
  std::set<std::string> known_;
};

}  // namespace latmpm::scene_toml
