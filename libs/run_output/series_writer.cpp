#include "run_output/series_writer.hpp"

#include <cstdlib>
#include <cstdio>
#include <stdexcept>

#include "core/errors.hpp"
#include "core/file_transfer.hpp"
#include "core/hdf5_file.hpp"

namespace latmpm {

SeriesWriter::SeriesWriter(std::string csv_path, std::string hdf5_path,
                           std::vector<SeriesColumn> columns, Provenance provenance)
    : csv_path_(std::move(csv_path)), hdf5_path_(std::move(hdf5_path)),
      columns_(std::move(columns)), provenance_(std::move(provenance)),
      values_(columns_.size()) {
  csv_.open(csv_path_, std::ios::trunc);
  if (!csv_) throw InputError(csv_path_, "", "cannot write the series file");
  for (size_t c = 0; c < columns_.size(); ++c) csv_ << (c ? "," : "") << columns_[c].header();
  csv_ << std::endl;
}

SeriesWriter::SeriesWriter(std::string csv_path, std::string hdf5_path, std::vector<SeriesColumn> columns,
                           Provenance provenance, const std::vector<std::vector<double>>& earlier_rows)
    : SeriesWriter(std::move(csv_path), std::move(hdf5_path), std::move(columns), std::move(provenance)) {
  for (const auto& row : earlier_rows) append(row);
}

std::vector<std::vector<double>> read_series_csv(const std::string& path, std::vector<std::string>* header) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "", "cannot read the series file");
  std::string line;
  std::vector<std::vector<double>> rows;
  auto split = [](const std::string& text) {
    std::vector<std::string> cells;
    size_t start = 0;
    for (size_t comma; (comma = text.find(',', start)) != std::string::npos; start = comma + 1)
      cells.push_back(text.substr(start, comma - start));
    cells.push_back(text.substr(start));
    return cells;
  };
  if (!std::getline(in, line)) throw InputError(path, "", "empty series file (no header)");
  const auto head = split(line);
  if (header) *header = head;
  for (int number = 2; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    const auto cells = split(line);
    if (cells.size() != head.size())
      throw InputError(path + ":" + std::to_string(number), "", "a row with " + std::to_string(cells.size()) +
                                                                    " values for " + std::to_string(head.size()) + " columns");
    std::vector<double> row;
    for (const auto& c : cells) {
      char* end = nullptr;
      row.push_back(std::strtod(c.c_str(), &end));
      if (end == c.c_str()) throw InputError(path + ":" + std::to_string(number), "", "'" + c + "' is not a number");
    }
    rows.push_back(row);
  }
  return rows;
}

void SeriesWriter::append(const std::vector<double>& row) {
  if (row.size() != columns_.size())
    throw std::logic_error("series row has " + std::to_string(row.size()) + " values for " +
                           std::to_string(columns_.size()) + " columns");
  char buf[32];
  for (size_t c = 0; c < row.size(); ++c) {
    // 17 significant digits: the CSV holds exactly the doubles the HDF5 file holds.
    std::snprintf(buf, sizeof buf, "%.17g", row[c]);
    csv_ << (c ? "," : "") << buf;
    values_[c].push_back(row[c]);
  }
  csv_ << std::endl;  // flush: the row is on disk before the next step
  if (!csv_) throw OutputError(csv_path_, "write failed (disk full?)");
  ++rows_;
}

void SeriesWriter::save() const {
  OutputFile out(hdf5_path_, hdf5_path_);
  {
    Hdf5File file(out.temp_path(), Hdf5File::Mode::create);
    write_provenance(file, provenance_);
    std::vector<std::string> headers;
    for (const auto& c : columns_) headers.push_back(c.header());
    file.write_strings("/series/columns", headers);
    file.set_attribute("/series", "rows", int64_t(rows_));
    for (size_t c = 0; c < columns_.size(); ++c) {
      const std::string dataset = "/series/" + columns_[c].name;
      file.write(dataset, values_[c], {values_[c].size()});
      file.set_attribute(dataset, "unit", columns_[c].unit);
      file.set_attribute(dataset, "description", columns_[c].description);
    }
    file.close();
  }
  out.commit();
}

}  // namespace latmpm
