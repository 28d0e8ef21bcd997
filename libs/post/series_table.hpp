// A run's series.csv as columns: header cells "name[unit]" (docs/scene.md, "Series columns"),
// one value per row and column. Reading tolerates what a live or killed run leaves behind: a
// last line cut short is dropped (and said so in `notes`); anything else malformed is an
// InputError naming the file and line.
#pragma once
#include <string>
#include <vector>

namespace latmpm::post {

struct SeriesTable {
  std::vector<std::string> names, units;      // "load_driven", "N"
  std::vector<std::vector<double>> columns;   // columns[c][row]
  std::vector<std::string> notes;             // e.g. "series.csv: line 83 incomplete, dropped"

  size_t rows() const { return columns.empty() ? 0 : columns.front().size(); }
  bool has(const std::string& name) const { return index(name) >= 0; }
  int index(const std::string& name) const;  // -1 when absent
  // The column's values; throws InputError(where, name, "no such column") when absent.
  const std::vector<double>& column(const std::string& name, const std::string& where) const;
  const std::string& unit(const std::string& name) const;  // "" when absent
};

// Throws InputError(path, "line N", problem) for a malformed header or row.
SeriesTable read_series_csv(const std::string& path);
// The same from text (tests); `name` stands for the file in messages.
SeriesTable parse_series_csv(const std::string& text, const std::string& name);

}  // namespace latmpm::post
