#include "run_output/series_writer.hpp"

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
  if (!csv_) throw InputError(csv_path_, "", "cannot write the series file (disk full?)");
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
  }
  out.commit();
}

}  // namespace latmpm
