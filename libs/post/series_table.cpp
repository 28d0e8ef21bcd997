#include "post/series_table.hpp"

#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/errors.hpp"

namespace latmpm::post {

namespace {

std::vector<std::string> split_commas(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

std::string trim(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

bool parse_number(const std::string& cell, double& value) {
  const std::string t = trim(cell);
  if (t.empty()) return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtod(t.c_str(), &end);
  return end == t.c_str() + t.size() && errno != ERANGE;
}

}  // namespace

int SeriesTable::index(const std::string& name) const {
  for (size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return int(i);
  return -1;
}

const std::vector<double>& SeriesTable::column(const std::string& name, const std::string& where) const {
  const int i = index(name);
  if (i < 0) throw InputError(where, name, "no such column");
  return columns[size_t(i)];
}

const std::string& SeriesTable::unit(const std::string& name) const {
  static const std::string none;
  const int i = index(name);
  return i < 0 ? none : units[size_t(i)];
}

SeriesTable parse_series_csv(const std::string& text, const std::string& name) {
  SeriesTable table;
  std::vector<std::string> lines;
  {
    std::stringstream ss(text);
    std::string line;
    while (std::getline(ss, line)) lines.push_back(line);
  }
  const bool ends_whole = !text.empty() && text.back() == '\n';
  size_t first = 0;
  while (first < lines.size() && (trim(lines[first]).empty() || lines[first][0] == '#')) ++first;
  if (first == lines.size()) throw InputError(name, "header", "empty file, expected 'name[unit],...'");

  for (const std::string& raw : split_commas(lines[first])) {
    const std::string cell = trim(raw);
    const size_t open = cell.find('['), close = cell.rfind(']');
    if (cell.empty() || open == 0 || open == std::string::npos || close != cell.size() - 1 || close < open)
      throw InputError(name, "line " + std::to_string(first + 1),
                       "header cell '" + cell + "' is not of the form name[unit]");
    table.names.push_back(cell.substr(0, open));
    table.units.push_back(cell.substr(open + 1, close - open - 1));
  }
  table.columns.assign(table.names.size(), {});

  for (size_t l = first + 1; l < lines.size(); ++l) {
    if (trim(lines[l]).empty() || lines[l][0] == '#') continue;
    const std::vector<std::string> cells = split_commas(lines[l]);
    std::vector<double> row(cells.size());
    bool numeric = true;
    for (size_t c = 0; c < cells.size(); ++c) numeric = numeric && parse_number(cells[c], row[c]);
    const bool last = l + 1 == lines.size();
    if (cells.size() != table.names.size() || !numeric) {
      // A run writes row by row: the last line of a run that is going or was killed may be cut.
      if (last && !ends_whole) {
        table.notes.push_back(name + ": line " + std::to_string(l + 1) + " incomplete (run cut short?), dropped");
        break;
      }
      throw InputError(name, "line " + std::to_string(l + 1),
                       cells.size() != table.names.size()
                           ? std::to_string(cells.size()) + " values, the header has " +
                                 std::to_string(table.names.size())
                           : "a value is not a number");
    }
    for (size_t c = 0; c < row.size(); ++c) table.columns[c].push_back(row[c]);
  }
  return table;
}

SeriesTable read_series_csv(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot read");
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_series_csv(ss.str(), path);
}

}  // namespace latmpm::post
