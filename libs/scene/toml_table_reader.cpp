#include "scene/toml_table_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/text.hpp"

namespace latmpm::scene_toml {
namespace {

std::string trim(const std::string& s) {
  size_t b = s.find_first_not_of(" \t"), e = s.find_last_not_of(" \t");
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

std::vector<std::string> split_key(const std::string& key) {
  std::vector<std::string> parts;
  std::stringstream ss(key);
  for (std::string part; std::getline(ss, part, '.');) parts.push_back(trim(part));
  if (!key.empty() && key.back() == '.') parts.emplace_back();
  return parts;
}

// A number as it would be typed, for messages: "10", "0.4".
std::string number_text(const toml::node& node) {
  if (auto* i = node.as_integer()) return std::to_string(i->get());
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", node.as_floating_point()->get());
  return buf;
}

// Edit distance, to tell a misspelt key from a missing one.
size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
      diagonal = up;
    }
  }
  return row[b.size()];
}

int line_of(const toml::node* node) {
  return node ? static_cast<int>(node->source().begin.line) : 0;
}

}  // namespace

void Origins::add_override(const std::string& key_path, const std::string& assignment) {
  overrides_[key_path] = assignment;
}

std::string Origins::where(const std::string& key_path, const toml::node* node,
                           const toml::node* fallback) const {
  for (const auto& [path, assignment] : overrides_)
    if (key_path == path || key_path.compare(0, path.size() + 1, path + ".") == 0) return assignment;
  int line = line_of(node);
  if (line == 0) line = line_of(fallback);
  return line > 0 ? file_ + ":" + std::to_string(line) : file_;
}

void apply_override(toml::table& document, const std::string& assignment, Origins& origins) {
  const std::string where = "--set " + assignment;
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError(where, "", "expected key=value, e.g. --set grid.cell=0.4mm");
  const std::string key = trim(assignment.substr(0, eq)), text = trim(assignment.substr(eq + 1));
  const std::vector<std::string> parts = split_key(key);
  for (const auto& part : parts)
    if (part.empty()) throw InputError(where, key, "empty part in the key path");

  // The value: TOML if it parses as one value ("0.4", "[...]", "{ time = \"1s\" }"),
  // otherwise the text itself ("0.4mm", "c-points.h5").
  toml::table parsed;
  bool is_toml = false;
  try {
    parsed = toml::parse("v = " + text);
    is_toml = parsed.size() == 1 && parsed.contains("v");
  } catch (const toml::parse_error&) {
  }
  auto assign_table = [&](toml::table& t, const std::string& k) {
    if (is_toml)
      t.insert_or_assign(k, std::move(*parsed.get("v")));
    else
      t.insert_or_assign(k, text);
  };

  toml::node* container = &document;
  std::string reached;
  for (size_t i = 0; i < parts.size(); ++i) {
    const std::string& part = parts[i];
    const bool last = i + 1 == parts.size();
    toml::node* child = nullptr;
    if (auto* t = container->as_table()) {
      if (last) {
        assign_table(*t, part);
        break;
      }
      child = t->get(part);
      if (!child) {
        t->insert_or_assign(part, toml::table{});
        child = t->get(part);
      }
    } else if (auto* a = container->as_array()) {
      char* end = nullptr;
      long index = std::strtol(part.c_str(), &end, 10);
      if (*end != '\0' || index < 0)
        throw InputError(where, key, "'" + reached + "' is an array: '" + part + "' is not an index");
      if (static_cast<size_t>(index) > a->size())
        throw InputError(where, key, "index " + part + " is past the end of '" + reached + "' (" +
                                         std::to_string(a->size()) + " entries)");
      if (static_cast<size_t>(index) == a->size()) a->push_back(toml::table{});
      if (last) {
        toml::table holder;
        assign_table(holder, "v");
        a->replace(a->cbegin() + index, std::move(*holder.get("v")));
        break;
      }
      child = a->get(static_cast<size_t>(index));
    } else {
      throw InputError(where, key, "'" + reached + "' is a value, not a table");
    }
    reached += (reached.empty() ? "" : ".") + part;
    container = child;
  }
  std::string normalised;
  for (const auto& part : parts) normalised += (normalised.empty() ? "" : ".") + part;
  origins.add_override(normalised, where);
}

TableReader::TableReader(toml::table& table, std::string path, const Origins& origins)
    : table_(&table), path_(std::move(path)), origins_(&origins) {}

std::string TableReader::key_path(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

std::string TableReader::where(const std::string& key) const {
  return origins_->where(key_path(key), table_->get(key), table_);
}

bool TableReader::overridden(const std::string& key) const {
  return where(key).rfind("--set ", 0) == 0;
}

void TableReader::fail(const std::string& key, const std::string& problem) const {
  throw InputError(where(key), key_path(key), problem);
}

int TableReader::line() const { return line_of(table_); }

toml::node* TableReader::find(const std::string& key) {
  known_.insert(key);
  return table_->get(key);
}

bool TableReader::has(const std::string& key) { return find(key) != nullptr; }

bool TableReader::has_text(const std::string& key) {
  const toml::node* node = find(key);
  return node && node->is_string();
}

toml::node& TableReader::require(const std::string& key) {
  toml::node* node = find(key);
  if (!node) {
    // A present key the schema has not asked for, one or two letters off: a typo.
    for (const std::string& present : keys())
      if (!known_.count(present) && edit_distance(present, key) <= 2)
        throw InputError(where(present), key_path(present),
                         "unknown key; did you mean '" + key + "'?");
    std::string table_name = path_.empty() ? "the scene" : "[" + path_ + "]";
    throw InputError(where(key), key_path(key), "missing; " + table_name + " needs '" + key + "'");
  }
  return *node;
}

std::string TableReader::type_name(const toml::node& node) const {
  switch (node.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a number";
    case toml::node_type::boolean: return "a boolean";
    default: return "a date or time";
  }
}

double TableReader::quantity_of(const std::string& key, toml::node& node, const Dimension& dimension) {
  if (node.is_number()) {
    // A bare TOML number is only right for a dimensionless value; otherwise the same
    // message as for the string "10" ("'10' has no unit; expected a pressure ...").
    if (dimension.is_dimensionless())
      return node.is_integer() ? double(node.as_integer()->get()) : node.as_floating_point()->get();
    return parse_quantity(number_text(node), dimension, where(key), key_path(key));
  }
  if (!node.is_string() && dimension.is_dimensionless())
    fail(key, "expected a number, found " + type_name(node));
  if (!node.is_string())
    fail(key, "expected a quantity with a unit as a string (e.g. \"1" + si_unit(dimension) +
                  "\"), found " + type_name(node));
  return parse_quantity(node.as_string()->get(), dimension, where(key), key_path(key));
}

double TableReader::quantity(const std::string& key, const Dimension& dimension) {
  return quantity_of(key, require(key), dimension);
}

double TableReader::quantity(const std::string& key, const Dimension& dimension,
                             const std::string& fallback) {
  if (toml::node* node = find(key)) return quantity_of(key, *node, dimension);
  table_->insert_or_assign(key, fallback);
  return parse_quantity(fallback, dimension, where(key), key_path(key));
}

double TableReader::number(const std::string& key) {
  double v = quantity_of(key, require(key), dimension::none);
  if (!std::isfinite(v)) fail(key, "is not a finite number");
  return v;
}

double TableReader::number(const std::string& key, double fallback) {
  if (!has(key)) table_->insert_or_assign(key, fallback);
  return number(key);
}

long TableReader::integer(const std::string& key, long fallback) {
  toml::node* node = find(key);
  if (!node) {
    table_->insert_or_assign(key, int64_t(fallback));
    return fallback;
  }
  if (!node->is_integer()) fail(key, "expected a whole number, found " + type_name(*node));
  return static_cast<long>(node->as_integer()->get());
}

std::string TableReader::text(const std::string& key) {
  toml::node& node = require(key);
  if (!node.is_string()) fail(key, "expected a string, found " + type_name(node));
  return node.as_string()->get();
}

std::string TableReader::text(const std::string& key, const std::string& fallback) {
  if (!has(key)) table_->insert_or_assign(key, fallback);
  return text(key);
}

bool TableReader::boolean(const std::string& key, bool fallback) {
  toml::node* node = find(key);
  if (!node) {
    table_->insert_or_assign(key, fallback);
    return fallback;
  }
  if (!node->is_boolean()) fail(key, "expected true or false, found " + type_name(*node));
  return node->as_boolean()->get();
}

std::string TableReader::choice(const std::string& key, const std::vector<std::string>& allowed,
                                const std::string& fallback) {
  std::string value = fallback.empty() ? text(key) : text(key, fallback);
  if (std::find(allowed.begin(), allowed.end(), value) == allowed.end()) {
    fail(key, "'" + value + "' is not one of: " + joined(allowed));
  }
  return value;
}

Eigen::Vector3d TableReader::vector(const std::string& key, const Dimension& dimension) {
  toml::node& node = require(key);
  toml::array* a = node.as_array();
  if (!a || a->size() != 3)
    fail(key, "expected three components [x, y, z], e.g. [\"0" + si_unit(dimension) + "\", \"0" +
                  si_unit(dimension) + "\", \"1" + si_unit(dimension) + "\"]");
  Eigen::Vector3d v;
  for (size_t i = 0; i < 3; ++i) {
    toml::node& c = *a->get(i);
    std::string field = key_path(key) + "[" + std::to_string(i) + "]";
    if (c.is_string())
      v[i] = parse_quantity(c.as_string()->get(), dimension, where(key), field);
    else if (c.is_number())
      v[i] = parse_quantity(number_text(c), dimension, where(key), field);
    else
      throw InputError(where(key), field, "expected a quantity with a unit, found " + type_name(c));
  }
  return v;
}

Eigen::Vector3d TableReader::vector(const std::string& key, const Dimension& dimension,
                                    const std::string& fallback_component) {
  if (!has(key))
    table_->insert_or_assign(key, toml::array{fallback_component, fallback_component, fallback_component});
  return vector(key, dimension);
}

TableReader TableReader::table(const std::string& key) {
  toml::node& node = require(key);
  if (!node.is_table()) fail(key, "expected a table, found " + type_name(node));
  return TableReader(*node.as_table(), key_path(key), *origins_);
}

std::optional<TableReader> TableReader::optional_table(const std::string& key) {
  if (!has(key)) return std::nullopt;
  return table(key);
}

TableReader TableReader::table_or_empty(const std::string& key) {
  if (!has(key)) table_->insert_or_assign(key, toml::table{});
  return table(key);
}

std::vector<TableReader> TableReader::tables(const std::string& key) {
  toml::node& node = require(key);
  toml::array* a = node.as_array();
  if (!a || !a->is_array_of_tables())
    fail(key, "expected an array of tables ([[" + key + "]] sections), found " + type_name(node));
  std::vector<TableReader> result;
  for (size_t i = 0; i < a->size(); ++i)
    result.emplace_back(*a->get(i)->as_table(), key_path(key) + "." + std::to_string(i), *origins_);
  return result;
}

std::vector<std::string> TableReader::keys() const {
  std::vector<std::pair<int, std::string>> ordered;
  for (auto&& [k, v] : *table_) ordered.emplace_back(line_of(&v), std::string(k.str()));
  std::stable_sort(ordered.begin(), ordered.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> result;
  for (auto& [line, k] : ordered) result.push_back(k);
  return result;
}

void TableReader::replace_text(const std::string& key, const std::string& value) {
  table_->insert_or_assign(key, value);
}

void TableReader::finish() const {
  for (const std::string& key : keys()) {
    if (known_.count(key)) continue;
    const std::string list = joined(known_);
    std::string here = path_.empty() ? "at the top level" : "in [" + path_ + "]";
    throw InputError(where(key), key_path(key),
                     "unknown key " + here + (list.empty() ? "" : " (expected one of: " + list + ")"));
  }
}

}  // namespace latmpm::scene_toml
